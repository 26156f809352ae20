import { describe, expect, it } from 'vitest';
import type { Status } from '../../src/protocol';
import type { UrlScenario } from '../../src/url';
import { commandsFor, decodeTwin, decodeUrl, encodeUrl, encodeView, fromStatus, linkContents } from '../../src/url';

const status: Status = {
  type: 'status',
  epoch: 3,
  scenario: 'rosette',
  title: 'Rosette',
  paused: true,
  time_scale: 0.25,
  method: 'rattle4',
  adaptive: false,
  dt: 0.0005,
  params: { length: 0.7, mass: 2.5, g: -9.81 },
  t: 12.3,
  t0: 0,
  start: { x: [0.6062177826491071, 0.1 + 0.2, -0.35000000000000003], v: [-0, 1.2124355652982142, 1e-300] },
  lagging: false,
  frame_fields: [],
  model: 'damped',
  model_params: { damping: 0.1 + 0.2, drag: 0, gravity_z: -1, forcing_phase: -0 },
};

describe('URL round trip', () => {
  it('reproduces every value bit for bit, negative g and awkward floats included', () => {
    const u = fromStatus(status);
    const { value, problems } = decodeUrl(encodeUrl(u));
    expect(problems).toEqual([]);
    expect(value).toEqual(u);
    expect(Object.is(value.v?.[0], -0)).toBe(true);
    expect(value.x?.[1]).toBe(0.1 + 0.2);
    expect(value.g).toBe(-9.81);
    expect(value.model).toBe('damped');
    expect(value.modelParams?.['damping']).toBe(0.1 + 0.2);
    expect(Object.is(value.modelParams?.['forcing_phase'], -0)).toBe(true);
  });

  it('leaves out unreadable model parameters, naming them', () => {
    const { value, problems } = decodeUrl('?model=damped&mp=damping:0.5,drag:x,bad%20name:1,c:1:2');
    expect(value).toEqual({ model: 'damped', modelParams: { damping: 0.5 } });
    expect(problems).toEqual([
      'mp: "drag:x" is not name:number',
      'mp: "bad name:1" is not name:number',
      'mp: "c:1:2" is not name:number',
    ]);
  });

  it('round-trips through a full URL with a leading ?', () => {
    const u: UrlScenario = { length: 1e-3, g: 1e21, method: 'dop853', timeScale: 100 };
    const url = new URL(`http://127.0.0.1:8000/?${encodeUrl(u)}`);
    expect(decodeUrl(url.search).value).toEqual(u);
  });

  it('names unreadable values and leaves them out', () => {
    const { value, problems } = decodeUrl('?l=abc&g=Infinity&x=1,2&v=0,0,0&method=%3Cscript%3E&zz=1&m=2');
    expect(value).toEqual({ mass: 2 });
    expect(problems).toEqual([
      'unknown URL key zz',
      'l = "abc" is not a finite number',
      'g = "Infinity" is not a finite number',
      'method = "<script>" is not a name',
      'x = "1,2" is not three finite numbers',
    ]);
  });

  it('gives the commands that rebuild the scenario, in order, ending with reset (and pause)', () => {
    const cmds = commandsFor(fromStatus(status));
    expect(cmds.map((c) => c.type)).toEqual([
      'load_scenario',
      'set_model',
      'set_params',
      'set_method',
      'set_time_scale',
      'set_state',
      'reset',
      'pause',
      'step',
    ]);
    expect(cmds[8]).toEqual({ type: 'step', n: 24600 }); // the paused time 12.3 s in steps of 0.5 ms
    expect(cmds[1]).toEqual({ type: 'set_model', model: 'damped', params: status.model_params });
    expect(cmds[2]).toEqual({ type: 'set_params', length: 0.7, mass: 2.5, g: -9.81 });
    expect(cmds[5]).toEqual({ type: 'set_state', x: status.start.x, v: status.start.v });
    expect(commandsFor({})).toEqual([]);
  });
});

describe('the whole lab in the link (issue 28)', () => {
  it('carries the view options that differ, the plot, the second pendulum, the language and the paused time', () => {
    const defaults = { trail: true, ruler: false, stereo: 'off', trailSeconds: 10 };
    const view = encodeView({ trail: false, ruler: true, stereo: 'anaglyph', trailSeconds: 10 }, defaults);
    expect(view).toEqual({ trail: false, ruler: true, stereo: 'anaglyph' });
    const u: UrlScenario = { ...fromStatus(status), view, plot: ['theta', 'energy'], lang: 'fr' };
    const own = decodeTwin('own:0.25:2:10');
    if (own !== null) u.twin = own;
    const q = encodeUrl(u);
    expect(q).toContain('view=-trail%2Cruler%2Cstereo%3Aanaglyph');
    const { value, problems } = decodeUrl(q);
    expect(problems).toEqual([]);
    expect(value.view).toEqual(view);
    expect(value.plot).toEqual(['theta', 'energy']);
    expect(value.lang).toBe('fr');
    expect(value.at).toBe(12.3);
    expect(value.twin?.mode).toBe('own');
    expect(value.twin?.length).toBe(0.25);
    expect(value.twin?.mass).toBe(2);
    expect((value.twin?.theta ?? 0) * (180 / Math.PI)).toBeCloseTo(10, 12);
    expect(linkContents(value)).toMatch(/paused at 12\.300 s.*view: −trail, ruler, stereo anaglyph.*plot energy against theta.*second pendulum own:0\.25:2:10.*language fr/);
  });
  it('reads every second pendulum and names what it cannot read', () => {
    expect(decodeTwin('eps:0.5')?.epsilon).toBeCloseTo((0.5 * Math.PI) / 180, 15);
    expect(decodeTwin('method:rk4')?.method).toBe('rk4');
    expect(decodeTwin('damped:0.3')?.damping).toBe(0.3);
    expect(decodeTwin('own:-1:2:10')).toBeNull();
    expect(decodeTwin('fly:1')).toBeNull();
    const bad = decodeUrl('twin=own:1&plot=a&view=x%3Ay%3Az&at=-3');
    expect(bad.problems).toHaveLength(4);
    // a time out of range echoed as it was written (2e6 was shown as 2000000)
    expect(decodeUrl('at=2e6').problems).toEqual(['at = "2e6" is not a time 0 … 1e6 s']);
  });
  it('carries no dt for an adaptive method (its steps are its own; the session dt is only its first)', () => {
    expect(fromStatus(status).dt).toBe(0.0005);
    const u = fromStatus({ ...status, method: 'dop853', adaptive: true });
    expect(u.dt).toBeUndefined();
    expect(encodeUrl(u)).not.toContain('dt=');
    expect(commandsFor(u)).toContainEqual({ type: 'set_method', method: 'dop853' });
  });
  it('does not replay a paused time for an adaptive method or a running lab', () => {
    expect(fromStatus({ ...status, adaptive: true }).at).toBeUndefined();
    expect(fromStatus({ ...status, paused: false }).at).toBeUndefined();
    expect(commandsFor({ ...fromStatus(status), paused: false }).some((c) => c.type === 'step')).toBe(false);
  });
});
