// b2analytic demos: the command line of every demo and benchmark.
#include "CommandLine.h"

#include "OutputRecord.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

namespace b2a::demo
{

namespace
{
std::string Needs(const std::string& what, const std::string& value)
{
	return "needs " + what + ", got '" + value + "'";
}

std::string FromTo(double lo, double hi)
{
	char text[96];
	std::snprintf(text, sizeof text, "from %g to %g", lo, hi);
	return text;
}

// CLI11's help with its option groups one blank line apart (its own puts two) and no blank line
// at the end.
class HelpLayout : public CLI::Formatter
{
public:
	std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override
	{
		std::string text = CLI::Formatter::make_help(app, std::move(name), mode);
		for (size_t at = text.find("\n\n\n"); at != std::string::npos; at = text.find("\n\n\n", at))
			text.erase(at, 1);
		while (text.size() > 1 && text[text.size() - 2] == '\n')
			text.pop_back();
		return text;
	}
};

// The whole text as strtod reads it, finite.
bool ReadFinite(const std::string& text, double& value)
{
	char* end = nullptr;
	value = std::strtod(text.c_str(), &end);
	return !text.empty() && *end == '\0' && std::isfinite(value);
}

// A finite number from lo to hi (and whole if `whole`), rewritten exactly: decimal digits for a
// whole number, a hexadecimal literal otherwise.
CLI::Validator NumberIn(double lo, double hi, bool whole)
{
	return CLI::Validator(
		[lo, hi, whole](std::string& text) {
			double value = 0.0;
			if (!ReadFinite(text, value) || (whole && value != std::floor(value)) || value < lo || value > hi)
				return Needs(std::string(whole ? "a whole number " : "a number ") + FromTo(lo, hi), text);
			char exact[48];
			std::snprintf(exact, sizeof exact, whole ? "%.0f" : "%a", value);
			text = exact;
			return std::string();
		},
		"", whole ? "WholeNumber" : "RealNumber");
}
} // namespace

CLI::Validator WholeNumber(double lo, double hi)
{
	return NumberIn(lo, hi, true);
}

CLI::Validator RealNumber(double lo, double hi)
{
	return NumberIn(lo, hi, false);
}

CLI::Validator UnsignedInteger()
{
	return CLI::Validator(
		[](std::string& text) {
			const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
			errno = 0;
			const unsigned long long value = digits ? std::strtoull(text.c_str(), nullptr, 10) : 0;
			if (!digits || errno == ERANGE)
				return Needs("a whole number from 0 to 18446744073709551615", text);
			text = std::to_string(value);
			return std::string();
		},
		"", "UnsignedInteger");
}

CLI::Validator OneOf(std::vector<std::string> names)
{
	std::string list;
	for (const std::string& n : names)
		list += (list.empty() ? "" : ", ") + n;
	return CLI::Validator(
		[names, list](std::string& text) {
			return std::find(names.begin(), names.end(), text) != names.end() ? std::string() : Needs("one of " + list, text);
		},
		"", "OneOf");
}

CLI::Validator ListOf(CLI::Validator item)
{
	return CLI::Validator(
		[item](std::string& text) {
			std::string rewritten;
			size_t start = 0;
			for (int k = 1; start <= text.size(); ++k)
			{
				const size_t comma = std::min(text.find(',', start), text.size());
				std::string value = text.substr(start, comma - start);
				const std::string error = item(value);
				if (!error.empty())
					return "item " + std::to_string(k) + " of '" + text + "' " + error;
				rewritten += (start == 0 ? "" : ",") + value;
				start = comma + 1;
			}
			text = rewritten;
			return std::string();
		},
		"", "ListOf");
}

CommandLine::CommandLine(const std::string& name, const std::string& help) : m_name(name), m_app(help, name)
{
	m_app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
	m_app.set_help_flag(); // added back by Parse, among the common options after the program's own
	auto layout = std::make_shared<HelpLayout>();
	layout->column_width(24);
	m_app.formatter(layout);
}

DemoOptions CommandLine::Parse(int argc, char** argv)
{
	DemoOptions o;
	o.name = m_name;
	o.out = "out/" + m_name;
	const std::string common = "Common options";
	m_app.add_option("--out", o.out,
	                 "output folder (default out/<program>); created if missing. The files an\n"
	                 "earlier run of this program wrote there are removed first (listed in\n" +
	                     std::string("DIR/") + OutputRecord::kFileName + "), nothing else")
		->type_name("DIR")
		->group(common);
	m_app.add_option("--seed", o.seed, "random seed (default 1)")->type_name("N")->transform(UnsignedInteger())->group(common);
	m_app.add_flag("--quick", o.quick, "reduced run for CI, under a minute")->group(common);
	m_app.set_help_flag("-h,--help", "this text")->group(common);
	try
	{
		m_app.parse(argc, argv);
	}
	catch (const CLI::CallForHelp&)
	{
		std::fputs(m_app.help().c_str(), stdout);
		std::exit(0);
	}
	catch (const CLI::ParseError& e)
	{
		std::fprintf(stderr, "%s: %s (see --help)\n", m_name.c_str(), e.what());
		std::exit(2);
	}
	for (const auto& setDefault : m_quickDefaults)
		setDefault(o.quick);

	std::error_code ec;
	std::filesystem::create_directories(o.out, ec);
	if (ec || !std::filesystem::is_directory(o.out))
	{
		std::fprintf(stderr, "%s: cannot create output folder '%s': %s\n", m_name.c_str(), o.out.c_str(), ec.message().c_str());
		std::exit(1);
	}
	RecordOutputsIn(o.out, m_name);
	return o;
}

void CommandLine::ReadItem(const std::string& item, double& value)
{
	value = std::strtod(item.c_str(), nullptr); // hexadecimal (RealNumber), exact
}

void CommandLine::ReadItem(const std::string& item, int& value)
{
	value = int(std::strtol(item.c_str(), nullptr, 10)); // decimal digits (WholeNumber)
}

void CommandLine::ReadItem(const std::string& item, std::string& value)
{
	value = item;
}

} // namespace b2a::demo
