// Generates the multi-issue conformance tests for the Blackfin simulator.
//
//   gen_parallel OUTDIR [--per-file N] [--with-known-deviations]
//
// writes OUTDIR/par_*.s (the simulator test-suite format: run them with emu/sim_testsuite.sh)
// and prints on stdout how many combinations it generated, legal and illegal. N legal
// combinations go in one file (default 25; 1 shows each failing combination on its own).
// --with-known-deviations also writes the illegal combinations emu/README.md lists as not
// checked by the simulator (those tests fail).
//
// A multi-issue instruction is one 32-bit slot (slot 0: ALU, MAC, shift or video op, or MNOP)
// and two 16-bit slots (slot 1: any load, store or DAG modify; slot 2: the I-register loads
// and stores only). The rule checked: all slots read their operands before any slot writes
// (Blackfin Processor Programming Reference, "Issuing Parallel Instructions"). So every
// generated legal combination has one slot writing a register another slot reads; the
// expected values come from this program's own model of each operation executed under that
// rule, never from the simulator. For each combination the model also runs the slots one
// after the other with the writer first (the way a simulator that writes at once behaves) and
// counts the combination as discriminating when that gives a different final state, so a
// simulator breaking the rule fails the test.
//
// Legality follows GNU as (gas/config/bfin-parse.y: slot 1 takes the LDST group, slot 2 only
// dspLDST loads and stores, at most one store, no register written by two slots) and the
// illegal combinations of the simulator's own se_illegalcombination.S (no I register modified
// by two slots, no D register loaded by two slots, a SEARCH only with a load through P0 and a
// NOP, only 16-bit loads, stores and DAG ops in slots 1 and 2). Each illegal combination is emitted as raw
// halfwords (the assembler refuses them) in a test for the operating environment, whose
// EVT3 handler expects EXCAUSE 0x22 (illegal instruction combination, PRM "Exceptions",
// SEQSTAT.EXCAUSE) and skips the 8-byte instruction; the test also checks that the faulting
// instruction left registers and memory unchanged (an exception is taken before the
// instruction commits).
//
// C++17, standard library only.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using u8 = std::uint8_t;
using u32 = std::uint32_t;
using s32 = std::int32_t;
using u64 = std::uint64_t;
using s64 = std::int64_t;

// Register numbering of the model.
enum {
  R0 = 0,
  P0 = 8,
  FP = 14,
  I0 = 15,
  M0 = 19,
  B0 = 23,
  L0 = 27,
  NREG = 31
};

std::string regname(int r) {
  static const char* const names[NREG] = {
      "R0", "R1", "R2", "R3", "R4", "R5", "R6", "R7", "P0", "P1", "P2", "P3", "P4", "P5", "FP", "I0",
      "I1", "I2", "I3", "M0", "M1", "M2", "M3", "B0", "B1", "B2", "B3", "L0", "L1", "L2", "L3"};
  return names[r];
}

// The data buffer the tests work on: BUFSZ bytes, byte j = 0x5B + 37 * j (mod 256). 37 is odd,
// so all 256 bytes differ and any two different addresses load different values.
constexpr u32 BUFSZ = 256;
u8 init_byte(u32 j) { return u8(0x5B + 37 * j); }

struct State {
  u32 r[NREG] = {};
  u64 a0 = 0;          // 40 bits
  u32 azan = 0;        // ASTAT bits 0 (AZ) and 1 (AN)
  u8 mem[BUFSZ] = {};
  u32 base = 0;        // address of mem[0]
  bool fault = false;  // an access outside the buffer or misaligned (only in the wrong order)
  std::set<u32> stored;  // word addresses written
};

u32 ld(const State& s, State& out, u32 addr, int size) {
  if (addr % size != 0 || addr < s.base || addr + size > s.base + BUFSZ) {
    out.fault = true;
    return 0;
  }
  u32 v = 0;
  for (int k = size - 1; k >= 0; --k) v = (v << 8) | s.mem[addr - s.base + k];
  return v;
}

void st(State& out, u32 addr, int size, u32 v) {
  if (addr % size != 0 || addr < out.base || addr + size > out.base + BUFSZ) {
    out.fault = true;
    return;
  }
  for (int k = 0; k < size; ++k) out.mem[addr - out.base + k] = u8(v >> (8 * k));
  out.stored.insert(addr & ~3u);
}

u32 sext16(u32 v) { return u32(s32(std::int16_t(v & 0xffff))); }
u32 sext8(u32 v) { return u32(s32(std::int8_t(v & 0xff))); }

// DAG post-modify or modify of Ii by a signed amount, with the circular-buffer rule
// (PRM, "Circular Buffer Addressing"): with L != 0, a positive modify that reaches B + L
// or beyond subtracts L, a negative one that goes below B adds L.
u32 dag_mod(const State& s, int i, s32 m) {
  u32 I = s.r[I0 + i], B = s.r[B0 + i], L = s.r[L0 + i];
  u32 n = I + u32(m);
  if (L != 0) {
    if (m >= 0 && n >= B + L) n -= L;
    if (m < 0 && n < B) n += L;
  }
  return n;
}

u32 bitrev(u32 v) {
  u32 r = 0;
  for (int k = 0; k < 32; ++k) r |= ((v >> k) & 1u) << (31 - k);
  return r;
}

// Bit-reversed addition: the carry propagates from the MSB towards the LSB (PRM,
// "Bit-Reversed Addressing"); no circular wrap.
u32 brev_add(u32 a, u32 b) { return bitrev(bitrev(a) + bitrev(b)); }

struct Op {
  std::string text;
  int group = 0;  // 0: slot 0 (32-bit), 1: slot 1 only, 2: slot 1 or 2
  bool store = false;
  bool load = false;
  std::set<int> reads, writes;  // registers (D registers whole)
  int mod_i = -1;               // I register this op modifies
  int acc_i = -1;               // I register this op addresses memory with (without modifying)
  bool astat = false;           // the model knows this op's AZ/AN
  bool a0 = false;              // writes A0
  // Reads everything from `in` before writing anything to `out` (which may be `in`).
  std::function<void(const State& in, State& out)> exec;
};

Op nop16() {
  Op o;
  o.text = "NOP";
  o.group = 2;
  o.exec = [](const State&, State&) {};
  return o;
}

Op mnop() {
  Op o;
  o.text = "MNOP";
  o.group = 0;
  o.exec = [](const State&, State&) {};
  return o;
}

std::string hex(u32 v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", v);
  return b;
}

// ---- slot 0 ----------------------------------------------------------------------------

enum S0Kind { ADD_S, VADD, VSUB, VASHR2, LSL3, LSR3, MUL_IS, MAX, PACK, HADD_H, ACC_IS, NS0 };

