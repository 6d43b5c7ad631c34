#include "app/cli/environment_flags.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "app/cli/errors.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"
#include "core/conventions.h"

namespace skinlayer::cli {
namespace {

// The index of `word` in `names`; nullopt when it is none of them.
template <std::size_t N>
std::optional<std::size_t> index_of(const std::array<std::string_view, N>& names, std::string_view word) {
  const auto found = std::find(names.begin(), names.end(), word);
  if (found == names.end()) return std::nullopt;
  return static_cast<std::size_t>(found - names.begin());
}

}  // namespace

std::vector<std::string_view> lighting_flag_names() {
  return {"env", "env-rotate", "env-ev", "background", "samples", "light", "tonemap"};
}

LightingFlags lighting_from_flags(const ParsedFlags& flags) {
  LightingFlags lighting;
  if (const std::optional<std::string_view> env = flags.value("env")) {
    if (env->empty()) throw UsageError("env = '' is empty; give furnace, studio, sky or FILE.hdr");
    const bool builtin = *env == "furnace" || *env == "studio" || *env == "sky";
    std::error_code error;
    if (!builtin && !std::filesystem::is_regular_file(std::string(*env), error)) {
      const bool folder = std::filesystem::is_directory(std::string(*env), error);
      throw UsageError("env = " + text::quoted(*env) + (folder ? " is a folder" : " is no file") +
                       " and not a built-in environment: give furnace, studio, sky or FILE.hdr");
    }
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
  const std::optional<std::size_t> backdrop = index_of(kBackgroundNames, background);
  if (!backdrop) throw UsageError("background = " + text::quoted(background) + " is not one of: show, blur, hide");
  lighting.view.background = static_cast<EnvironmentBackground>(*backdrop);
  if (const std::optional<std::string_view> text = flags.value("samples")) {
    const std::optional<double> value = text::parse_number(*text);
    if (!value || *value != std::floor(*value) || *value < 1 || *value > kMaxEnvironmentSamples) {
      throw UsageError("samples = " + text::quoted(*text) + " must be a whole number in [1, " +
                       std::to_string(kMaxEnvironmentSamples) + "] (estimates per pixel)");
    }
    lighting.samples = static_cast<int>(*value);
  }
  const std::string_view light = flags.value("light").value_or(lighting.environment ? "off" : "on");
  if (light != "on" && light != "off") throw UsageError("light = " + text::quoted(light) + " is not on or off");
  lighting.directional_light = light == "on";
  if (!lighting.directional_light && !lighting.environment) {
    throw UsageError("--light off needs --env: nothing would light the sphere");
  }
  const std::string_view tonemap = flags.value("tonemap").value_or("exponential");
  const std::optional<std::size_t> tone_map = index_of(kToneMapNames, tonemap);
  if (!tone_map) throw UsageError("tonemap = " + text::quoted(tonemap) + " is not one of: exponential, aces, none");
  lighting.tone_map = static_cast<ToneMap>(*tone_map);
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
