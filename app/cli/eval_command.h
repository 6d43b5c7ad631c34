// `skinlayer eval [material flags]`: the layer's BSDF at direction pairs read as CSV from stdin.
//
// Solves the layer once, then reads every row (see csv_reader.h) and writes
//   theta_i,theta_o,phi,brdf_surface,brdf_subsurface,brdf,btdf
// one row per input row, in order: the angles as parsed (degrees, in the shortest form that reads back exactly),
// then the BSDFs in 1/sr with "%.17g" (brdf = brdf_surface + brdf_subsurface). Output is all or nothing: nothing is
// written unless every row parsed and every value is finite. An RGB albedo solves each distinct channel and writes
//   theta_i,theta_o,phi,brdf_surface,brdf_subsurface_{r,g,b},brdf_{r,g,b},btdf_{r,g,b}
// (each channel the grey solve with that channel's albedo; the surface term does not depend on colour).
#pragma once

#include <istream>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string eval_usage();

// Runs the command on arguments (after "eval") and returns the exit status. Errors are thrown (see errors.h).
int run_eval_command(std::span<const std::string_view> arguments, std::istream& in, std::ostream& out);

}  // namespace skinlayer::cli
