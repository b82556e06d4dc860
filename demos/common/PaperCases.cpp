// b2analytic demos: the paper's pair cases.
#include "PaperCases.h"

namespace b2a::demo
{

LevelResult ContactCase::Solve() const
{
	if (mode == "common")
		return SolveCommonLevel(*a, pa, *b, pb, method);
	return SolveScaleA(*a, pa, *b, pb, method);
}

namespace
{
// A case with our own poses (the paper's are missing from its text), solved automatically.
ContactCase OwnPoses(const char* name, const char* description, const char* mode, ShapePtr a, ShapePtr b, Pose pa, Pose pb)
{
	ContactCase c;
	c.name = name;
	c.description = description;
	c.mode = mode;
	c.a = std::move(a);
	c.b = std::move(b);
	c.pa = pa;
	c.pb = pb;
	return c;
}

// A case the paper specifies fully, with its level and point where it gives them.
ContactCase PaperPoses(const char* name, const char* description, const char* mode, ShapePtr a, ShapePtr b, Pose pa, Pose pb,
                       MethodChoice method, double paperLevel, Vec2 paperPoint)
{
	ContactCase c = OwnPoses(name, description, mode, std::move(a), std::move(b), pa, pb);
	c.ownPoses = false;
	c.method = method;
	c.paperLevel = paperLevel;
	c.paperPoint = paperPoint;
	return c;
}
} // namespace

std::vector<ContactCase> PaperContactCases()
{
	std::vector<ContactCase> cases;
	// Superellipses of the paper's Figure 1 (n = 6, m = 8, a = 2, b = 4), poses ours.
	const ShapePtr se = MakeSuperellipse(2.0, 4.0, 6.0, 8.0);
	cases.push_back(OwnPoses("superellipse_separated", "separated superellipses enlarged to touch (paper Fig. 2a, 3a kind)", "common", se,
	                 se, Pose({0.0, 0.0}, kPi / 4), Pose({13.0, 9.0}, -kPi / 6)));
	cases.push_back(OwnPoses("superellipse_overlapping", "overlapping superellipses reduced to touch (paper Fig. 2b, 3b kind)", "common",
	                 se, se, Pose({0.0, 0.0}, kPi / 4), Pose({1.5, -5.5}, kPi / 3)));
	// Hearts (paper eq. 20 with α = 1), grid method; poses ours.
	const ShapePtr heart = MakeHeart(1.0);
	cases.push_back(OwnPoses("heart_separated", "heart i enlarged onto heart j's surface, grid method (paper Fig. 6a, 7a kind)", "scale_a",
	                 heart, heart, Pose({3.0, 5.0}, 0.2), Pose({4.9, 6.8}, -0.5)));
	cases.push_back(OwnPoses("heart_overlapping", "heart i reduced onto heart k's surface, grid method (paper Fig. 6b, 7b kind)",
	                 "scale_a", heart, heart, Pose({3.0, 5.0}, 0.2), Pose({3.7, 5.9}, 0.6)));
	cases.push_back(OwnPoses("heart_in_notch", "a small heart inside the notch of a big one: several local minima", "scale_a",
	                 MakeHeart(0.05), MakeHeart(1.0), Pose({0.0, 1.1}, kPi), Pose({0.0, 0.0}, 0.0)));
	// Ellipses with the grid method (paper Fig. 9 kind), poses ours.
	const ShapePtr ell = MakeEllipse(4.0, 2.0);
	cases.push_back(OwnPoses("ellipse_grid_separated", "separated ellipses, grid method (paper Fig. 9a, 9c kind)", "scale_a", ell, ell,
	                 Pose({0.0, 0.0}, 0.3), Pose({9.0, 4.0}, -0.4)));
	cases.push_back(OwnPoses("ellipse_grid_overlapping", "overlapping ellipses, grid method (paper Fig. 9b, 9d kind)", "scale_a", ell, ell,
	                 Pose({0.0, 0.0}, 0.3), Pose({4.0, 1.5}, 1.2)));
	// The paper's 1000:1 ellipses (Fig. 16), fully specified: j rescaled onto i's surface.
	const ShapePtr needle = MakeEllipse(0.1, 100.0);
	const Pose pi({1.2, 3.4}, kPi / 5.6), pj({2.1, -19.5}, kPi / 4.5);
	const Vec2 paperPoint(54.4032, -81.2724);
	cases.push_back(PaperPoses("ellipse_1000_grid", "1000:1 ellipses, j enlarged onto i's surface by the grid method (paper Fig. 16)",
	                 "scale_a", needle, needle, pj, pi, MethodChoice::automatic, 13.6177, paperPoint));
	cases.push_back(PaperPoses("ellipse_1000_newton_scale", "the same by Newton on B's surface (the paper reports singular Jacobians)",
	                 "scale_a", needle, needle, pj, pi, MethodChoice::newton, 13.6177, paperPoint));
	cases.push_back(PaperPoses("ellipse_1000_common", "1000:1 ellipses, both rescaled to the common level (automatic: Newton)", "common",
	                 needle, needle, pi, pj, MethodChoice::automatic, 0.0, Vec2()));
	return cases;
}

std::vector<CollisionCase> PaperCollisionCases()
{
	const auto superellipse = MakeSuperellipse(2.0, 4.0, 6.0, 8.0);
	const auto heart = MakeHeart(1.0);
	return {
		{"superellipses", superellipse, superellipse, Motion{Pose({-6.0, -8.0}, kPi / 4), {600.0, 450.0}, 40.0},
		 Motion{Pose({25.0, 12.0}, -kPi / 6), {-500.0, -250.0}, -30.0}, 0.05},
		{"hearts", heart, heart, Motion{Pose({2.0, 4.5}, 0.2), {120.0, 110.0}, 25.0}, Motion{Pose({5.5, 7.8}, -0.6), {-160.0, -90.0}, -40.0},
		 0.03},
		{"ellipses", MakeEllipse(10.0, 4.0), MakeEllipse(30.0, 12.0), Motion{Pose({-60.0, 40.0}, 0.5), {3000.0, -1500.0}, 20.0},
		 Motion{Pose({30.0, -10.0}, -0.3), {-500.0, 400.0}, -5.0}, 0.05},
	};
}

} // namespace b2a::demo
