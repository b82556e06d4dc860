// b2a_viewer: the one table of samples (category, name, factory), as the testbed's.
#pragma once

#include "Sample.h"

#include <memory>
#include <string>
#include <vector>

namespace b2a::viewer
{

/// A registered sample.
struct SampleEntry
{
	const char* category;                   ///< the panel's group
	const char* name;                       ///< the name shown
	std::unique_ptr<Sample> (*factory)();   ///< makes the sample in its starting state
};

/// Every sample, in the panel's order.
const std::vector<SampleEntry>& Samples();

/// The command-line key of a sample: its name in lower case with spaces as hyphens
/// ("Hopper discharge" → "hopper-discharge").
std::string SampleKey(const SampleEntry& entry);

/// The index of the sample with this key, or -1.
int FindSample(const std::string& key);

} // namespace b2a::viewer
