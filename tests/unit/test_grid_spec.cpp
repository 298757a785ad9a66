#include "bridge/core/Error.h"
#include "bridge/grid/FieldSet.h"
#include "bridge/grid/GridSpec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

TEST(FieldValidation, AcceptsValidFields) { EXPECT_NO_THROW(validateFields(uniformFields(), "test")); }

TEST(FieldValidation, NamesFieldAndCellOfNonFiniteIndex) {
    FieldSet fields = uniformFields();
    fields.deltaIndex[fields.grid.linearIndex(2, 1, 0)] = std::numeric_limits<float>::quiet_NaN();
    try {
        validateFields(fields, "sim");
        FAIL() << "NaN index accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("field index, cell (2, 1, 0)"), std::string::npos) << error.what();
    }
}

TEST(FieldValidation, RejectsNonPositiveIndex) {
    FieldSet fields = uniformFields();
    fields.deltaIndex[0] = -1.0f;
    EXPECT_THROW(validateFields(fields, "sim"), InputError);
}

TEST(FieldValidation, RejectsScatteringAboveExtinction) {
    FieldSet fields = uniformFields();
    fields.scattering[3 * 26 + 2] = 3.0f;
    try {
        validateFields(fields, "sim");
        FAIL() << "scattering > extinction accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("field scattering, cell (2, 2, 2)"), std::string::npos) << error.what();
    }
}

TEST(FieldValidation, RejectsNegativeExtinction) {
    FieldSet fields = uniformFields();
    fields.scattering.clear();
    fields.extinction[4] = -0.5f;
    EXPECT_THROW(validateFields(fields, "sim"), InputError);
}

}  // namespace
}  // namespace eikon
