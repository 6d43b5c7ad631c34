#include "app/preview/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/material/atomic_file.h"

namespace skinlayer {

std::optional<std::filesystem::path> recent_files_path() {
  const char* config = std::getenv("XDG_CONFIG_HOME");
  if (config != nullptr && config[0] == '/') return std::filesystem::path(config) / "skinlayer" / "recent.json";
  const char* home = std::getenv("HOME");
  if (home != nullptr && home[0] != '\0') return std::filesystem::path(home) / ".config" / "skinlayer" / "recent.json";
  return std::nullopt;
}

std::vector<std::string> read_recent_files(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return {};
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  std::vector<std::string> list;
  if (!json.is_object() || !json.contains("recent") || !json["recent"].is_array()) return list;
  for (const nlohmann::json& entry : json["recent"]) {
    if (entry.is_string() && list.size() < kMaxRecentFiles) list.push_back(entry.get<std::string>());
  }
  return list;
}

std::vector<std::string> with_recent_file(std::vector<std::string> list, const std::string& path) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  const std::string entry = error ? path : absolute.lexically_normal().string();
  list.erase(std::remove(list.begin(), list.end(), entry), list.end());
  list.insert(list.begin(), entry);
  if (list.size() > kMaxRecentFiles) list.resize(kMaxRecentFiles);
  return list;
}

void write_recent_files(const std::filesystem::path& file, const std::vector<std::string>& list) {
  std::error_code error;
  std::filesystem::create_directories(file.parent_path(), error);
  const nlohmann::json json = {{"recent", list}};
  write_file_atomically(file.string(), json.dump(2) + "\n");
}

}  // namespace skinlayer