bool s0_reads_b(int k) { return !(k == VASHR2 || k == LSL3 || k == LSR3); }

Op slot0(int kind, int d, int a, int b) {
  Op o;
  o.group = 0;
  std::string D = regname(d), A = regname(a), Bn = regname(b);
  o.reads.insert(a);
  if (s0_reads_b(kind)) o.reads.insert(b);
  o.writes.insert(d);
  switch (kind) {
    case ADD_S:  // 32-bit saturating add (PRM "Add"); AZ = zero, AN = negative result
      o.text = D + " = " + A + " + " + Bn + " (S)";
      o.astat = true;
      o.exec = [=](const State& in, State& out) {
        s64 r = s64(s32(in.r[a])) + s64(s32(in.r[b]));
        if (r > 0x7fffffff) r = 0x7fffffff;
        if (r < -s64(0x80000000)) r = -s64(0x80000000);
        out.r[d] = u32(r);
        out.azan = (u32(r) == 0 ? 1u : 0u) | ((u32(r) >> 31) ? 2u : 0u);
      };
      break;
    case VADD:  // two 16-bit adds, wrapping; AZ/AN if either half is zero/negative
    case VSUB: {
      bool sub = kind == VSUB;
      o.text = D + " = " + A + (sub ? " -|- " : " +|+ ") + Bn;
      o.astat = true;
      o.exec = [=](const State& in, State& out) {
        u32 x = in.r[a], y = in.r[b];
        u32 lo = (sub ? (x - y) : (x + y)) & 0xffff;
        u32 hi = (sub ? ((x >> 16) - (y >> 16)) : ((x >> 16) + (y >> 16))) & 0xffff;
        out.r[d] = (hi << 16) | lo;
        out.azan = ((lo == 0 || hi == 0) ? 1u : 0u) | (((lo | hi) & 0x8000) ? 2u : 0u);
      };
      break;
    }
    case VASHR2:  // each half shifted right arithmetically by 2
      o.text = D + " = " + A + " >>> 2 (V)";
      o.exec = [=](const State& in, State& out) {
        u32 x = in.r[a];
        u32 lo = u32(std::int16_t(x & 0xffff) >> 2) & 0xffff;
        u32 hi = u32(std::int16_t(x >> 16) >> 2) & 0xffff;
        out.r[d] = (hi << 16) | lo;
      };
      break;
    case LSL3:
      o.text = D + " = " + A + " << 3";
      o.exec = [=](const State& in, State& out) { out.r[d] = in.r[a] << 3; };
      break;
    case LSR3:
      o.text = D + " = " + A + " >> 3";
      o.exec = [=](const State& in, State& out) { out.r[d] = in.r[a] >> 3; };
      break;
    case MUL_IS:  // signed 16 x 16 -> 32 integer product
      o.text = D + " = " + A + ".L * " + Bn + ".L (IS)";
      o.exec = [=](const State& in, State& out) {
        out.r[d] = u32(s32(std::int16_t(in.r[a] & 0xffff)) * s32(std::int16_t(in.r[b] & 0xffff)));
      };
      break;
    case MAX:
      o.text = D + " = MAX (" + A + ", " + Bn + ")";
      o.exec = [=](const State& in, State& out) {
        out.r[d] = s32(in.r[a]) > s32(in.r[b]) ? in.r[a] : in.r[b];
      };
      break;
    case PACK:  // high half from the first operand, low half from the second
      o.text = D + " = PACK (" + A + ".L, " + Bn + ".H)";
      o.exec = [=](const State& in, State& out) {
        out.r[d] = ((in.r[a] & 0xffff) << 16) | (in.r[b] >> 16);
      };
      break;
    case HADD_H:  // 16-bit add into the high half; the low half of D keeps its old value
      o.text = D + ".H = " + A + ".L + " + Bn + ".H (NS)";
      o.reads.insert(d);
      o.exec = [=](const State& in, State& out) {
        u32 sum = ((in.r[a] & 0xffff) + (in.r[b] >> 16)) & 0xffff;
        out.r[d] = (sum << 16) | (in.r[d] & 0xffff);
      };
      break;
    case ACC_IS:  // A0 = signed integer product, D = A0 (fits in 32 bits, no saturation)
      o.text = D + " = (A0 = " + A + ".L * " + Bn + ".L) (IS)";
      o.a0 = true;
      o.exec = [=](const State& in, State& out) {
        s32 p = s32(std::int16_t(in.r[a] & 0xffff)) * s32(std::int16_t(in.r[b] & 0xffff));
        out.a0 = u64(s64(p)) & 0xffffffffffull;
        out.r[d] = u32(p);
      };
      break;
  }
  return o;
}

// ---- I-register loads and stores (dspLDST; slot 1 or 2) ----------------------------------

enum IForm { IF_W, IF_WPP, IF_WMM, IF_WPM, IF_L, IF_H, IF_LPP, IF_HMM, NIF };
bool iform_modifies(int f) { return f == IF_WPP || f == IF_WMM || f == IF_WPM || f == IF_LPP || f == IF_HMM; }

std::string iaddr(int f, int i, int m) {
  std::string I = regname(I0 + i);
  switch (f) {
    case IF_WPP: case IF_LPP: return "[" + I + "++]";
    case IF_WMM: case IF_HMM: return "[" + I + "--]";
    case IF_WPM: return "[" + I + " ++ " + regname(M0 + m) + "]";
    default: return "[" + I + "]";
  }
}

void i_post(const State& in, State& out, int f, int i, int m) {
  switch (f) {
    case IF_WPP: out.r[I0 + i] = dag_mod(in, i, 4); break;
    case IF_WMM: out.r[I0 + i] = dag_mod(in, i, -4); break;
    case IF_WPM: out.r[I0 + i] = dag_mod(in, i, s32(in.r[M0 + m])); break;
    case IF_LPP: out.r[I0 + i] = dag_mod(in, i, 2); break;
    case IF_HMM: out.r[I0 + i] = dag_mod(in, i, -2); break;
    default: break;
  }
}

Op iload(int f, int d, int i, int m) {
  Op o;
  o.group = 2;
  o.load = true;
  bool word = f == IF_W || f == IF_WPP || f == IF_WMM || f == IF_WPM;
  bool high = f == IF_H || f == IF_HMM;
  std::string D = regname(d);
  o.text = word ? D + " = " + iaddr(f, i, m) : D + (high ? ".H" : ".L") + " = W" + iaddr(f, i, m);
  o.reads.insert(I0 + i);
  o.reads.insert(B0 + i);
  o.reads.insert(L0 + i);
  if (f == IF_WPM) o.reads.insert(M0 + m);
  if (!word) o.reads.insert(d);
  o.writes.insert(d);
  if (iform_modifies(f)) {
    o.writes.insert(I0 + i);
    o.mod_i = i;
  } else {
    o.acc_i = i;
  }
  o.exec = [=](const State& in, State& out) {
    u32 addr = in.r[I0 + i];
    u32 v;
    if (word) {
      v = ld(in, out, addr, 4);
    } else {
      u32 h = ld(in, out, addr, 2);
      v = high ? ((h << 16) | (in.r[d] & 0xffff)) : ((in.r[d] & 0xffff0000) | h);
    }
    i_post(in, out, f, i, m);
    out.r[d] = v;
  };
  return o;
}

