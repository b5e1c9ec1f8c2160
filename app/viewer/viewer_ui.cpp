#include "viewer/viewer_ui.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "backends/imgui_impl_glfw.h"
#include "backends/imgui_impl_opengl3.h"
#include "foveate/core/error.hpp"
#include "foveate/gpu/gl.hpp"
#include "foveate/techniques/palette.hpp"

namespace foveate::app::viewer {

namespace {

ImVec4 rgb(float r, float g, float b) { return {r, g, b, 1.0f}; }

// A technique's colour, the same as in the reports (techniques/palette.hpp).
ImVec4 technique_rgb(const std::string& technique) {
  const Rgb8 c = technique_colour(technique);
  return rgb(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f);
}

/// The slider's range: the declared one, with pixel radii up to the output's
/// diagonal (typing a value with Ctrl+click still reaches the declared range).
std::pair<double, double> slider_range(const ParamDecl& d, const Viewer& v) {
  double hi = d.max;
  if (d.unit == "px") hi = std::min(hi, std::ceil(std::hypot(v.width(), v.height())));
  return {d.min, std::max(hi, d.min)};
}

}  // namespace

Ui::Ui(gpu::Window& window) : window_(window.native_handle()) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini beside the user's files
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.0f;
  style.Colors[ImGuiCol_WindowBg].w = 1.0f;  // opaque: the panel is beside the image
  if (!ImGui_ImplGlfw_InitForOpenGL(static_cast<GLFWwindow*>(window.native_handle()), true) ||
      !ImGui_ImplOpenGL3_Init("#version 410 core")) {
    ImGui::DestroyContext();
    throw Error("view: the UI (Dear ImGui) could not start on this window");
  }
}

Ui::~Ui() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

bool Ui::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool Ui::wants_keyboard() const { return ImGui::GetIO().WantTextInput; }

template <class Fn>
void Ui::act(Fn&& fn) {
  try {
    fn();
    error_.clear();
  } catch (const Error& e) {
    error_ = e.what();
  }
}

void Ui::parameters(Viewer& v) {
  const TechniqueInfo& info = technique_info(v.technique_name());
  // A copy: a change below rebuilds the technique (Viewer::set_param), and
  // with it the values it holds, while the rest of the list is still drawn.
  const ParamValues values = v.technique().values();
  const auto& over = v.overrides();
  if (info.params.empty()) ImGui::TextDisabled("(no parameters)");
  for (const ParamDecl& d : info.params) {
    ImGui::PushID(d.key.c_str());
    const bool overridden = over.count(d.key) > 0;
    const std::string label = d.key + (overridden ? " *" : "");
    const std::string id = v.technique_name() + "." + d.key;
    if (d.type == ParamType::Boolean) {
      bool b = values.boolean(d.key);
      if (ImGui::Checkbox(label.c_str(), &b)) {
        act([&] { v.set_param("", d.key, b ? 1.0 : 0.0); });
      }
    } else if (!d.allowed.empty()) {
      // Listed values (ParamDecl::allowed): one button each, so that a
      // slider never stops between them.
      const double current = values.real(d.key);
      for (const double a : d.allowed) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", a);
        if (ImGui::RadioButton(text, current == a)) act([&] { v.set_param("", d.key, a); });
        ImGui::SameLine();
      }
      ImGui::TextUnformatted(label.c_str());
    } else {
      const auto [lo, hi] = slider_range(d, v);
      auto it = pending_.find(id);
      double value = it != pending_.end() ? it->second : values.real(d.key);
      const std::string unit = d.unit.empty() ? "" : " " + d.unit;
      bool changed = false;
      if (d.type == ParamType::Integer) {
        int i = static_cast<int>(std::lround(value));
        const std::string fmt = "%d" + unit;
        changed = ImGui::SliderInt(label.c_str(), &i, static_cast<int>(lo), static_cast<int>(hi),
                                   fmt.c_str());
        value = i;
      } else {
        const std::string fmt = "%.3f" + unit;
        const ImGuiSliderFlags flags =
            lo > 0 && hi / lo >= 100 ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
        changed = ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &value, &lo, &hi,
                                      fmt.c_str(), flags);
      }
      if (changed) pending_[id] = value;
      // Applied when let go: a technique is rebuilt per change.
      if (ImGui::IsItemDeactivatedAfterEdit()) {
        const double apply = pending_.count(id) ? pending_[id] : value;
        pending_.erase(id);
        act([&] { v.set_param("", d.key, apply); });
      } else if (!ImGui::IsItemActive()) {
        pending_.erase(id);
      }
    }
    if (ImGui::IsItemHovered()) {
      char range[96];
      if (d.allowed.empty()) {
        std::snprintf(range, sizeof range, "\nrange %g..%g%s%s", d.min, d.max,
                      d.unit.empty() ? "" : " ", d.unit.c_str());
      } else {
        std::snprintf(range, sizeof range, "\none of the values shown");
      }
      ImGui::SetTooltip("%s%s%s", d.help.c_str(), range,
                        overridden ? "\n* set here or by --param" : "\nderived default");
    }
    ImGui::PopID();
  }
  if (ImGui::Button("Reset to defaults (R)")) act([&] { v.reset_params(); });
}

