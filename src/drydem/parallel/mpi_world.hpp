// SPDX-License-Identifier: MIT
// MPI for the whole process, started once (docs/parallel.md). Two users share it: the domain
// decomposition of a run launched as several ranks (mpirun, srun), and hypre's conduction solves,
// which need MPI even in a one-process run (a singleton on MPI_COMM_SELF).
#pragma once
#include <string>

namespace drydem::parallel {

/// The rank count a launcher started this process with, from its environment (Open MPI's mpirun:
/// OMPI_COMM_WORLD_SIZE; Slurm's srun and other PMI launchers: PMI_SIZE, PMIX_SIZE is not set by
/// every PMIx, so SLURM_NTASKS with SLURM_STEP_ID); 1 when none started it.
int launcher_ranks();

/// Starts MPI once per process (thread level serialized: one thread calls at a time, not always
/// the same one), or does nothing when it runs already. In a one-process run it keeps Open MPI
/// from probing networks (OMPI_MCA_btl=self unless set). Throws RunError when MPI does not start.
void start_mpi();

/// Whether an MPI launcher (mpirun, or srun with PMI) started this process, even as one rank.
bool launched();

/// Ends MPI if this process started it under a launcher (which counts a rank that exits without
/// it as failed). A singleton, started without one, is never finalised: Open MPI's finalize
/// unloads plugins that hypre's objects still reference at exit.
void finish_mpi();

struct World {
    int rank = 0, size = 1;
};
/// This process's rank and the rank count of MPI_COMM_WORLD ({0, 1} while MPI is not started).
World world();

// What the ranks of one run agree on over MPI_COMM_WORLD (the run's root is rank 0). Each is a
// collective: every rank must call it, in the same order.

/// Rank 0's value, on every rank.
[[nodiscard]] int broadcast(int value);
/// Rank 0's text, on every rank.
[[nodiscard]] std::string broadcast(const std::string& text);
/// The largest value over the ranks.
[[nodiscard]] int all_max(int value);

/// Wall seconds this process has spent inside MPI waiting for other ranks (broadcast, all_max
/// above, and the halo's exchanges and reductions): what the balancing subtracts from the elapsed
/// time to find a rank's own work.
[[nodiscard]] double waited_seconds();
/// Adds to waited_seconds() (the halo's exchanges and reductions report their time here).
void add_waited(double seconds);

/// Ends every rank of the launch at once (MPI_Abort): for a failure on one rank that the others
/// cannot learn of, so that no rank waits forever in an exchange. Without MPI it exits.
[[noreturn]] void abort_all(int code);

} // namespace drydem::parallel
