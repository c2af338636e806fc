#pragma once
/// @file
/// Reading scenes and impulses from text (the scene format is in
/// docs/formats.md).

#include <cstddef>
#include <istream>
#include <string>

#include "fixel/progress.h"
#include "fixel/scene.h"

namespace fixel {

/// Parses and validates a scene from JSON text. `source` names the input in
/// messages. Throws ParseError for malformed text or numbers, SceneError for
/// invalid values (each naming the JSON path and value), UnsupportedError for
/// valid requests not handled yet. `control` (may be null) is polled while
/// the outline is read, checked and integrated (task "load"): progress on
/// huge parts, and StoppedError past its deadline or when cancelled.
Scene parse_scene(const std::string& json_text, const std::string& source = "scene", RunControl* control = nullptr);

/// Reads and parses a scene file. Throws InputError if it cannot be read,
/// or is larger than kMaxSceneBytes (/dev/zero, say).
Scene load_scene(const std::string& path, RunControl* control = nullptr);

/// The largest scene text read: 256 MiB (a 100,000-edge outline in exact
/// decimals is a few MiB).
constexpr std::size_t kMaxSceneBytes = std::size_t(256) << 20;

/// Reads and parses a scene from a stream (standard input, say), at most
/// kMaxSceneBytes, polling `control` while it reads (task "load"). Throws
/// InputError naming `source` when it cannot be read or is too large.
Scene read_scene(std::istream& in, const std::string& source, RunControl* control = nullptr);

/// The scene in the scene-file format, as indented JSON text: every field
/// written (the defaults included), every number an exact string, friction
/// intervals as ["lo", "hi"]. The mass, inertia and centre of mass that the
/// outline gave (uniform density) are left out, so that parse_scene derives
/// them again, exactly, and keeps the flags saying so (a value flagged
/// derived but no longer what reading would derive, as one set in code
/// after loading, is written); with
/// `with_derived` they are written too (the values again, the flags not).
/// Invalid UTF-8 in a name or description set in code becomes U+FFFD.
/// Throws what check_scene_values throws (a scene built in code with, say,
/// an empty velocity), rather than write what reading would refuse.
std::string write_scene(const Scene& scene, bool with_derived = false);

/// Writes write_scene(scene) to the file `path`: first to a new file of a
/// fresh name beside it, then renamed over it, so an error leaves any
/// earlier file whole; a symbolic link is written through (its target
/// replaced or made), a read-only file is refused, and a path that is not
/// a regular file (a FIFO, a device, /dev/stdout) is refused. Throws
/// InputError(field "save_scene(path)", path) when it cannot be written.
void save_scene(const Scene& scene, const std::string& path);

/// Parses an impulse given as "px,py[,pθ]" and checks its length against dof.
VectorQ parse_impulse(const std::string& text, int dof, const std::string& field = "--impulse");

}  // namespace fixel
