// SPDX-License-Identifier: Apache-2.0
// A QEMU TCG plugin that counts the guest instructions executed between
// calls of a marker function, for the per-board frame budgets
// (tests/targets/frame_budget.py). Debian's qemu-user 7.2 ships no plugin
// but loads one (-plugin), and counting in a plugin costs an add per
// instruction where `-d exec` logging costs a formatted line (12 million
// lines took 59 s): the Cortex-M0+ frame is tens of millions.
//
//   qemu-arm -plugin libkestrel-qemu-insn-count.so,marker=<symbol> <program>
//
// Every executed instruction adds one to a counter. Each time the first
// instruction of <symbol> executes, the plugin prints to stderr
//   kestrel-insn-count: interval <i> <instructions since the previous mark>
// and when the program exits, the total. The marker's own instructions and
// its call count in the interval after it (a few, the same every time).
// With profile=<n>, it also prints at exit the n functions (ELF symbols)
// that executed the most instructions from the first mark on: where a
// frame's instructions go (not used by the budget check).
//
// The plugin API is QEMU's C ABI (include/qemu/qemu-plugin.h, plugin
// version 1 in QEMU 7.2), which no Debian package installs: only the
// declarations used here are written out below.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

extern "C" {
using qemu_plugin_id_t = std::uint64_t;
struct qemu_info_t;
struct qemu_plugin_tb;
struct qemu_plugin_insn;
enum qemu_plugin_cb_flags { QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_CB_R_REGS, QEMU_PLUGIN_CB_RW_REGS };
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };
using qemu_plugin_vcpu_tb_trans_cb_t = void (*)(qemu_plugin_id_t, qemu_plugin_tb*);
using qemu_plugin_vcpu_udata_cb_t = void (*)(unsigned int, void*);
using qemu_plugin_udata_cb_t = void (*)(qemu_plugin_id_t, void*);
void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t, qemu_plugin_vcpu_tb_trans_cb_t);
void qemu_plugin_register_vcpu_insn_exec_inline(qemu_plugin_insn*, qemu_plugin_op, void*, std::uint64_t);
void qemu_plugin_register_vcpu_insn_exec_cb(qemu_plugin_insn*, qemu_plugin_vcpu_udata_cb_t, qemu_plugin_cb_flags,
                                            void*);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t, qemu_plugin_udata_cb_t, void*);
std::size_t qemu_plugin_tb_n_insns(const qemu_plugin_tb*);
qemu_plugin_insn* qemu_plugin_tb_get_insn(const qemu_plugin_tb*, std::size_t);
const char* qemu_plugin_insn_symbol(const qemu_plugin_insn*);
std::uint64_t qemu_plugin_insn_vaddr(const qemu_plugin_insn*);
void qemu_plugin_outs(const char*);

__attribute__((visibility("default"))) extern const int qemu_plugin_version;
__attribute__((visibility("default"))) int qemu_plugin_install(qemu_plugin_id_t, const qemu_info_t*, int, char**);
}

