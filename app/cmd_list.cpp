// foveate scenes and foveate techniques: what there is to render with.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/bench/session_options.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/scenes/scene.hpp"
#include "foveate/techniques/technique.hpp"
#include "session_args.hpp"

namespace foveate::app {

void register_scenes(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("scenes", "List the built-in scenes");
  auto json = std::make_shared<bool>(false);
  sub->add_flag("--json", *json, "Print the list as JSON");
  sub->callback([json] {
    if (*json) {
      nlohmann::json j = nlohmann::json::array();
      for (const SceneListing& s : builtin_scenes())
        j.push_back({{"name", s.name}, {"description", s.description}});
      std::cout << j.dump(2) << '\n';
      return;
    }
    for (const SceneListing& s : builtin_scenes())
      std::printf("%-10s %s\n", s.name.c_str(), s.description.c_str());
    std::printf(
        "\nAlso: a Shadertoy shader file (.glsl, .frag) or a mesh file (OBJ, glTF/GLB, PLY, FBX, "
        "3DS, ...).\n");
  });
}

namespace {

struct TechniquesArgs {
  std::string display = "desktop-1080p";
  std::string size = kDefaultSize;
  bool json = false;
  std::string acuity_preset;  ///< --acuity (--quality): "A", "B" or empty
  std::optional<double> slope;
  std::optional<double> margin;
};

void print_techniques_json(const TechniqueConfig& c, PixelSize size) {
  nlohmann::json j = {{"display", c.display},
                      {"size", {size.width, size.height}},
                      {"acuity", {{"slope", c.acuity.slope}, {"w0_deg", c.acuity.w0_deg}}},
                      {"margin", c.margin ? nlohmann::json(*c.margin) : nlohmann::json()}};
  nlohmann::json list = nlohmann::json::array();
  for (const TechniqueInfo& t : techniques()) {
    const ParamValues values = resolve_parameters(t, c);
    nlohmann::json params = nlohmann::json::array();
    for (const ParamDecl& p : t.params) {
      params.push_back({{"key", p.key},
                        {"value", values.real(p.key)},
                        {"unit", p.unit},
                        {"type", param_type_name(p.type)},
                        {"min", p.min},
                        {"max", p.max},
                        {"tune", p.tune},
                        {"allowed", p.allowed},
                        {"help", p.help}});
    }
    list.push_back({{"name", t.name},
                    {"summary", t.summary},
                    {"after", t.source},
                    {"needs_meshes", t.needs.meshes},
                    {"parameters", params}});
  }
  j["techniques"] = list;
  std::cout << j.dump(2) << '\n';
}

void print_techniques_text(const TechniqueConfig& c, PixelSize size) {
  std::printf("defaults derived for %s at %dx%d, MAR slope %s%s\n\n", c.display.name.c_str(),
              size.width, size.height, format_number(c.acuity.slope, 4).c_str(),
              c.margin ? (", margin " + format_number(*c.margin, 3)).c_str()
                       : " (each technique planned with its own margin)");
  for (const TechniqueInfo& t : techniques()) {
    std::printf("%s — %s\n  after: %s\n", t.name.c_str(), t.summary.c_str(), t.source.c_str());
    if (t.needs.meshes) std::printf("  needs: a scene with meshes\n");
    const ParamValues values = resolve_parameters(t, c);
    for (const ParamDecl& p : t.params) {
      const std::string value =
          format_fixed(values.real(p.key), p.type == ParamType::Real ? 3 : 0) +
          (p.unit.empty() ? "" : " " + p.unit);
      const std::string range =
          p.allowed.empty() ? format_number(p.min) + ".." + format_number(p.max) : allowed_text(p);
      std::printf("  %-22s = %-14s %s [%s]\n", p.key.c_str(), value.c_str(), p.help.c_str(),
                  range.c_str());
    }
    std::printf("\n");
  }
}

}  // namespace

void register_techniques(CLI::App& app) {
  auto a = std::make_shared<TechniquesArgs>();
  CLI::App* sub =
      app.add_subcommand("techniques", "List the techniques with their parameters and defaults");
  sub->add_option("--display", a->display, "Display for the derived defaults")
      ->capture_default_str();
  sub->add_option("--size", a->size, "Render size for the derived defaults (render's default)")
      ->capture_default_str();
  sub->add_flag("--json", a->json, "Print the techniques, parameters and defaults as JSON");
  add_acuity_options(sub, a->acuity_preset, a->slope);
  sub->add_option("--margin", a->margin,
                  "Derive the defaults for every technique planned with this margin (as "
                  "render's and bench's --margin, 1 to 4; default: each technique's own)");
  sub->callback([a] {
    const PixelSize size = parse_size(a->size, "--size");
    TechniqueConfig c;
    c.display = with_flag("--display", [&] {
                  return Display::load(a->display);
                }).resized(size.width, size.height);
    c.acuity = bench::acuity_from(a->acuity_preset, a->slope);
    if (a->margin) bench::check_margin(*a->margin);
    note_savings(c.display, c.acuity, a->margin);
    c.margin = a->margin;
    if (a->json) {
      print_techniques_json(c, size);
    } else {
      print_techniques_text(c, size);
    }
  });
}

const CommandRegistrar kScenes(21, register_scenes);
const CommandRegistrar kTechniques(22, register_techniques);

}  // namespace foveate::app
