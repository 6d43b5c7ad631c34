// The environment-lighting flags of `render` (and the previewer's --capture): --env furnace|studio|sky|FILE.hdr,
// --env-rotate DEG, --env-ev EV, --background show|blur|hide, --samples N, --light on|off, --tonemap
// exponential|aces|none (app/render/environment_map.h, app/render/renderer.h).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli/flag_parser.h"
#include "app/render/environment_map.h"
#include "app/render/renderer.h"

namespace skinlayer::cli {

inline constexpr int kDefaultEnvironmentSamples = 256;
// The flags' words for the backdrop and the tone map, indexed by the enums' values (also the picture metadata's).
inline constexpr std::array<std::string_view, 3> kBackgroundNames = {"hide", "show", "blur"};
inline constexpr std::array<std::string_view, 3> kToneMapNames = {"exponential", "aces", "none"};
inline constexpr int kMaxEnvironmentSamples = 1 << 20;

struct LightingFlags {
  std::optional<std::string> environment;  // a built-in name or a .hdr path; unset: the directional light alone
  EnvironmentView view;
  int samples = kDefaultEnvironmentSamples;  // estimates per pixel
  bool directional_light = true;             // default: on without --env, off with it
  ToneMap tone_map = ToneMap::Exponential;
};

// The flag names, for ParsedFlags::parse.
std::vector<std::string_view> lighting_flag_names();
// Reads and checks the flags; throws UsageError naming the flag and its valid values.
LightingFlags lighting_from_flags(const ParsedFlags& flags);
std::string lighting_flags_usage();

}  // namespace skinlayer::cli