void Ui::measurements(Viewer& v) {
  const ViewerStats& s = v.stats();
  ImGui::Text("frame time   %.1f ms (%s)", s.frame_ms, v.technique_name().c_str());
  if (s.native_ms) {
    ImGui::Text("native       %.1f ms (%d samples)", *s.native_ms, s.native_samples);
  } else {
    ImGui::TextDisabled("native       not yet measured");
  }
  if (const auto sp = v.speedup()) {
    ImGui::TextColored(*sp >= 1.0 ? rgb(0.4f, 1, 0.4f) : rgb(1, 0.5f, 0.4f),
                       "speedup      %.2fx against native", *sp);
  } else {
    ImGui::TextDisabled("speedup      -");
  }
  const double share =
      s.last.native_pixels > 0 ? 100.0 * s.last.shaded_pixels / s.last.native_pixels : 0.0;
  ImGui::Text("shaded       %.1f %% of native pixels", share);
  for (const PixelPart& p : s.last.parts) {
    ImGui::TextDisabled("  %-14s %.1f %%", p.name.c_str(),
                        s.last.native_pixels > 0 ? 100.0 * p.pixels / s.last.native_pixels : 0.0);
  }
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled(v.split() ? "native is timed every frame (split screen), glFinish-bracketed"
                                : "native is timed on the same frame about once a second, "
                                  "glFinish-bracketed");
  ImGui::PopTextWrapPos();
  frame_time_graph(v);
}

// The last frame times of each technique shown, in its colour, and native's
// samples, on one scale from 0 so that their heights compare.
void Ui::frame_time_graph(Viewer& v) {
  const auto& history = v.history();
  float top = 0;
  for (const auto& [t, h] : history) {
    for (float ms : h) top = std::max(top, ms);
  }
  if (history.empty() || !(top > 0)) {
    ImGui::TextDisabled("frame-time graph: no frames measured yet");
    return;
  }
  top *= 1.1f;
  ImGui::TextDisabled("frame times, last %zu frames each, 0 to %.1f ms:", kHistoryFrames,
                      static_cast<double>(top));
  // The technique shown first, then the others measured, native last.
  std::vector<std::string> order{v.technique_name()};
  for (const auto& [t, h] : history) {
    if (t != v.technique_name() && t != "native") order.push_back(t);
  }
  if (v.technique_name() != "native") order.push_back("native");
  for (const std::string& t : order) {
    const auto it = history.find(t);
    if (it == history.end() || it->second.empty()) continue;
    const std::vector<float>& h = it->second;
    float mean = 0;
    for (float ms : h) mean += ms;
    mean /= static_cast<float>(h.size());
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%s %.2f ms", t.c_str(), static_cast<double>(mean));
    ImGui::PushStyleColor(ImGuiCol_PlotLines, technique_rgb(t));
    ImGui::PushID(t.c_str());
    ImGui::PlotLines(
        "##ft", h.data(), static_cast<int>(h.size()), 0, overlay, 0.0f, top,
        ImVec2(ImGui::GetContentRegionAvail().x, t == v.technique_name() ? 54.0f : 30.0f));
    ImGui::PopID();
    ImGui::PopStyleColor();
  }
}

