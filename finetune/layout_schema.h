#pragma once
// The JSON Schema of the layout object (FORMAT.md), for constrained decoding of LLM answers:
//   "response_format": {"type": "json_schema",
//                       "json_schema": {"name": "villa_layout", "strict": true, "schema": LayoutJsonSchema()}}
// as enforced by vLLM (xgrammar / guidance), SGLang, llama.cpp and Ollama.
//
// Shape: an object with exactly the six keys in canonical order (rooms, entrance, doors, opens, windows,
// interiors). Each is an object of named elements: the value schema is given by "additionalProperties"
// and the names by "propertyNames": {"pattern": ...} (room names category_L/i with L in 0..2 and i in
// 0..5, the limits of rules 6; element names a plain identifier). Element objects list their keys in
// the order the canonical writer emits them ("shape", then "is_panoramic" for windows, then "level"),
// because grammar engines fix the key order to the schema's. Shapes are patterns over the canonical
// shapely strings: "shapely.box(a, b, c, d)", "shapely.Polygon([(x, y), ...])" with at least 3 points,
// "shapely.LineString([(x1, y1), (x2, y2)])"; numbers with at most two decimals, no exponent.
// `level` is an integer enum 0..2 (entrance: 0 only); `is_panoramic` is 0 or 1.
// The schema constrains syntax only; ValidateLayout still decides whether the geometry is valid.
#include <nlohmann/json.hpp>

#include "util/result.h"

namespace villa {

const nlohmann::ordered_json& LayoutJsonSchema();

// The whole OpenAI-style `response_format` object wrapping LayoutJsonSchema() (name "villa_layout",
// strict true).
const nlohmann::ordered_json& LayoutResponseFormat();

// Checks `value` against LayoutJsonSchema() with a small interpreter of the keywords it uses (type,
// properties, required, additionalProperties, propertyNames, pattern, enum). The error names the JSON
// path and the bad value. Used to prove that every training answer is accepted by the grammar the
// generator decodes with.
Status MatchLayoutJsonSchema(const nlohmann::ordered_json& value);

}  // namespace villa
