// b2a_viewer: the shape editor.
#include "samples/ShapeEditor.h"

#include "b2analytic/HeartShape.h"
#include "b2analytic/SuperellipseShape.h"

#include <imgui.h>

namespace b2a::viewer
{

bool ShapeEditor::Make()
{
	try
	{
		switch (kind)
		{
		case EditorKind::superellipse: shape = MakeSuperellipse(a, b, n, m); break;
		case EditorKind::ellipse: shape = MakeEllipse(a, b); break;
		case EditorKind::circle: shape = MakeCircle(a); break;
		case EditorKind::heart: shape = MakeHeart(alpha); break;
		}
		error.clear();
		return true;
	}
	catch (const InvalidParameter& e)
	{
		shape.reset();
		error = e.what();
		return false;
	}
}

void ShapeEditor::Panel()
{
	static const char* kinds[] = {"superellipse", "ellipse", "circle", "heart"};
	int k = int(kind);
	bool changed = ImGui::Combo("shape", &k, kinds, 4);
	kind = EditorKind(k);
	if (kind == EditorKind::superellipse || kind == EditorKind::ellipse)
	{
		changed |= ImGui::SliderFloat("a", &a, 0.1f, 4.0f);
		changed |= ImGui::SliderFloat("b", &b, 0.1f, 4.0f);
	}
	if (kind == EditorKind::superellipse)
	{
		changed |= ImGui::SliderFloat("n", &n, 1.0f, 20.0f);
		changed |= ImGui::SliderFloat("m", &m, 1.0f, 20.0f);
	}
	if (kind == EditorKind::circle)
		changed |= ImGui::SliderFloat("radius", &a, 0.1f, 4.0f);
	if (kind == EditorKind::heart)
		changed |= ImGui::SliderFloat("alpha", &alpha, 0.05f, 4.0f);
	if (changed)
		Make();
	if (!shape)
		ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "refused: %s", error.c_str());
	else
	{
		ImGui::TextWrapped("%s", shape->Describe().c_str());
		ImGui::Text("area %.4g, bounding radius %.4g", shape->Mass().area, shape->BoundingRadius());
	}
}

} // namespace b2a::viewer
