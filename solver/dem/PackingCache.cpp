// Packing cache: one text file per parameter set, hex floats so that a reload is bit-exact, and a
// checksum on its last line so that a damaged file is made again rather than used.
#include "solver/dem/Packing.h"

#include "solver/core/Checksum.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace lbdem::solver::dem {

namespace {

// Bump when the generator changes, so that old cached packings are not reused.
constexpr int kGeneratorVersion = 3; // 3: one thread, whatever the run's count
// Starts the last line of an entry, which sums all the lines before it.
const std::string kChecksumPrefix = "checksum ";

std::string hexFloat(Real v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%a", v);
    return buffer;
}

} // namespace

std::string defaultPackingCacheDir() {
    if (const char* dir = std::getenv("LBDEM_CACHE_DIR"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::string(xdg) + "/lbdem";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::string(home) + "/.cache/lbdem";
    return (std::filesystem::temp_directory_path() / "lbdem-cache").string();
}

std::string packingCacheKey(const PackingRequest& r) {
    const Material& m = r.material;
    std::ostringstream text;
    text << kGeneratorVersion << ' ' << r.count << ' ' << r.seed << ' ' << r.fixed_friction;
    for (Real v : {r.d_min, r.size_ratio, r.target, r.aspect_ratio, r.tolerance, r.gravity,
                   m.normal_stiffness, m.tangential_stiffness, m.restitution, m.friction,
                   m.wall_friction, m.rolling_resistance, m.density})
        text << ' ' << hexFloat(v);
    // 64-bit FNV-1a of the parameter text.
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (unsigned char c : text.str()) {
        hash ^= c;
        hash *= 0x100000001b3ULL;
    }
    char key[32];
    std::snprintf(key, sizeof key, "%016llx", static_cast<unsigned long long>(hash));
    return key;
}

bool readCachedPacking(const std::string& path, Packing& p) {
    std::ifstream file(path, std::ios::binary);
    if (!file) return false;
    const std::string text((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
    // The last line is "checksum HEX" over everything before it; a file without it (written
    // before checksums, or cut short) or whose sum differs is not used.
    const auto last = text.rfind(kChecksumPrefix);
    if (last == std::string::npos || (last > 0 && text[last - 1] != '\n')) return false;
    const std::string body = text.substr(0, last);
    if (text.substr(last) != kChecksumPrefix + solver::checksumOf(body) + "\n") return false;
    std::istringstream in(body);
    std::string magic, token;
    std::size_t n = 0;
    in >> magic >> n;
    if (magic != "lbdem-packing" || !in) return false;
    auto real = [&](Real& v) {
        if (!(in >> token)) return false;
        char* end = nullptr;
        v = std::strtod(token.c_str(), &end);
        return end != token.c_str() && *end == '\0' && std::isfinite(v);
    };
    Real converged = 0, depositions = 0;
    if (!(real(p.width) && real(p.height) && real(p.fraction) && real(p.target) &&
          real(p.prep_friction) && real(depositions) && real(converged)))
        return false;
    p.depositions = static_cast<int>(depositions);
    p.converged = converged != 0;
    p.x.resize(n);
    p.y.resize(n);
    p.radius.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        if (!(real(p.x[k]) && real(p.y[k]) && real(p.radius[k]))) return false;
    p.wall_s = 0;
    return true;
}

bool writeCachedPacking(const std::string& path, const Packing& p) {
    std::error_code error;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), error);
    // Write a sibling file and rename it, so a reader never sees half a packing.
    const std::string partial = path + ".part";
    std::ostringstream text;
    text << "lbdem-packing " << p.x.size() << '\n';
    for (Real v : {p.width, p.height, p.fraction, p.target, p.prep_friction, Real(p.depositions),
                   Real(p.converged ? 1 : 0)})
        text << hexFloat(v) << '\n';
    for (std::size_t k = 0; k < p.x.size(); ++k)
        text << hexFloat(p.x[k]) << ' ' << hexFloat(p.y[k]) << ' ' << hexFloat(p.radius[k]) << '\n';
    const std::string body = text.str();
    {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        if (!out) return false;
        out << body << kChecksumPrefix << solver::checksumOf(body) << '\n';
        if (!out) return false;
    }
    std::filesystem::rename(partial, path, error);
    return !error;
}

} // namespace lbdem::solver::dem
