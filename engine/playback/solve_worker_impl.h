// The solve worker's state and steps, behind SolveWorker's pointer (solve_worker.h says what they
// do). For the worker's own files: solve_worker.cpp (the thread, the solves, the UI's calls) and
// solve_worker_plan.cpp (what to solve next, and what the cache keeps).
#pragma once

#include "playback/solve_worker.h"

#include <atomic>
#include <condition_variable>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>

namespace ib::play {

class SolveWorker::Impl {
 public:
  struct Parameters {
    InterpolationParams interpolation;
    DynamicsParams dynamics;
    Eigen::VectorXd kappa;  // t x 1
  };

  // One piece of the worker's work, chosen under the lock (plan) and done without it (run).
  struct Job {
    enum class Kind { kNone, kApply, kStill, kFrame };
    Kind kind = Kind::kNone;
    long generation = 0;  // the parameter set it solves with
    Parameters parameters;  // kApply
    Eigen::VectorXd weights;  // kStill
    long request = 0;         // kStill: which showWeights
    int frame = -1;           // kFrame: the frame solved
    int target = -1;          // kFrame: the frame it is for (frame, or a later one on the way)
    bool wanted = false;      // kFrame: for the wanted frame (or on the way to it), not solving ahead
    bool resume = false;      // kFrame, dynamics: resume from `checkpoint` first (restart if empty)
    FrameStream::Checkpoint checkpoint;
    bool seek = false;        // kFrame, no dynamics: seek to `frame` first, warm from `neighbour`
    std::shared_ptr<const AnimationFrame> neighbour;
  };

  // Checks parameters for `mesh` as the constructor does (InputError naming the field).
  static void validate(const Multimesh& mesh, const Parameters& parameters);

  Impl(std::shared_ptr<const Multimesh> mesh, Timeline timeline, Parameters parameters, const Options& options);
  ~Impl();
  void setParameters(Parameters parameters);
  void showFrame(int index);
  void showWeights(const Eigen::VectorXd& w);
  void setSolveAhead(bool on);
  std::shared_ptr<const AnimationFrame> latest() const;
  std::shared_ptr<const AnimationFrame> cached(int index) const;
  Stats stats() const;
  bool waitIdle(double seconds);
  const Multimesh& mesh() const { return *mesh_; }

 private:
  // Worker thread: waits for a job, runs it, records its outcome.
  void run();
  void apply(const Job& job);
  std::optional<AnimationFrame> solve(const Job& job);
  void record(const Job& job, std::optional<AnimationFrame> frame, const std::string& error);
  // Under the lock: what to do next (kNone: nothing, wait).
  Job plan() const;
  Job towards(int frame, bool wanted) const;  // the next solve on the way to `frame`
  bool reachable(int frame) const;            // no failed solve on the way to it
  int distance(int frame) const;              // from the wanted frame, around a loop
  int checkpointBelow(int frame) const;       // the nearest checkpoint's frame at or before it
  bool idle() const;                          // the wanted frame or still is solved (or failed)
  void cancelUnless(bool useful);             // cancels the running solve unless still useful
  void insert(int index, std::shared_ptr<const AnimationFrame> frame);

  // Fixed.
  const std::shared_ptr<const Multimesh> mesh_;
  const Timeline timeline_;
  const Options options_;
  const int frameCount_;
  SolverOptions solverOptions_;

  // Worker thread only.
  std::optional<FrameStream> stream_;
  std::optional<Interpolator> still_;
  Eigen::MatrixX2d stillStart_;  // the last still's positions (n x 2; empty before the first)
  Parameters applied_;
  std::atomic<bool> cancel_{false};  // read by the solvers; set under the lock, cleared per job

  // Shared, under mutex_.
  mutable std::mutex mutex_;
  std::condition_variable wake_;  // the worker waits for work
  std::condition_variable done_;  // waitIdle waits for outcomes
  bool stop_ = false;
  std::optional<Parameters> pending_;  // the newest parameters, not yet applied
  long generation_ = 0;                // parameter sets given; the applied one once pending_ is empty
  bool built_ = false;                 // the stream exists
  bool dynamics_ = false;              // the applied parameters have dynamics
  int streamNext_ = 0;                 // stream_->nextFrame()
  bool weightsMode_ = false;
  bool ahead_ = true;                  // setSolveAhead
  int wanted_ = 0;
  Eigen::VectorXd weights_;            // showWeights
  long request_ = 0, stillDone_ = -1;  // showWeights calls; the one last solved or failed
  std::map<int, std::shared_ptr<const AnimationFrame>> cache_;
  std::map<int, FrameStream::Checkpoint> checkpoints_;  // with dynamics, by frame (0 always)
  std::set<int> failed_;               // frames whose solve threw with these parameters
  // The most recently solved frame or still that was wanted when it was solved, and the most
  // recently solved one of all.
  std::shared_ptr<const AnimationFrame> picture_, lastSolved_;
  struct Running {  // what cancelUnless needs of the job under way
    Job::Kind kind = Job::Kind::kNone;
    int frame = -1;
    bool wanted = false;
  } running_;
  Stats stats_;
  std::thread thread_;                 // last: started once everything above is set
};

}  // namespace ib::play
