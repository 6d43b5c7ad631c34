// The previewer's background solver: one std::jthread that turns SolveRequests into fitted tables and their GPU
// texture data (solve_color + make_table_textures), so the UI thread never waits on a solve.
//
// Contract:
//  - submit() and poll() only lock a mutex around a move of a small struct: they never wait for a solve.
//  - Newest parameters win. At most one request is pending: a submit replaces a pending one that has not started
//    (coalescing). A solve in progress when a newer request arrives is abandoned at core's next cancellation point
//    (SolveOptions::cancelled) and never published; the worker then takes the newest.
//  - Two phases where the full resolution is costly (core's preview_is_coarser: small sigma, strong forward
//    scattering, near-matched interfaces): a preview at capped resolution (SolveOptions::preview, tens of ms) is
//    published first, with SolveResult::preview set, then the full solve of the same request unless a newer one has
//    arrived. So a dragged slider shows every step at the preview's pace and the picture settles on the full solve
//    when the mouse stops.
//  - poll() hands out the newest published result not yet polled, exactly once. Results only ever come out in
//    increasing (generation, phase) order.
//  - Destruction requests stop, abandons a solve in progress at its next cancellation point and joins the thread.
#pragma once

#include <array>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>

#include "app/preview/solve_request.h"
#include "app/render/table_textures.h"
#include "app/solution/material_solve.h"
#include "core/solve/solve_cache.h"

namespace skinlayer {

struct SolveResult {
  std::uint64_t generation = 0;  // the value submit() returned for the request this answers
  SolveRequest request;
  // Every model needed_models() asks for, indexed by SubsurfaceModel (the renderer slot of that model), and its
  // tables in the GPU layout (shaders/table_layout.h). When error is set only the sphere's model is engaged, empty.
  std::array<std::optional<ColorTables>, 3> by_model;
  std::array<TableTextureData, 3> textures_by_model;
  std::string error;     // non-empty: the request was rejected (ParameterError's message) or the solve failed
  double seconds = 0.0;  // wall time of the solve and the texture build
  bool preview = false;  // solved at the preview's capped resolution; the full solve of this request follows

  // The sphere's model (request.material.model): its tables and their GPU layout; empty when error is set.
  const ColorTables& tables() const { return *by_model[static_cast<std::size_t>(request.material.model)]; }
  const TableTextureData& textures() const {
    return textures_by_model[static_cast<std::size_t>(request.material.model)];
  }
};

// Runs one request on the calling thread: what the worker does for each phase of a job (options.preview picks the
// phase). Exceptions become SolveResult::error, except SolveCancelled, which propagates. `options` carry the
// worker's cache of interface operators, the parallel-for over the RGB channels and the cancellation check.
SolveResult compute_solve(const SolveRequest& request, std::uint64_t generation, const SolveOptions& options = {});

// What the worker runs for each phase of a job: compute_solve, unless the owner gives another (the tests give one
// that holds a solve on a latch, or watches its cancellation checks, and then calls compute_solve).
using SolveFunction =
    std::function<SolveResult(const SolveRequest& request, std::uint64_t generation, const SolveOptions& options)>;

// How many solves ran and how many of their results were discarded as stale (for tests and diagnostics).
struct SolveWorkerStats {
  std::uint64_t solved = 0;     // solves run to the end (previews and full solves)
  std::uint64_t discarded = 0;  // of those, superseded before they could be published
  std::uint64_t previews = 0;   // previews published
  std::uint64_t cancelled = 0;  // solves abandoned part-way, or refinements never begun, for a newer request (or for
                                // shutdown)
  std::size_t cache_bytes = 0;  // what the worker's SolveCache holds after its last solve (its budget bounds it)
};

class SolveWorker {
 public:
  // on_published is called on the worker thread, without the lock held, each time a result becomes available to
  // poll() (the window passes glfwPostEmptyEvent to wake its event loop). It must not call back into the worker.
  // `solve` runs each phase on the worker thread (SolveFunction).
  explicit SolveWorker(std::function<void()> on_published = {}, SolveFunction solve = compute_solve);
  ~SolveWorker() = default;  // the jthread member requests stop and joins

  SolveWorker(const SolveWorker&) = delete;
  SolveWorker& operator=(const SolveWorker&) = delete;

  // Queues the request, replacing any pending one, and returns its generation (1, 2, 3, ...).
  std::uint64_t submit(SolveRequest request);

  // The newest finished result not yet polled, if any. Never blocks on a solve.
  std::optional<SolveResult> poll();

  // True while the newest submission has no result published yet (pending or being solved): newer parameters
  // submitted now would only wait.
  bool busy() const;

  // True until the newest submission's final (full-resolution, or failed) result is published: false means what
  // poll() gives or gave last is the settled answer to the newest parameters.
  bool settling() const;

  SolveWorkerStats stats() const;

 private:
  void run(std::stop_token stop);
  bool superseded(std::uint64_t generation, const std::stop_token& stop) const;
  // Makes `result` the one poll() hands out if it still answers the newest submission; true if it did.
  bool publish(SolveResult&& result, bool final_result);

  std::function<void()> on_published_;
  SolveFunction solve_;
  mutable std::mutex mutex_;
  std::condition_variable_any wake_;
  std::optional<SolveRequest> pending_;  // the newest request, not started yet
  std::uint64_t submitted_ = 0;          // generation of the newest submit()
  std::uint64_t published_ = 0;          // generation of the newest result made available to poll()
  std::uint64_t settled_ = 0;            // generation of the newest final result made available to poll()
  std::optional<SolveResult> finished_;  // published, not yet polled
  SolveWorkerStats stats_;
  SolveCache cache_;     // used by the worker thread only: re-solves that keep the interfaces reuse their operators
  std::jthread thread_;  // last: started after every member above exists, joined before they go
};

}  // namespace skinlayer
