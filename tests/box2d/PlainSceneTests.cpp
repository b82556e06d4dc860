// b2analytic tests: scenes of Box2D's own shapes behave exactly as without the extension.
#include "PlainScene.h"
#include "SceneSupport.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <memory>
#include <string>

TEST_CASE("a scene of boxes, polygons and circles steps bit-identically with and without the adapter")
{
	// This process has the adapter's contact registered (the other tests here create analytic
	// fixtures, which links it in); b2a_plain_scene links Box2D alone. Both run the same scene.
	b2World probe(b2Vec2(0.0f, 0.0f));
	b2BodyDef bd;
	b2a::CreateAnalyticFixture(probe.CreateBody(&bd), b2a::MakeCircle(1.0), 1.0f); // registration is in place

	const int steps = 240;
	const std::string here = b2a::test::RunPlainScene(steps);
	std::string there;
	{
		const std::string cmd = std::string("\"") + B2A_PLAIN_SCENE_EXE + "\" " + std::to_string(steps);
		std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
		REQUIRE(pipe);
		char buffer[4096];
		size_t n;
		while ((n = std::fread(buffer, 1, sizeof(buffer), pipe.get())) > 0)
			there.append(buffer, n);
	}
	REQUIRE(there.size() > 1000); // 61 bodies of six hexadecimal numbers
	CHECK(here == there);
}
