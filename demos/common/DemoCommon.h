// b2analytic demos: command line, output folder, progress and summary shared by every demo.
#pragma once

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace b2a::demo
{

/// The options every demo takes, and the values of a demo's own options.
struct DemoOptions
{
	std::string name;         ///< the demo's name (for messages)
	std::string out;          ///< output folder (created if missing)
	std::uint64_t seed = 1;   ///< random seed
	bool quick = false;       ///< reduced run for CI (under a minute)
	std::map<std::string, std::string> extra; ///< the demo's own options given, by name

	/// A demo option as a number in [lo, hi], or `fallback` when not given; exits 2 with a
	/// message naming the option and the value when it is not such a number.
	double Number(const std::string& option, double fallback, double lo, double hi) const;
	/// A demo option as a comma-separated list of numbers in [lo, hi]; exits 2 like Number.
	std::vector<double> Numbers(const std::string& option, const std::vector<double>& fallback, double lo, double hi) const;
};

/// Parse --help, --out DIR, --seed N, --quick and the demo's own options `extra` (each taking a
/// value). Prints `help` and exits 0 on --help; prints a message naming the bad argument and
/// exits 2 on anything it does not know. Creates the output folder (default out/<name>).
DemoOptions ParseDemoOptions(int argc, char** argv, const char* name, const char* help,
                             const std::vector<std::string>& extra = {});

/// JSON with fields in the order they were written.
using Json = nlohmann::ordered_json;

/// Write `value` as pretty JSON to `path`; exits 1 with a message if the file cannot be written.
void WriteJson(const std::string& path, const Json& value);

/// Write text to a file; exits 1 with a message if it cannot be written.
void WriteText(const std::string& path, const std::string& text);

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
