#pragma once
/// \file set_options.h
/// \brief `--set NAME=VALUE` onto a configuration, the same way for every command that has it:
/// each item NAME=VALUE, each name once, not also given by the command's own option for it, the
/// value set by the configuration's own by-name setter (its message on a bad name or value).

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace metricmap::cli {

/// Parameter name -> the command's own option that sets it.
using OwnOptions = std::vector<std::pair<std::string, std::string>>;

/// \brief Apply `settings` in order with `set(name, value)` (which throws std::invalid_argument).
/// \returns the names set, in order. \throws UsageError ("--set: ...") for a malformed item, a
/// name given twice, a name its own option also gave, or what `set` refuses.
std::vector<std::string> applySetOptions(
    const CLI::App& app, const std::vector<std::string>& settings, const OwnOptions& own,
    const std::function<void(const std::string& name, const std::string& value)>& set);

/// \brief Run `validate` (a configuration's whole check), its std::invalid_argument a UsageError
/// prefixed "--set: ".
void validateSetOptions(const std::function<void()>& validate);

}  // namespace metricmap::cli
