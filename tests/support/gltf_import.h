// A glTF import as the tests see it: the model, and what its Reporter collected (errors joined
// into one message, warnings each on their own, every diagnostic with its pointer and place).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "io/base/reporter.h"
#include "io/gltf/loader.h"

namespace rt::test {

struct ImportProblems {
  Diagnostics found;
  std::string message;  // every error's message, joined by "; " (or the unknown mesh's names)
  std::vector<std::string> warnings;
  bool unknown_mesh = false;
  bool over_limit = false;

  const Diagnostic* first_error() const {
    for (const Diagnostic& d : found.all())
      if (d.severity == Severity::kError) return &d;
    return nullptr;
  }
};

inline std::optional<ImportedModel> import_gltf(const std::string& path, const std::optional<std::string>& mesh,
                                                const LoadLimits& limits, LimitUsage& usage, ImportProblems& out) {
  out = ImportProblems{};
  Reporter report(out.found, path);
  ImportError error;
  auto model = rt::import_gltf(path, mesh, limits, usage, report, error);
  for (const Diagnostic& d : out.found.all()) {
    if (d.severity == Severity::kWarning) out.warnings.push_back(d.message);
    else out.message += (out.message.empty() ? "" : "; ") + d.message;
  }
  out.unknown_mesh = error.unknown_mesh;
  if (error.unknown_mesh) out.message = error.message;
  out.over_limit = report.stopped_by_limit();
  return model;
}

inline std::optional<ImportedModel> import_gltf(const std::string& path, const std::optional<std::string>& mesh,
                                                const LoadLimits& limits, ImportProblems& out) {
  LimitUsage usage;
  return import_gltf(path, mesh, limits, usage, out);
}

// The model at `path`, imported whole under the default limits; the test stops on an error and
// lists the warnings.
inline ImportedModel imported(const std::string& path) {
  ImportProblems problems;
  auto model = import_gltf(path, std::nullopt, LoadLimits{}, problems);
  INFO(problems.message);
  REQUIRE(model);
  for (const std::string& w : problems.warnings) UNSCOPED_INFO(w);
  return std::move(*model);
}

}  // namespace rt::test
