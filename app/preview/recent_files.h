// The previewer's recent material files, kept as JSON in $XDG_CONFIG_HOME/skinlayer/recent.json (or
// ~/.config/skinlayer/recent.json), newest first, at most kMaxRecentFiles.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace skinlayer {

inline constexpr std::size_t kMaxRecentFiles = 10;

// The file that holds the list, from the environment; nullopt when neither XDG_CONFIG_HOME nor HOME is set.
std::optional<std::filesystem::path> recent_files_path();

// The list in `file`; empty when the file is missing or unreadable (a damaged list is not worth an error).
std::vector<std::string> read_recent_files(const std::filesystem::path& file);

// The list with `path` (made absolute) first, without duplicates, cut to kMaxRecentFiles.
std::vector<std::string> with_recent_file(std::vector<std::string> list, const std::string& path);

// Writes the list atomically, creating the folder. Throws std::runtime_error naming the file on failure.
void write_recent_files(const std::filesystem::path& file, const std::vector<std::string>& list);

}  // namespace skinlayer
