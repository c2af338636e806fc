#pragma once
/// @file
/// Cancellation, time limit and progress for loops whose length comes from
/// the input. Polled by simulate, enumerate_outcomes, guaranteed_set,
/// compute_region (RegionOptions::control), sample_region, plan_push,
/// parse_scene and load_scene (task "load", through make_boundary,
/// check_simple_loop and mass_properties), the design search (design,
/// design_batch, DesignSearch::start, through DesignOptions::control), and
/// physics::push and physics::validate_region (PushOptions::control). The
/// library only polls; installing signal handlers and exiting is the
/// caller's business (the CLI sets `cancel` from its SIGINT handler).

#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <sstream>
#include <string>

#include "fixel/error.h"

namespace fixel {

/// Why a run stopped early.
enum class StopReason { kInterrupted, kTimeLimit };

/// Thrown by RunControl::poll when the run is cancelled or past its
/// deadline. Not an InputError (the input was fine) and not an
/// InternalError; `what()` says what was done, e.g. "simulate: interrupted
/// after 1200 of 100000000 steps; no result".
class StoppedError : public Error {
 public:
  StoppedError(StopReason reason, const std::string& message, long done, long total)
      : Error(message), reason_(reason), done_(done), total_(total) {}
  StopReason reason() const { return reason_; }
  long done() const { return done_; }    ///< Units of work completed.
  long total() const { return total_; }  ///< Units asked for (0 if unknown).

 private:
  StopReason reason_;
  long done_, total_;
};

/// The hook a long loop polls once per unit of work.
struct RunControl {
  using Clock = std::chrono::steady_clock;

  /// Set (from any thread or a signal handler: std::atomic<bool> is
  /// lock-free) to stop the run at the next poll.
  std::atomic<bool> cancel{false};
  /// Stop at the first poll after this time.
  std::optional<Clock::time_point> deadline;
  /// Called with (task, done, total, unit) at most every `interval`,
  /// starting one `interval` after `start`; total is 0 when unknown.
  std::function<void(const char* task, long done, long total, const char* unit)> on_progress;
  std::chrono::milliseconds interval{1000};
  Clock::time_point start = Clock::now();

  /// A limit at or beyond this (about 32 years), +∞ included, sets no
  /// deadline: steady_clock's nanoseconds would overflow past 292 years,
  /// and a deadline before now would stop the run at once.
  static constexpr double kNoLimitSeconds = 1e9;

  /// Sets `deadline` to `seconds` (s, > 0) after `from`, or none for a limit
  /// of kNoLimitSeconds or more. Throws InputError naming `field` for a
  /// limit that is not > 0 (NaN included).
  void set_time_limit(double seconds, const std::string& field = "max_seconds", Clock::time_point from = Clock::now()) {
    if (!(seconds > 0)) {
      std::ostringstream shown;  // 0, -2.5, nan: not std::to_string's 0.000000
      shown << seconds;
      throw InputError(field, shown.str(), "must be a positive number of seconds");
    }
    if (seconds >= kNoLimitSeconds) {
      deadline.reset();
      return;
    }
    deadline = from + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  }

  /// Throws StoppedError if cancelled or past the deadline, with poll's
  /// message; reports no progress and changes nothing, so any thread may
  /// call it while another polls.
  void check_stop(const char* task, long done, long total, const char* unit) const {
    if (cancel.load(std::memory_order_relaxed)) stop(StopReason::kInterrupted, task, done, total, unit);
    if (deadline && Clock::now() >= *deadline) stop(StopReason::kTimeLimit, task, done, total, unit);
  }

