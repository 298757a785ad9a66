// The processes of one eikon command: a single process, or the ranks of an
// MPI job when mpirun (or another MPI launcher) started eikon — told by the
// launcher's environment (OMPI_COMM_WORLD_SIZE, PMIX_RANK, PMI_SIZE). Started
// any other way eikon makes no MPI call at all, so the same binary runs
// alone exactly as before: that is the single-process path every other test
// takes, and MPI is a build requirement (libopenmpi-dev), not an option.
//
// Errors (apps/common/ExitCodes.h): input — the command line first, then the
// command's scene and files — is checked by every rank before any rank
// communicates, and the ranks fail together: a bad input is reported once,
// by rank 0 (or by the rank that alone met it, naming itself), and every
// rank exits 2. Then the ranks compare what they checked (Agreement): ranks
// started with different arguments or reading different scenes are refused
// alike, rank 0 naming the first difference. A failure after that is one
// rank's: it says so with its rank and ends the job (MPI_Abort), so no rank
// waits for it for ever. SIGINT, SIGTERM and SIGHUP remove a rank's
// temporaries and end it with exit 1, which mpirun passes on after stopping
// the others.
//
// Ranks on one machine share its cores: each gets cores / local ranks TBB
// threads and, unless LP_NUM_THREADS is set, as many llvmpipe threads.
#pragma once

#include "render/stages/LightPassShare.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace eikon::app {

class Ranks {
public:
    // Initializes MPI when a launcher started this process; call once, first.
    static Ranks& start(int& argc, char**& argv);
    // The processes of this command (after start).
    static Ranks& world();
    ~Ranks();

    int rank() const { return rank_; }
    int size() const { return size_; }
    // Rank and rank count among the processes on this machine (the GPU a rank uses).
    int localRank() const { return localRank_; }
    int localSize() const { return localSize_; }
    bool distributed() const { return size_ > 1; }
    bool first() const { return rank_ == 0; }
    std::string describe() const;  // "rank 1 of 2" (empty alone)

    // Collectives: every rank calls each, in the same order.
    void barrier() const;
    // Rank 0 receives every rank's text, in rank order; the others get {}.
    std::vector<std::string> gatherToFirst(const std::string& text) const;
    // The light pass's raw tallies summed (maxima taken) onto rank 0.
    render::LightPassExchange& lightPassExchange();

    // What every rank must hold alike: `text`, canonical (equal texts, equal
    // inputs), compared by hash; where another rank's differs, rank 0 says
    // how in `difference(theirs, theirRank)`.
    struct Agreement {
        std::string text;
        std::function<std::string(const std::string& theirs, int theirRank)> difference;
    };
    // Runs `checks` (every input of the command) on every rank, then agrees:
    // when a rank failed, rank 0's error (or, where rank 0 passed, each
    // failing rank's, named by its rank) is reported and every rank throws
    // (rank 0 its error, the others ReportedElsewhere with its exit code).
    // Then every rank's `agreement`, which `checks` fills, is compared with
    // rank 0's: where one differs, rank 0 throws InputError("ranks
    // disagree: " + the first difference) and the others ReportedElsewhere(2).
    // From then on failures are one rank's (runGuarded). Alone: just runs
    // the checks.
    void checkInputsTogether(const std::function<void()>& checks, const Agreement& agreement = {});
    // Runs a command: after checkInputsTogether, a failure is reported with
    // this rank's name and ends the job with its exit code (2 bad input, 1
    // anything else), since the other ranks would wait for this one.
    int runGuarded(const std::function<int()>& body);
    // Ends every rank of the job with `code` (alone: exits).
    [[noreturn]] void abort(int code) const;

private:
    // "eikon: error (rank r of n): what" on stderr, in one write.
    void reportError(const std::string& what) const;
    // Every rank's `agreement` against rank 0's (checkInputsTogether).
    void requireAgreement(const Agreement& agreement) const;
    struct ThreadBudget;  // the cores of this machine shared among its ranks
    Ranks();
    bool mpi_ = false;
    int rank_ = 0, size_ = 1, localRank_ = 0, localSize_ = 1;
    bool inputsChecked_ = false;  // outside checkInputsTogether, having passed one
    std::unique_ptr<render::LightPassExchange> exchange_;
    std::unique_ptr<ThreadBudget> threads_;
};

}  // namespace eikon::app
