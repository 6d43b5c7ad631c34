#include "app/window/test_action_script.h"

#include <stdexcept>
#include <string_view>

#include "app/cli/flag_parser.h"
#include "app/preview/scripted_edit.h"

namespace skinlayer {

TestActionScript::TestActionScript(const std::vector<std::string>& actions)
    : actions_(actions.begin(), actions.end()) {}

void TestActionScript::step(const TestActionReadiness& ready, TestActionTarget& target, ActionRequests& requests) {
  if (!drag_steps_.empty()) {
    apply_scripted_edit(target.state(), "set", drag_steps_.front());
    drag_steps_.pop_front();
    return;
  }
  if (actions_.empty() || !ready.settled || ready.dialog == FileDialog::Kind::Open ||
      ready.dialog == FileDialog::Kind::SaveAs) {
    return;
  }
  const std::string action = actions_.front();
  const std::size_t space = action.find(' ');
  const std::string verb = action.substr(0, space);
  const std::string argument = space == std::string::npos ? "" : action.substr(space + 1);
  if ((verb == "memory" || verb == "rest") && !ready.resting) return;  // at rest, as a person glancing at top
  actions_.pop_front();
  last_action_ = std::chrono::steady_clock::now();
  if (verb == "undo") {
    requests.undo = true;
  } else if (verb == "redo") {
    requests.redo = true;
  } else if (verb == "drop") {
    requests.file_commands.push_back({FileCommand::Kind::OpenPath, argument});
  } else if (verb == "save") {
    requests.file_commands.push_back({FileCommand::Kind::SaveAs, argument});
  } else if (verb == "preset") {
    requests.file_commands.push_back({FileCommand::Kind::LoadPreset, argument});
  } else if (verb == "discard") {
    if (ready.dialog != FileDialog::Kind::ConfirmDiscard) throw std::runtime_error("test action: nothing to discard");
    requests.file_commands.push_back({FileCommand::Kind::Discard, ""});
  } else if (verb == "quit") {
    requests.quit = true;  // as Ctrl+Q or the window's close button
  } else if (verb == "title") {
    target.print_title();
  } else if (verb == "export-merl") {
    target.start_export(ExportFormat::Merl, argument);
  } else if (verb == "export-bsdf") {
    target.start_export(ExportFormat::Bsdf, argument);
  } else if (verb == "export-rgl") {
    target.start_export(ExportFormat::Rgl, argument);
  } else if (verb == "export-blender") {
    target.start_export(ExportFormat::Blender, argument);
  } else if (verb == "export-mtlx") {
    target.start_export(ExportFormat::MaterialX, argument);
  } else if (verb == "match") {
    const std::vector<std::string_view> channels = cli::split_list(argument, ',');
    if (channels.size() != 3) throw std::runtime_error("test action: match needs R,G,B");
    target.start_match({std::stod(std::string(channels[0])), std::stod(std::string(channels[1])),
                        std::stod(std::string(channels[2]))});
  } else if (verb == "drag") {
    const std::vector<std::string> steps = drag_steps(argument);
    drag_steps_.assign(steps.begin(), steps.end());
  } else if (verb == "rest") {  // waited for above
  } else if (verb == "memory") {
    target.print_memory();
  } else if (verb == "pin") {
    target.pin();
  } else if (verb == "pin-fit") {
    if (argument != "principled" && argument != "openpbr") {
      throw std::runtime_error("test action: pin-fit needs principled or openpbr");
    }
    target.pin_fit(argument == "principled" ? ShaderTarget::Principled : ShaderTarget::OpenPbr);
  } else if (verb == "unpin") {
    target.unpin();
  } else if (!apply_scripted_edit(target.state(), verb, argument)) {
    throw std::runtime_error("test action: unknown action '" + action + "'");
  }
}

}  // namespace skinlayer
