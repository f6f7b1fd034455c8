#pragma once
// Output files are written whole or not at all: to a temporary file beside
// the target, then renamed over it, so a failure never leaves a partial file
// nor touches an existing one.
#include <optional>
#include <string>
#include <string_view>

namespace sandpic {

// Throws InputError naming the path if its folder is missing or not writable.
void check_writable(const std::string& path);
// The part of check_writable a new folder needs too: its own folder exists
// and is writable.
void check_parent_writable(const std::string& path);
void check_folder(const std::string& dir);  // creates it if missing
void write_atomic(const std::string& path, std::string_view bytes);
// For outputs written over a run (--frames, --video): a new empty folder,
// or file keeping the path's extension (a video writer picks its container
// by it), beside `path`; move_into_place renames it over `path` with the
// permissions a new one would get. Both throw InputError naming the path.
std::string temp_folder_beside(const std::string& path);
std::string temp_file_beside(const std::string& path);
void move_into_place(const std::string& tmp, const std::string& path);
// A whole file's bytes; nullopt if it cannot be read.
std::optional<std::string> read_text(const std::string& path);

}  // namespace sandpic
