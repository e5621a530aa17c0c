#pragma once
// Java .properties files (Sweet Home 3D's furniture catalogs), read as java.util.Properties.load does:
// ISO-8859-1 bytes, `#` and `!` comment lines, a line ending in an odd number of backslashes continues
// on the next (whose leading blanks are dropped), the key ends at the first unescaped `=`, `:` or blank,
// escapes \t \n \r \f \uXXXX (UTF-16, surrogate pairs joined) and `\x` = x. A later key replaces an
// earlier one. Keys and values come out as UTF-8.
#include <map>
#include <string>
#include <string_view>

#include "util/result.h"

namespace villa {

using JavaProperties = std::map<std::string, std::string>;

// `where` names the file in errors ("BlendSwap-CC-0.sh3f: PluginFurnitureCatalog.properties"); errors
// give the line: "<where>:12: malformed \uXXXX escape: \u00g1".
Result<JavaProperties> ParseJavaProperties(std::string_view latin1, const std::string& where);

}  // namespace villa
