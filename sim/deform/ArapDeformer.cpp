#include "sim/deform/ArapDeformer.h"

#include "bridge/core/Error.h"
#include "sim/deform/Keyframes.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SVD>
#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::sim {

namespace {

Eigen::Vector3d toEigen(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

struct ArapDeformer::Solver {
    struct Neighbour {
        int vertex;
        double weight;
    };

    std::vector<glm::dvec3> rest;
    std::vector<std::vector<Neighbour>> neighbours;
    std::vector<int> handleOf;   // per vertex: index into handles, −1 when free
    std::vector<int> freeIndex;  // per vertex: row in the reduced system, −1 for handle vertices
    std::vector<HandleDesc> handles;
    std::vector<glm::dvec3> handleCentres;
    int iterations = 1;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor;
    std::vector<glm::dvec3> current;  // warm start: the last frame's solution
    std::vector<Eigen::Matrix3d> rotations;

    void buildWeights(const TriangleMesh& mesh) {
        neighbours.assign(rest.size(), {});
        auto add = [&](int a, int b, double w) {
            for (Neighbour& n : neighbours[a])
                if (n.vertex == b) {
                    n.weight += w;
                    return;
                }
            neighbours[a].push_back({b, w});
        };
        double total = 0.0;
        for (const glm::ivec3& t : mesh.triangles)
            for (int corner = 0; corner < 3; ++corner) {
                const int c = t[corner], a = t[(corner + 1) % 3], b = t[(corner + 2) % 3];
                const glm::dvec3 ea = rest[a] - rest[c], eb = rest[b] - rest[c];
                const double sine = glm::length(glm::cross(ea, eb));
                const double cotangent = sine > 1e-300 ? glm::dot(ea, eb) / sine : 0.0;  // angle at c, opposite a–b
                add(a, b, 0.5 * cotangent);
                add(b, a, 0.5 * cotangent);
                total += std::abs(cotangent);
            }
        const double floor = 1e-3 * total / std::max<std::size_t>(1, 3 * mesh.triangles.size());
        for (auto& list : neighbours)
            for (Neighbour& n : list) n.weight = std::max(n.weight, floor);
    }

    void factorise(const std::string& where) {
        int rows = 0;
        freeIndex.assign(rest.size(), -1);
        for (std::size_t v = 0; v < rest.size(); ++v)
            if (handleOf[v] < 0) freeIndex[v] = rows++;
        if (rows == 0) return;
        std::vector<Eigen::Triplet<double>> entries;
        for (std::size_t v = 0; v < rest.size(); ++v) {
            if (freeIndex[v] < 0) continue;
            double diagonal = 0.0;
            for (const Neighbour& n : neighbours[v]) {
                diagonal += n.weight;
                if (freeIndex[n.vertex] >= 0) entries.emplace_back(freeIndex[v], freeIndex[n.vertex], -n.weight);
            }
            entries.emplace_back(freeIndex[v], freeIndex[v], diagonal);
        }
        Eigen::SparseMatrix<double> laplacian(rows, rows);
        laplacian.setFromTriplets(entries.begin(), entries.end());
        factor.compute(laplacian);
        if (factor.info() != Eigen::Success)
            throw InputError(where, "handles that pin every connected part of the mesh",
                             "a system that cannot be factorised");
    }

    void requireHandleInEveryPart(const std::string& where) const {
        std::vector<int> part(rest.size(), -1);
        for (std::size_t seed = 0; seed < rest.size(); ++seed) {
            if (part[seed] >= 0 || neighbours[seed].empty()) continue;
            bool pinned = false;
            std::vector<int> stack{static_cast<int>(seed)};
            part[seed] = 1;
            while (!stack.empty()) {
                const int v = stack.back();
                stack.pop_back();
                pinned = pinned || handleOf[v] >= 0;
                for (const Neighbour& n : neighbours[v])
                    if (part[n.vertex] < 0) {
                        part[n.vertex] = 1;
                        stack.push_back(n.vertex);
                    }
            }
            if (!pinned)
                throw InputError(where, "a handle region in every connected part of the mesh",
                                 "a part with no handle vertex (it would float free)");
        }
    }

    void localStep() {
        rotations.resize(rest.size());
        tbb::parallel_for(std::size_t{0}, rest.size(), [&](std::size_t i) {
            Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
            for (const Neighbour& n : neighbours[i])
                covariance += n.weight * toEigen(rest[i] - rest[n.vertex]) * toEigen(current[i] - current[n.vertex]).transpose();
            const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
            Eigen::Matrix3d v = svd.matrixV();
            Eigen::Matrix3d r = v * svd.matrixU().transpose();
            if (r.determinant() < 0.0) {  // a reflection: flip the axis of the smallest singular value
                v.col(2) *= -1.0;
                r = v * svd.matrixU().transpose();
            }
            rotations[i] = r.allFinite() ? r : Eigen::Matrix3d::Identity();
        });
    }

    void globalStep() {
        const int rows = static_cast<int>(factor.rows());
        if (rows == 0) return;
        Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(rows, 3);
        for (std::size_t i = 0; i < rest.size(); ++i) {
            if (freeIndex[i] < 0) continue;
            Eigen::Vector3d b = Eigen::Vector3d::Zero();
            for (const Neighbour& n : neighbours[i]) {
                b += 0.5 * n.weight * (rotations[i] + rotations[n.vertex]) * toEigen(rest[i] - rest[n.vertex]);
                if (freeIndex[n.vertex] < 0) b += n.weight * toEigen(current[n.vertex]);
            }
            rhs.row(freeIndex[i]) = b.transpose();
        }
        const Eigen::MatrixXd solution = factor.solve(rhs);
        for (std::size_t i = 0; i < rest.size(); ++i)
            if (freeIndex[i] >= 0)
                current[i] = glm::dvec3(solution(freeIndex[i], 0), solution(freeIndex[i], 1), solution(freeIndex[i], 2));
    }
};

ArapDeformer::ArapDeformer(const DeformerDesc& desc, const TriangleMesh& rest, const std::string& where)
    : solver_(std::make_unique<Solver>()) {
    Solver& s = *solver_;
    s.rest = rest.vertices;
    s.current = rest.vertices;
    s.handles = desc.handles;
    s.iterations = desc.iterations;
    s.handleOf.assign(rest.vertices.size(), -1);
    for (std::size_t h = 0; h < desc.handles.size(); ++h) {
        const HandleDesc& handle = desc.handles[h];
        glm::dvec3 centroid(0.0);
        int members = 0;
        for (std::size_t v = 0; v < rest.vertices.size(); ++v) {
            const glm::dvec3& p = rest.vertices[v];
            if (s.handleOf[v] >= 0 || glm::any(glm::lessThan(p, handle.regionMin)) ||
                glm::any(glm::greaterThan(p, handle.regionMax)))
                continue;
            s.handleOf[v] = static_cast<int>(h);
            centroid += p;
            ++members;
        }
        s.handleCentres.push_back(members > 0 ? centroid / double(members) : centroid);
        if (members == 0)
            throw InputError(where + ".handles[" + std::to_string(h) + "]",
                             "a region holding at least one vertex of the placed mesh", "none inside");
    }
    s.buildWeights(rest);
    s.requireHandleInEveryPart(where + ".handles");
    s.factorise(where + ".handles");
}

ArapDeformer::~ArapDeformer() = default;

std::size_t ArapDeformer::handleVertexCount() const {
    return static_cast<std::size_t>(std::count_if(solver_->handleOf.begin(), solver_->handleOf.end(),
                                                  [](int h) { return h >= 0; }));
}

void ArapDeformer::deform(double time, std::vector<glm::dvec3>& deformed) {
    Solver& s = *solver_;
    std::vector<glm::dmat4> poses;
    for (const HandleDesc& handle : s.handles) poses.push_back(placementMatrix(poseAt(handle.keys, time)));
    for (std::size_t v = 0; v < s.rest.size(); ++v) {
        const int h = s.handleOf[v];
        if (h >= 0) s.current[v] = s.handleCentres[h] + glm::dvec3(poses[h] * glm::dvec4(s.rest[v] - s.handleCentres[h], 1.0));
    }
    for (int iteration = 0; iteration < s.iterations; ++iteration) {
        s.localStep();
        s.globalStep();
    }
    deformed = s.current;
}

}  // namespace eikon::sim
