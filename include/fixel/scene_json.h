#pragma once
/// @file
/// Reading scenes and impulses from text (the scene format is in
/// docs/formats.md).

#include <string>

#include "fixel/scene.h"

namespace fixel {

/// Parses and validates a scene from JSON text. `source` names the input in
/// messages. Throws ParseError for malformed text or numbers, SceneError for
/// invalid values (each naming the JSON path and value), UnsupportedError for
/// valid requests not handled yet.
Scene parse_scene(const std::string& json_text, const std::string& source = "scene");

/// Reads and parses a scene file. Throws InputError if it cannot be read.
Scene load_scene(const std::string& path);

/// Parses an impulse given as "px,py[,pθ]" and checks its length against dof.
VectorQ parse_impulse(const std::string& text, int dof, const std::string& field = "--impulse");

}  // namespace fixel
