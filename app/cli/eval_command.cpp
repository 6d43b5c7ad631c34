#include "app/cli/eval_command.h"

#include <string>
#include <vector>

#include "app/cli/csv_reader.h"
#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/cli/numeric_table.h"
#include "app/cli/skin_flag.h"
#include "app/material/color_channels.h"
#include "app/process/parallel_for.h"
#include "app/solution/solved_document.h"
#include "core/conventions.h"

namespace skinlayer::cli {

std::string eval_usage() {
  return "Usage: skinlayer eval [material flags] [--albedo A | r,g,b] [--model stam|lambert|hk] < rows.csv\n"
         "\n"
         "Reads CSV rows theta_i,theta_o,phi from stdin and writes, one row per input row, in order:\n"
         "  theta_i,theta_o,phi,brdf_surface,brdf_subsurface,brdf,btdf\n"
         "Angles are degrees. theta is measured from the normal of the side where the direction lies (theta_o from\n"
         "the lower normal for btdf); phi is the outgoing minus the incident azimuth, 180 = forward. theta_i and\n"
         "theta_o lie in [0, 90]; phi is any finite number. The first line may be the header theta_i,theta_o,phi.\n"
         "BSDFs are plain (not cosine-weighted), in 1/sr; brdf = brdf_surface + brdf_subsurface; btdf is the\n"
         "radiance BSDF into the medium below without the unscattered beam (0 for --bottom lambert:A).\n"
         "An RGB albedo (--albedo r,g,b, a preset, a material file or a stack's albedo=r:g:b) writes one column per\n"
         "channel for what depends on colour; the surface term does not:\n"
         "  theta_i,theta_o,phi,brdf_surface,brdf_subsurface_r,brdf_subsurface_g,brdf_subsurface_b,\n"
         "  brdf_r,brdf_g,brdf_b,btdf_r,btdf_g,btdf_b\n"
         "Each channel is the grey solve with that channel's albedo. --albedo A makes any material grey.\n"
         "A --skin writes the same RGB columns: each is the spectrum's linear sRGB under D65 (CIE 1931 2-degree\n"
         "observer), from one solve per wavelength, 400-700 nm in 10 nm steps; --wavelength NM gives one\n"
         "wavelength's grey columns instead.\n"
         "--model picks the subsurface model (the surface term is the same): stam, the layer model (default);\n"
         "lambert, A/pi with the layer's albedo at normal incidence; hk, Hanrahan-Krueger single scattering.\n"
         "\n" +
         rgb_albedo_usage() + "\n" + skin_flags_usage() + "\n" + material_flags_usage() +
         "\n"
         "Example:\n"
         "  printf 'theta_i,theta_o,phi\\n30,30,180\\n' | skinlayer eval --sigma 0.3 --T 0.5 --bottom matched\n"
         "  printf '30,30,180\\n' | skinlayer eval --preset skin-fair\n";
}

namespace {

// One row per direction pair: the grey columns, or for a colour material (RGB, or a skin's spectrum) the surface
// term, grey, then the subsurface BRDF, the BRDF and the BTDF per channel (app/solution/solved_document.h).
void write_rows(const SolvedDocument& solved, std::istream& in, std::ostream& out) {
  const std::vector<AngleRow> rows = read_angle_rows(in);
  std::vector<std::string> columns = {"brdf_surface"};
  for (const char* quantity : {"brdf_subsurface", "brdf", "btdf"}) {
    const std::vector<std::string> names = solved.grey ? std::vector<std::string>{quantity} : channel_columns(quantity);
    columns.insert(columns.end(), names.begin(), names.end());
  }
  NumericTable table({"theta_i", "theta_o", "phi"}, columns);
  for (const AngleRow& row : rows) {
    const BsdfPoint point = evaluate(solved, degrees_to_radians(row.theta_i), degrees_to_radians(row.theta_o),
                                     degrees_to_radians(row.phi));
    if (solved.grey) {
      table.add_row({row.theta_i, row.theta_o, row.phi, point.surface, point.subsurface[0],
                     point.surface + point.subsurface[0], point.btdf[0]});
      continue;
    }
    const auto& sub = point.subsurface;
    table.add_row({row.theta_i, row.theta_o, row.phi, point.surface, sub[0], sub[1], sub[2], point.surface + sub[0],
                   point.surface + sub[1], point.surface + sub[2], point.btdf[0], point.btdf[1], point.btdf[2]});
  }
  table.require_finite();
  table.write_csv(out);
}

}  // namespace

int run_eval_command(std::span<const std::string_view> arguments, std::istream& in, std::ostream& out) {
  const ParsedFlags flags =
      ParsedFlags::parse(arguments, material_flags_and({kModelFlag, kSkinFlag, kWavelengthFlag}), "skinlayer eval");
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  if (const std::optional<double> wavelength = wavelength_from_flags(flags)) {
    document = document_at_wavelength(document, *wavelength);
  }
  const SubsurfaceModel model = model_from_flags(flags, document.model);
  write_rows(solve_document(document, model, parallel_for_threads), in, out);
  return kExitSuccess;
}

}  // namespace skinlayer::cli
