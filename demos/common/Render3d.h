// b2analytic demos: shaded 3D views of posed 3D shapes as SVG (orthographic, painter's
// algorithm, Lambert shading), with axes in the world's units, and meshes as Wavefront OBJ.
#pragma once

#include "b2analytic/3d/Shape3.h"

#include <array>
#include <string>
#include <vector>

namespace b2a::demo
{

/// A triangle mesh in world coordinates, triangles counter-clockwise seen from outside.
struct Mesh3
{
	std::string name;                       ///< the object's name (OBJ group)
	std::vector<Vec3> vertex;               ///< world positions
	std::vector<std::array<int, 3>> triangle; ///< vertex indices
	std::string colour = "#4e79a7";         ///< base colour (#rrggbb) for shading
};

/// The mesh of a shape's surface samples (about `samples` of them, SurfaceSamples3's grid) at
/// a pose: quads between rings split in two, fans at the poles.
Mesh3 SurfaceMesh(const Shape3& shape, const Pose3& pose, int samples, const std::string& name, const std::string& colour);

/// Writes meshes as one Wavefront OBJ file (an object per mesh); exits 1 with a message if the
/// file cannot be written.
void WriteObj(const std::string& path, const std::vector<Mesh3>& meshes, const std::string& comment);

/// A marked point with an optional arrow (a contact point and its normal).
struct Marker3
{
	Vec3 point;                    ///< world point
	Vec3 arrow;                    ///< arrow from the point (world length; zero: none)
	std::string colour = "#000000"; ///< colour of dot and arrow
	std::string label;             ///< text next to the point
};

/// What a view shows: the world box (axes with ticks in `unit`), the camera's direction.
struct View3
{
	Box3 box;                 ///< the world box drawn as axes (fixed across snapshots)
	double azimuth = -0.9;    ///< camera direction's azimuth about z (radians)
	double elevation = 0.45;  ///< camera direction's elevation above the x-y plane (radians)
	double tick = 5.0;        ///< tick spacing on the axes
	std::string unit = "mm";  ///< the axes' unit
};

/// An SVG group drawing the meshes shaded (light from the camera's upper left), the box's
/// back edges as axes with ticks and labels, then the markers on top, in the pixel rectangle
/// (x0, y0, width, height) with `title` at its top.
std::string RenderPanel(const std::vector<Mesh3>& meshes, const View3& view, const std::vector<Marker3>& markers,
                        const std::string& title, double x0, double y0, double width, double height);

/// A complete SVG document of the given pixel size around `body` (white background).
std::string SvgDocument(const std::string& body, double width, double height);

} // namespace b2a::demo
