// b2analytic demos: the record of which program wrote which file of an output folder.
#include "OutputRecord.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

namespace b2a::demo
{

namespace
{
namespace fs = std::filesystem;
using Record = nlohmann::ordered_json;

// The record in the folder, or an empty one when there is none. A file that is not a record
// (edited by hand, cut short) is reported and replaced: what it listed is then left alone.
Record ReadRecord(const fs::path& file)
{
	std::ifstream in(file);
	if (!in)
		return Record::object();
	try
	{
		Record record = Record::parse(in);
		if (record.is_object())
			return record;
	}
	catch (const Record::exception&)
	{
	}
	std::fprintf(stderr, "warning: '%s' is not a record of output files; starting a new one\n", file.string().c_str());
	return Record::object();
}

void WriteRecord(const fs::path& file, const Record& record)
{
	std::ofstream out(file);
	out << record.dump(1, '\t') << '\n';
	out.close();
	if (!out)
		std::fprintf(stderr, "warning: cannot write the record of output files '%s'\n", file.string().c_str());
}

// A name directly in the folder: no separator, not "." or "..", not the record itself. Only such
// names are ever removed, whatever the record says.
bool IsPlainName(const std::string& name)
{
	return !name.empty() && name != "." && name != ".." && name != OutputRecord::kFileName &&
	       name.find('/') == std::string::npos && name.find('\\') == std::string::npos;
}

std::unique_ptr<OutputRecord> g_current;
} // namespace

OutputRecord::OutputRecord(std::string folder, std::string program) : m_folder(std::move(folder)), m_program(std::move(program))
{
}

std::vector<std::string> OutputRecord::ClearEarlier()
{
	m_cleared = true;
	const fs::path recordFile = fs::path(m_folder) / kFileName;
	Record record = ReadRecord(recordFile);
	std::vector<std::string> removed;
	bool changed = false;
	for (auto it = record.begin(); it != record.end();)
	{
		if (!(it.value().is_string() && it.value().get<std::string>() == m_program))
		{
			++it;
			continue;
		}
		const std::string name = it.key();
		if (IsPlainName(name))
		{
			// A file or a link (the link itself goes, never what it points to); never a folder.
			std::error_code ec;
			const fs::path file = fs::path(m_folder) / name;
			const fs::file_status status = fs::symlink_status(file, ec);
			if (!ec && (fs::is_regular_file(status) || fs::is_symlink(status)) && fs::remove(file, ec))
				removed.push_back(name);
		}
		it = record.erase(it); // removed, gone already, or not a file this program can have written
		changed = true;
	}
	if (changed)
		WriteRecord(recordFile, record);
	return removed;
}

void OutputRecord::Add(const std::string& path)
{
	if (!m_cleared)
		ClearEarlier();
	const fs::path file(path);
	const std::string name = file.filename().string();
	std::error_code ec;
	const fs::path parent = file.has_parent_path() ? file.parent_path() : fs::path(".");
	if (!IsPlainName(name) || !fs::equivalent(parent, m_folder, ec) || ec)
		return;
	if (std::find(m_written.begin(), m_written.end(), name) != m_written.end())
		return; // recorded already (a file rewritten during the run)
	m_written.push_back(name);
	const fs::path recordFile = fs::path(m_folder) / kFileName;
	Record record = ReadRecord(recordFile);
	record[name] = m_program;
	WriteRecord(recordFile, record);
}

void RecordOutputsIn(const std::string& folder, const std::string& program)
{
	g_current = std::make_unique<OutputRecord>(folder, program);
}

OutputRecord* CurrentOutputRecord()
{
	return g_current.get();
}

} // namespace b2a::demo
