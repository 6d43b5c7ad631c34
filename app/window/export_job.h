// The previewer's file exports that take a while (the MERL table: 1-2 s), on a thread of their own so that the
// window keeps drawing: one at a time, with its progress for the panel and its outcome when it ends. The thread is
// joined by the destructor (RAII); a job cannot be cancelled, since it only writes its own file.
#pragma once

#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "app/render/material_solve.h"

namespace skinlayer {

class ExportJob {
 public:
  ExportJob() = default;
  ExportJob(const ExportJob&) = delete;
  ExportJob& operator=(const ExportJob&) = delete;
  ~ExportJob();

  // Starts writing the MERL table of `tables` to path (a timestamped name in the current folder when empty).
  // Returns false, and starts nothing, while another export runs.
  bool start_merl(const ColorTables& tables, std::string path);

  bool running() const { return running_.load(); }
  // "exporting MERL … (40 of 90 rows)" while running; empty otherwise.
  std::string progress() const;
  // The outcome of a job that has ended since the last call ("saved PATH (MERL, N bytes)" or the error), once.
  std::optional<std::string> take_outcome();

 private:
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<int> rows_done_{0};
  std::atomic<int> rows_total_{0};
  mutable std::mutex mutex_;  // guards path_ and outcome_
  std::string path_;
  std::optional<std::string> outcome_;
};

// The timestamped name of an export: skinlayer-YYYYMMDD-HHMMSS.binary.
std::string timestamped_merl_name();

}  // namespace skinlayer