Op istore(int f, int s, int i, int m) {
  Op o;
  o.group = 2;
  o.store = true;
  bool word = f == IF_W || f == IF_WPP || f == IF_WMM || f == IF_WPM;
  bool high = f == IF_H || f == IF_HMM;
  std::string S = regname(s);
  o.text = word ? iaddr(f, i, m) + " = " + S : "W" + iaddr(f, i, m) + " = " + S + (high ? ".H" : ".L");
  o.reads.insert(s);
  o.reads.insert(I0 + i);
  o.reads.insert(B0 + i);
  o.reads.insert(L0 + i);
  if (f == IF_WPM) o.reads.insert(M0 + m);
  if (iform_modifies(f)) {
    o.writes.insert(I0 + i);
    o.mod_i = i;
  } else {
    o.acc_i = i;
  }
  o.exec = [=](const State& in, State& out) {
    u32 addr = in.r[I0 + i], v = in.r[s];
    i_post(in, out, f, i, m);
    if (word)
      st(out, addr, 4, v);
    else
      st(out, addr, 2, high ? v >> 16 : v & 0xffff);
  };
  return o;
}

// ---- P-register loads and stores (LDST, LDSTii, LDSTiiFP, LDSTpmod; slot 1 only) ---------

enum PForm {
  PL_W, PL_WPP, PL_WMM, PL_WOFF, PL_WPQ, PL_FP, PL_HZ, PL_HXPP, PL_HZMM, PL_HXOFF, PL_HZPQ,
  PL_LPQ, PL_H_HI, PL_BZ, PL_BXPP, PL_BZMM, NPL
};
enum PSForm {
  PS_W, PS_WPP, PS_WMM, PS_WOFF, PS_WPQ, PS_FP, PS_H, PS_HPP, PS_HMM, PS_HOFF, PS_HHPQ, PS_HH,
  PS_B, PS_BPP, PS_BMM, NPS
};

Op pload(int f, int d, int p, int q) {
  Op o;
  o.group = 1;
  o.load = true;
  std::string D = regname(d), P = regname(P0 + p), Q = regname(P0 + q);
  int size = 4, post = 0;  // post: 0 none, 1 ++, -1 --, 2 ++Pq
  u32 off = 0;
  bool sx = false, lo = false, hi = false, fp = false;
  switch (f) {
    case PL_W: o.text = D + " = [" + P + "]"; break;
    case PL_WPP: o.text = D + " = [" + P + "++]"; post = 1; break;
    case PL_WMM: o.text = D + " = [" + P + "--]"; post = -1; break;
    case PL_WOFF: o.text = D + " = [" + P + " + 8]"; off = 8; break;
    case PL_WPQ: o.text = D + " = [" + P + " ++ " + Q + "]"; post = 2; break;
    case PL_FP: o.text = D + " = [FP - 8]"; fp = true; off = u32(-8); break;
    case PL_HZ: o.text = D + " = W[" + P + "] (Z)"; size = 2; break;
    case PL_HXPP: o.text = D + " = W[" + P + "++] (X)"; size = 2; post = 1; sx = true; break;
    case PL_HZMM: o.text = D + " = W[" + P + "--] (Z)"; size = 2; post = -1; break;
    case PL_HXOFF: o.text = D + " = W[" + P + " + 6] (X)"; size = 2; off = 6; sx = true; break;
    case PL_HZPQ: o.text = D + " = W[" + P + " ++ " + Q + "] (Z)"; size = 2; post = 2; break;
    case PL_LPQ: o.text = D + ".L = W[" + P + " ++ " + Q + "]"; size = 2; post = 2; lo = true; break;
    case PL_H_HI: o.text = D + ".H = W[" + P + "]"; size = 2; hi = true; break;
    case PL_BZ: o.text = D + " = B[" + P + "] (Z)"; size = 1; break;
    case PL_BXPP: o.text = D + " = B[" + P + "++] (X)"; size = 1; post = 1; sx = true; break;
    case PL_BZMM: o.text = D + " = B[" + P + "--] (Z)"; size = 1; post = -1; break;
  }
  int preg = fp ? FP : P0 + p;
  o.reads.insert(preg);
  if (post == 2) o.reads.insert(P0 + q);
  if (post) o.writes.insert(preg);
  if (lo || hi) o.reads.insert(d);
  o.writes.insert(d);
  o.exec = [=](const State& in, State& out) {
    u32 addr = in.r[preg] + off;
    u32 v = ld(in, out, addr, size);
    if (size == 2 && sx) v = sext16(v);
    if (size == 1 && sx) v = sext8(v);
    if (lo) v = (in.r[d] & 0xffff0000) | v;
    if (hi) v = (v << 16) | (in.r[d] & 0xffff);
    u32 np = in.r[preg];
    if (post == 1) np += size;
    if (post == -1) np -= size;
    if (post == 2) np += in.r[P0 + q];
    if (post) out.r[preg] = np;
    out.r[d] = v;
  };
  return o;
}

