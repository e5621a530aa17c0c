#include "finetune/system_prompt.h"

#include <cstddef>

namespace villa {
namespace embedded {
// Generated from finetune/system_prompt.md at build time (finetune/embed_text.cmake).
extern const char kSystemPromptText[];
extern const std::size_t kSystemPromptText_size;
}  // namespace embedded

std::string_view SystemPrompt() {
  // The file ends with a newline (editors add one); the prompt sent is the text without it.
  static const std::string_view prompt = [] {
    std::string_view text(embedded::kSystemPromptText, embedded::kSystemPromptText_size);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ' || text.back() == '\t')) {
      text.remove_suffix(1);
    }
    return text;
  }();
  return prompt;
}

}  // namespace villa
