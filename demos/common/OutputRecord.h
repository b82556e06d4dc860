// b2analytic demos: which program wrote which file of an output folder, so that a run removes
// its own earlier output and leaves no stale file beside the new ones.
#pragma once

#include <string>
#include <vector>

namespace b2a::demo
{

/// The files programs wrote into one output folder, kept in the folder's OutputRecord::kFileName
/// (a JSON object: file name -> program). A program's run removes the files its earlier runs
/// wrote there before it writes its first file (a hopper run with other snapshot times leaves no
/// snapshot of the last run behind). Nothing else is ever removed: not the user's files, not
/// another program's files, no folder, and only names directly in the folder; a file written
/// by one program and then by another belongs to the last.
class OutputRecord
{
public:
	/// The record's file in the folder.
	static constexpr const char* kFileName = ".b2a_outputs.json";

	/// The record of `folder` (which exists) for the program `program`.
	OutputRecord(std::string folder, std::string program);

	/// Removes the files this program wrote into the folder in earlier runs and drops them from
	/// the record; returns their names. Called once, before the first Add.
	std::vector<std::string> ClearEarlier();

	/// Notes that this program wrote `path`; does nothing when `path` is not directly in the folder.
	/// The first call clears the earlier output (ClearEarlier) if that has not been done.
	void Add(const std::string& path);

	/// The folder.
	const std::string& Folder() const { return m_folder; }

private:
	std::string m_folder, m_program;
	bool m_cleared = false;
	std::vector<std::string> m_written; // names this run wrote, as recorded
};

/// Start recording what this program writes into `folder` (CommandLine::Parse does): WriteText,
/// WriteJson and OpenOutput then add every file they write there to its OutputRecord.
void RecordOutputsIn(const std::string& folder, const std::string& program);

/// The record of the current program's output folder (nullptr before RecordOutputsIn).
OutputRecord* CurrentOutputRecord();

} // namespace b2a::demo
