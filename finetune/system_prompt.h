#pragma once
// The system prompt of the layout generator LLM: one text, finetune/system_prompt.md, compiled into the
// library. The fine-tune export writes it into every training sample and the generator's LLM backend
// sends it with every request, so training and inference can never drift apart.
#include <string_view>

namespace villa {

// The prompt exactly as sent: the bytes of finetune/system_prompt.md without trailing whitespace.
// It states every rule of FORMAT.md and the exact output shape (one compact JSON layout object).
std::string_view SystemPrompt();

}  // namespace villa
