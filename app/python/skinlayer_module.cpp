// The compiled half of the Python package `skinlayer` (app/python/skinlayer/__init__.py is the other, with the
// documented API): material documents from command-line arguments, solves, and their evaluation, albedo, tables
// and export, each through the same function as the command line (app/solution, app/export/material_export.h).
// Work that takes time runs with the GIL released and stops at Ctrl-C (interruptible.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/export_flags.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/cli/skin_flag.h"
#include "app/cli/theta_list.h"
#include "app/cli/unscattered_flag.h"
#include "app/export/fitted_export.h"
#include "app/export/material_export.h"
#include "app/material/atomic_file.h"
#include "app/material/material_file.h"
#include "app/material/material_json.h"
#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/python/interruptible.h"
#include "app/solution/document_albedo.h"
#include "app/solution/document_profile.h"
#include "app/solution/material_solve.h"
#include "app/solution/pair_evaluation.h"
#include "app/solution/solved_document.h"
#include "core/conventions.h"
#include "core/solve/solve_options.h"

namespace py = pybind11;

namespace skinlayer::python {
namespace {

// A material document solved with one model: what Solution wraps.
struct Solution {
  MaterialDocument document;  // at --wavelength when one was given
  SolvedDocument solved;
  std::shared_ptr<UnscatteredLobeCache> lobes = std::make_shared<UnscatteredLobeCache>();  // built by a first eval
};

cli::ParsedFlags parse(const std::vector<std::string>& arguments, std::span<const std::string_view> known,
                       std::string_view command, std::span<const std::string_view> switches = {}) {
  const std::vector<std::string_view> views(arguments.begin(), arguments.end());
  return cli::ParsedFlags::parse(views, known, command, switches);
}

MaterialDocument document_from_arguments(const std::vector<std::string>& arguments) {
  const cli::ParsedFlags flags = parse(arguments, cli::material_flags_and({cli::kSkinFlag}), "skinlayer.Material");
  return cli::material_document_from_flags(flags, cli::AlbedoFlag::GreyOrRgb);
}

Solution solve_material(const MaterialDocument& material, const std::vector<std::string>& arguments) {
  const std::string_view known[] = {cli::kModelFlag, cli::kWavelengthFlag};
  const cli::ParsedFlags flags = parse(arguments, known, "skinlayer.solve");
  Solution solution{material, {}};
  if (const std::optional<double> wavelength = cli::wavelength_from_flags(flags)) {
    solution.document = cli::document_at_wavelength(material, *wavelength);
  }
  const SubsurfaceModel model = cli::model_from_flags(flags, solution.document.model);
  solution.solved = run_interruptible([&](const std::function<bool()>& cancelled) {
    return solve_document(solution.document, model, parallel_for_threads, cancelled);
  });
  return solution;
}

using InputArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::span<const double> flat(const InputArray& array, const char* name) {
  if (array.ndim() != 1) throw ParameterError(std::string(name) + " must be one-dimensional");
  return {array.data(), static_cast<std::size_t>(array.size())};
}

py::array_t<double> values(std::size_t count, int channels) {
  if (channels == 1) return py::array_t<double>(static_cast<py::ssize_t>(count));
  return py::array_t<double>({static_cast<py::ssize_t>(count), static_cast<py::ssize_t>(channels)});
}

std::span<double> span_of(py::array_t<double>& array) {
  return {array.mutable_data(), static_cast<std::size_t>(array.size())};
}

// (brdf_surface, brdf_subsurface, brdf, btdf): n values, or n x 3 for a colour material.
py::tuple eval(const Solution& solution, const InputArray& theta_i, const InputArray& theta_o, const InputArray& phi,
               const std::string& unscattered) {
  const UnscatteredLobe lobe = cli::unscattered_lobe_named(unscattered);
  const std::span<const double> ti = flat(theta_i, "theta_i"), to = flat(theta_o, "theta_o"), p = flat(phi, "phi");
  const int channels = value_channels(solution.solved);
  py::array_t<double> surface = values(ti.size(), 1), subsurface = values(ti.size(), channels),
                      brdf = values(ti.size(), channels), btdf = values(ti.size(), channels);
  const BsdfArrays out{span_of(surface), span_of(subsurface), span_of(brdf), span_of(btdf)};
  run_interruptible([&](const std::function<bool()>& cancelled) {
    evaluate_pairs(solution.solved, ti, to, p, out, parallel_for_threads, cancelled, lobe, solution.lobes.get());
    return true;
  });
  return py::make_tuple(surface, subsurface, brdf, btdf);
}

// The spatial profile at radii in the document's unit: (unit, reflectance per channel, transmittance per channel).
// Not interruptible: it has no cancellation points yet (about 2 s per channel).
py::tuple profile(const Solution& solution, const std::vector<double>& radii, bool diffuse) {
  ProfileRequest request;
  request.incidence = diffuse ? Incidence::Diffuse : Incidence::Normal;
  const DocumentProfile p = document_profile_at_radii(solution.document, radii, request);
  return py::make_tuple(p.unit, p.reflectance, p.transmittance);
}

// Per channel, a dict of the albedo command's columns (without their _r, _g, _b), each one value per angle.
py::list albedo(const Solution& solution, const std::string& theta_list) {
  if (solution.solved.model != SubsurfaceModel::Stam) {
    throw ParameterError("albedo is the layer model's (stam) and this solution is the " +
                         std::string(subsurface_model_name(solution.solved.model)) +
                         " model's; solve with model='stam'");
  }
  const std::vector<double> degrees = cli::parse_theta_list(theta_list);
  std::vector<double> radians;
  for (const double theta : degrees) radians.push_back(degrees_to_radians(theta));
  const std::vector<std::vector<DirectionalAlbedo>> channels =
      run_interruptible([&](const std::function<bool()>& cancelled) {
        return document_albedo(solution.document, radians, parallel_for_threads, cancelled);
      });
  py::list result;
  for (const std::vector<DirectionalAlbedo>& rows : channels) {
    std::vector<double> surface, subsurface, reflectance, transmittance, absorptance;
    std::vector<std::vector<double>> layers(rows.front().layer_absorptance.size());
    for (const DirectionalAlbedo& row : rows) {
      surface.push_back(row.reflectance_surface);
      subsurface.push_back(row.reflectance_subsurface);
      reflectance.push_back(row.reflectance());
      transmittance.push_back(row.transmittance);
      absorptance.push_back(row.absorptance);
      for (std::size_t i = 0; i < layers.size(); ++i) layers[i].push_back(row.layer_absorptance[i]);
    }
    py::dict columns;
    columns["theta_i"] = py::array_t<double>(py::cast(degrees));
    columns["reflectance_surface"] = py::array_t<double>(py::cast(surface));
    columns["reflectance_subsurface"] = py::array_t<double>(py::cast(subsurface));
    columns["reflectance"] = py::array_t<double>(py::cast(reflectance));
    columns["transmittance"] = py::array_t<double>(py::cast(transmittance));
    columns["absorptance"] = py::array_t<double>(py::cast(absorptance));
    for (std::size_t i = 0; i < layers.size(); ++i) {
      columns[py::str("absorptance_layer" + std::to_string(i + 1))] = py::array_t<double>(py::cast(layers[i]));
    }
    result.append(columns);
  }
  return result;
}

// One dict per solve: its grid angles (degrees) and its Fourier coefficient tables, (modes, K, K), 1/sr.
py::list tables(const Solution& solution) {
  py::list result;
  const std::vector<double>& wavelengths = solution.solved.channels.wavelengths_nm;
  for (std::size_t k = 0; k < solution.solved.tables.size(); ++k) {
    const LayerTables& table = solution.solved.tables[k];
    const auto size = static_cast<py::ssize_t>(table.grid_size()), modes = static_cast<py::ssize_t>(table.modes());
    std::vector<double> theta;
    for (int i = 0; i < table.grid_size(); ++i)
      theta.push_back(radians_to_degrees(LayerTables::grid_angle(i, table.grid_size())));
    const auto coefficients = [&](std::span<const double> data) {
      py::array_t<double> array({modes, size, size});
      std::copy(data.begin(), data.end(), array.mutable_data());
      return array;
    };
    py::dict entry;
    entry["theta"] = py::array_t<double>(py::cast(theta));
    entry["reflection"] = coefficients(table.reflection_coefficients());
    entry["transmission"] = coefficients(table.transmission_coefficients());
    if (k < wavelengths.size()) entry["wavelength_nm"] = wavelengths[k];
    result.append(entry);
  }
  return result;
}

py::array_t<double> to_rgb(const Solution& solution) {
  const auto& weights = solution.solved.channels.to_rgb;
  py::array_t<double> array({py::ssize_t{3}, static_cast<py::ssize_t>(weights.cols())});
  auto view = array.mutable_unchecked<2>();
  for (py::ssize_t c = 0; c < 3; ++c) {
    for (py::ssize_t k = 0; k < weights.cols(); ++k) view(c, k) = weights(c, k);
  }
  return array;
}

// Writes the file; returns its size in bytes.
std::size_t export_file(const Solution& solution, const std::string& path, const std::vector<std::string>& arguments) {
  const cli::ParsedFlags flags =
      parse(arguments, cli::export_flag_names(), "Solution.export", cli::export_switch_names());
  const cli::ExportRequest request = cli::export_request_from_flags(flags);
  if (path.empty()) throw ParameterError("path must name the file to write");
  if (const std::optional<std::string> missing = cli::missing_output_folder(path)) throw ParameterError(*missing);
  if (const auto* fitted = std::get_if<FittedExportSettings>(&request)) {
    const std::string text = fitted_export_text(solution.document, *fitted, parallel_for_threads);
    write_file_atomically(path, text);
    return text.size();
  }
  ExportSettings settings = std::get<ExportSettings>(request);
  settings.description = rgl_description(solution.document);
  ColorMaterial material = color_material(solution.document);
  material.model = solution.solved.model;
  const std::string bytes = run_interruptible([&](const std::function<bool()>& cancelled) {
    SolveOptions options;
    options.parallel_for = parallel_for_threads;
    options.cancelled = cancelled;
    return export_bytes(material, settings, options);
  });
  write_file_atomically(path, bytes);
  return bytes.size();
}

void translate_errors() {
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const SolveCancelled& cancelled) {
      PyErr_SetString(PyExc_KeyboardInterrupt, cancelled.what());
    } catch (const ParameterError& bad) {
      PyErr_SetString(PyExc_ValueError, bad.what());
    } catch (const cli::UsageError& bad) {
      PyErr_SetString(PyExc_ValueError, bad.what());
    } catch (const cli::InputError& bad) {
      PyErr_SetString(PyExc_ValueError, bad.what());
    } catch (const MaterialFileMissing& missing) {
      PyErr_SetString(
          missing.kind() == MaterialFileMissing::Kind::kFolder ? PyExc_IsADirectoryError : PyExc_FileNotFoundError,
          missing.what());
    } catch (const MaterialFileError& bad) {
      PyErr_SetString(PyExc_ValueError, bad.what());
    }
  });
}

}  // namespace
}  // namespace skinlayer::python

