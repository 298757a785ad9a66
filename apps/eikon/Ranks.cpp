#include "apps/eikon/Ranks.h"

#include "apps/common/ExitCodes.h"
#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"

#include <mpi.h>
#include <tbb/global_control.h>
#include <zlib.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <thread>

namespace eikon::app {

namespace {

bool startedByMpiLauncher() {
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
        if (std::getenv(variable)) return true;
    return false;
}

void check(int result, const char* call) {
    if (result != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + call + " failed");
}

// Sums every share's tallies onto rank 0 (MPI_Reduce): integers exactly,
// whatever the rank count, so the frame has the bits of one process's.
class MpiLightPassExchange final : public render::LightPassExchange {
public:
    explicit MpiLightPassExchange(bool first) : first_(first) {}

    void combine(render::LightPassTallies& tallies) override {
        reduce(tallies.sums, MPI_UINT64_T, MPI_SUM);
        reduce(tallies.maxima, MPI_UINT32_T, MPI_MAX);
        reduce(tallies.floatSums, MPI_FLOAT, MPI_SUM);
    }
    bool receivesTotals() const override { return first_; }

private:
    template <typename T>
    void reduce(std::vector<T>& values, MPI_Datatype type, MPI_Op op) const {
        // Counts above INT_MAX (a 2^31-texel receiver) would need chunking; the
        // GPU limits of a receiver and a grid keep them far below.
        EIKON_CHECK_MSG(values.size() < (std::size_t{1} << 31), "a light pass's tallies fit one MPI message");
        const int count = static_cast<int>(values.size());
        if (first_)
            check(MPI_Reduce(MPI_IN_PLACE, values.data(), count, type, op, 0, MPI_COMM_WORLD), "MPI_Reduce");
        else
            check(MPI_Reduce(values.data(), nullptr, count, type, op, 0, MPI_COMM_WORLD), "MPI_Reduce");
    }

    bool first_;
};

Ranks* theWorld = nullptr;

}  // namespace

struct Ranks::ThreadBudget {
    explicit ThreadBudget(std::size_t threads) : control(tbb::global_control::max_allowed_parallelism, threads) {}
    tbb::global_control control;
};

Ranks::Ranks() = default;

Ranks& Ranks::start(int& argc, char**& argv) {
    EIKON_CHECK_MSG(!theWorld, "Ranks::start once");
    static Ranks world;
    theWorld = &world;
    if (!startedByMpiLauncher()) return world;
    int provided = 0;
    // Funneled: only the main thread calls MPI (the simulation thread of a
    // pipelined run and TBB's workers never do).
    check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    world.mpi_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &world.rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &world.size_);
    MPI_Comm node;
    check(MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, world.rank_, MPI_INFO_NULL, &node),
          "MPI_Comm_split_type");
    MPI_Comm_rank(node, &world.localRank_);
    MPI_Comm_size(node, &world.localSize_);
    MPI_Comm_free(&node);
    if (world.localSize_ > 1) {
        const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
        const unsigned share = std::max(1u, cores / static_cast<unsigned>(world.localSize_));
        world.threads_ = std::make_unique<ThreadBudget>(share);
        ::setenv("LP_NUM_THREADS", std::to_string(share).c_str(), /*overwrite=*/0);  // before any GL context
    }
    return world;
}

Ranks& Ranks::world() {
    EIKON_CHECK_MSG(theWorld, "Ranks::start first");
    return *theWorld;
}

Ranks::~Ranks() {
    exchange_.reset();
    if (mpi_) MPI_Finalize();
}

std::string Ranks::describe() const {
    return distributed() ? "rank " + std::to_string(rank_) + " of " + std::to_string(size_) : std::string();
}

void Ranks::barrier() const {
    if (mpi_) check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
}

std::vector<std::string> Ranks::gatherToFirst(const std::string& text) const {
    if (!mpi_) return {text};
    EIKON_CHECK_MSG(text.size() < (std::size_t{1} << 31), "a rank's text fits one MPI message");
    const int length = static_cast<int>(text.size());
    std::vector<int> lengths(first() ? static_cast<std::size_t>(size_) : 0);
    check(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
    std::vector<int> offsets(lengths.size());
    long long total = 0;
    for (std::size_t r = 0; r < lengths.size(); ++r) {
        offsets[r] = static_cast<int>(total);
        total += lengths[r];
    }
    EIKON_CHECK_MSG(total < (1LL << 31), "the ranks' texts fit one MPI message");
    std::string all(static_cast<std::size_t>(total), '\0');
    check(MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
                      MPI_COMM_WORLD),
          "MPI_Gatherv");
    std::vector<std::string> texts;
    for (std::size_t r = 0; r < lengths.size(); ++r)
        texts.push_back(all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r])));
    return texts;
}

