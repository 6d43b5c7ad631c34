#include "app/cli/eval_command.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli/csv_reader.h"
#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/cli/numeric_table.h"
#include "app/cli/skin_flag.h"
#include "app/cli/unscattered_flag.h"
#include "app/material/color_channels.h"
#include "app/process/parallel_for.h"
#include "app/solution/pair_evaluation.h"
#include "app/solution/solved_document.h"

namespace skinlayer::cli {

std::string eval_usage() {
  return "Usage: skinlayer eval [material flags] [--albedo A | r,g,b] [--model stam|lambert|hk]\n"
         "                      [--unscattered auto|exact|table] < rows.csv\n"
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
         "--unscattered picks how the light that crosses two rough interfaces unscattered is evaluated: exact, by\n"
         "its quadrature at each pair (~0.1-0.2 ms a pair); table, from a table of its cosine series built once\n"
         "(~0.1 s), within 0.5% of the lobe's peak (2% past theta_i 85), for sigma >= 0.15 at both interfaces;\n"
         "auto (default), the table from 4096 rows on where it can be built, else exact.\n"
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
void write_rows(const SolvedDocument& solved, std::istream& in, std::ostream& out, UnscatteredLobe lobe) {
  const std::vector<AngleRow> rows = read_angle_rows(in);
  std::vector<double> theta_i, theta_o, phi;
  for (const AngleRow& row : rows) {
    theta_i.push_back(row.theta_i);
    theta_o.push_back(row.theta_o);
    phi.push_back(row.phi);
  }
  const auto channels = static_cast<std::size_t>(value_channels(solved));
  std::vector<double> surface(rows.size()), subsurface(rows.size() * channels), brdf(rows.size() * channels),
      btdf(rows.size() * channels);
  evaluate_pairs(solved, theta_i, theta_o, phi, {surface, subsurface, brdf, btdf}, parallel_for_threads, {}, lobe);
  std::vector<std::string> columns = {"brdf_surface"};
  for (const char* quantity : {"brdf_subsurface", "brdf", "btdf"}) {
    const std::vector<std::string> names = solved.grey ? std::vector<std::string>{quantity} : channel_columns(quantity);
    columns.insert(columns.end(), names.begin(), names.end());
  }
  NumericTable table({"theta_i", "theta_o", "phi"}, columns);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    std::vector<double> row = {theta_i[k], theta_o[k], phi[k], surface[k]};
    for (const std::vector<double>* quantity : {&subsurface, &brdf, &btdf}) {
      row.insert(row.end(), quantity->begin() + k * channels, quantity->begin() + (k + 1) * channels);
    }
    table.add_row(row);
  }
  table.require_finite();
  table.write_csv(out);
}

}  // namespace

int run_eval_command(std::span<const std::string_view> arguments, std::istream& in, std::ostream& out) {
  const ParsedFlags flags = ParsedFlags::parse(
      arguments, material_flags_and({kModelFlag, kSkinFlag, kWavelengthFlag, kUnscatteredFlag}), "skinlayer eval");
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  if (const std::optional<double> wavelength = wavelength_from_flags(flags)) {
    document = document_at_wavelength(document, *wavelength);
  }
  const SubsurfaceModel model = model_from_flags(flags, document.model);
  const UnscatteredLobe lobe = unscattered_lobe_from_flags(flags);
  write_rows(solve_document(document, model, parallel_for_threads), in, out, lobe);
  return kExitSuccess;
}

}  // namespace skinlayer::cli
