// b2analytic tests: a demo's run removes the files its earlier run wrote into the same output
// folder, and nothing else (demos/common/OutputRecord.h).
#include <doctest/doctest.h>

#include "common/OutputRecord.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using b2a::demo::OutputRecord;

namespace
{
void Touch(const fs::path& path, const std::string& text = "x")
{
	std::ofstream f(path);
	f << text;
}

// A program's run: the record made, then each file noted and written, as WriteText does.
void Run(const std::string& folder, const std::string& program, const std::vector<std::string>& files)
{
	OutputRecord record(folder, program);
	for (const std::string& name : files)
	{
		record.Add(folder + "/" + name);
		Touch(fs::path(folder) / name, program);
	}
}

std::vector<std::string> Files(const fs::path& folder)
{
	std::vector<std::string> names;
	for (const auto& e : fs::directory_iterator(folder))
		names.push_back(e.path().filename().string());
	std::sort(names.begin(), names.end());
	return names;
}
} // namespace

TEST_CASE("OutputRecord: a second run removes what the first wrote and no longer writes, and nothing else goes")
{
	const fs::path folder = "demo_out/output_record";
	fs::remove_all(folder);
	fs::create_directories(folder / "user_folder");
	Touch(folder / "notes.txt");              // the user's own file
	Touch(folder / "user_folder" / "a.csv"); // and folder

	Run(folder.string(), "b2a_demo_hopper", {"summary.json", "snapshot_0.110.svg", "discharge.csv"});
	Run(folder.string(), "b2a_demo_packing", {"energies.csv", "final.svg"});
	CHECK(Files(folder) == std::vector<std::string>{".b2a_outputs.json", "discharge.csv", "energies.csv", "final.svg", "notes.txt",
	                                                "snapshot_0.110.svg", "summary.json", "user_folder"});

	// The hopper again, with other snapshot times: its old snapshot goes, the packing's files,
	// the user's file and folder stay.
	Run(folder.string(), "b2a_demo_hopper", {"summary.json", "snapshot_0.250.svg", "discharge.csv"});
	CHECK(Files(folder) == std::vector<std::string>{".b2a_outputs.json", "discharge.csv", "energies.csv", "final.svg", "notes.txt",
	                                                "snapshot_0.250.svg", "summary.json", "user_folder"});
	CHECK(fs::exists(folder / "user_folder" / "a.csv"));

	// A file the packing writes after the hopper wrote it is the packing's: the hopper's next run
	// leaves it.
	Run(folder.string(), "b2a_demo_packing", {"energies.csv", "final.svg", "summary.json"});
	Run(folder.string(), "b2a_demo_hopper", {"discharge.csv"});
	CHECK(Files(folder) == std::vector<std::string>{".b2a_outputs.json", "discharge.csv", "energies.csv", "final.svg", "notes.txt",
	                                                "summary.json", "user_folder"});
	std::ifstream summary(folder / "summary.json");
	std::string owner;
	summary >> owner;
	CHECK(owner == "b2a_demo_packing");

	// The record names every file with the program that wrote it last.
	std::ifstream recordFile(folder / OutputRecord::kFileName);
	const nlohmann::json record = nlohmann::json::parse(recordFile);
	CHECK(record == nlohmann::json{{"energies.csv", "b2a_demo_packing"},
	                               {"final.svg", "b2a_demo_packing"},
	                               {"summary.json", "b2a_demo_packing"},
	                               {"discharge.csv", "b2a_demo_hopper"}});
}

TEST_CASE("OutputRecord: whatever the record says, only plain files directly in the folder are removed")
{
	const fs::path folder = "demo_out/output_record_guard";
	fs::remove_all(folder);
	fs::create_directories(folder / "sub");
	Touch(folder / "sub" / "kept.txt");
	Touch(folder / "outside.txt");
	fs::create_directories("demo_out/output_record_neighbour");
	Touch("demo_out/output_record_neighbour/kept.txt");
	{
		std::ofstream f(folder / OutputRecord::kFileName);
		f << R"({"sub": "p", "sub/kept.txt": "p", "../output_record_neighbour/kept.txt": "p", "..": "p", ".": "p",
		         ".b2a_outputs.json": "p", "gone.svg": "p", "outside.txt": "another"})";
	}
	OutputRecord record(folder.string(), "p");
	CHECK(record.ClearEarlier().empty()); // gone.svg is gone already; the rest is not p's to remove
	CHECK(fs::is_directory(folder / "sub"));
	CHECK(fs::exists(folder / "sub" / "kept.txt"));
	CHECK(fs::exists(folder / "outside.txt"));
	CHECK(fs::exists("demo_out/output_record_neighbour/kept.txt"));
	// Entries of p that name nothing p can have written are dropped; the other program's stays.
	std::ifstream recordFile(folder / OutputRecord::kFileName);
	CHECK(nlohmann::json::parse(recordFile) == nlohmann::json{{"outside.txt", "another"}});

	// Files elsewhere are not recorded; a record that is not JSON is replaced, its files left.
	{
		std::ofstream f(folder / OutputRecord::kFileName);
		f << "not json";
	}
	OutputRecord again(folder.string(), "p");
	again.Add("demo_out/output_record_neighbour/kept.txt");
	again.Add((folder / "sub" / "kept.txt").string());
	again.Add((folder / "new.csv").string());
	std::ifstream replaced(folder / OutputRecord::kFileName);
	CHECK(nlohmann::json::parse(replaced) == nlohmann::json{{"new.csv", "p"}});
	CHECK(fs::exists(folder / "outside.txt"));
}

#ifdef B2A_BENCH_PAIRS
TEST_CASE("b2a_bench_pairs run twice into one folder leaves only the second run's pictures beside the user's files")
{
	const fs::path folder = "demo_out/output_record_bench";
	fs::remove_all(folder);
	fs::create_directories(folder);
	Touch(folder / "notes.txt");
	const std::string exe = std::string("\"") + B2A_BENCH_PAIRS + "\" --quick --poses 1 --repeats 1 --out " + folder.string();
	REQUIRE(std::system((exe + " --families circle,ellipse_a3 > /dev/null 2>&1").c_str()) == 0);
	CHECK(fs::exists(folder / "pairs_circle.svg"));
	CHECK(fs::exists(folder / "pairs_ellipse_a3.svg"));
	REQUIRE(std::system((exe + " --families circle > /dev/null 2>&1").c_str()) == 0);
	CHECK(Files(folder) == std::vector<std::string>{".b2a_outputs.json", "notes.txt", "pairs.csv", "pairs.md", "pairs_circle.svg"});
}
#endif
