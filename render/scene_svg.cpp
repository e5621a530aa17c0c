// The SVG backend: plain SVG 1.1 text. Words stay <text> (searchable, selectable, accessible) and rooms
// are groups with a <title>, which a browser shows as a tooltip.
#include <cstdio>
#include <string>

#include "render/scene.h"

namespace villa::plan {
namespace {

std::string Num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  std::string s = buffer;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string Color(const Rgb& c) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", ToByte(c.r), ToByte(c.g), ToByte(c.b));
  return buffer;
}

std::string Escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

void WritePath(std::string& out, const PathItem& item) {
  std::string d;
  for (const SubPath& sub : item.subpaths) {
    for (size_t i = 0; i < sub.points.size(); ++i) {
      d += i == 0 ? (d.empty() ? "M" : " M") : " L";
      d += Num(sub.points[i].x) + " " + Num(sub.points[i].y);
    }
    if (sub.closed && !sub.points.empty()) d += " Z";
  }
  if (d.empty()) return;
  out += "<path d=\"" + d + "\"";
  if (item.fill) {
    out += " fill=\"" + Color(item.fill->color) + "\"";
    if (item.fill->alpha < 1.0) out += " fill-opacity=\"" + Num(item.fill->alpha) + "\"";
  } else {
    out += " fill=\"none\"";
  }
  if (item.stroke) {
    const Stroke& s = *item.stroke;
    out += " stroke=\"" + Color(s.color) + "\" stroke-width=\"" + Num(s.width) + "\"";
    if (s.alpha < 1.0) out += " stroke-opacity=\"" + Num(s.alpha) + "\"";
    if (!s.dash.empty()) {
      out += " stroke-dasharray=\"";
      for (size_t i = 0; i < s.dash.size(); ++i) out += (i ? "," : "") + Num(s.dash[i]);
      out += "\"";
    }
    if (s.cap == LineCap::kRound) out += " stroke-linecap=\"round\"";
    if (s.cap == LineCap::kSquare) out += " stroke-linecap=\"square\"";
    if (s.join == LineJoin::kRound) out += " stroke-linejoin=\"round\"";
    if (s.join == LineJoin::kBevel) out += " stroke-linejoin=\"bevel\"";
    if (s.join == LineJoin::kMiter) out += " stroke-miterlimit=\"6\"";
  }
  out += "/>\n";
}

void WriteText(std::string& out, const TextItem& item) {
  out += "<text x=\"" + Num(item.at.x) + "\" y=\"" + Num(item.at.y) + "\" font-size=\"" + Num(item.size) + "\"";
  if (item.bold) out += " font-weight=\"bold\"";
  if (item.anchor == TextAnchor::kMiddle) out += " text-anchor=\"middle\"";
  if (item.anchor == TextAnchor::kEnd) out += " text-anchor=\"end\"";
  out += " fill=\"" + Color(item.color) + "\"";
  if (item.angle_deg != 0.0) {
    out += " transform=\"rotate(" + Num(item.angle_deg) + " " + Num(item.at.x) + " " + Num(item.at.y) + ")\"";
  }
  out += ">" + Escape(item.text) + "</text>\n";
}

}  // namespace

std::string SceneToSvg(const Scene& scene) {
  std::string out;
  out.reserve(scene.items.size() * 96 + 512);
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + std::to_string(scene.width) +
         "\" height=\"" + std::to_string(scene.height) + "\" viewBox=\"0 0 " + std::to_string(scene.width) + " " +
         std::to_string(scene.height) + "\" font-family=\"" + Escape(scene.font_family) +
         ", sans-serif\" xml:space=\"preserve\">\n";
  if (!scene.title.empty()) out += "<title>" + Escape(scene.title) + "</title>\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + std::to_string(scene.width) + "\" height=\"" +
         std::to_string(scene.height) + "\" fill=\"" + Color(scene.background) + "\"/>\n";
  for (const SceneItem& item : scene.items) {
    if (const auto* path = std::get_if<PathItem>(&item)) {
      WritePath(out, *path);
    } else if (const auto* text = std::get_if<TextItem>(&item)) {
      WriteText(out, *text);
    } else if (const auto* group = std::get_if<GroupBegin>(&item)) {
      out += "<g";
      if (!group->id.empty()) out += " id=\"" + Escape(group->id) + "\"";
      out += ">\n";
      if (!group->title.empty()) out += "<title>" + Escape(group->title) + "</title>\n";
    } else {
      out += "</g>\n";
    }
  }
  out += "</svg>\n";
  return out;
}

}  // namespace villa::plan