// Saving the parameters set to a file --params-file reads, and copying a
// command line that starts the viewer as it is.
void Ui::save_and_share(Viewer& v) {
  ImGui::InputText("file", params_path_, sizeof params_path_);
  if (ImGui::Button("Save parameters")) {
    const std::string path = params_path_;
    act([&] {
      v.save_params(path);
      done_ = "saved to " + path + " (read it with --params-file)";
    });
  }
  ImGui::SameLine();
  if (ImGui::Button("Copy command line")) {
    glfwSetClipboardString(static_cast<GLFWwindow*>(window_), v.command_line().c_str());
    done_ = "command line copied";
  }
  if (!done_.empty()) ImGui::TextDisabled("%s", done_.c_str());
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("%s", v.command_line().c_str());
  ImGui::PopTextWrapPos();
}

void Ui::legend_and_gaze(Viewer& v) {
  if (ImGui::CollapsingHeader("Overlay legend (O)", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (!v.overlay()) ImGui::TextDisabled("(overlay off)");
    int k = 0;
    for (const LegendEntry& e : v.legend()) {
      // The swatch is the shape the overlay draws: a layer's target and its
      // blend ring share a colour.
      ImGui::PushID(k++);
      const ImVec2 at = ImGui::GetCursorScreenPos();
      const ImU32 c = ImGui::ColorConvertFloat4ToU32(rgb(e.r, e.g, e.b));
      ImDrawList* dl = ImGui::GetWindowDrawList();
      const ImVec2 mid(at.x + 8, at.y + 8);
      if (e.kind == OverlayShape::Kind::Rect) {
        dl->AddRect(ImVec2(at.x + 1, at.y + 3), ImVec2(at.x + 15, at.y + 13), c, 0.0f, 0, 2.0f);
      } else if (e.kind == OverlayShape::Kind::Circle) {
        dl->AddCircle(mid, 6.0f, c, 0, 2.0f);
      } else {
        dl->AddCircleFilled(mid, 4.0f, c);
      }
      ImGui::Dummy(ImVec2(16, 16));
      ImGui::SameLine();
      ImGui::TextWrapped("%s", e.label.c_str());
      ImGui::PopID();
    }
  }
  if (ImGui::CollapsingHeader("Gaze", ImGuiTreeNodeFlags_DefaultOpen)) {
    auto& g = v.session().gaze();
    const auto& f = g.last();
    ImGui::TextWrapped("source: %s", g.describe().c_str());
    if (v.gaze_follows_mouse()) {
      const std::string hold = v.mouse_gaze().state();
      if (hold == "following") {
        ImGui::TextColored(rgb(0.4f, 1, 0.4f), "following the mouse over the image (F freezes)");
      } else if (hold == "held") {
        ImGui::TextColored(rgb(1, 0.85f, 0.3f),
                           "held at its last place on the image (the mouse is away)");
      } else {
        ImGui::TextColored(rgb(0.5f, 0.8f, 1), "frozen (F follows the mouse again)");
      }
    }
    ImGui::Text("at %.0f, %.0f px, latency %.1f ms", v.gaze().gaze_px.x, v.gaze().gaze_px.y,
                v.gaze().latency_ms);
    ImGui::Text("filter: %s%s%s",
                f.fallback  ? "fallback (centre, wider fovea)"
                : f.holding ? "holding the last gaze"
                : f.valid   ? "tracking"
                            : "no data",
                f.in_saccade ? ", saccade" : "", "");
    ImGui::TextWrapped("%s", g.report().c_str());
  }
}

void Ui::acuity_and_display(Viewer& v) {
  if (ImGui::RadioButton("acuity A", v.acuity_preset() == "A"))
    act([&] { v.set_acuity_preset("A"); });
  ImGui::SameLine();
  if (ImGui::RadioButton("acuity B", v.acuity_preset() == "B"))
    act([&] { v.set_acuity_preset("B"); });
  auto it = pending_.find("slope");
  double m = it != pending_.end() ? it->second : v.slope();
  const double lo = 0.005, hi = 0.08;
  if (ImGui::SliderScalar("MAR slope m", ImGuiDataType_Double, &m, &lo, &hi, "%.4f deg/deg"))
    pending_["slope"] = m;
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    pending_.erase("slope");
    act([&] { v.set_slope(m); });
  } else if (!ImGui::IsItemActive()) {
    pending_.erase("slope");
  }
  if (ImGui::BeginCombo("display", v.display_spec().c_str())) {
    for (const Display& d : Display::presets()) {
      if (ImGui::Selectable(d.name.c_str(), d.name == v.display_spec())) {
        act([&] { v.set_display(d.name); });
      }
    }
    ImGui::EndCombo();
  }
}