  /// Throws StoppedError if cancelled or past the deadline; reports progress
  /// when due. `unit` names the work ("steps", "points", "segments").
  /// Inside a ControlScope for this control, an exact step's stop within
  /// the loop is told as this poll's (internal::poll_exact_step).
  void poll(const char* task, long done, long total, const char* unit) {
    note_poll(task, done, total, unit);
    if (cancel.load(std::memory_order_relaxed)) stop(StopReason::kInterrupted, task, done, total, unit);
    const auto now = Clock::now();
    if (deadline && now >= *deadline) stop(StopReason::kTimeLimit, task, done, total, unit);
    if (on_progress && now - start >= interval && now >= next_report_) {
      next_report_ = now + interval;
      on_progress(task, done, total, unit);
    }
  }

 private:
  [[noreturn]] static void stop(StopReason reason, const char* task, long done, long total, const char* unit) {
    std::string msg = std::string(task) + ": " +
                      (reason == StopReason::kInterrupted ? "interrupted" : "time limit reached") + " after " +
                      std::to_string(done) + (total > 0 ? " of " + std::to_string(total) : "") + " " + unit +
                      "; no result";
    throw StoppedError(reason, msg, done, total);
  }
  // Records this poll for the calling thread's ControlScope (src/progress.cpp).
  void note_poll(const char* task, long done, long total, const char* unit) const;
  Clock::time_point next_report_{};
};

/// Polls `control` if there is one.
inline void poll(RunControl* control, const char* task, long done, long total, const char* unit) {
  if (control) control->poll(task, done, total, unit);
}

/// Makes `control` (or none) the control of the exact steps on the calling
/// thread that take none of their own, for the life of the scope: the
/// seated pose, building J and J′ (sustained_set, approach_set) and their
/// region targets, J′'s wrench tests, one exact LCP, the outcomes of one
/// impulse, a B-spline curve's Bézier pieces. With numbers of thousands
/// of digits one such step can take minutes; inside it, cancel and the
/// deadline are checked (RunControl::check_stop, no progress report) and
/// end it with StoppedError, e.g. "sustained set J: time limit reached after
/// 412 exact steps; no result". Scopes nest; the innermost wins. Threads
/// started inside do not inherit it.
///
/// Inside a library function that polls the control in its own loop
/// (simulate's steps, the region's segments), an exact step's stop is told
/// as that loop's last poll: "simulate: time limit reached after 1529 of
/// 100000000 steps; no result", as its own poll would say.
class ControlScope {
 public:
  explicit ControlScope(const RunControl* control) : ControlScope(control, false) {}
  /// `loop`: the scope of a function that polls `control` in its own loop;
  /// its polls are then recorded for the stop message above. A caller's
  /// scope records none, so that no finished loop's poll (a file's reading)
  /// names a later stop.
  ControlScope(const RunControl* control, bool loop);
  ~ControlScope();
  ControlScope(const ControlScope&) = delete;
  ControlScope& operator=(const ControlScope&) = delete;

  /// The last poll of the scope's control inside a loop's scope (task
  /// null: none, or not a loop's scope).
  struct LastPoll {
    const char* task = nullptr;
    long done = 0, total = 0;
    const char* unit = nullptr;
  };

 private:
  const RunControl* previous_;
  long previous_steps_;
  LastPoll previous_poll_;
  bool previous_loop_;
};

namespace internal {
/// Checks the calling thread's ControlScope, if any: one exact step of the
/// innermost ExactTask.
void poll_exact_step();

/// A loop's ControlScope for `control` when one is given; else the
/// caller's scope stays (the library's functions that take a control and
/// poll it in a loop open one).
class ControlScopeIfGiven {
 public:
  explicit ControlScopeIfGiven(const RunControl* control) {
    if (control) scope_.emplace(control, true);
  }

 private:
  std::optional<ControlScope> scope_;
};

/// Names the exact steps polled on this thread for the life of the scope
/// (the stop message's task, e.g. "sustained set J").
class ExactTask {
 public:
  explicit ExactTask(const char* name);
  ~ExactTask();
  ExactTask(const ExactTask&) = delete;
  ExactTask& operator=(const ExactTask&) = delete;

 private:
  const char* previous_;
  long previous_steps_;
};
}  // namespace internal

}  // namespace fixel
