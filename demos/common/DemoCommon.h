// b2analytic demos: output files, progress and summary shared by every demo (the command line
// is CommandLine.h).
#pragma once

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <string>

namespace b2a::demo
{

/// The options every demo and benchmark takes (CommandLine::Parse reads them).
struct DemoOptions
{
	std::string name;       ///< the program's name (for messages)
	std::string out;        ///< output folder (created if missing)
	std::uint64_t seed = 1; ///< random seed
	bool quick = false;     ///< reduced run for CI (under a minute)
};

/// JSON with fields in the order they were written.
using Json = nlohmann::ordered_json;

/// Write `value` as pretty JSON to `path`; exits 1 with a message if the file cannot be written.
/// Like every writer here, it adds the file to the output folder's record (OutputRecord).
void WriteJson(const std::string& path, const Json& value);

/// Write text to a file; exits 1 with a message if it cannot be written.
void WriteText(const std::string& path, const std::string& text);

/// A file opened for writing a little at a time (a CSV filled during the run); exits 1 with a
/// message if it cannot be created.
std::ofstream OpenOutput(const std::string& path);

/// Progress on stderr, at most a few lines a second.
class Progress
{
public:
	/// A progress reporter for a demo.
	explicit Progress(const char* name) : m_name(name), m_start(std::chrono::steady_clock::now()) {}
	/// Report a fraction done (0..1) with a short note.
	void Report(double fraction, const std::string& note);
	/// Seconds since construction.
	double Elapsed() const;

private:
	const char* m_name;
	std::chrono::steady_clock::time_point m_start;
	double m_last = -1.0;
};

} // namespace b2a::demo
