// sumo_tostring.cpp - SUMO's toString<int> without a string stream (the
// libsumo module only).
//
// libsumo's Vehicle::moveToXY builds a lane id, edge + "_" +
// toString(laneIndex), on every call, even for the keepRoute 2 placements of
// the ships fairway steers, whose lane is -1 and whose id is never looked up.
// SUMO's toString (utils/common/ToString.h, a header Debian does not ship) is
// a template that makes an std::ostringstream, sets it to fixed notation and
// gPrecision digits and writes the value into it: about 2,600 instructions
// for an int (callgrind, Debian's SUMO 1.15), 108 M of the 3.81 G of the 1 nm
// fog run of bench/imperfect_cost.py (41,267 placements).
//
// toString<int> is a vague-linkage instantiation that libsumocpp.so exports
// and calls through its PLT; the module's definition below comes first in the
// look-up of the module's libraries (dlopen with RTLD_DEEPBIND, or without it
// after a program that defines none, backend_load.c), so SUMO's calls reach
// this one.  It writes what the stream writes for an int: the decimal digits
// with a leading '-' (no precision or notation applies to an integer), as long
// as the stream's locale, the global C++ one, is the classic "C" locale
// (neither fairway nor libsumo sets another); under another the stream's own
// way is taken.
#include <ios>
#include <locale>
#include <sstream>
#include <string>

// SUMO's declaration (ToString.h: the default accuracy is gPrecision)
template <class T> std::string toString(const T &t, std::streamsize accuracy);

template <>
__attribute__((visibility("default"))) std::string toString<int>(const int &t,
                                                                 std::streamsize accuracy)
{
    if (std::locale() == std::locale::classic()) {
        char buf[16], *p = buf + sizeof buf;
        // the magnitude as unsigned: INT_MIN's too
        unsigned int u = t < 0 ? 0u - (unsigned int)t : (unsigned int)t;
        do
            *--p = (char)('0' + u % 10u);
        while (u /= 10u);
        if (t < 0)
            *--p = '-';
        return std::string(p, (size_t)(buf + sizeof buf - p));
    }
    std::ostringstream oss;
    oss.setf(std::ios::fixed, std::ios::floatfield);
    oss.precision(accuracy);
    oss << t;
    return oss.str();
}
