# Turns a text file into a C++ source holding its bytes, so `villa` needs no data file at run time.
#   cmake -DINPUT=<file> -DOUTPUT=<file.cpp> -DSYMBOL=<name> -P embed_text.cmake
# Defines `extern const char SYMBOL[]` (NUL-terminated) and `extern const std::size_t SYMBOL_size`
# in namespace villa::embedded. Bytes are written as hex, so any content (quotes, backslashes, the
# ")" of a raw string) is safe.
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" hex_length)
math(EXPR byte_count "${hex_length} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
# Break the initialiser into lines of 16 bytes (CMake regexes have no {n}, so spell the group out).
string(REPEAT "0x[0-9a-f][0-9a-f]," 16 row)
string(REGEX REPLACE "(${row})" "\\1\n  " bytes "${bytes}")
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${INPUT} by finetune/embed_text.cmake; do not edit.\n"
  "#include <cstddef>\n"
  "namespace villa::embedded {\n"
  "extern const char ${SYMBOL}[];\n"
  "extern const std::size_t ${SYMBOL}_size;\n"
  "const char ${SYMBOL}[] = {\n  ${bytes}0x00};\n"
  "const std::size_t ${SYMBOL}_size = ${byte_count};\n"
  "}  // namespace villa::embedded\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