PYBIND11_MODULE(_skinlayer, module) {
  using namespace skinlayer;
  using namespace skinlayer::python;
  module.doc() = "skinlayer's compiled core; use the skinlayer package, which documents every function.";
  translate_errors();

  py::class_<MaterialDocument>(module, "Document")
      .def_readonly("name", &MaterialDocument::name)
      .def_readonly("description", &MaterialDocument::description)
      .def_property_readonly("grey", &MaterialDocument::grey)
      .def_property_readonly("skin", [](const MaterialDocument& d) { return d.skin.has_value(); })
      .def_property_readonly("layer_count", [](const MaterialDocument& d) { return d.layer.layer_count(); })
      .def("json", [](const MaterialDocument& d) { return material_json_text(d); })
      .def("save", [](const MaterialDocument& d, const std::string& path) { write_material_file(d, path); });
  module.def("document", &document_from_arguments, py::arg("arguments"));
  module.def("preset_names", &preset_names);
  module.def("default_thetas", [] { return std::string(cli::kDefaultThetas); });

  py::class_<Solution>(module, "Solution")
      .def_readonly("document", &Solution::document)
      .def_property_readonly("model",
                             [](const Solution& s) { return std::string(subsurface_model_name(s.solved.model)); })
      .def_property_readonly("grey", [](const Solution& s) { return s.solved.grey; })
      .def_property_readonly("wavelengths_nm", [](const Solution& s) { return s.solved.channels.wavelengths_nm; })
      .def_property_readonly("to_rgb", &to_rgb)
      .def("eval", &eval, py::arg("theta_i"), py::arg("theta_o"), py::arg("phi"), py::arg("unscattered"))
      .def("albedo", &albedo, py::arg("theta_list"))
      .def("profile", &profile, py::arg("radii"), py::arg("diffuse"))
      .def("tables", &tables)
      .def("export", &export_file, py::arg("path"), py::arg("arguments"));
  module.def("solve", &solve_material, py::arg("material"), py::arg("arguments"));
}