Op pstore(int f, int s, int p, int q) {
  Op o;
  o.group = 1;
  o.store = true;
  std::string S = regname(s), P = regname(P0 + p), Q = regname(P0 + q);
  int size = 4, post = 0;
  u32 off = 0;
  bool hi = false, fp = false;
  switch (f) {
    case PS_W: o.text = "[" + P + "] = " + S; break;
    case PS_WPP: o.text = "[" + P + "++] = " + S; post = 1; break;
    case PS_WMM: o.text = "[" + P + "--] = " + S; post = -1; break;
    case PS_WOFF: o.text = "[" + P + " + 8] = " + S; off = 8; break;
    case PS_WPQ: o.text = "[" + P + " ++ " + Q + "] = " + S; post = 2; break;
    case PS_FP: o.text = "[FP - 8] = " + S; fp = true; off = u32(-8); break;
    case PS_H: o.text = "W[" + P + "] = " + S; size = 2; break;
    case PS_HPP: o.text = "W[" + P + "++] = " + S; size = 2; post = 1; break;
    case PS_HMM: o.text = "W[" + P + "--] = " + S; size = 2; post = -1; break;
    case PS_HOFF: o.text = "W[" + P + " + 6] = " + S; size = 2; off = 6; break;
    case PS_HHPQ: o.text = "W[" + P + " ++ " + Q + "] = " + S + ".H"; size = 2; post = 2; hi = true; break;
    case PS_HH: o.text = "W[" + P + "] = " + S + ".H"; size = 2; hi = true; break;
    case PS_B: o.text = "B[" + P + "] = " + S; size = 1; break;
    case PS_BPP: o.text = "B[" + P + "++] = " + S; size = 1; post = 1; break;
    case PS_BMM: o.text = "B[" + P + "--] = " + S; size = 1; post = -1; break;
  }
  int preg = fp ? FP : P0 + p;
  o.reads.insert(preg);
  o.reads.insert(s);
  if (post == 2) o.reads.insert(P0 + q);
  if (post) o.writes.insert(preg);
  o.exec = [=](const State& in, State& out) {
    u32 addr = in.r[preg] + off, v = in.r[s];
    if (hi) v >>= 16;
    u32 np = in.r[preg];
    if (post == 1) np += size;
    if (post == -1) np -= size;
    if (post == 2) np += in.r[P0 + q];
    if (post) out.r[preg] = np;
    st(out, addr, size, size == 4 ? v : size == 2 ? (v & 0xffff) : (v & 0xff));
  };
  return o;
}

// Pointer-register loads and stores (slot 1 only).
enum PPForm { PP_L, PP_LPP, PP_LMM, PP_LOFF, PP_LFP, PP_S, PP_SPP, PP_SOFF, PP_SFP, NPP };
bool ppform_store(int f) { return f >= PP_S; }

Op pptr(int f, int pd, int p) {
  Op o;
  o.group = 1;
  std::string D = regname(P0 + pd), P = regname(P0 + p);
  int post = 0;
  u32 off = 0;
  bool fp = false;
  switch (f) {
    case PP_L: o.text = D + " = [" + P + "]"; break;
    case PP_LPP: o.text = D + " = [" + P + "++]"; post = 1; break;
    case PP_LMM: o.text = D + " = [" + P + "--]"; post = -1; break;
    case PP_LOFF: o.text = D + " = [" + P + " + 4]"; off = 4; break;
    case PP_LFP: o.text = D + " = [FP - 8]"; fp = true; off = u32(-8); break;
    case PP_S: o.text = "[" + P + "] = " + D; break;
    case PP_SPP: o.text = "[" + P + "++] = " + D; post = 1; break;
    case PP_SOFF: o.text = "[" + P + " + 4] = " + D; off = 4; break;
    case PP_SFP: o.text = "[FP - 8] = " + D; fp = true; off = u32(-8); break;
  }
  bool store = ppform_store(f);
  o.store = store;
  o.load = !store;
  int preg = fp ? FP : P0 + p;
  o.reads.insert(preg);
  if (post) o.writes.insert(preg);
  if (store) o.reads.insert(P0 + pd); else o.writes.insert(P0 + pd);
  o.exec = [=](const State& in, State& out) {
    u32 addr = in.r[preg] + off;
    u32 np = in.r[preg] + (post == 1 ? 4u : post == -1 ? u32(-4) : 0u);
    if (store) {
      u32 v = in.r[P0 + pd];
      if (post) out.r[preg] = np;
      st(out, addr, 4, v);
    } else {
      u32 v = ld(in, out, addr, 4);
      if (post) out.r[preg] = np;
      out.r[P0 + pd] = v;
    }
  };
  return o;
}

// ---- DAG modifies (dagMODim, dagMODik; slot 1 only) -------------------------------------

enum DForm { D_ADDM, D_SUBM, D_BREV, D_ADD2, D_SUB2, D_ADD4, D_SUB4, ND };

Op dag(int f, int i, int m) {
  Op o;
  o.group = 1;
  std::string I = regname(I0 + i), M = regname(M0 + m);
  switch (f) {
    case D_ADDM: o.text = I + " += " + M; break;
    case D_SUBM: o.text = I + " -= " + M; break;
    case D_BREV: o.text = I + " += " + M + " (BREV)"; break;
    case D_ADD2: o.text = I + " += 2"; break;
    case D_SUB2: o.text = I + " -= 2"; break;
    case D_ADD4: o.text = I + " += 4"; break;
    case D_SUB4: o.text = I + " -= 4"; break;
  }
  o.reads.insert(I0 + i);
  o.reads.insert(B0 + i);
  o.reads.insert(L0 + i);
  if (f <= D_BREV) o.reads.insert(M0 + m);
  o.writes.insert(I0 + i);
  o.mod_i = i;
  o.exec = [=](const State& in, State& out) {
    s32 mv = s32(in.r[M0 + m]);
    u32 n = 0;
    switch (f) {
      case D_ADDM: n = dag_mod(in, i, mv); break;
      case D_SUBM: n = dag_mod(in, i, -mv); break;
      case D_BREV: n = brev_add(in.r[I0 + i], in.r[M0 + m]); break;
      case D_ADD2: n = dag_mod(in, i, 2); break;
      case D_SUB2: n = dag_mod(in, i, -2); break;
      case D_ADD4: n = dag_mod(in, i, 4); break;
      case D_SUB4: n = dag_mod(in, i, -4); break;
    }
    out.r[I0 + i] = n;
  };
  return o;
}

// ---- test emission ---------------------------------------------------------------------

// Register values every combination starts from. The buffer sits at `base`; P, FP and I
// registers point into separate parts of it so that the loads of one slot and the stores of
// another never touch the same word unless a combination makes them share a register.
State initial(u32 base) {
  State s;
  s.base = base;
  for (u32 j = 0; j < BUFSZ; ++j) s.mem[j] = init_byte(j);
  static const u32 rv[8] = {0x11223344, 0x05068708, 0x7A0B8C0D, 0x31425364,
                            0x00F1F0E2, 0x7A6B5C4D, 0x21324354, 0x09182736};
  for (int k = 0; k < 8; ++k) s.r[R0 + k] = rv[k];
  s.r[P0 + 0] = base + 0x04;
  s.r[P0 + 1] = base + 0x20;
  s.r[P0 + 2] = 0x10;  // post-modify amount for [P1 ++ P2]
  s.r[P0 + 3] = base + 0xF0;
  s.r[P0 + 4] = 0x2468ACE0;
  s.r[P0 + 5] = 0x13579BDF;
  s.r[FP] = base + 0x40;
  s.r[I0 + 0] = base + 0xE0;
  s.r[I0 + 1] = base + 0x68;  // slot 1's
  s.r[I0 + 2] = base + 0xA8;  // slot 2's
  s.r[I0 + 3] = base + 0xD0;
  s.r[M0 + 0] = 4;
  s.r[M0 + 1] = 8;
  s.r[M0 + 2] = u32(-12);
  s.r[M0 + 3] = 16;
  return s;
}

