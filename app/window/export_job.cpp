#include "app/window/export_job.h"

#include <exception>
#include <filesystem>
#include <string_view>

#include "app/export/fitted_export.h"
#include "app/export/material_export.h"
#include "app/material/atomic_file.h"
#include "app/process/parallel_for.h"
#include "app/render/png_export.h"

namespace skinlayer {

const char* export_format_name(ExportFormat format) {
  switch (format) {
    case ExportFormat::Merl:
      return "MERL";
    case ExportFormat::Bsdf:
      return "SCATFUN";
    case ExportFormat::Rgl:
      return "RGL tensor";
    case ExportFormat::Blender:
      return "Blender script";
    case ExportFormat::MaterialX:
      return "MaterialX";
  }
  return "";
}
const char* export_extension(ExportFormat format) {
  switch (format) {
    case ExportFormat::Merl:
      return ".binary";
    case ExportFormat::Bsdf:
      return ".bsdf";
    case ExportFormat::Rgl:
      return ".rgl.bsdf";
    case ExportFormat::Blender:
      return ".py";
    case ExportFormat::MaterialX:
      return ".mtlx";
  }
  return "";
}

std::string with_export_extension(const std::string& path, ExportFormat format) {
  const std::string_view extension = export_extension(format);
  if (path.ends_with(extension)) return path;
  return std::filesystem::path(path).replace_extension(extension).string();
}

std::string timestamped_export_name(ExportFormat format) {
  return std::filesystem::path(timestamped_png_name()).replace_extension(export_extension(format)).string();
}

ExportJob::~ExportJob() {
  if (thread_.joinable()) thread_.join();
}

bool ExportJob::start(ExportFormat format, const ColorTables& tables, std::string path) {
  if (running_.load()) return false;
  if (thread_.joinable()) thread_.join();
  if (path.empty()) path = timestamped_export_name(format);
  format_ = format;
  {
    const std::lock_guard lock(mutex_);
    path_ = path;
  }
  rows_done_ = 0;
  rows_total_ = 0;
  running_ = true;
  thread_ = std::thread([this, format, tables, path] {
    std::string outcome;
    try {
      const auto progress = [this](int done, int total, std::string_view) {
        rows_done_ = done;
        rows_total_ = total;
      };
      std::string bytes;
      if (format == ExportFormat::Blender || format == ExportFormat::MaterialX) {  // a fit, then a small text
        FittedExportSettings fitted;
        fitted.format = format == ExportFormat::Blender ? FittedFormat::BlenderScript : FittedFormat::MaterialX;
        bytes = fitted_export_text(material_document(tables.material), fitted, parallel_for_threads);
      } else {
        SolveOptions options;  // the upside-down solve of a Fourier BSDF, a skin's wavelengths
        options.parallel_for = parallel_for_threads;
        ExportSettings settings;
        settings.format = format == ExportFormat::Merl   ? TabulatedFormat::Merl
                          : format == ExportFormat::Bsdf ? TabulatedFormat::Scatfun
                                                         : TabulatedFormat::RglSpectral;
        settings.description = rgl_description(material_document(tables.material));
        bytes = export_bytes(tables, settings, options, progress);
      }
      write_file_atomically(path, bytes);
      outcome = "saved " + path + " (" + export_format_name(format) + ", " + std::to_string(bytes.size()) + " bytes)";
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
  const int total = rows_total_.load();
  return "exporting " + path_ + " (" + export_format_name(format_) + ", " +
         (total == 0 ? std::string(format_ == ExportFormat::Blender || format_ == ExportFormat::MaterialX ? "fitting"
                                                                                                          : "solving")
                     : std::to_string(rows_done_.load()) + " of " + std::to_string(total) + " rows") +
         ")";
}

std::optional<std::string> ExportJob::take_outcome() {
  const std::lock_guard lock(mutex_);
  std::optional<std::string> outcome = std::move(outcome_);
  outcome_.reset();
  return outcome;
}

}  // namespace skinlayer