render::LightPassExchange& Ranks::lightPassExchange() {
    if (!exchange_) exchange_ = std::make_unique<MpiLightPassExchange>(first());
    return *exchange_;
}

void Ranks::checkInputsTogether(const std::function<void()>& checks, const Agreement& agreement) {
    inputsChecked_ = false;  // a failure from here on is the ranks' together, not one rank's
    std::exception_ptr failure;
    int code = 0;
    try {
        checks();
    } catch (const InputError&) {
        failure = std::current_exception();
        code = 2;
    } catch (const std::exception&) {
        failure = std::current_exception();
        code = 1;
    }
    if (!distributed()) {
        if (failure) std::rethrow_exception(failure);
        inputsChecked_ = true;
        return;
    }
    // [0]: the worst exit code of any rank; [1]: rank 0 failed.
    const int mine[2] = {code, first() && failure ? 1 : 0};
    int all[2] = {0, 0};
    check(MPI_Allreduce(mine, all, 2, MPI_INT, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    if (all[0] != 0) {
        // The job ends together, its error reported once: mpirun may stop a
        // rank still on its way out once another has exited, and that signal
        // is not a second error.
        io::exitOnSignalsWith(all[0], "");
        if (failure && first()) std::rethrow_exception(failure);
        if (failure && all[1] == 0) {  // met by this rank, not by rank 0: say which rank
            try {
                std::rethrow_exception(failure);
            } catch (const std::exception& error) {
                reportError(error.what());
            }
        }
        throw ReportedElsewhere(all[0]);
    }
    requireAgreement(agreement);
    inputsChecked_ = true;
}

void Ranks::requireAgreement(const Agreement& agreement) const {
    // Equal everywhere exactly where the largest hash and the largest
    // complement (the complement of the smallest) are complements: one call.
    const std::uint32_t hash = static_cast<std::uint32_t>(
        crc32_z(0L, reinterpret_cast<const Bytef*>(agreement.text.data()), agreement.text.size()));
    const std::uint32_t mine[2] = {hash, ~hash};
    std::uint32_t largest[2] = {0, 0};
    check(MPI_Allreduce(mine, largest, 2, MPI_UINT32_T, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    if (largest[0] == static_cast<std::uint32_t>(~largest[1])) return;
    const std::vector<std::string> texts = gatherToFirst(agreement.text);
    if (!first()) throw ReportedElsewhere(2);
    for (int r = 1; r < size_; ++r)
        if (texts[static_cast<std::size_t>(r)] != agreement.text)
            throw InputError("ranks disagree: " + agreement.difference(texts[static_cast<std::size_t>(r)], r) +
                             "; every rank must be started with the same arguments and read the same scene");
    EIKON_CHECK_MSG(false, "texts whose hashes differ differ");
}

int Ranks::runGuarded(const std::function<int()>& body) {
    if (!distributed()) return body();
    io::exitOnSignalsWith(1, "eikon: error (" + describe() + "): stopped by a signal; its temporaries removed\n");
    try {
        return body();
    } catch (const ReportedElsewhere&) {
        throw;
    } catch (const InputError& error) {
        if (!inputsChecked_) throw;
        reportError(error.what());
        abort(2);
    } catch (const std::exception& error) {
        if (!inputsChecked_) throw;
        reportError(error.what());
        abort(1);
    }
}

// One write of the whole line: mpirun forwards a rank's stderr as it
// arrives and prints its own abort notice, which used to land between the
// pieces of a message written in parts.
void Ranks::reportError(const std::string& what) const {
    const std::string line = "eikon: error (" + describe() + "): " + what + "\n";
    std::cerr.write(line.data(), static_cast<std::streamsize>(line.size()));
}

void Ranks::abort(int code) const {
    std::cerr.flush();
    if (mpi_) MPI_Abort(MPI_COMM_WORLD, code);
    std::exit(code);
}

}  // namespace eikon::app
