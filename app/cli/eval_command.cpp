#include "app/cli/eval_command.h"

#include <vector>

#include "app/cli/csv_reader.h"
#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/cli/numeric_table.h"
#include "core/conventions.h"
#include "core/solver.h"
#include "core/subsurface_model.h"

namespace skinlayer::cli {

std::string eval_usage() {
  return "Usage: skinlayer eval [material flags] [--model stam|lambert|hk] < rows.csv\n"
         "\n"
         "Reads CSV rows theta_i,theta_o,phi from stdin and writes, one row per input row, in order:\n"
         "  theta_i,theta_o,phi,brdf_surface,brdf_subsurface,brdf,btdf\n"
         "Angles are degrees. theta is measured from the normal of the side where the direction lies (theta_o from\n"
         "the lower normal for btdf); phi is the outgoing minus the incident azimuth, 180 = forward. theta_i and\n"
         "theta_o lie in [0, 90]; phi is any finite number. The first line may be the header theta_i,theta_o,phi.\n"
         "BSDFs are plain (not cosine-weighted), in 1/sr; brdf = brdf_surface + brdf_subsurface; btdf is the\n"
         "radiance BSDF into the medium below without the unscattered beam (0 for --bottom lambert:A).\n"
         "--model picks the subsurface model (the surface term is the same): stam, the layer model (default);\n"
         "lambert, A/pi with the layer's albedo at normal incidence; hk, Hanrahan-Krueger single scattering.\n"
         "\n" +
         material_flags_usage() +
         "\n"
         "Example:\n"
         "  printf 'theta_i,theta_o,phi\\n30,30,180\\n' | skinlayer eval --sigma 0.3 --T 0.5 --bottom matched\n";
}

int run_eval_command(std::span<const std::string_view> arguments, std::istream& in, std::ostream& out) {
  const ParsedFlags flags = ParsedFlags::parse(arguments, material_flags_and({kModelFlag}), "skinlayer eval");
  const MaterialDocument document = material_document_from_flags(flags);
  const Material material = single_channel(document);
  const LayerTables tables = solve_model(material, model_from_flags(flags, document.model));
  const std::vector<AngleRow> rows = read_angle_rows(in);

  NumericTable table({"theta_i", "theta_o", "phi"}, {"brdf_surface", "brdf_subsurface", "brdf", "btdf"});
  for (const AngleRow& row : rows) {
    const double theta_i = degrees_to_radians(row.theta_i);
    const double theta_o = degrees_to_radians(row.theta_o);
    const double phi = degrees_to_radians(row.phi);
    const double surface = brdf_surface(material, theta_i, theta_o, phi);
    const double subsurface = tables.brdf_subsurface(theta_i, theta_o, phi);
    table.add_row({row.theta_i, row.theta_o, row.phi, surface, subsurface, surface + subsurface,
                   tables.btdf(theta_i, theta_o, phi)});
  }
  table.require_finite();
  table.write_csv(out);
  return kExitSuccess;
}

}  // namespace skinlayer::cli
