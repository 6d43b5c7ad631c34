#include "app/cli/help_command.h"

#include "app/cli/command_table.h"
#include "app/cli/errors.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {

std::string overview_usage() {
  return "skinlayer: Stam's (2001) skin-layer illumination model: a rough dielectric surface over a scattering slab.\n"
         "\n"
         "Usage:\n"
         "  skinlayer eval [material flags] < rows.csv\n"
         "      BRDF and BTDF at direction pairs: CSV rows theta_i,theta_o,phi (degrees) in, values (1/sr) out.\n"
         "  skinlayer albedo [material flags] [--theta-i LIST]\n"
         "      reflectance, transmittance and absorptance for light from each incidence angle.\n"
         "  skinlayer profile [material flags] [--annuli DR:N | --radii LIST]\n"
         "      where a pencil beam's light leaves the layer, per unit area: the spatial profile (BSSRDF).\n"
         "  skinlayer spectrum [material flags] [--skin KEY=VALUE,...] [--theta-i LIST] [--wavelength NM]\n"
         "      reflectance, transmittance and absorptance per wavelength, of a skin or a grey material.\n"
         "  skinlayer match --color R,G,B|#RRGGBB | --spectrum FILE.csv [material flags] [-o FILE.json]\n"
         "      pick the colour (or a measured spectrum), get the parameters: the material that reproduces it.\n"
         "  skinlayer render [material flags] [--albedo A | r,g,b] [view flags] -o FILE.png\n"
         "      the previewer's sphere and polar lobes, rendered offscreen (no display needed) to a PNG.\n"
         "  skinlayer material [material flags] [--name N] [--description D] [-o FILE.json]\n"
         "      the complete material as a material file, which --material FILE reads back (every command).\n"
         "  skinlayer presets [--colors]\n"
         "      the named presets (--preset NAME): the paper's settings, skin, leaf, paper, wax, jade, paint;\n"
         "      --colors gives each one's colour at normal incidence.\n"
         "  skinlayer figures -o DIR [--size PX]\n"
         "      the results figures (lobe plots and model spheres): a PNG and a CSV each, and index.html.\n"
         "  skinlayer fit --target principled [material flags] [-o FILE.json]\n"
         "      the Blender 3.4 Principled BSDF parameters nearest the material, with the fit's error.\n"
         "  skinlayer export --format bsdf|merl|rgl [material flags] -o FILE\n"
         "      the solved material as a tabulated Fourier BSDF (pbrt-v3, layerlab), a MERL BRDF table or an\n"
         "      RGL measured-BSDF tensor file (pbrt-v4, Mitsuba 3).\n"
         "  skinlayer validate [--quick] [-o DIR]\n"
         "      the solver against an independent Monte Carlo walk over a grid of layers: tables and a report.\n"
         "  skinlayer help [COMMAND], skinlayer COMMAND --help\n"
         "      usage of a command, with every flag, its range and default.\n"
         "  skinlayer --version\n"
         "  skinlayer [--capture FILE.png [material flags]]\n"
         "      the interactive previewer (a window; F1 lists its keys). --capture opens it, saves a screenshot of\n"
         "      the whole window and exits. Without a display it says so: use skinlayer render instead.\n"
         "\n"
         "Exit status: 0 success; 1 malformed input on stdin or a failed computation; 2 a bad command line or a\n"
         "parameter out of range. Every error is one line on stderr.\n";
}

int run_help_command(std::span<const std::string_view> arguments, std::ostream& out) {
  if (arguments.empty()) {
    out << overview_usage();
    return kExitSuccess;
  }
  if (arguments.size() > 1) throw UsageError("help takes at most one command name, as in skinlayer help eval");
  const Command* command = find_command(arguments.front());
  if (command == nullptr) {
    throw UsageError("unknown command " + text::quoted(arguments.front()) + "; the commands are " + command_names());
  }
  out << command->usage();
  return kExitSuccess;
}

}  // namespace skinlayer::cli
