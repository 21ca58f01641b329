// What the solve worker does next, and what its cache keeps (solve_worker.h, "Timeline mode").
// Everything here runs under the worker's lock.
#include "playback/solve_worker_impl.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>

namespace ib::play {

void SolveWorker::Impl::insert(int index, std::shared_ptr<const AnimationFrame> frame) {
  cache_.emplace(index, std::move(frame));  // a frame solved again on the way keeps its first solve
  while (static_cast<int>(cache_.size()) > options_.cacheFrames) {
    auto farthest = cache_.begin();
    for (auto it = cache_.begin(); it != cache_.end(); ++it)
      if (distance(it->first) > distance(farthest->first)) farthest = it;
    cache_.erase(farthest);
  }
}

int SolveWorker::Impl::distance(int frame) const {
  const int d = std::abs(frame - wanted_);
  return timeline_.loops() ? std::min(d, frameCount_ - d) : d;
}

int SolveWorker::Impl::checkpointBelow(int frame) const {
  auto it = checkpoints_.upper_bound(frame);
  return it == checkpoints_.begin() ? 0 : std::prev(it)->first;
}

bool SolveWorker::Impl::reachable(int frame) const {
  if (!dynamics_) return !failed_.count(frame);
  const auto it = failed_.lower_bound(checkpointBelow(frame));
  return it == failed_.end() || *it > frame;
}

SolveWorker::Impl::Job SolveWorker::Impl::towards(int frame, bool wanted) const {
  Job job;
  job.kind = Job::Kind::kFrame;
  job.generation = generation_;
  job.wanted = wanted;
  job.target = frame;
  if (dynamics_) {
    const int from = checkpointBelow(frame);
    if (streamNext_ >= from && streamNext_ <= frame) {
      job.frame = streamNext_;
    } else {
      job.frame = from;
      job.resume = true;
      if (const auto it = checkpoints_.find(from); it != checkpoints_.end()) job.checkpoint = it->second;
    }
    return job;
  }
  job.frame = frame;
  if (streamNext_ != frame) {
    job.seek = true;
    const auto next = cache_.find(frame - 1), after = cache_.find(frame + 1);
    if (next != cache_.end()) {
      job.neighbour = next->second;
    } else if (after != cache_.end()) {
      job.neighbour = after->second;
    }  // else a cold start: a frame of other parameters could hold the energy's other minimum

  }
  return job;
}

SolveWorker::Impl::Job SolveWorker::Impl::plan() const {
  Job job;
  if (pending_) {
    job.kind = Job::Kind::kApply;
    job.generation = generation_;
    job.parameters = *pending_;
    return job;
  }
  if (!built_ || frameCount_ == 0) return job;
  if (weightsMode_) {
    if (stillDone_ == request_) return job;
    job.kind = Job::Kind::kStill;
    job.generation = generation_;
    job.weights = weights_;
    job.request = request_;
    return job;
  }
  if (!cache_.count(wanted_)) return reachable(wanted_) ? towards(wanted_, true) : job;
  if (!ahead_) return job;
  // Ahead of the wanted frame while the cache has room, or the frame is nearer than its farthest.
  int farthest = 0;
  for (const auto& entry : cache_) farthest = std::max(farthest, distance(entry.first));
  const bool full = static_cast<int>(cache_.size()) >= options_.cacheFrames;
  for (int k = 1; k < frameCount_; ++k) {
    int frame = wanted_ + k;
    if (frame >= frameCount_) {
      if (!timeline_.loops()) break;
      frame -= frameCount_;
    }
    if (cache_.count(frame)) continue;
    if (full && distance(frame) >= farthest) break;
    if (!reachable(frame)) {
      if (dynamics_) break;  // every later frame depends on it
      continue;
    }
    return towards(frame, false);
  }
  return job;
}

bool SolveWorker::Impl::idle() const {
  if (pending_ || running_.kind == Job::Kind::kApply) return false;
  if (!built_ || frameCount_ == 0) return true;  // nothing can be solved (Stats::error says why)
  if (weightsMode_) return stillDone_ == request_;
  return cache_.count(wanted_) || !reachable(wanted_);
}

}  // namespace ib::play
