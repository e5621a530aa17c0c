#include "finetune/sample_format.h"

namespace villa {
namespace {

using Json = nlohmann::ordered_json;

Result<std::string> StringField(const Json& object, const char* key, const std::string& path) {
  auto it = object.find(key);
  if (it == object.end()) return Error{path + ": missing \"" + key + "\""};
  if (!it->is_string()) return Error{path + "." + key + ": expected a string, got " + it->dump().substr(0, 60)};
  return it->get<std::string>();
}

// A conversation array of exactly three turns (messages) or two turns (sharegpt) with the expected roles.
Result<SampleTexts> ReadTurns(const Json& turns, const char* array_key, const char* role_key, const char* content_key,
                              const std::vector<std::string>& roles) {
  const std::string path = array_key;
  if (!turns.is_array()) return Error{path + ": expected an array of turns"};
  if (turns.size() != roles.size()) {
    return Error{path + ": expected " + std::to_string(roles.size()) + " turns, got " + std::to_string(turns.size())};
  }
  std::vector<std::string> contents;
  for (std::size_t i = 0; i < turns.size(); ++i) {
    const std::string where = path + "[" + std::to_string(i) + "]";
    if (!turns[i].is_object()) return Error{where + ": expected an object"};
    auto role = StringField(turns[i], role_key, where);
    if (!role) return Error{role.error()};
    if (*role != roles[i]) return Error{where + "." + role_key + ": expected \"" + roles[i] + "\", got \"" + *role + "\""};
    auto content = StringField(turns[i], content_key, where);
    if (!content) return Error{content.error()};
    contents.push_back(std::move(*content));
  }
  SampleTexts texts;
  if (roles.size() == 3) {
    texts.system = contents[0], texts.user = contents[1], texts.assistant = contents[2];
  } else {
    texts.user = contents[0], texts.assistant = contents[1];
  }
  return texts;
}

}  // namespace

Json SampleLine(ExportFormat format, const SampleTexts& texts) {
  switch (format) {
    case ExportFormat::kMessages:
      return Json{{"messages", Json::array({Json{{"role", "system"}, {"content", texts.system}},
                                            Json{{"role", "user"}, {"content", texts.user}},
                                            Json{{"role", "assistant"}, {"content", texts.assistant}}})}};
    case ExportFormat::kShareGpt:
      return Json{{"conversations", Json::array({Json{{"from", "human"}, {"value", texts.user}},
                                                 Json{{"from", "gpt"}, {"value", texts.assistant}}})},
                  {"system", texts.system}};
    case ExportFormat::kAlpaca:
      return Json{{"instruction", texts.user}, {"input", ""}, {"output", texts.assistant}, {"system", texts.system}};
  }
  return Json::object();
}

Result<SampleTexts> ParseSampleLine(const Json& line, ExportFormat* format) {
  if (!line.is_object()) return Error{"expected a JSON object"};
  if (line.contains("messages")) {
    if (format) *format = ExportFormat::kMessages;
    return ReadTurns(line["messages"], "messages", "role", "content", {"system", "user", "assistant"});
  }
  if (line.contains("conversations")) {
    if (format) *format = ExportFormat::kShareGpt;
    auto texts = ReadTurns(line["conversations"], "conversations", "from", "value", {"human", "gpt"});
    if (!texts) return texts;
    auto system = StringField(line, "system", "(line)");
    if (!system) return Error{system.error()};
    texts->system = *system;
    return texts;
  }
  if (line.contains("instruction")) {
    if (format) *format = ExportFormat::kAlpaca;
    SampleTexts texts;
    auto user = StringField(line, "instruction", "(line)");
    if (!user) return Error{user.error()};
    auto input = StringField(line, "input", "(line)");
    if (!input) return Error{input.error()};
    if (!input->empty()) return Error{"(line).input: expected \"\" (the description is the instruction)"};
    auto output = StringField(line, "output", "(line)");
    if (!output) return Error{output.error()};
    auto system = StringField(line, "system", "(line)");
    if (!system) return Error{system.error()};
    texts.user = *user, texts.assistant = *output, texts.system = *system;
    return texts;
  }
  return Error{"not a sample of any export format (no \"messages\", \"conversations\" or \"instruction\" key)"};
}

Json DatasetInfoEntry(ExportFormat format, const std::string& file_name) {
  switch (format) {
    case ExportFormat::kMessages:
      return Json{{"file_name", file_name},
                  {"formatting", "sharegpt"},
                  {"columns", Json{{"messages", "messages"}}},
                  {"tags", Json{{"role_tag", "role"},
                                {"content_tag", "content"},
                                {"user_tag", "user"},
                                {"assistant_tag", "assistant"},
                                {"system_tag", "system"}}}};
    case ExportFormat::kShareGpt:
      return Json{{"file_name", file_name},
                  {"formatting", "sharegpt"},
                  {"columns", Json{{"messages", "conversations"}, {"system", "system"}}},
                  {"tags", Json{{"role_tag", "from"}, {"content_tag", "value"}, {"user_tag", "human"}, {"assistant_tag", "gpt"}}}};
    case ExportFormat::kAlpaca:
      return Json{{"file_name", file_name},
                  {"formatting", "alpaca"},
                  {"columns", Json{{"prompt", "instruction"}, {"query", "input"}, {"response", "output"}, {"system", "system"}}}};
  }
  return Json::object();
}

}  // namespace villa
