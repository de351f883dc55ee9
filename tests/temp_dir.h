#pragma once
// A fresh folder under the system's temporary directory for the files a test writes, removed with everything in
// it when the test ends.
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace lidr::test {

class TempDir {
public:
    TempDir() {
        static int counter = 0;  // one per process (an inline function's static): names never repeat
        path_ = std::filesystem::temp_directory_path() /
                ("lidr-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    // Writes `content` to the file `name` in the folder; returns its path.
    std::string write(const std::string& name, const std::string& content) const {
        const std::string f = file(name);
        std::ofstream(f, std::ios::binary) << content;
        return f;
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace lidr::test