struct Combo {
  std::string family;  // which slot writes what another reads
  Op s[3];
  bool circular = false;  // B/L of the modified I register set so that the update wraps
  std::vector<int> wrong_order;  // writer first
};

// Sets B/L of I register i so that the modify `o` wraps: a positive step ends at B + L
// exactly (wrapping to B), a negative one starts at B (wrapping to B + L - step).
bool make_circular(State& s, const Op& o, int i) {
  State t = s;
  State u = t;
  o.exec(t, u);
  u32 I = s.r[I0 + i], n = u.r[I0 + i];
  s32 step = s32(n - I);
  if (step == 0) return false;
  if (step > 0) {
    s.r[B0 + i] = I - 8;
    s.r[L0 + i] = 8 + u32(step);
  } else {
    s.r[B0 + i] = I;
    s.r[L0 + i] = 0x18;
  }
  return true;
}

void run_parallel(const Combo& c, const State& pre, State& out) {
  out = pre;
  for (const Op& o : c.s) o.exec(pre, out);
}

void run_sequential(const Combo& c, const State& pre, State& out) {
  out = pre;
  for (int k : c.wrong_order) {
    State in = out;
    c.s[k].exec(in, out);
  }
}

std::string insn_text(const Combo& c) {
  return c.s[0].text + " || " + c.s[1].text + " || " + c.s[2].text + ";";
}

// Legality as GNU as and the PRM's parallel-issue rules see it (see the top of the file).
// Also refuses the combinations the rule does not decide: a load and a store of the same
// memory word in one instruction.
bool legal(const Combo& c, const State& pre, std::string* why) {
  if (c.s[0].group != 0 || c.s[2].group != 2 || c.s[1].group == 0) { *why = "slot groups"; return false; }
  if (c.s[1].store && c.s[2].store) { *why = "two stores"; return false; }
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b)
      for (int r : c.s[a].writes)
        if (c.s[b].writes.count(r)) { *why = "register written twice"; return false; }
  State par;
  run_parallel(c, pre, par);
  if (par.fault) { *why = "model fault"; return false; }
  // Same-word load and store.
  std::set<u32> ld_words, st_words;
  for (int k = 1; k < 3; ++k) {
    State o1 = pre;
    c.s[k].exec(pre, o1);
    if (c.s[k].store) st_words.insert(o1.stored.begin(), o1.stored.end());
  }
  // The load addresses: a load's word is the one its address register points to (old value).
  for (int k = 1; k < 3; ++k) {
    if (!c.s[k].load) continue;
    // Find the address by probing: run the op on a state whose memory is poisoned at one word.
    for (u32 w = 0; w < BUFSZ; w += 4) {
      State p = pre;
      for (int b = 0; b < 4; ++b) p.mem[w + b] ^= 0xFF;
      State o1 = pre, o2 = p;
      c.s[k].exec(pre, o1);
      c.s[k].exec(p, o2);
      bool diff = false;
      for (int r = 0; r < NREG; ++r) diff |= o1.r[r] != o2.r[r];
      if (diff) ld_words.insert(pre.base + w);
    }
  }
  for (u32 w : ld_words)
    if (st_words.count(w)) { *why = "load and store of one word"; return false; }
  return true;
}

struct Emitter {
  std::string dir;
  int per_file;
  std::string family_file;
  std::map<std::string, int> file_no;  // next file number of each family
  int in_file = 0;
  std::ofstream out;
  std::string env;  // "" (virtual) or "operating"
  u32 base;
  int total = 0;
  std::map<std::string, int> counts;

  void close() {
    if (out.is_open()) {
      out << "\tpass\n";
      out.close();
    }
  }
  void open_if_needed(const std::string& family) {
    if (out.is_open() && family_file == family && in_file < per_file) return;
    close();
    family_file = family;
    char name[128];
    std::snprintf(name, sizeof name, "%s/par_%s_%02d.s", dir.c_str(), family.c_str(), file_no[family]++);
    out.open(name);
    if (!out) {
      std::fprintf(stderr, "gen_parallel: cannot write %s\n", name);
      std::exit(1);
    }
    in_file = 0;
    out << "# mach: bfin\n\n";
    out << "# Generated by emu/tests/semantics/gen_parallel.cpp (family " << family << "): multi-issue\n"
        << "# combinations in which one slot writes a register another slot reads. Expected values\n"
        << "# are the generator's model of the rule that all slots read before any slot writes.\n\n";
    out << ".include \"testutils.inc\"\n\tstart\n\n";
  }
};

void emit_init(std::ostream& o, const State& s) {
  // The buffer, byte j = 0x5B + 37 j.
  o << "\timm32 P0, " << hex(s.base) << ";\n\tR0 = 0x5B (Z);\n\tP1 = " << BUFSZ << " (Z);\n"
    << "\tLSETUP (1f, 2f) LC0 = P1;\n1:\tB[P0++] = R0;\n2:\tR0 += 37;\n";
  o << "\tR0 = 0;\n\tASTAT = R0;\n\tA0 = 0;\n";
  for (int r = 0; r < NREG; ++r) o << "\timm32 " << regname(r) << ", " << hex(s.r[r]) << ";\n";
}

void emit_checks(std::ostream& o, const State& exp, const State& alt, bool astat, bool a0) {
  for (int r = 0; r < NREG; ++r) {
    if (r >= M0) break;  // M, B and L are never written by these instructions
    o << "\tCHECKREG " << regname(r) << ", " << hex(exp.r[r]) << ";\n";
  }
  if (a0) {
    o << "\tR7 = A0.W;\n\tCHECKREG R7, " << hex(u32(exp.a0)) << ";\n";
  }
  if (astat) {
    o << "\tR7 = ASTAT;\n\tR6 = 3;\n\tR7 = R7 & R6;\n\tCHECKREG R7, " << hex(exp.azan) << ";\n";
  }
  std::set<u32> words = exp.stored;
  words.insert(alt.stored.begin(), alt.stored.end());
  for (u32 w : words) {
    u32 v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | exp.mem[w - exp.base + k];
    o << "\timm32 P5, " << hex(w) << ";\n\tR7 = [P5];\n\tCHECKREG R7, " << hex(v) << ";\n";
  }
}

bool differs(const State& a, const State& b, bool astat, bool a0) {
  if (a.fault != b.fault) return true;
  for (int r = 0; r < NREG; ++r)
    if (a.r[r] != b.r[r]) return true;
  if (a0 && (a.a0 & 0xffffffff) != (b.a0 & 0xffffffff)) return true;
  if (astat && a.azan != b.azan) return true;
  for (u32 j = 0; j < BUFSZ; ++j)
    if (a.mem[j] != b.mem[j]) return true;
  return false;
}

