// CPU time of the headless chromium an end-to-end test started (Linux /proc; elsewhere null): the processes
// whose command line names `marker` (the test's own profile directory, so no other browser on the machine
// counts) and all their descendants (GPU process, where SwiftShader rasterises WebGL; renderers; utilities),
// utime + stime of every thread, in seconds. The machine's other load slows a page's frame rate but hardly
// its CPU time per frame, which is why comparisons between two ways of drawing use it (classroom.mjs). By
// thread (cpuByThread): where a frame's CPU goes, process by process (profile.mjs, bench/lab_frames.mjs).
import { readdirSync, readFileSync } from 'node:fs';

const TICK = 100; // USER_HZ: /proc counts CPU time in clock ticks

function stat(pid) {
  const s = readFileSync(`/proc/${pid}/stat`, 'utf8');
  const f = s.slice(s.lastIndexOf(')') + 2).split(' ');
  return { ppid: Number(f[1]), cpu: (Number(f[11]) + Number(f[12])) / TICK };
}

/** The processes whose command line names `marker` and all their descendants, as pid -> { ppid, cpu [s],
 *  cmd (the command line) }; null without /proc. */
function browserProcesses(marker) {
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
  for (let grew = ours.size > 0; grew; ) {
    grew = false;
    for (const [pid, p] of procs) {
      if (!ours.has(pid) && ours.has(p.ppid)) {
        ours.add(pid);
        grew = true;
      }
    }
  }
  return new Map([...ours].map((pid) => [pid, procs.get(pid)]));
}

/** CPU seconds [s] of the browser started with `marker` on its command line, or null without /proc. */
export function browserCpu(marker) {
  const ours = browserProcesses(marker);
  if (ours === null || ours.size === 0) return null;
  let cpu = 0;
  for (const p of ours.values()) cpu += p.cpu;
  return cpu;
}

/**
 * CPU seconds [s] by thread of the browser started with `marker` on its command line, keyed
 * `<kind>: <thread name without its trailing number>` (threads of one name summed), where
 * `kindOf(args)` names a process by its arguments (chromium rewrites its children's command lines into
 * one space-separated string, so they are split at NULs and spaces); `more` adds other processes as
 * [pid, kind] pairs (a server). Empty without /proc.
 */
export function cpuByThread(marker, kindOf, more = []) {
  const out = {};
  const kinds = [...(browserProcesses(marker) ?? new Map())].map(([pid, p]) => [pid, kindOf(p.cmd.split(/[\0 ]/))]);
  for (const [pid, kind] of [...kinds, ...more]) {
    let tids = [];
    try {
      tids = readdirSync(`/proc/${pid}/task`);
    } catch {
      continue;
    }
    for (const tid of tids) {
      try {
        const key = `${kind}: ${readFileSync(`/proc/${pid}/task/${tid}/comm`, 'utf8').trim().replace(/\d+$/, '')}`;
        out[key] = (out[key] ?? 0) + stat(`${pid}/task/${tid}`).cpu;
      } catch {
        /* gone */
      }
    }
  }
  return out;
}
