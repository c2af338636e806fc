#include "fixel/internal/flint_thread.h"

#include <flint/flint.h>

#include <thread>

namespace fixel::internal {

namespace {

// Read during static initialisation, which runs on the main thread.
const std::thread::id g_main_thread = std::this_thread::get_id();

struct FlintThreadCleanup {
  ~FlintThreadCleanup() {
    if (std::this_thread::get_id() != g_main_thread) flint_cleanup();
  }
};

}  // namespace

void free_flint_caches_at_thread_exit() { thread_local FlintThreadCleanup cleanup; }

}  // namespace fixel::internal
