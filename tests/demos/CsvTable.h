// b2analytic tests: reading the benchmarks' CSV tables (plain cells, no quoting).
#pragma once

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace b2a::test
{

/// One CSV row, cells by column name.
using CsvRow = std::map<std::string, std::string>;

/// The cells of one CSV line; an empty last cell ("a,b,") counts (getline alone would drop it).
inline std::vector<std::string> SplitCsvLine(const std::string& line)
{
	std::vector<std::string> cells;
	size_t start = 0;
	for (size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
		cells.push_back(line.substr(start, comma - start));
	cells.push_back(line.substr(start));
	return cells;
}

/// The CSV as rows keyed by column name; `header` receives the column names.
inline std::vector<CsvRow> ReadCsv(const std::string& path, std::vector<std::string>& header)
{
	std::ifstream f(path);
	REQUIRE(f.good());
	std::string line;
	REQUIRE(std::getline(f, line));
	header = SplitCsvLine(line);
	std::vector<CsvRow> rows;
	while (std::getline(f, line))
	{
		const std::vector<std::string> cells = SplitCsvLine(line);
		REQUIRE(cells.size() == header.size());
		CsvRow row;
		for (size_t i = 0; i < cells.size(); ++i)
			row[header[i]] = cells[i];
		rows.push_back(row);
	}
	return rows;
}

/// A cell as a number; fails the test when it is not one.
inline double CsvNumber(const CsvRow& row, const std::string& column)
{
	const std::string& text = row.at(column);
	char* end = nullptr;
	const double v = std::strtod(text.c_str(), &end);
	INFO("column " << column << " = '" << text << "'");
	REQUIRE(*end == '\0');
	return v;
}

} // namespace b2a::test
