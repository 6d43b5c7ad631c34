// The previewer's file exports that take a while (a MERL table, a Fourier BSDF or an RGL tensor: 0.5-3 s; a fitted
// shader: 0.5-3 s of fitting), on a
// thread of their own so that the window keeps drawing: one at a time, with its progress for the panel and its
// outcome when it ends. The thread is joined by the destructor (RAII); a job cannot be cancelled, since it only
// writes its own file.
#pragma once

#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "app/solution/material_solve.h"

namespace skinlayer {

enum class ExportFormat {
  Merl,       // the MERL BRDF .binary (app/export/merl_brdf.h)
  Bsdf,       // the tabulated Fourier BSDF .bsdf, SCATFUN (app/export/fourier_bsdf_export.h), at the default nodes
  Rgl,        // the RGL tensor file .rgl.bsdf in its spectral form, for pbrt-v4 and Mitsuba 3 (app/export/rgl_export.h)
  Blender,    // a Blender 3.4 script .py building the fitted Principled BSDF (app/export/blender_script.h)
  MaterialX,  // a MaterialX 1.39 document .mtlx with the fitted OpenPBR Surface (app/export/openpbr_materialx.h)
};

// The format's name in messages ("MERL", "SCATFUN", "RGL tensor", "Blender script", "MaterialX") and its file
// extension (".binary", ".bsdf", ".rgl.bsdf": both readers take any name, and it keeps the two .bsdf exports of one
// screenshot apart; ".py", ".mtlx").
const char* export_format_name(ExportFormat format);
const char* export_extension(ExportFormat format);

// The path with the format's extension in place of its own ("shot.png" -> "shot.binary"), kept as it is when it
// already ends with it ("a.rgl.bsdf" stays, rather than becoming "a.rgl.rgl.bsdf").
std::string with_export_extension(const std::string& path, ExportFormat format);

class ExportJob {
 public:
  ExportJob() = default;
  ExportJob(const ExportJob&) = delete;
  ExportJob& operator=(const ExportJob&) = delete;
  ~ExportJob();

  // Starts writing `tables` in `format` to path (a timestamped name in the current folder when empty).
  // Returns false, and starts nothing, while another export runs.
  bool start(ExportFormat format, const ColorTables& tables, std::string path);

  bool running() const { return running_.load(); }
  // "exporting PATH (MERL, 40 of 90 rows)" while running; empty otherwise.
  std::string progress() const;
  // The outcome of a job that has ended since the last call ("saved PATH (MERL, N bytes)" or the error), once.
  std::optional<std::string> take_outcome();

 private:
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<int> rows_done_{0};
  std::atomic<int> rows_total_{0};
  ExportFormat format_ = ExportFormat::Merl;  // written before the thread starts, read while it runs
  mutable std::mutex mutex_;  // guards path_ and outcome_
  std::string path_;
  std::optional<std::string> outcome_;
};

// The timestamped name of an export: skinlayer-YYYYMMDD-HHMMSS.binary (or .bsdf).
std::string timestamped_export_name(ExportFormat format);

}  // namespace skinlayer
