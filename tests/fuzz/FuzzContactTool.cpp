// b2analytic fuzzing: one request line of the b2a_contact tool, any bytes.
//
// AnswerContactRequest promises one JSON object on one line for any input: {"id", "status":
// "ok", ...} with finite numbers and points of one dimension (2 numbers for 2D shapes, 3 for 3D),
// or {"id", "status": "error", "error": "<message>"}, and never throws. A time of impact of
// "time": null (no contact before t_max) carries null points and the gap at t_max instead. Any
// other answer, an exception, a crash, a hang or a sanitizer report is a bug.
#include "ContactTool.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace
{
using json = nlohmann::ordered_json; // keeps the order of the answer's keys

[[noreturn]] void Fail(const char* what, const std::string& line, const std::string& answer)
{
	std::fprintf(stderr, "b2a fuzz check failed: %s\nrequest: %s\nanswer: %s\n", what, line.c_str(), answer.c_str());
	__builtin_trap();
}

bool FiniteNumber(const json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

// A point or vector of `size` finite numbers.
bool FiniteVector(const json& v, std::size_t size)
{
	if (!v.is_array() || v.size() != size)
		return false;
	for (const json& x : v)
		if (!FiniteNumber(x))
			return false;
	return true;
}

void CheckOkAnswer(json& out, const std::string& line, const std::string& answer)
{
	if (out["status"] != "ok")
		Fail("ok is true but the status is not \"ok\"", line, answer);
	if (out["mode"] == "toi" && out["time"].is_null())
	{
		if (!FiniteNumber(out["separation_at_t_max"]))
			Fail("a time of impact without contact has no finite separation_at_t_max", line, answer);
		return;
	}
	if (out["mode"] == "toi" && !FiniteNumber(out["time"]))
		Fail("a time of impact is neither null nor finite", line, answer);
	for (const char* key : {"scale", "separation"})
		if (!FiniteNumber(out[key]))
			Fail("a number of an ok answer is not finite", line, answer);
	const std::size_t dimension = out["point"].is_array() ? out["point"].size() : 0;
	if (dimension != 2 && dimension != 3)
		Fail("the point of an ok answer is not a 2- or 3-vector", line, answer);
	for (const char* key : {"point", "normal", "point_a", "point_b"})
		if (!FiniteVector(out[key], dimension))
			Fail("a point of an ok answer is not finite numbers of the point's dimension", line, answer);
	if (!out["touching"].is_boolean() || !out["iterations"].is_number_integer())
		Fail("touching or iterations has the wrong type", line, answer);
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const std::string line(reinterpret_cast<const char*>(data), size);
	bool ok = true;
	const std::string answer = b2a::tool::AnswerContactRequest(line, ok);
	if (answer.find('\n') != std::string::npos)
		Fail("the answer spans more than one line", line, answer);
	json out;
	try
	{
		out = json::parse(answer);
	}
	catch (const json::exception&)
	{
		Fail("the answer is not JSON", line, answer);
	}
	if (!out.is_object() || !out.contains("id") || !out.contains("status") || out.begin().key() != "id")
		Fail("the answer is not an object starting with \"id\" and holding \"status\"", line, answer);
	if (ok)
		CheckOkAnswer(out, line, answer);
	else
	{
		if (out["status"] != "error" || !out["error"].is_string() || out["error"].get<std::string>().empty())
			Fail("an error answer has no \"error\" message", line, answer);
	}
	return 0;
}
