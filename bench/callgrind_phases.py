#!/usr/bin/env python3
"""Splits the instructions of a VTP run measured by callgrind into the phases of the kernel.

    valgrind --tool=callgrind --dump-instr=yes --callgrind-out-file=OUT \
      --toggle-collect='CGAL_ext::Geodesics_3::internal::VTP_solver::run()' \
      BENCH --mesh MESH --method vtp
    python3 bench/callgrind_phases.py OUT BENCH [WINDOWS] [--fine]

BENCH must be built with -O3 -g (the same code as -O3: the count is the same). Each instruction
is charged to the innermost kernel function of its inline chain (addr2line -i); the distance
helpers (norm2d, distance_at) and std helpers are charged to their caller. WINDOWS (the
windows_created of the run) gives instructions per window; --fine splits phases by function.
"""
import collections
import re
import subprocess
import sys

PHASES = [
    ('pairwise clipping', ['prune_pairs', 'clip_against_later', 'sort_by_start', 'clip_pair', 'compare_on_overlap', 'equal_distance_points']),
    ('trimming', ['trim_by_edge_vertices', 'keep_window', 'list_window']),
    ('unfolding', ['make_child', 'face_crossing', 'apex_crossing', 'distance_to_apex']),
    ('emissions of pseudo-sources', ['compute_emission', 'apply_emission', 'emit_', 'saddle_cone', 'polar_angle']),
    ('list bookkeeping', ['schedule', 'inside_swept', 'add_chain', 'detach', 'merge', 'relax', 'set_distance',
                          'take_vertex', 'Object_pool', 'Indexed_pool', 'Run_pool', 'Window_list', 'drain',
                          'insert_window', 'note_live_windows', 'for_each_outgoing', 'run()', 'Min_heap',
                          'take_vertices', 'flush_waiting', 'limit()', 'reset_wavefront', 'update_stop']),
]
HELPERS = ('allocator_traits', 'Double_pair', 'clamp_to', 'square_roots', 'norm2d', 'square_root', '_mm_', 'distance_at(', ' std::max<', ' std::min<', 'std::abs', 'std::sqrt',
           'std::copysign', 'std::isfinite', 'std::__atomic_base', 'std::vector<', '__new_allocator', '__normal_iterator',
           'Solver_mesh::', 'std::operator<', 'std::__and_', 'std::swap', 'std::move', 'std::pair<', 'enable_if',
           '__gnu_cxx::operator', '__ops::')


def read_costs(path, binary_name):
    """Self cost per instruction address of the binary (other objects summed as 'libraries')."""
    cost = collections.Counter()
    names, obj, addr, after_call = {}, None, 0, False
    for line in open(path):
        line = line.rstrip('\n')
        m = re.match(r'c?ob=\((\d+)\)(?: (.*))?', line)
        if m:
            if m.group(2):
                names[m.group(1)] = m.group(2)
            if line.startswith('ob='):
                obj = names[m.group(1)]
            continue
        if line.startswith('calls='):
            after_call = True  # the next line is the inclusive cost of the call
            continue
        if not line or line[0] not in '0123456789+-*':
            continue
        parts = line.split()
        a = parts[0]
        if a.startswith('0x'):
            addr = int(a, 16)
        elif a[0] in '+-':
            addr += int(a)
        if after_call:
            after_call = False
            continue
        if len(parts) >= 3:
            cost[addr if obj and obj.endswith(binary_name) else 'libraries'] += int(parts[2])
    return cost


def inline_chains(binary, addresses):
    out = subprocess.run(['addr2line', '-a', '-i', '-f', '-C', '-e', binary] + ['0x%x' % a for a in addresses],
                         capture_output=True, text=True, check=True).stdout.split('\n')
    chains, current, i = {}, None, 0
    while i < len(out):
        if out[i].startswith('0x'):
            current = int(out[i], 16)
            chains[current] = []
            i += 1
        elif current is not None and out[i]:
            chains[current].append(out[i])  # function name, then its file:line
            i += 2
        else:
            i += 1
    return chains


def phase(chain, fine):
    def named(p, keys, name):
        return p + (' / ' + next(k for k in keys if k in name) if fine else '')
    for name in chain:  # innermost first
        if 'Window' in name and re.search(r'std::__(insertion_sort|introsort|unguarded|move_median|final_insertion|copy_move)', name):
            return 'pairwise clipping' + (' / sort' if fine else '')
        if 'remove_if' in name:
            return 'pairwise clipping' + (' / sort' if fine else '')
        if 'heap' in name and 'pair<double, int>' in name:
            return 'list bookkeeping' + (' / heap' if fine else '')
        if 'VTP_solver::' in name:
            for p, keys in PHASES:
                if any(k in name for k in keys):
                    return named(p, keys, name)
            if 'VTP_solver::propagate' in name:
                return 'propagate loops (list copy, apex, children)'
        # (a helper by its name, not by the types of its parameters: the pool's functions take vectors)
        if not any(p in name.split('(')[0] for p in ('Indexed_pool<', 'Run_pool<')) and any(k in name for k in HELPERS):
            continue
        for p, keys in PHASES:
            if any(k in name for k in keys):
                return named(p, keys, name)
        return 'other'
    return 'other'


def main():
    args = [a for a in sys.argv[1:] if a != '--fine']
    fine = '--fine' in sys.argv
    out, binary = args[0], args[1]
    windows = float(args[2]) if len(args) > 2 else 0
    cost = read_costs(out, binary.split('/')[-1])
    chains = inline_chains(binary, [a for a in cost if isinstance(a, int)])
    total = collections.Counter()
    for a, c in cost.items():
        total[phase(chains.get(a, []), fine) if isinstance(a, int) else 'libraries'] += c
    s = sum(total.values())
    for p, c in total.most_common():
        print('%-48s %14d %5.1f%% %7.1f/window' % (p, c, 100.0 * c / s, c / windows if windows else 0))
    print('%-48s %14d %5.1f%% %7.1f/window' % ('total', s, 100.0, s / windows if windows else 0))


if __name__ == '__main__':
    main()
