#pragma once
/// @file
/// Reading scenes and impulses from text (the scene format is in
/// docs/formats.md).

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

/// Reads and parses a scene file. Throws InputError if it cannot be read.
Scene load_scene(const std::string& path, RunControl* control = nullptr);

/// Parses an impulse given as "px,py[,pθ]" and checks its length against dof.
VectorQ parse_impulse(const std::string& text, int dof, const std::string& field = "--impulse");

}  // namespace fixel
