#pragma once
// The one way a message quotes a value that came from outside (a name, a shape string, a JSON value, a
// server's answer): whole when short, else cut, so a 10 MB name makes a one-line error, not 10 MB of output.
#include <cstddef>
#include <string>
#include <string_view>

namespace villa {

// At most this many bytes of a quoted value appear in a message, "..." included.
inline constexpr std::size_t kExcerptLength = 80;

// `text` when it is at most `limit` bytes long; otherwise its first bytes and "..." (`limit` bytes in all),
// never cutting a UTF-8 character in two. `limit` below 4 is taken as 4.
std::string Excerpt(std::string_view text, std::size_t limit = kExcerptLength);

// `text` safe to print on a terminal (issue 33): control bytes (C0 but for none, DEL, and the C1 controls
// U+0080-U+009F) and invalid UTF-8 bytes become \xHH, so a name cannot move the cursor, clear the screen or
// set the window title.
std::string Printable(std::string_view text);

}  // namespace villa
