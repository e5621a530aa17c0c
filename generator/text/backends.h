#pragma once
// The two backends behind PlanLayout() (plan.h). Each fills the candidate layout and the per-round
// record of a PlanSummary; PlanLayout() then validates, measures and checks the result the same way for
// both, so neither can report an invalid layout as valid.
#include <optional>
#include <string>

#include "generator/text/plan.h"
#include "partitioner/partitioner.h"

namespace villa {

// The partitioner's options for one attempt: the brief's floors, footprint class, room counts (per floor
// and in total), connections and panoramic windows. `floors` (1..3) is the attempt's floor count;
// `only_required` asks for exactly the rooms the brief lists.
PartitionOptions PartitionOptionsForBrief(const Brief& brief, int floors, bool only_required);

// Replaces the whole-building room counts of `o` by per-floor ones of our own choosing (living spaces
// low, bedrooms and balconies high, the rest where there is space; ties shuffled by `seed`).
void DistributeRooms(PartitionOptions& o, std::uint64_t seed);

// Generate-and-test over partitioner seeds within options.time_budget_s / options.max_attempts.
// Sets summary.layout (the best valid candidate), summary.shape_class, summary.attempts, summary.rounds
// (one record) and summary.error when nothing valid came out.
void PlanProcedural(const Brief& brief, const PlanOptions& options, PlanSummary& summary);

// The LLM conversation: first answer, then up to options.rounds corrective rounds. Sets summary.layout
// (the first valid answer, else the last one that parsed), summary.rounds, summary.attempts,
// summary.raw_answer, and summary.error for a transport failure or when no answer was valid.
void PlanWithLlm(const std::string& text, const PlanOptions& options, PlanSummary& summary);

// The corrective message sent after an invalid answer (exposed for tests).
std::string RepairMessage(const std::vector<Violation>& violations);

}  // namespace villa
