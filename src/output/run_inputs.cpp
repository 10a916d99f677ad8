#include "fabform/output/run_inputs.hpp"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "fabform/error.hpp"
#include "fabform/io/sha256.hpp"

namespace fabform {

RunInputs describe_inputs(const Scene& scene, const std::vector<SceneOverride>& overrides) {
  RunInputs inputs;
  inputs.scene_file = std::filesystem::absolute(scene.path).lexically_normal().string();
  inputs.overrides = overrides;
  const auto add = [&](const std::string& role, const std::string& path) {
    inputs.files.push_back({role, path, sha256_of_file(path)});
  };
  add("scene", scene.path);
  add("warp", scene.warp_path);
  add("weft", scene.weft_path);
  if (scene.shear.on && !scene.shear.material_path.empty()) add("shear", scene.shear.material_path);  // not a rigidity G
  for (const BodySpec& body : scene.bodies) add("body " + body.name, body.mesh_path);
  return inputs;
}

RunInputs read_run_inputs(const std::string& result_json) {
  std::ifstream in(result_json, std::ios::binary);
  if (!in) throw InputError({result_json, 0, ""}, "cannot be read (not a fabform results folder?)");
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    RunInputs inputs;
    inputs.scene_file = j.at("scene_file").get<std::string>();
    for (const auto& o : j.at("overrides"))
      inputs.overrides.push_back(o.value("unset", false) ? parse_unset(o.at("key")) : SceneOverride{o.at("key"), o.at("value")});
    for (const auto& f : j.at("inputs")) inputs.files.push_back({f.at("role"), f.at("path"), f.at("sha256")});
    return inputs;
  } catch (const nlohmann::json::exception& error) {
    throw InputError({result_json, 0, ""}, std::string("not a fabform result: ") + error.what());
  }
}

std::string input_change(const RunInputs& then, const RunInputs& now) {
  if (then.files.size() != now.files.size()) return "the scene now reads other files";
  for (std::size_t i = 0; i < then.files.size(); ++i) {
    const InputFile& a = then.files[i];
    const InputFile& b = now.files[i];
    if (a.role != b.role) return "the scene now reads other files (" + b.role + ")";
    if (a.sha256 != b.sha256) return "the " + a.role + " file " + b.path + " has changed since";
  }
  return "";
}

}  // namespace fabform
