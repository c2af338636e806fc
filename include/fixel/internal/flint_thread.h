#pragma once
// FLINT (and Arb, which registers its caches with FLINT) keeps per-thread
// caches that only flint_cleanup() frees. A thread other than the main one
// that calls FLINT would leak them when it ends, as a Python thread pool's
// threads do. The main thread's are FLINT's to free at exit.

namespace fixel::internal {

// Has the calling thread, if it is not the main thread, call
// flint_cleanup() when it ends. Call it before the caller's own
// thread_local FLINT-backed storage is first made, so that the cleanup
// runs after that storage is destroyed. Cheap after the first call.
void free_flint_caches_at_thread_exit();

}  // namespace fixel::internal
