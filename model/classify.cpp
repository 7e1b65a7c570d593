// classify.cpp — the combination tables and the classification program.
// Each table is written row by row as in algorithm.md section 3, so that a
// reader can check it against the paper cell by cell.
#include "classify.h"

namespace csgrt {

std::string Class::str() const {
    switch (kind) {
    case OUT: return "OUT";
    case IN: return "IN " + std::to_string(to);
    case BORDER: return "BORDER " + std::to_string(from) + "," + std::to_string(to);
    }
    return "?";
}

Class table_add(Class l, Class r) {
    if (r.kind == Class::IN) return r;                       // right operand owns
    if (r.kind == Class::OUT) return l;
    // r is BORDER c,d
    if (l.kind == Class::OUT) return r;
    if (l.kind == Class::IN) {
        if (r.from == 0) return Class::border(l.to, r.to);   // c = 0: BORDER l,d
        if (r.to == 0) return Class::border(r.from, l.to);   // d = 0: BORDER c,l
        return r;                                            // BORDER c,d
    }
    return Class::out();                                     // cannot occur
}

Class table_sub(Class l, Class r) {
    if (r.kind == Class::IN) return Class::out();
    if (r.kind == Class::OUT) return l;
    // r is BORDER c,d
    if (l.kind == Class::IN) {
        if (r.from == 0) return Class::border(l.to, 0);      // entering the cutter
        if (r.to == 0) return Class::border(0, l.to);        // leaving the cutter
        return Class::out();
    }
    return Class::out();                                     // OUT row; BORDER row cannot occur
}

Class table_and(Class l, Class r) {
    if (l.kind == Class::OUT) return Class::out();
    if (r.kind == Class::OUT) return Class::out();
    if (r.kind == Class::IN) return l;                       // IN l, or BORDER a,b
    // r is BORDER c,d
    if (l.kind == Class::IN) {
        if (r.from == 0) return Class::border(0, l.to);
        if (r.to == 0) return Class::border(l.to, 0);
        return l;                                            // IN l
    }
    return Class::out();                                     // cannot occur
}

Class combine(Op op, Class l, Class r) {
    switch (op) {
    case Op::ADD: return table_add(l, r);
    case Op::SUB: return table_sub(l, r);
    case Op::AND: return table_and(l, r);
    case Op::LEAF: break;
    }
    return Class::out();
}

Class classify(const std::vector<Instr>& program, const uint8_t* flags,
               const uint8_t* leaf_material, int hit_leaf, bool entering) {
    Class stack[kMaxStackDepth];
    int sp = 0;
    for (const Instr& ins : program) {
        if (ins.op == Op::LEAF) {
            const int leaf = ins.arg;
            const uint8_t m = leaf_material[leaf];
            Class c;
            if (leaf == hit_leaf)
                c = entering ? Class::border(0, m) : Class::border(m, 0);
            else
                c = flags[leaf] ? Class::in(m) : Class::out();
            stack[sp++] = c;
        } else {
            const Class r = stack[--sp];
            const Class l = stack[--sp];
            stack[sp++] = combine(ins.op, l, r);
        }
    }
    return sp > 0 ? stack[sp - 1] : Class::out();
}

int stack_depth(const std::vector<Instr>& program) {
    int sp = 0, max_sp = 0;
    for (const Instr& ins : program) {
        sp += (ins.op == Op::LEAF) ? 1 : -1;
        if (sp > max_sp) max_sp = sp;
    }
    return max_sp;
}

}  // namespace csgrt
