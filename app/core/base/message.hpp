#pragma once
// Messages that quote the input. A refusal is one short line (README, "Bad input"), whatever the input
// holds: a 5 MB data: URI, a 60 MB number, a newline or an escape sequence in a key or a file name.
#include <cstddef>
#include <string>
#include <string_view>

namespace shadelab {

// `text` made safe for one terminal line: control characters (C0, DEL, C1) and bytes that are not
// UTF-8 are written as \n, \t, \xNN; valid UTF-8 (a lecturer's "ombrée.json") is kept.
std::string escapeControls(std::string_view text);

// Input quoted in a message: escaped as above and cut to about `limit` bytes, the cut said as
// "...(N bytes)".
std::string quoteInput(std::string_view text, std::size_t limit = 60);

// A whole message as one line: escaped as above; longer than `limit`, its middle is replaced by
// " [... N bytes ...] " so the start (what and where) and the end (why) both stay.
std::string oneLine(std::string_view message, std::size_t limit = 400);

// A log of lines of its own (a GLSL compiler's) as one: its lines joined with "; " (after a line that
// ends in ':', with a space), the trailing newlines dropped. Not escaped or cut: oneLine does that.
std::string joinedLines(std::string log);

}  // namespace shadelab
