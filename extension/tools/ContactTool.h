// b2analytic: the request handling of the b2a_contact tool (JSON Lines in, JSON Lines out).
#pragma once

#include <string>

namespace b2a::tool
{

/// Answer one request line. Returns the JSON object to print (one line, no newline) and sets
/// `ok` to false when the answer is an error object. Never throws: every failure, malformed
/// JSON included, becomes {"id": ..., "status": "error", "error": "..."}.
std::string AnswerContactRequest(const std::string& line, bool& ok);

/// The first line of `b2a_contact --help`: what the tool does.
const char* ContactToolSummary();

/// The text `b2a_contact --help` prints after the usage and the options: the 2D part (request and
/// answer formats, exit status, an example), then the 3D shapes and the toi mode.
const char* ContactToolHelp();

/// The --help text's part on 2D shapes and modes.
const char* ContactTool2dHelp();

} // namespace b2a::tool
