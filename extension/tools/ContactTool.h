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

/// The text `b2a_contact --help` prints after the usage and the options: the request and answer
/// formats, the exit status and an example.
const char* ContactToolHelp();

} // namespace b2a::tool
