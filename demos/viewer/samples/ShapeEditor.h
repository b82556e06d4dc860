// b2a_viewer: the sandbox's shape editor: the parameters of a superellipse, an ellipse, a circle
// or a heart, and the shape they make (or the factory's reason for refusing them).
#pragma once

#include "b2analytic/Shape.h"

#include <string>

namespace b2a::viewer
{

/// The kinds of shape the editor makes.
enum class EditorKind : int
{
	superellipse = 0, ///< |x/a|^n + |y/b|^m ≤ 1
	ellipse,          ///< n = m = 2
	circle,           ///< radius a
	heart             ///< the paper's heart with parameter alpha
};

/// The editor's parameters and the shape they make.
struct ShapeEditor
{
	EditorKind kind = EditorKind::superellipse; ///< which shape
	float a = 1.0f;     ///< semi-axis along x (the circle's radius)
	float b = 0.6f;     ///< semi-axis along y
	float n = 4.0f;     ///< exponent along x
	float m = 4.0f;     ///< exponent along y
	float alpha = 1.0f; ///< the heart's alpha
	ShapePtr shape;     ///< the shape made, null when refused
	std::string error;  ///< the factory's message when refused (it names the field and value)

	/// Make the shape from the parameters. False (no shape, `error` set) when the factory refuses
	/// them, as it does for a value typed past a slider's range.
	bool Make();
	/// The editor's part of the panel (Dear ImGui); remakes the shape when a value changes.
	void Panel();
};

} // namespace b2a::viewer
