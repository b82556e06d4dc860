// b2analytic demos: shared output files and progress.
#include "DemoCommon.h"

#include "OutputRecord.h"

#include <cstdio>
#include <cstdlib>

namespace b2a::demo
{

std::ofstream OpenOutput(const std::string& path)
{
	if (OutputRecord* record = CurrentOutputRecord())
		record->Add(path); // before writing: the first file clears the program's earlier output
	std::ofstream f(path);
	if (!f)
	{
		std::fprintf(stderr, "cannot write '%s'\n", path.c_str());
		std::exit(1);
	}
	return f;
}

void WriteText(const std::string& path, const std::string& text)
{
	std::ofstream f = OpenOutput(path);
	f << text;
	f.close();
	if (!f)
	{
		std::fprintf(stderr, "cannot write '%s'\n", path.c_str());
		std::exit(1);
	}
}

void WriteJson(const std::string& path, const Json& value)
{
	WriteText(path, value.dump(2) + "\n");
}

double Progress::Elapsed() const
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
}

void Progress::Report(double fraction, const std::string& note)
{
	const double t = Elapsed();
	if (fraction < 1.0 && t - m_last < 0.5)
		return;
	m_last = t;
	std::fprintf(stderr, "[%s] %5.1f%%  %6.1f s  %s\n", m_name, 100.0 * fraction, t, note.c_str());
}

} // namespace b2a::demo
