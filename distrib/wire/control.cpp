#include "distrib/wire/control.h"

#include <bit>
#include <cmath>

namespace povwall::distrib {

using json = nlohmann::json;

Buffer control_frame(const json& message) {
    auto buf = std::make_shared<std::vector<uint8_t>>();
    const std::string text = message.dump();
    encode_frame(FrameType::Control, 0,
                 {reinterpret_cast<const uint8_t*>(text.data()), text.size()}, *buf);
    return buf;
}

json parse_control(const Frame& frame) {
    return json::parse(frame.body.begin(), frame.body.end(), nullptr, false);
}

std::string control_type(const json& message) {
    if (!message.is_object()) return "";
    const auto it = message.find("type");
    return it != message.end() && it->is_string() ? it->get<std::string>() : "";
}

Buffer hello_frame(const Hello& hello) {
    return control_frame(
        {{"type", "hello"}, {"token", hello.token}, {"from", hello.from}});
}

std::optional<Hello> hello_from_json(const json& message) {
    if (control_type(message) != "hello") return std::nullopt;
    const auto token = message.find("token");
    const auto from = message.find("from");
    if (token == message.end() || !token->is_string() || from == message.end() ||
        !from->is_number_integer())
        return std::nullopt;
    const int64_t caller = from->get<int64_t>();
    if (caller < -1 || caller > (int64_t(1) << 20)) return std::nullopt;
    return Hello{token->get<std::string>(), int(caller)};
}

json plan_to_json(const trace::RenderPlan& p) {
    json lights = json::array();
    for (const trace::LightPlan& l : p.lights)
        lights.push_back({l.shadow_rays, l.unoccluded, l.reason});
    return {{"everything_on", p.everything_on},
            {"quality", p.quality.level},
            {"reflection_rays", p.reflection_rays},
            {"transmission_rays", p.transmission_rays},
            {"refraction_rays", p.refraction_rays},
            {"lights", lights},
            {"skip_unlit_shadow_rays", p.skip_unlit_shadow_rays},
            {"flat_threshold", p.flat_threshold},
            {"parent_tracking", p.parent_tracking},
            {"parents_required", p.parents_required},
            {"parent_reason", p.parent_reason},
            {"finite_primitives", p.finite_primitives},
            {"infinite_primitives", p.infinite_primitives}};
}

trace::RenderPlan plan_from_json(const json& j) {
    trace::RenderPlan p;
    p.everything_on = j.at("everything_on").get<bool>();
    p.quality = trace::Quality::of(j.at("quality").get<int>());
    p.reflection_rays = j.at("reflection_rays").get<bool>();
    p.transmission_rays = j.at("transmission_rays").get<bool>();
    p.refraction_rays = j.at("refraction_rays").get<bool>();
    for (const json& l : j.at("lights")) {
        trace::LightPlan lp;
        lp.shadow_rays = l.at(0).get<bool>();
        lp.unoccluded = l.at(1).get<bool>();
        lp.reason = l.at(2).get<std::string>();
        p.lights.push_back(std::move(lp));
    }
    p.skip_unlit_shadow_rays = j.at("skip_unlit_shadow_rays").get<bool>();
    p.flat_threshold = j.at("flat_threshold").get<int>();
    p.parent_tracking = j.at("parent_tracking").get<bool>();
    p.parents_required = j.at("parents_required").get<bool>();
    p.parent_reason = j.at("parent_reason").get<std::string>();
    p.finite_primitives = j.at("finite_primitives").get<size_t>();
    p.infinite_primitives = j.at("infinite_primitives").get<size_t>();
    return p;
}

json reach_to_json(const std::vector<Bounds3>& reach) {
    json out = json::array();
    for (const Bounds3& b : reach) {
        out.push_back({std::bit_cast<uint64_t>(b.lo.x), std::bit_cast<uint64_t>(b.lo.y),
                       std::bit_cast<uint64_t>(b.lo.z), std::bit_cast<uint64_t>(b.hi.x),
                       std::bit_cast<uint64_t>(b.hi.y), std::bit_cast<uint64_t>(b.hi.z)});
    }
    return out;
}

bool reach_from_json(const json& j, int boxes, std::vector<Bounds3>& reach) {
    if (!j.is_array() || j.size() != size_t(boxes)) return false;
    for (const json& b : j) {
        if (!b.is_array() || b.size() != 6) return false;
        Real v[6];
        for (int k = 0; k < 6; ++k) {
            if (!b[size_t(k)].is_number_unsigned()) return false;
            v[k] = std::bit_cast<Real>(b[size_t(k)].get<uint64_t>());
            if (std::isnan(v[k])) return false;
        }
        reach.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}});
    }
    return true;
}

}  // namespace povwall::distrib
