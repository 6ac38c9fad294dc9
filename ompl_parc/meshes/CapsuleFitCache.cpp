#include "ompl_parc/meshes/CapsuleFitCache.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace
{
    /** What a fit was made from, as a string: equal keys, equal fits. */
    std::string fitKey(const std::string &meshFile, const Eigen::Vector3d &scale, unsigned int maxCapsules)
    {
        std::ifstream in(meshFile, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ostringstream key;
        key.precision(17);
        key << "v1 " << bytes.size() << ' ' << std::hash<std::string>()(bytes) << ' ' << scale.x() << ' ' << scale.y()
            << ' ' << scale.z() << ' ' << maxCapsules;
        return key.str();
    }
}  // namespace

std::string ompl_parc::CapsuleFitCache::entryPath(const std::string &meshFile)
{
    return meshFile + ".ompl_parc_fit.json";
}

ompl_parc::CapsuleFit ompl_parc::CapsuleFitCache::fit(const std::string &meshFile, const Eigen::Vector3d &scale,
                                                      unsigned int maxCapsules, bool write)
{
    const std::string key = fitKey(meshFile, scale, maxCapsules);
    if (auto cached = load(meshFile, key))
        return *cached;
    CapsuleFit fit(*TriangleMesh::read(meshFile, scale), maxCapsules);
    if (write)
        store(meshFile, key, fit);
    return fit;
}

std::optional<ompl_parc::CapsuleFit> ompl_parc::CapsuleFitCache::load(const std::string &meshFile,
                                                                      const std::string &key)
{
    std::ifstream in(entryPath(meshFile));
    if (!in)
        return std::nullopt;
    const nlohmann::json entry = nlohmann::json::parse(in, nullptr, false);
    try
    {
        if (!entry.is_object() || entry.at("key").get<std::string>() != key)
            return std::nullopt;
        std::vector<CapsuleFit::Capsule> capsules;
        for (const auto &c : entry.at("capsules"))
        {
            const auto v = c.get<std::vector<double>>();
            if (v.size() != 7 || !(v[6] > 0.) || !std::isfinite(v[6]))
                return std::nullopt;
            CapsuleFit::Capsule capsule{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]};
            if (!capsule.a.allFinite() || !capsule.b.allFinite())
                return std::nullopt;
            capsules.push_back(capsule);
        }
        if (capsules.empty())
            return std::nullopt;
        return CapsuleFit(std::move(capsules), entry.at("mesh_volume").get<double>(),
                          entry.at("fit_volume").get<double>());
    }
    catch (const nlohmann::json::exception &)
    {
        return std::nullopt;
    }
}

void ompl_parc::CapsuleFitCache::store(const std::string &meshFile, const std::string &key, const CapsuleFit &fit)
{
    nlohmann::json entry = {{"key", key}, {"mesh_volume", fit.getMeshVolume()}, {"fit_volume", fit.getFitVolume()}};
    entry["capsules"] = nlohmann::json::array();
    for (const auto &c : fit.getCapsules())
        entry["capsules"].push_back({c.a.x(), c.a.y(), c.a.z(), c.b.x(), c.b.y(), c.b.z(), c.radius});
    std::ostringstream id;
    id << getpid() << '.' << std::this_thread::get_id();
    const std::string path = entryPath(meshFile), temporary = path + ".tmp" + id.str();
    bool written;
    {
        std::ofstream out(temporary);
        written = static_cast<bool>(out << entry.dump(1) << '\n');
    }
    std::error_code error;
    if (written)
        std::filesystem::rename(temporary, path, error);
    if (!written || error)
        std::filesystem::remove(temporary, error);  // a read-only folder keeps no cache
}
