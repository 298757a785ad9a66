// TBB-parallel reductions and updates over flat arrays, shared by the Krylov
// solvers and the field checks. Sums are accumulated per block and combined,
// so results are deterministic only up to rounding.
#pragma once

#include <cstddef>
#include <vector>

namespace eikon::sim {

double dot(const std::vector<double>& a, const std::vector<double>& b);
double maxAbs(const std::vector<double>& a);
double sum(const std::vector<double>& a);
// Every entry equal to the first (true for none).
bool isUniform(const std::vector<double>& a);

// y += alpha · x
void axpy(double alpha, const std::vector<double>& x, std::vector<double>& y);

}  // namespace eikon::sim
