#include "mpi_session.h"

#include <cstdlib>

#include <fmt/format.h>

#ifdef LANDSIM_HAVE_MPI
#include <mpi.h>
#endif

namespace landsim::app {
namespace {

const MpiSession* g_session = nullptr;

#ifdef LANDSIM_HAVE_MPI
// Launched by an MPI starter: OpenMPI's mpirun, or a PMI-based one (Slurm's srun).
bool launched_by_mpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr ||
         std::getenv("PMIX_RANK") != nullptr;
}
#endif

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
#ifdef LANDSIM_HAVE_MPI
  if (launched_by_mpi()) {
    int provided = 0;
    // Only the main thread calls MPI; the renderer's workers are TBB threads.
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
    MPI_Comm_size(node, &ranks_on_node_);
    MPI_Comm_free(&node);
    initialised_ = true;
  }
#else
  (void)argc;
  (void)argv;
#endif
  g_session = this;
}

MpiSession::~MpiSession() {
#ifdef LANDSIM_HAVE_MPI
  if (initialised_) MPI_Finalize();
#endif
  g_session = nullptr;
}

std::string MpiSession::label() const {
  return distributed() ? fmt::format("rank {} of {}: ", rank_, size_) : std::string();
}

void MpiSession::abort(int code) const {
#ifdef LANDSIM_HAVE_MPI
  if (initialised_) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

const MpiSession* current_session() { return g_session; }

}  // namespace landsim::app