// The split's divider, draggable on the image, or the A/B flip's label.
void Ui::draw_divider(Viewer& v) {
  ImGuiIO& io = ImGui::GetIO();
  const float W = static_cast<float>(v.shown_width()), H = static_cast<float>(v.shown_height());
  if (v.split()) {
    const float x = static_cast<float>(v.divider()) * W;
    const ImVec2 m = io.MousePos;
    const bool near = std::abs(m.x - x) <= 6.0f && m.y >= 0 && m.y < H;
    if (!io.WantCaptureMouse && near && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
      dragging_ = true;
    if (!io.MouseDown[ImGuiMouseButton_Left]) dragging_ = false;
    if (dragging_) v.set_divider(std::clamp(m.x / W, 0.0f, 1.0f));
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const ImU32 c =
        (near || dragging_) ? IM_COL32(255, 255, 80, 255) : IM_COL32(255, 255, 255, 200);
    dl->AddLine(ImVec2(x, 0), ImVec2(x, H), c, 2.0f);
    dl->AddRectFilled(ImVec2(x - 4, H * 0.5f - 14), ImVec2(x + 4, H * 0.5f + 14), c, 2.0f);
    dl->AddText(ImVec2(6, 4), IM_COL32(255, 255, 255, 230), "native");
    const std::string right = v.technique_name();
    dl->AddText(ImVec2(W - 6 - ImGui::CalcTextSize(right.c_str()).x, 4),
                IM_COL32(255, 255, 255, 230), right.c_str());
  } else {
    dragging_ = false;
    if (v.show_native()) {
      ImGui::GetForegroundDrawList()->AddText(ImVec2(6, 4), IM_COL32(255, 255, 255, 230),
                                              "native (Space: back to the technique)");
    }
  }
}

void Ui::draw(Viewer& v) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  const float W = static_cast<float>(v.shown_width());

  ImGui::SetNextWindowPos(ImVec2(W, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(std::max(io.DisplaySize.x - W, 100.0f), io.DisplaySize.y),
                           ImGuiCond_Always);
  ImGui::Begin("foveate view", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(-150);
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, rgb(1, 0.4f, 0.3f));
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
  }
  const auto& names = v.available();
  if (ImGui::BeginCombo("technique (1-9)", v.technique_name().c_str())) {
    for (size_t i = 0; i < names.size(); ++i) {
      const std::string item = std::to_string(i + 1) + " " + names[i];
      if (ImGui::Selectable(item.c_str(), names[i] == v.technique_name())) {
        act([&] { v.set_technique(names[i]); });
      }
    }
    ImGui::EndCombo();
  }
  if (ImGui::CollapsingHeader("Measured", ImGuiTreeNodeFlags_DefaultOpen)) measurements(v);
  if (ImGui::CollapsingHeader("Compare with native", ImGuiTreeNodeFlags_DefaultOpen)) {
    bool native = v.show_native(), split = v.split(), overlay = v.overlay();
    if (ImGui::Checkbox("show native (A/B: Space)", &native)) v.set_show_native(native);
    if (ImGui::Checkbox("split screen: native | foveated (S)", &split)) v.set_split(split);
    if (v.split()) {
      float d = static_cast<float>(v.divider());
      if (ImGui::SliderFloat("divider", &d, 0.0f, 1.0f, "%.2f")) act([&] { v.set_divider(d); });
    }
    if (ImGui::Checkbox("overlay (O)", &overlay)) v.set_overlay(overlay);
  }
  if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) parameters(v);
  if (ImGui::CollapsingHeader("Acuity and display", ImGuiTreeNodeFlags_DefaultOpen))
    acuity_and_display(v);
  legend_and_gaze(v);
  if (ImGui::CollapsingHeader("Save and share", ImGuiTreeNodeFlags_DefaultOpen)) save_and_share(v);
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled(
      "keys: 1-9 technique, Space A/B, S split, O overlay, F freeze the gaze, R reset, Esc quit");
  ImGui::PopTextWrapPos();
  ImGui::PopItemWidth();
  // The cursor's place is in content coordinates: the height the contents need.
  content_height_ = ImGui::GetCursorPosY() + ImGui::GetStyle().WindowPadding.y;
  scrolls_ = ImGui::GetScrollMaxY() > 0.0f;
  ImGui::End();

  draw_divider(v);

  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDisable(GL_FRAMEBUFFER_SRGB);  // ImGui's colours are sRGB-encoded already
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace foveate::app::viewer
