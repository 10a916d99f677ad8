#pragma once
// SHA-256 digests (OpenSSL's libcrypto) of the files a run reads, so that result.json says
// exactly which inputs made a result and a resumed run can refuse inputs that changed since.
// The hex digest is the one `sha256sum FILE` prints.
#include <string>
#include <string_view>

namespace fabform {

/// Lower-case hex SHA-256 of `bytes`.
std::string sha256_hex(std::string_view bytes);

/// Lower-case hex SHA-256 of the file's content; throws InputError naming it when unreadable.
std::string sha256_of_file(const std::string& path);

}  // namespace fabform
