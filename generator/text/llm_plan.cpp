// The LLM backend: the fine-tune's system prompt, the request text, and corrective rounds that send the
// validator's findings back until the layout is valid or the rounds are spent.
#include <chrono>
#include <sstream>

#include "finetune/layout_schema.h"
#include "finetune/system_prompt.h"
#include "generator/text/backends.h"
#include "layout/layout_io.h"
#include "layout/validate.h"

namespace villa {

std::string RepairMessage(const std::vector<Violation>& violations) {
  std::ostringstream out;
  out << "The layout you returned breaks " << violations.size() << (violations.size() == 1 ? " rule" : " rules")
      << " of the format:\n";
  const std::size_t shown = std::min<std::size_t>(violations.size(), 40);
  for (std::size_t i = 0; i < shown; ++i) out << "- rule " << violations[i].rule << ": " << violations[i].message << "\n";
  if (shown < violations.size()) out << "- ... and " << (violations.size() - shown) << " more\n";
  out << "Return the corrected complete layout as one JSON object with the six keys, and nothing else.";
  return out.str();
}

void PlanWithLlm(const std::string& text, const PlanOptions& options, PlanSummary& summary) {
  LlmOptions llm = options.llm;
  if (!llm.seed) llm.seed = options.seed;
  std::vector<ChatMessage> messages{{"system", std::string(SystemPrompt()), {}}, {"user", text, {}}};
  // The layout schema for constrained decoding (finetune/layout_schema.h), unless the server lacks it.
  const nlohmann::ordered_json response_format = options.json_schema ? LayoutResponseFormat() : nullptr;
  std::optional<Layout> last_parsed;
  bool transport_failed = false;
  for (int round = 0; round <= options.rounds; ++round) {
    PlanRound record;
    record.round = round;
    int http_attempts = 0;
    Result<ChatAnswer> answer = ChatCompletion(llm, messages, response_format, &http_attempts);
    record.http_attempts = http_attempts;
    if (!answer.ok()) {
      record.error = answer.error();
      summary.rounds.push_back(record);
      summary.error = answer.error();
      transport_failed = true;
      break;  // the transport already retried; another round would meet the same server
    }
    ++summary.attempts;
    record.seconds = answer->seconds;
    record.finish_reason = answer->finish_reason;
    summary.raw_answer = answer->content;
    std::string feedback;
    if (answer->finish_reason == "length") {
      record.error = "the answer was cut off at max_tokens (finish_reason \"length\"): " +
                     std::to_string(answer->content.size()) + " characters received";
      feedback = "Your previous answer was cut off before the JSON was complete. Return the complete layout as one "
                 "compact JSON object (no spaces or line breaks), and nothing else.";
    } else {
      Result<Layout> layout = ParseLayoutText(ExtractJsonText(answer->content), "answer");
      if (!layout.ok()) {
        record.error = layout.error();
        feedback = "Your answer is not a valid layout JSON: " + layout.error() +
                   "\nReturn the complete layout as one JSON object with the six keys, and nothing else.";
      } else {
        record.parsed = true;
        ValidationReport report = ValidateLayout(*layout);
        record.violations = static_cast<int>(report.violations.size());
        record.requirements_met = CheckBrief(summary.brief, *layout).met();
        if (report.valid()) {
          record.valid = true;
          summary.rounds.push_back(record);
          summary.layout = std::move(layout.value());
          summary.error.clear();
          return;
        }
        last_parsed = std::move(layout.value());
        feedback = RepairMessage(report.violations);
      }
    }
    summary.rounds.push_back(record);
    summary.error = record.error.empty() ? "the model's layout is invalid" : record.error;
    if (round == options.rounds) break;
    if (answer->finish_reason != "length") messages.push_back({"assistant", answer->content, {}});
    messages.push_back({"user", feedback, {}});
  }
  if (!summary.layout && last_parsed) summary.layout = std::move(last_parsed);
  if (!transport_failed)
    summary.error = "no valid layout in " + std::to_string(summary.attempts) +
                    (summary.attempts == 1 ? " answer" : " answers") + "; last: " + summary.error;
}

}  // namespace villa