struct Stats {
  int generated = 0, discriminating = 0;
  std::map<std::string, int> refused;
};

void add_legal(Emitter& e, Stats& st, Combo c, int circ_op = -1) {
  State pre = initial(e.base);
  if (circ_op >= 0) {
    const Op& o = c.s[circ_op];
    if (!make_circular(pre, o, o.mod_i)) return;
    c.circular = true;
  }
  std::string why;
  if (!legal(c, pre, &why)) {
    st.refused[why]++;
    return;
  }
  State exp, alt;
  run_parallel(c, pre, exp);
  run_sequential(c, pre, alt);
  bool astat = c.s[0].astat, a0 = c.s[0].a0;
  bool disc = differs(exp, alt, astat, a0);
  e.open_if_needed(c.family);
  std::ostream& o = e.out;
  o << "\n\t# " << c.family << " " << st.generated << ": " << insn_text(c)
    << (c.circular ? "  (circular buffer, the update wraps)" : "") << "\n";
  emit_init(o, pre);
  o << "\t" << insn_text(c) << "\n";
  emit_checks(o, exp, alt, astat, a0);
  e.in_file++;
  st.generated++;
  e.counts[c.family]++;
  if (disc) st.discriminating++;
}

// ---- illegal combinations --------------------------------------------------------------

