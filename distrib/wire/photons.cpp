#include "distrib/wire/photons.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace povwall::distrib {
namespace {

using nlohmann::json;

void write_photon(std::vector<uint8_t>& body, const trace::Photon& p) {
    static_assert(sizeof(p.pos) == 12 && sizeof(p.rgbe) == 4);
    uint8_t record[kPhotonRecordSize];
    std::memcpy(record, p.pos, 12);
    std::memcpy(record + 12, p.rgbe, 4);
    std::memcpy(record + 16, &p.theta, 1);
    std::memcpy(record + 17, &p.phi, 1);
    record[18] = p.axis;
    body.insert(body.end(), record, record + kPhotonRecordSize);
}

void append_frames(const std::vector<trace::Photon>& photons, std::vector<Buffer>& out) {
    for (size_t first = 0; first < photons.size(); first += kPhotonsPerFrame) {
        const size_t count = std::min(kPhotonsPerFrame, photons.size() - first);
        std::vector<uint8_t> body;
        body.reserve(count * kPhotonRecordSize);
        for (size_t k = first; k < first + count; ++k) write_photon(body, photons[k]);
        auto buf = std::make_shared<std::vector<uint8_t>>();
        encode_frame(FrameType::Photons, uint32_t(count), body, *buf);
        out.push_back(std::move(buf));
    }
}

json map_fields(const trace::PhotonMap& map) {
    return {{"count", map.size()},
            {"min_radius", std::bit_cast<uint64_t>(map.min_gather_radius())},
            {"radius_step", std::bit_cast<uint64_t>(map.radius_step())}};
}

// A map's count and radii; false unless finite and non-negative.
bool read_map_fields(const json& j, size_t& count, double& min_radius,
                     double& radius_step) {
    if (!j.is_object()) return false;
    for (const char* key : {"count", "min_radius", "radius_step"})
        if (!j.contains(key) || !j[key].is_number_unsigned()) return false;
    count = j["count"].get<size_t>();
    min_radius = std::bit_cast<double>(j["min_radius"].get<uint64_t>());
    radius_step = std::bit_cast<double>(j["radius_step"].get<uint64_t>());
    return std::isfinite(min_radius) && std::isfinite(radius_step) && min_radius >= 0 &&
           radius_step >= 0;
}

// An int field of at least `min`; false when missing, of another type or out of range.
bool read_int(const json& j, const char* key, int min, int& out) {
    if (!j.contains(key) || !j[key].is_number_integer()) return false;
    if (j[key].is_number_unsigned() && j[key].get<uint64_t>() > uint64_t(INT32_MAX))
        return false;
    const int64_t v = j[key].get<int64_t>();
    if (v < min || v > INT32_MAX) return false;
    out = int(v);
    return true;
}

}  // namespace

std::vector<Buffer> photon_map_frames(const trace::PhotonMap* map) {
    std::vector<Buffer> out;
    if (!map) {
        out.push_back(control_frame({{"type", "photons"}, {"map", false}}));
        return out;
    }
    append_frames(map->photons(), out);
    if (map->media()) append_frames(map->media()->photons(), out);
    const PhotonSettings& s = map->settings();
    json message = {{"type", "photons"},
                    {"map", true},
                    {"surface", map_fields(*map)},
                    {"gather_min", s.gather_min},
                    {"gather_max", s.gather_max},
                    {"expand_tolerance", std::bit_cast<uint32_t>(s.expand_tolerance)},
                    {"expand_min", s.expand_min}};
    if (map->media()) message["media"] = map_fields(*map->media());
    out.push_back(control_frame(message));
    return out;
}

bool read_photons(std::span<const uint8_t> body, uint32_t count,
                  std::vector<trace::Photon>& out) {
    if (body.size() != size_t(count) * kPhotonRecordSize) return false;
    const size_t before = out.size();
    out.resize(before + count);
    for (size_t k = 0; k < count; ++k) {
        trace::Photon& p = out[before + k];
        const uint8_t* r = body.data() + k * kPhotonRecordSize;
        std::memcpy(p.pos, r, 12);
        std::memcpy(p.rgbe, r + 12, 4);
        std::memcpy(&p.theta, r + 16, 1);
        std::memcpy(&p.phi, r + 17, 1);
        p.axis = r[18];
        if (!std::isfinite(p.pos[0]) || !std::isfinite(p.pos[1]) ||
            !std::isfinite(p.pos[2]) || p.axis > 2) {
            out.resize(before);
            return false;
        }
    }
    return true;
}

bool photon_map_from_message(const json& message, std::vector<trace::Photon>&& photons,
                             std::shared_ptr<const trace::PhotonMap>& map) {
    map = nullptr;
    if (!message.contains("map") || !message["map"].is_boolean()) return false;
    if (!message["map"].get<bool>()) return photons.empty();
    size_t surface = 0, media = 0;
    double radius = 0, step = 0, media_radius = 0, media_step = 0;
    if (!message.contains("surface") ||
        !read_map_fields(message["surface"], surface, radius, step))
        return false;
    const bool has_media = message.contains("media");
    if (has_media && !read_map_fields(message["media"], media, media_radius, media_step))
        return false;
    if (surface + media != photons.size()) return false;
    PhotonSettings s;
    if (!read_int(message, "gather_max", 1, s.gather_max) ||
        !read_int(message, "gather_min", 0, s.gather_min) ||
        s.gather_min > s.gather_max ||
        !read_int(message, "expand_min", 0, s.expand_min) ||
        !message.contains("expand_tolerance") ||
        !message["expand_tolerance"].is_number_unsigned() ||
        message["expand_tolerance"].get<uint64_t>() > UINT32_MAX)
        return false;
    s.expand_tolerance =
        std::bit_cast<float>(message["expand_tolerance"].get<uint32_t>());
    // The parser's range (parser/photons.cpp): what it cannot produce is not a map.
    if (!std::isfinite(s.expand_tolerance) || s.expand_tolerance < 0) return false;
    std::shared_ptr<trace::PhotonMap> media_map;
    if (has_media)
        media_map = trace::PhotonMap::assemble(
            s,
            std::vector<trace::Photon>(photons.begin() + ptrdiff_t(surface),
                                       photons.end()),
            media_radius, media_step, nullptr);
    photons.resize(surface);
    map = trace::PhotonMap::assemble(s, std::move(photons), radius, step,
                                     std::move(media_map));
    return true;
}

}  // namespace povwall::distrib
