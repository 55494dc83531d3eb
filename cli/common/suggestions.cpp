#include "cli/common/suggestions.h"

#include <algorithm>
#include <cctype>

#include "io/json/reader.h"

namespace rt {

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  const auto near = closest_match(word, candidates);
  return near ? " (did you mean \"" + *near + "\"?)" : "";
}

std::optional<std::string> unknown_argument_message(const CLI::App& app, const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  std::vector<std::string> commands;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    commands.push_back(sub->get_name());
  const std::string& first = args.front();
  if (first.empty() || first[0] == '-') return std::nullopt;  // --help, --version: CLI11's
  const CLI::App* command = nullptr;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == first) command = sub;
  if (!command) {
    std::string message = "unknown command \"" + first + "\"" + did_you_mean(first, commands);
    std::string list;
    for (const std::string& c : commands) list += (list.empty() ? "" : ", ") + c;
    return message + "; expected one of: " + list;
  }
  // Down to the innermost command named (farm slurm): its options are the ones that count.
  size_t next = 1;
  std::string path = first;
  for (bool deeper = true; deeper && next < args.size();) {
    deeper = false;
    for (const CLI::App* sub : command->get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == args[next]) {
        command = sub;
        path += " " + args[next++];
        deeper = true;
        break;
      }
  }
  // A command that passes the options it does not know on (farm slurm, to every task's render)
  // has no unknown options: CLI11's own message (a value out of range) stands.
  if (command->get_allow_extras()) return std::nullopt;
  std::vector<std::string> options;
  for (const CLI::Option* o : command->get_options()) {
    for (const std::string& name : o->get_lnames()) options.push_back("--" + name);
    for (const std::string& name : o->get_snames()) options.push_back("-" + name);
  }
  for (size_t i = next; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() < 2 || a[0] != '-' || a == "--") continue;
    const std::string name = a.substr(0, a.find('='));
    if (std::find(options.begin(), options.end(), name) != options.end()) continue;
    if (name.size() > 1 && name[1] != '-' && std::isdigit(static_cast<unsigned char>(name[1]))) continue;  // -5
    return path + ": unknown option \"" + name + "\"" + did_you_mean(name, options);
  }
  return std::nullopt;
}

}  // namespace rt
