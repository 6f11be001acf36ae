// bench_sumo_state - the two ways to save SUMO's state in a running simulation,
// measured on the default study's base scenario (issue 23, deliverable 2):
//
//  (a) libsumo's Simulation::saveState / loadState, SUMO started with
//      --save-state.rng (without it a reloaded simulation draws other numbers);
//  (b) fork(): the process holding libsumo is copied (copy-on-write) at the
//      step; the copy continues.
//
// Both are measured at t = T (1800 s) of SUMO's side of the base scenario
// (its run.sumocfg: `fairway run scenarios/traffic/dover-crossing.yaml --out
// DIR` writes DIR/dover-crossing/sumo/run.sumocfg), nothing of fairway's in
// the process: no own ship, no orders.  Printed:
//  (a) the cost of saveState and of loadState (medians of REPS), the state
//      file's size, and whether the continuation after a load is the one
//      after the save: every vehicle's position at every step of the next
//      H (600) s, the largest difference and the vehicles present in one and
//      not the other; also two loads of the same file against each other;
//  (b) the cost of fork() in the parent (median of REPS, the child exits at
//      once), and the steps after it: the simulated minute [T, T+60) stepped in
//      a copy forked from a paused copy (what a restore is: the snapshot, a
//      paused process, forks the branch), its minor page faults, against the
//      minute [T-60, T) stepped with no copy alive; the minute after it in the
//      copy; the parent's own next minute with the paused copy alive; and the
//      continuation of the copy against the parent's (the same H s, positions
//      compared as in (a)).
// SUMO 1.15 (Debian's) writes a Poisson flow's period ("exp(RATE)") into the
// state as period="-0.00" and then refuses to load it ("Invalid repetition
// rate in the definition of flowState"); the base scenario's four flows are
// all Poisson.  (a) puts each flow's period from the route file back into the
// state file after saving (patch_flows, timed apart) so that the load can be
// measured at all.
// Wall seconds on the monotonic clock (a copy's minute is in another process:
// CPU clocks would split it); the machine is shared, so medians.
//
//     build/bench/bench_sumo_state SUMOCFG [STATE_DIR]   (STATE_DIR: /tmp)
// Results: bench/results/snapshot.txt.
#include <libsumo/libsumo.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace S = libsumo;

