// SPDX-License-Identifier: MIT
#include "drydem/parallel/mpi_world.hpp"
#include "drydem/core/error.hpp"
#include <mpi.h>
#include <algorithm>
#include <thread>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <string>

namespace drydem::parallel {

namespace {

int env_int(const char* name) {
    const char* v = std::getenv(name);
    if (!v || !*v) return 0;
    char* end = nullptr;
    const long n = std::strtol(v, &end, 10);
    return (*end == '\0' && n > 0 && n < (1L << 24)) ? int(n) : 0;
}

bool started_here = false;
double waited = 0.0; // waited_seconds()

} // namespace

int launcher_ranks() {
    if (int n = env_int("OMPI_COMM_WORLD_SIZE")) return n;
    if (int n = env_int("PMI_SIZE")) return n;
    if (int n = env_int("PMIX_SIZE")) return n;
    // srun without a PMI plugin that exports a size: a job step's task count.
    if (std::getenv("SLURM_STEP_ID"))
        if (int n = env_int("SLURM_NTASKS")) return n;
    return 1;
}

bool launched() {
    return env_int("OMPI_COMM_WORLD_SIZE") || env_int("PMI_SIZE") || env_int("PMIX_SIZE");
}

void start_mpi() {
    static std::once_flag once;
    std::call_once(once, [] {
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (initialised) return;
        // One rank talks only to itself: skip the probing of networks (and its warnings on
        // machines without them). A user's own OMPI_MCA_btl wins.
        if (launcher_ranks() == 1) setenv("OMPI_MCA_btl", "self", 0);
        int provided = 0;
        if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS)
            throw RunError("MPI did not start (MPI_Init_thread failed)");
        if (provided < MPI_THREAD_SERIALIZED)
            throw RunError("MPI started without thread support (MPI_THREAD_SERIALIZED needed: "
                           "the analysis calls MPI from a worker thread)");
        started_here = true;
    });
}

void finish_mpi() {
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (!initialised || finalised || !started_here) return;
    if (launched()) MPI_Finalize();
}

World world() {
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (!initialised || finalised) return {};
    World w;
    MPI_Comm_rank(MPI_COMM_WORLD, &w.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &w.size);
    return w;
}

double waited_seconds() { return waited; }
void add_waited(double seconds) { waited += seconds; }

namespace {
/// Waits for a request without holding a core for long: it spins for the first 2 ms (a step's
/// release follows the stop agreement within microseconds), then sleeps in naps growing from
/// 50 us to 10 ms (rank 0 writing a checkpoint or running the structure analysis for minutes,
/// while the other ranks would otherwise busy-poll a core each).
void wait_patiently(MPI_Request& request) {
    const double t0 = MPI_Wtime();
    auto nap = std::chrono::microseconds(50);
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return;
        if (MPI_Wtime() - t0 > 2e-3) {
            std::this_thread::sleep_for(nap);
            nap = std::min(2 * nap, std::chrono::microseconds(10000));
        }
    }
}
} // namespace

int broadcast(int value) {
    // Non-blocking on every rank alike (a blocking and a non-blocking collective do not match).
    const double t0 = MPI_Wtime();
    MPI_Request request;
    MPI_Ibcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
    wait_patiently(request);
    waited += MPI_Wtime() - t0;
    return value;
}

std::string broadcast(const std::string& text) {
    std::uint64_t length = text.size();
    MPI_Bcast(&length, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    std::string out = world().rank == 0 ? text : std::string(length, ' ');
    if (length > 0) MPI_Bcast(out.data(), int(length), MPI_CHAR, 0, MPI_COMM_WORLD);
    return out;
}

int all_max(int value) {
    const double t0 = MPI_Wtime();
    int out = value;
    MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    waited += MPI_Wtime() - t0;
    return out;
}

void abort_all(int code) {
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (initialised && !finalised) MPI_Abort(MPI_COMM_WORLD, code);
    std::_Exit(code);
}

} // namespace drydem::parallel
