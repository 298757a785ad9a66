// FieldTextures copies to the GPU only what changed: a field one version
// behind takes just the cells its FieldChange names, and the textures then
// hold exactly what a full copy would; anything else is copied whole.
#include "render/stages/FieldTextures.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace eikon {
namespace {

constexpr int kEdge = 12;

FieldSet randomFields(std::mt19937& random) {
    FieldSet fields;
    fields.grid = GridSpec{{kEdge, kEdge + 1, kEdge + 2}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    fields.deltaIndex.resize(fields.grid.cellCount());
    fields.extinction.resize(3 * fields.grid.cellCount());
    for (float& v : fields.deltaIndex) v = value(random);
    for (float& v : fields.extinction) v = value(random);
    fields.indexVersion = fields.extinctionVersion = 1;
    return fields;
}

// New values in `box`, a new version, and (when `said`) the change recorded.
void changeCells(FieldSet& fields, const CellBox& box, bool said, std::mt19937& random) {
    std::uniform_real_distribution<float> value(2.0f, 3.0f);
    for (int k = box.min.z; k < box.max.z; ++k)
        for (int j = box.min.y; j < box.max.y; ++j)
            for (int i = box.min.x; i < box.max.x; ++i) {
                const std::size_t cell = fields.grid.linearIndex(i, j, k);
                fields.deltaIndex[cell] = value(random);
                for (int c = 0; c < 3; ++c) fields.extinction[3 * cell + static_cast<std::size_t>(c)] = value(random);
            }
    ++fields.indexVersion;
    ++fields.extinctionVersion;
    if (said) {
        fields.indexChange = {fields.indexVersion, box};
        fields.extinctionChange = {fields.extinctionVersion, box};
    }
}

std::vector<float> textureValues(const gl::Texture3D& texture, GLenum format, int components, const GridSpec& grid) {
    std::vector<float> values(static_cast<std::size_t>(components) * grid.cellCount());
    glGetTextureImage(texture.id(), 0, format, GL_FLOAT, static_cast<GLsizei>(values.size() * sizeof(float)),
                      values.data());
    return values;
}

class FieldTexturesTest : public ::testing::Test {
protected:
    void SetUp() override { test::glContext(); }

    void expectTexturesHold(const render::FieldTextures& textures, const FieldSet& fields) {
        EXPECT_EQ(textureValues(textures.index(), GL_RED, 1, fields.grid), fields.deltaIndex);
        EXPECT_EQ(textureValues(textures.extinction(), GL_RGB, 3, fields.grid), fields.extinction);
    }
};

TEST_F(FieldTexturesTest, AFieldOneVersionBehindTakesOnlyTheChangedCells) {
    std::mt19937 random(5);
    FieldSet fields = randomFields(random);
    render::FieldTextures textures;
    const std::size_t perCell = sizeof(float) * 4;  // δn and κ's three channels
    EXPECT_GE(textures.upload(render::hostUpload(fields)).host, perCell * fields.grid.cellCount());

    const CellBox box{{2, 3, 4}, {5, 7, 9}};
    changeCells(fields, box, true, random);
    const render::UploadBytes bytes = textures.upload(render::hostUpload(fields));
    EXPECT_EQ(bytes.host, perCell * static_cast<std::size_t>(box.cellCount()));
    expectTexturesHold(textures, fields);

    // A box touching the grid's far corner, where the unpack offsets end.
    const CellBox corner{{kEdge - 3, kEdge - 2, kEdge - 1}, {kEdge, kEdge + 1, kEdge + 2}};
    changeCells(fields, corner, true, random);
    EXPECT_EQ(textures.upload(render::hostUpload(fields)).host, perCell * static_cast<std::size_t>(corner.cellCount()));
    expectTexturesHold(textures, fields);
}

TEST_F(FieldTexturesTest, AnUnsaidOrSkippedChangeIsCopiedWhole) {
    std::mt19937 random(6);
    FieldSet fields = randomFields(random);
    render::FieldTextures textures;
    textures.upload(render::hostUpload(fields));
    const std::size_t whole = sizeof(float) * 4 * fields.grid.cellCount();

    changeCells(fields, {{0, 0, 0}, {2, 2, 2}}, false, random);  // no FieldChange for this version
    EXPECT_EQ(textures.upload(render::hostUpload(fields)).host, whole);
    expectTexturesHold(textures, fields);

    // Two versions on, only the second's cells said: the texture holds neither before it.
    changeCells(fields, {{1, 1, 1}, {3, 3, 3}}, true, random);
    changeCells(fields, {{6, 6, 6}, {8, 8, 8}}, true, random);
    EXPECT_EQ(textures.upload(render::hostUpload(fields)).host, whole);
    expectTexturesHold(textures, fields);
}

}  // namespace
}  // namespace eikon