namespace {

const int kT = 1800;  // s, the snapshot's time
const int kH = 600;   // s, the continuation compared
const int kReps = 9;  // repetitions of each timed operation

double now_s()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

long minflt()
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_minflt;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Every vehicle's position at every step: (step, id) -> (x, y).
using Track = std::map<std::pair<int, std::string>, std::pair<double, double>>;

Track record(int steps)
{
    Track tr;
    for (int k = 0; k < steps; k++) {
        S::Simulation::step();
        for (const std::string &id : S::Vehicle::getIDList()) {
            S::TraCIPosition p = S::Vehicle::getPosition(id);
            tr[{k, id}] = {p.x, p.y};
        }
    }
    return tr;
}

// The largest position difference over the (step, vehicle) pairs in both,
// and the pairs in one only.
void compare(const char *what, const Track &a, const Track &b, int step = -1)
{
    double dmax = 0.0;
    long only_a = 0, only_b = 0, both = 0;
    for (const auto &e : a) {
        if (step >= 0 && e.first.first != step)
            continue;
        auto it = b.find(e.first);
        if (it == b.end()) {
            only_a++;
            continue;
        }
        both++;
        dmax = std::max(dmax, std::hypot(e.second.first - it->second.first,
                                         e.second.second - it->second.second));
    }
    for (const auto &e : b)
        only_b += (step < 0 || e.first.first == step) && a.find(e.first) == a.end();
    std::printf("  %-44s %ld (step, vehicle) pairs in both, max position difference %.3g m; "
                "%ld only in the first, %ld only in the second\n",
                what, both, dmax, only_a, only_b);
}

std::string slurp(const std::string &file)
{
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The value of attribute key in the element that starts at from.
std::string attr(const std::string &text, size_t from, const std::string &key)
{
    size_t end = text.find('>', from);
    size_t at = text.find(" " + key + "=\"", from);
    if (at == std::string::npos || at > end)
        return "";
    at += key.size() + 3;
    return text.substr(at, text.find('"', at) - at);
}

// The route file's flows' periods put into the state file (see above);
// returns the number of flows patched.
int patch_flows(const std::string &routes, const std::string &state)
{
    std::string r = slurp(routes), s = slurp(state);
    int n = 0;
    for (size_t at = r.find("<flow "); at != std::string::npos; at = r.find("<flow ", at + 1)) {
        std::string id = attr(r, at, "id"), period = attr(r, at, "period");
        size_t fs = s.find("<flowState id=\"" + id + "\"");
        if (fs == std::string::npos || period.empty())
            continue;
        size_t p = s.find(" period=\"", fs);
        if (p == std::string::npos || p > s.find('>', fs))
            continue;
        p += 9;
        s.replace(p, s.find('"', p) - p, period);
        n++;
    }
    std::ofstream(state) << s;
    return n;
}

void steps(int n)
{
    for (int k = 0; k < n; k++)
        S::Simulation::step();
}

// (a) saveState / loadState.
void save_load(const std::string &dir, const std::string &routes)
{
    std::string file = dir + "/fw_bench_state.xml";
    std::vector<double> save, load;
    for (int r = 0; r < kReps; r++) {
        double t0 = now_s();
        S::Simulation::saveState(file);
        save.push_back(now_s() - t0);
    }
    struct stat sb;
    long size = stat(file.c_str(), &sb) == 0 ? (long)sb.st_size : -1;
    std::string gz = dir + "/fw_bench_state.xml.gz";
    double tg = now_s();
    S::Simulation::saveState(gz);
    tg = now_s() - tg;
    long gsize = stat(gz.c_str(), &sb) == 0 ? (long)sb.st_size : -1;
    int nveh = (int)S::Vehicle::getIDList().size();
    double tp = now_s();
    int patched = patch_flows(routes, file);
    tp = now_s() - tp;
    Track after_save = record(kH);
    for (int r = 0; r < kReps; r++) {
        double t0 = now_s();
        S::Simulation::loadState(file);
        load.push_back(now_s() - t0);
    }
    Track after_load = record(kH);
    S::Simulation::loadState(file);
    Track after_load2 = record(kH);
    std::printf("(a) saveState / loadState at t = %d s (%d vehicles, --save-state.rng):\n", kT,
                nveh);
    std::printf("  saveState %.2f ms, loadState %.2f ms (medians of %d); state file %ld bytes "
                "(.xml.gz: %ld bytes, saved in %.2f ms); %d Poisson flows' periods put back "
                "in %.2f ms\n",
                1e3 * median(save), 1e3 * median(load), kReps, size, gsize, 1e3 * tg, patched,
                1e3 * tp);
    compare("continuation after load vs after save:", after_save, after_load);
    compare("the first step after load vs after save:", after_save, after_load, 0);
    compare("two loads of the same state:", after_load, after_load2);
    std::remove(file.c_str());
    std::remove(gz.c_str());
}

// A child's measurements, written to the parent through a pipe.
struct Minutes {
    double first, second; // s wall
    long flt_first, flt_second;
};

// The branch: the minute [T, T+60) and the next, then the continuation's
// positions from T (the first kH s) written to fd as text.
void branch(int fd)
{
    Minutes m;
    long f0 = minflt();
    double t0 = now_s();
    steps(60);
    m.first = now_s() - t0;
    long f1 = minflt();
    steps(60);
    m.second = now_s() - t0 - m.first;
    m.flt_first = f1 - f0;
    m.flt_second = minflt() - f1;
    if (write(fd, &m, sizeof m) != (ssize_t)sizeof m)
        _exit(1);
    _exit(0);
}

// The branch's continuation: kH s of positions, as records through fd.
void branch_track(int fd)
{
    Track tr = record(kH);
    for (const auto &e : tr) {
        char line[200];
        int n = std::snprintf(line, sizeof line, "%d %s %.17g %.17g\n", e.first.first,
                              e.first.second.c_str(), e.second.first, e.second.second);
        if (write(fd, line, (size_t)n) != n)
            _exit(1);
    }
    _exit(0);
}

Track read_track(int fd)
{
    Track tr;
    FILE *f = fdopen(fd, "r");
    int k;
    char id[128];
    double x, y;
    while (f && std::fscanf(f, "%d %127s %lf %lf", &k, id, &x, &y) == 4)
        tr[{k, id}] = {x, y};
    if (f)
        std::fclose(f);
    return tr;
}

int reap(pid_t pid)
{
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        ;
    return status;
}

// (b) fork.  The paused copy (the snapshot) forks each branch, as fairway's
// restore does; fork's own cost is timed in the parent.
void forked(double t_minute_before, long flt_before)
{
    std::vector<double> fork_s;
    for (int r = 0; r < kReps; r++) {
        double t0 = now_s();
        pid_t p = fork();
        if (p == 0)
            _exit(0);
        fork_s.push_back(now_s() - t0);
        reap(p);
    }
    int res[2];
    if (pipe(res) != 0)
        std::exit(1);
    pid_t snap = fork();
    if (snap == 0) { // the snapshot: forks the branches one after another
        close(res[0]);
        std::vector<double> fk;
        for (int r = 0; r < kReps; r++) {
            double t0 = now_s();
            pid_t b = fork();
            if (b == 0)
                branch(res[1]);
            fk.push_back(now_s() - t0);
            reap(b);
        }
        double m = median(fk);
        if (write(res[1], &m, sizeof m) != (ssize_t)sizeof m)
            _exit(1);
        pid_t b = fork();
        if (b == 0)
            branch_track(res[1]);
        reap(b);
        _exit(0);
    }
    close(res[1]);
    std::vector<double> first, second, ff, fs;
    for (int r = 0; r < kReps; r++) {
        Minutes m;
        if (read(res[0], &m, sizeof m) != (ssize_t)sizeof m)
            std::exit(1);
        first.push_back(m.first);
        second.push_back(m.second);
        ff.push_back((double)m.flt_first);
        fs.push_back((double)m.flt_second);
    }
    double fork_in_snap;
    if (read(res[0], &fork_in_snap, sizeof fork_in_snap) != (ssize_t)sizeof fork_in_snap)
        std::exit(1);
    Track copy = read_track(res[0]);
    reap(snap);
    // the parent's own minute while a paused copy shares its pages: fork
    // another (it exits when the pipe closes) and step
    int hold[2];
    if (pipe(hold) != 0)
        std::exit(1);
    pid_t paused = fork();
    if (paused == 0) {
        close(hold[1]);
        char c;
        while (read(hold[0], &c, 1) > 0)
            ;
        _exit(0);
    }
    close(hold[0]);
    long f0 = minflt();
    double t0 = now_s();
    Track mine = record(kH);
    double t_parent = now_s() - t0; // kH s, the first minute dominating the faults
    long flt_parent = minflt() - f0;
    close(hold[1]);
    reap(paused);
    std::printf("(b) fork at t = %d s:\n", kT);
    std::printf("  fork() %.2f ms in the process (median of %d), %.2f ms in the paused copy "
                "forking a branch\n",
                1e3 * median(fork_s), kReps, 1e3 * fork_in_snap);
    std::printf("  the minute [%d, %d) with no copy alive: %.2f ms, %ld minor faults\n", kT - 60,
                kT, 1e3 * t_minute_before, flt_before);
    std::printf("  a branch's first minute [%d, %d): %.2f ms, %.0f minor faults; its second "
                "minute: %.2f ms, %.0f faults (medians of %d)\n",
                kT, kT + 60, 1e3 * median(first), median(ff), 1e3 * median(second),
                median(fs), kReps);
    std::printf("  the parent's next %d s with a paused copy alive: %.2f ms, %ld minor faults\n",
                kH, 1e3 * t_parent, flt_parent);
    compare("the copy's continuation vs the parent's:", mine, copy);
}

} // namespace

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_sumo_state SUMOCFG [STATE_DIR]\n");
        return 2;
    }
    std::string dir = argc > 2 ? argv[2] : "/tmp";
    try {
        S::Simulation::start({"sumo", "-c", argv[1], "--save-state.rng", "true",
                              "--no-warnings", "true", "--log", "/dev/null"});
        steps(kT - 60);
        long f0 = minflt();
        double t0 = now_s();
        steps(60);
        double minute = now_s() - t0;
        long flt = minflt() - f0;
        forked(minute, flt);
        std::string cfg = argv[1], cdir = cfg.substr(0, cfg.rfind('/') + 1);
        std::string text = slurp(cfg);
        size_t rf = text.find("<route-files ");
        std::string routes = rf == std::string::npos ? "" : attr(text, rf, "value");
        if (!routes.empty() && routes[0] != '/')
            routes = cdir + routes;
        save_load(dir, routes);
        S::Simulation::close();
    } catch (const std::exception &e) {
        std::fprintf(stderr, "bench_sumo_state: %s\n", e.what());
        return 1;
    }
    return 0;
}
