#include "distributed_render.h"

#include <mpi.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <vector>

namespace landsim::app {
namespace {

enum Tag : int { kRequest = 1, kChunk = 2, kResult = 3 };
constexpr int kChunkTiles = 4;

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Asks rank 0 for chunks until told the image is done; sends each chunk's pixels back.
void work(const renderer::ViewRenderer& tiles) {
  renderer::Film film = tiles.new_film();
  for (;;) {
    MPI_Send(nullptr, 0, MPI_INT, 0, kRequest, MPI_COMM_WORLD);
    std::array<int, 2> chunk{};
    MPI_Recv(chunk.data(), 2, MPI_INT, 0, kChunk, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (chunk[0] < 0) return;
    const std::uint64_t rays = tiles.render_tiles(chunk[0], chunk[1], film);
    std::vector<std::uint32_t> words = renderer::pack_tiles(film, chunk[0], chunk[1]);
    // Header: first tile, last tile, rays (two words).
    words.insert(
        words.begin(),
        {static_cast<std::uint32_t>(chunk[0]), static_cast<std::uint32_t>(chunk[1]),
         static_cast<std::uint32_t>(rays & 0xffffffffu), static_cast<std::uint32_t>(rays >> 32)});
    MPI_Send(words.data(), static_cast<int>(words.size()), MPI_UINT32_T, 0, kResult,
             MPI_COMM_WORLD);
  }
}

class Coordinator {
 public:
  Coordinator(const renderer::ViewRenderer& tiles, const renderer::RenderOptions& options,
              const MpiSession& session)
      : tiles_(tiles),
        options_(options),
        session_(session),
        film_(tiles.new_film()),
        count_(tiles.tile_count()),
        done_(static_cast<std::size_t>(count_), false) {
    next_ = options.resume ? renderer::resume_checkpoint(options, film_, count_) : 0;
    for (int t = 0; t < next_; ++t) done_[static_cast<std::size_t>(t)] = true;
    finished_ = next_;
  }

  renderer::Film run(DistributedStats& stats) {
    const auto start = Clock::now();
    last_checkpoint_ = start;
    int stopped = 0;
    while (finished_ < count_ || stopped < session_.size() - 1) {
      MPI_Status status;
      int pending = 0;
      timed([&] { MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &pending, &status); });
      if (!pending && next_ < count_) {  // no one is waiting: render a chunk here
        const int first = next_, last = std::min(next_ + kChunkTiles, count_);
        next_ = last;
        stats.rays += tiles_.render_tiles(first, last, film_);
        stats.tiles_by_rank0 += last - first;
        finish(first, last);
        continue;
      }
      if (!pending) timed([&] { MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status); });
      stopped += serve(status, stats) ? 1 : 0;
    }
    if (!options_.checkpoint.empty()) {
      std::error_code ignored;
      std::filesystem::remove(options_.checkpoint, ignored);
    }
    stats.seconds = since(start);
    stats.communication_seconds = communication_;
    return std::move(film_);
  }

 private:
  template <typename Call>
  void timed(Call&& call) {
    const auto t = Clock::now();
    call();
    communication_ += since(t);
  }

  // Answers one message; true when it told a rank that this image is done.
  bool serve(const MPI_Status& status, DistributedStats& stats) {
    if (status.MPI_TAG == kRequest) {
      timed([&] {
        MPI_Recv(nullptr, 0, MPI_INT, status.MPI_SOURCE, kRequest, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
      });
      std::array<int, 2> chunk{-1, -1};
      if (next_ < count_) chunk = {next_, std::min(next_ + kChunkTiles, count_)}, next_ = chunk[1];
      timed([&] { MPI_Send(chunk.data(), 2, MPI_INT, status.MPI_SOURCE, kChunk, MPI_COMM_WORLD); });
      return chunk[0] < 0;
    }
    int size = 0;
    MPI_Get_count(&status, MPI_UINT32_T, &size);
    std::vector<std::uint32_t> words(static_cast<std::size_t>(size));
    timed([&] {
      MPI_Recv(words.data(), size, MPI_UINT32_T, status.MPI_SOURCE, kResult, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
    });
    const int first = static_cast<int>(words[0]), last = static_cast<int>(words[1]);
    stats.rays += words[2] | static_cast<std::uint64_t>(words[3]) << 32;
    words.erase(words.begin(), words.begin() + 4);
    renderer::unpack_tiles(words, first, last, film_);
    finish(first, last);
    return false;
  }

  // Marks tiles done; reports progress; checkpoints the finished prefix now and then.
  void finish(int first, int last) {
    for (int t = first; t < last; ++t) done_[static_cast<std::size_t>(t)] = true;
    const int before = finished_;
    finished_ += last - first;
    if (options_.progress && finished_ * 20 / count_ != before * 20 / count_)
      options_.progress(static_cast<double>(finished_) / count_);
    if (options_.checkpoint.empty() || since(last_checkpoint_) < options_.checkpoint_seconds)
      return;
    int prefix = 0;
    while (prefix < count_ && done_[static_cast<std::size_t>(prefix)]) ++prefix;
    if (prefix < count_) renderer::write_checkpoint(options_, film_, prefix);
    last_checkpoint_ = Clock::now();
  }

  const renderer::ViewRenderer& tiles_;
  const renderer::RenderOptions& options_;
  const MpiSession& session_;
  renderer::Film film_;
  int count_;
  std::vector<bool> done_;
  int next_ = 0;
  int finished_ = 0;
  double communication_ = 0.0;
  Clock::time_point last_checkpoint_;
};

}  // namespace

renderer::Film render_distributed(const renderer::Renderer& renderer, const renderer::View& view,
                                  const renderer::RenderOptions& options, const MpiSession& session,
                                  DistributedStats* stats) {
  const renderer::ViewRenderer tiles(renderer, view, options);
  if (options.started) options.started();
  DistributedStats local;
  DistributedStats& s = stats != nullptr ? *stats : local;
  if (session.rank() != 0) {
    work(tiles);
    return renderer::Film(0, 0);
  }
  return Coordinator(tiles, options, session).run(s);
}

}  // namespace landsim::app
