// parse.h — the scene parser: reads a scene written in csgrt's strict subset
// of POV-Ray 3.7's scene language (docs/scene-language.md) and produces the
// Scene AST of scene.h. Every error is a csgrt::SceneError whose what() reads
// "file:line:col: message".
#pragma once

#include "scene.h"

#include <string>

namespace csgrt {

// Reads and parses the file at `path`. #include names are resolved relative
// to the folder of the file that contains the #include.
Scene parse_scene_file(const std::string& path);

// Parses `text` as if it were the contents of a file called `filename` (used
// only in error positions). #include names are resolved relative to the
// current working directory.
Scene parse_scene_string(const std::string& text, const std::string& filename);

}  // namespace csgrt
