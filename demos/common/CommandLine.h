// b2analytic demos: the command line of every demo and benchmark (CLI11), and the options they
// all share (--out, --seed, --quick, --help).
#pragma once

#include "DemoCommon.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace b2a::demo
{

// Validators for CommandLine::Add. Each accepts a value as the demos always read it and rewrites
// it in a form CLI11 2.1 then converts exactly: CLI11 reads integers with base 0 ("012" would be
// octal 10) and floating-point numbers through long double (a decimal rounded twice can differ
// from strtod's double in the last bit), so the rewritten text is plain decimal digits for a
// whole number and a hexadecimal floating-point literal, exact in any precision, for a real one.
// A value they reject is reported as "--option: needs ..., got 'value'".

/// A whole number from `lo` to `hi`, written as any number strtod reads ("40", "40.0", "1e6").
CLI::Validator WholeNumber(double lo, double hi);
/// A finite number from `lo` to `hi`, as strtod reads it.
CLI::Validator RealNumber(double lo, double hi);
/// A whole number from 0 to 2^64 - 1 in decimal digits (a random seed).
CLI::Validator UnsignedInteger();
/// One of `names`, spelled exactly.
CLI::Validator OneOf(std::vector<std::string> names);
/// A comma-separated list of one or more items, each accepted by `item` ("4,6,8"); empty items
/// are errors. Rewrites every item as `item` does.
CLI::Validator ListOf(CLI::Validator item);

/// `T` where a template argument must not be deduced (an option's defaults take the option's type:
/// 40000 for a std::uint64_t).
template <class T>
using NotDeduced = typename std::enable_if<true, T>::type;

/// A program's command line. The program adds its own options, then Parse adds the common ones
/// and reads the arguments:
///
///     CommandLine cli("b2a_demo_packing", kHelp);
///     int particles = 0;
///     cli.Add("--particles", particles, 900, 200, "N", "number of particles (default 900, quick 200)",
///             WholeNumber(1, 20000));
///     const DemoOptions opt = cli.Parse(argc, argv);
///
/// --help prints `help` (what the program does and writes), the usage line, the program's options
/// and the common ones. An option given more than once takes its last value.
class CommandLine
{
public:
	/// The command line of the program `name`; `help` is the text --help prints above the usage line.
	CommandLine(const std::string& name, const std::string& help);

	/// An option with one value, read into `value` by `check` (which also validates it); `text`
	/// names the value in the help ("N", "T"). Without the option `value` keeps what it holds.
	template <class T>
	CLI::Option* Add(const std::string& flag, T& value, const std::string& text, const std::string& help,
	                 const CLI::Validator& check)
	{
		return m_app.add_option(flag, value, help)->type_name(text)->transform(check);
	}

	/// A comma-separated list ("4,6,8"), each item read into `values` by `check`.
	template <class T>
	CLI::Option* Add(const std::string& flag, std::vector<T>& values, const std::string& text, const std::string& help,
	                 const CLI::Validator& check)
	{
		return m_app
			.add_option_function<std::string>(
				flag, [&values](const std::string& list) { values = SplitList<T>(list); }, help)
			->type_name(text)
			->transform(ListOf(check));
	}

	/// Either kind of option, with one default for a full run and another for --quick.
	template <class T>
	CLI::Option* Add(const std::string& flag, T& value, const NotDeduced<T>& full, const NotDeduced<T>& quick,
	                 const std::string& text, const std::string& help, const CLI::Validator& check)
	{
		CLI::Option* option = Add(flag, value, text, help, check);
		m_quickDefaults.push_back([&value, option, full, quick](bool isQuick) {
			if (option->count() == 0)
				value = isQuick ? quick : full;
		});
		return option;
	}

	/// Adds the common options (--out DIR, --seed N, --quick, --help) and reads the arguments. Exits 0
	/// after printing the help on --help; exits 2 with a message naming the option and the value
	/// on a bad argument; exits 1 if the output folder (default out/<name>) cannot be created.
	/// Files the program writes there through WriteText, WriteJson or OpenOutput replace those
	/// of its earlier run (OutputRecord).
	DemoOptions Parse(int argc, char** argv);

	/// The CLI11 application, for what Add does not cover.
	CLI::App& App() { return m_app; }

private:
	// The items of a list ListOf has validated and rewritten.
	template <class T>
	static std::vector<T> SplitList(const std::string& list)
	{
		std::vector<T> values;
		size_t start = 0;
		while (start <= list.size())
		{
			const size_t comma = std::min(list.find(',', start), list.size());
			values.emplace_back();
			ReadItem(list.substr(start, comma - start), values.back());
			start = comma + 1;
		}
		return values;
	}
	static void ReadItem(const std::string& item, double& value);
	static void ReadItem(const std::string& item, int& value);
	static void ReadItem(const std::string& item, std::string& value);

	std::string m_name;
	CLI::App m_app;
	std::vector<std::function<void(bool)>> m_quickDefaults;
};

} // namespace b2a::demo
