#include "bridge/core/Error.h"
#include "bridge/grid/FieldSet.h"
#include "bridge/grid/GridSpec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

namespace eikon {
namespace {

GridSpec threeCubed() { return GridSpec{{3, 3, 3}, glm::dvec3(-1.5), glm::dvec3(1.5)}; }

TEST(GridSpec, CellCentresAndIndices) {
    const GridSpec grid = threeCubed();
    EXPECT_EQ(grid.cellCount(), 27u);
    EXPECT_EQ(grid.linearIndex(2, 1, 0), 5u);
    EXPECT_EQ(grid.linearIndex(0, 0, 1), 9u);
    EXPECT_EQ(grid.cellCentre(0, 0, 0), glm::dvec3(-1.0));
    EXPECT_EQ(grid.cellCentre(1, 1, 1), glm::dvec3(0.0));
    EXPECT_DOUBLE_EQ(grid.voxelVolume(), 1.0);
    EXPECT_TRUE(grid.contains(glm::dvec3(1.5)));
    EXPECT_FALSE(grid.contains(glm::dvec3(1.5, 0.0, 1.6)));
}

TEST(GridSpec, NonCubicVoxels) {
    const GridSpec grid{{4, 2, 1}, glm::dvec3(0.0), glm::dvec3(2.0, 1.0, 3.0)};
    EXPECT_EQ(grid.voxelSize(), glm::dvec3(0.5, 0.5, 3.0));
    EXPECT_DOUBLE_EQ(grid.smallestVoxelEdge(), 0.5);
}

FieldSet uniformFields() {
    FieldSet fields;
    fields.grid = threeCubed();
    fields.referenceIndex = 1.0;
    fields.deltaIndex.assign(27, 0.1f);
    fields.extinction.assign(81, 2.0f);
    fields.scattering.assign(81, 1.0f);
    return fields;
}

// An origin as a producer gives one: a file and the keys behind a field.
std::string sceneKeys(std::string_view field, const glm::dvec3*) { return "scene.json: " + std::string(field) + " keys"; }

std::string refusal(const FieldSet& fields) {
    try {
        validateFields(fields, sceneKeys);
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(FieldValidation, AcceptsValidFields) { EXPECT_EQ(refusal(uniformFields()), ""); }

// The refusal names the producer's keys and the cell's world position, not
// the cell's index in a grid the user never sees.
TEST(FieldValidation, NamesTheKeysAndPositionOfANonFiniteIndex) {
    FieldSet fields = uniformFields();
    fields.deltaIndex[fields.grid.linearIndex(2, 1, 0)] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(refusal(fields), "scene.json: index keys (the refractive index at (1, 0, -1) m): expected a finite "
                               "index n > 0, found nan");
}

TEST(FieldValidation, RejectsNonPositiveIndex) {
    FieldSet fields = uniformFields();
    fields.deltaIndex[0] = -1.0f;
    EXPECT_NE(refusal(fields).find("found 0"), std::string::npos) << refusal(fields);
}

TEST(FieldValidation, RejectsScatteringAboveExtinction) {
    FieldSet fields = uniformFields();
    fields.scattering[3 * 26 + 2] = 3.0f;
    EXPECT_EQ(refusal(fields), "scene.json: scattering keys (the scattering σs at (1, 1, 1) m): expected a finite "
                               "value in [0, extinction = 2] (1/m), found 3");
}

TEST(FieldValidation, RejectsNegativeExtinction) {
    FieldSet fields = uniformFields();
    fields.scattering.clear();
    fields.extinction[4] = -0.5f;
    EXPECT_NE(refusal(fields).find("scene.json: extinction keys (the extinction κ at (0, -1, -1) m)"),
              std::string::npos)
        << refusal(fields);
}

}  // namespace
}  // namespace eikon
