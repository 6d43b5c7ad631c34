#include "app/window/export_job.h"

#include <exception>
#include <filesystem>

#include "app/export/color_export.h"
#include "app/material/atomic_file.h"
#include "app/process/parallel_for.h"
#include "app/render/png_export.h"

namespace skinlayer {

std::string timestamped_merl_name() {
  return std::filesystem::path(timestamped_png_name()).replace_extension(".binary").string();
}

ExportJob::~ExportJob() {
  if (thread_.joinable()) thread_.join();
}

bool ExportJob::start_merl(const ColorTables& tables, std::string path) {
  if (running_.load()) return false;
  if (thread_.joinable()) thread_.join();
  if (path.empty()) path = timestamped_merl_name();
  {
    const std::lock_guard lock(mutex_);
    path_ = path;
  }
  rows_done_ = 0;
  rows_total_ = 0;
  running_ = true;
  thread_ = std::thread([this, tables, path] {
    std::string outcome;
    try {
      const std::string bytes = merl_file(
          tables,
          [this](int done, int total) {
            rows_done_ = done;
            rows_total_ = total;
          },
          parallel_for_threads);
      write_file_atomically(path, bytes);
      outcome = "saved " + path + " (MERL, " + std::to_string(bytes.size()) + " bytes)";
    } catch (const std::exception& error) {
      outcome = error.what();
    }
    {
      const std::lock_guard lock(mutex_);
      outcome_ = outcome;
    }
    running_ = false;
  });
  return true;
}

std::string ExportJob::progress() const {
  if (!running_.load()) return "";
  const std::lock_guard lock(mutex_);
  return "exporting " + path_ + " (MERL, " + std::to_string(rows_done_.load()) + " of " +
         std::to_string(rows_total_.load() == 0 ? 90 : rows_total_.load()) + " rows)";
}

std::optional<std::string> ExportJob::take_outcome() {
  const std::lock_guard lock(mutex_);
  std::optional<std::string> outcome = std::move(outcome_);
  outcome_.reset();
  return outcome;
}

}  // namespace skinlayer
