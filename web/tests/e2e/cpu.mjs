// CPU time of the headless chromium an end-to-end test started (Linux /proc; elsewhere null): the processes
// whose command line names `marker` (the test's own profile directory, so no other browser on the machine
// counts) and all their descendants (GPU process, where SwiftShader rasterises WebGL; renderers; utilities),
// utime + stime of every thread, in seconds. The machine's other load slows a page's frame rate but hardly
// its CPU time per frame, which is why comparisons between two ways of drawing use it (classroom.mjs).
import { readdirSync, readFileSync } from 'node:fs';

const TICK = 100; // USER_HZ: /proc counts CPU time in clock ticks

function stat(pid) {
  const s = readFileSync(`/proc/${pid}/stat`, 'utf8');
  const f = s.slice(s.lastIndexOf(')') + 2).split(' ');
  return { ppid: Number(f[1]), cpu: (Number(f[11]) + Number(f[12])) / TICK };
}

/** CPU seconds [s] of the browser started with `marker` on its command line, or null without /proc. */
export function browserCpu(marker) {
  let pids;
  try {
    pids = readdirSync('/proc').filter((d) => /^\d+$/.test(d));
  } catch {
    return null;
  }
  const procs = new Map();
  for (const pid of pids) {
    try {
      procs.set(Number(pid), { ...stat(pid), cmd: readFileSync(`/proc/${pid}/cmdline`, 'utf8') });
    } catch {
      /* gone */
    }
  }
  const ours = new Set([...procs].filter(([, p]) => p.cmd.includes(marker)).map(([pid]) => pid));
  if (ours.size === 0) return null;
  for (let grew = true; grew; ) {
    grew = false;
    for (const [pid, p] of procs) {
      if (!ours.has(pid) && ours.has(p.ppid)) {
        ours.add(pid);
        grew = true;
      }
    }
  }
  let cpu = 0;
  for (const pid of ours) cpu += procs.get(pid).cpu;
  return cpu;
}
