// The fused instructions of vm/fused.def as tables: their opcodes (after bytecode's, from
// kOpCount), their base patterns with each instruction's word offset, and their names and
// meanings. Freestanding, as the rest of the VM; what the quickener, the execute loop, the
// machine's breakpoints and the tools read.
#pragma once
#include <cstdint>

#include "bytecode/opcodes.h"

namespace uprog::vm {

constexpr uint32_t kMostFusedInstructions = 14;

// One fused instruction's pattern: its base instructions and the words they take together.
// A folded family's pattern has one compare-and-jump that stands for its six relations
// (JEQI..JGEI or JNEQF..JNGEF, in that order): ops[relation_at] is the first of them.
constexpr uint8_t kNoRelation = 0xFF;
struct FusedShape {
  uint8_t count;
  bytecode::Op ops[kMostFusedInstructions];
  uint8_t length;
  uint8_t relation_at = kNoRelation;
  bool per_relation = false;  // a handler for each relation (FUSED_PER_RELATION), else a switch
};
// A folded compare-and-jump's relation, 0..5 for == != < <= > >=, holds of a and b. In a family
// declared FUSED_PER_RELATION each relation has a handler of its own (kFamilyMembers, below),
// in which the relation is a constant: the switch is the compiler's. Elsewhere the switch runs:
// its jump is one a handler (each inlines its own), which predicts well where a program's
// sites of it share a relation; on ST's loop it measured 8% faster than a branch-free table of
// the four states (<, ==, >, unordered), 0.489 s against 0.532 s (medians of 5, alternated).
// For floats the table was tried again for room in the embeddable core (half the switch's
// bytes in each switching handler): 3 % slower on Gold's profile, so the switch stays
// (docs/architecture.md).
template <typename T>
constexpr bool relation_holds(uint32_t relation, T a, T b) {
  switch (relation) {
    case 0:
      return a == b;
    case 1:
      return a != b;
    case 2:
      return a < b;
    case 3:
      return a <= b;
    case 4:
      return a > b;
    default:
      return a >= b;
  }
}
static_assert(relation_holds(0, 2, 2) && relation_holds(1, 2, 3) && relation_holds(2, 2, 3) &&
              relation_holds(3, 3, 3) && relation_holds(4, 4, 3) && relation_holds(5, 3, 3) &&
              !relation_holds(5, 2, 3) && !relation_holds(2, 3, 3));

// Of a pattern's opcodes (bytecode::Op, or their bytes as kFusedBases packs them): the words
// before the k-th.
template <typename OpOrByte>
constexpr uint32_t words_before(const OpOrByte* ops, uint32_t k) {
  uint32_t at = 0;
  for (uint32_t i = 0; i < k; ++i) at += bytecode::op_length(static_cast<bytecode::Op>(ops[i]));
  return at;
}
// Where the pattern's k-th instruction starts: a word offset from the first.
constexpr uint32_t fused_offset(const FusedShape& s, uint32_t k) { return words_before(s.ops, k); }
// The pattern leaves a value for the rest of an expression (its last instruction pushes and goes
// on): like such a base instruction it seldom ends a line (the execute loop's DISPATCH_VALUE).
constexpr bool leaves_value(const FusedShape& s) {
  const bytecode::OpInfo& last = bytecode::op_info(s.ops[s.count - 1]);
  return last.push > 0 && last.flow == bytecode::Flow::Next;
}

namespace fused_detail {
using enum bytecode::Op;
// A pattern's place for any of six opcodes from `first`: the int (JREL) or float (JNRELF)
// compare-and-jumps, or the int (IARITH) or float (FARITH) operators, whose WHEN takes three.
struct AnyRelation {
  bytecode::Op first;
};
inline constexpr AnyRelation JREL{JEQI};
inline constexpr AnyRelation JNRELF{JNEQF};
inline constexpr AnyRelation FARITH{ADDF};
inline constexpr AnyRelation IARITH{ADDI};
constexpr void add(FusedShape& s, bytecode::Op op) { s.ops[s.count++] = op; }
constexpr void add(FusedShape& s, AnyRelation r) {
  s.relation_at = s.count;
  s.ops[s.count++] = r.first;
}
constexpr FusedShape per_relation(FusedShape s) {
  s.per_relation = true;
  return s;
}
template <typename... Ops>
constexpr FusedShape shape(Ops... ops) {
  FusedShape s{};
  (add(s, ops), ...);
  uint8_t at = 0;
  for (uint32_t k = 0; k < s.count; ++k)
    at = static_cast<uint8_t>(at + bytecode::op_length(s.ops[k]));
  s.length = at;
  return s;
}
#define UPROG_UNPAREN(...) __VA_ARGS__
inline constexpr FusedShape kShapes[] = {
#define FUSED(name, pattern, when, meaning, ...) shape(UPROG_UNPAREN pattern),
#define FUSED_PER_RELATION(name, pattern, when, meaning, ...) \
  per_relation(shape(UPROG_UNPAREN pattern)),
#include "vm/fused.def"
#undef FUSED_PER_RELATION
#undef FUSED
};
}  // namespace fused_detail

enum class Fused : uint8_t {
#define FUSED(name, pattern, when, meaning, ...) name,
#include "vm/fused.def"
#undef FUSED
};

// The patterns in full, for what runs at compile time (the execute loop's handlers, the
// quickener's WHEN) and for tools; the quickener matches kFusedBases' copy (below).
inline constexpr const FusedShape* kFusedShapes = fused_detail::kShapes;
inline constexpr uint32_t kFusedCount = sizeof(fused_detail::kShapes) / sizeof(FusedShape);
inline constexpr uint32_t kFirstFused = bytecode::kOpCount;

// The opcodes, from kFirstFused: one for each fused instruction, and for a folded family
// declared FUSED_PER_RELATION one for each relation, which the quickener picks from the
// pattern's compare-and-jump. One declaration, six handlers: a run-time switch on the relation,
// shared by every site of the family, measured 8-16% slower on bench/peers' loops and a quarter
// of a Gold float condition (docs/architecture.md); the families that loops and conditions
// rarely run keep the switch, as the six handlers take room in the embeddable core
// (scripts/footprint).
constexpr uint32_t kFamilyMembers = 6;
constexpr uint32_t opcodes_of(const FusedShape& s) { return s.per_relation ? kFamilyMembers : 1u; }
constexpr uint32_t count_fused_opcodes() {
  uint32_t n = 0;
  for (const FusedShape& s : fused_detail::kShapes) n += opcodes_of(s);
  return n;
}
inline constexpr uint32_t kFusedOpcodeCount = count_fused_opcodes();
static_assert(kFirstFused + kFusedOpcodeCount <= 256, "an opcode is one byte");

constexpr uint32_t count_pattern_ops() {
  uint32_t n = 0;
  for (const FusedShape& s : fused_detail::kShapes) n += s.count;
  return n;
}

// What runs after compile time needs of the fused instructions: of each fused opcode, its
// instruction, its pattern's first opcode and its words; of each instruction, its first opcode
// (the machine, to see base code); and the patterns as the quickener matches them when an image
// loads: each pattern's base opcodes one after another, where each starts, and its folded
// relation's place. kShapes keeps 14 opcodes for every pattern, most of them unused, and only
// compile-time code reads it: firmware carries this table alone (scripts/footprint).
struct FusedBases {
  uint8_t instruction[kFusedOpcodeCount];
  uint8_t first[kFusedOpcodeCount];
  uint8_t length[kFusedOpcodeCount];
  uint8_t first_opcode[kFusedCount];
  uint8_t pattern_ops[count_pattern_ops()];
  uint16_t pattern_start[kFusedCount + 1];  // f's: pattern_ops[pattern_start[f]] and on
  uint8_t relation_at[kFusedCount];         // FusedShape's
};
constexpr FusedBases make_fused_bases() {
  FusedBases b{};
  uint32_t op = 0, at = 0;
  for (uint32_t f = 0; f < kFusedCount; ++f) {
    const FusedShape& s = fused_detail::kShapes[f];
    b.first_opcode[f] = static_cast<uint8_t>(op);
    for (uint32_t m = 0; m < opcodes_of(s); ++m, ++op) {
      b.instruction[op] = static_cast<uint8_t>(f);
      b.first[op] = static_cast<uint8_t>(s.ops[0]);
      b.length[op] = s.length;
    }
    b.pattern_start[f] = static_cast<uint16_t>(at);
    b.relation_at[f] = s.relation_at;
    for (uint32_t k = 0; k < s.count; ++k) b.pattern_ops[at++] = static_cast<uint8_t>(s.ops[k]);
  }
  b.pattern_start[kFusedCount] = static_cast<uint16_t>(at);
  return b;
}
inline constexpr FusedBases kFusedBases = make_fused_bases();

// The opcode of fused instruction f, a folded family's for `relation` (0..5).
constexpr uint32_t fused_number(Fused f, uint32_t relation = 0) {
  return kFirstFused + kFusedBases.first_opcode[static_cast<uint32_t>(f)] + relation;
}
constexpr bool is_fused(uint32_t word) { return (word & 0xFFu) >= kFirstFused; }
// Which fused instruction a fused word's opcode is (a folded family's for any relation).
constexpr uint32_t fused_of(uint32_t word) {
  return kFusedBases.instruction[(word & 0xFFu) - kFirstFused];
}
// The base word a fused instruction's first word was: its pattern's first opcode, no mark (a
// word inside a fused sequence carries none). Any other word as it is.
constexpr uint32_t base_word(uint32_t word) {
  if (!is_fused(word)) return word;
  return (word & ~0x1FFu) | kFusedBases.first[(word & 0xFFu) - kFirstFused];
}
// How many words the instruction at `word` takes: a fused one its whole pattern.
constexpr uint32_t instruction_length(uint32_t word) {
  return is_fused(word) ? kFusedBases.length[(word & 0xFFu) - kFirstFused]
                        : bytecode::op_length(bytecode::word_op(word));
}

// Names and meanings, for tools (a firmware that does not use them carries none).
inline constexpr const char* kFusedNames[] = {
#define FUSED(name, pattern, when, meaning, ...) #name,
#include "vm/fused.def"
#undef FUSED
};
inline constexpr const char* kFusedMeanings[] = {
#define FUSED(name, pattern, when, meaning, ...) meaning,
#include "vm/fused.def"
#undef FUSED
};

}  // namespace uprog::vm
