#include "fixel/progress.h"

namespace fixel {

namespace {
// This thread's innermost ControlScope: its control, the exact steps seen
// under the innermost ExactTask, the last poll of its control inside it, and
// the innermost ExactTask's name.
thread_local const RunControl* t_control = nullptr;
thread_local long t_steps = 0;
thread_local ControlScope::LastPoll t_last_poll;
thread_local bool t_loop = false;
thread_local const char* t_task = "exact arithmetic";
}  // namespace

void RunControl::note_poll(const char* task, long done, long total, const char* unit) const {
  if (t_loop && this == t_control) t_last_poll = {task, done, total, unit};
}

ControlScope::ControlScope(const RunControl* control, bool loop)
    : previous_(t_control), previous_steps_(t_steps), previous_poll_(t_last_poll), previous_loop_(t_loop) {
  t_control = control;
  t_steps = 0;
  t_last_poll = {};
  t_loop = loop;
}

ControlScope::~ControlScope() {
  t_control = previous_;
  t_steps = previous_steps_;
  t_last_poll = previous_poll_;
  t_loop = previous_loop_;
}

namespace internal {

void poll_exact_step() {
  if (t_control == nullptr) return;
  if (t_last_poll.task != nullptr)  // inside a loop that polls: told as its poll
    t_control->check_stop(t_last_poll.task, t_last_poll.done, t_last_poll.total, t_last_poll.unit);
  else
    t_control->check_stop(t_task, t_steps, 0, "exact steps");  // the steps done before this one
  ++t_steps;
}

ExactTask::ExactTask(const char* name) : previous_(t_task), previous_steps_(t_steps) {
  t_task = name;
  t_steps = 0;
}

ExactTask::~ExactTask() {
  t_task = previous_;
  t_steps = previous_steps_;
}

}  // namespace internal

}  // namespace fixel
