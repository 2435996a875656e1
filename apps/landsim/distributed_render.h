#pragma once
// One image rendered by every rank of an MPI world: rank 0 hands out chunks of tiles from a
// queue as ranks ask for work (and renders chunks itself between messages); the other ranks
// render their chunks and send the pixels back, every plane bit for bit. Tiles do not depend
// on who renders them, so the image equals a single-process render exactly. Rank 0 writes
// checkpoints of the finished prefix of tiles and resumes from them like a plain render.
#include "mpi_session.h"
#include "renderer/transport/render.h"

namespace landsim::app {

struct DistributedStats {
  double seconds = 0.0;
  double communication_seconds = 0.0;  // rank 0: in MPI calls (probe, send, receive)
  std::uint64_t rays = 0;              // all ranks
  int tiles_by_rank0 = 0;
};

// Every rank calls it for every image, in the same order. Rank 0 gets the image; the other
// ranks get an empty film.
renderer::Film render_distributed(const renderer::Renderer& renderer, const renderer::View& view,
                                  const renderer::RenderOptions& options, const MpiSession& session,
                                  DistributedStats* stats = nullptr);

}  // namespace landsim::app
