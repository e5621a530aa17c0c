#pragma once
// The data card (README.md) written beside an export: what is in it, where it came from, how to train on
// it with LLaMA-Factory, axolotl and TRL, and how to serve and use the result.
#include <string>

#include "finetune/export.h"
#include "finetune/trainer_configs.h"

namespace villa {

std::string DataCard(const ExportSummary& summary, const TrainerConfigInput& config);

}  // namespace villa