struct Illegal {
  std::string what;
  u32 w[4];  // the four halfwords: slot 0 (two), slot 1, slot 2
  bool known = false;  // a deviation emu/README.md lists as not fixed
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: gen_parallel OUTDIR [--per-file N] [--with-known-deviations]\n");
    return 2;
  }
  std::string dir = argv[1];
  int per_file = 25;
  bool with_known = false;
  for (int k = 2; k < argc; ++k) {
    std::string a = argv[k];
    if (a == "--per-file" && k + 1 < argc) per_file = std::atoi(argv[++k]);
    else if (a == "--with-known-deviations") with_known = true;
    else {
      std::fprintf(stderr, "gen_parallel: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  if (per_file < 1) per_file = 1;

  Emitter e;
  e.dir = dir;
  e.per_file = per_file;
  e.base = 0x00F00000;  // mapped memory of the virtual environment
  Stats st;

  // Default register roles: slot 0 writes R0 from R1 and R2; slot 1 uses R3, P1 (P2 as the
  // post-modify), I1/M1; slot 2 uses R4, I2/M2. A family makes two roles share a register.
  const int S0D = R0 + 0, S0A = R0 + 1, S0B = R0 + 2, S1D = R0 + 3, S2D = R0 + 4;

  auto s1_dloads = [&](int d, std::vector<Op>& v) {
    for (int f = 0; f < NIF; ++f) v.push_back(iload(f, d, 1, 1));
    for (int f = 0; f < NPL; ++f) v.push_back(pload(f, d, 1, 2));
  };
  auto s1_dstores = [&](int s, std::vector<Op>& v) {
    for (int f = 0; f < NIF; ++f) v.push_back(istore(f, s, 1, 1));
    for (int f = 0; f < NPS; ++f) v.push_back(pstore(f, s, 1, 2));
  };

  // 1. Slot 0 writes a D register that slot 1 stores: the store writes the old value.
  for (int k = 0; k < NS0; ++k) {
    std::vector<Op> v;
    s1_dstores(S0D, v);
    for (const Op& s1 : v) {
      Combo c{"s0w_s1st", {slot0(k, S0D, S0A, S0B), s1, nop16()}, false, {}};
      c.wrong_order = {0, 1, 2};
      add_legal(e, st, c);
    }
  }
  // 2. Slot 0 writes a D register that slot 2 stores.
  for (int k = 0; k < NS0; ++k)
    for (int f = 0; f < NIF; ++f) {
      Combo c{"s0w_s2st", {slot0(k, S0D, S0A, S0B), nop16(), istore(f, S0D, 2, 2)}, false, {}};
      c.wrong_order = {0, 1, 2};
      add_legal(e, st, c);
    }
  // 3. Slot 1 loads a D register that slot 0 reads: slot 0 computes with the old value.
  for (int k = 0; k < NS0; ++k) {
    std::vector<Op> v;
    s1_dloads(S0A, v);
    for (const Op& s1 : v) {
      Combo c{"s1ld_s0r", {slot0(k, S0D, S0A, S0B), s1, nop16()}, false, {}};
      c.wrong_order = {1, 0, 2};
      add_legal(e, st, c);
    }
  }
  // 4. Slot 2 loads a D register that slot 0 reads.
  for (int k = 0; k < NS0; ++k)
    for (int f = 0; f < NIF; ++f) {
      int r = s0_reads_b(k) ? S0B : S0A;
      Combo c{"s2ld_s0r", {slot0(k, S0D, S0A, S0B), nop16(), iload(f, r, 2, 2)}, false, {}};
      c.wrong_order = {2, 0, 1};
      add_legal(e, st, c);
    }
  // 5. Slot 1 loads a D register that slot 2 stores.
  {
    std::vector<Op> v;
    s1_dloads(S1D, v);
    for (const Op& s1 : v)
      for (int f = 0; f < NIF; ++f) {
        Combo c{"s1ld_s2st", {mnop(), s1, istore(f, S1D, 2, 2)}, false, {}};
        c.wrong_order = {0, 1, 2};
        add_legal(e, st, c);
      }
  }
  // 6. Slot 2 loads a D register that slot 1 stores.
  {
    std::vector<Op> v;
    s1_dstores(S2D, v);
    for (const Op& s1 : v)
      for (int f = 0; f < NIF; ++f) {
        Combo c{"s2ld_s1st", {mnop(), s1, iload(f, S2D, 2, 2)}, false, {}};
        c.wrong_order = {0, 2, 1};
        add_legal(e, st, c);
      }
  }
  // 7. Slot 1 modifies I1 (DAG modify, BREV, post-modify load or store) and slot 2 addresses
  // memory through I1 without modifying it: slot 2 uses the old I1. With and without a
  // circular buffer that makes the update wrap (not for BREV, which ignores L).
  {
    std::vector<Op> mods;
    for (int f = 0; f < ND; ++f) mods.push_back(dag(f, 1, 1));
    for (int f = 0; f < NIF; ++f)
      if (iform_modifies(f)) {
        mods.push_back(iload(f, S1D, 1, 1));
        mods.push_back(istore(f, S1D, 1, 1));
      }
    std::vector<Op> users;
    for (int f = 0; f < NIF; ++f)
      if (!iform_modifies(f)) {
        users.push_back(iload(f, S2D, 1, 2));
        users.push_back(istore(f, S2D, 1, 2));
      }
    for (int circ = 0; circ < 2; ++circ)
      for (const Op& m : mods)
        for (const Op& u : users) {
          if (circ && m.text.find("BREV") != std::string::npos) continue;
          Combo c{circ ? "s1mod_s2use_circ" : "s1mod_s2use", {mnop(), m, u}, false, {}};
          c.wrong_order = {0, 1, 2};
          add_legal(e, st, c, circ ? 1 : -1);
        }
  }
  // 8. Slot 2 modifies I1 (post-modify load or store) and slot 1 addresses memory through I1.
  {
    std::vector<Op> mods, users;
    for (int f = 0; f < NIF; ++f)
      if (iform_modifies(f)) {
        mods.push_back(iload(f, S2D, 1, 2));
        mods.push_back(istore(f, S2D, 1, 2));
      } else {
        users.push_back(iload(f, S1D, 1, 1));
        users.push_back(istore(f, S1D, 1, 1));
      }
    for (int circ = 0; circ < 2; ++circ)
      for (const Op& m : mods)
        for (const Op& u : users) {
          Combo c{circ ? "s2mod_s1use_circ" : "s2mod_s1use", {mnop(), u, m}, false, {}};
          c.wrong_order = {0, 2, 1};
          add_legal(e, st, c, circ ? 2 : -1);
        }
  }
  // 9. All three: slot 0 writes R0, slot 1 modifies I1, slot 2 stores R0 through I1 (the
  // shape of the FFT instruction): both the old R0 and the old I1 are used.
  for (int k = 0; k < NS0; ++k)
    for (int f = 0; f < ND; ++f)
      for (int g : {IF_W, IF_L, IF_H}) {
        Combo c{"s0w_s1mod_s2st", {slot0(k, S0D, S0A, S0B), dag(f, 1, 1), istore(g, S0D, 1, 2)}, false, {}};
        c.wrong_order = {0, 1, 2};
        add_legal(e, st, c);
      }
  // 10. Pointer loads and stores in slot 1 next to a slot 0 result stored by slot 2 or a
  // slot 2 load read by slot 0; the P registers they write are read by no other slot, so
  // these check the pointer update itself (including P1 = [P1], which reads the old P1).
  for (int k = 0; k < NS0; ++k)
    for (int f = 0; f < NPP; ++f)
      for (int same = 0; same < 2; ++same) {
        if (same && (ppform_store(f) || f == PP_LPP || f == PP_LMM || f == PP_LFP)) continue;
        Op p = pptr(f, same ? 1 : 3, 1);
        Combo c;
        if (ppform_store(f)) {
          int r = s0_reads_b(k) ? S0B : S0A;
          c = Combo{"s1ptr", {slot0(k, S0D, S0A, S0B), p, iload(IF_W, r, 2, 2)}, false, {}};
          c.wrong_order = {2, 0, 1};
        } else {
          c = Combo{"s1ptr", {slot0(k, S0D, S0A, S0B), p, istore(IF_W, S0D, 2, 2)}, false, {}};
          c.wrong_order = {0, 1, 2};
        }
        add_legal(e, st, c);
      }
  e.close();

  // ---- illegal combinations, operating environment ----
  // Halfwords from bfin-elf-as/objdump of the single instructions (see the comments).
  const u32 A0R0[2] = {0xCC09, 0x2000};      // A0 = R0 (dsp32alu, multi-issue bit set)
  const u32 MNOPW[2] = {0xC803, 0x1800};     // MNOP
  const u32 ADDS[2] = {0xCC04, 0x200A};      // R0 = R1 + R2 (S)
  const u32 SEARCHW[2] = {0xCC0D, 0x0210};   // (R0, R1) = SEARCH R2 (GT)
  std::vector<Illegal> ill = {
      // Two stores.
      {"A0 = R0 || [P1] = R3 || [I2] = R4 (two stores)", {A0R0[0], A0R0[1], 0x930B, 0x9F14}},
      {"A0 = R0 || W[P1] = R3 || W[I2] = R4.L (two stores)", {A0R0[0], A0R0[1], 0x970B, 0x9F34}},
      {"A0 = R0 || [I1] = R3 || [I2] = R4 (two stores)", {A0R0[0], A0R0[1], 0x9F0B, 0x9F14}},
      {"A0 = R0 || [FP - 8] = R3 || [I2++] = R4 (two stores)", {A0R0[0], A0R0[1], 0xBBE3, 0x9E14}},
      {"A0 = R0 || [P1 + 8] = R3 || [I2] = R4 (two stores)", {A0R0[0], A0R0[1], 0xB08B, 0x9F14}},
      {"A0 = R0 || [P1 ++ P2] = R3 || [I2] = R4 (two stores)", {A0R0[0], A0R0[1], 0x88D1, 0x9F14}},
      // One I register modified by both 16-bit slots.
      {"A0 = R0 || I1 += M1 || R4 = [I1++] (I1 modified twice)", {A0R0[0], A0R0[1], 0x9E65, 0x9C0C}},
      {"A0 = R0 || I1 += M1 (BREV) || W[I1++] = R4.L (I1 modified twice)", {A0R0[0], A0R0[1], 0x9EE5, 0x9E2C}},
      {"A0 = R0 || R3 = [I1++] || R4 = [I1--] (I1 modified twice)", {A0R0[0], A0R0[1], 0x9C0B, 0x9C8C}},
      {"A0 = R0 || I1 += 4 || R4 = [I1 ++ M2] (I1 modified twice)", {A0R0[0], A0R0[1], 0x9F69, 0x9DCC}},
      // One D register loaded by both 16-bit slots.
      {"A0 = R0 || R3 = [P1] || R3 = [I2] (R3 loaded twice)", {A0R0[0], A0R0[1], 0x910B, 0x9D13}},
      {"A0 = R0 || R3 = [I1] || R3.L = W[I2] (R3 loaded twice)", {A0R0[0], A0R0[1], 0x9D0B, 0x9D33}},
      // Slot 0's destination also loaded by a 16-bit slot.
      // The simulator does not check these (emu/README.md): generated only with
      // --with-known-deviations.
      {"R0 = R1 + R2 (S) || R0 = [P1] || NOP (R0 written twice)", {ADDS[0], ADDS[1], 0x9108, 0x0000}, true},
      {"R0 = R1 + R2 (S) || NOP || R0 = [I2] (R0 written twice)", {ADDS[0], ADDS[1], 0x0000, 0x9D10}, true},
      // Slot 2 holding what only slot 1 may hold.
      {"MNOP || NOP || R3 = [P1] (P-register load in slot 2)", {MNOPW[0], MNOPW[1], 0x0000, 0x910B}},
      {"MNOP || NOP || [P1] = R4 (P-register store in slot 2)", {MNOPW[0], MNOPW[1], 0x0000, 0x930C}},
      {"MNOP || NOP || [FP - 8] = R4 (FP store in slot 2)", {MNOPW[0], MNOPW[1], 0x0000, 0xBBE4}},
      {"MNOP || NOP || I2 += M2 (DAG modify in slot 2)", {MNOPW[0], MNOPW[1], 0x0000, 0x9E6A}},
      {"MNOP || R3 = [I1] || I2 += 4 (DAG modify in slot 2)", {MNOPW[0], MNOPW[1], 0x9D0B, 0x9F6A}},
      // Slot 1 holding something other than a load, store or DAG op.
      {"MNOP || R3 += 1 || NOP (ALU op in slot 1)", {MNOPW[0], MNOPW[1], 0x640B, 0x0000}},
      {"MNOP || R3 = R4 || NOP (register move in slot 1)", {MNOPW[0], MNOPW[1], 0x301C, 0x0000}},
      {"A0 = R0 || RAISE 15 || NOP (program control in slot 1)", {A0R0[0], A0R0[1], 0x009F, 0x0000}},
      {"MNOP || MNOP (a 32-bit instruction in slot 1)", {MNOPW[0], MNOPW[1], 0xC803, 0x1800}},
      // SEARCH only with a load through P0 and a NOP (the PRM text quoted in the
      // simulator's decode_dsp32alu_0; se_illegalcombination.S counts [P0 ++ P1] illegal).
      {"(R0, R1) = SEARCH R2 (GT) || [P1] = R3 || NOP (SEARCH with a store)", {SEARCHW[0], SEARCHW[1], 0x930B, 0x0000}},
      {"(R0, R1) = SEARCH R2 (GT) || R4 = [P0 ++ P1] || NOP (SEARCH with a P-modify load)", {SEARCHW[0], SEARCHW[1], 0x8108, 0x0000}},
      {"(R0, R1) = SEARCH R2 (GT) || R4 = [P1++] || NOP (SEARCH with a load not through P0)", {SEARCHW[0], SEARCHW[1], 0x900C, 0x0000}},
      {"(R0, R1) = SEARCH R2 (GT) || NOP || R4 = [I0] (SEARCH with a slot-2 load)", {SEARCHW[0], SEARCHW[1], 0x0000, 0x9D04}},
  };
  // One file each: a simulator that misses one check fails that file alone.
  int n_illegal = 0, n_known = 0;
  State pre = initial(0xFF800000);  // L1 data bank A: mapped in the operating environment
  for (const Illegal& il : ill) {
    if (il.known && !with_known) {
      ++n_known;
      continue;
    }
    char name[128];
    std::snprintf(name, sizeof name, "%s/par_illegal_%02d.s", dir.c_str(), n_illegal);
    std::ofstream o(name);
    if (!o) {
      std::fprintf(stderr, "gen_parallel: cannot write %s\n", name);
      return 1;
    }
    o << "# mach: bfin\n# sim: --environment operating\n\n"
      << "# Generated by emu/tests/semantics/gen_parallel.cpp: an illegal multi-issue combination\n"
      << "# raises EXCAUSE 0x22 (illegal instruction combination) and changes nothing.\n"
      << "# The EVT3 handler counts it in R7 (after checking EXCAUSE) and returns past the\n"
      << "# 8-byte instruction; then the count, the registers and the memory are checked.\n"
      << "# " << il.what << "\n\n"
      << ".include \"testutils.inc\"\n\tstart\n\n"
      << "\t# EVT3 (0xFFE0200C) = the handler; then drop to user mode at 1f with RTI.\n"
      << "\timm32 P0, 0xFFE0200C;\n\tR0.L = xhandler;\n\tR0.H = xhandler;\n\t[P0] = R0;\n"
      << "\tR0.L = 1f;\n\tR0.H = 1f;\n\tRETI = R0;\n\tRTI;\n1:\n";
    emit_init(o, pre);
    o << "\tR7 = 0;\n";
    o << "\t.short 0x" << std::hex << il.w[0] << ", 0x" << il.w[1] << ", 0x" << il.w[2] << ", 0x" << il.w[3]
      << std::dec << ";\n";
    o << "\tCHECKREG R7, 0x00000001;\n";
    // R5, R6 and P4 belong to the handler; no illegal combination here names them.
    for (int r = 0; r < M0; ++r) {
      if (r == R0 + 5 || r == R0 + 6 || r == R0 + 7 || r == P0 + 4) continue;
      o << "\tCHECKREG " << regname(r) << ", " << hex(pre.r[r]) << ";\n";
    }
    o << "\tR6 = A0.W;\n\tCHECKREG R6, 0x00000000;\n\tR6 = ASTAT;\n\tCHECKREG R6, 0x00000000;\n";
    // The words the slots would have stored.
    for (u32 w : {0x20u, 0x28u, 0x38u, 0x68u, 0xA8u, 0xACu}) {
      u32 v = 0;
      for (int k = 3; k >= 0; --k) v = (v << 8) | pre.mem[w + k];
      o << "\timm32 P5, " << hex(pre.base + w) << ";\n\tR6 = [P5];\n\tCHECKREG R6, " << hex(v) << ";\n";
    }
    o << "\n\tdbg_pass;\n\n"
      << "xhandler:\n"
      << "\t# Only EXCAUSE 0x22 is expected; anything else fails the test. ASTAT is kept\n"
      << "\t# in P4: the compare and the count change it.\n"
      << "\tP4 = ASTAT;\n\tR6 = SEQSTAT;\n\tR5 = 0x3F;\n\tR6 = R6 & R5;\n\tR5 = 0x22;\n\tCC = R6 == R5;\n"
      << "\tIF !CC JUMP 9f;\n\tR7 += 1;\n\tR6 = RETX;\n\tR6 += 8;\n\tRETX = R6;\n\tASTAT = P4;\n\tRTX;\n"
      << "9:\tdbg_fail;\n";
    ++n_illegal;
  }

  std::printf("legal combinations generated: %d (discriminating: %d)\n", st.generated, st.discriminating);
  for (const auto& kv : e.counts) std::printf("  %-18s %d\n", kv.first.c_str(), kv.second);
  std::printf("refused as illegal or undecided while enumerating:");
  for (const auto& kv : st.refused) std::printf(" %s %d;", kv.first.c_str(), kv.second);
  std::printf("\nillegal combinations generated: %d (left out: %d the simulator is known not to check)\n",
              n_illegal, n_known);
  return 0;
}
