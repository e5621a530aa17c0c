#pragma once
// The generator backend flags shared by `villa plan`, `villa eval` and `villa generate` (defined in
// cli/plan.cpp): --backend, --llm, --model, --api-key-env, --seed, --rounds, --timeout, ...
#include <string>

#include <CLI/CLI.hpp>

#include "generator/text/plan.h"

namespace villa::cli {

// Adds the flags to `sub`, binding them into `options` (and the two strings read by ApplyBackendFlags).
void AddBackendFlags(CLI::App* sub, std::string& backend, std::string& api_key_env, PlanOptions& options);
// After parsing: resolves the backend choice and reads the API key from the named variable.
// Throws UsageError for a bad combination (e.g. --backend llm without --llm).
void ApplyBackendFlags(const std::string& backend, const std::string& api_key_env, PlanOptions& options);

}  // namespace villa::cli
