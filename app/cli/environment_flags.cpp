#include "app/cli/environment_flags.h"

#include <cmath>

#include "app/cli/errors.h"
#include "app/cli/numbers.h"
#include "app/cli/quoted.h"
#include "core/conventions.h"

namespace skinlayer::cli {

std::vector<std::string_view> lighting_flag_names() {
  return {"env", "env-rotate", "env-ev", "background", "samples", "light", "tonemap"};
}

LightingFlags lighting_from_flags(const ParsedFlags& flags) {
  LightingFlags lighting;
  if (const std::optional<std::string_view> env = flags.value("env")) {
    if (env->empty()) throw UsageError("env = '' is empty; give furnace, studio, sky or FILE.hdr");
    lighting.environment = std::string(*env);
  } else {
    for (std::string_view name : {"env-rotate", "env-ev", "background", "samples"}) {
      if (flags.has(name)) throw UsageError("--" + std::string(name) + " needs --env (an environment to light with)");
    }
  }
  lighting.view.rotation = degrees_to_radians(
      number_flag(flags, "env-rotate", 0.0, -360.0, 360.0, " (degrees about the vertical, turning the environment)"));
  lighting.view.scale = std::exp2(number_flag(flags, "env-ev", 0.0, -20.0, 20.0, " (exposure value: radiance x 2^EV)"));
  const std::string_view background = flags.value("background").value_or("show");
  if (background == "show") {
    lighting.view.background = EnvironmentBackground::Show;
  } else if (background == "blur") {
    lighting.view.background = EnvironmentBackground::Blur;
  } else if (background == "hide") {
    lighting.view.background = EnvironmentBackground::Hide;
  } else {
    throw UsageError("background = " + quoted(background) + " is not one of: show, blur, hide");
  }
  if (const std::optional<std::string_view> text = flags.value("samples")) {
    const std::optional<double> value = parse_number(*text);
    if (!value || *value != std::floor(*value) || *value < 1 || *value > kMaxEnvironmentSamples) {
      throw UsageError("samples = " + quoted(*text) + " must be a whole number in [1, " +
                       std::to_string(kMaxEnvironmentSamples) + "] (estimates per pixel)");
    }
    lighting.samples = static_cast<int>(*value);
  }
  const std::string_view light = flags.value("light").value_or(lighting.environment ? "off" : "on");
  if (light != "on" && light != "off") throw UsageError("light = " + quoted(light) + " is not on or off");
  lighting.directional_light = light == "on";
  if (!lighting.directional_light && !lighting.environment) {
    throw UsageError("--light off needs --env: nothing would light the sphere");
  }
  const std::string_view tonemap = flags.value("tonemap").value_or("exponential");
  if (tonemap == "exponential") {
    lighting.tone_map = ToneMap::Exponential;
  } else if (tonemap == "aces") {
    lighting.tone_map = ToneMap::Aces;
  } else if (tonemap == "none") {
    lighting.tone_map = ToneMap::None;
  } else {
    throw UsageError("tonemap = " + quoted(tonemap) + " is not one of: exponential, aces, none");
  }
  return lighting;
}

std::string lighting_flags_usage() {
  return "  --env E              light the sphere by an environment: furnace (uniform radiance 1), studio (a\n"
         "                       softbox and two strip lights), sky (a sun and a sky), or an equirectangular\n"
         "                       Radiance FILE.hdr; a progressive Monte Carlo estimate (--samples)\n"
         "  --env-rotate DEG     turn the environment about the vertical, degrees in [-360, 360] (default 0)\n"
         "  --env-ev EV          scale its radiance by 2^EV, EV in [-20, 20] (default 0)\n"
         "  --background B       behind the sphere: show (the environment), blur, or hide (default show)\n"
         "  --samples N          estimates per pixel, whole number in [1, 1048576] (default 256)\n"
         "  --light on|off       the directional light (default on; off with --env)\n"
         "  --tonemap T          the PNG's tone map: exponential (default), aces, or none (clamped)\n";
}

}  // namespace skinlayer::cli
