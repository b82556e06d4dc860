// b2analytic tests: the plain scene in a program that links Box2D alone (no adapter).
#include "../PlainScene.h"

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv)
{
	const int steps = argc > 1 ? std::atoi(argv[1]) : 240;
	std::fputs(b2a::test::RunPlainScene(steps).c_str(), stdout);
	return 0;
}
