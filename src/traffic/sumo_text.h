// sumo_text.h - SUMO's strings into the fixed char arrays of backend.h's C
// structs (ids, types): cut to fit, always terminated.  Shared by the back
// end's C++ files; a copy per ship and step, so no printf machinery.
#ifndef FW_SUMO_TEXT_H
#define FW_SUMO_TEXT_H

#include <algorithm>
#include <cstring>
#include <string>

inline void fw_copy_text(char *dst, size_t n, const std::string &s)
{
    const size_t k = std::min(n - 1, s.size());
    std::memcpy(dst, s.data(), k);
    dst[k] = '\0';
}

#endif