namespace {

constexpr std::size_t kNameCapacity = 128;
char g_marker[kNameCapacity] = "";
std::uint64_t g_marker_vaddr = 0;  // entry of the marker, the first instruction seen with its name
bool g_marker_seen = false;
std::uint64_t g_count = 0;  // instructions executed so far (single vCPU: user mode, one thread)
std::uint64_t g_last = 0;   // g_count at the previous mark
unsigned g_interval = 0;

// profile=<n>: per-symbol counters, keyed by the symbol-name pointer QEMU
// returns (one string per symbol of the loaded ELF), open addressing.
constexpr std::size_t kSymbols = 8192;
std::size_t g_profile = 0;
const char* g_sym[kSymbols] = {};
std::uint64_t g_sym_count[kSymbols] = {};
std::uint64_t g_sym_base[kSymbols] = {};  // counts at the first mark

std::uint64_t* bucket(const char* sym) {
  static const char kUnknown[] = "?";
  if (sym == nullptr) sym = kUnknown;
  std::size_t h = (reinterpret_cast<std::uintptr_t>(sym) >> 3) % kSymbols;
  for (std::size_t probe = 0; probe < kSymbols; ++probe, h = (h + 1) % kSymbols) {
    if (g_sym[h] == sym) return &g_sym_count[h];
    if (g_sym[h] == nullptr) {
      g_sym[h] = sym;
      return &g_sym_count[h];
    }
  }
  return nullptr;  // table full: that symbol goes unprofiled
}

void print_profile() {
  std::size_t order[kSymbols];
  std::size_t n = 0;
  for (std::size_t i = 0; i < kSymbols; ++i) {
    if (g_sym[i] != nullptr && g_sym_count[i] > g_sym_base[i]) order[n++] = i;
  }
  std::sort(order, order + n, [](std::size_t a, std::size_t b) {
    return g_sym_count[a] - g_sym_base[a] > g_sym_count[b] - g_sym_base[b];
  });
  for (std::size_t k = 0; k < n && k < g_profile; ++k) {
    char line[256];
    std::snprintf(line, sizeof line, "kestrel-insn-count: profile %llu %s\n",
                  static_cast<unsigned long long>(g_sym_count[order[k]] - g_sym_base[order[k]]), g_sym[order[k]]);
    qemu_plugin_outs(line);
  }
}

void on_marker(unsigned int, void*) {
  // The inline add of the marker's first instruction runs before this
  // callback is reached; both see the same g_count on every call.
  char line[96];
  std::snprintf(line, sizeof line, "kestrel-insn-count: interval %u %llu\n", ++g_interval,
                static_cast<unsigned long long>(g_count - g_last));
  qemu_plugin_outs(line);
  g_last = g_count;
  if (g_interval == 1 && g_profile > 0) std::memcpy(g_sym_base, g_sym_count, sizeof g_sym_base);
}

void on_exit(qemu_plugin_id_t, void*) {
  char line[96];
  std::snprintf(line, sizeof line, "kestrel-insn-count: total %llu marks %u\n",
                static_cast<unsigned long long>(g_count), g_interval);
  qemu_plugin_outs(line);
  if (g_profile > 0) print_profile();
}

void on_translate(qemu_plugin_id_t, qemu_plugin_tb* tb) {
  const std::size_t n = qemu_plugin_tb_n_insns(tb);
  for (std::size_t i = 0; i < n; ++i) {
    qemu_plugin_insn* insn = qemu_plugin_tb_get_insn(tb, i);
    qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, &g_count, 1);
    const char* sym = qemu_plugin_insn_symbol(insn);
    if (g_profile > 0) {
      if (std::uint64_t* b = bucket(sym)) qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, b, 1);
    }
    if (sym == nullptr || std::strcmp(sym, g_marker) != 0) continue;
    // The marker's entry is its lowest address: the first instruction
    // translated with its name is the entry when it is reached by a call.
    const std::uint64_t va = qemu_plugin_insn_vaddr(insn);
    if (!g_marker_seen) {
      g_marker_seen = true;
      g_marker_vaddr = va;
    }
    if (va == g_marker_vaddr) {
      qemu_plugin_register_vcpu_insn_exec_cb(insn, on_marker, QEMU_PLUGIN_CB_NO_REGS, nullptr);
    }
  }
}

}  // namespace

extern "C" {
const int qemu_plugin_version = 1;

int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t*, int argc, char** argv) {
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "marker=", 7) == 0) {
      std::snprintf(g_marker, sizeof g_marker, "%s", argv[i] + 7);
    } else if (std::strncmp(argv[i], "profile=", 8) == 0) {
      g_profile = std::strtoul(argv[i] + 8, nullptr, 10);
    }
  }
  if (g_marker[0] == '\0') {
    qemu_plugin_outs("kestrel-insn-count: give marker=<symbol>\n");
    return -1;
  }
  qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
  qemu_plugin_register_atexit_cb(id, on_exit, nullptr);
  return 0;
}
}
