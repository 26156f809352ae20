(function(){const e=document.createElement("link").relList;if(e&&e.supports&&e.supports("modulepreload"))return;for(const s of document.querySelectorAll('link[rel="modulepreload"]'))i(s);new MutationObserver(s=>{for(const r of s)if(r.type==="childList")for(const a of r.addedNodes)a.tagName==="LINK"&&a.rel==="modulepreload"&&i(a)}).observe(document,{childList:!0,subtree:!0});function t(s){const r={};return s.integrity&&(r.integrity=s.integrity),s.referrerPolicy&&(r.referrerPolicy=s.referrerPolicy),s.crossOrigin==="use-credentials"?r.credentials="include":s.crossOrigin==="anonymous"?r.credentials="omit":r.credentials="same-origin",r}function i(s){if(s.ep)return;s.ep=!0;const r=t(s);fetch(s.href,r)}})();const yv=["t","x1","x2","x3","v1","v2","v3","energy","j3","tension","power","a1","a2","a3","pivot1","pivot2","pivot3","taut","error_x"],bv={fields:yv},ud=bv.fields,wv=ud.length,uo=8*wv;function vn(n){const e=ud.indexOf(n);if(e<0)throw new Error(`frame.json lacks the field ${n}`);return e}const Ei={t:vn("t"),x:[vn("x1"),vn("x2"),vn("x3")],v:[vn("v1"),vn("v2"),vn("v3")],energy:vn("energy"),j3:vn("j3"),tension:vn("tension"),power:vn("power"),a:[vn("a1"),vn("a2"),vn("a3")],pivot:[vn("pivot1"),vn("pivot2"),vn("pivot3")],taut:vn("taut"),errorX:vn("error_x")};class vi extends Error{}function Sv(n){if(n.byteLength===0||n.byteLength%uo!==0)throw new vi(`a frame message has a multiple of ${uo} bytes, got ${n.byteLength}`);const e=new DataView(n),t=n.byteLength/uo,i=[];for(let s=0;s<t;s++){const r=s*uo,a=l=>e.getFloat64(r+8*l,!0),o=l=>[a(l[0]),a(l[1]),a(l[2])];i.push({t:a(Ei.t),x:o(Ei.x),v:o(Ei.v),energy:a(Ei.energy),j3:a(Ei.j3),tension:a(Ei.tension),power:a(Ei.power),a:o(Ei.a),pivot:o(Ei.pivot),taut:a(Ei.taut)!==0,errorX:a(Ei.errorX)})}return i}function Zl(n){return typeof n=="object"&&n!==null&&!Array.isArray(n)}function Mv(n){let e;try{e=JSON.parse(n)}catch(t){throw new vi(`notice is not JSON: ${String(t)}`)}if(!Zl(e))throw new vi("notice is not a JSON object");if(e.type==="error"&&typeof e.message=="string"){const t=typeof e.command=="string"?e.command:null,i={type:"error",message:e.message,command:t},s=e.values;return typeof e.key=="string"&&Zl(s)&&Object.values(s).every(r=>typeof r=="string"||typeof r=="number")&&(i.key=e.key,i.values=s),i}if(e.type==="status"){const t=e.params;if(!Zl(t)||typeof e.epoch!="number"||typeof e.method!="string")throw new vi("status notice lacks epoch, method or params");const i=e.frame_fields;if(Array.isArray(i)&&i.join(",")!==ud.join(","))throw new vi(`server frame layout ${i.join(",")} differs from the page's`);return e}if(e.type==="event")return Ev(e);throw new vi(`unknown notice type ${JSON.stringify(e.type)}`)}function jl(n){return typeof n=="number"&&Number.isFinite(n)}function Ev(n){const{kind:e,t,energy_lost:i,x:s,epoch:r}=n,a=n.skipped??0;if(e!=="slack"&&e!=="taut")throw new vi(`event notice: kind ${JSON.stringify(e)} is not "slack" or "taut"`);if(!jl(t))throw new vi("event notice: t is not a finite number");if(!jl(i)||i<0)throw new vi("event notice: energy_lost is not a finite number ≥ 0");if(!Array.isArray(s)||s.length!==3||!s.every(jl))throw new vi("event notice: x is not 3 finite numbers");if(!Number.isInteger(r)||!Number.isInteger(a)||a<0)throw new vi("event notice: epoch or skipped is not an integer");return{type:"event",kind:e,t,energy_lost:i,x:[s[0],s[1],s[2]],epoch:r,skipped:a}}async function Av(){return"server"}function Tv(n){return new WebSocket(n)}function Xc(n){const e=n.protocol==="https:"?"wss:":"ws:",t=n.pathname.endsWith("/")?n.pathname:n.pathname.replace(/[^/]*$/,"");return`${e}//${n.host}${t}ws`}function $c(n,e,t,i=20){const s=Date.now()+t;return new Promise(r=>{const a=()=>{(n()??-1)>=e()?r(!0):Date.now()>=s?r(!1):setTimeout(a,i)};a()})}class dd{constructor(e,t){this.url=e,this.handlers=t,this.open()}url;handlers;sent=0;ws=null;retryMs=500;closedByUs=!1;open(){const e=Tv(this.url);e.binaryType="arraybuffer",e.onopen=()=>{this.retryMs=500,this.sent=0,this.handlers.onOpen()},e.onmessage=t=>{try{t.data instanceof ArrayBuffer?this.handlers.onFrames(Sv(t.data)):typeof t.data=="string"&&this.handlers.onNotice(Mv(t.data))}catch(i){if(i instanceof vi)this.handlers.onProtocolError(i.message);else throw i}},e.onclose=()=>{this.ws=null,this.handlers.onClose(),this.closedByUs||(setTimeout(()=>this.open(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))},this.ws=e}get isOpen(){return this.ws!==null&&this.ws.readyState===1}send(e){return!this.isOpen||this.ws===null?!1:(this.ws.send(JSON.stringify(e)),this.sent++,!0)}close(){this.closedByUs=!0,this.ws?.close()}}const Rv={"page.title":"Pendulab lab — the spherical pendulum","page.units":"SI units, z up","page.scene":"3-D view of the pendulum (drag to orbit, scroll to zoom)","page.panel":"controls and measurements","page.skip":"Skip to controls","page.software":"software WebGL: no antialiasing","conn.connected":"connected","conn.retrying":"disconnected: retrying…","conn.gone":"The lab’s server is not answering: the pendulum has stopped. Is pendulab serve still running? Trying to reconnect …","conn.noStart":"The lab could not start:","toolbar.label":"run controls","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Reset","toolbar.stepShort":"Step","toolbar.recordShort":"● Record","toolbar.recordStopShort":"■ Stop","toolbar.start":"start (Space)","toolbar.pause":"pause (Space)","toolbar.reset":"reset to the start (R)","toolbar.step":"one step (S)","toolbar.record":"record a video (WebM)","toolbar.recordStop":"stop recording and download the video","toolbar.help":"keyboard shortcuts and colour key (?)","toolbar.present":"presentation mode: large type for a projector","toolbar.language":"language","toolbar.collapse":"hide the panel","toolbar.expand":"show the panel","gui.title":"Pendulab lab","gui.pendulum":"Pendulum","gui.model":"model","gui.modelParams":"{model}: parameters","gui.paramHelp":"{help} — key {name} [{unit}]; allowed: {range}; default {default}","gui.integrator":"Integrator","gui.method":"method","gui.order":"order {n}","gui.symplectic":"symplectic","gui.adaptive":"adaptive","method.rk4":"Runge–Kutta, 4th order (classic; drifts off the sphere)","method.dop853":"Adaptive, very accurate (Dormand–Prince, 8th order)","method.rattle":"Symplectic (RATTLE, 2nd order; the default)","method.rattle4":"Symplectic (RATTLE, 4th order)","method.rattle6":"Symplectic (RATTLE, 6th order)","method.rattle8":"Symplectic (RATTLE, 8th order)","method.rkmk4":"Rotation steps on the sphere (Munthe-Kaas, 4th order)","method.rk4_angles":"Runge–Kutta 4 in angles (breaks down at the poles)","method.other":"{name} (order {n})","kind.generic":"goes round and round in a rosette","kind.conical":"circles at one height (conical pendulum)","kind.planar":"swings to and fro in a plane","kind.planar_rotating":"swings over the top in a plane","kind.separatrix":"creeps towards the top for ever","kind.rest":"at rest","kind.great_circle":"goes round a great circle (no gravity)","data.energy":"energy E","data.energyChange":"energy change E − E₀","data.spin":"angular momentum about the vertical J₃","data.spinChange":"its change J₃ − J₃(0)","data.height":"height z","data.turning":"lowest and highest height z₁, z₂","gui.dtRange":"dt must be between {min} and {max} s","gui.dtHelp":"step size of fixed-step methods; {min} … {max} s (dop853 chooses its own)","gui.run":"Run","gui.timeScale":"time scale [×]","gui.tsRange":"the time scale must be between {min} and {max}","gui.tsHelp":"simulated seconds per second (slow motion below 1); {min} … {max}","gui.stepN":"steps per step","gui.scenario":"scenario","gui.view":"View","gui.trail":"trail","gui.trailSeconds":"trail [s]","gui.sphere":"sphere of reach","gui.axes":"axes","gui.topView":"top view","gui.stereo":"stereo","gui.stereoHelp":"anaglyph: red–cyan glasses; side by side: a stereo viewer","stereo.off":"off","stereo.anaglyph":"anaglyph","stereo.sideBySide":"side by side","gui.vectors":"Vectors","gui.origin":"origin {axis} [m]","gui.originHelp":"origin of L and τ relative to the pivot (0: the pivot)","gui.export":"Share and export","gui.csv":"download trajectory (CSV)","gui.toml":"download scenario (TOML)","gui.tomlHelp":"the scenario as it stands (model, parameters, start, method) as a file for `pendulab run`","gui.png":"screenshot (PNG)","gui.link":"copy link to this lab (what it carries: on copying)","vec.velocity":"velocity v","vec.velocityHelp":"v [m/s], drawn as 0.25 s of travel","vec.momentum":"momentum m v","vec.momentumHelp":"m v [kg m/s], 0.25 m per kg m/s","vec.gravity":"gravity m g","vec.gravityHelp":"the weight m g d [N] (d: the gravity direction); forces: m·max(|g|, 1) N ↔ 0.5 l","vec.tension":"rod force (tension)","vec.tensionHelp":"the rod force −T x/|x| [N], T from the server","vec.net":"net force m a","vec.netHelp":"m a [N]: a = ẍ computed by the server’s core (relative to the pivot)","vec.angularMomentum":"angular momentum L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] about the origin o, drawn from o","vec.torque":"torque τ","vec.torqueHelp":"τ = (x − o) × m a [N m] about the origin o, drawn from o; dL/dt = τ","data.now":"Now (from the server)","data.exact":"Exact solution of this orbit","data.tension":"tension","data.tensionMin":"tension min","data.tensionMax":"tension max","data.method":"method","data.state":"state","data.paused":"paused","data.running":"running","data.lagging":" (lagging: slower than asked)","data.model":"model","data.kind":"kind of motion","data.periodZ":"z-period T_z","data.swingPeriod":"swing period T","data.advance":"azimuthal advance Δφ per T_z","data.rotation":"rotation number W = Δφ/2π","data.reduced":"reduced view (σ₁, σ₂, σ₃): J₃ surface ∩ energy plane","portrait.phase":"phase portrait: vertical speed ż against height z","portrait.veff":"effective potential V_eff(θ); energy E dashed, θ now dotted","portrait.em":"energy–momentum map: E against J₃ (dot: now)","portrait.orbit":"orbit","portrait.emBoundary":"boundary (conical orbits)","note.spring":"the swinging spring leaves the sphere (its length varies): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.string":"the string goes slack (free flight inside the sphere): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.exactIdeal":"the exact solution exists for the ideal pendulum only; this is the model “{model}”","note.reducedIdeal":"the reduced view is the ideal pendulum’s; this is the model “{model}”","note.phasesPlanar":"no phases: they split the turn of an orbit that goes round the vertical; this orbit {kind}","note.phasesNoGravity":"no phases: without gravity the bob goes round a great circle at constant speed, with nothing to split","event.slack":"the string went slack (tension 0: free flight)","event.taut":"the string snapped taut, lost {lost} J","event.skippedOne":" ({n} earlier event of this moment not shown)","event.skippedMany":" ({n} earlier events of this moment not shown)","event.slackRow":"went slack","event.tautRow":"snapped taut","event.tautValue":"t = {t} s, lost {lost}","data.power":"power P = dE/dt","data.springForce":"spring force k(|r| − l₀)","data.springLength":"spring length |r|","data.stretch":"stretch |r| − l₀","data.string":"string","data.slackZero":"slack (0)","data.slack":"slack: free flight, |x| = {r} m","data.taut":"taut","data.events":"events","data.noEvents":"none yet (slack, snaps)","data.z3":"z₃ (outside)","data.dynamic":"Δφ dynamic","data.geometric":"Δφ geometric","data.error":"position error |Δx|","data.errorRel":"position error / l","data.errorHow":"error obtained by","data.errorPaused":"estimate paused (the server’s work budget is used up; it catches up when there is time)","data.errorNone":"no estimate","data.errorCrane":"no estimate: the crane mode runs its own integrator (DOP853) at the session’s tolerances","data.howExact":"the true error: against the exact solution (since t = {since} s)","data.howRichardson":"estimate: Richardson against a companion at dt/2 = {dt} s, order p = {p} (since t = {since} s)","data.howCompanion":"estimate: a companion run at rtol = {rtol} (since t = {since} s)"},Cv={"page.softwareHelp":"{renderer}: drawn without multisampling for the frame rate","tools.start":"Start angle","tools.thetaHelp":"θ₀: the angle from the downward vertical, in degrees (0 … 180)","tools.phiHelp":"φ₀: the azimuth around the vertical, in degrees","tools.phiDotHelp":"φ̇₀: how fast the bob starts going round, in degrees per second (0: a planar swing)","tools.setStart":"set start","tools.world":"Gravity and friction","tools.gravity":"gravity","tools.friction":"friction","tools.frictionHelp":"linear damping c [1/s]: the force −m c v; on the ideal pendulum it switches to the damped model","tools.noFriction":"the model “{model}” has no friction parameter","tools.now":"Angles now","tools.stopwatch":"Stopwatch (simulated time)","tools.swStart":"start","tools.swStop":"stop","tools.swLap":"lap","tools.swReset":"reset","tools.period":"Period timer","tools.periodHelp":"measured from the motion: the lowest points of the bob; a swing’s period ends when the bob passes the bottom again the same way. Compared with the exact value (ideal pendulum) or the theory (small-swing formula with friction)","tools.periodCount":"mean over {n} periods","tools.periodCountZ":"mean over {n} lowest-to-lowest times","tools.periodWait":"waiting for the bob to pass its lowest point twice","tools.motion":"motion","tools.kindNone":"—","tools.kindSwing":"swings to and fro","tools.kindOver":"swings over the top","tools.kindOrbit":"goes round (never through the bottom)","tools.periodSwing":"period T [s]","tools.periodZ":"lowest point to lowest point [s]","tools.advance":"turn between lowest points [°]","tools.precession":"pattern turns per round [°]","tools.amplitude":"amplitude (largest angle) [°]","tools.band":"angle from the vertical [°]","tools.theory":"theory","tools.measured":"measured","tools.exact":"exact","tools.difference":"difference","tools.overlays":"Ruler and protractor","tools.ruler":"ruler (metres)","tools.protractor":"protractor (θ in degrees)","gloss.title":"Words (glossary)","gloss.advanced":"show formula numbers and extra rows (advanced)","gloss.period":"period T","gloss.periodText":"the time for one whole swing: from one side to the other and back, until the bob passes the bottom again the same way. Measured in seconds.","gloss.amplitude":"amplitude","gloss.amplitudeText":"the largest angle between the rod and the vertical during a swing. With friction it gets smaller swing by swing.","gloss.lowest":"lowest point","gloss.lowestText":"where the bob is lowest in a swing. A swing passes through the very bottom; a bob going round passes its lowest point beside it.","gloss.friction":"friction (damping)","gloss.frictionText":"a force against the motion that takes energy out, so the swings die away. The number c says how strong it is (per second).","gloss.gravity":"gravity g","gloss.gravityText":"how strongly the planet pulls: 9.81 m/s² on Earth, 1.62 on the Moon. A stronger pull makes the pendulum swing faster.","gloss.energy":"kinetic and potential energy","gloss.energyText":"kinetic energy is energy of motion (fast bob: much); potential energy is energy of height (high bob: much). They turn into each other as the bob swings; friction takes some away.","gloss.spin":"angular momentum J₃","gloss.spinText":"how much the bob goes round the vertical. Zero for a swing in a plane; it stays the same for the ideal pendulum.","gloss.precession":"precession","gloss.precessionText":"a bob going round does not close its path: the pattern turns a little every round, and the top view becomes a rosette.","gloss.method":"method (integrator)","gloss.methodText":"the way the computer works out the motion in small time steps. Symplectic methods keep the energy right for a long time; others drift.","gloss.drift":"energy drift","gloss.driftText":"how far the computed energy has wandered from where it started. For the ideal pendulum it should stay zero; what is left is the computer’s rounding.","tools.moveGroup":"move the {what}","tools.moveLeft":"move left","tools.moveRight":"move right","tools.moveUp":"move up","tools.moveDown":"move down","tools.moveBack":"back to its place","describe.none":"no motion yet","describe.text":"angle {theta}° from the vertical, {dir}, speed {v} m/s","describe.rest":"at rest","describe.turning":"at a turning point","describe.rising":"rising","describe.falling":"falling towards the bottom","describe.energy":"; energy {k} % kinetic, {u} % potential","describe.lost":", {p} % lost to friction","describe.toggle":"describe the motion every 5 s (screen readers; D: now)","tools.sound":"sound: a tone at each lowest point (higher when faster)","tools.mystery":"mystery planet (find g from the period)","tools.reveal":"reveal g","tools.mysteryOn":"a mystery planet: time the swings and work out g = 4π² l / T²","tools.revealed":"the mystery planet’s g is {g} m/s²","start.notNumber":"{name} must be a number","start.thetaRange":"θ₀ = {value}° is not allowed: 0 … 180°","gravity.custom":"custom","gravity.earth":"Earth","gravity.moon":"Moon","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"zero","gravity.negative":"negative (upwards)","energy.title":"Energy","energy.kinetic":"kinetic","energy.potential":"potential","energy.lost":"lost","energy.total":"total","plot.dE":"energy drift |ΔE|/E_s (log)","plot.dJ3":"J₃ drift |ΔJ₃|/J_s (log)","plot.z":"height z(t)","plot.tension":"rod tension T(t)","plot.time":"time t [s]","plot.floor":"float64 roundoff 2.2e-16","alt.empty":"no data yet","alt.summary":"{y} from {yLo} to {yHi} against {x} from {xLo} to {xHi}; now {yNow} at {xNow}","chosen.title":"Plot any variables","chosen.xAxis":"across","chosen.yAxis":"up","var.t":"time t","var.theta":"angle θ","var.phi":"azimuth φ","var.x":"x","var.y":"y","var.z":"height z","var.zdot":"vertical speed ż","var.speed":"speed |v|","var.energy":"energy E","var.kinetic":"kinetic energy K","var.potential":"potential energy U","var.j3":"angular momentum J₃","var.tension":"tension T","var.power":"power P","var.radius":"distance |x|"},Pv={"twin.title":"Two pendulums","twin.mode":"second pendulum","twin.off":"off","twin.epsilon":"start differs by ε","twin.method":"another integrator","twin.damped":"damped beside this one","twin.own":"its own length, mass and start (side by side)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"pendulum {n} needs a length > 0, a mass > 0 and a start angle 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"period T [s] (periods)","twin.methodPick":"integrator","twin.damping":"damping [1/s]","twin.start":"start both","twin.badEpsilon":"ε must be a number (degrees)","twin.badDamping":"the damping must be a number ≥ 0 (1/s)","twin.first":"pendulum 1","twin.second":"pendulum 2","twin.separation":"separation of the bobs |r₁ − r₂| [m]","help.title":"Keyboard shortcuts and colour key","help.space":"start / pause","help.r":"reset to the start","help.s":"one step (paused)","help.arrows":"on a focused slider: one step down / up","help.page":"on a focused slider: ten steps","help.camera":"on the 3-D view: turn the camera / zoom","help.bobKeys":"on the 3-D view: move the bob’s start by 1° (pauses)","help.describe":"describe the motion now (screen readers)","help.tab":"move between controls","help.help":"this overlay","help.esc":"close this overlay","help.colours":"Colours","help.close":"close","help.bob":"bob","help.trail":"trail","help.twin":"second pendulum","help.ruler":"ruler and protractor","msg.notConnected":"not connected to the server","msg.veffFailed":"the effective potential: {why}","msg.emFailed":"the energy–momentum map: {why}","msg.downloadFailed":"the scenario download: {why}","msg.linkProblems":"the link’s values left out: {what}","url.unknownKey":"unknown URL key {key}","url.notName":"{key} = {value} is not a name","url.notNumber":"{key} = {value} is not a finite number","url.notThree":"{key} = {value} is not three finite numbers","url.notPair":"mp: {value} is not name:number","url.startXv":"the start needs both x and v","url.notTime":"at = {value} is not a time 0 … 1e6 s","url.notView":"view: {value} is not a view option","url.notPlot":"plot = {value} is not two variable names","url.notTwin":"twin = {value} is not own:l:m:θ₀, eps:ε, method:name or damped:c","link.scenario":"the scenario (model, parameters, method, start)","link.paused":"paused","link.pausedAt":"paused at {t} s","link.view":"view: {list}","link.plot":"plot {y} against {x}","link.twin":"second pendulum {what}","link.lang":"language {lang}","msg.linkCopied":"link copied; it carries {what}","msg.dragged":"start set by dragging (at rest there): press start to release it","msg.pull":"pull the arrow to set the start velocity","msg.capped":" (capped: the most the arrow sets, 4√(g l))","msg.velocitySet":"start velocity set: |v| = {v} m/s{cap}; press start to run from it","msg.velocity":"start velocity |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} is not allowed: {allowed} ({range})","msg.recording":"recording the view…","msg.recorded":"video saved ({mb} MB, WebM)","msg.noRecording":"this browser cannot record the view ({why})","fit.title":"Measured data","fit.load":"Load measured data…","fit.help":"a CSV file of measurements in SI units (columns t, x, y, z or x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): the server fits the pendulum to it, loads the fitted motion and draws the measured path dotted beside it","fit.model":"model","fit.params":"fit","fit.paramsDefault":"what the data determine","fit.paramsHelp":"the parameters to fit, comma separated (e.g. length,g,damping,pivot); empty: what the data can determine","fit.clear":"clear measured path","fit.running":"fitting {name} …","fit.noPath":"(frame-free data: no measured path to draw)","fit.failed":"fit: {why}","fit.loaded":"fitted {name}: the fitted motion is loaded, the measured path dotted in gold","page.tools":"measuring tools","page.energy":"energy bar chart","page.data":"data panel","page.plots":"live plots","page.portraits":"phase portrait, effective potential, energy–momentum map","page.reduced":"reduced view in σ-space","gui.modelsHelp":"the models (code name in brackets):","fit.summary":"{model}: {state}","fit.converged":"the fit converged","fit.notConverged":"the fit did not converge","fit.notDetermined":"(not determined by these data)","fit.fullReport":"the fit’s full report (as pendulab fit prints it, in English)"},Lv={"server.too_small":"{name} = {value}: at least {limit} allowed","server.too_small_strict":"{name} = {value}: must be more than {limit}","server.too_large":"{name} = {value}: at most {limit} allowed","server.too_large_strict":"{name} = {value}: must be less than {limit}","server.missing":"{name} is missing","server.unknown_key":"unknown key {name}","server.nonfinite_motion":"the motion left floating point at t = {t} s ({fields} not finite): parameters or a start this extreme; paused — reset, or change the parameters","server.integration_stopped":"the computation stopped ({detail}); paused","server.throttled":"throttled: {lost} command(s) dropped; send at most {per_second} per second","server.server_full":"the server is full: {active} lab sessions are open, the most it serves at once; close another tab or try again later","server.device_full":"too many lab sessions from your device: {have} are open, the most one device may have; close another tab","server.device_busy":"too many computations at once from your device: at most {most} may run or wait for one device; wait for the answers, then try again","server.step_too_small":"the step size became too small at t = {t} s (h = {h} s): the motion changes too fast for the tolerances","server.diverged":"the integration diverged after t = {t} s with method {method} (dt = {dt} s): reduce dt, or choose an adaptive (dop853) or structure-preserving (rattle) method","server.diverged_rattle":"the integration diverged after t = {t} s with method {method} (dt = {dt} s): reduce dt (the step must resolve the fastest motion, dt·ω ≪ 1)","server.diverged_dop853":"the integration diverged after t = {t} s with method {method} (dt = {dt} s): lower rtol and atol, or choose the structure-preserving rattle","server.diverged_dt":"the integration diverged after t = {t} s with method {method} (dt = {dt} s): reduce dt","server.near_pole":"the computation reached a pole (the pendulum straight up or down) at t = {t} s, where these equations fail: use a Cartesian method","server.not_finite":"{name}[{index}] = {value} is not a finite number","server.off_sphere":"the start is not on the sphere: {what} = {value} exceeds the tolerance {tolerance}","server.invalid_parameter":"{name} = {value} is not allowed: {allowed}","server.unknown_model":"unknown model {model}; available: {available}","server.not_lab_model":"model {model} does not run in the lab (use pendulab run); the lab's models: {available}","server.unknown_parameter":"the {model} model has no parameter {name}; its parameters: {available}","server.no_parameters":"the {model} model has no parameter {name}; it has none besides length, mass, g","server.still_stepping":"still stepping: {waiting} steps are waiting to be taken (at most {most}); wait for the frame, or pause","server.method_not_for_spring":"method {method} cannot run the {model} model (it leaves the sphere: rattle runs Störmer–Verlet (order 2), rattle4 its triple jump (order 4)); use one of {available}","server.method_not_for_string":"method {method} cannot run the {model} model (its taut phases need a fixed-step method that keeps TS²); use one of {available}","server.method_not_for_crane":"method {method} cannot run the {model} model (the crane mode steps its load with the crane integrator, adaptive DOP853 with projection onto the rope); use {available}","server.not_crane":"not in the crane mode (the lab runs the {model} model): switch it on first with the button “Crane mode”","server.internal_error":"internal error of the server (a fault of the software: please report it); details: {detail}","server.busy":"busy: {waiting} computations are waiting; try again in a moment","server.work_timeout":"the computation took longer than {seconds} s and was stopped; try fewer data, fewer parameters or a simpler model","server.not_json":"the request is not JSON","server.out_of_memory":"the request needs more memory than the server has for it","server.worker_died":"the server's worker for this computation stopped (exit code {code}); the request may need more memory than the server has","server.data_too_many_rows":"{file}: {rows} lines of data; at most {most} samples are fitted: thin the data","server.data_not_number":"{file}: row {row} (line {line}), column {column}: {cell} is not a number","server.data_cell_infinite":"{file}: row {row} (line {line}), column {column}: {cell} is infinite or too large for a number","server.data_cell_subnormal":"{file}: row {row} (line {line}), column {column}: {cell} is so close to 0 that it is no measurement: write 0","server.data_cell_beyond":"{file}: row {row} (line {line}), column {column}: {cell} is beyond ±{limit} {unit}: check the column's unit","server.data_times_too_close":"{file}: row {row} (line {line}), column {column}: {cell} is only {step} s from another time; samples closer than {most} s cannot be told apart","server.data_row_short":"{file}: row {row} (line {line}) has {have} values; the columns used need {need}","server.data_long_line":"{file}: line {line} is {chars} characters long and not a row of numbers; a header row may have at most {most}","server.data_no_rows_in_first":"{file}: no row of numbers in the first {lines} lines: is this a data file?","server.data_no_rows":"{file}: no rows of numbers","server.data_linear_acceleration":"{file}: column {column} is a linear acceleration (the phone removed gravity); the fit needs the acceleration with gravity (e.g. phyphox 'Acceleration with g')","server.data_pixels":"{file}: column {column} is in pixels; scale it to metres first (a ruler of known length in the video gives metres per pixel)","server.data_bad_unit":"{file}: column {column} has the unit {unit}; allowed are {allowed}","server.data_no_time":"{file}: no time column t among the columns {columns}: name the columns in the file's first row (t, x, y, z, theta, phi, angle …)","server.data_repeated_columns":"{file}: the column(s) {repeated} appear more than once among {columns} (several tracks or runs in one file?): keep one","server.data_no_header":"{file}: the file has no row of column names: write them above the numbers (e.g. t,x,y,z)","server.data_unknown_columns":"{file}: unknown column name(s) {unknown}; use {allowed}","server.data_components":"{file}: {kind} needs all three components {parts}; found only {found}","server.data_positions_alone":"{file}: the position column(s) {have} alone; positions are x, y, z, or x, z (a camera from the side), or x, y (seen from above)","server.data_crane_run":"{file}: a crane run (pendulab crane run --out) with the columns {columns}: its payload hangs from a moving trolley, maybe below a hook and on a hoisted rope, which none of the fit's models (a fixed pivot) describes. A fit needs a pendulum's t, x, y, z as {command} writes them; for a crane's sway after the move, write t and the payload's offset from the pivot (payload_x - pivot_x, payload_y - pivot_y) as t,x,y","server.data_crane_grid":"{file}: a crane grid (pendulab crane grid --out) with the columns {columns}: one row per case, no time series to fit. A fit needs a pendulum's t, x, y, z as {command} writes them","server.data_no_columns":"{file}: no data columns among {columns}: name them t, x, y, z, theta, phi or angle (docs/fit.md)","server.data_too_few":"only {have} usable samples: a fit needs at least {need}","server.data_time_twice":"the time t = {t} s appears twice: every sample needs its own time","server.data_theta_range":"the angle θ from the vertical must lie between 0 and π rad; the data go from {lo} to {hi}: degrees instead of radians?","server.data_value_beyond":"{kind} in row {row} (sorted by time): {value} is beyond ±{limit} in SI units; a pendulum's measurement never is: check the file's units and columns","server.data_span":"the record lasts {span} s; a fit needs {least} s to {most} s (times in seconds?)","server.data_spacing":"the times {t1} s and {t2} s are only {gap} s apart: rounding, not a measurement","server.data_not_csv":"{file}: not a readable CSV file","server.fit_unknown_model":"model {model}: use one of {allowed}","server.fit_cannot_fit":"{param} cannot be fitted with the {model} model; choose from {allowed}","server.fit_planar_phi":"a swing in one plane keeps the sideways angle and speed at 0: do not fit them","server.fit_pivot_needs_positions":"the pivot's position is fitted from positions only; these data have none","server.fit_t_offset_ideal":"t_offset is fitted for the ideal pendulum only","server.fit_failed":"the fit of {file} failed: the data hold values the fit cannot follow in floating point (times or positions extremely far apart or close together, or a noise far from the data's scale)"},Dv={"scenario.conical":"Conical pendulum at 45°","scenario.damped":"Damped rosette (c = 0.05 1/s)","scenario.foucault":"Foucault pendulum at 49° N, Earth’s rotation exaggerated (Ω = 0.02 rad/s)","scenario.inverted_g":"Inverted gravity: the rosette mirrored","scenario.near_top":"Released just below the top","scenario.over_the_top":"Over the top: planar revolutions","scenario.planar_large":"Planar swing of amplitude 150°","scenario.rosette":"Rosette: 60° release with sideways spin","scenario.crane_hoist":"Gantry crane: ZV-shaped 8 m move while hoisting 12 m -> 6 m, in a cross wind","scenario.slewing_crane":"Slewing crane: R = 5 m, ω = 0.3 rad/s, l = 10 m","scenario.small_ellipse":"Small ellipse with Airy precession","scenario.string_slack":"String pendulum: slack at z = l/2, inelastic snap","scenario.swinging_spring":"Swinging spring at the 1:1:2 resonance","scenario.zero_g":"Zero gravity: a great circle","modelHelp.ideal":"a rod without friction: the textbook pendulum","modelHelp.damped":"with friction, air drag or a periodic push","modelHelp.rotating":"seen from the turning Earth: the swing plane turns (Foucault)","modelHelp.slewing":"hanging from the boom of a turning crane","modelHelp.vibrating":"the pivot shaken up and down: it can stand upside down (Kapitza)","modelHelp.sampled_pivot":"the pivot moves along a given path","modelHelp.spring":"a spring instead of a rod: it swings and bounces","modelHelp.string":"a string instead of a rod: it can go slack and snap taut","key.space":"Space","key.page":"Page ↑ / Page ↓","key.shift":"Shift","toolbar.simpleShort":"Simple","toolbar.simple":"simple view: only the classroom tools (length, mass, gravity, friction, stopwatch, period, ruler, energy); press again for everything","extras.add":"+ another pendulum (own length, mass, start)","extras.pendulum":"pendulum {n}","extras.remove":"remove pendulum {n}","extras.title":"Up to four pendulums","extras.hint":"With the second pendulum on “its own length, mass and start”: add pendulums 3 and 4, then “start both” starts all, each timed by its own period timer."},Fs={...Rv,...Cv,...Pv,...Lv,...Dv},Nv={"page.title":"Pendulab-Labor — das Kugelpendel","page.units":"SI-Einheiten, z nach oben","page.scene":"3-D-Ansicht des Pendels (ziehen zum Drehen, scrollen zum Zoomen)","page.panel":"Steuerung und Messungen","page.skip":"Zur Steuerung springen","page.software":"Software-WebGL: ohne Kantenglättung","conn.connected":"verbunden","conn.retrying":"getrennt: neuer Versuch…","conn.gone":"Der Server des Labors antwortet nicht: das Pendel steht. Läuft pendulab serve noch? Neuer Verbindungsversuch …","conn.noStart":"Das Labor konnte nicht starten:","toolbar.label":"Ablauf","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Zurück","toolbar.stepShort":"Schritt","toolbar.recordShort":"● Aufnahme","toolbar.recordStopShort":"■ Stopp","toolbar.start":"Start (Leertaste)","toolbar.pause":"Pause (Leertaste)","toolbar.reset":"zurück zum Start (R)","toolbar.step":"ein Schritt (S)","toolbar.record":"Video aufnehmen (WebM)","toolbar.recordStop":"Aufnahme beenden und Video speichern","toolbar.help":"Tastenkürzel und Farben (?)","toolbar.present":"Präsentationsmodus: große Schrift für einen Beamer","toolbar.language":"Sprache","toolbar.collapse":"Leiste ausblenden","toolbar.expand":"Leiste einblenden","gui.title":"Pendulab-Labor","gui.pendulum":"Pendel","gui.model":"Modell","gui.modelParams":"{model}: Parameter","gui.paramHelp":"{help} — Schlüssel {name} [{unit}]; erlaubt: {range}; Vorgabe {default}","gui.integrator":"Integrator","gui.method":"Verfahren","gui.order":"Ordnung {n}","gui.symplectic":"symplektisch","gui.adaptive":"adaptiv","method.rk4":"Runge–Kutta, 4. Ordnung (klassisch; verlässt die Kugel)","method.dop853":"Adaptiv, sehr genau (Dormand–Prince, 8. Ordnung)","method.rattle":"Symplektisch (RATTLE, 2. Ordnung; Voreinstellung)","method.rattle4":"Symplektisch (RATTLE, 4. Ordnung)","method.rattle6":"Symplektisch (RATTLE, 6. Ordnung)","method.rattle8":"Symplektisch (RATTLE, 8. Ordnung)","method.rkmk4":"Drehschritte auf der Kugel (Munthe-Kaas, 4. Ordnung)","method.rk4_angles":"Runge–Kutta 4 in Winkeln (versagt an den Polen)","method.other":"{name} ({n}. Ordnung)","kind.generic":"kreist in einer Rosette","kind.conical":"kreist in einer Höhe (Kegelpendel)","kind.planar":"schwingt in einer Ebene hin und her","kind.planar_rotating":"schwingt in einer Ebene über den höchsten Punkt","kind.separatrix":"kriecht für immer auf den höchsten Punkt zu","kind.rest":"in Ruhe","kind.great_circle":"läuft auf einem Großkreis (ohne Schwerkraft)","data.energy":"Energie E","data.energyChange":"Energieänderung E − E₀","data.spin":"Drehimpuls um die Senkrechte J₃","data.spinChange":"seine Änderung J₃ − J₃(0)","data.height":"Höhe z","data.turning":"tiefste und höchste Höhe z₁, z₂","gui.dtRange":"dt muss zwischen {min} und {max} s liegen","gui.dtHelp":"Schrittweite der Verfahren mit festem Schritt; {min} … {max} s (dop853 wählt selbst)","gui.run":"Ablauf","gui.timeScale":"Zeitfaktor [×]","gui.tsRange":"der Zeitfaktor muss zwischen {min} und {max} liegen","gui.tsHelp":"simulierte Sekunden pro Sekunde (Zeitlupe unter 1); {min} … {max}","gui.stepN":"Schritte pro Schritt","gui.scenario":"Szenario","gui.view":"Ansicht","gui.trail":"Spur","gui.trailSeconds":"Spur [s]","gui.sphere":"Kugel der Reichweite","gui.axes":"Achsen","gui.topView":"Draufsicht","gui.stereo":"Stereo","gui.stereoHelp":"Anaglyphe: Rot-Cyan-Brille; nebeneinander: ein Stereobetrachter","stereo.off":"aus","stereo.anaglyph":"Anaglyphe (Rot–Cyan)","stereo.sideBySide":"nebeneinander","gui.vectors":"Vektoren","gui.origin":"Ursprung {axis} [m]","gui.originHelp":"Ursprung von L und τ relativ zum Aufhängepunkt (0: der Aufhängepunkt)","gui.export":"Teilen und exportieren","gui.csv":"Bahn herunterladen (CSV)","gui.toml":"Szenario herunterladen (TOML)","gui.tomlHelp":"das Szenario, wie es ist (Modell, Parameter, Start, Verfahren), als Datei für `pendulab run`","gui.png":"Bildschirmfoto (PNG)","gui.link":"Link zu diesem Labor kopieren (was er enthält: beim Kopieren)","vec.velocity":"Geschwindigkeit v","vec.velocityHelp":"v [m/s], gezeichnet als Weg in 0,25 s","vec.momentum":"Impuls m v","vec.momentumHelp":"m v [kg m/s], 0,25 m pro kg m/s","vec.gravity":"Gewichtskraft m g","vec.gravityHelp":"die Gewichtskraft m g d [N] (d: Richtung der Schwerkraft); Kräfte: m·max(|g|, 1) N ↔ 0,5 l","vec.tension":"Stangenkraft (Zugkraft)","vec.tensionHelp":"die Stangenkraft −T x/|x| [N], T vom Server","vec.net":"Gesamtkraft m a","vec.netHelp":"m a [N]: a = ẍ vom Kern des Servers berechnet (relativ zum Aufhängepunkt)","vec.angularMomentum":"Drehimpuls L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] um den Ursprung o, von o aus gezeichnet","vec.torque":"Drehmoment τ","vec.torqueHelp":"τ = (x − o) × m a [N m] um den Ursprung o, von o aus gezeichnet; dL/dt = τ","data.now":"Jetzt (vom Server)","data.exact":"Exakte Lösung dieser Bahn","data.tension":"Zugkraft","data.tensionMin":"Zugkraft min","data.tensionMax":"Zugkraft max","data.method":"Verfahren","data.state":"Zustand","data.paused":"angehalten","data.running":"läuft","data.lagging":" (hinkt nach: langsamer als verlangt)","data.model":"Modell","data.kind":"Art der Bewegung","data.periodZ":"z-Periode T_z","data.swingPeriod":"Schwingungsdauer T","data.advance":"Azimutvorschub Δφ pro T_z","data.rotation":"Umlaufzahl W = Δφ/2π","data.reduced":"reduzierte Ansicht (σ₁, σ₂, σ₃): J₃-Fläche ∩ Energieebene","portrait.phase":"Phasenporträt: Vertikalgeschwindigkeit ż gegen Höhe z","portrait.veff":"effektives Potential V_eff(θ); Energie E gestrichelt, θ jetzt gepunktet","portrait.em":"Energie-Impuls-Abbildung: E gegen J₃ (Punkt: jetzt)","portrait.orbit":"Bahn","portrait.emBoundary":"Rand (konische Bahnen)","note.spring":"die Schwingfeder verlässt die Kugel (ihre Länge ändert sich): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.string":"die Schnur wird schlaff (freier Flug in der Kugel): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.exactIdeal":"die exakte Lösung gibt es nur für das ideale Pendel; dies ist das Modell „{model}“","note.reducedIdeal":"die reduzierte Ansicht ist die des idealen Pendels; dies ist das Modell „{model}“","note.phasesPlanar":"keine Phasen: sie teilen die Drehung einer Bahn, die um die Senkrechte kreist; diese Bahn {kind}","note.phasesNoGravity":"keine Phasen: ohne Schwerkraft läuft die Kugel gleichförmig auf einem Großkreis, da gibt es nichts aufzuteilen","event.slack":"die Schnur wurde schlaff (Zugkraft 0: freier Flug)","event.taut":"die Schnur straffte sich ruckartig, verlor {lost} J","event.skippedOne":" ({n} früheres Ereignis dieses Moments nicht gezeigt)","event.skippedMany":" ({n} frühere Ereignisse dieses Moments nicht gezeigt)","event.slackRow":"schlaff geworden","event.tautRow":"gestrafft","event.tautValue":"t = {t} s, verlor {lost}","data.power":"Leistung P = dE/dt","data.springForce":"Federkraft k(|r| − l₀)","data.springLength":"Federlänge |r|","data.stretch":"Dehnung |r| − l₀","data.string":"Schnur","data.slackZero":"schlaff (0)","data.slack":"schlaff: freier Flug, |x| = {r} m","data.taut":"straff","data.events":"Ereignisse","data.noEvents":"noch keine (schlaff, Straffen)","data.z3":"z₃ (außerhalb)","data.dynamic":"Δφ dynamisch","data.geometric":"Δφ geometrisch","data.error":"Lagefehler |Δx|","data.errorRel":"Lagefehler / l","data.errorHow":"Fehler ermittelt durch","data.errorPaused":"Schätzung pausiert (das Rechenbudget des Servers ist aufgebraucht; sie holt auf, sobald Zeit ist)","data.errorNone":"keine Schätzung","data.errorCrane":"keine Schätzung: der Kranmodus rechnet mit seinem eigenen Integrator (DOP853) bei den Toleranzen der Sitzung","data.howExact":"den wahren Fehler: gegen die exakte Lösung (seit t = {since} s)","data.howRichardson":"Schätzung: Richardson gegen einen Begleitlauf mit dt/2 = {dt} s, Ordnung p = {p} (seit t = {since} s)","data.howCompanion":"Schätzung: einen Begleitlauf mit rtol = {rtol} (seit t = {since} s)"},Iv={"page.softwareHelp":"{renderer}: ohne Multisampling gezeichnet, für die Bildrate","tools.start":"Startwinkel","tools.thetaHelp":"θ₀: der Winkel zur Senkrechten nach unten, in Grad (0 … 180)","tools.phiHelp":"φ₀: der Winkel um die Senkrechte, in Grad","tools.phiDotHelp":"φ̇₀: wie schnell die Kugel zu kreisen beginnt, in Grad pro Sekunde (0: ebene Schwingung)","tools.setStart":"Start setzen","tools.world":"Schwerkraft und Reibung","tools.gravity":"Schwerkraft","tools.friction":"Reibung","tools.frictionHelp":"lineare Dämpfung c [1/s]: die Kraft −m c v; beim idealen Pendel wird auf das gedämpfte Modell gewechselt","tools.noFriction":"das Modell „{model}“ hat keinen Reibungsparameter","tools.now":"Winkel jetzt","tools.stopwatch":"Stoppuhr (simulierte Zeit)","tools.swStart":"Start","tools.swStop":"Stopp","tools.swLap":"Runde","tools.swReset":"Null","tools.period":"Periodenmessung","tools.periodHelp":"aus der Bewegung gemessen: den tiefsten Punkten der Kugel; eine Periode der Schwingung endet, wenn die Kugel den tiefsten Punkt wieder in derselben Richtung durchläuft. Verglichen mit dem exakten Wert (ideales Pendel) oder der Theorie (Formel für kleine Ausschläge mit Reibung)","tools.periodCount":"Mittel über {n} Perioden","tools.periodCountZ":"Mittel über {n} Zeiten von tiefstem zu tiefstem Punkt","tools.periodWait":"wartet, bis die Kugel zweimal den tiefsten Punkt durchlaufen hat","tools.motion":"Bewegung","tools.kindNone":"—","tools.kindSwing":"schwingt hin und her","tools.kindOver":"schwingt über den höchsten Punkt","tools.kindOrbit":"kreist (nie durch den tiefsten Punkt)","tools.periodSwing":"Periode T [s]","tools.periodZ":"tiefster bis tiefster Punkt [s]","tools.advance":"Drehung zwischen tiefsten Punkten [°]","tools.precession":"Bahn dreht sich pro Umlauf um [°]","tools.amplitude":"Amplitude (größter Winkel) [°]","tools.band":"Winkel zur Senkrechten [°]","tools.theory":"Theorie","tools.measured":"gemessen","tools.exact":"exakt","tools.difference":"Abweichung","tools.overlays":"Lineal und Winkelmesser","tools.ruler":"Lineal (Meter)","tools.protractor":"Winkelmesser (θ in Grad)","gloss.title":"Wörter (Glossar)","gloss.advanced":"Formelnummern und weitere Zeilen zeigen (für Fortgeschrittene)","gloss.period":"Periode T","gloss.periodText":"die Zeit für eine ganze Schwingung: von einer Seite zur anderen und zurück, bis die Kugel den tiefsten Punkt wieder in derselben Richtung durchläuft. In Sekunden.","gloss.amplitude":"Amplitude","gloss.amplitudeText":"der größte Winkel zwischen Stange und Senkrechter während einer Schwingung. Mit Reibung wird er von Schwingung zu Schwingung kleiner.","gloss.lowest":"tiefster Punkt","gloss.lowestText":"wo die Kugel in einer Schwingung am tiefsten ist. Eine Schwingung geht durch den untersten Punkt; eine kreisende Kugel läuft daneben vorbei.","gloss.friction":"Reibung (Dämpfung)","gloss.frictionText":"eine Kraft gegen die Bewegung, die Energie wegnimmt, so dass die Schwingungen abklingen. Die Zahl c sagt, wie stark (pro Sekunde).","gloss.gravity":"Schwerebeschleunigung g","gloss.gravityText":"wie stark der Planet zieht: 9,81 m/s² auf der Erde, 1,62 auf dem Mond. Stärkerer Zug lässt das Pendel schneller schwingen.","gloss.energy":"kinetische und potentielle Energie","gloss.energyText":"kinetische Energie ist Bewegungsenergie (schnelle Kugel: viel); potentielle Energie ist Höhenenergie (hohe Kugel: viel). Beim Schwingen wandeln sie sich ineinander um; Reibung nimmt etwas weg.","gloss.spin":"Drehimpuls J₃","gloss.spinText":"wie sehr die Kugel um die Senkrechte kreist. Null für eine Schwingung in einer Ebene; beim idealen Pendel bleibt er gleich.","gloss.precession":"Präzession","gloss.precessionText":"eine kreisende Kugel schließt ihre Bahn nicht: das Muster dreht sich bei jedem Umlauf ein wenig, und von oben entsteht eine Rosette.","gloss.method":"Verfahren (Integrator)","gloss.methodText":"wie der Computer die Bewegung in kleinen Zeitschritten ausrechnet. Symplektische Verfahren halten die Energie lange richtig; andere driften.","gloss.drift":"Energiedrift","gloss.driftText":"wie weit die berechnete Energie von ihrem Anfangswert abgewandert ist. Beim idealen Pendel sollte sie null bleiben; was übrig ist, ist Rundung des Computers.","tools.moveGroup":"{what} verschieben","tools.moveLeft":"nach links","tools.moveRight":"nach rechts","tools.moveUp":"nach oben","tools.moveDown":"nach unten","tools.moveBack":"zurück an seinen Platz","describe.none":"noch keine Bewegung","describe.text":"Winkel {theta}° zur Senkrechten, {dir}, Geschwindigkeit {v} m/s","describe.rest":"in Ruhe","describe.turning":"am Umkehrpunkt","describe.rising":"steigt","describe.falling":"fällt zum tiefsten Punkt","describe.energy":"; Energie {k} % kinetisch, {u} % potentiell","describe.lost":", {p} % durch Reibung verloren","describe.toggle":"Bewegung alle 5 s beschreiben (Bildschirmleser; D: jetzt)","tools.sound":"Ton: ein Ton an jedem tiefsten Punkt (höher, wenn schneller)","tools.mystery":"geheimer Planet (g aus der Periode bestimmen)","tools.reveal":"g zeigen","tools.mysteryOn":"ein geheimer Planet: Schwingungen stoppen und g = 4π² l / T² ausrechnen","tools.revealed":"g des geheimen Planeten ist {g} m/s²","start.notNumber":"{name} muss eine Zahl sein","start.thetaRange":"θ₀ = {value}° ist nicht erlaubt: 0 … 180°","gravity.custom":"eigene","gravity.earth":"Erde","gravity.moon":"Mond","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"null","gravity.negative":"negativ (nach oben)","energy.title":"Energie","energy.kinetic":"kinetisch","energy.potential":"potentiell","energy.lost":"verloren","energy.total":"gesamt","plot.dE":"Energiedrift |ΔE|/E_s (log)","plot.dJ3":"J₃-Drift |ΔJ₃|/J_s (log)","plot.z":"Höhe z(t)","plot.tension":"Stangenkraft T(t)","plot.time":"Zeit t [s]","plot.floor":"float64-Rundung 2,2e-16","alt.empty":"noch keine Daten","alt.summary":"{y} von {yLo} bis {yHi} gegen {x} von {xLo} bis {xHi}; jetzt {yNow} bei {xNow}","chosen.title":"Beliebige Größen zeichnen","chosen.xAxis":"waagerecht","chosen.yAxis":"senkrecht","var.t":"Zeit t","var.theta":"Winkel θ","var.phi":"Azimut φ","var.x":"x","var.y":"y","var.z":"Höhe z","var.zdot":"Vertikalgeschwindigkeit ż","var.speed":"Geschwindigkeit |v|","var.energy":"Energie E","var.kinetic":"kinetische Energie K","var.potential":"potentielle Energie U","var.j3":"Drehimpuls J₃","var.tension":"Zugkraft T","var.power":"Leistung P","var.radius":"Abstand |x|"},kv={"twin.title":"Zwei Pendel","twin.mode":"zweites Pendel","twin.off":"aus","twin.epsilon":"Start um ε verschieden","twin.method":"anderer Integrator","twin.damped":"gedämpft daneben","twin.own":"eigene Länge, Masse und Start (nebeneinander)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"Pendel {n} braucht eine Länge > 0, eine Masse > 0 und einen Startwinkel 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"Periode T [s] (Perioden)","twin.methodPick":"Integrator","twin.damping":"Dämpfung [1/s]","twin.start":"beide starten","twin.badEpsilon":"ε muss eine Zahl sein (Grad)","twin.badDamping":"die Dämpfung muss eine Zahl ≥ 0 sein (1/s)","twin.first":"Pendel 1","twin.second":"Pendel 2","twin.separation":"Abstand der Kugeln |r₁ − r₂| [m]","help.title":"Tastenkürzel und Farben","help.space":"Start / Pause","help.r":"zurück zum Start","help.s":"ein Schritt (angehalten)","help.arrows":"auf einem Schieberegler: einen Schritt runter / hoch","help.page":"auf einem Schieberegler: zehn Schritte","help.camera":"in der 3-D-Ansicht: Kamera drehen / zoomen","help.bobKeys":"in der 3-D-Ansicht: Start der Kugel um 1° verschieben (hält an)","help.describe":"die Bewegung jetzt beschreiben (Bildschirmleser)","help.tab":"zwischen Bedienelementen wechseln","help.help":"diese Übersicht","help.esc":"diese Übersicht schließen","help.colours":"Farben","help.close":"schließen","help.bob":"Kugel","help.trail":"Spur","help.twin":"zweites Pendel","help.ruler":"Lineal und Winkelmesser","msg.notConnected":"keine Verbindung zum Server","msg.veffFailed":"das effektive Potential: {why}","msg.emFailed":"die Energie-Impuls-Abbildung: {why}","msg.downloadFailed":"das Herunterladen des Szenarios: {why}","msg.linkProblems":"aus dem Link weggelassen: {what}","url.unknownKey":"unbekannter Schlüssel {key} im Link","url.notName":"{key} = {value} ist kein Name","url.notNumber":"{key} = {value} ist keine endliche Zahl","url.notThree":"{key} = {value} sind keine drei endlichen Zahlen","url.notPair":"mp: {value} ist nicht Name:Zahl","url.startXv":"der Start braucht x und v","url.notTime":"at = {value} ist keine Zeit 0 … 1e6 s","url.notView":"view: {value} ist keine Ansichtsoption","url.notPlot":"plot = {value} sind nicht zwei Variablennamen","url.notTwin":"twin = {value} ist nicht own:l:m:θ₀, eps:ε, method:Name oder damped:c","link.scenario":"das Szenario (Modell, Parameter, Verfahren, Start)","link.paused":"angehalten","link.pausedAt":"angehalten bei {t} s","link.view":"Ansicht: {list}","link.plot":"Diagramm {y} gegen {x}","link.twin":"zweites Pendel {what}","link.lang":"Sprache {lang}","msg.linkCopied":"Link kopiert; er enthält {what}","msg.dragged":"Start durch Ziehen gesetzt (dort in Ruhe): Start drücken, um loszulassen","msg.pull":"den Pfeil ziehen, um die Startgeschwindigkeit zu setzen","msg.capped":" (begrenzt: höchstens 4√(g l))","msg.velocitySet":"Startgeschwindigkeit gesetzt: |v| = {v} m/s{cap}; Start drücken","msg.velocity":"Startgeschwindigkeit |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} ist nicht erlaubt: {allowed} ({range})","msg.recording":"die Ansicht wird aufgenommen…","msg.recorded":"Video gespeichert ({mb} MB, WebM)","msg.noRecording":"dieser Browser kann die Ansicht nicht aufnehmen ({why})","fit.title":"Messdaten","fit.load":"Messdaten laden…","fit.help":"eine CSV-Datei mit Messwerten in SI-Einheiten (Spalten t, x, y, z oder x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): der Server passt das Pendel an, lädt die angepasste Bewegung und zeichnet die gemessene Bahn gepunktet daneben","fit.model":"Modell","fit.params":"anpassen","fit.paramsDefault":"was die Daten bestimmen","fit.paramsHelp":"die anzupassenden Parameter, durch Kommas getrennt (z. B. length,g,damping,pivot); leer: was die Daten bestimmen können","fit.clear":"gemessene Bahn löschen","fit.running":"{name} wird angepasst …","fit.noPath":"(Daten ohne Bezugssystem: keine Bahn zu zeichnen)","fit.failed":"Anpassung: {why}","fit.loaded":"{name} angepasst: die angepasste Bewegung ist geladen, die gemessene Bahn golden gepunktet","page.tools":"Messwerkzeuge","page.energy":"Energie-Balkendiagramm","page.data":"Datenfeld","page.plots":"Live-Diagramme","page.portraits":"Phasenporträt, effektives Potential, Energie-Impuls-Abbildung","page.reduced":"reduzierte Ansicht im σ-Raum","gui.modelsHelp":"die Modelle (Codename in Klammern):","fit.summary":"{model}: {state}","fit.converged":"die Anpassung ist konvergiert","fit.notConverged":"die Anpassung ist nicht konvergiert","fit.notDetermined":"(durch diese Daten nicht bestimmt)","fit.fullReport":"der vollständige Bericht der Anpassung (wie pendulab fit ihn ausgibt, auf Englisch)"},Fv={"server.too_small":"{name} = {value}: mindestens {limit} erlaubt","server.too_small_strict":"{name} = {value}: muss größer als {limit} sein","server.too_large":"{name} = {value}: höchstens {limit} erlaubt","server.too_large_strict":"{name} = {value}: muss kleiner als {limit} sein","server.missing":"{name} fehlt","server.unknown_key":"unbekannter Schlüssel {name}","server.nonfinite_motion":"die Bewegung hat bei t = {t} s den Zahlenbereich verlassen ({fields} nicht endlich): zu extreme Parameter oder Startwerte; angehalten — zurücksetzen oder die Parameter ändern","server.integration_stopped":"die Rechnung ist stehen geblieben ({detail}); angehalten","server.throttled":"zu viele Befehle: {lost} verworfen; höchstens {per_second} pro Sekunde senden","server.server_full":"der Server ist voll: {active} Laborsitzungen sind offen, mehr bedient er nicht gleichzeitig; einen anderen Tab schließen oder später versuchen","server.device_full":"zu viele Laborsitzungen von diesem Gerät: {have} sind offen, mehr darf ein Gerät nicht haben; einen anderen Tab schließen","server.device_busy":"zu viele Berechnungen gleichzeitig von diesem Gerät: höchstens {most} dürfen für ein Gerät laufen oder warten; die Antworten abwarten, dann erneut versuchen","server.step_too_small":"die Schrittweite wurde bei t = {t} s zu klein (h = {h} s): die Bewegung ändert sich für die Toleranzen zu schnell","server.diverged":"die Integration ist nach t = {t} s mit dem Verfahren {method} divergiert (dt = {dt} s): dt verkleinern oder ein adaptives (dop853) oder strukturerhaltendes (rattle) Verfahren wählen","server.diverged_rattle":"die Integration ist nach t = {t} s mit dem Verfahren {method} divergiert (dt = {dt} s): dt verkleinern (der Schritt muss die schnellste Bewegung auflösen, dt·ω ≪ 1)","server.diverged_dop853":"die Integration ist nach t = {t} s mit dem Verfahren {method} divergiert (dt = {dt} s): rtol und atol verkleinern oder das strukturerhaltende rattle wählen","server.diverged_dt":"die Integration ist nach t = {t} s mit dem Verfahren {method} divergiert (dt = {dt} s): dt verkleinern","server.near_pole":"die Rechnung hat bei t = {t} s einen Pol erreicht (das Pendel genau nach oben oder unten), wo diese Gleichungen versagen: ein kartesisches Verfahren wählen","server.not_finite":"{name}[{index}] = {value} ist keine endliche Zahl","server.off_sphere":"der Start liegt nicht auf der Kugel: {what} = {value} überschreitet die Toleranz {tolerance}","server.invalid_parameter":"{name} = {value} ist nicht erlaubt: {allowed}","server.unknown_model":"unbekanntes Modell {model}; verfügbar: {available}","server.not_lab_model":"das Modell {model} läuft nicht im Labor (pendulab run verwenden); die Modelle des Labors: {available}","server.unknown_parameter":"das Modell {model} hat keinen Parameter {name}; seine Parameter: {available}","server.no_parameters":"das Modell {model} hat keinen Parameter {name}; es hat keine außer Länge, Masse, g","server.still_stepping":"es wird noch gerechnet: {waiting} Schritte warten (höchstens {most}); auf das Bild warten oder pausieren","server.method_not_for_spring":"das Verfahren {method} kann das Modell {model} nicht rechnen (es verlässt die Kugel: rattle rechnet Störmer–Verlet (Ordnung 2), rattle4 dessen Triple-Jump-Komposition (Ordnung 4)); eines von {available} wählen","server.method_not_for_string":"das Verfahren {method} kann das Modell {model} nicht rechnen (seine straffen Phasen brauchen ein Verfahren mit festem Schritt, das TS² einhält); eines von {available} wählen","server.method_not_for_crane":"das Verfahren {method} kann das Modell {model} nicht rechnen (der Kranmodus rechnet seine Last mit dem Kran-Integrator, adaptivem DOP853 mit Projektion auf das Seil); {available} wählen","server.not_crane":"nicht im Kranmodus (das Labor rechnet das Modell {model}): ihn zuerst mit der Schaltfläche „Kranmodus“ einschalten","server.internal_error":"interner Fehler des Servers (ein Fehler der Software: bitte melden); Details (englisch): {detail}","server.busy":"beschäftigt: {waiting} Berechnungen warten schon; gleich noch einmal versuchen","server.work_timeout":"die Berechnung dauerte länger als {seconds} s und wurde abgebrochen; weniger Daten, weniger Parameter oder ein einfacheres Modell versuchen","server.not_json":"die Anfrage ist kein JSON","server.out_of_memory":"die Anfrage braucht mehr Speicher, als der Server dafür hat","server.worker_died":"der Rechenprozess des Servers für diese Berechnung ist beendet worden (Exit-Code {code}); die Anfrage braucht vielleicht mehr Speicher, als der Server hat","server.data_too_many_rows":"{file}: {rows} Datenzeilen; höchstens {most} Messwerte werden angepasst: die Daten ausdünnen","server.data_not_number":"{file}: Zeile {row} (Zeile {line} der Datei), Spalte {column}: {cell} ist keine Zahl","server.data_cell_infinite":"{file}: Zeile {row} (Zeile {line} der Datei), Spalte {column}: {cell} ist unendlich oder zu groß für eine Zahl","server.data_cell_subnormal":"{file}: Zeile {row} (Zeile {line} der Datei), Spalte {column}: {cell} ist so nah an 0, dass es kein Messwert ist: 0 schreiben","server.data_cell_beyond":"{file}: Zeile {row} (Zeile {line} der Datei), Spalte {column}: {cell} liegt jenseits von ±{limit} {unit}: die Einheit der Spalte prüfen","server.data_times_too_close":"{file}: Zeile {row} (Zeile {line} der Datei), Spalte {column}: {cell} liegt nur {step} s neben einer anderen Zeit; Messwerte, die näher als {most} s beieinander liegen, lassen sich nicht unterscheiden","server.data_row_short":"{file}: Zeile {row} (Zeile {line} der Datei) hat {have} Werte; die verwendeten Spalten brauchen {need}","server.data_long_line":"{file}: Zeile {line} ist {chars} Zeichen lang und keine Zeile mit Zahlen; eine Kopfzeile darf höchstens {most} haben","server.data_no_rows_in_first":"{file}: keine Zeile mit Zahlen in den ersten {lines} Zeilen: ist das eine Datendatei?","server.data_no_rows":"{file}: keine Zeilen mit Zahlen","server.data_linear_acceleration":"{file}: Spalte {column} ist eine lineare Beschleunigung (das Handy hat die Schwerkraft abgezogen); die Anpassung braucht die Beschleunigung mit Schwerkraft (z. B. phyphox „Beschleunigung mit g“)","server.data_pixels":"{file}: Spalte {column} ist in Pixeln; zuerst in Meter umrechnen (ein Maßstab bekannter Länge im Video gibt Meter pro Pixel)","server.data_bad_unit":"{file}: Spalte {column} hat die Einheit {unit}; erlaubt sind {allowed}","server.data_no_time":"{file}: keine Zeitspalte t unter den Spalten {columns}: die Spalten in der ersten Zeile der Datei benennen (t, x, y, z, theta, phi, angle …)","server.data_repeated_columns":"{file}: die Spalte(n) {repeated} kommen unter {columns} mehrfach vor (mehrere Spuren oder Messreihen in einer Datei?): eine behalten","server.data_no_header":"{file}: die Datei hat keine Zeile mit Spaltennamen: sie über die Zahlen schreiben (z. B. t,x,y,z)","server.data_unknown_columns":"{file}: unbekannte Spaltenname(n) {unknown}; erlaubt sind {allowed}","server.data_components":"{file}: {kind} braucht alle drei Komponenten {parts}; gefunden nur {found}","server.data_positions_alone":"{file}: die Positionsspalte(n) {have} allein; Positionen sind x, y, z oder x, z (Kamera von der Seite) oder x, y (von oben gesehen)","server.data_crane_run":"{file}: ein Kranlauf (pendulab crane run --out) mit den Spalten {columns}: seine Last hängt an einer fahrenden Laufkatze, vielleicht unter einem Haken und an einem gehievten Seil, was keines der Modelle der Anpassung (ein fester Aufhängepunkt) beschreibt. Eine Anpassung braucht t, x, y, z eines Pendels, wie {command} sie schreibt; für das Pendeln eines Krans nach der Fahrt t und den Abstand der Last vom Aufhängepunkt (payload_x - pivot_x, payload_y - pivot_y) als t,x,y schreiben","server.data_crane_grid":"{file}: ein Krangitter (pendulab crane grid --out) mit den Spalten {columns}: eine Zeile je Fall, keine Zeitreihe zum Anpassen. Eine Anpassung braucht t, x, y, z eines Pendels, wie {command} sie schreibt","server.data_no_columns":"{file}: keine Datenspalten unter {columns}: sie t, x, y, z, theta, phi oder angle nennen (docs/fit.md)","server.data_too_few":"nur {have} brauchbare Messwerte: eine Anpassung braucht mindestens {need}","server.data_time_twice":"die Zeit t = {t} s kommt zweimal vor: jeder Messwert braucht seine eigene Zeit","server.data_theta_range":"der Winkel θ zur Senkrechten muss zwischen 0 und π rad liegen; die Daten reichen von {lo} bis {hi}: Grad statt Bogenmaß?","server.data_value_beyond":"{kind} in Zeile {row} (nach der Zeit sortiert): {value} liegt jenseits von ±{limit} in SI-Einheiten; das ist nie ein Messwert eines Pendels: Einheiten und Spalten der Datei prüfen","server.data_span":"die Aufnahme dauert {span} s; eine Anpassung braucht {least} s bis {most} s (Zeiten in Sekunden?)","server.data_spacing":"die Zeiten {t1} s und {t2} s liegen nur {gap} s auseinander: Rundung, keine Messung","server.data_not_csv":"{file}: keine lesbare CSV-Datei","server.fit_unknown_model":"Modell {model}: eines von {allowed} wählen","server.fit_cannot_fit":"{param} lässt sich mit dem Modell {model} nicht anpassen; wählbar sind {allowed}","server.fit_planar_phi":"eine Schwingung in einer Ebene hält den seitlichen Winkel und seine Geschwindigkeit bei 0: sie nicht anpassen","server.fit_pivot_needs_positions":"der Aufhängepunkt wird nur aus Positionen angepasst; diese Daten haben keine","server.fit_t_offset_ideal":"t_offset wird nur für das ideale Pendel angepasst","server.fit_failed":"die Anpassung von {file} ist gescheitert: die Daten enthalten Werte, denen die Anpassung in Gleitkommazahlen nicht folgen kann (Zeiten oder Positionen extrem weit auseinander oder dicht beieinander, oder ein Rauschen weit weg vom Maßstab der Daten)"},Uv={"scenario.conical":"Kegelpendel bei 45°","scenario.damped":"Gedämpfte Rosette (c = 0.05 1/s)","scenario.foucault":"Foucault-Pendel bei 49° N, Erddrehung übertrieben (Ω = 0.02 rad/s)","scenario.inverted_g":"Umgekehrte Schwerkraft: die Rosette gespiegelt","scenario.near_top":"Knapp unter dem höchsten Punkt losgelassen","scenario.over_the_top":"Über Kopf: ebene Überschläge","scenario.planar_large":"Ebene Schwingung mit 150° Amplitude","scenario.rosette":"Rosette: bei 60° mit seitlichem Schwung losgelassen","scenario.crane_hoist":"Portalkran: ZV-geformte 8-m-Fahrt beim Heben von 12 m auf 6 m, bei Seitenwind","scenario.slewing_crane":"Drehkran: R = 5 m, ω = 0.3 rad/s, l = 10 m","scenario.small_ellipse":"Kleine Ellipse mit Airy-Präzession","scenario.string_slack":"Pendel an einer Schnur: schlaff bei z = l/2, unelastischer Ruck","scenario.swinging_spring":"Schwingfeder in der 1:1:2-Resonanz","scenario.zero_g":"Schwerelos: ein Großkreis","modelHelp.ideal":"eine Stange ohne Reibung: das Pendel aus dem Lehrbuch","modelHelp.damped":"mit Reibung, Luftwiderstand oder periodischem Antrieb","modelHelp.rotating":"von der sich drehenden Erde aus gesehen: die Schwingebene dreht sich (Foucault)","modelHelp.slewing":"am Ausleger eines sich drehenden Krans","modelHelp.vibrating":"der Aufhängepunkt wird auf und ab gerüttelt: es kann kopfüber stehen (Kapitza)","modelHelp.sampled_pivot":"der Aufhängepunkt bewegt sich auf einer vorgegebenen Bahn","modelHelp.spring":"eine Feder statt einer Stange: es schwingt und federt","modelHelp.string":"eine Schnur statt einer Stange: sie kann schlaff werden und sich ruckartig spannen","key.space":"Leertaste","key.page":"Bild ↑ / Bild ↓","key.shift":"Umschalt","toolbar.simpleShort":"Einfach","toolbar.simple":"einfache Ansicht: nur die Werkzeuge für den Unterricht (Länge, Masse, Schwerkraft, Reibung, Stoppuhr, Periode, Lineal, Energie); noch einmal drücken für alles","extras.add":"+ noch ein Pendel (eigene Länge, Masse, Start)","extras.pendulum":"Pendel {n}","extras.remove":"Pendel {n} entfernen","extras.title":"Bis zu vier Pendel","extras.hint":"Mit dem zweiten Pendel auf „eigene Länge, Masse und Start“: Pendel 3 und 4 hinzufügen, dann startet „beide starten“ alle, jedes mit seiner eigenen Periodenmessung."},Ov={length:["Länge l","Länge der Stange vom Aufhängepunkt zur Kugel"],mass:["Masse m","Masse der Kugel"],g:["Schwerebeschleunigung g","Stärke der Schwerkraft (jedes Vorzeichen; 0 erlaubt)"],damping:["Reibung (lineare Dämpfung) c","Reibungskraft −m c v, proportional zur Geschwindigkeit"],drag:["Luftwiderstand c_q","Kraft −m c_q |v| v, quadratisch in der Geschwindigkeit"],friction:["trockene Reibung am Aufhängepunkt ε_f","Haftreibung (Coulomb) am Aufhängepunkt: ein Drehmoment m l² ε_f gegen die Schwingung, gleich wie schnell sie ist"],friction_speed:["Glättungsgeschwindigkeit der trockenen Reibung ω_ε","unter dieser Winkelgeschwindigkeit klingt die trockene Reibung sanft ab, wie tanh(|ω|/ω_ε)"],forcing_amplitude:["Antrieb: Stärke A","periodische Kraft pro Masse A cos(ω t + ψ) in Richtung e"],forcing_omega:["Antrieb: Kreisfrequenz ω","wie schnell der Antrieb schwingt"],forcing_phase:["Antrieb: Phase ψ","Phase des Antriebs bei t = 0"],forcing_x:["Antriebsrichtung e: x","x-Komponente der Antriebsrichtung (wird normiert)"],forcing_y:["Antriebsrichtung e: y","y-Komponente der Antriebsrichtung"],forcing_z:["Antriebsrichtung e: z","z-Komponente der Antriebsrichtung"],gravity_x:["Schwerkraftrichtung d: x","x-Komponente der Richtung der Schwerkraft (wird normiert)"],gravity_y:["Schwerkraftrichtung d: y","y-Komponente der Richtung der Schwerkraft"],gravity_z:["Schwerkraftrichtung d: z","z-Komponente der Richtung der Schwerkraft"],frame_rate:["Drehrate des Bezugssystems |Ω|","wie schnell sich das Bezugssystem dreht (Erde: 7,292e-5)"],latitude:["geografische Breite λ","Breite des Ortes (Foucault-Pendel)"],radius:["Auslegerradius R","Abstand des Aufhängepunkts von der Drehachse des Krans"],rate:["Drehrate des Krans ω","wie schnell sich der Ausleger dreht"],height:["Höhe des Aufhängepunkts h","Höhe des Auslegers"],amplitude:["Rüttelamplitude A","Amplitude der senkrechten Schwingung des Aufhängepunkts"],frequency:["Rüttelfrequenz ν","Kreisfrequenz der Schwingung des Aufhängepunkts"],stiffness:["Federkonstante k","Steifigkeit der Feder; die Länge l ist die entspannte Länge"],restitution:["Stoßzahl e","wie elastisch die Schnur beim Straffen zurückfedert (0 … 1)"]},zv={ideal:"Ideales Pendel",damped:"Gedämpft und angetrieben",rotating:"Auf der drehenden Erde (Foucault)",slewing:"Drehkran",vibrating:"Gerüttelter Aufhängepunkt (Kapitza)",sampled_pivot:"Aufhängepunkt auf vorgegebener Bahn",spring:"Schwingfeder",string:"Pendel an einer Schnur",crane:"Portalkran (Kranmodus)"},Bv={...Nv,...Iv,...kv,...Fv,...Uv},Hv={"page.title":"Laboratoire Pendulab — le pendule sphérique","page.units":"unités SI, z vers le haut","page.scene":"vue 3D du pendule (glisser pour tourner, molette pour zoomer)","page.panel":"commandes et mesures","page.skip":"Aller aux commandes","page.software":"WebGL logiciel : sans anticrénelage","conn.connected":"connecté","conn.retrying":"déconnecté : nouvel essai…","conn.gone":"Le serveur du laboratoire ne répond pas : le pendule est arrêté. pendulab serve tourne-t-il encore ? Nouvel essai de connexion …","conn.noStart":"Le laboratoire n’a pas pu démarrer :","toolbar.label":"commandes de marche","toolbar.startShort":"▶ Démarrer","toolbar.pauseShort":"Pause","toolbar.resetShort":"Revenir","toolbar.stepShort":"Pas","toolbar.recordShort":"● Filmer","toolbar.recordStopShort":"■ Arrêter","toolbar.start":"démarrer (Espace)","toolbar.pause":"pause (Espace)","toolbar.reset":"revenir au départ (R)","toolbar.step":"un pas (S)","toolbar.record":"filmer la vue (WebM)","toolbar.recordStop":"arrêter de filmer et télécharger la vidéo","toolbar.help":"raccourcis clavier et légende des couleurs (?)","toolbar.present":"mode présentation : gros caractères pour un vidéoprojecteur","toolbar.language":"langue","toolbar.collapse":"masquer le panneau","toolbar.expand":"afficher le panneau","gui.title":"Laboratoire Pendulab","gui.pendulum":"Pendule","gui.model":"modèle","gui.modelParams":"{model} : paramètres","gui.paramHelp":"{help} — clé {name} [{unit}] ; permis : {range} ; par défaut {default}","gui.integrator":"Méthode de calcul","gui.method":"méthode","gui.order":"ordre {n}","gui.symplectic":"symplectique","gui.adaptive":"adaptative","method.rk4":"Runge–Kutta, ordre 4 (classique ; quitte la sphère)","method.dop853":"Adaptative, très précise (Dormand–Prince, ordre 8)","method.rattle":"Symplectique (RATTLE, ordre 2 ; par défaut)","method.rattle4":"Symplectique (RATTLE, ordre 4)","method.rattle6":"Symplectique (RATTLE, ordre 6)","method.rattle8":"Symplectique (RATTLE, ordre 8)","method.rkmk4":"Pas de rotation sur la sphère (Munthe-Kaas, ordre 4)","method.rk4_angles":"Runge–Kutta 4 en angles (échoue aux pôles)","method.other":"{name} (ordre {n})","kind.generic":"tourne en rosace","kind.conical":"tourne à hauteur constante (pendule conique)","kind.planar":"oscille dans un plan","kind.planar_rotating":"fait des tours complets dans un plan","kind.separatrix":"monte vers le sommet sans jamais l’atteindre","kind.rest":"au repos","kind.great_circle":"parcourt un grand cercle (sans pesanteur)","data.energy":"énergie E","data.energyChange":"variation de l’énergie E − E₀","data.spin":"moment cinétique autour de la verticale J₃","data.spinChange":"sa variation J₃ − J₃(0)","data.height":"hauteur z","data.turning":"hauteurs la plus basse et la plus haute z₁, z₂","gui.dtRange":"dt doit être entre {min} et {max} s","gui.dtHelp":"pas de temps des méthodes à pas fixe ; {min} … {max} s (dop853 choisit le sien)","gui.run":"Marche","gui.timeScale":"échelle de temps [×]","gui.tsRange":"l’échelle de temps doit être entre {min} et {max}","gui.tsHelp":"secondes simulées par seconde (ralenti en dessous de 1) ; {min} … {max}","gui.stepN":"pas par clic","gui.scenario":"scénario","gui.view":"Vue","gui.trail":"trace","gui.trailSeconds":"trace [s]","gui.sphere":"sphère atteignable","gui.axes":"axes","gui.topView":"vue de dessus","gui.stereo":"stéréo","gui.stereoHelp":"anaglyphe : lunettes rouge–cyan ; côte à côte : visionneuse stéréo","stereo.off":"non","stereo.anaglyph":"anaglyphe (rouge–cyan)","stereo.sideBySide":"côte à côte","gui.vectors":"Vecteurs","gui.origin":"origine {axis} [m]","gui.originHelp":"origine de L et τ par rapport au point de suspension (0 : le point de suspension)","gui.export":"Partager et exporter","gui.csv":"télécharger la trajectoire (CSV)","gui.toml":"télécharger le scénario (TOML)","gui.tomlHelp":"le scénario tel qu’il est (modèle, paramètres, départ, méthode) en fichier pour `pendulab run`","gui.png":"capture d’écran (PNG)","gui.link":"copier le lien vers ce laboratoire (son contenu : à la copie)","vec.velocity":"vitesse v","vec.velocityHelp":"v [m/s], dessinée comme 0,25 s de trajet","vec.momentum":"quantité de mouvement m v","vec.momentumHelp":"m v [kg m/s], 0,25 m par kg m/s","vec.gravity":"poids m g","vec.gravityHelp":"le poids m g d [N] (d : direction de la pesanteur) ; forces : m·max(|g|, 1) N ↔ 0,5 l","vec.tension":"force de la tige (tension)","vec.tensionHelp":"la force de la tige −T x/|x| [N], T venant du serveur","vec.net":"force résultante m a","vec.netHelp":"m a [N] : a = ẍ calculée par le cœur du serveur (par rapport au point de suspension)","vec.angularMomentum":"moment cinétique L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] par rapport à l’origine o, dessiné depuis o","vec.torque":"moment de force τ","vec.torqueHelp":"τ = (x − o) × m a [N m] par rapport à l’origine o, dessiné depuis o ; dL/dt = τ","data.now":"Maintenant (du serveur)","data.exact":"Solution exacte de cette orbite","data.tension":"tension","data.tensionMin":"tension min","data.tensionMax":"tension max","data.method":"méthode","data.state":"état","data.paused":"en pause","data.running":"en marche","data.lagging":" (en retard : plus lent que demandé)","data.model":"modèle","data.kind":"type de mouvement","data.periodZ":"du point le plus bas au suivant T_z","data.swingPeriod":"période d’oscillation T","data.advance":"rotation entre deux points les plus bas Δφ","data.rotation":"nombre de rotation W = Δφ/2π","data.reduced":"vue réduite (σ₁, σ₂, σ₃) : surface J₃ ∩ plan d’énergie","portrait.phase":"portrait de phase : vitesse verticale ż selon la hauteur z","portrait.veff":"potentiel effectif V_eff(θ) ; énergie E en tirets, θ actuel en pointillés","portrait.em":"carte énergie–moment : E selon J₃ (point : maintenant)","portrait.orbit":"orbite","portrait.emBoundary":"bord (orbites coniques)","note.spring":"le ressort quitte la sphère (sa longueur varie) : V_eff, la carte énergie–moment, la vue réduite et la solution exacte sont celles du pendule à tige et ne sont pas affichées","note.string":"le fil se détend (vol libre dans la sphère) : V_eff, la carte énergie–moment, la vue réduite et la solution exacte sont celles du pendule à tige et ne sont pas affichées","note.exactIdeal":"la solution exacte n’existe que pour le pendule idéal ; ceci est le modèle « {model} »","note.reducedIdeal":"la vue réduite est celle du pendule idéal ; ceci est le modèle « {model} »","note.phasesPlanar":"pas de phases : elles partagent le tour d’une orbite qui tourne autour de la verticale ; cette orbite {kind}","note.phasesNoGravity":"pas de phases : sans pesanteur la masse parcourt un grand cercle à vitesse constante, il n’y a rien à partager","event.slack":"le fil s’est détendu (tension 0 : vol libre)","event.taut":"le fil s’est tendu d’un coup, {lost} J perdus","event.skippedOne":" ({n} événement antérieur de cet instant non affiché)","event.skippedMany":" ({n} événements antérieurs de cet instant non affichés)","event.slackRow":"détendu","event.tautRow":"tendu d’un coup","event.tautValue":"t = {t} s, perdu {lost}","data.power":"puissance P = dE/dt","data.springForce":"force du ressort k(|r| − l₀)","data.springLength":"longueur du ressort |r|","data.stretch":"allongement |r| − l₀","data.string":"fil","data.slackZero":"détendu (0)","data.slack":"détendu : vol libre, |x| = {r} m","data.taut":"tendu","data.events":"événements","data.noEvents":"aucun pour l’instant (détentes, à-coups)","data.z3":"z₃ (hors de la sphère)","data.dynamic":"Δφ dynamique","data.geometric":"Δφ géométrique","data.error":"erreur de position |Δx|","data.errorRel":"erreur de position / l","data.errorHow":"erreur obtenue par","data.errorPaused":"estimation en pause (le budget de calcul du serveur est épuisé ; elle rattrape quand il y a du temps)","data.errorNone":"pas d’estimation","data.errorCrane":"pas d’estimation : le mode grue calcule avec son propre intégrateur (DOP853) aux tolérances de la session","data.howExact":"l’erreur vraie : comparée à la solution exacte (depuis t = {since} s)","data.howRichardson":"estimation : Richardson avec un calcul compagnon à dt/2 = {dt} s, ordre p = {p} (depuis t = {since} s)","data.howCompanion":"estimation : un calcul compagnon à rtol = {rtol} (depuis t = {since} s)"},Vv={"page.softwareHelp":"{renderer} : dessiné sans multiéchantillonnage pour la fluidité","tools.start":"Angle de départ","tools.thetaHelp":"θ₀ : l’angle avec la verticale vers le bas, en degrés (0 … 180)","tools.phiHelp":"φ₀ : l’azimut autour de la verticale, en degrés","tools.phiDotHelp":"φ̇₀ : à quelle vitesse la masse commence à tourner, en degrés par seconde (0 : une oscillation plane)","tools.setStart":"fixer le départ","tools.world":"Pesanteur et frottement","tools.gravity":"pesanteur","tools.friction":"frottement","tools.frictionHelp":"amortissement linéaire c [1/s] : la force −m c v ; sur le pendule idéal, passe au modèle amorti","tools.noFriction":"le modèle « {model} » n’a pas de paramètre de frottement","tools.now":"Angles maintenant","tools.stopwatch":"Chronomètre (temps simulé)","tools.swStart":"démarrer","tools.swStop":"arrêter","tools.swLap":"tour","tools.swReset":"remettre à zéro","tools.period":"Mesure de la période","tools.periodHelp":"mesurée sur le mouvement : les points les plus bas de la masse ; une période d’oscillation se termine quand la masse repasse en bas dans le même sens. Comparée à la valeur exacte (pendule idéal) ou à la théorie (formule des petites oscillations avec frottement)","tools.periodCount":"moyenne sur {n} périodes","tools.periodCountZ":"moyenne sur {n} passages d’un point le plus bas au suivant","tools.periodWait":"attend que la masse passe deux fois par son point le plus bas","tools.motion":"mouvement","tools.kindNone":"—","tools.kindSwing":"oscille d’avant en arrière","tools.kindOver":"fait des tours complets","tools.kindOrbit":"tourne (ne passe jamais par le bas)","tools.periodSwing":"période T [s]","tools.periodZ":"d’un point le plus bas au suivant [s]","tools.advance":"rotation entre deux points les plus bas [°]","tools.precession":"la figure tourne par tour de [°]","tools.amplitude":"amplitude (plus grand angle) [°]","tools.band":"angle avec la verticale [°]","tools.theory":"théorie","tools.measured":"mesuré","tools.exact":"exact","tools.difference":"écart","tools.overlays":"Règle et rapporteur","tools.ruler":"règle (mètres)","tools.protractor":"rapporteur (θ en degrés)","gloss.title":"Mots (glossaire)","gloss.advanced":"afficher les numéros de formules et les lignes en plus (avancé)","gloss.period":"période T","gloss.periodText":"le temps d’une oscillation complète : d’un côté à l’autre et retour, jusqu’à ce que la masse repasse en bas dans le même sens. En secondes.","gloss.amplitude":"amplitude","gloss.amplitudeText":"le plus grand angle entre la tige et la verticale pendant une oscillation. Avec frottement, il diminue d’une oscillation à l’autre.","gloss.lowest":"point le plus bas","gloss.lowestText":"là où la masse est la plus basse pendant une oscillation. Une oscillation passe tout en bas ; une masse qui tourne passe à côté.","gloss.friction":"frottement (amortissement)","gloss.frictionText":"une force contre le mouvement qui enlève de l’énergie, si bien que les oscillations s’éteignent. Le nombre c dit sa force (par seconde).","gloss.gravity":"pesanteur g","gloss.gravityText":"la force avec laquelle la planète attire : 9,81 m/s² sur Terre, 1,62 sur la Lune. Une attraction plus forte fait osciller le pendule plus vite.","gloss.energy":"énergie cinétique et potentielle","gloss.energyText":"l’énergie cinétique est l’énergie du mouvement (masse rapide : beaucoup) ; l’énergie potentielle est l’énergie de hauteur (masse haute : beaucoup). Elles se transforment l’une en l’autre ; le frottement en enlève.","gloss.spin":"moment cinétique J₃","gloss.spinText":"à quel point la masse tourne autour de la verticale. Nul pour une oscillation dans un plan ; il reste constant pour le pendule idéal.","gloss.precession":"précession","gloss.precessionText":"une masse qui tourne ne referme pas sa trajectoire : la figure tourne un peu à chaque tour, et vue de dessus devient une rosace.","gloss.method":"méthode (intégrateur)","gloss.methodText":"la façon dont l’ordinateur calcule le mouvement par petits pas de temps. Les méthodes symplectiques gardent l’énergie juste longtemps ; les autres dérivent.","gloss.drift":"dérive de l’énergie","gloss.driftText":"de combien l’énergie calculée s’est éloignée de sa valeur de départ. Pour le pendule idéal elle devrait rester nulle ; ce qui reste est l’arrondi de l’ordinateur.","tools.moveGroup":"déplacer : {what}","tools.moveLeft":"vers la gauche","tools.moveRight":"vers la droite","tools.moveUp":"vers le haut","tools.moveDown":"vers le bas","tools.moveBack":"remettre à sa place","describe.none":"pas encore de mouvement","describe.text":"angle de {theta}° avec la verticale, {dir}, vitesse {v} m/s","describe.rest":"au repos","describe.turning":"à un point de rebroussement","describe.rising":"monte","describe.falling":"descend vers le bas","describe.energy":" ; énergie {k} % cinétique, {u} % potentielle","describe.lost":", {p} % perdue par frottement","describe.toggle":"décrire le mouvement toutes les 5 s (lecteurs d’écran ; D : maintenant)","tools.sound":"son : un ton à chaque point le plus bas (plus aigu si plus rapide)","tools.mystery":"planète mystère (trouver g avec la période)","tools.reveal":"révéler g","tools.mysteryOn":"une planète mystère : chronométrer les oscillations et calculer g = 4π² l / T²","tools.revealed":"g de la planète mystère vaut {g} m/s²","start.notNumber":"{name} doit être un nombre","start.thetaRange":"θ₀ = {value}° n’est pas permis : 0 … 180°","gravity.custom":"autre","gravity.earth":"Terre","gravity.moon":"Lune","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"nulle","gravity.negative":"négative (vers le haut)","energy.title":"Énergie","energy.kinetic":"cinétique","energy.potential":"potentielle","energy.lost":"perdue","energy.total":"totale","plot.dE":"dérive de l’énergie |ΔE|/E_s (log)","plot.dJ3":"dérive de J₃ |ΔJ₃|/J_s (log)","plot.z":"hauteur z(t)","plot.tension":"tension de la tige T(t)","plot.time":"temps t [s]","plot.floor":"arrondi float64 2,2e-16","alt.empty":"pas encore de données","alt.summary":"{y} de {yLo} à {yHi} selon {x} de {xLo} à {xHi} ; maintenant {yNow} à {xNow}","chosen.title":"Tracer des grandeurs au choix","chosen.xAxis":"en abscisse","chosen.yAxis":"en ordonnée","var.t":"temps t","var.theta":"angle θ","var.phi":"azimut φ","var.x":"x","var.y":"y","var.z":"hauteur z","var.zdot":"vitesse verticale ż","var.speed":"vitesse |v|","var.energy":"énergie E","var.kinetic":"énergie cinétique K","var.potential":"énergie potentielle U","var.j3":"moment cinétique J₃","var.tension":"tension T","var.power":"puissance P","var.radius":"distance |x|"},Gv={"twin.title":"Deux pendules","twin.mode":"second pendule","twin.off":"aucun","twin.epsilon":"départ différent de ε","twin.method":"une autre méthode de calcul","twin.damped":"amorti à côté de celui-ci","twin.own":"sa propre longueur, masse et départ (côte à côte)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"le pendule {n} demande une longueur > 0, une masse > 0 et un angle de départ 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"période T [s] (périodes)","twin.methodPick":"méthode","twin.damping":"amortissement [1/s]","twin.start":"démarrer les deux","twin.badEpsilon":"ε doit être un nombre (degrés)","twin.badDamping":"l’amortissement doit être un nombre ≥ 0 (1/s)","twin.first":"pendule 1","twin.second":"pendule 2","twin.separation":"distance entre les masses |r₁ − r₂| [m]","help.title":"Raccourcis clavier et légende des couleurs","help.space":"démarrer / pause","help.r":"revenir au départ","help.s":"un pas (en pause)","help.arrows":"sur un curseur sélectionné : un pas vers le bas / le haut","help.page":"sur un curseur sélectionné : dix pas","help.camera":"dans la vue 3D : tourner la caméra / zoomer","help.bobKeys":"dans la vue 3D : déplacer le départ de la masse de 1° (met en pause)","help.describe":"décrire le mouvement maintenant (lecteurs d’écran)","help.tab":"passer d’une commande à l’autre","help.help":"cette fenêtre","help.esc":"fermer cette fenêtre","help.colours":"Couleurs","help.close":"fermer","help.bob":"masse","help.trail":"trace","help.twin":"second pendule","help.ruler":"règle et rapporteur","msg.notConnected":"pas de connexion au serveur","msg.veffFailed":"le potentiel effectif : {why}","msg.emFailed":"l’application énergie–moment : {why}","msg.downloadFailed":"le téléchargement du scénario : {why}","msg.linkProblems":"valeurs du lien ignorées : {what}","url.unknownKey":"clé {key} inconnue dans le lien","url.notName":"{key} = {value} n’est pas un nom","url.notNumber":"{key} = {value} n’est pas un nombre fini","url.notThree":"{key} = {value} ne sont pas trois nombres finis","url.notPair":"mp : {value} n’est pas nom:nombre","url.startXv":"le départ demande x et v","url.notTime":"at = {value} n’est pas un instant de 0 … 1e6 s","url.notView":"view : {value} n’est pas une option de vue","url.notPlot":"plot = {value} ne sont pas deux noms de variables","url.notTwin":"twin = {value} n’est pas own:l:m:θ₀, eps:ε, method:nom ou damped:c","link.scenario":"le scénario (modèle, paramètres, méthode, départ)","link.paused":"en pause","link.pausedAt":"en pause à {t} s","link.view":"vue : {list}","link.plot":"graphique {y} selon {x}","link.twin":"second pendule {what}","link.lang":"langue {lang}","msg.linkCopied":"lien copié ; il contient {what}","msg.dragged":"départ fixé en glissant (au repos à cet endroit) : appuyer sur démarrer pour le lâcher","msg.pull":"tirer la flèche pour fixer la vitesse de départ","msg.capped":" (limitée : le maximum de la flèche, 4√(g l))","msg.velocitySet":"vitesse de départ fixée : |v| = {v} m/s{cap} ; appuyer sur démarrer pour partir de là","msg.velocity":"vitesse de départ |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} n’est pas permis : {allowed} ({range})","msg.recording":"la vue est filmée…","msg.recorded":"vidéo enregistrée ({mb} Mo, WebM)","msg.noRecording":"ce navigateur ne peut pas filmer la vue ({why})","fit.title":"Données mesurées","fit.load":"Charger des mesures…","fit.help":"un fichier CSV de mesures en unités SI (colonnes t, x, y, z ou x, z ; theta, phi ; angle ; specific_force ; angular_speed — docs/fit.md) : le serveur y ajuste le pendule, charge le mouvement ajusté et dessine le chemin mesuré en pointillés à côté","fit.model":"modèle","fit.params":"ajuster","fit.paramsDefault":"ce que les données déterminent","fit.paramsHelp":"les paramètres à ajuster, séparés par des virgules (p. ex. length,g,damping,pivot) ; vide : ce que les données peuvent déterminer","fit.clear":"effacer le chemin mesuré","fit.running":"ajustement de {name} …","fit.noPath":"(données sans repère : pas de chemin mesuré à dessiner)","fit.failed":"ajustement : {why}","fit.loaded":"{name} ajusté : le mouvement ajusté est chargé, le chemin mesuré en pointillés dorés","page.tools":"outils de mesure","page.energy":"diagramme en barres de l’énergie","page.data":"panneau de données","page.plots":"courbes en direct","page.portraits":"portrait de phase, potentiel effectif, carte énergie–moment","page.reduced":"vue réduite dans l’espace σ","gui.modelsHelp":"les modèles (nom de code entre parenthèses) :","fit.summary":"{model} : {state}","fit.converged":"l’ajustement a convergé","fit.notConverged":"l’ajustement n’a pas convergé","fit.notDetermined":"(non déterminé par ces données)","fit.fullReport":"le rapport complet de l’ajustement (tel que pendulab fit l’affiche, en anglais)"},Wv={"server.too_small":"{name} = {value} : au moins {limit}","server.too_small_strict":"{name} = {value} : doit être supérieur à {limit}","server.too_large":"{name} = {value} : au plus {limit}","server.too_large_strict":"{name} = {value} : doit être inférieur à {limit}","server.missing":"{name} manque","server.unknown_key":"clé inconnue {name}","server.nonfinite_motion":"le mouvement a quitté les nombres à virgule flottante à t = {t} s ({fields} non finis) : paramètres ou départ trop extrêmes ; en pause — réinitialiser ou changer les paramètres","server.integration_stopped":"le calcul s’est arrêté ({detail}) ; en pause","server.throttled":"trop de commandes : {lost} ignorées ; en envoyer au plus {per_second} par seconde","server.server_full":"le serveur est plein : {active} sessions du labo sont ouvertes, le maximum qu’il sert à la fois ; fermer un autre onglet ou réessayer plus tard","server.device_full":"trop de sessions du labo depuis votre appareil : {have} sont ouvertes, le maximum par appareil ; fermer un autre onglet","server.device_busy":"trop de calculs à la fois depuis votre appareil : au plus {most} peuvent tourner ou attendre pour un appareil ; attendre les réponses, puis réessayer","server.step_too_small":"le pas est devenu trop petit à t = {t} s (h = {h} s) : le mouvement change trop vite pour les tolérances","server.diverged":"l’intégration a divergé après t = {t} s avec la méthode {method} (dt = {dt} s) : réduire dt, ou choisir une méthode adaptative (dop853) ou qui préserve la structure (rattle)","server.diverged_rattle":"l’intégration a divergé après t = {t} s avec la méthode {method} (dt = {dt} s) : réduire dt (le pas doit résoudre le mouvement le plus rapide, dt·ω ≪ 1)","server.diverged_dop853":"l’intégration a divergé après t = {t} s avec la méthode {method} (dt = {dt} s) : réduire rtol et atol, ou choisir rattle, qui préserve la structure","server.diverged_dt":"l’intégration a divergé après t = {t} s avec la méthode {method} (dt = {dt} s) : réduire dt","server.near_pole":"le calcul a atteint un pôle (le pendule tout droit en haut ou en bas) à t = {t} s, où ces équations échouent : choisir une méthode cartésienne","server.not_finite":"{name}[{index}] = {value} n’est pas un nombre fini","server.off_sphere":"le départ n’est pas sur la sphère : {what} = {value} dépasse la tolérance {tolerance}","server.invalid_parameter":"{name} = {value} n’est pas permis : {allowed}","server.unknown_model":"modèle inconnu {model} ; disponibles : {available}","server.not_lab_model":"le modèle {model} ne tourne pas dans le labo (utiliser pendulab run) ; les modèles du labo : {available}","server.unknown_parameter":"le modèle {model} n’a pas de paramètre {name} ; ses paramètres : {available}","server.no_parameters":"le modèle {model} n’a pas de paramètre {name} ; il n’en a pas d’autres que longueur, masse, g","server.still_stepping":"calcul en cours : {waiting} pas attendent d’être faits (au plus {most}) ; attendre l’image, ou mettre en pause","server.method_not_for_spring":"la méthode {method} ne peut pas calculer le modèle {model} (il quitte la sphère : rattle y applique Störmer–Verlet (ordre 2), rattle4 sa composition triple jump (ordre 4)) ; choisir parmi {available}","server.method_not_for_string":"la méthode {method} ne peut pas calculer le modèle {model} (ses phases tendues demandent une méthode à pas fixe qui préserve TS²) ; choisir parmi {available}","server.method_not_for_crane":"la méthode {method} ne peut pas calculer le modèle {model} (le mode grue calcule sa charge avec l’intégrateur de grue, DOP853 adaptatif avec projection sur le câble) ; choisir {available}","server.not_crane":"pas en mode grue (le labo calcule le modèle {model}) : l’activer d’abord avec le bouton « Mode grue »","server.internal_error":"erreur interne du serveur (un défaut du logiciel : merci de le signaler) ; détails (en anglais) : {detail}","server.busy":"occupé : {waiting} calculs attendent déjà ; réessayer dans un instant","server.work_timeout":"le calcul a duré plus de {seconds} s et a été arrêté ; essayer moins de données, moins de paramètres ou un modèle plus simple","server.not_json":"la requête n’est pas du JSON","server.out_of_memory":"la requête demande plus de mémoire que le serveur n’en a pour elle","server.worker_died":"le processus de calcul du serveur s’est arrêté (code de sortie {code}) ; la requête demande peut-être plus de mémoire que le serveur n’en a","server.data_too_many_rows":"{file} : {rows} lignes de données ; au plus {most} mesures sont ajustées : alléger les données","server.data_not_number":"{file} : ligne {row} (ligne {line} du fichier), colonne {column} : {cell} n’est pas un nombre","server.data_cell_infinite":"{file} : ligne {row} (ligne {line} du fichier), colonne {column} : {cell} est infini ou trop grand pour un nombre","server.data_cell_subnormal":"{file} : ligne {row} (ligne {line} du fichier), colonne {column} : {cell} est si proche de 0 que ce n’est pas une mesure : écrire 0","server.data_cell_beyond":"{file} : ligne {row} (ligne {line} du fichier), colonne {column} : {cell} dépasse ±{limit} {unit} : vérifier l’unité de la colonne","server.data_times_too_close":"{file} : ligne {row} (ligne {line} du fichier), colonne {column} : {cell} n’est qu’à {step} s d’un autre instant ; des mesures à moins de {most} s l’une de l’autre ne se distinguent pas","server.data_row_short":"{file} : la ligne {row} (ligne {line} du fichier) a {have} valeurs ; les colonnes utilisées en demandent {need}","server.data_long_line":"{file} : la ligne {line} a {chars} caractères et n’est pas une ligne de nombres ; une ligne d’en-tête en a au plus {most}","server.data_no_rows_in_first":"{file} : aucune ligne de nombres dans les {lines} premières lignes : est-ce un fichier de données ?","server.data_no_rows":"{file} : aucune ligne de nombres","server.data_linear_acceleration":"{file} : la colonne {column} est une accélération linéaire (le téléphone a retiré la pesanteur) ; l’ajustement demande l’accélération avec la pesanteur (p. ex. phyphox « Accélération avec g »)","server.data_pixels":"{file} : la colonne {column} est en pixels ; la convertir d’abord en mètres (une règle de longueur connue dans la vidéo donne les mètres par pixel)","server.data_bad_unit":"{file} : la colonne {column} a l’unité {unit} ; sont permises {allowed}","server.data_no_time":"{file} : pas de colonne de temps t parmi les colonnes {columns} : nommer les colonnes dans la première ligne du fichier (t, x, y, z, theta, phi, angle …)","server.data_repeated_columns":"{file} : la ou les colonnes {repeated} apparaissent plusieurs fois parmi {columns} (plusieurs pistes ou séries dans un fichier ?) : en garder une","server.data_no_header":"{file} : le fichier n’a pas de ligne de noms de colonnes : les écrire au-dessus des nombres (p. ex. t,x,y,z)","server.data_unknown_columns":"{file} : nom(s) de colonne inconnu(s) {unknown} ; utiliser {allowed}","server.data_components":"{file} : {kind} demande les trois composantes {parts} ; trouvé seulement {found}","server.data_positions_alone":"{file} : la ou les colonnes de position {have} seules ; les positions sont x, y, z, ou x, z (une caméra de côté), ou x, y (vu d’en haut)","server.data_crane_run":"{file} : une course de grue (pendulab crane run --out) avec les colonnes {columns} : sa charge pend d’un chariot qui se déplace, peut-être sous un crochet et à un câble hissé, ce qu’aucun modèle de l’ajustement (un point de suspension fixe) ne décrit. Un ajustement demande t, x, y, z d’un pendule, tels que {command} les écrit ; pour le balancement d’une grue après le déplacement, écrire t et l’écart de la charge au point de suspension (payload_x - pivot_x, payload_y - pivot_y) en t,x,y","server.data_crane_grid":"{file} : une grille de grue (pendulab crane grid --out) avec les colonnes {columns} : une ligne par cas, aucune série temporelle à ajuster. Un ajustement demande t, x, y, z d’un pendule, tels que {command} les écrit","server.data_no_columns":"{file} : aucune colonne de données parmi {columns} : les nommer t, x, y, z, theta, phi ou angle (docs/fit.md)","server.data_too_few":"seulement {have} mesures utilisables : un ajustement en demande au moins {need}","server.data_time_twice":"l’instant t = {t} s apparaît deux fois : chaque mesure a besoin de son propre instant","server.data_theta_range":"l’angle θ à la verticale doit être entre 0 et π rad ; les données vont de {lo} à {hi} : des degrés au lieu de radians ?","server.data_value_beyond":"{kind} à la ligne {row} (triée par temps) : {value} dépasse ±{limit} en unités SI ; une mesure de pendule ne le fait jamais : vérifier les unités et les colonnes du fichier","server.data_span":"l’enregistrement dure {span} s ; un ajustement demande de {least} s à {most} s (temps en secondes ?)","server.data_spacing":"les instants {t1} s et {t2} s ne sont qu’à {gap} s l’un de l’autre : un arrondi, pas une mesure","server.data_not_csv":"{file} : pas un fichier CSV lisible","server.fit_unknown_model":"modèle {model} : utiliser l’un de {allowed}","server.fit_cannot_fit":"{param} ne peut pas être ajusté avec le modèle {model} ; choisir parmi {allowed}","server.fit_planar_phi":"une oscillation dans un plan garde l’angle latéral et sa vitesse à 0 : ne pas les ajuster","server.fit_pivot_needs_positions":"la position du point de suspension ne s’ajuste qu’à partir de positions ; ces données n’en ont pas","server.fit_t_offset_ideal":"t_offset ne s’ajuste que pour le pendule idéal","server.fit_failed":"l’ajustement de {file} a échoué : les données contiennent des valeurs que l’ajustement ne peut pas suivre en virgule flottante (temps ou positions extrêmement éloignés ou rapprochés, ou un bruit loin de l’échelle des données)"},qv={"scenario.conical":"Pendule conique à 45°","scenario.damped":"Rosette amortie (c = 0.05 1/s)","scenario.foucault":"Pendule de Foucault à 49° N, rotation de la Terre exagérée (Ω = 0.02 rad/s)","scenario.inverted_g":"Gravité inversée : la rosette en miroir","scenario.near_top":"Lâché juste sous le sommet","scenario.over_the_top":"Par-dessus le sommet : tours dans un plan","scenario.planar_large":"Oscillation plane d’amplitude 150°","scenario.rosette":"Rosette : lâché à 60° avec un élan latéral","scenario.crane_hoist":"Pont roulant : déplacement de 8 m mis en forme ZV en levant de 12 m à 6 m, par vent de travers","scenario.slewing_crane":"Grue pivotante : R = 5 m, ω = 0.3 rad/s, l = 10 m","scenario.small_ellipse":"Petite ellipse avec précession d’Airy","scenario.string_slack":"Pendule à fil : fil détendu à z = l/2, choc inélastique","scenario.swinging_spring":"Ressort oscillant à la résonance 1:1:2","scenario.zero_g":"Gravité nulle : un grand cercle","modelHelp.ideal":"une tige sans frottement : le pendule des manuels","modelHelp.damped":"avec frottement, résistance de l’air ou poussée périodique","modelHelp.rotating":"vu depuis la Terre qui tourne : le plan d’oscillation tourne (Foucault)","modelHelp.slewing":"suspendu à la flèche d’une grue qui tourne","modelHelp.vibrating":"le point d’attache secoué de haut en bas : il peut tenir à l’envers (Kapitza)","modelHelp.sampled_pivot":"le point d’attache suit une trajectoire donnée","modelHelp.spring":"un ressort au lieu d’une tige : il oscille et rebondit","modelHelp.string":"un fil au lieu d’une tige : il peut se détendre puis se tendre d’un coup","key.space":"Espace","key.page":"Pg préc. / Pg suiv.","key.shift":"Maj","toolbar.simpleShort":"Simple","toolbar.simple":"vue simple : seulement les outils de classe (longueur, masse, gravité, frottement, chronomètre, période, règle, énergie) ; appuyer à nouveau pour tout voir","extras.add":"+ un autre pendule (longueur, masse, départ propres)","extras.pendulum":"pendule {n}","extras.remove":"retirer le pendule {n}","extras.title":"Jusqu’à quatre pendules","extras.hint":"Avec le deuxième pendule sur « longueur, masse et départ propres » : ajouter les pendules 3 et 4, puis « démarrer les deux » les démarre tous, chacun chronométré par sa propre mesure de période."},Xv={length:["longueur l","longueur de la tige du point de suspension à la masse"],mass:["masse m","masse de la boule"],g:["pesanteur g","intensité de la pesanteur (tout signe ; 0 permis)"],damping:["frottement (amortissement linéaire) c","force de frottement −m c v, proportionnelle à la vitesse"],drag:["résistance de l’air c_q","force −m c_q |v| v, quadratique en vitesse"],friction:["frottement sec au point de suspension ε_f","frottement sec (Coulomb) au point de suspension : un couple m l² ε_f contre l’oscillation, quelle que soit sa vitesse"],friction_speed:["vitesse de lissage du frottement sec ω_ε","sous cette vitesse angulaire le frottement sec s’efface en douceur, comme tanh(|ω|/ω_ε)"],forcing_amplitude:["forçage : intensité A","force périodique par masse A cos(ω t + ψ) dans la direction e"],forcing_omega:["forçage : pulsation ω","à quelle vitesse le forçage oscille"],forcing_phase:["forçage : phase ψ","phase du forçage à t = 0"],forcing_x:["direction du forçage e : x","composante x de la direction du forçage (normalisée)"],forcing_y:["direction du forçage e : y","composante y de la direction du forçage"],forcing_z:["direction du forçage e : z","composante z de la direction du forçage"],gravity_x:["direction de la pesanteur d : x","composante x de la direction de la pesanteur (normalisée)"],gravity_y:["direction de la pesanteur d : y","composante y de la direction de la pesanteur"],gravity_z:["direction de la pesanteur d : z","composante z de la direction de la pesanteur"],frame_rate:["vitesse de rotation du référentiel |Ω|","à quelle vitesse tourne le référentiel (Terre : 7,292e-5)"],latitude:["latitude λ","latitude du lieu (pendule de Foucault)"],radius:["rayon de la flèche R","distance du point de suspension à l’axe de rotation de la grue"],rate:["vitesse de rotation de la grue ω","à quelle vitesse tourne la flèche"],height:["hauteur du point de suspension h","hauteur de la flèche"],amplitude:["amplitude de vibration A","amplitude de l’oscillation verticale du point de suspension"],frequency:["fréquence de vibration ν","pulsation de l’oscillation du point de suspension"],stiffness:["raideur du ressort k","raideur du ressort ; la longueur l est la longueur au repos"],restitution:["coefficient de restitution e","élasticité du fil quand il se tend d’un coup (0 … 1)"]},$v={ideal:"Pendule idéal",damped:"Amorti et forcé",rotating:"Sur la Terre qui tourne (Foucault)",slewing:"Grue pivotante",vibrating:"Point de suspension vibrant (Kapitza)",sampled_pivot:"Point de suspension sur un chemin donné",spring:"Ressort oscillant",string:"Pendule à fil",crane:"Pont roulant (mode grue)"},Kv={...Hv,...Vv,...Gv,...Wv,...qv},Ja={en:{name:"English",words:Fs,params:{},models:{crane:"Gantry crane (crane mode)"}},de:{name:"Deutsch",words:Bv,params:Ov,models:zv},fr:{name:"Français",words:Kv,params:Xv,models:$v}};let Qa="en";function Jl(n){return typeof n=="string"&&Object.hasOwn(Ja,n)}function Yv(n,e,t){if(Jl(n))return n;if(Jl(e))return e;for(const i of t){const s=i.toLowerCase().split("-")[0];if(Jl(s))return s}return"en"}function Zv(n){Qa=n}function eo(){return Qa}function T(n,e={}){const t=Ja[Qa].words;return zp(t[n]??Fs[n],e)}function zp(n,e={}){return n.replace(/\{(\w+)\}/g,(t,i)=>i in e?String(e[i]):t)}function hd(n,e,t){return Ja[Qa].params[n]??[e,t]}function bi(n,e){return Ja[Qa].models[n]??e}function ul(n,e){const t=`method.${n}`;return Object.hasOwn(Fs,t)?T(t):T("method.other",{name:n,n:e})}function Bp(n){const e=`kind.${n}`;return Object.hasOwn(Fs,e)?T(e):n}function gh(n,e){const t=`scenario.${n}`;return Object.hasOwn(Fs,t)?T(t):e??n}function jv(n,e){const t=`modelHelp.${n}`;return Object.hasOwn(Fs,t)?T(t):e}function fd(n,e){const t=typeof n=="object"&&n!==null?n:{},i=typeof t.detail=="string"?t.detail:e;if(typeof t.key!="string")return i;const s=typeof t.values=="object"&&t.values!==null?t.values:{};return Hp({message:i,key:t.key,values:s})}function Hp(n){const e=`server.${n.key??""}`;if(n.key===void 0||!Object.hasOwn(Fs,e))return n.message;const t={...n.values??{}};typeof t.model=="string"&&(t.model=bi(t.model,t.model)),typeof t.name=="string"&&(t.name=hd(t.name,t.name,"")[0]);const i=`server.${String(t.why)}`;return n.key==="integration_stopped"&&typeof t.why=="string"&&Object.hasOwn(Fs,i)&&(t.detail=T(i,t)),T(e,t)}const Jv=["spring","string","crane"];function Qv(n){return!Jv.includes(n??"ideal")}function pd(n){return n==="spring"?T("note.spring"):n==="string"?T("note.string"):null}function Kc(n,e){return n==="spring"?"coil":n==="string"?e?"taut string":"slack string":"rod"}function ft(n,e=6){if(n==null||Number.isNaN(n))return"—";if(!Number.isFinite(n))return n>0?"∞":"−∞";if(n===0)return"0";const t=Math.abs(n);return t>=.001&&t<1e6?n.toPrecision(e):n.toExponential(e-1)}function Di(n){return n.validity.badInput||n.value.trim()===""?NaN:Number(n.value)}function Yc(n){if(Array.isArray(n))return`[${n.map(Yc).join(", ")}]`;if(n!==null&&typeof n=="object"){const e=Object.entries(n).filter(([,t])=>t!==void 0);return e.sort(([t],[i])=>t<i?-1:t>i?1:0),`{${e.map(([t,i])=>`${JSON.stringify(t)}: ${Yc(i)}`).join(", ")}}`}return JSON.stringify(n)??"null"}const e_=5;function t_(n){const e=n.kind==="slack"?T("event.slack"):T("event.taut",{lost:ft(n.energy_lost,3)}),t=n.skipped>0?T(n.skipped>1?"event.skippedMany":"event.skippedOne",{n:n.skipped}):"";return`t = ${n.t.toFixed(3)} s: ${e}${t}`}function n_(n){return n.kind==="slack"?[T("event.slackRow"),`t = ${ft(n.t,6)} s`,""]:[T("event.tautRow"),T("event.tautValue",{t:ft(n.t,6),lost:ft(n.energy_lost,4)}),"J"]}function i_(n,e,t,i=e_){if(t===null||e.epoch!==t)return n;const s=[...n,e];return s.length>i?s.slice(s.length-i):s}function s_(n){return n.replace(/\s*\((?:docs\/theory\.md\s*)?(?:T-\d+\.\d+|§\s?\d+)(?:[,;]\s*(?:T-\d+\.\d+|§\s?\d+))*\)/g,"").replace(/\s*(?:docs\/theory\.md\s*)?(?:T-\d+\.\d+|§\s?\d+)/g,"").replace(/\s+([,;.:)])/g,"$1").replace(/[,;]+\)/g,")").replace(/\(\s*\)/g,"").replace(/\s{2,}/g," ").trim()}let md=!1;function Jo(){return md}function Zc(n){if(!(n instanceof HTMLElement)||!n.hasAttribute("title"))return;const e=n.title;e!==n.dataset.titleShown&&(n.dataset.titleFull=e);const t=n.dataset.titleFull??e,i=md?t:s_(t);n.dataset.titleShown=i,e!==i&&(n.title=i)}function Vp(n){n instanceof Element&&Zc(n);for(const e of n.querySelectorAll("[title]"))Zc(e)}function Gp(n){md=n,document.body.classList.toggle("advanced",n),Vp(document.body)}function r_(){let n=!1;try{n=window.localStorage?.getItem("pendulab.advanced")==="1"}catch{n=!1}Gp(n),new MutationObserver(e=>{for(const t of e){t.type==="attributes"&&t.target instanceof Element&&Zc(t.target);for(const i of t.addedNodes)i instanceof Element&&Vp(i)}}).observe(document.body,{subtree:!0,childList:!0,attributes:!0,attributeFilter:["title"]})}function a_(n){try{window.localStorage?.setItem("pendulab.advanced",n?"1":"0")}catch{}Gp(n)}function o_(n,e){const t=e.reference,i=e.status,s=e.tensionExtremes,r=[["t",ft(n?.t,7),"s"],[T("data.energy"),ft(n?.energy,10),"J"],[T("data.energyChange"),n&&t?ft(n.energy-t.energy,3):"—","J"],[T("data.spin"),ft(n?.j3,10),"kg m²/s"],[T("data.spinChange"),n&&t?ft(n.j3-t.j3,3):"—","kg m²/s"],[T("data.tension"),ft(n?.tension,6),"N"],[T("data.tensionMin"),s?`${ft(s.min,6)} (t = ${ft(s.tMin,4)} s)`:"—","N"],[T("data.tensionMax"),s?`${ft(s.max,6)} (t = ${ft(s.tMax,4)} s)`:"—","N"],[T("data.height"),ft(n?.x[2],6),"m"],[T("data.method"),i?`${ul(i.method,0)}${i.adaptive?"":`, dt = ${i.dt} s`}`:"—",""],[T("data.state"),i?`${i.paused?T("data.paused"):T("data.running")}${i.lagging?T("data.lagging"):""}`:"—",""],...l_(n,i)];i&&i.model!=="ideal"&&(r.splice(1,0,[T("data.model"),bi(i.model,i.model),""]),r.splice(4,0,[T("data.power"),ft(n?.power,6),"W"]));const a=r.findIndex(l=>l[0]===T("data.tension")),o=Kc(i?.model,n?.taut??!0);if(o==="coil"&&i){const l=n?Math.hypot(...n.x):null;r[a]=[T("data.springForce"),ft(n?.tension,6),"N"],r.splice(a+1,0,[T("data.springLength"),ft(l,6),"m"],[T("data.stretch"),l===null?"—":ft(l-i.params.length,4),"m"])}else o==="slack string"?(r[a]=[T("data.tension"),T("data.slackZero"),"N"],r.splice(a+1,0,[T("data.string"),T("data.slack",{r:ft(n?Math.hypot(...n.x):null,5)}),""])):o==="taut string"&&r.splice(a+1,0,[T("data.string"),T("data.taut"),""]);if(i?.model==="string"){const l=[...e.events].reverse().map(n_);r.push(...l.length>0?l:[[T("data.events"),T("data.noEvents"),""]])}return r}function l_(n,e){const t=e?.error_estimate;if(!e||!t)return[];if(t.how===null)return[[T("data.errorHow"),e.model==="crane"?T("data.errorCrane"):t.note??T("data.errorNone"),""]];const i=ft(t.since,6),s=t.how==="exact"?T("data.howExact",{since:i}):t.how==="richardson"?T("data.howRichardson",{dt:ft(t.reference.dt,3),p:t.order??"?",since:i}):T("data.howCompanion",{rtol:ft(t.reference.rtol,3),since:i}),r=n?.errorX,a=r!==void 0&&r>=0;return[[T("data.error"),a?ft(r,3):r===void 0?"—":T("data.errorPaused"),a?"m":""],[T("data.errorRel"),a?ft(r/e.params.length,3):"—",""],[T("data.errorHow"),s,""]]}function c_(n){const e=n.status,t=pd(e?.model);return t!==null?t:e&&e.model!=="ideal"?T("note.exactIdeal",{model:bi(e.model,e.model)}):n.exactError??u_(n.exact)}function u_(n){return n===null||n.phases!==null||n.phases_note===null?"":n.kind==="great_circle"?T("note.phasesNoGravity"):T("note.phasesPlanar",{kind:Bp(n.kind)})}function d_(n){if(n===null)return[];const e=n.turning_heights,t=[[T("data.kind"),Bp(n.kind),""],[T("data.turning"),`${ft(e[0])}, ${ft(e[1])}`,"m"]];return e.length>2&&Jo()&&t.push([T("data.z3"),ft(e[2]),"m"]),t.push([n.kind==="planar"?T("data.swingPeriod"):T("data.periodZ"),n.period_z_infinite?"∞":ft(n.period_z),"s"]),n.azimuth_advance!==null&&t.push([T("data.advance"),ft(n.azimuth_advance),"rad"]),n.rotation_number!==null&&Jo()&&t.push([T("data.rotation"),ft(n.rotation_number),""]),n.phases!==null&&Jo()&&(t.push([T("data.dynamic"),ft(n.phases.dynamic),"rad"]),t.push([T("data.geometric"),ft(n.phases.geometric),"rad"])),t}class h_{live;exactTable;note;constructor(e){const t=i=>{const s=document.createElement("h3");s.textContent=i,e.appendChild(s)};t(T("data.now")),this.live=document.createElement("table"),e.appendChild(this.live),t(T("data.exact")),this.exactTable=document.createElement("table"),e.appendChild(this.exactTable),this.note=document.createElement("p"),this.note.className="note",e.appendChild(this.note)}fill(e,t){for(;e.rows.length>t.length;)e.deleteRow(-1);t.forEach(([i,s,r],a)=>{const o=e.rows[a]??e.insertRow();for(;o.cells.length<3;)o.insertCell();const[l,c,u]=[o.cells[0],o.cells[1],o.cells[2]];l&&l.textContent!==i&&(l.textContent=i),c&&c.textContent!==s&&(c.textContent=s),u&&u.textContent!==r&&(u.textContent=r)})}update(e,t){this.fill(this.live,o_(e,t)),this.fill(this.exactTable,d_(t.exact));const i=c_(t);this.note.textContent!==i&&(this.note.textContent=i)}}const f_=!0,Mn="u-",p_="uplot",m_=Mn+"hz",g_=Mn+"vt",v_=Mn+"title",__=Mn+"wrap",x_=Mn+"under",y_=Mn+"over",b_=Mn+"axis",Js=Mn+"off",w_=Mn+"select",S_=Mn+"cursor-x",M_=Mn+"cursor-y",E_=Mn+"cursor-pt",A_=Mn+"legend",T_=Mn+"live",R_=Mn+"inline",C_=Mn+"series",P_=Mn+"marker",vh=Mn+"label",L_=Mn+"value",Ca="width",Pa="height",va="top",_h="bottom",yr="left",Ql="right",gd="#000",xh=gd+"0",ec="mousemove",yh="mousedown",tc="mouseup",bh="mouseenter",wh="mouseleave",Sh="dblclick",D_="resize",N_="scroll",Mh="change",dl="dppxchange",vd="--",sa=typeof window<"u",jc=sa?document:null,Gr=sa?window:null,I_=sa?navigator:null;let Et,ho;function Jc(){let n=devicePixelRatio;Et!=n&&(Et=n,ho&&eu(Mh,ho,Jc),ho=matchMedia(`(min-resolution: ${Et-.001}dppx) and (max-resolution: ${Et+.001}dppx)`),Qs(Mh,ho,Jc),Gr.dispatchEvent(new CustomEvent(dl)))}function ri(n,e){if(e!=null){let t=n.classList;!t.contains(e)&&t.add(e)}}function Qc(n,e){let t=n.classList;t.contains(e)&&t.remove(e)}function Wt(n,e,t){n.style[e]=t+"px"}function Ci(n,e,t,i){let s=jc.createElement(n);return e!=null&&ri(s,e),t?.insertBefore(s,i),s}function pi(n,e){return Ci("div",n,e)}const Eh=new WeakMap;function Wi(n,e,t,i,s){let r="translate("+e+"px,"+t+"px)",a=Eh.get(n);r!=a&&(n.style.transform=r,Eh.set(n,r),e<0||t<0||e>i||t>s?ri(n,Js):Qc(n,Js))}const Ah=new WeakMap;function Th(n,e,t){let i=e+t,s=Ah.get(n);i!=s&&(Ah.set(n,i),n.style.background=e,n.style.borderColor=t)}const Rh=new WeakMap;function Ch(n,e,t,i){let s=e+""+t,r=Rh.get(n);s!=r&&(Rh.set(n,s),n.style.height=t+"px",n.style.width=e+"px",n.style.marginLeft=i?-e/2+"px":0,n.style.marginTop=i?-t/2+"px":0)}const _d={passive:!0},k_={..._d,capture:!0};function Qs(n,e,t,i){e.addEventListener(n,t,i?k_:_d)}function eu(n,e,t,i){e.removeEventListener(n,t,_d)}sa&&Jc();function Pi(n,e,t,i){let s;t=t||0,i=i||e.length-1;let r=i<=2147483647;for(;i-t>1;)s=r?t+i>>1:oi((t+i)/2),e[s]<n?t=s:i=s;return n-e[t]<=e[i]-n?t:i}function Wp(n){return(t,i,s)=>{let r=-1,a=-1;for(let o=i;o<=s;o++)if(n(t[o])){r=o;break}for(let o=s;o>=i;o--)if(n(t[o])){a=o;break}return[r,a]}}const qp=n=>n!=null,Xp=n=>n!=null&&n>0,Al=Wp(qp),F_=Wp(Xp);function U_(n,e,t,i=0,s=!1){let r=s?F_:Al,a=s?Xp:qp;[e,t]=r(n,e,t);let o=n[e],l=n[e];if(e>-1)if(i==1)o=n[e],l=n[t];else if(i==-1)o=n[t],l=n[e];else for(let c=e;c<=t;c++){let u=n[c];a(u)&&(u<o?o=u:u>l&&(l=u))}return[o??Ft,l??-Ft]}function Tl(n,e,t,i){let s=Dh(n),r=Dh(e);n==e&&(s==-1?(n*=t,e/=t):(n/=t,e*=t));let a=t==10?ps:$p,o=s==1?oi:mi,l=r==1?mi:oi,c=o(a(yn(n))),u=l(a(yn(e))),d=Kr(t,c),h=Kr(t,u);return t==10&&(c<0&&(d=Ut(d,-c)),u<0&&(h=Ut(h,-u))),i||t==2?(n=d*s,e=h*r):(n=jp(n,d),e=Rl(e,h)),[n,e]}function xd(n,e,t,i){let s=Tl(n,e,t,i);return n==0&&(s[0]=0),e==0&&(s[1]=0),s}const yd=.1,Ph={mode:3,pad:yd},ka={pad:0,soft:null,mode:0},O_={min:ka,max:ka};function hl(n,e,t,i){return Cl(t)?Lh(n,e,t):(ka.pad=t,ka.soft=i?0:null,ka.mode=i?3:0,Lh(n,e,O_))}function wt(n,e){return n??e}function z_(n,e,t){for(e=wt(e,0),t=wt(t,n.length-1);e<=t;){if(n[e]!=null)return!0;e++}return!1}function Lh(n,e,t){let i=t.min,s=t.max,r=wt(i.pad,0),a=wt(s.pad,0),o=wt(i.hard,-Ft),l=wt(s.hard,Ft),c=wt(i.soft,Ft),u=wt(s.soft,-Ft),d=wt(i.mode,0),h=wt(s.mode,0),m=e-n,g=ps(m),y=Kn(yn(n),yn(e)),p=ps(y),f=yn(p-g);(m<1e-24||f>10)&&(m=0,(n==0||e==0)&&(m=1e-24,d==2&&c!=Ft&&(r=0),h==2&&u!=-Ft&&(a=0)));let x=m||y||1e3,R=ps(x),S=Kr(10,oi(R)),C=x*(m==0?n==0?.1:1:r),w=Ut(jp(n-C,S/10),24),v=n>=c&&(d==1||d==3&&w<=c||d==2&&w>=c)?c:Ft,M=Kn(o,w<v&&n>=v?v:Ni(v,w)),F=x*(m==0?e==0?.1:1:a),L=Ut(Rl(e+F,S/10),24),D=e<=u&&(h==1||h==3&&L>=u||h==2&&L<=u)?u:-Ft,B=Ni(l,L>D&&e<=D?D:Kn(D,L));return M==B&&M==0&&(B=100),[M,B]}const B_=new Intl.NumberFormat(sa?I_.language:"en-US"),bd=n=>B_.format(n),ui=Math,Qo=ui.PI,yn=ui.abs,oi=ui.floor,xn=ui.round,mi=ui.ceil,Ni=ui.min,Kn=ui.max,Kr=ui.pow,Dh=ui.sign,ps=ui.log10,$p=ui.log2,H_=(n,e=1)=>ui.sinh(n)*e,nc=(n,e=1)=>ui.asinh(n/e),Ft=1/0;function Nh(n){return(ps((n^n>>31)-(n>>31))|0)+1}function tu(n,e,t){return Ni(Kn(n,e),t)}function Kp(n){return typeof n=="function"}function gt(n){return Kp(n)?n:()=>n}const V_=()=>{},Yp=n=>n,Zp=(n,e)=>e,G_=n=>null,Ih=n=>!0,kh=(n,e)=>n==e,W_=/\.\d*?(?=9{6,}|0{6,})/gm,ir=n=>{if(Qp(n)||Us.has(n))return n;const e=`${n}`,t=e.match(W_);if(t==null)return n;let i=t[0].length-1;if(e.indexOf("e-")!=-1){let[s,r]=e.split("e");return+`${ir(s)}e${r}`}return Ut(n,i)};function Zs(n,e){return ir(Ut(ir(n/e))*e)}function Rl(n,e){return ir(mi(ir(n/e))*e)}function jp(n,e){return ir(oi(ir(n/e))*e)}function Ut(n,e=0){if(Qp(n))return n;let t=10**e,i=n*t*(1+Number.EPSILON);return xn(i)/t}const Us=new Map;function Jp(n){return((""+n).split(".")[1]||"").length}function Va(n,e,t,i){let s=[],r=i.map(Jp);for(let a=e;a<t;a++){let o=yn(a),l=Ut(Kr(n,a),o);for(let c=0;c<i.length;c++){let u=n==10?+`${i[c]}e${a}`:i[c]*l,d=(a>=0?0:o)+(a>=r[c]?0:r[c]),h=n==10?u:Ut(u,d);s.push(h),Us.set(h,d)}}return s}const Fa={},wd=[],Yr=[null,null],Ls=Array.isArray,Qp=Number.isInteger,q_=n=>n===void 0;function Fh(n){return typeof n=="string"}function Cl(n){let e=!1;if(n!=null){let t=n.constructor;e=t==null||t==Object}return e}function X_(n){return n!=null&&typeof n=="object"}const $_=Object.getPrototypeOf(Uint8Array),em="__proto__";function Zr(n,e=Cl){let t;if(Ls(n)){let i=n.find(s=>s!=null);if(Ls(i)||e(i)){t=Array(n.length);for(let s=0;s<n.length;s++)t[s]=Zr(n[s],e)}else t=n.slice()}else if(n instanceof $_)t=n.slice();else if(e(n)){t={};for(let i in n)i!=em&&(t[i]=Zr(n[i],e))}else t=n;return t}function pn(n){let e=arguments;for(let t=1;t<e.length;t++){let i=e[t];for(let s in i)s!=em&&(Cl(n[s])?pn(n[s],Zr(i[s])):n[s]=Zr(i[s]))}return n}const K_=0,Y_=1,Z_=2;function j_(n,e,t){for(let i=0,s,r=-1;i<e.length;i++){let a=e[i];if(a>r){for(s=a-1;s>=0&&n[s]==null;)n[s--]=null;for(s=a+1;s<t&&n[s]==null;)n[r=s++]=null}}}function J_(n,e){if(t0(n)){let a=n[0].slice();for(let o=1;o<n.length;o++)a.push(...n[o].slice(1));return n0(a[0])||(a=e0(a)),a}let t=new Set;for(let a=0;a<n.length;a++){let l=n[a][0],c=l.length;for(let u=0;u<c;u++)t.add(l[u])}let i=[Array.from(t).sort((a,o)=>a-o)],s=i[0].length,r=new Map;for(let a=0;a<s;a++)r.set(i[0][a],a);for(let a=0;a<n.length;a++){let o=n[a],l=o[0];for(let c=1;c<o.length;c++){let u=o[c],d=Array(s).fill(void 0),h=e?e[a][c]:Y_,m=[];for(let g=0;g<u.length;g++){let y=u[g],p=r.get(l[g]);y===null?h!=K_&&(d[p]=y,h==Z_&&m.push(p)):d[p]=y}j_(d,m,s),i.push(d)}}return i}const Q_=typeof queueMicrotask>"u"?n=>Promise.resolve().then(n):queueMicrotask;function e0(n){let e=n[0],t=e.length,i=Array(t);for(let r=0;r<i.length;r++)i[r]=r;i.sort((r,a)=>e[r]-e[a]);let s=[];for(let r=0;r<n.length;r++){let a=n[r],o=Array(t);for(let l=0;l<t;l++)o[l]=a[i[l]];s.push(o)}return s}function t0(n){let e=n[0][0],t=e.length;for(let i=1;i<n.length;i++){let s=n[i][0];if(s.length!=t)return!1;if(s!=e){for(let r=0;r<t;r++)if(s[r]!=e[r])return!1}}return!0}function n0(n,e=100){const t=n.length;if(t<=1)return!0;let i=0,s=t-1;for(;i<=s&&n[i]==null;)i++;for(;s>=i&&n[s]==null;)s--;if(s<=i)return!0;const r=Kn(1,oi((s-i+1)/e));for(let a=n[i],o=i+r;o<=s;o+=r){const l=n[o];if(l!=null){if(l<=a)return!1;a=l}}return!0}const tm=["January","February","March","April","May","June","July","August","September","October","November","December"],nm=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function im(n){return n.slice(0,3)}const i0=nm.map(im),s0=tm.map(im),r0={MMMM:tm,MMM:s0,WWWW:nm,WWW:i0};function _a(n){return(n<10?"0":"")+n}function a0(n){return(n<10?"00":n<100?"0":"")+n}const o0={YYYY:n=>n.getFullYear(),YY:n=>(n.getFullYear()+"").slice(2),MMMM:(n,e)=>e.MMMM[n.getMonth()],MMM:(n,e)=>e.MMM[n.getMonth()],MM:n=>_a(n.getMonth()+1),M:n=>n.getMonth()+1,DD:n=>_a(n.getDate()),D:n=>n.getDate(),WWWW:(n,e)=>e.WWWW[n.getDay()],WWW:(n,e)=>e.WWW[n.getDay()],HH:n=>_a(n.getHours()),H:n=>n.getHours(),h:n=>{let e=n.getHours();return e==0?12:e>12?e-12:e},AA:n=>n.getHours()>=12?"PM":"AM",aa:n=>n.getHours()>=12?"pm":"am",a:n=>n.getHours()>=12?"p":"a",mm:n=>_a(n.getMinutes()),m:n=>n.getMinutes(),ss:n=>_a(n.getSeconds()),s:n=>n.getSeconds(),fff:n=>a0(n.getMilliseconds())};function Sd(n,e){e=e||r0;let t=[],i=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=i.exec(n);)t.push(s[0][0]=="{"?o0[s[1]]:s[0]);return r=>{let a="";for(let o=0;o<t.length;o++)a+=typeof t[o]=="string"?t[o]:t[o](r,e);return a}}const l0=new Intl.DateTimeFormat().resolvedOptions().timeZone;function c0(n,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+n+n.getTimezoneOffset()*6e4):e==l0?t=n:(t=new Date(n.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(n.getMilliseconds())),t}const sm=n=>n%1==0,fl=[1,2,2.5,5],u0=Va(10,-32,0,fl),rm=Va(10,0,32,fl),d0=rm.filter(sm),js=u0.concat(rm),Md=`
`,am="{YYYY}",Uh=Md+am,om="{M}/{D}",La=Md+om,fo=La+"/{YY}",lm="{aa}",h0="{h}:{mm}",zr=h0+lm,Oh=Md+zr,zh=":{ss}",Tt=null;function cm(n){let e=n*1e3,t=e*60,i=t*60,s=i*24,r=s*30,a=s*365,l=(n==1?Va(10,0,3,fl).filter(sm):Va(10,-3,0,fl)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,i,i*2,i*3,i*4,i*6,i*8,i*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,a,a*2,a*5,a*10,a*25,a*50,a*100]);const c=[[a,am,Tt,Tt,Tt,Tt,Tt,Tt,1],[s*28,"{MMM}",Uh,Tt,Tt,Tt,Tt,Tt,1],[s,om,Uh,Tt,Tt,Tt,Tt,Tt,1],[i,"{h}"+lm,fo,Tt,La,Tt,Tt,Tt,1],[t,zr,fo,Tt,La,Tt,Tt,Tt,1],[e,zh,fo+" "+zr,Tt,La+" "+zr,Tt,Oh,Tt,1],[n,zh+".{fff}",fo+" "+zr,Tt,La+" "+zr,Tt,Oh,Tt,1]];function u(d){return(h,m,g,y,p,f)=>{let x=[],R=p>=a,S=p>=r&&p<a,C=d(g),w=Ut(C*n,3),v=ic(C.getFullYear(),R?0:C.getMonth(),S||R?1:C.getDate()),M=Ut(v*n,3);if(S||R){let F=S?p/r:0,L=R?p/a:0,D=w==M?w:Ut(ic(v.getFullYear()+L,v.getMonth()+F,1)*n,3),B=new Date(xn(D/n)),G=B.getFullYear(),k=B.getMonth();for(let W=0;D<=y;W++){let Y=ic(G+L*W,k+F*W,1),V=Y-d(Ut(Y*n,3));D=Ut((+Y+V)*n,3),D<=y&&x.push(D)}}else{let F=p>=s?s:p,L=oi(g)-oi(w),D=M+L+Rl(w-M,F);x.push(D);let B=d(D),G=B.getHours()+B.getMinutes()/t+B.getSeconds()/i,k=p/i,W=h.axes[m]._space,Y=f/W;for(;D=Ut(D+p,n==1?0:3),!(D>y);)if(k>1){let V=oi(Ut(G+k,6))%24,Q=d(D).getHours()-V;Q>1&&(Q=-1),D-=Q*i,G=(G+k)%24;let se=x[x.length-1];Ut((D-se)/p,3)*Y>=.7&&x.push(D)}else x.push(D)}return x}}return[l,c,u]}const[f0,p0,m0]=cm(1),[g0,v0,_0]=cm(.001);Va(2,-53,53,[1]);function Bh(n,e){return n.map(t=>t.map((i,s)=>s==0||s==8||i==null?i:e(s==1||t[8]==0?i:t[1]+i)))}function Hh(n,e){return(t,i,s,r,a)=>{let o=e.find(g=>a>=g[0])||e[e.length-1],l,c,u,d,h,m;return i.map(g=>{let y=n(g),p=y.getFullYear(),f=y.getMonth(),x=y.getDate(),R=y.getHours(),S=y.getMinutes(),C=y.getSeconds(),w=p!=l&&o[2]||f!=c&&o[3]||x!=u&&o[4]||R!=d&&o[5]||S!=h&&o[6]||C!=m&&o[7]||o[1];return l=p,c=f,u=x,d=R,h=S,m=C,w(y)})}}function x0(n,e){let t=Sd(e);return(i,s,r,a,o)=>s.map(l=>t(n(l)))}function ic(n,e,t){return new Date(n,e,t)}function Vh(n,e){return e(n)}const y0="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function Gh(n,e){return(t,i,s,r)=>r==null?vd:e(n(i))}function b0(n,e){let t=n.series[e];return t.width?t.stroke(n,e):t.points.width?t.points.stroke(n,e):null}function w0(n,e){return n.series[e].fill(n,e)}const S0={show:!0,live:!0,isolate:!1,mount:V_,markers:{show:!0,width:2,stroke:b0,fill:w0,dash:"solid"},idx:null,idxs:null,values:[]};function M0(n,e){let t=n.cursor.points,i=pi(),s=t.size(n,e);Wt(i,Ca,s),Wt(i,Pa,s);let r=s/-2;Wt(i,"marginLeft",r),Wt(i,"marginTop",r);let a=t.width(n,e,s);return a&&Wt(i,"borderWidth",a),i}function E0(n,e){let t=n.series[e].points;return t._fill||t._stroke}function A0(n,e){let t=n.series[e].points;return t._stroke||t._fill}function T0(n,e){return n.series[e].points.size}const sc=[0,0];function R0(n,e,t){return sc[0]=e,sc[1]=t,sc}function po(n,e,t,i=!0){return s=>{s.button==0&&(!i||s.target==e)&&t(s)}}function rc(n,e,t,i=!0){return s=>{(!i||s.target==e)&&t(s)}}const C0={show:!0,x:!0,y:!0,lock:!1,move:R0,points:{one:!1,show:M0,size:T0,width:0,stroke:A0,fill:E0},bind:{mousedown:po,mouseup:po,click:po,dblclick:po,mousemove:rc,mouseleave:rc,mouseenter:rc},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(n,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(n,e,t,i,s)=>i-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},um={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},Ed=pn({},um,{filter:Zp}),dm=pn({},Ed,{size:10}),hm=pn({},um,{show:!1}),Ad='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',fm="bold "+Ad,pm=1.5,Wh={show:!0,scale:"x",stroke:gd,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:fm,side:2,grid:Ed,ticks:dm,border:hm,font:Ad,lineGap:pm,rotate:0},P0="Value",L0="Time",qh={show:!0,scale:"x",auto:!1,sorted:1,min:Ft,max:-Ft,idxs:[]};function D0(n,e,t,i,s){return e.map(r=>r==null?"":bd(r))}function N0(n,e,t,i,s,r,a){let o=[],l=Us.get(s)||0;t=a?t:Ut(Rl(t,s),l);for(let c=t;c<=i;c=Ut(c+s,l))o.push(Object.is(c,-0)?0:c);return o}function nu(n,e,t,i,s,r,a){const o=[],l=n.scales[n.axes[e].scale].log,c=l==10?ps:$p,u=oi(c(t));s=Kr(l,u),l==10&&(s=js[Pi(s,js)]);let d=t,h=s*l;l==10&&(h=js[Pi(h,js)]);do o.push(d),d=d+s,l==10&&!Us.has(d)&&(d=Ut(d,Us.get(s))),d>=h&&(s=d,h=s*l,l==10&&(h=js[Pi(h,js)]));while(d<=i);return o}function I0(n,e,t,i,s,r,a){let l=n.scales[n.axes[e].scale].asinh,c=i>l?nu(n,e,Kn(l,t),i,s):[l],u=i>=0&&t<=0?[0]:[];return(t<-l?nu(n,e,Kn(l,-i),-t,s):[l]).reverse().map(h=>-h).concat(u,c)}const mm=/./,k0=/[12357]/,F0=/[125]/,Xh=/1/,iu=(n,e,t,i)=>n.map((s,r)=>e==4&&s==0||r%i==0&&t.test(s.toExponential()[s<0?1:0])?s:null);function U0(n,e,t,i,s){let r=n.axes[t],a=r.scale,o=n.scales[a],l=n.valToPos,c=r._space,u=l(10,a),d=l(9,a)-u>=c?mm:l(7,a)-u>=c?k0:l(5,a)-u>=c?F0:Xh;if(d==Xh){let h=yn(l(1,a)-u);if(h<c)return iu(e.slice().reverse(),o.distr,d,mi(c/h)).reverse()}return iu(e,o.distr,d,1)}function O0(n,e,t,i,s){let r=n.axes[t],a=r.scale,o=r._space,l=n.valToPos,c=yn(l(1,a)-l(2,a));return c<o?iu(e.slice().reverse(),3,mm,mi(o/c)).reverse():e}function z0(n,e,t,i){return i==null?vd:e==null?"":bd(e)}const $h={show:!0,scale:"y",stroke:gd,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:fm,side:3,grid:Ed,ticks:dm,border:hm,font:Ad,lineGap:pm,rotate:0};function B0(n,e){let t=3+(n||1)*2;return Ut(t*e,3)}function H0(n,e){let{scale:t,idxs:i}=n.series[0],s=n._data[0],r=n.valToPos(s[i[0]],t,!0),a=n.valToPos(s[i[1]],t,!0),o=yn(a-r),l=n.series[e],c=o/(l.points.space*Et);return i[1]-i[0]<=c}const Kh={scale:null,auto:!0,sorted:0,min:Ft,max:-Ft},gm=(n,e,t,i,s)=>s,Yh={show:!0,auto:!0,sorted:0,gaps:gm,alpha:1,facets:[pn({},Kh,{scale:"x"}),pn({},Kh,{scale:"y"})]},Zh={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:gm,alpha:1,points:{show:H0,filter:null},values:null,min:Ft,max:-Ft,idxs:[],path:null,clip:null};function V0(n,e,t,i,s){return t/10}const vm={time:f_,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},G0=pn({},vm,{time:!1,ori:1}),jh={};function _m(n,e){let t=jh[n];return t||(t={key:n,plots:[],sub(i){t.plots.push(i)},unsub(i){t.plots=t.plots.filter(s=>s!=i)},pub(i,s,r,a,o,l,c){for(let u=0;u<t.plots.length;u++)t.plots[u]!=s&&t.plots[u].pub(i,s,r,a,o,l,c)}},n!=null&&(jh[n]=t)),t}const jr=1,su=2;function ar(n,e,t){const i=n.mode,s=n.series[e],r=i==2?n._data[e]:n._data,a=n.scales,o=n.bbox;let l=r[0],c=i==2?r[1]:r[e],u=i==2?a[s.facets[0].scale]:a[n.series[0].scale],d=i==2?a[s.facets[1].scale]:a[s.scale],h=o.left,m=o.top,g=o.width,y=o.height,p=n.valToPosH,f=n.valToPosV;return u.ori==0?t(s,l,c,u,d,p,f,h,m,g,y,Ll,ra,Nl,ym,wm):t(s,l,c,u,d,f,p,m,h,y,g,Dl,aa,Cd,bm,Sm)}function Td(n,e){let t=0,i=0,s=wt(n.bands,wd);for(let r=0;r<s.length;r++){let a=s[r];a.series[0]==e?t=a.dir:a.series[1]==e&&(a.dir==1?i|=1:i|=2)}return[t,i==1?-1:i==2?1:i==3?2:0]}function W0(n,e,t,i,s){let r=n.mode,a=n.series[e],o=r==2?a.facets[1].scale:a.scale,l=n.scales[o];return s==-1?l.min:s==1?l.max:l.distr==3?l.dir==1?l.min:l.max:0}function ms(n,e,t,i,s,r){return ar(n,e,(a,o,l,c,u,d,h,m,g,y,p)=>{let f=a.pxRound;const x=c.dir*(c.ori==0?1:-1),R=c.ori==0?ra:aa;let S,C;x==1?(S=t,C=i):(S=i,C=t);let w=f(d(o[S],c,y,m)),v=f(h(l[S],u,p,g)),M=f(d(o[C],c,y,m)),F=f(h(r==1?u.max:u.min,u,p,g)),L=new Path2D(s);return R(L,M,F),R(L,w,F),R(L,w,v),L})}function Pl(n,e,t,i,s,r){let a=null;if(n.length>0){a=new Path2D;const o=e==0?Nl:Cd;let l=t;for(let d=0;d<n.length;d++){let h=n[d];if(h[1]>h[0]){let m=h[0]-l;m>0&&o(a,l,i,m,i+r),l=h[1]}}let c=t+s-l,u=10;c>0&&o(a,l,i-u/2,c,i+r+u)}return a}function q0(n,e,t){let i=n[n.length-1];i&&i[0]==e?i[1]=t:n.push([e,t])}function Rd(n,e,t,i,s,r,a){let o=[],l=n.length;for(let c=s==1?t:i;c>=t&&c<=i;c+=s)if(e[c]===null){let d=c,h=c;if(s==1)for(;++c<=i&&e[c]===null;)h=c;else for(;--c>=t&&e[c]===null;)h=c;let m=r(n[d]),g=h==d?m:r(n[h]),y=d-s;m=a<=0&&y>=0&&y<l?r(n[y]):m;let f=h+s;g=a>=0&&f>=0&&f<l?r(n[f]):g,g>=m&&o.push([m,g])}return o}function Jh(n){return n==0?Yp:n==1?xn:e=>Zs(e,n)}function xm(n){let e=n==0?Ll:Dl,t=n==0?(s,r,a,o,l,c)=>{s.arcTo(r,a,o,l,c)}:(s,r,a,o,l,c)=>{s.arcTo(a,r,l,o,c)},i=n==0?(s,r,a,o,l)=>{s.rect(r,a,o,l)}:(s,r,a,o,l)=>{s.rect(a,r,l,o)};return(s,r,a,o,l,c=0,u=0)=>{c==0&&u==0?i(s,r,a,o,l):(c=Ni(c,o/2,l/2),u=Ni(u,o/2,l/2),e(s,r+c,a),t(s,r+o,a,r+o,a+l,c),t(s,r+o,a+l,r,a+l,u),t(s,r,a+l,r,a,u),t(s,r,a,r+o,a,c),s.closePath())}}const Ll=(n,e,t)=>{n.moveTo(e,t)},Dl=(n,e,t)=>{n.moveTo(t,e)},ra=(n,e,t)=>{n.lineTo(e,t)},aa=(n,e,t)=>{n.lineTo(t,e)},Nl=xm(0),Cd=xm(1),ym=(n,e,t,i,s,r)=>{n.arc(e,t,i,s,r)},bm=(n,e,t,i,s,r)=>{n.arc(t,e,i,s,r)},wm=(n,e,t,i,s,r,a)=>{n.bezierCurveTo(e,t,i,s,r,a)},Sm=(n,e,t,i,s,r,a)=>{n.bezierCurveTo(t,e,s,i,a,r)};function Mm(n){return(e,t,i,s,r)=>ar(e,t,(a,o,l,c,u,d,h,m,g,y,p)=>{let{pxRound:f,points:x}=a,R,S;c.ori==0?(R=Ll,S=ym):(R=Dl,S=bm);const C=Ut(x.width*Et,3);let w=(x.size-x.width)/2*Et,v=Ut(w*2,3),M=new Path2D,F=new Path2D,{left:L,top:D,width:B,height:G}=e.bbox;Nl(F,L-v,D-v,B+v*2,G+v*2);const k=W=>{if(l[W]!=null){let Y=f(d(o[W],c,y,m)),V=f(h(l[W],u,p,g));R(M,Y+w,V),S(M,Y,V,w,0,Qo*2)}};if(r)r.forEach(k);else for(let W=i;W<=s;W++)k(W);return{stroke:C>0?M:null,fill:M,clip:F,flags:jr|su}})}function Em(n){return(e,t,i,s,r,a)=>{i!=s&&(r!=i&&a!=i&&n(e,t,i),r!=s&&a!=s&&n(e,t,s),n(e,t,a))}}const X0=Em(ra),$0=Em(aa);function Am(n){const e=wt(n?.alignGaps,0);return(t,i,s,r)=>ar(t,i,(a,o,l,c,u,d,h,m,g,y,p)=>{[s,r]=Al(l,s,r);let f=a.pxRound,x=G=>f(d(G,c,y,m)),R=G=>f(h(G,u,p,g)),S,C;c.ori==0?(S=ra,C=X0):(S=aa,C=$0);const w=c.dir*(c.ori==0?1:-1),v={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:jr},M=v.stroke;let F=!1;if(r-s>=y*4){let G=de=>t.posToVal(de,c.key,!0),k=null,W=null,Y,V,le,j=x(o[w==1?s:r]),Q=x(o[s]),se=x(o[r]),he=G(w==1?Q+1:se-1);for(let de=w==1?s:r;de>=s&&de<=r;de+=w){let ee=o[de],_e=(w==1?ee<he:ee>he)?j:x(ee),Te=l[de];_e==j?Te!=null?(V=Te,k==null?(S(M,_e,R(V)),Y=k=W=V):V<k?k=V:V>W&&(W=V)):Te===null&&(F=!0):(k!=null&&C(M,j,R(k),R(W),R(Y),R(V)),Te!=null?(V=Te,S(M,_e,R(V)),k=W=Y=V):(k=W=null,Te===null&&(F=!0)),j=_e,he=G(j+w))}k!=null&&k!=W&&le!=j&&C(M,j,R(k),R(W),R(Y),R(V))}else for(let G=w==1?s:r;G>=s&&G<=r;G+=w){let k=l[G];k===null?F=!0:k!=null&&S(M,x(o[G]),R(k))}let[D,B]=Td(t,i);if(a.fill!=null||D!=0){let G=v.fill=new Path2D(M),k=a.fillTo(t,i,a.min,a.max,D),W=R(k),Y=x(o[s]),V=x(o[r]);w==-1&&([V,Y]=[Y,V]),S(G,V,W),S(G,Y,W)}if(!a.spanGaps){let G=[];F&&G.push(...Rd(o,l,s,r,w,x,e)),v.gaps=G=a.gaps(t,i,s,r,G),v.clip=Pl(G,c.ori,m,g,y,p)}return B!=0&&(v.band=B==2?[ms(t,i,s,r,M,-1),ms(t,i,s,r,M,1)]:ms(t,i,s,r,M,B)),v})}function K0(n){const e=wt(n.align,1),t=wt(n.ascDesc,!1),i=wt(n.alignGaps,0),s=wt(n.extend,!1);return(r,a,o,l)=>ar(r,a,(c,u,d,h,m,g,y,p,f,x,R)=>{[o,l]=Al(d,o,l);let S=c.pxRound,{left:C,width:w}=r.bbox,v=Q=>S(g(Q,h,x,p)),M=Q=>S(y(Q,m,R,f)),F=h.ori==0?ra:aa;const L={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:jr},D=L.stroke,B=h.dir*(h.ori==0?1:-1);let G=M(d[B==1?o:l]),k=v(u[B==1?o:l]),W=k,Y=k;s&&e==-1&&(Y=C,F(D,Y,G)),F(D,k,G);for(let Q=B==1?o:l;Q>=o&&Q<=l;Q+=B){let se=d[Q];if(se==null)continue;let he=v(u[Q]),de=M(se);e==1?F(D,he,G):F(D,W,de),F(D,he,de),G=de,W=he}let V=W;s&&e==1&&(V=C+w,F(D,V,G));let[le,j]=Td(r,a);if(c.fill!=null||le!=0){let Q=L.fill=new Path2D(D),se=c.fillTo(r,a,c.min,c.max,le),he=M(se);F(Q,V,he),F(Q,Y,he)}if(!c.spanGaps){let Q=[];Q.push(...Rd(u,d,o,l,B,v,i));let se=c.width*Et/2,he=t||e==1?se:-se,de=t||e==-1?-se:se;Q.forEach(ee=>{ee[0]+=he,ee[1]+=de}),L.gaps=Q=c.gaps(r,a,o,l,Q),L.clip=Pl(Q,h.ori,p,f,x,R)}return j!=0&&(L.band=j==2?[ms(r,a,o,l,D,-1),ms(r,a,o,l,D,1)]:ms(r,a,o,l,D,j)),L})}function Qh(n,e,t,i,s,r,a=Ft){if(n.length>1){let o=null;for(let l=0,c=1/0;l<n.length;l++)if(e[l]!==void 0){if(o!=null){let u=yn(n[l]-n[o]);u<c&&(c=u,a=yn(t(n[l],i,s,r)-t(n[o],i,s,r)))}o=l}}return a}function Y0(n){n=n||Fa;const e=wt(n.size,[.6,Ft,1]),t=n.align||0,i=n.gap||0;let s=n.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;const r=gt(s),a=1-e[0],o=wt(e[1],Ft),l=wt(e[2],1),c=wt(n.disp,Fa),u=wt(n.each,m=>{}),{fill:d,stroke:h}=c;return(m,g,y,p)=>ar(m,g,(f,x,R,S,C,w,v,M,F,L,D)=>{let B=f.pxRound,G=t,k=i*Et,W=o*Et,Y=l*Et,V,le;S.ori==0?[V,le]=r(m,g):[le,V]=r(m,g);const j=S.dir*(S.ori==0?1:-1);let Q=S.ori==0?Nl:Cd,se=S.ori==0?u:(Ce,$e,nt,Se,kt,Be,Xe)=>{u(Ce,$e,nt,kt,Se,Xe,Be)},he=wt(m.bands,wd).find(Ce=>Ce.series[0]==g),de=he!=null?he.dir:0,ee=f.fillTo(m,g,f.min,f.max,de),me=B(v(ee,C,D,F)),_e,Te,we,Ge=L,tt=B(f.width*Et),He=!1,ct=null,rt=null,Qe=null,qt=null;d!=null&&(tt==0||h!=null)&&(He=!0,ct=d.values(m,g,y,p),rt=new Map,new Set(ct).forEach(Ce=>{Ce!=null&&rt.set(Ce,new Path2D)}),tt>0&&(Qe=h.values(m,g,y,p),qt=new Map,new Set(Qe).forEach(Ce=>{Ce!=null&&qt.set(Ce,new Path2D)})));let{x0:zt,size:on}=c;if(zt!=null&&on!=null){G=1,x=zt.values(m,g,y,p),zt.unit==2&&(x=x.map(nt=>m.posToVal(M+nt*L,S.key,!0)));let Ce=on.values(m,g,y,p);on.unit==2?Te=Ce[0]*L:Te=w(Ce[0],S,L,M)-w(0,S,L,M),Ge=Qh(x,R,w,S,L,M,Ge),we=Ge-Te+k}else Ge=Qh(x,R,w,S,L,M,Ge),we=Ge*a+k,Te=Ge-we;we<1&&(we=0),tt>=Te/2&&(tt=0),we<5&&(B=Yp);let Nt=we>0,En=Ge-we-(Nt?tt:0);Te=B(tu(En,Y,W)),_e=(G==0?Te/2:G==j?0:Te)-G*j*((G==0?k/2:0)+(Nt?tt/2:0));const _t={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},mn=He?null:new Path2D;let Kt=null;if(he!=null)Kt=m.data[he.series[1]];else{let{y0:Ce,y1:$e}=c;Ce!=null&&$e!=null&&(R=$e.values(m,g,y,p),Kt=Ce.values(m,g,y,p))}let ln=V*Te,O=le*Te;for(let Ce=j==1?y:p;Ce>=y&&Ce<=p;Ce+=j){let $e=R[Ce];if($e==null)continue;if(Kt!=null){let X=Kt[Ce]??0;if($e-X==0)continue;me=v(X,C,D,F)}let nt=S.distr!=2||c!=null?x[Ce]:Ce,Se=w(nt,S,L,M),kt=v(wt($e,ee),C,D,F),Be=B(Se-_e),Xe=B(Kn(kt,me)),P=B(Ni(kt,me)),b=Xe-P;if($e!=null){let X=$e<0?O:ln,ue=$e<0?ln:O;He?(tt>0&&Qe[Ce]!=null&&Q(qt.get(Qe[Ce]),Be,P+oi(tt/2),Te,Kn(0,b-tt),X,ue),ct[Ce]!=null&&Q(rt.get(ct[Ce]),Be,P+oi(tt/2),Te,Kn(0,b-tt),X,ue)):Q(mn,Be,P+oi(tt/2),Te,Kn(0,b-tt),X,ue),se(m,g,Ce,Be-tt/2,P,Te+tt,b)}}return tt>0?_t.stroke=He?qt:mn:He||(_t._fill=f.width==0?f._fill:f._stroke??f._fill,_t.width=0),_t.fill=He?rt:mn,_t})}function Z0(n,e){const t=wt(e?.alignGaps,0);return(i,s,r,a)=>ar(i,s,(o,l,c,u,d,h,m,g,y,p,f)=>{[r,a]=Al(c,r,a);let x=o.pxRound,R=V=>x(h(V,u,p,g)),S=V=>x(m(V,d,f,y)),C,w,v;u.ori==0?(C=Ll,v=ra,w=wm):(C=Dl,v=aa,w=Sm);const M=u.dir*(u.ori==0?1:-1);let F=R(l[M==1?r:a]),L=F,D=[],B=[];for(let V=M==1?r:a;V>=r&&V<=a;V+=M)if(c[V]!=null){let j=l[V],Q=R(j);D.push(L=Q),B.push(S(c[V]))}const G={stroke:n(D,B,C,v,w,x),fill:null,clip:null,band:null,gaps:null,flags:jr},k=G.stroke;let[W,Y]=Td(i,s);if(o.fill!=null||W!=0){let V=G.fill=new Path2D(k),le=o.fillTo(i,s,o.min,o.max,W),j=S(le);v(V,L,j),v(V,F,j)}if(!o.spanGaps){let V=[];V.push(...Rd(l,c,r,a,M,R,t)),G.gaps=V=o.gaps(i,s,r,a,V),G.clip=Pl(V,u.ori,g,y,p,f)}return Y!=0&&(G.band=Y==2?[ms(i,s,r,a,k,-1),ms(i,s,r,a,k,1)]:ms(i,s,r,a,k,Y)),G})}function j0(n){return Z0(J0,n)}function J0(n,e,t,i,s,r){const a=n.length;if(a<2)return null;const o=new Path2D;if(t(o,n[0],e[0]),a==2)i(o,n[1],e[1]);else{let l=Array(a),c=Array(a-1),u=Array(a-1),d=Array(a-1);for(let h=0;h<a-1;h++)u[h]=e[h+1]-e[h],d[h]=n[h+1]-n[h],c[h]=u[h]/d[h];l[0]=c[0];for(let h=1;h<a-1;h++)c[h]===0||c[h-1]===0||c[h-1]>0!=c[h]>0?l[h]=0:(l[h]=3*(d[h-1]+d[h])/((2*d[h]+d[h-1])/c[h-1]+(d[h]+2*d[h-1])/c[h]),isFinite(l[h])||(l[h]=0));l[a-1]=c[a-2];for(let h=0;h<a-1;h++)s(o,n[h]+d[h]/3,e[h]+l[h]*d[h]/3,n[h+1]-d[h]/3,e[h+1]-l[h+1]*d[h]/3,n[h+1],e[h+1])}return o}const ru=new Set;function ef(){for(let n of ru)n.syncRect(!0)}sa&&(Qs(D_,Gr,ef),Qs(N_,Gr,ef,!0),Qs(dl,Gr,()=>{On.pxRatio=Et}));const Q0=Am(),ex=Mm();function tf(n,e,t,i){return(i?[n[0],n[1]].concat(n.slice(2)):[n[0]].concat(n.slice(1))).map((r,a)=>au(r,a,e,t))}function tx(n,e){return n.map((t,i)=>i==0?{}:pn({},e,t))}function au(n,e,t,i){return pn({},e==0?t:i,n)}function Tm(n,e,t){return e==null?Yr:[e,t]}const nx=Tm;function ix(n,e,t){return e==null?Yr:hl(e,t,yd,!0)}function Rm(n,e,t,i){return e==null?Yr:Tl(e,t,n.scales[i].log,!1)}const sx=Rm;function Cm(n,e,t,i){return e==null?Yr:xd(e,t,n.scales[i].log,!1)}const rx=Cm;function ax(n,e,t,i,s){let r=Kn(Nh(n),Nh(e)),a=e-n,o=Pi(s/i*a,t);do{let l=t[o],c=i*l/a;if(c>=s&&r+(l<5?Us.get(l):0)<=17)return[l,c]}while(++o<t.length);return[0,0]}function nf(n){let e,t;return n=n.replace(/(\d+)px/,(i,s)=>(e=xn((t=+s)*Et))+"px"),[n,e,t]}function ox(n){n.show&&[n.font,n.labelFont].forEach(e=>{let t=Ut(e[2]*Et,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function On(n,e,t){const i={mode:wt(n.mode,1)},s=i.mode;function r(_,E,N,I){let q=E.valToPct(_);return I+N*(E.dir==-1?1-q:q)}function a(_,E,N,I){let q=E.valToPct(_);return I+N*(E.dir==-1?q:1-q)}function o(_,E,N,I){return E.ori==0?r(_,E,N,I):a(_,E,N,I)}i.valToPosH=r,i.valToPosV=a;let l=!1;i.status=0;const c=i.root=pi(p_);if(n.id!=null&&(c.id=n.id),ri(c,n.class),n.title){let _=pi(v_,c);_.textContent=n.title}const u=Ci("canvas"),d=i.ctx=u.getContext("2d"),h=pi(__,c);Qs("click",h,_=>{_.target===g&&(Ht!=mr||Xt!=gr)&&Ln.click(i,_)},!0);const m=i.under=pi(x_,h);h.appendChild(u);const g=i.over=pi(y_,h);n=Zr(n);const y=+wt(n.pxAlign,1),p=Jh(y);(n.plugins||[]).forEach(_=>{_.opts&&(n=_.opts(i,n)||n)});const f=n.ms||.001,x=i.series=s==1?tf(n.series||[],qh,Zh,!1):tx(n.series||[null],Yh),R=i.axes=tf(n.axes||[],Wh,$h,!0),S=i.scales={},C=i.bands=n.bands||[];C.forEach(_=>{_.fill=gt(_.fill||null),_.dir=wt(_.dir,-1)});const w=s==2?x[1].facets[0].scale:x[0].scale,v={axes:rs,series:dt},M=(n.drawOrder||["axes","series"]).map(_=>v[_]);function F(_){const E=_.distr==3?N=>ps(N>0?N:_.clamp(i,N,_.min,_.max,_.key)):_.distr==4?N=>nc(N,_.asinh):_.distr==100?N=>_.fwd(N):N=>N;return N=>{let I=E(N),{_min:q,_max:Z}=_,oe=Z-q;return(I-q)/oe}}function L(_){let E=S[_];if(E==null){let N=(n.scales||Fa)[_]||Fa;if(N.from!=null){L(N.from);let I=pn({},S[N.from],N,{key:_});I.valToPct=F(I),S[_]=I}else{E=S[_]=pn({},_==w?vm:G0,N),E.key=_;let I=E.time,q=E.range,Z=Ls(q);if((_!=w||s==2&&!I)&&(Z&&(q[0]==null||q[1]==null)&&(q={min:q[0]==null?Ph:{mode:1,hard:q[0],soft:q[0]},max:q[1]==null?Ph:{mode:1,hard:q[1],soft:q[1]}},Z=!1),!Z&&Cl(q))){let oe=q;q=(fe,ye,Ne)=>ye==null?Yr:hl(ye,Ne,oe)}E.range=gt(q||(I?nx:_==w?E.distr==3?sx:E.distr==4?rx:Tm:E.distr==3?Rm:E.distr==4?Cm:ix)),E.auto=gt(Z?!1:E.auto),E.clamp=gt(E.clamp||V0),E._min=E._max=null,E.valToPct=F(E)}}}L("x"),L("y"),s==1&&x.forEach(_=>{L(_.scale)}),R.forEach(_=>{L(_.scale)});for(let _ in n.scales)L(_);const D=S[w],B=D.distr;let G,k;D.ori==0?(ri(c,m_),G=r,k=a):(ri(c,g_),G=a,k=r);const W={};for(let _ in S){let E=S[_];(E.min!=null||E.max!=null)&&(W[_]={min:E.min,max:E.max},E.min=E.max=null)}const Y=n.tzDate||(_=>new Date(xn(_/f))),V=n.fmtDate||Sd,le=f==1?m0(Y):_0(Y),j=Hh(Y,Bh(f==1?p0:v0,V)),Q=Gh(Y,Vh(y0,V)),se=[],he=i.legend=pn({},S0,n.legend),de=i.cursor=pn({},C0,{drag:{y:s==2}},n.cursor),ee=he.show,me=de.show,_e=he.markers;he.idxs=se,_e.width=gt(_e.width),_e.dash=gt(_e.dash),_e.stroke=gt(_e.stroke),_e.fill=gt(_e.fill);let Te,we,Ge,tt=[],He=[],ct,rt=!1,Qe={};if(he.live){const _=x[1]?x[1].values:null;rt=_!=null,ct=rt?_(i,1,0):{_:0};for(let E in ct)Qe[E]=vd}if(ee)if(Te=Ci("table",A_,c),Ge=Ci("tbody",null,Te),he.mount(i,Te),rt){we=Ci("thead",null,Te,Ge);let _=Ci("tr",null,we);Ci("th",null,_);for(var qt in ct)Ci("th",vh,_).textContent=qt}else ri(Te,R_),he.live&&ri(Te,T_);const zt={show:!0},on={show:!1};function Nt(_,E){if(E==0&&(rt||!he.live||s==2))return Yr;let N=[],I=Ci("tr",C_,Ge,Ge.childNodes[E]);ri(I,_.class),_.show||ri(I,Js);let q=Ci("th",null,I);if(_e.show){let fe=pi(P_,q);if(E>0){let ye=_e.width(i,E);ye&&(fe.style.border=ye+"px "+_e.dash(i,E)+" "+_e.stroke(i,E)),fe.style.background=_e.fill(i,E)}}let Z=pi(vh,q);_.label instanceof HTMLElement?Z.appendChild(_.label):Z.textContent=_.label,E>0&&(_e.show||(Z.style.color=_.width>0?_e.stroke(i,E):_e.fill(i,E)),_t("click",q,fe=>{if(de._lock)return;Ye(fe);let ye=x.indexOf(_);if((fe.ctrlKey||fe.metaKey)!=he.isolate){let Ne=x.some((Ie,Fe)=>Fe>0&&Fe!=ye&&Ie.show);x.forEach((Ie,Fe)=>{Fe>0&&Bi(Fe,Ne?Fe==ye?zt:on:zt,!0,hn.setSeries)})}else Bi(ye,{show:!_.show},!0,hn.setSeries)},!1),Ze&&_t(bh,q,fe=>{de._lock||(Ye(fe),Bi(x.indexOf(_),_r,!0,hn.setSeries))},!1));for(var oe in ct){let fe=Ci("td",L_,I);fe.textContent="--",N.push(fe)}return[I,N]}const En=new Map;function _t(_,E,N,I=!0){const q=En.get(E)||{},Z=de.bind[_](i,E,N,I);Z&&(Qs(_,E,q[_]=Z),En.set(E,q))}function mn(_,E,N){const I=En.get(E)||{};for(let q in I)(_==null||q==_)&&(eu(q,E,I[q]),delete I[q]);_==null&&En.delete(E)}let Kt=0,ln=0,O=0,Ce=0,$e=0,nt=0,Se=$e,kt=nt,Be=O,Xe=Ce,P=0,b=0,X=0,ue=0;i.bbox={};let ae=!1,ve=!1,xe=!1,te=!1,ie=!1,pe=!1;function U(_,E,N){(N||_!=i.width||E!=i.height)&&re(_,E),at(!1),xe=!0,ve=!0,In()}function re(_,E){i.width=Kt=O=_,i.height=ln=Ce=E,$e=nt=0,be(),Ve();let N=i.bbox;P=N.left=Zs($e*Et,.5),b=N.top=Zs(nt*Et,.5),X=N.width=Zs(O*Et,.5),ue=N.height=Zs(Ce*Et,.5)}const ne=3;function Me(){let _=!1,E=0;for(;!_;){E++;let N=hr(E),I=zi(E);_=E==ne||N&&I,_||(re(i.width,i.height),ve=!0)}}function ge({width:_,height:E}){U(_,E)}i.setSize=ge;function be(){let _=!1,E=!1,N=!1,I=!1;R.forEach((q,Z)=>{if(q.show&&q._show){let{side:oe,_size:fe}=q,ye=oe%2,Ne=q.label!=null?q.labelSize:0,Ie=fe+Ne;Ie>0&&(ye?(O-=Ie,oe==3?($e+=Ie,I=!0):N=!0):(Ce-=Ie,oe==0?(nt+=Ie,_=!0):E=!0))}}),Ui[0]=_,Ui[1]=N,Ui[2]=E,Ui[3]=I,O-=wi[1]+wi[3],$e+=wi[3],Ce-=wi[2]+wi[0],nt+=wi[0]}function Ve(){let _=$e+O,E=nt+Ce,N=$e,I=nt;function q(Z,oe){switch(Z){case 1:return _+=oe,_-oe;case 2:return E+=oe,E-oe;case 3:return N-=oe,N+oe;case 0:return I-=oe,I+oe}}R.forEach((Z,oe)=>{if(Z.show&&Z._show){let fe=Z.side;Z._pos=q(fe,Z._size),Z.label!=null&&(Z._lpos=q(fe,Z.labelSize))}})}if(de.dataIdx==null){let _=de.hover,E=_.skip=new Set(_.skip??[]);E.add(void 0);let N=_.prox=gt(_.prox),I=_.bias??=0;de.dataIdx=(q,Z,oe,fe)=>{if(Z==0)return oe;let ye=oe,Ne=N(q,Z,oe,fe)??Ft,Ie=Ne>=0&&Ne<Ft,Fe=D.ori==0?O:Ce,et=de.left,St=e[0],bt=e[Z];if(E.has(bt[oe])){ye=null;let ht=null,Ke=null,We;if(I==0||I==-1)for(We=oe;ht==null&&We-- >0;)E.has(bt[We])||(ht=We);if(I==0||I==1)for(We=oe;Ke==null&&We++<bt.length;)E.has(bt[We])||(Ke=We);if(ht!=null||Ke!=null)if(Ie){let Gt=ht==null?-1/0:G(St[ht],D,Fe,0),jt=Ke==null?1/0:G(St[Ke],D,Fe,0),Cn=et-Gt,It=jt-et;Cn<=It?Cn<=Ne&&(ye=ht):It<=Ne&&(ye=Ke)}else ye=Ke==null?ht:ht==null?Ke:oe-ht<=Ke-oe?ht:Ke}else Ie&&yn(et-G(St[oe],D,Fe,0))>Ne&&(ye=null);return ye}}const Ye=_=>{de.event=_};de.idxs=se,de._lock=!1;let ce=de.points;ce.show=gt(ce.show),ce.size=gt(ce.size),ce.stroke=gt(ce.stroke),ce.width=gt(ce.width),ce.fill=gt(ce.fill);const Ue=i.focus=pn({},n.focus||{alpha:.3},de.focus),Ze=Ue.prox>=0,Re=Ze&&ce.one;let st=[],Bt=[],Bn=[];function ca(_,E){let N=ce.show(i,E);if(N instanceof HTMLElement)return ri(N,E_),ri(N,_.class),Wi(N,-10,-10,O,Ce),g.insertBefore(N,st[E]),N}function cr(_,E){if(s==1||E>0){let N=s==1&&S[_.scale].time,I=_.value;_.value=N?Fh(I)?Gh(Y,Vh(I,V)):I||Q:I||z0,_.label=_.label||(N?L0:P0)}if(Re||E>0){_.width=_.width==null?1:_.width,_.paths=_.paths||Q0||G_,_.fillTo=gt(_.fillTo||W0),_.pxAlign=+wt(_.pxAlign,y),_.pxRound=Jh(_.pxAlign),_.stroke=gt(_.stroke||null),_.fill=gt(_.fill||null),_._stroke=_._fill=_._paths=_._focus=null;let N=B0(Kn(1,_.width),1),I=_.points=pn({},{size:N,width:Kn(1,N*.2),stroke:_.stroke,space:N*2,paths:ex,_stroke:null,_fill:null},_.points);I.show=gt(I.show),I.filter=gt(I.filter),I.fill=gt(I.fill),I.stroke=gt(I.stroke),I.paths=gt(I.paths),I.pxAlign=_.pxAlign}if(ee){let N=Nt(_,E);tt.splice(E,0,N[0]),He.splice(E,0,N[1]),he.values.push(null)}if(me){se.splice(E,0,null);let N=null;Re?E==0&&(N=ca(_,E)):E>0&&(N=ca(_,E)),st.splice(E,0,N),Bt.splice(E,0,0),Bn.splice(E,0,0)}Rn("addSeries",E)}function Bl(_,E){E=E??x.length,_=s==1?au(_,E,qh,Zh):au(_,E,{},Yh),x.splice(E,0,_),cr(x[E],E)}i.addSeries=Bl;function ao(_){if(x.splice(_,1),ee){he.values.splice(_,1),He.splice(_,1);let E=tt.splice(_,1)[0];mn(null,E.firstChild),E.remove()}me&&(se.splice(_,1),st.splice(_,1)[0].remove(),Bt.splice(_,1),Bn.splice(_,1)),Rn("delSeries",_)}i.delSeries=ao;const Ui=[!1,!1,!1,!1];function ns(_,E){if(_._show=_.show,_.show){let N=_.side%2,I=S[_.scale];I==null&&(_.scale=N?x[1].scale:w,I=S[_.scale]);let q=I.time;_.size=gt(_.size),_.space=gt(_.space),_.rotate=gt(_.rotate),Ls(_.incrs)&&_.incrs.forEach(oe=>{!Us.has(oe)&&Us.set(oe,Jp(oe))}),_.incrs=gt(_.incrs||(I.distr==2?d0:q?f==1?f0:g0:js)),_.splits=gt(_.splits||(q&&I.distr==1?le:I.distr==3?nu:I.distr==4?I0:N0)),_.stroke=gt(_.stroke),_.grid.stroke=gt(_.grid.stroke),_.ticks.stroke=gt(_.ticks.stroke),_.border.stroke=gt(_.border.stroke);let Z=_.values;_.values=Ls(Z)&&!Ls(Z[0])?gt(Z):q?Ls(Z)?Hh(Y,Bh(Z,V)):Fh(Z)?x0(Y,Z):Z||j:Z||D0,_.filter=gt(_.filter||(I.distr>=3&&I.log==10?U0:I.distr==3&&I.log==2?O0:Zp)),_.font=nf(_.font),_.labelFont=nf(_.labelFont),_._size=_.size(i,null,E,0),_._space=_._rotate=_._incrs=_._found=_._splits=_._values=null,_._size>0&&(Ui[E]=!0,_._el=pi(b_,h))}}function is(_,E,N,I){let[q,Z,oe,fe]=N,ye=E%2,Ne=0;return ye==0&&(fe||Z)&&(Ne=E==0&&!q||E==2&&!oe?xn(Wh.size/3):0),ye==1&&(q||oe)&&(Ne=E==1&&!Z||E==3&&!fe?xn($h.size/2):0),Ne}const ua=i.padding=(n.padding||[is,is,is,is]).map(_=>gt(wt(_,is))),wi=i._padding=ua.map((_,E)=>_(i,E,Ui,0));let Yt,tn=null,nn=null;const Oi=s==1?x[0].idxs:null;let Qn=null,xs=!1;function da(_,E){if(e=_??[],i.data=i._data=e,s==2){Yt=0;for(let N=1;N<x.length;N++)Yt+=e[N][0].length}else{e.length==0&&(i.data=i._data=e=[[]]),Qn=e[0],Yt=Qn.length;let N=e;if(B==2){N=e.slice();let I=N[0]=Array(Yt);for(let q=0;q<Yt;q++)I[q]=q}i._data=e=N}if(at(!0),Rn("setData"),B==2&&(xe=!0),E!==!1){let N=D;N.auto(i,xs)?ha():ws(w,N.min,N.max),te=te||de.left>=0,pe=!0,In()}}i.setData=da;function ha(){xs=!0;let _,E;s==1&&(Yt>0?(tn=Oi[0]=0,nn=Oi[1]=Yt-1,_=e[0][tn],E=e[0][nn],B==2?(_=tn,E=nn):_==E&&(B==3?[_,E]=Tl(_,_,D.log,!1):B==4?[_,E]=xd(_,_,D.log,!1):D.time?E=_+xn(86400/f):[_,E]=hl(_,E,yd,!0))):(tn=Oi[0]=_=null,nn=Oi[1]=E=null)),ws(w,_,E)}let ur,ys,dr,A,H,J,$,K,Ee,Pe;function Ae(_,E,N,I,q,Z){_??=xh,N??=wd,I??="butt",q??=xh,Z??="round",_!=ur&&(d.strokeStyle=ur=_),q!=ys&&(d.fillStyle=ys=q),E!=dr&&(d.lineWidth=dr=E),Z!=H&&(d.lineJoin=H=Z),I!=J&&(d.lineCap=J=I),N!=A&&d.setLineDash(A=N)}function Le(_,E,N,I){E!=ys&&(d.fillStyle=ys=E),_!=$&&(d.font=$=_),N!=K&&(d.textAlign=K=N),I!=Ee&&(d.textBaseline=Ee=I)}function ze(_,E,N,I,q=0){if(I.length>0&&_.auto(i,xs)&&(E==null||E.min==null)){let Z=wt(tn,0),oe=wt(nn,I.length-1),fe=N.min==null?U_(I,Z,oe,q,_.distr==3):[N.min,N.max];_.min=Ni(_.min,N.min=fe[0]),_.max=Kn(_.max,N.max=fe[1])}}const Je={min:null,max:null};function ut(){for(let I in S){let q=S[I];W[I]==null&&(q.min==null||W[w]!=null&&q.auto(i,xs))&&(W[I]=Je)}for(let I in S){let q=S[I];W[I]==null&&q.from!=null&&W[q.from]!=null&&(W[I]=Je)}W[w]!=null&&at(!0);let _={};for(let I in W){let q=W[I];if(q!=null){let Z=_[I]=Zr(S[I],X_);if(q.min!=null)pn(Z,q);else if(I!=w||s==2)if(Yt==0&&Z.from==null){let oe=Z.range(i,null,null,I);Z.min=oe[0],Z.max=oe[1]}else Z.min=Ft,Z.max=-Ft}}if(Yt>0){x.forEach((I,q)=>{if(s==1){let Z=I.scale,oe=W[Z];if(oe==null)return;let fe=_[Z];if(q==0){let ye=fe.range(i,fe.min,fe.max,Z);fe.min=ye[0],fe.max=ye[1],tn=Pi(fe.min,e[0]),nn=Pi(fe.max,e[0]),nn-tn>1&&(e[0][tn]<fe.min&&tn++,e[0][nn]>fe.max&&nn--),I.min=Qn[tn],I.max=Qn[nn]}else I.show&&I.auto&&ze(fe,oe,I,e[q],I.sorted);I.idxs[0]=tn,I.idxs[1]=nn}else if(q>0&&I.show&&I.auto){let[Z,oe]=I.facets,fe=Z.scale,ye=oe.scale,[Ne,Ie]=e[q],Fe=_[fe],et=_[ye];Fe!=null&&ze(Fe,W[fe],Z,Ne,Z.sorted),et!=null&&ze(et,W[ye],oe,Ie,oe.sorted),I.min=oe.min,I.max=oe.max}});for(let I in _){let q=_[I],Z=W[I];if(q.from==null&&(Z==null||Z.min==null)){let oe=q.range(i,q.min==Ft?null:q.min,q.max==-Ft?null:q.max,I);q.min=oe[0],q.max=oe[1]}}}for(let I in _){let q=_[I];if(q.from!=null){let Z=_[q.from];if(Z.min==null)q.min=q.max=null;else{let oe=q.range(i,Z.min,Z.max,I);q.min=oe[0],q.max=oe[1]}}}let E={},N=!1;for(let I in _){let q=_[I],Z=S[I];if(Z.min!=q.min||Z.max!=q.max){Z.min=q.min,Z.max=q.max;let oe=Z.distr;Z._min=oe==3?ps(Z.min):oe==4?nc(Z.min,Z.asinh):oe==100?Z.fwd(Z.min):Z.min,Z._max=oe==3?ps(Z.max):oe==4?nc(Z.max,Z.asinh):oe==100?Z.fwd(Z.max):Z.max,E[I]=N=!0}}if(N){x.forEach((I,q)=>{s==2?q>0&&E.y&&(I._paths=null):E[I.scale]&&(I._paths=null)});for(let I in E)xe=!0,Rn("setScale",I);me&&de.left>=0&&(te=pe=!0)}for(let I in W)W[I]=null}function Oe(_){let E=tu(tn-1,0,Yt-1),N=tu(nn+1,0,Yt-1);for(;_[E]==null&&E>0;)E--;for(;_[N]==null&&N<Yt-1;)N++;return[E,N]}function dt(){if(Yt>0){let _=x.some(E=>E._focus)&&Pe!=Ue.alpha;_&&(d.globalAlpha=Pe=Ue.alpha),x.forEach((E,N)=>{if(N>0&&E.show&&($t(N,!1),$t(N,!0),E._paths==null)){let I=Pe;Pe!=E.alpha&&(d.globalAlpha=Pe=E.alpha);let q=s==2?[0,e[N][0].length-1]:Oe(e[N]);E._paths=E.paths(i,N,q[0],q[1]),Pe!=I&&(d.globalAlpha=Pe=I)}}),x.forEach((E,N)=>{if(N>0&&E.show){let I=Pe;Pe!=E.alpha&&(d.globalAlpha=Pe=E.alpha),E._paths!=null&&Rt(N,!1);{let q=E._paths!=null?E._paths.gaps:null,Z=E.points.show(i,N,tn,nn,q),oe=E.points.filter(i,N,Z,q);(Z||oe)&&(E.points._paths=E.points.paths(i,N,tn,nn,oe),Rt(N,!0))}Pe!=I&&(d.globalAlpha=Pe=I),Rn("drawSeries",N)}}),_&&(d.globalAlpha=Pe=1)}}function $t(_,E){let N=E?x[_].points:x[_];N._stroke=N.stroke(i,_),N._fill=N.fill(i,_)}function Rt(_,E){let N=E?x[_].points:x[_],{stroke:I,fill:q,clip:Z,flags:oe,_stroke:fe=N._stroke,_fill:ye=N._fill,_width:Ne=N.width}=N._paths;Ne=Ut(Ne*Et,3);let Ie=null,Fe=Ne%2/2;E&&ye==null&&(ye=Ne>0?"#fff":fe);let et=N.pxAlign==1&&Fe>0;if(et&&d.translate(Fe,Fe),!E){let St=P-Ne/2,bt=b-Ne/2,ht=X+Ne,Ke=ue+Ne;Ie=new Path2D,Ie.rect(St,bt,ht,Ke)}E?ke(fe,Ne,N.dash,N.cap,ye,I,q,oe,Z):Ct(_,fe,Ne,N.dash,N.cap,ye,I,q,oe,Ie,Z),et&&d.translate(-Fe,-Fe)}function Ct(_,E,N,I,q,Z,oe,fe,ye,Ne,Ie){let Fe=!1;ye!=0&&C.forEach((et,St)=>{if(et.series[0]==_){let bt=x[et.series[1]],ht=e[et.series[1]],Ke=(bt._paths||Fa).band;Ls(Ke)&&(Ke=et.dir==1?Ke[0]:Ke[1]);let We,Gt=null;bt.show&&Ke&&z_(ht,tn,nn)?(Gt=et.fill(i,St)||Z,We=bt._paths.clip):Ke=null,ke(E,N,I,q,Gt,oe,fe,ye,Ne,Ie,We,Ke),Fe=!0}}),Fe||ke(E,N,I,q,Z,oe,fe,ye,Ne,Ie)}const gn=jr|su;function ke(_,E,N,I,q,Z,oe,fe,ye,Ne,Ie,Fe){Ae(_,E,N,I,q),(ye||Ne||Fe)&&(d.save(),ye&&d.clip(ye),Ne&&d.clip(Ne)),Fe?(fe&gn)==gn?(d.clip(Fe),Ie&&d.clip(Ie),mt(q,oe),cn(_,Z,E)):fe&su?(mt(q,oe),d.clip(Fe),cn(_,Z,E)):fe&jr&&(d.save(),d.clip(Fe),Ie&&d.clip(Ie),mt(q,oe),d.restore(),cn(_,Z,E)):(mt(q,oe),cn(_,Z,E)),(ye||Ne||Fe)&&d.restore()}function cn(_,E,N){N>0&&(E instanceof Map?E.forEach((I,q)=>{d.strokeStyle=ur=q,d.stroke(I)}):E!=null&&_&&d.stroke(E))}function mt(_,E){E instanceof Map?E.forEach((N,I)=>{d.fillStyle=ys=I,d.fill(N)}):E!=null&&_&&d.fill(E)}function ss(_,E,N,I){let q=R[_],Z;if(I<=0)Z=[0,0];else{let oe=q._space=q.space(i,_,E,N,I),fe=q._incrs=q.incrs(i,_,E,N,I,oe);Z=ax(E,N,fe,I,oe)}return q._found=Z}function un(_,E,N,I,q,Z,oe,fe,ye,Ne){let Ie=oe%2/2;y==1&&d.translate(Ie,Ie),Ae(fe,oe,ye,Ne,fe),d.beginPath();let Fe,et,St,bt,ht=q+(I==0||I==3?-Z:Z);N==0?(et=q,bt=ht):(Fe=q,St=ht);for(let Ke=0;Ke<_.length;Ke++)E[Ke]!=null&&(N==0?Fe=St=_[Ke]:et=bt=_[Ke],d.moveTo(Fe,et),d.lineTo(St,bt));d.stroke(),y==1&&d.translate(-Ie,-Ie)}function hr(_){let E=!0;return R.forEach((N,I)=>{if(!N.show)return;let q=S[N.scale];if(q.min==null){N._show&&(E=!1,N._show=!1,at(!1));return}else N._show||(E=!1,N._show=!0,at(!1));let Z=N.side,oe=Z%2,{min:fe,max:ye}=q,[Ne,Ie]=ss(I,fe,ye,oe==0?O:Ce);if(Ie==0)return;let Fe=q.distr==2,et=N._splits=N.splits(i,I,fe,ye,Ne,Ie,Fe),St=q.distr==2?et.map(We=>Qn[We]):et,bt=q.distr==2?Qn[et[1]]-Qn[et[0]]:Ne,ht=N._values=N.values(i,N.filter(i,St,I,Ie,bt),I,Ie,bt);N._rotate=Z==2?N.rotate(i,ht,I,Ie):0;let Ke=N._size;N._size=mi(N.size(i,ht,I,_)),Ke!=null&&N._size!=Ke&&(E=!1)}),E}function zi(_){let E=!0;return ua.forEach((N,I)=>{let q=N(i,I,Ui,_);q!=wi[I]&&(E=!1),wi[I]=q}),E}function rs(){for(let _=0;_<R.length;_++){let E=R[_];if(!E.show||!E._show)continue;let N=E.side,I=N%2,q,Z,oe=E.stroke(i,_),fe=N==0||N==3?-1:1,[ye,Ne]=E._found;if(E.label!=null){let Gn=E.labelGap*fe,ni=xn((E._lpos+Gn)*Et);Le(E.labelFont[0],oe,"center",N==2?va:_h),d.save(),I==1?(q=Z=0,d.translate(ni,xn(b+ue/2)),d.rotate((N==3?-Qo:Qo)/2)):(q=xn(P+X/2),Z=ni);let Ws=Kp(E.label)?E.label(i,_,ye,Ne):E.label;d.fillText(Ws,q,Z),d.restore()}if(Ne==0)continue;let Ie=S[E.scale],Fe=I==0?X:ue,et=I==0?P:b,St=E._splits,bt=Ie.distr==2?St.map(Gn=>Qn[Gn]):St,ht=Ie.distr==2?Qn[St[1]]-Qn[St[0]]:ye,Ke=E.ticks,We=E.border,Gt=Ke.show?Ke.size:0,jt=xn(Gt*Et),Cn=xn((E.alignTo==2?E._size-Gt-E.gap:E.gap)*Et),It=E._rotate*-Qo/180,Jt=p(E._pos*Et),ei=(jt+Cn)*fe,Vn=Jt+ei;Z=I==0?Vn:0,q=I==1?Vn:0;let di=E.font[0],Si=E.align==1?yr:E.align==2?Ql:It>0?yr:It<0?Ql:I==0?"center":N==3?Ql:yr,Vi=It||I==1?"middle":N==2?va:_h;Le(di,oe,Si,Vi);let ti=E.font[1]*E.lineGap,hi=St.map(Gn=>p(o(Gn,Ie,Fe,et))),Mi=E._values;for(let Gn=0;Gn<Mi.length;Gn++){let ni=Mi[Gn];if(ni!=null){I==0?q=hi[Gn]:Z=hi[Gn],ni=""+ni;let Ws=ni.indexOf(`
`)==-1?[ni]:ni.split(/\n/gm);for(let Wn=0;Wn<Ws.length;Wn++){let mh=Ws[Wn];It?(d.save(),d.translate(q,Z+Wn*ti),d.rotate(It),d.fillText(mh,0,0),d.restore()):d.fillText(mh,q,Z+Wn*ti)}}}Ke.show&&un(hi,Ke.filter(i,bt,_,Ne,ht),I,N,Jt,jt,Ut(Ke.width*Et,3),Ke.stroke(i,_),Ke.dash,Ke.cap);let Gi=E.grid;Gi.show&&un(hi,Gi.filter(i,bt,_,Ne,ht),I,I==0?2:1,I==0?b:P,I==0?ue:X,Ut(Gi.width*Et,3),Gi.stroke(i,_),Gi.dash,Gi.cap),We.show&&un([Jt],[1],I==0?1:0,I==0?1:2,I==1?b:P,I==1?ue:X,Ut(We.width*Et,3),We.stroke(i,_),We.dash,We.cap)}Rn("drawAxes")}function at(_){x.forEach((E,N)=>{N>0&&(E._paths=null,_&&(s==1?(E.min=null,E.max=null):E.facets.forEach(I=>{I.min=null,I.max=null})))})}let Zt=!1,Hn=!1,Pt=[];function dn(){Hn=!1;for(let _=0;_<Pt.length;_++)Rn(...Pt[_]);Pt.length=0}function In(){Zt||(Q_(jd),Zt=!0)}function oo(_,E=!1){Zt=!0,Hn=E,_(i),jd(),E&&Pt.length>0&&queueMicrotask(dn)}i.batch=oo;function jd(){if(ae&&(ut(),ae=!1),xe&&(Me(),xe=!1),ve){if(Wt(m,yr,$e),Wt(m,va,nt),Wt(m,Ca,O),Wt(m,Pa,Ce),Wt(g,yr,$e),Wt(g,va,nt),Wt(g,Ca,O),Wt(g,Pa,Ce),Wt(h,Ca,Kt),Wt(h,Pa,ln),u.width=xn(Kt*Et),u.height=xn(ln*Et),R.forEach(({_el:_,_show:E,_size:N,_pos:I,side:q})=>{if(_!=null)if(E){let Z=q===3||q===0?N:0,oe=q%2==1;Wt(_,oe?"left":"top",I-Z),Wt(_,oe?"width":"height",N),Wt(_,oe?"top":"left",oe?nt:$e),Wt(_,oe?"height":"width",oe?Ce:O),Qc(_,Js)}else ri(_,Js)}),ur=ys=dr=H=J=$=K=Ee=A=null,Pe=1,ma(!0),$e!=Se||nt!=kt||O!=Be||Ce!=Xe){at(!1);let _=O/Be,E=Ce/Xe;if(me&&!te&&de.left>=0){de.left*=_,de.top*=E,fr&&Wi(fr,xn(de.left),0,O,Ce),pr&&Wi(pr,0,xn(de.top),O,Ce);for(let N=0;N<st.length;N++){let I=st[N];I!=null&&(Bt[N]*=_,Bn[N]*=E,Wi(I,mi(Bt[N]),mi(Bn[N]),O,Ce))}}if(Vt.show&&!ie&&Vt.left>=0&&Vt.width>0){Vt.left*=_,Vt.width*=_,Vt.top*=E,Vt.height*=E;for(let N in Xl)Wt(vr,N,Vt[N])}Se=$e,kt=nt,Be=O,Xe=Ce}Rn("setSize"),ve=!1}Kt>0&&ln>0&&(d.clearRect(0,0,u.width,u.height),Rn("drawClear"),M.forEach(_=>_()),Rn("draw")),Vt.show&&ie&&(lo(Vt),ie=!1),me&&te&&(Gs(null,!0,!1),te=!1),he.show&&he.live&&pe&&(Wl(),pe=!1),l||(l=!0,i.status=1,Rn("ready")),xs=!1,Zt=!1}i.redraw=(_,E)=>{xe=E||!1,_!==!1?ws(w,D.min,D.max):In()};function Hl(_,E){let N=S[_];if(N.from==null){if(Yt==0){let I=N.range(i,E.min,E.max,_);E.min=I[0],E.max=I[1]}if(E.min>E.max){let I=E.min;E.min=E.max,E.max=I}if(Yt>1&&E.min!=null&&E.max!=null&&E.max-E.min<1e-16)return;_==w&&N.distr==2&&Yt>0&&(E.min=Pi(E.min,e[0]),E.max=Pi(E.max,e[0]),E.min==E.max&&E.max++),W[_]=E,ae=!0,In()}}i.setScale=Hl;let Vl,Gl,fr,pr,Jd,Qd,mr,gr,eh,th,Ht,Xt,bs=!1;const Ln=de.drag;let An=Ln.x,Tn=Ln.y;me&&(de.x&&(Vl=pi(S_,g)),de.y&&(Gl=pi(M_,g)),D.ori==0?(fr=Vl,pr=Gl):(fr=Gl,pr=Vl),Ht=de.left,Xt=de.top);const Vt=i.select=pn({show:!0,over:!0,left:0,width:0,top:0,height:0},n.select),vr=Vt.show?pi(w_,Vt.over?g:m):null;function lo(_,E){if(Vt.show){for(let N in _)Vt[N]=_[N],N in Xl&&Wt(vr,N,_[N]);E!==!1&&Rn("setSelect")}}i.setSelect=lo;function lv(_){if(x[_].show)ee&&Qc(tt[_],Js);else if(ee&&ri(tt[_],Js),me){let N=Re?st[0]:st[_];N!=null&&Wi(N,-10,-10,O,Ce)}}function ws(_,E,N){Hl(_,{min:E,max:N})}function Bi(_,E,N,I){E.focus!=null&&fv(_),E.show!=null&&x.forEach((q,Z)=>{Z>0&&(_==Z||_==null)&&(q.show=E.show,lv(Z),s==2?(ws(q.facets[0].scale,null,null),ws(q.facets[1].scale,null,null)):ws(q.scale,null,null),In())}),N!==!1&&Rn("setSeries",_,E),I&&ga("setSeries",i,_,E)}i.setSeries=Bi;function cv(_,E){pn(C[_],E)}function uv(_,E){_.fill=gt(_.fill||null),_.dir=wt(_.dir,-1),E=E??C.length,C.splice(E,0,_)}function dv(_){_==null?C.length=0:C.splice(_,1)}i.addBand=uv,i.setBand=cv,i.delBand=dv;function hv(_,E){x[_].alpha=E,me&&st[_]!=null&&(st[_].style.opacity=E),ee&&tt[_]&&(tt[_].style.opacity=E)}let as,Ss,Vs;const _r={focus:!0};function fv(_){if(_!=Vs){let E=_==null,N=Ue.alpha!=1;x.forEach((I,q)=>{if(s==1||q>0){let Z=E||q==0||q==_;I._focus=E?null:Z,N&&hv(q,Z?1:Ue.alpha)}}),Vs=_,N&&In()}}ee&&Ze&&_t(wh,Te,_=>{de._lock||(Ye(_),Vs!=null&&Bi(null,_r,!0,hn.setSeries))});function Hi(_,E,N){let I=S[E];N&&(_=_/Et-(I.ori==1?nt:$e));let q=O;I.ori==1&&(q=Ce,_=q-_),I.dir==-1&&(_=q-_);let Z=I._min,oe=I._max,fe=_/q,ye=Z+(oe-Z)*fe,Ne=I.distr;return Ne==3?Kr(10,ye):Ne==4?H_(ye,I.asinh):Ne==100?I.bwd(ye):ye}function pv(_,E){let N=Hi(_,w,E);return Pi(N,e[0],tn,nn)}i.valToIdx=_=>Pi(_,e[0]),i.posToIdx=pv,i.posToVal=Hi,i.valToPos=(_,E,N)=>S[E].ori==0?r(_,S[E],N?X:O,N?P:0):a(_,S[E],N?ue:Ce,N?b:0),i.setCursor=(_,E,N)=>{Ht=_.left,Xt=_.top,Gs(null,E,N)};function nh(_,E){Wt(vr,yr,Vt.left=_),Wt(vr,Ca,Vt.width=E)}function ih(_,E){Wt(vr,va,Vt.top=_),Wt(vr,Pa,Vt.height=E)}let fa=D.ori==0?nh:ih,pa=D.ori==1?nh:ih;function mv(){if(ee&&he.live)for(let _=s==2?1:0;_<x.length;_++){if(_==0&&rt)continue;let E=he.values[_],N=0;for(let I in E)He[_][N++].firstChild.nodeValue=E[I]}}function Wl(_,E){if(_!=null&&(_.idxs?_.idxs.forEach((N,I)=>{se[I]=N}):q_(_.idx)||se.fill(_.idx),he.idx=se[0]),ee&&he.live){for(let N=0;N<x.length;N++)(N>0||s==1&&!rt)&&gv(N,se[N]);mv()}pe=!1,E!==!1&&Rn("setLegend")}i.setLegend=Wl;function gv(_,E){let N=x[_],I=_==0&&B==2?Qn:e[_],q;rt?q=N.values(i,_,E)??Qe:(q=N.value(i,E==null?null:I[E],_,E),q=q==null?Qe:{_:q}),he.values[_]=q}function Gs(_,E,N){eh=Ht,th=Xt,[Ht,Xt]=de.move(i,Ht,Xt),de.left=Ht,de.top=Xt,me&&(fr&&Wi(fr,xn(Ht),0,O,Ce),pr&&Wi(pr,0,xn(Xt),O,Ce));let I,q=tn>nn;as=Ft,Ss=null;let Z=D.ori==0?O:Ce,oe=D.ori==1?O:Ce;if(Ht<0||Yt==0||q){I=de.idx=null;for(let fe=0;fe<x.length;fe++){let ye=st[fe];ye!=null&&Wi(ye,-10,-10,O,Ce)}Ze&&Bi(null,_r,!0,_==null&&hn.setSeries),he.live&&(se.fill(I),pe=!0)}else{let fe,ye,Ne;s==1&&(fe=D.ori==0?Ht:Xt,ye=Hi(fe,w),I=de.idx=Pi(ye,e[0],tn,nn),Ne=G(e[0][I],D,Z,0));let Ie=-10,Fe=-10,et=0,St=0,bt=!0,ht="",Ke="";for(let We=s==2?1:0;We<x.length;We++){let Gt=x[We],jt=se[We],Cn=jt==null?null:s==1?e[We][jt]:e[We][1][jt],It=de.dataIdx(i,We,I,ye),Jt=It==null?null:s==1?e[We][It]:e[We][1][It];if(pe=pe||Jt!=Cn||It!=jt,se[We]=It,We>0&&Gt.show){let ei=It==null?-10:It==I?Ne:G(s==1?e[0][It]:e[We][0][It],D,Z,0),Vn=Jt==null?-10:k(Jt,s==1?S[Gt.scale]:S[Gt.facets[1].scale],oe,0);if(Ze&&Jt!=null){let di=D.ori==1?Ht:Xt,Si=yn(Ue.dist(i,We,It,Vn,di));if(Si<as){let Vi=Ue.bias;if(Vi!=0){let ti=Hi(di,Gt.scale),hi=Jt>=0?1:-1,Mi=ti>=0?1:-1;Mi==hi&&(Mi==1?Vi==1?Jt>=ti:Jt<=ti:Vi==1?Jt<=ti:Jt>=ti)&&(as=Si,Ss=We)}else as=Si,Ss=We}}if(pe||Re){let di,Si;D.ori==0?(di=ei,Si=Vn):(di=Vn,Si=ei);let Vi,ti,hi,Mi,Gi,Gn,ni=!0,Ws=ce.bbox;if(Ws!=null){ni=!1;let Wn=Ws(i,We);hi=Wn.left,Mi=Wn.top,Vi=Wn.width,ti=Wn.height}else hi=di,Mi=Si,Vi=ti=ce.size(i,We);if(Gn=ce.fill(i,We),Gi=ce.stroke(i,We),Re)We==Ss&&as<=Ue.prox&&(Ie=hi,Fe=Mi,et=Vi,St=ti,bt=ni,ht=Gn,Ke=Gi);else{let Wn=st[We];Wn!=null&&(Bt[We]=hi,Bn[We]=Mi,Ch(Wn,Vi,ti,ni),Th(Wn,Gn,Gi),Wi(Wn,mi(hi),mi(Mi),O,Ce))}}}}if(Re){let We=Ue.prox,Gt=Vs==null?as<=We:as>We||Ss!=Vs;if(pe||Gt){let jt=st[0];jt!=null&&(Bt[0]=Ie,Bn[0]=Fe,Ch(jt,et,St,bt),Th(jt,ht,Ke),Wi(jt,mi(Ie),mi(Fe),O,Ce))}}}if(Vt.show&&bs)if(_!=null){let[fe,ye]=hn.scales,[Ne,Ie]=hn.match,[Fe,et]=_.cursor.sync.scales,St=_.cursor.drag;if(An=St._x,Tn=St._y,An||Tn){let{left:bt,top:ht,width:Ke,height:We}=_.select,Gt=_.scales[Fe].ori,jt=_.posToVal,Cn,It,Jt,ei,Vn,di=fe!=null&&Ne(fe,Fe),Si=ye!=null&&Ie(ye,et);di&&An?(Gt==0?(Cn=bt,It=Ke):(Cn=ht,It=We),Jt=S[fe],ei=G(jt(Cn,Fe),Jt,Z,0),Vn=G(jt(Cn+It,Fe),Jt,Z,0),fa(Ni(ei,Vn),yn(Vn-ei))):fa(0,Z),Si&&Tn?(Gt==1?(Cn=bt,It=Ke):(Cn=ht,It=We),Jt=S[ye],ei=k(jt(Cn,et),Jt,oe,0),Vn=k(jt(Cn+It,et),Jt,oe,0),pa(Ni(ei,Vn),yn(Vn-ei))):pa(0,oe)}else $l()}else{let fe=yn(eh-Jd),ye=yn(th-Qd);if(D.ori==1){let et=fe;fe=ye,ye=et}An=Ln.x&&fe>=Ln.dist,Tn=Ln.y&&ye>=Ln.dist;let Ne=Ln.uni;Ne!=null?An&&Tn&&(An=fe>=Ne,Tn=ye>=Ne,!An&&!Tn&&(ye>fe?Tn=!0:An=!0)):Ln.x&&Ln.y&&(An||Tn)&&(An=Tn=!0);let Ie,Fe;An&&(D.ori==0?(Ie=mr,Fe=Ht):(Ie=gr,Fe=Xt),fa(Ni(Ie,Fe),yn(Fe-Ie)),Tn||pa(0,oe)),Tn&&(D.ori==1?(Ie=mr,Fe=Ht):(Ie=gr,Fe=Xt),pa(Ni(Ie,Fe),yn(Fe-Ie)),An||fa(0,Z)),!An&&!Tn&&(fa(0,0),pa(0,0))}if(Ln._x=An,Ln._y=Tn,_==null){if(N){if(ph!=null){let[fe,ye]=hn.scales;hn.values[0]=fe!=null?Hi(D.ori==0?Ht:Xt,fe):null,hn.values[1]=ye!=null?Hi(D.ori==1?Ht:Xt,ye):null}ga(ec,i,Ht,Xt,O,Ce,I)}if(Ze){let fe=N&&hn.setSeries,ye=Ue.prox;Vs==null?as<=ye&&Bi(Ss,_r,!0,fe):as>ye?Bi(null,_r,!0,fe):Ss!=Vs&&Bi(Ss,_r,!0,fe)}}pe&&(he.idx=I,Wl()),E!==!1&&Rn("setCursor")}let Ms=null;Object.defineProperty(i,"rect",{get(){return Ms==null&&ma(!1),Ms}});function ma(_=!1){_?Ms=null:(Ms=g.getBoundingClientRect(),Rn("syncRect",Ms))}function sh(_,E,N,I,q,Z,oe){de._lock||bs&&_!=null&&_.movementX==0&&_.movementY==0||(ql(_,E,N,I,q,Z,oe,!1,_!=null),_!=null?Gs(null,!0,!0):Gs(E,!0,!1))}function ql(_,E,N,I,q,Z,oe,fe,ye){if(Ms==null&&ma(!1),Ye(_),_!=null)N=_.clientX-Ms.left,I=_.clientY-Ms.top;else{if(N<0||I<0){Ht=-10,Xt=-10;return}let[Ne,Ie]=hn.scales,Fe=E.cursor.sync,[et,St]=Fe.values,[bt,ht]=Fe.scales,[Ke,We]=hn.match,Gt=E.axes[0].side%2==1,jt=D.ori==0?O:Ce,Cn=D.ori==1?O:Ce,It=Gt?Z:q,Jt=Gt?q:Z,ei=Gt?I:N,Vn=Gt?N:I;if(bt!=null?N=Ke(Ne,bt)?o(et,S[Ne],jt,0):-10:N=jt*(ei/It),ht!=null?I=We(Ie,ht)?o(St,S[Ie],Cn,0):-10:I=Cn*(Vn/Jt),D.ori==1){let di=N;N=I,I=di}}ye&&(E==null||E.cursor.event.type==ec)&&((N<=1||N>=O-1)&&(N=Zs(N,O)),(I<=1||I>=Ce-1)&&(I=Zs(I,Ce))),fe?(Jd=N,Qd=I,[mr,gr]=de.move(i,N,I)):(Ht=N,Xt=I)}const Xl={width:0,height:0,left:0,top:0};function $l(){lo(Xl,!1)}let rh,ah,oh,lh;function ch(_,E,N,I,q,Z,oe){bs=!0,An=Tn=Ln._x=Ln._y=!1,ql(_,E,N,I,q,Z,oe,!0,!1),_!=null&&(_t(tc,jc,uh,!1),ga(yh,i,mr,gr,O,Ce,null));let{left:fe,top:ye,width:Ne,height:Ie}=Vt;rh=fe,ah=ye,oh=Ne,lh=Ie}function uh(_,E,N,I,q,Z,oe){bs=Ln._x=Ln._y=!1,ql(_,E,N,I,q,Z,oe,!1,!0);let{left:fe,top:ye,width:Ne,height:Ie}=Vt,Fe=Ne>0||Ie>0,et=rh!=fe||ah!=ye||oh!=Ne||lh!=Ie;if(Fe&&et&&lo(Vt),Ln.setScale&&Fe&&et){let St=fe,bt=Ne,ht=ye,Ke=Ie;if(D.ori==1&&(St=ye,bt=Ie,ht=fe,Ke=Ne),An&&ws(w,Hi(St,w),Hi(St+bt,w)),Tn)for(let We in S){let Gt=S[We];We!=w&&Gt.from==null&&Gt.min!=Ft&&ws(We,Hi(ht+Ke,We),Hi(ht,We))}$l()}else de.lock&&(de._lock=!de._lock,Gs(E,!0,_!=null));_!=null&&(mn(tc,jc),ga(tc,i,Ht,Xt,O,Ce,null))}function vv(_,E,N,I,q,Z,oe){if(de._lock)return;Ye(_);let fe=bs;if(bs){let ye=!0,Ne=!0,Ie=10,Fe,et;D.ori==0?(Fe=An,et=Tn):(Fe=Tn,et=An),Fe&&et&&(ye=Ht<=Ie||Ht>=O-Ie,Ne=Xt<=Ie||Xt>=Ce-Ie),Fe&&ye&&(Ht=Ht<mr?0:O),et&&Ne&&(Xt=Xt<gr?0:Ce),Gs(null,!0,!0),bs=!1}Ht=-10,Xt=-10,se.fill(null),Gs(null,!0,!0),fe&&(bs=fe)}function dh(_,E,N,I,q,Z,oe){de._lock||(Ye(_),ha(),$l(),_!=null&&ga(Sh,i,Ht,Xt,O,Ce,null))}function hh(){R.forEach(ox),U(i.width,i.height,!0)}Qs(dl,Gr,hh);const xr={};xr.mousedown=ch,xr.mousemove=sh,xr.mouseup=uh,xr.dblclick=dh,xr.setSeries=(_,E,N,I)=>{let q=hn.match[2];N=q(i,E,N),N!=-1&&Bi(N,I,!0,!1)},me&&(_t(yh,g,ch),_t(ec,g,sh),_t(bh,g,_=>{Ye(_),ma(!1)}),_t(wh,g,vv),_t(Sh,g,dh),ru.add(i),i.syncRect=ma);const co=i.hooks=n.hooks||{};function Rn(_,E,N){Hn?Pt.push([_,E,N]):_ in co&&co[_].forEach(I=>{I.call(null,i,E,N)})}(n.plugins||[]).forEach(_=>{for(let E in _.hooks)co[E]=(co[E]||[]).concat(_.hooks[E])});const fh=(_,E,N)=>N,hn=pn({key:null,setSeries:!1,filters:{pub:Ih,sub:Ih},scales:[w,x[1]?x[1].scale:null],match:[kh,kh,fh],values:[null,null]},de.sync);hn.match.length==2&&hn.match.push(fh),de.sync=hn;const ph=hn.key,Kl=_m(ph);function ga(_,E,N,I,q,Z,oe){hn.filters.pub(_,E,N,I,q,Z,oe)&&Kl.pub(_,E,N,I,q,Z,oe)}Kl.sub(i);function _v(_,E,N,I,q,Z,oe){hn.filters.sub(_,E,N,I,q,Z,oe)&&xr[_](null,E,N,I,q,Z,oe)}i.pub=_v;function xv(){Kl.unsub(i),ru.delete(i),En.clear(),eu(dl,Gr,hh),c.remove(),Te?.remove(),Rn("destroy")}i.destroy=xv;function Yl(){Rn("init",n,e),da(e||n.data,!1),W[w]?Hl(w,W[w]):ha(),ie=Vt.show&&(Vt.width>0||Vt.height>0),te=pe=!0,U(n.width,n.height)}return x.forEach(cr),R.forEach(ns),t?t instanceof HTMLElement?(t.appendChild(c),Yl()):t(i,Yl):Yl(),i}On.assign=pn;On.fmtNum=bd;On.rangeNum=hl;On.rangeLog=Tl;On.rangeAsinh=xd;On.orient=ar;On.pxRatio=Et;On.join=J_;On.fmtDate=Sd,On.tzDate=c0;On.sync=_m;{On.addGap=q0,On.clipGaps=Pl;let n=On.paths={points:Mm};n.linear=Am,n.stepped=K0,n.bars=Y0,n.spline=j0}class Il{shown=new Map;observer;constructor(){this.observer=typeof IntersectionObserver>"u"?null:new IntersectionObserver(e=>{for(const t of e)this.shown.set(t.target,t.isIntersecting)})}watch(e){this.shown.set(e,!0),this.observer?.observe(e)}visible(e){return this.shown.get(e)??!0}}const lx=1e-6,cx=1e-12,Pd=2**-52;function ou(n,e,t=.05){if(n===null||e===null||!Number.isFinite(n)||!Number.isFinite(e))return[-1,1];n>e&&([n,e]=[e,n]);const i=Math.max(lx*Math.max(Math.abs(n),Math.abs(e)),cx),s=e-n;if(s<i){const r=n/2+e/2;return[r-i/2,r+i/2]}return[n-t*s,e+t*s]}function ux(n,e){return!Number.isFinite(n)||!(e>0)?null:Math.max(Math.abs(n)/e,Pd/10)}function dx(n,e){const t=Pd/10,i=n!==null&&Number.isFinite(n)&&n>0?Math.min(n,t):t,s=e!==null&&Number.isFinite(e)&&e>0?Math.max(e,1e-12):1e-12;return[10**Math.floor(Math.log10(i)),10**Math.ceil(Math.log10(s)+1e-9)]}const br=n=>Number.isFinite(n)?Math.abs(n)>=1e4||Math.abs(n)<.001&&n!==0?n.toExponential(2):n.toPrecision(3):"—";function Pm(n,e,t,i,s){let[r,a,o,l]=[1/0,-1/0,1/0,-1/0];const c=Math.min(i.length,s.length);for(let d=0;d<c;d++){const[h,m]=[i[d],s[d]??NaN];!Number.isFinite(h)||!Number.isFinite(m)||([r,a,o,l]=[Math.min(r,h),Math.max(a,h),Math.min(o,m),Math.max(l,m)])}const u=n?`${n}: `:"";return r>a?`${u}${T("alt.empty")}`:`${u}${T("alt.summary",{y:t,x:e,yLo:br(o),yHi:br(l),xLo:br(r),xHi:br(a),xNow:br(i[c-1]??NaN),yNow:br(s[c-1]??NaN)})}`}function Lm(n,e){n.getAttribute("role")!=="img"&&n.setAttribute("role","img"),n.getAttribute("aria-label")!==e&&n.setAttribute("aria-label",e)}function hx(n,e,t,i,s){const r=Math.max(Math.abs(i),1);return{energy:Math.max(Math.abs(n),t*r*s),j3:Math.max(Math.abs(e),t*s*Math.sqrt(r*s))}}const ac=[{title:"plot.dE",axis:"|ΔE|/E_s",key:"dE",color:"#ffb347",drift:"energy"},{title:"plot.dJ3",axis:"|ΔJ₃|/J_s",key:"dJ3",color:"#7dff8a",drift:"j3"},{title:"plot.z",axis:"z [m]",key:"z",color:"#59c3ff",events:!0},{title:"plot.tension",axis:"T [N]",key:"tension",color:"#ff5d73",events:!0}];function fx(n){if(n===null||!Number.isFinite(n))return"";if(n===0)return"0";const e=Math.abs(n);return e>=.001&&e<1e4?String(+n.toPrecision(4)):n.toExponential(0)}class px{constructor(e,t=()=>{}){this.container=e;let i=0;const s={stroke:"#aab",grid:{stroke:"#2a2f3a"},ticks:{stroke:"#2a2f3a"},labelSize:16};for(const r of ac){const a=document.createElement("div");a.className="plot",a.dataset.plot=r.key,e.appendChild(a),this.els.push(a),this.visibility.watch(a),this.shown.push({h:null,n:-1,t:NaN,ev:null});const o=[()=>t(performance.now()-i)];r.events&&o.push(c=>this.markEvents(c)),r.drift&&o.push(c=>this.markFloor(c));const l={title:T(r.title),width:this.width(),height:160,scales:{x:{time:!1,range:(c,u,d)=>ou(u,d,0)},y:r.drift?{distr:3,log:10,range:(c,u,d)=>dx(u,d)}:{range:(c,u,d)=>ou(u,d)}},legend:{show:!0,live:!1},hooks:{drawClear:[()=>{i=performance.now()}],draw:o},cursor:{show:!0,drag:{x:!1,y:!1}},series:[{label:"t [s]"},{label:r.axis,stroke:r.color,width:1.5}],axes:[{...s,label:T("plot.time")},{...s,label:r.axis,size:64,values:(c,u)=>u.map(fx)}]};this.charts.push(new On(l,[[],[]],a))}new ResizeObserver(()=>this.resize()).observe(e)}container;charts=[];els=[];visibility=new Il;shown=[];events=[];width(){return Math.max(200,this.container.clientWidth-8)}resize(){for(const e of this.charts)e.setSize({width:this.width(),height:160})}markFloor(e){const{ctx:t,bbox:i}=e,s=Math.round(e.valToPos(Pd,"y",!0))+.5;s>=i.top&&s<=i.top+i.height&&(t.save(),t.strokeStyle="#8a93a6",t.setLineDash([5,4]),t.beginPath(),t.moveTo(i.left,s),t.lineTo(i.left+i.width,s),t.stroke(),t.fillStyle="#8a93a6",t.font=`${Math.round(11*devicePixelRatio)}px system-ui, sans-serif`,t.textAlign="left",t.textBaseline="bottom",t.fillText(T("plot.floor"),i.left+4,s-3),t.restore())}markEvents(e){const[t,i]=[e.scales.x?.min,e.scales.x?.max];if(t===void 0||i===void 0||t===null||i===null)return;const{ctx:s,bbox:r}=e;s.save(),s.lineWidth=1,s.strokeStyle="#e0e0e0";for(const a of this.events){if(a.t<t||a.t>i)continue;const o=Math.round(e.valToPos(a.t,"x",!0))+.5;s.setLineDash(a.kind==="slack"?[4,3]:[]),s.beginPath(),s.moveTo(o,r.top),s.lineTo(o,r.top+r.height),s.stroke()}s.restore()}scales(){return ac.map((e,t)=>{const i=this.charts[t]?.scales.y;return{key:e.key,distr:i?.distr??1,min:i?.min??null,max:i?.max??null}})}update(e,t=[],i={energy:1,j3:1}){this.events=t;const s=e.t.length,r=e.t[s-1]??NaN;ac.forEach((a,o)=>{const l=this.charts[o],c=this.els[o],u=this.shown[o];if(l===void 0||c===void 0||u===void 0||!this.visibility.visible(c)||u.h===e&&u.n===s&&Object.is(u.t,r)&&u.ev===t)return;Object.assign(u,{h:e,n:s,t:r,ev:t});const d=e[a.key],h=a.drift,m=h?d.map(g=>ux(g,i[h])):d;l.setData([e.t,m]),Lm(l.root,Pm(a.axis,T("plot.time"),a.axis,e.t,m))})}}function er(n,e=.1){let t=1/0,i=-1/0;for(const a of n)Number.isFinite(a)&&(a<t&&(t=a),a>i&&(i=a));if(t>i)return{lo:-1,hi:1};if(t===i)return{lo:t-Math.max(.5,Math.abs(t)*.1),hi:i+Math.max(.5,Math.abs(t)*.1)};const[s,r]=ou(t,i,e);return{lo:s,hi:r}}function mx(n,e,t){const i=Math.max(e===null?0:e-n,.2*t);return{lo:n-.15*i,hi:n+2.2*i}}function mo(n,e=Math.abs(n)){if(n===0)return"0";const t=Math.abs(n),i=Math.min(12,Math.max(3,Math.ceil(Math.log10(t/Math.max(e,1e-300)))+2));return t>=.01&&t<1e4?String(+n.toPrecision(i)):n.toExponential(Math.max(1,i-2))}class Ua{constructor(e,t,i,s,r=150){this.title=t,this.xLabel=i,this.yLabel=s,this.height=r;const a=document.createElement("div");a.className="plot curve";const o=document.createElement("div");o.className="curve-title",o.textContent=t,a.appendChild(o),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("aria-label",t),this.canvas.setAttribute("role","img"),a.appendChild(this.canvas),e.appendChild(a),this.ctx=this.canvas.getContext("2d")}title;xLabel;yLabel;height;canvas;ctx;draw(e,t,i,s,r={}){const a=t[0];Lm(this.canvas,Pm(this.title,this.xLabel,this.yLabel,a?.x??[],a?.y??[]));const o=this.ctx;if(o===null)return;const l=Math.min(window.devicePixelRatio||1,2),c=Math.max(100,e),u=this.height;this.canvas.width!==Math.round(c*l)&&(this.canvas.width=Math.round(c*l),this.canvas.height=Math.round(u*l),this.canvas.style.width=`${c}px`,this.canvas.style.height=`${u}px`),o.setTransform(l,0,0,l,0,0),o.clearRect(0,0,c,u);const d=56,h=u-20,m=6,g=c-8,y=R=>d+(R-i.lo)/(i.hi-i.lo)*(g-d),p=R=>h-(R-s.lo)/(s.hi-s.lo)*(h-m);o.strokeStyle="#2a2f3a",o.strokeRect(d,m,g-d,h-m),o.fillStyle="#aab",o.font="11px system-ui, sans-serif",o.fillText(mo(s.hi,s.hi-s.lo),4,m+10),o.fillText(mo(s.lo,s.hi-s.lo),4,h),o.fillText(this.yLabel,4,(m+h)/2),o.fillText(mo(i.lo,i.hi-i.lo),d,u-4);const f=mo(i.hi,i.hi-i.lo);o.fillText(f,g-o.measureText(f).width,u-4),o.fillText(this.xLabel,(d+g)/2-10,u-4),o.save(),o.beginPath(),o.rect(d,m,g-d,h-m),o.clip(),r.hLine!==void 0&&r.hLine!==null&&this.line(o,d,p(r.hLine),g,p(r.hLine),"#ffb347"),r.vLine!==void 0&&r.vLine!==null&&this.line(o,y(r.vLine),m,y(r.vLine),h,"#888");for(const R of t){o.strokeStyle=R.color,o.lineWidth=1.5,o.beginPath();let S=!1;for(let C=0;C<R.x.length;C++){const w=R.x[C],v=R.y[C];if(!Number.isFinite(w)||!Number.isFinite(v)){S=!1;continue}const M=Math.max(-1e4,Math.min(1e4,p(v)));S?o.lineTo(y(w),M):o.moveTo(y(w),M),S=!0}o.stroke()}r.dot&&(o.fillStyle="#ff8c42",o.beginPath(),o.arc(y(r.dot[0]),p(r.dot[1]),3.5,0,2*Math.PI),o.fill()),o.restore();let x=m+12;o.textAlign="right";for(const R of t)R.label&&(o.fillStyle=R.color,o.fillText(`— ${R.label}`,g-4,x),x+=13);o.textAlign="left"}line(e,t,i,s,r,a){e.strokeStyle=a,e.lineWidth=1,e.setLineDash([4,3]),e.beginPath(),e.moveTo(t,i),e.lineTo(s,r),e.stroke(),e.setLineDash([])}}function gx(n){return Math.atan2(Math.hypot(n[0],n[1]),-n[2])}class vx{constructor(e){this.container=e,this.phase=new Ua(e,T("portrait.phase"),"z [m]","ż [m/s]"),this.potential=new Ua(e,T("portrait.veff"),"θ [rad]","E [J]"),this.em=new Ua(e,T("portrait.em"),"J₃ [kg m²/s]","E [J]");for(const t of[this.phase,this.potential,this.em])this.visibility.watch(t.canvas);this.note=document.createElement("p"),this.note.className="note",this.note.dataset.note="portraits",e.appendChild(this.note)}container;phase;potential;em;note;visibility=new Il;setModel(e){const t=pd(e)??"";this.note.textContent!==t&&(this.note.textContent=t)}updateEM(e,t){if(!this.visibility.visible(this.em.canvas))return;const i=Math.max(200,this.container.clientWidth-8);if(e===null){this.em.draw(i,[],{lo:-1,hi:1},{lo:-1,hi:1});return}const s=e.top.energy,r=er([...e.boundary.j3.filter((o,l)=>(e.boundary.energy[l]??1/0)<2.6*s),t?.j3??0],.05),a={lo:e.bottom.energy-.15*s,hi:Math.max(2.6*s,(t?.energy??0)+.2*s)};this.em.draw(i,[{x:e.boundary.j3,y:e.boundary.energy,color:"#c9a0ff",label:T("portrait.emBoundary")}],r,a,{vLine:0,hLine:e.top.energy,dot:t?[t.j3,t.energy]:null})}update(e,t,i,s,r,a){const o=Math.max(200,this.container.clientWidth-8);if(this.visibility.visible(this.phase.canvas)){const c=t?[t.x[2],t.v[2]]:null,u=er(t?[...e.z,t.x[2]]:e.z),d=er(t?[...e.zdot,t.v[2]]:e.zdot);this.phase.draw(o,[{x:e.z,y:e.zdot,color:"#59c3ff",label:T("portrait.orbit")}],u,d,{dot:c})}if(!this.visibility.visible(this.potential.canvas))return;if(i===null||i.theta.length===0){this.potential.draw(o,[],{lo:0,hi:Math.PI},{lo:-1,hi:1});return}const l=mx(i.minimum.v_eff,t?.energy??null,s*Math.max(Math.abs(r),1)*a);this.potential.draw(o,[{x:i.theta,y:i.v_eff,color:"#7dff8a",label:"V_eff(θ)"}],{lo:0,hi:Math.PI},l,{hLine:t?.energy??null,vLine:t?gx(t.x):null})}}async function lu(n,e){const t=await fetch(n,e),i=await t.json();if(!t.ok)throw new Error(fd(i,`${n}: HTTP ${t.status}`));return i}class Dm extends Error{}const _x=1;let el=0;const cu=[];async function go(n,e,t=()=>!1){el>=_x&&await new Promise(i=>cu.push(i)),el++;try{if(t())throw new Dm(`${n}: no longer needed`);return await lu(n,{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(e)})}finally{el--,cu.shift()?.()}}function xx(n){const e=Date.now()+n;return new Promise(t=>{const i=()=>el===0&&cu.length===0||Date.now()>=e?t():setTimeout(i,20);i()})}const oc=n=>e=>{e instanceof Dm||n(e)},vo=n=>n instanceof Error?n.message:String(n);class yx{constructor(e,t,i){this.store=e,this.reduced=t,this.explain=i}store;reduced;explain;veff=null;em=null;veffKey="";veffAt=-1/0;veffJ3=null;emKey="";exactEpoch=-1;reducedEpoch=-1;onFrames(){const e=this.store.status,t=this.store.trajectory[0],i=this.store.latest();if(!(e===null||t===void 0||i===null)){if(this.exactEpoch!==e.epoch&&this.fetchExact(e,t),this.reducedEpoch!==e.epoch&&this.fetchReduced(e,t),!Qv(e.model)){[this.veff,this.em,this.veffKey,this.emKey]=[null,null,"",""];return}this.fetchEM(e,t),this.fetchPotential(e,i)}}fetchPotential(e,t){const i=e.params,s=`${e.epoch}:${i.length}:${i.mass}:${i.g}`,r=performance.now(),a=Math.abs(t.j3-(this.veffJ3??NaN))>.001*Math.max(Math.abs(t.j3),1e-9);s===this.veffKey&&!(a&&r-this.veffAt>1e3)||(s!==this.veffKey&&(this.veff=null),[this.veffKey,this.veffAt,this.veffJ3]=[s,r,t.j3],go("api/effective_potential",{length:i.length,mass:i.mass,g:i.g,j3:t.j3},()=>this.veffKey!==s).then(o=>{this.veffKey===s&&(this.veff=o)},oc(o=>this.explain(T("msg.veffFailed",{why:vo(o)})))))}fetchEM(e,t){const i=e.params,s=`${i.length}:${i.mass}:${i.g}`;s!==this.emKey&&(this.emKey=s,this.em=null,i.g!==0&&go("api/em_map",{length:i.length,mass:i.mass,g:i.g,x:t.x,v:t.v},()=>this.emKey!==s).then(r=>{this.emKey===s&&(this.em=r)},oc(r=>this.explain(T("msg.emFailed",{why:vo(r)})))))}fetchReduced(e,t){if(this.reducedEpoch=e.epoch,e.model!=="ideal"){this.reduced.setNote(pd(e.model)??T("note.reducedIdeal",{model:bi(e.model,e.model)}));return}this.reduced.setNote(null);const i=e.params,s=()=>this.store.status?.epoch!==e.epoch;go("api/reduced",{length:i.length,mass:i.mass,g:i.g,x:t.x,v:t.v},s).then(r=>{s()||this.reduced.set(r)},oc(r=>this.reduced.setNote(`reduced view: ${vo(r)}`)))}fetchExact(e,t){if(this.exactEpoch=e.epoch,e.model!=="ideal")return;const i=e.params;go("api/exact",{length:i.length,mass:i.mass,g:i.g,x:t.x,v:t.v},()=>this.store.status?.epoch!==e.epoch).then(s=>{this.store.status?.epoch===e.epoch&&this.store.setExact(s)},s=>{this.store.status?.epoch===e.epoch&&this.store.setExact(null,vo(s))})}}const Ld="187",Wr={ROTATE:0,DOLLY:1,PAN:2},Hr={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},bx=0,sf=1,wx=2,tl=1,Sx=2,Da=3,Os=0,Jn=1,_i=2,qr=0,Oa=1,rf=2,af=3,of=4,Mx=5,Br=100,Ex=101,Ax=102,Tx=103,Rx=104,Cx=200,Px=201,Lx=202,Dx=203,Nm=204,Im=205,Nx=206,Ix=207,kx=208,Fx=209,Ux=210,Ox=211,zx=212,Bx=213,Hx=214,uu=0,du=1,hu=2,Ga=3,fu=4,pu=5,mu=6,gu=7,km=0,Vx=1,Gx=2,gs=0,Fm=1,Um=2,Om=3,zm=4,Bm=5,Hm=6,Vm=7,Gm=300,Jr=301,Wa=302,lc=303,cc=304,vu=1e3,hs=1001,_u=1002,Nn=1003,Wx=1004,_o=1005,jn=1006,uc=1007,Ns=1008,ai=1009,Wm=1010,qm=1011,qa=1012,Dd=1013,es=1014,Zi=1015,ts=1016,Nd=1017,Id=1018,Qr=1020,Xm=35902,$m=35899,Km=1021,Ym=1022,ji=1023,zs=1026,Is=1027,Zm=1028,kd=1029,sr=1030,Fd=1031,Ud=1033,nl=33776,il=33777,sl=33778,rl=33779,xu=35840,yu=35841,bu=35842,wu=35843,Su=36196,Mu=37492,Eu=37496,Au=37488,Tu=37489,pl=37490,Ru=37491,Cu=37808,Pu=37809,Lu=37810,Du=37811,Nu=37812,Iu=37813,ku=37814,Fu=37815,Uu=37816,Ou=37817,zu=37818,Bu=37819,Hu=37820,Vu=37821,Gu=36492,Wu=36494,qu=36495,Xu=36283,$u=36284,ml=36285,Ku=36286,qx=3200,Yu=0,Xx=1,Ds="",gi="srgb",gl="srgb-linear",vl="linear",Lt="srgb",dc=7680,$x=519,Kx=512,Yx=513,Zx=514,jm=515,jx=516,Jx=517,Jm=518,Qm=519,eg=35044,lf="300 es",Ii=2e3,Xa=2001;function Qx(n){for(let e=n.length-1;e>=0;--e)if(n[e]>=65535)return!0;return!1}function _l(n){return document.createElementNS("http://www.w3.org/1999/xhtml",n)}function ey(){const n=_l("canvas");return n.style.display="block",n}const cf={};function xl(...n){const e="THREE."+n.shift();console.log(e,...n)}function tg(n){const e=n[0];if(typeof e=="string"&&e.startsWith("TSL:")){const t=n[1];t&&t.isStackTrace?n[0]+=" "+t.getLocation():n[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return n}function je(...n){n=tg(n);const e="THREE."+n.shift();{const t=n[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...n)}}function yt(...n){n=tg(n);const e="THREE."+n.shift();{const t=n[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...n)}}function al(...n){const e=n.join(" ");e in cf||(cf[e]=!0,je(...n))}function ty(n,e,t){return new Promise(function(i,s){function r(){switch(n.clientWaitSync(e,n.SYNC_FLUSH_COMMANDS_BIT,0)){case n.WAIT_FAILED:s();break;case n.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:i()}}setTimeout(r,t)})}const ny={[uu]:uu,[hu]:mu,[fu]:fu,[Ga]:pu,[du]:du,[mu]:hu,[gu]:gu,[pu]:Ga};class Hs{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});const i=this._listeners;i[e]===void 0&&(i[e]=[]),i[e].indexOf(t)===-1&&i[e].push(t)}hasEventListener(e,t){const i=this._listeners;return i===void 0?!1:i[e]!==void 0&&i[e].indexOf(t)!==-1}removeEventListener(e,t){const i=this._listeners;if(i===void 0)return;const s=i[e];if(s!==void 0){const r=s.indexOf(t);r!==-1&&s.splice(r,1)}}dispatchEvent(e){const t=this._listeners;if(t===void 0)return;const i=t[e.type];if(i!==void 0){e.target=this;const s=i.slice(0);for(let r=0,a=s.length;r<a;r++)s[r].call(this,e);e.target=null}}}const kn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],za=Math.PI/180,Zu=180/Math.PI;function or(){const n=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,i=Math.random()*4294967295|0;return(kn[n&255]+kn[n>>8&255]+kn[n>>16&255]+kn[n>>24&255]+"-"+kn[e&255]+kn[e>>8&255]+"-"+kn[e>>16&15|64]+kn[e>>24&255]+"-"+kn[t&63|128]+kn[t>>8&255]+"-"+kn[t>>16&255]+kn[t>>24&255]+kn[i&255]+kn[i>>8&255]+kn[i>>16&255]+kn[i>>24&255]).toLowerCase()}function pt(n,e,t){return Math.max(e,Math.min(t,n))}function iy(n,e){return(n%e+e)%e}function hc(n,e,t){return(1-t)*n+t*e}function sy(n){return Math.pow(2,Math.floor(Math.log(n)/Math.LN2))}function kl(n){switch(n.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function ng(n,e){if(e.constructor===Float32Array)return n;const t=kl(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(n/t,-1)}function ig(n,e){if(e.constructor===Float32Array)return n;const t=kl(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(n*t)}const ry={DEG2RAD:za};class qe{static{this.prototype.isVector2=!0}constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){const t=this.x,i=this.y,s=e.elements;return this.x=s[0]*t+s[3]*i+s[6],this.y=s[1]*t+s[4]*i+s[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=pt(this.x,e.x,t.x),this.y=pt(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=pt(this.x,e,t),this.y=pt(this.y,e,t),this}clampLength(e,t){const i=this.length();return this.divideScalar(i||1).multiplyScalar(pt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const i=this.dot(e)/t;return Math.acos(pt(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,i=this.y-e.y;return t*t+i*i}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){const i=Math.cos(t),s=Math.sin(t),r=this.x-e.x,a=this.y-e.y;return this.x=r*i-a*s+e.x,this.y=r*s+a*i+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}}class _s{constructor(e=0,t=0,i=0,s=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=i,this._w=s}static slerpFlat(e,t,i,s,r,a,o){let l=i[s+0],c=i[s+1],u=i[s+2],d=i[s+3],h=r[a+0],m=r[a+1],g=r[a+2],y=r[a+3];if(d!==y||l!==h||c!==m||u!==g){let p=l*h+c*m+u*g+d*y;p<0&&(h=-h,m=-m,g=-g,y=-y,p=-p);let f=1-o;if(p<.9995){const x=Math.acos(p),R=Math.sin(x);f=Math.sin(f*x)/R,o=Math.sin(o*x)/R,l=l*f+h*o,c=c*f+m*o,u=u*f+g*o,d=d*f+y*o}else{l=l*f+h*o,c=c*f+m*o,u=u*f+g*o,d=d*f+y*o;const x=1/Math.sqrt(l*l+c*c+u*u+d*d);l*=x,c*=x,u*=x,d*=x}}e[t]=l,e[t+1]=c,e[t+2]=u,e[t+3]=d}static multiplyQuaternionsFlat(e,t,i,s,r,a){const o=i[s],l=i[s+1],c=i[s+2],u=i[s+3],d=r[a],h=r[a+1],m=r[a+2],g=r[a+3];return e[t]=o*g+u*d+l*m-c*h,e[t+1]=l*g+u*h+c*d-o*m,e[t+2]=c*g+u*m+o*h-l*d,e[t+3]=u*g-o*d-l*h-c*m,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,i,s){return this._x=e,this._y=t,this._z=i,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){const i=e._x,s=e._y,r=e._z,a=e._order,o=Math.cos,l=Math.sin,c=o(i/2),u=o(s/2),d=o(r/2),h=l(i/2),m=l(s/2),g=l(r/2);switch(a){case"XYZ":this._x=h*u*d+c*m*g,this._y=c*m*d-h*u*g,this._z=c*u*g+h*m*d,this._w=c*u*d-h*m*g;break;case"YXZ":this._x=h*u*d+c*m*g,this._y=c*m*d-h*u*g,this._z=c*u*g-h*m*d,this._w=c*u*d+h*m*g;break;case"ZXY":this._x=h*u*d-c*m*g,this._y=c*m*d+h*u*g,this._z=c*u*g+h*m*d,this._w=c*u*d-h*m*g;break;case"ZYX":this._x=h*u*d-c*m*g,this._y=c*m*d+h*u*g,this._z=c*u*g-h*m*d,this._w=c*u*d+h*m*g;break;case"YZX":this._x=h*u*d+c*m*g,this._y=c*m*d+h*u*g,this._z=c*u*g-h*m*d,this._w=c*u*d-h*m*g;break;case"XZY":this._x=h*u*d-c*m*g,this._y=c*m*d-h*u*g,this._z=c*u*g+h*m*d,this._w=c*u*d+h*m*g;break;default:je("Quaternion: .setFromEuler() encountered an unknown order: "+a)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){const i=t/2,s=Math.sin(i);return this._x=e.x*s,this._y=e.y*s,this._z=e.z*s,this._w=Math.cos(i),this._onChangeCallback(),this}setFromRotationMatrix(e){const t=e.elements,i=t[0],s=t[4],r=t[8],a=t[1],o=t[5],l=t[9],c=t[2],u=t[6],d=t[10],h=i+o+d;if(h>0){const m=.5/Math.sqrt(h+1);this._w=.25/m,this._x=(u-l)*m,this._y=(r-c)*m,this._z=(a-s)*m}else if(i>o&&i>d){const m=2*Math.sqrt(1+i-o-d);this._w=(u-l)/m,this._x=.25*m,this._y=(s+a)/m,this._z=(r+c)/m}else if(o>d){const m=2*Math.sqrt(1+o-i-d);this._w=(r-c)/m,this._x=(s+a)/m,this._y=.25*m,this._z=(l+u)/m}else{const m=2*Math.sqrt(1+d-i-o);this._w=(a-s)/m,this._x=(r+c)/m,this._y=(l+u)/m,this._z=.25*m}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let i=e.dot(t)+1;return i<1e-8?(i=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=i):(this._x=0,this._y=-e.z,this._z=e.y,this._w=i)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=i),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(pt(this.dot(e),-1,1)))}rotateTowards(e,t){const i=this.angleTo(e);if(i===0)return this;const s=Math.min(1,t/i);return this.slerp(e,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){const i=e._x,s=e._y,r=e._z,a=e._w,o=t._x,l=t._y,c=t._z,u=t._w;return this._x=i*u+a*o+s*c-r*l,this._y=s*u+a*l+r*o-i*c,this._z=r*u+a*c+i*l-s*o,this._w=a*u-i*o-s*l-r*c,this._onChangeCallback(),this}slerp(e,t){let i=e._x,s=e._y,r=e._z,a=e._w,o=this.dot(e);o<0&&(i=-i,s=-s,r=-r,a=-a,o=-o);let l=1-t;if(o<.9995){const c=Math.acos(o),u=Math.sin(c);l=Math.sin(l*c)/u,t=Math.sin(t*c)/u,this._x=this._x*l+i*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+a*t,this._onChangeCallback()}else this._x=this._x*l+i*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+a*t,this.normalize();return this}slerpQuaternions(e,t,i){return this.copy(e).slerp(t,i)}random(){const e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),i=Math.random(),s=Math.sqrt(1-i),r=Math.sqrt(i);return this.set(s*Math.sin(e),s*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}}class z{static{this.prototype.isVector3=!0}constructor(e=0,t=0,i=0){this.x=e,this.y=t,this.z=i}set(e,t,i){return i===void 0&&(i=this.z),this.x=e,this.y=t,this.z=i,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(uf.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(uf.setFromAxisAngle(e,t))}applyMatrix3(e){const t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[3]*i+r[6]*s,this.y=r[1]*t+r[4]*i+r[7]*s,this.z=r[2]*t+r[5]*i+r[8]*s,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){const t=this.x,i=this.y,s=this.z,r=e.elements,a=1/(r[3]*t+r[7]*i+r[11]*s+r[15]);return this.x=(r[0]*t+r[4]*i+r[8]*s+r[12])*a,this.y=(r[1]*t+r[5]*i+r[9]*s+r[13])*a,this.z=(r[2]*t+r[6]*i+r[10]*s+r[14])*a,this}applyQuaternion(e){const t=this.x,i=this.y,s=this.z,r=e.x,a=e.y,o=e.z,l=e.w,c=2*(a*s-o*i),u=2*(o*t-r*s),d=2*(r*i-a*t);return this.x=t+l*c+a*d-o*u,this.y=i+l*u+o*c-r*d,this.z=s+l*d+r*u-a*c,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){const t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[4]*i+r[8]*s,this.y=r[1]*t+r[5]*i+r[9]*s,this.z=r[2]*t+r[6]*i+r[10]*s,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=pt(this.x,e.x,t.x),this.y=pt(this.y,e.y,t.y),this.z=pt(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=pt(this.x,e,t),this.y=pt(this.y,e,t),this.z=pt(this.z,e,t),this}clampLength(e,t){const i=this.length();return this.divideScalar(i||1).multiplyScalar(pt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){const i=e.x,s=e.y,r=e.z,a=t.x,o=t.y,l=t.z;return this.x=s*l-r*o,this.y=r*a-i*l,this.z=i*o-s*a,this}projectOnVector(e){const t=e.lengthSq();if(t===0)return this.set(0,0,0);const i=e.dot(this)/t;return this.copy(e).multiplyScalar(i)}projectOnPlane(e){return fc.copy(this).projectOnVector(e),this.sub(fc)}reflect(e){return this.sub(fc.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const i=this.dot(e)/t;return Math.acos(pt(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,i=this.y-e.y,s=this.z-e.z;return t*t+i*i+s*s}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,i){const s=Math.sin(t)*e;return this.x=s*Math.sin(i),this.y=Math.cos(t)*e,this.z=s*Math.cos(i),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,i){return this.x=e*Math.sin(t),this.y=i,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){const t=this.setFromMatrixColumn(e,0).length(),i=this.setFromMatrixColumn(e,1).length(),s=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=i,this.z=s,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){const e=Math.random()*Math.PI*2,t=Math.random()*2-1,i=Math.sqrt(1-t*t);return this.x=i*Math.cos(e),this.y=t,this.z=i*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}}const fc=new z,uf=new _s;class it{static{this.prototype.isMatrix3=!0}constructor(e,t,i,s,r,a,o,l,c){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,a,o,l,c)}set(e,t,i,s,r,a,o,l,c){const u=this.elements;return u[0]=e,u[1]=s,u[2]=o,u[3]=t,u[4]=r,u[5]=l,u[6]=i,u[7]=a,u[8]=c,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){const t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],this}extractBasis(e,t,i){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),i.setFromMatrix3Column(this,2),this}setFromMatrix4(e){const t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const i=e.elements,s=t.elements,r=this.elements,a=i[0],o=i[3],l=i[6],c=i[1],u=i[4],d=i[7],h=i[2],m=i[5],g=i[8],y=s[0],p=s[3],f=s[6],x=s[1],R=s[4],S=s[7],C=s[2],w=s[5],v=s[8];return r[0]=a*y+o*x+l*C,r[3]=a*p+o*R+l*w,r[6]=a*f+o*S+l*v,r[1]=c*y+u*x+d*C,r[4]=c*p+u*R+d*w,r[7]=c*f+u*S+d*v,r[2]=h*y+m*x+g*C,r[5]=h*p+m*R+g*w,r[8]=h*f+m*S+g*v,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){const e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],u=e[8];return t*a*u-t*o*c-i*r*u+i*o*l+s*r*c-s*a*l}invert(){const e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],u=e[8],d=u*a-o*c,h=o*l-u*r,m=c*r-a*l,g=t*d+i*h+s*m;if(g===0)return this.set(0,0,0,0,0,0,0,0,0);const y=1/g;return e[0]=d*y,e[1]=(s*c-u*i)*y,e[2]=(o*i-s*a)*y,e[3]=h*y,e[4]=(u*t-s*l)*y,e[5]=(s*r-o*t)*y,e[6]=m*y,e[7]=(i*l-c*t)*y,e[8]=(a*t-i*r)*y,this}transpose(){let e;const t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){const t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,i,s,r,a,o){const l=Math.cos(r),c=Math.sin(r);return this.set(i*l,i*c,-i*(l*a+c*o)+a+e,-s*c,s*l,-s*(-c*a+l*o)+o+t,0,0,1),this}scale(e,t){return al("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(pc.makeScale(e,t)),this}rotate(e){return al("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(pc.makeRotation(-e)),this}translate(e,t){return al("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(pc.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){const t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,i,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){const t=this.elements,i=e.elements;for(let s=0;s<9;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<9;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){const i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e}clone(){return new this.constructor().fromArray(this.elements)}}const pc=new it,df=new it().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),hf=new it().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function ay(){const n={enabled:!0,workingColorSpace:gl,spaces:{},convert:function(s,r,a){return this.enabled===!1||r===a||!r||!a||(this.spaces[r].transfer===Lt&&(s.r=vs(s.r),s.g=vs(s.g),s.b=vs(s.b)),this.spaces[r].primaries!==this.spaces[a].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[a].fromXYZ)),this.spaces[a].transfer===Lt&&(s.r=Xr(s.r),s.g=Xr(s.g),s.b=Xr(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===Ds?vl:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,a){return s.copy(this.spaces[a].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],i=[.3127,.329];return n.define({[gl]:{primaries:e,whitePoint:i,transfer:vl,toXYZ:df,fromXYZ:hf,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:gi},outputColorSpaceConfig:{drawingBufferColorSpace:gi}},[gi]:{primaries:e,whitePoint:i,transfer:Lt,toXYZ:df,fromXYZ:hf,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:gi}}}),n}const vt=ay();function vs(n){return n<.04045?n*.0773993808:Math.pow(n*.9478672986+.0521327014,2.4)}function Xr(n){return n<.0031308?n*12.92:1.055*Math.pow(n,.41666)-.055}let wr;class oy{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let i;if(e instanceof HTMLCanvasElement)i=e;else{wr===void 0&&(wr=_l("canvas")),wr.width=e.width,wr.height=e.height;const s=wr.getContext("2d");e instanceof ImageData?s.putImageData(e,0,0):s.drawImage(e,0,0,e.width,e.height),i=wr}return i.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){const t=_l("canvas");t.width=e.width,t.height=e.height;const i=t.getContext("2d");i.drawImage(e,0,0,e.width,e.height);const s=i.getImageData(0,0,e.width,e.height),r=s.data;for(let a=0;a<r.length;a++)r[a]=vs(r[a]/255)*255;return i.putImageData(s,0,0),t}else if(e.data){const t=e.data.slice(0);for(let i=0;i<t.length;i++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[i]=Math.floor(vs(t[i]/255)*255):t[i]=vs(t[i]);return{data:t,width:e.width,height:e.height}}else return je("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}}let ly=0;class Od{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:ly++}),this.uuid=or(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){const t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];const i={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let a=0,o=s.length;a<o;a++)s[a].isDataTexture?r.push(mc(s[a].image)):r.push(mc(s[a]))}else r=mc(s);i.url=r}return t||(e.images[this.uuid]=i),i}}function mc(n){return typeof HTMLImageElement<"u"&&n instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&n instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&n instanceof ImageBitmap?oy.getDataURL(n):n.data?{data:Array.from(n.data),width:n.width,height:n.height,type:n.data.constructor.name}:(je("Texture: Unable to serialize Texture."),{})}let cy=0;const gc=new z;class zn extends Hs{constructor(e=zn.DEFAULT_IMAGE,t=zn.DEFAULT_MAPPING,i=hs,s=hs,r=jn,a=Ns,o=ji,l=ai,c=zn.DEFAULT_ANISOTROPY,u=Ds){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:cy++}),this.uuid=or(),this.name="",this.source=new Od(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=i,this.wrapT=s,this.magFilter=r,this.minFilter=a,this.anisotropy=c,this.format=o,this.internalFormat=null,this.type=l,this.offset=new qe(0,0),this.repeat=new qe(1,1),this.center=new qe(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new it,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=u,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(gc).x}get height(){return this.source.getSize(gc).y}get depth(){return this.source.getSize(gc).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(const t in e){const i=e[t];if(i===void 0){je(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}const s=this[t];if(s===void 0){je(`Texture.setValues(): property '${t}' does not exist.`);continue}s&&i&&s.isVector2&&i.isVector2||s&&i&&s.isVector3&&i.isVector3||s&&i&&s.isMatrix3&&i.isMatrix3?s.copy(i):this[t]=i}}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];const i={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(i.userData=this.userData),t||(e.textures[this.uuid]=i),i}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==Gm)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case vu:e.x=e.x-Math.floor(e.x);break;case hs:e.x=e.x<0?0:1;break;case _u:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case vu:e.y=e.y-Math.floor(e.y);break;case hs:e.y=e.y<0?0:1;break;case _u:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}}zn.DEFAULT_IMAGE=null;zn.DEFAULT_MAPPING=Gm;zn.DEFAULT_ANISOTROPY=1;class rn{static{this.prototype.isVector4=!0}constructor(e=0,t=0,i=0,s=1){this.x=e,this.y=t,this.z=i,this.w=s}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,i,s){return this.x=e,this.y=t,this.z=i,this.w=s,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){const t=this.x,i=this.y,s=this.z,r=this.w,a=e.elements;return this.x=a[0]*t+a[4]*i+a[8]*s+a[12]*r,this.y=a[1]*t+a[5]*i+a[9]*s+a[13]*r,this.z=a[2]*t+a[6]*i+a[10]*s+a[14]*r,this.w=a[3]*t+a[7]*i+a[11]*s+a[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);const t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,i,s,r;const l=e.elements,c=l[0],u=l[4],d=l[8],h=l[1],m=l[5],g=l[9],y=l[2],p=l[6],f=l[10];if(Math.abs(u-h)<.01&&Math.abs(d-y)<.01&&Math.abs(g-p)<.01){if(Math.abs(u+h)<.1&&Math.abs(d+y)<.1&&Math.abs(g+p)<.1&&Math.abs(c+m+f-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;const R=(c+1)/2,S=(m+1)/2,C=(f+1)/2,w=(u+h)/4,v=(d+y)/4,M=(g+p)/4;return R>S&&R>C?R<.01?(i=0,s=.707106781,r=.707106781):(i=Math.sqrt(R),s=w/i,r=v/i):S>C?S<.01?(i=.707106781,s=0,r=.707106781):(s=Math.sqrt(S),i=w/s,r=M/s):C<.01?(i=.707106781,s=.707106781,r=0):(r=Math.sqrt(C),i=v/r,s=M/r),this.set(i,s,r,t),this}let x=Math.sqrt((p-g)*(p-g)+(d-y)*(d-y)+(h-u)*(h-u));return Math.abs(x)<.001&&(x=1),this.x=(p-g)/x,this.y=(d-y)/x,this.z=(h-u)/x,this.w=Math.acos((c+m+f-1)/2),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=pt(this.x,e.x,t.x),this.y=pt(this.y,e.y,t.y),this.z=pt(this.z,e.z,t.z),this.w=pt(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=pt(this.x,e,t),this.y=pt(this.y,e,t),this.z=pt(this.z,e,t),this.w=pt(this.w,e,t),this}clampLength(e,t){const i=this.length();return this.divideScalar(i||1).multiplyScalar(pt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this.w=e.w+(t.w-e.w)*i,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}}class uy extends Hs{constructor(e=1,t=1,i={}){super(),i=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:jn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},i),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=i.depth,this.scissor=new rn(0,0,e,t),this.scissorTest=!1,this.viewport=new rn(0,0,e,t),this.textures=[];const s=i.count;for(let r=0;r<s;r++)this.textures[r]=new zn({width:e,height:t,depth:i.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(i),this.depthBuffer=i.depthBuffer,this.stencilBuffer=i.stencilBuffer,this.resolveColorBuffer=i.resolveColorBuffer,this.resolveDepthBuffer=i.resolveDepthBuffer,this.resolveStencilBuffer=i.resolveStencilBuffer,this.storeMultisampledColorBuffer=i.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=i.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=i.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=i.depthTexture,this.samples=i.samples,this.multiview=i.multiview,this.useArrayDepthTexture=i.useArrayDepthTexture}_setTextureOptions(e={}){const t={minFilter:jn,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let i=0;i<this.textures.length;i++)this.textures[i].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,i=1){if(this.width!==e||this.height!==t||this.depth!==i){this.width=e,this.height=t,this.depth=i;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=e,this.textures[s].image.height=t,this.textures[s].image.depth=i,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,i=e.textures.length;t<i;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;const s=Object.assign({},e.textures[t].image);this.textures[t].source=new Od(s)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){const t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}}class Ji extends uy{constructor(e=1,t=1,i={}){super(e,t,i),this.isWebGLRenderTarget=!0}}class sg extends zn{constructor(e=null,t=1,i=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Nn,this.minFilter=Nn,this.wrapR=hs,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}}class dy extends zn{constructor(e=null,t=1,i=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Nn,this.minFilter=Nn,this.wrapR=hs,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}}class Dt{static{this.prototype.isMatrix4=!0}constructor(e,t,i,s,r,a,o,l,c,u,d,h,m,g,y,p){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,a,o,l,c,u,d,h,m,g,y,p)}set(e,t,i,s,r,a,o,l,c,u,d,h,m,g,y,p){const f=this.elements;return f[0]=e,f[4]=t,f[8]=i,f[12]=s,f[1]=r,f[5]=a,f[9]=o,f[13]=l,f[2]=c,f[6]=u,f[10]=d,f[14]=h,f[3]=m,f[7]=g,f[11]=y,f[15]=p,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new Dt().fromArray(this.elements)}copy(e){const t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],t[9]=i[9],t[10]=i[10],t[11]=i[11],t[12]=i[12],t[13]=i[13],t[14]=i[14],t[15]=i[15],this}copyPosition(e){const t=this.elements,i=e.elements;return t[12]=i[12],t[13]=i[13],t[14]=i[14],this}setFromMatrix3(e){const t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,i){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),i.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),i.setFromMatrixColumn(this,2),this)}makeBasis(e,t,i){return this.set(e.x,t.x,i.x,0,e.y,t.y,i.y,0,e.z,t.z,i.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();const t=this.elements,i=e.elements,s=1/Sr.setFromMatrixColumn(e,0).length(),r=1/Sr.setFromMatrixColumn(e,1).length(),a=1/Sr.setFromMatrixColumn(e,2).length();return t[0]=i[0]*s,t[1]=i[1]*s,t[2]=i[2]*s,t[3]=0,t[4]=i[4]*r,t[5]=i[5]*r,t[6]=i[6]*r,t[7]=0,t[8]=i[8]*a,t[9]=i[9]*a,t[10]=i[10]*a,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){const t=this.elements,i=e.x,s=e.y,r=e.z,a=Math.cos(i),o=Math.sin(i),l=Math.cos(s),c=Math.sin(s),u=Math.cos(r),d=Math.sin(r);if(e.order==="XYZ"){const h=a*u,m=a*d,g=o*u,y=o*d;t[0]=l*u,t[4]=-l*d,t[8]=c,t[1]=m+g*c,t[5]=h-y*c,t[9]=-o*l,t[2]=y-h*c,t[6]=g+m*c,t[10]=a*l}else if(e.order==="YXZ"){const h=l*u,m=l*d,g=c*u,y=c*d;t[0]=h+y*o,t[4]=g*o-m,t[8]=a*c,t[1]=a*d,t[5]=a*u,t[9]=-o,t[2]=m*o-g,t[6]=y+h*o,t[10]=a*l}else if(e.order==="ZXY"){const h=l*u,m=l*d,g=c*u,y=c*d;t[0]=h-y*o,t[4]=-a*d,t[8]=g+m*o,t[1]=m+g*o,t[5]=a*u,t[9]=y-h*o,t[2]=-a*c,t[6]=o,t[10]=a*l}else if(e.order==="ZYX"){const h=a*u,m=a*d,g=o*u,y=o*d;t[0]=l*u,t[4]=g*c-m,t[8]=h*c+y,t[1]=l*d,t[5]=y*c+h,t[9]=m*c-g,t[2]=-c,t[6]=o*l,t[10]=a*l}else if(e.order==="YZX"){const h=a*l,m=a*c,g=o*l,y=o*c;t[0]=l*u,t[4]=y-h*d,t[8]=g*d+m,t[1]=d,t[5]=a*u,t[9]=-o*u,t[2]=-c*u,t[6]=m*d+g,t[10]=h-y*d}else if(e.order==="XZY"){const h=a*l,m=a*c,g=o*l,y=o*c;t[0]=l*u,t[4]=-d,t[8]=c*u,t[1]=h*d+y,t[5]=a*u,t[9]=m*d-g,t[2]=g*d-m,t[6]=o*u,t[10]=y*d+h}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(hy,e,fy)}lookAt(e,t,i){const s=this.elements;return ii.subVectors(e,t),ii.lengthSq()===0&&(ii.z=1),ii.normalize(),Es.crossVectors(i,ii),Es.lengthSq()===0&&(Math.abs(i.z)===1?ii.x+=1e-4:ii.z+=1e-4,ii.normalize(),Es.crossVectors(i,ii)),Es.normalize(),xo.crossVectors(ii,Es),s[0]=Es.x,s[4]=xo.x,s[8]=ii.x,s[1]=Es.y,s[5]=xo.y,s[9]=ii.y,s[2]=Es.z,s[6]=xo.z,s[10]=ii.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const i=e.elements,s=t.elements,r=this.elements,a=i[0],o=i[4],l=i[8],c=i[12],u=i[1],d=i[5],h=i[9],m=i[13],g=i[2],y=i[6],p=i[10],f=i[14],x=i[3],R=i[7],S=i[11],C=i[15],w=s[0],v=s[4],M=s[8],F=s[12],L=s[1],D=s[5],B=s[9],G=s[13],k=s[2],W=s[6],Y=s[10],V=s[14],le=s[3],j=s[7],Q=s[11],se=s[15];return r[0]=a*w+o*L+l*k+c*le,r[4]=a*v+o*D+l*W+c*j,r[8]=a*M+o*B+l*Y+c*Q,r[12]=a*F+o*G+l*V+c*se,r[1]=u*w+d*L+h*k+m*le,r[5]=u*v+d*D+h*W+m*j,r[9]=u*M+d*B+h*Y+m*Q,r[13]=u*F+d*G+h*V+m*se,r[2]=g*w+y*L+p*k+f*le,r[6]=g*v+y*D+p*W+f*j,r[10]=g*M+y*B+p*Y+f*Q,r[14]=g*F+y*G+p*V+f*se,r[3]=x*w+R*L+S*k+C*le,r[7]=x*v+R*D+S*W+C*j,r[11]=x*M+R*B+S*Y+C*Q,r[15]=x*F+R*G+S*V+C*se,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){const e=this.elements,t=e[0],i=e[4],s=e[8],r=e[12],a=e[1],o=e[5],l=e[9],c=e[13],u=e[2],d=e[6],h=e[10],m=e[14],g=e[3],y=e[7],p=e[11],f=e[15],x=l*m-c*h,R=o*m-c*d,S=o*h-l*d,C=a*m-c*u,w=a*h-l*u,v=a*d-o*u;return t*(y*x-p*R+f*S)-i*(g*x-p*C+f*w)+s*(g*R-y*C+f*v)-r*(g*S-y*w+p*v)}determinantAffine(){const e=this.elements,t=e[0],i=e[4],s=e[8],r=e[1],a=e[5],o=e[9],l=e[2],c=e[6],u=e[10];return t*(a*u-o*c)-i*(r*u-o*l)+s*(r*c-a*l)}transpose(){const e=this.elements;let t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,i){const s=this.elements;return e.isVector3?(s[12]=e.x,s[13]=e.y,s[14]=e.z):(s[12]=e,s[13]=t,s[14]=i),this}invert(){const e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],u=e[8],d=e[9],h=e[10],m=e[11],g=e[12],y=e[13],p=e[14],f=e[15],x=t*o-i*a,R=t*l-s*a,S=t*c-r*a,C=i*l-s*o,w=i*c-r*o,v=s*c-r*l,M=u*y-d*g,F=u*p-h*g,L=u*f-m*g,D=d*p-h*y,B=d*f-m*y,G=h*f-m*p,k=x*G-R*B+S*D+C*L-w*F+v*M;if(k===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);const W=1/k;return e[0]=(o*G-l*B+c*D)*W,e[1]=(s*B-i*G-r*D)*W,e[2]=(y*v-p*w+f*C)*W,e[3]=(h*w-d*v-m*C)*W,e[4]=(l*L-a*G-c*F)*W,e[5]=(t*G-s*L+r*F)*W,e[6]=(p*S-g*v-f*R)*W,e[7]=(u*v-h*S+m*R)*W,e[8]=(a*B-o*L+c*M)*W,e[9]=(i*L-t*B-r*M)*W,e[10]=(g*w-y*S+f*x)*W,e[11]=(d*S-u*w-m*x)*W,e[12]=(o*F-a*D-l*M)*W,e[13]=(t*D-i*F+s*M)*W,e[14]=(y*R-g*C-p*x)*W,e[15]=(u*C-d*R+h*x)*W,this}scale(e){const t=this.elements,i=e.x,s=e.y,r=e.z;return t[0]*=i,t[4]*=s,t[8]*=r,t[1]*=i,t[5]*=s,t[9]*=r,t[2]*=i,t[6]*=s,t[10]*=r,t[3]*=i,t[7]*=s,t[11]*=r,this}getMaxScaleOnAxis(){const e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],i=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],s=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,i,s))}makeTranslation(e,t,i){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,i,0,0,0,1),this}makeRotationX(e){const t=Math.cos(e),i=Math.sin(e);return this.set(1,0,0,0,0,t,-i,0,0,i,t,0,0,0,0,1),this}makeRotationY(e){const t=Math.cos(e),i=Math.sin(e);return this.set(t,0,i,0,0,1,0,0,-i,0,t,0,0,0,0,1),this}makeRotationZ(e){const t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,0,i,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){const i=Math.cos(t),s=Math.sin(t),r=1-i,a=e.x,o=e.y,l=e.z,c=r*a,u=r*o;return this.set(c*a+i,c*o-s*l,c*l+s*o,0,c*o+s*l,u*o+i,u*l-s*a,0,c*l-s*o,u*l+s*a,r*l*l+i,0,0,0,0,1),this}makeScale(e,t,i){return this.set(e,0,0,0,0,t,0,0,0,0,i,0,0,0,0,1),this}makeShear(e,t,i,s,r,a){return this.set(1,i,r,0,e,1,a,0,t,s,1,0,0,0,0,1),this}compose(e,t,i){const s=this.elements,r=t._x,a=t._y,o=t._z,l=t._w,c=r+r,u=a+a,d=o+o,h=r*c,m=r*u,g=r*d,y=a*u,p=a*d,f=o*d,x=l*c,R=l*u,S=l*d,C=i.x,w=i.y,v=i.z;return s[0]=(1-(y+f))*C,s[1]=(m+S)*C,s[2]=(g-R)*C,s[3]=0,s[4]=(m-S)*w,s[5]=(1-(h+f))*w,s[6]=(p+x)*w,s[7]=0,s[8]=(g+R)*v,s[9]=(p-x)*v,s[10]=(1-(h+y))*v,s[11]=0,s[12]=e.x,s[13]=e.y,s[14]=e.z,s[15]=1,this}decompose(e,t,i){const s=this.elements;e.x=s[12],e.y=s[13],e.z=s[14];const r=this.determinantAffine();if(r===0)return i.set(1,1,1),t.identity(),this;let a=Sr.set(s[0],s[1],s[2]).length();const o=Sr.set(s[4],s[5],s[6]).length(),l=Sr.set(s[8],s[9],s[10]).length();r<0&&(a=-a),Ai.copy(this);const c=1/a,u=1/o,d=1/l;return Ai.elements[0]*=c,Ai.elements[1]*=c,Ai.elements[2]*=c,Ai.elements[4]*=u,Ai.elements[5]*=u,Ai.elements[6]*=u,Ai.elements[8]*=d,Ai.elements[9]*=d,Ai.elements[10]*=d,t.setFromRotationMatrix(Ai),i.x=a,i.y=o,i.z=l,this}makePerspective(e,t,i,s,r,a,o=Ii,l=!1){const c=this.elements,u=2*r/(t-e),d=2*r/(i-s),h=(t+e)/(t-e),m=(i+s)/(i-s);let g,y;if(l)g=r/(a-r),y=a*r/(a-r);else if(o===Ii)g=-(a+r)/(a-r),y=-2*a*r/(a-r);else if(o===Xa)g=-a/(a-r),y=-a*r/(a-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return c[0]=u,c[4]=0,c[8]=h,c[12]=0,c[1]=0,c[5]=d,c[9]=m,c[13]=0,c[2]=0,c[6]=0,c[10]=g,c[14]=y,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(e,t,i,s,r,a,o=Ii,l=!1){const c=this.elements,u=2/(t-e),d=2/(i-s),h=-(t+e)/(t-e),m=-(i+s)/(i-s);let g,y;if(l)g=1/(a-r),y=a/(a-r);else if(o===Ii)g=-2/(a-r),y=-(a+r)/(a-r);else if(o===Xa)g=-1/(a-r),y=-r/(a-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return c[0]=u,c[4]=0,c[8]=0,c[12]=h,c[1]=0,c[5]=d,c[9]=0,c[13]=m,c[2]=0,c[6]=0,c[10]=g,c[14]=y,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(e){const t=this.elements,i=e.elements;for(let s=0;s<16;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<16;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){const i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e[t+9]=i[9],e[t+10]=i[10],e[t+11]=i[11],e[t+12]=i[12],e[t+13]=i[13],e[t+14]=i[14],e[t+15]=i[15],e}}const Sr=new z,Ai=new Dt,hy=new z(0,0,0),fy=new z(1,1,1),Es=new z,xo=new z,ii=new z,ff=new Dt,pf=new _s;class Bs{constructor(e=0,t=0,i=0,s=Bs.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=i,this._order=s}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,i,s=this._order){return this._x=e,this._y=t,this._z=i,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,i=!0){const s=e.elements,r=s[0],a=s[4],o=s[8],l=s[1],c=s[5],u=s[9],d=s[2],h=s[6],m=s[10];switch(t){case"XYZ":this._y=Math.asin(pt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-u,m),this._z=Math.atan2(-a,r)):(this._x=Math.atan2(h,c),this._z=0);break;case"YXZ":this._x=Math.asin(-pt(u,-1,1)),Math.abs(u)<.9999999?(this._y=Math.atan2(o,m),this._z=Math.atan2(l,c)):(this._y=Math.atan2(-d,r),this._z=0);break;case"ZXY":this._x=Math.asin(pt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(-d,m),this._z=Math.atan2(-a,c)):(this._y=0,this._z=Math.atan2(l,r));break;case"ZYX":this._y=Math.asin(-pt(d,-1,1)),Math.abs(d)<.9999999?(this._x=Math.atan2(h,m),this._z=Math.atan2(l,r)):(this._x=0,this._z=Math.atan2(-a,c));break;case"YZX":this._z=Math.asin(pt(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-u,c),this._y=Math.atan2(-d,r)):(this._x=0,this._y=Math.atan2(o,m));break;case"XZY":this._z=Math.asin(-pt(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(h,c),this._y=Math.atan2(o,r)):(this._x=Math.atan2(-u,m),this._y=0);break;default:je("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,i===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,i){return ff.makeRotationFromQuaternion(e),this.setFromRotationMatrix(ff,t,i)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return pf.setFromEuler(this),this.setFromQuaternion(pf,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}}Bs.DEFAULT_ORDER="XYZ";class zd{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}}let py=0;const mf=new z,Mr=new _s,os=new Dt,yo=new z,xa=new z,my=new z,gy=new _s,gf=new z(1,0,0),vf=new z(0,1,0),_f=new z(0,0,1),xf={type:"added"},vy={type:"removed"},Er={type:"childadded",child:null},vc={type:"childremoved",child:null};class bn extends Hs{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:py++}),this.uuid=or(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=bn.DEFAULT_UP.clone();const e=new z,t=new Bs,i=new _s,s=new z(1,1,1);function r(){i.setFromEuler(t,!1)}function a(){t.setFromQuaternion(i,void 0,!1)}t._onChange(r),i._onChange(a),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:i},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new Dt},normalMatrix:{value:new it}}),this.matrix=new Dt,this.matrixWorld=new Dt,this.matrixAutoUpdate=bn.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=bn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new zd,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return Mr.setFromAxisAngle(e,t),this.quaternion.multiply(Mr),this}rotateOnWorldAxis(e,t){return Mr.setFromAxisAngle(e,t),this.quaternion.premultiply(Mr),this}rotateX(e){return this.rotateOnAxis(gf,e)}rotateY(e){return this.rotateOnAxis(vf,e)}rotateZ(e){return this.rotateOnAxis(_f,e)}translateOnAxis(e,t){return mf.copy(e).applyQuaternion(this.quaternion),this.position.add(mf.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(gf,e)}translateY(e){return this.translateOnAxis(vf,e)}translateZ(e){return this.translateOnAxis(_f,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(os.copy(this.matrixWorld).invert())}lookAt(e,t,i){e.isVector3?yo.copy(e):yo.set(e,t,i);const s=this.parent;this.updateWorldMatrix(!0,!1),xa.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?os.lookAt(xa,yo,this.up):os.lookAt(yo,xa,this.up),this.quaternion.setFromRotationMatrix(os),s&&(os.extractRotation(s.matrixWorld),Mr.setFromRotationMatrix(os),this.quaternion.premultiply(Mr.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(yt("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(xf),Er.child=e,this.dispatchEvent(Er),Er.child=null):yt("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let i=0;i<arguments.length;i++)this.remove(arguments[i]);return this}const t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(vy),vc.child=e,this.dispatchEvent(vc),vc.child=null),this}removeFromParent(){const e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),os.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),os.multiply(e.parent.matrixWorld)),e.applyMatrix4(os),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(xf),Er.child=e,this.dispatchEvent(Er),Er.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let i=0,s=this.children.length;i<s;i++){const a=this.children[i].getObjectByProperty(e,t);if(a!==void 0)return a}}getObjectsByProperty(e,t,i=[]){this[e]===t&&i.push(this);const s=this.children;for(let r=0,a=s.length;r<a;r++)s[r].getObjectsByProperty(e,t,i);return i}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(xa,e,my),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(xa,gy,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);const t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);const t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);const t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverseVisible(e)}traverseAncestors(e){const t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);const e=this.pivot;if(e!==null){const t=e.x,i=e.y,s=e.z,r=this.matrix.elements;r[12]+=t-r[0]*t-r[4]*i-r[8]*s,r[13]+=i-r[1]*t-r[5]*i-r[9]*s,r[14]+=s-r[2]*t-r[6]*i-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);const t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].updateMatrixWorld(e)}updateWorldMatrix(e,t,i=!1){const s=this.parent;if(e===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||i)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,i=!0),t===!0){const r=this.children;for(let a=0,o=r.length;a<o;a++)r[a].updateWorldMatrix(!1,!0,i)}}toJSON(e){const t=e===void 0||typeof e=="string",i={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},i.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});const s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(o=>({...o,boundingBox:o.boundingBox?o.boundingBox.toJSON():void 0,boundingSphere:o.boundingSphere?o.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(o=>({...o})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(e),s.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(o,l){return o[l.uuid]===void 0&&(o[l.uuid]=l.toJSON(e)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(e.geometries,this.geometry);const o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){const l=o.shapes;if(Array.isArray(l))for(let c=0,u=l.length;c<u;c++){const d=l[c];r(e.shapes,d)}else r(e.shapes,l)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){const o=[];for(let l=0,c=this.material.length;l<c;l++)o.push(r(e.materials,this.material[l]));s.material=o}else s.material=r(e.materials,this.material);if(this.children.length>0){s.children=[];for(let o=0;o<this.children.length;o++)s.children.push(this.children[o].toJSON(e).object)}if(this.animations.length>0){s.animations=[];for(let o=0;o<this.animations.length;o++){const l=this.animations[o];s.animations.push(r(e.animations,l))}}if(t){const o=a(e.geometries),l=a(e.materials),c=a(e.textures),u=a(e.images),d=a(e.shapes),h=a(e.skeletons),m=a(e.animations),g=a(e.nodes);o.length>0&&(i.geometries=o),l.length>0&&(i.materials=l),c.length>0&&(i.textures=c),u.length>0&&(i.images=u),d.length>0&&(i.shapes=d),h.length>0&&(i.skeletons=h),m.length>0&&(i.animations=m),g.length>0&&(i.nodes=g)}return i.object=s,i;function a(o){const l=[];for(const c in o){const u=o[c];delete u.metadata,l.push(u)}return l}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let i=0;i<e.children.length;i++){const s=e.children[i];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}}bn.DEFAULT_UP=new z(0,1,0);bn.DEFAULT_MATRIX_AUTO_UPDATE=!0;bn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;class ki extends bn{constructor(){super(),this.isGroup=!0,this.type="Group"}}const _y={type:"move"};class _c{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new ki,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new ki,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new z,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new z),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new ki,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new z,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new z,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){const t=this._hand;if(t)for(const i of e.hand.values())this._getHandJoint(t,i)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,i){let s=null,r=null,a=null;const o=this._targetRay,l=this._grip,c=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(c&&e.hand){a=!0;for(const y of e.hand.values()){const p=t.getJointPose(y,i),f=this._getHandJoint(c,y);p!==null&&(f.matrix.fromArray(p.transform.matrix),f.matrix.decompose(f.position,f.quaternion,f.scale),f.matrixWorldNeedsUpdate=!0,f.jointRadius=p.radius),f.visible=p!==null}const u=c.joints["index-finger-tip"],d=c.joints["thumb-tip"],h=u.position.distanceTo(d.position),m=.02,g=.005;c.inputState.pinching&&h>m+g?(c.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!c.inputState.pinching&&h<=m-g&&(c.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else l!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,i),r!==null&&(l.matrix.fromArray(r.transform.matrix),l.matrix.decompose(l.position,l.quaternion,l.scale),l.matrixWorldNeedsUpdate=!0,r.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(r.linearVelocity)):l.hasLinearVelocity=!1,r.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(r.angularVelocity)):l.hasAngularVelocity=!1,l.eventsEnabled&&l.dispatchEvent({type:"gripUpdated",data:e,target:this})));o!==null&&(s=t.getPose(e.targetRaySpace,i),s===null&&r!==null&&(s=r),s!==null&&(o.matrix.fromArray(s.transform.matrix),o.matrix.decompose(o.position,o.quaternion,o.scale),o.matrixWorldNeedsUpdate=!0,s.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(s.linearVelocity)):o.hasLinearVelocity=!1,s.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(s.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(_y)))}return o!==null&&(o.visible=s!==null),l!==null&&(l.visible=r!==null),c!==null&&(c.visible=a!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){const i=new ki;i.matrixAutoUpdate=!1,i.visible=!1,e.joints[t.jointName]=i,e.add(i)}return e.joints[t.jointName]}}const rg={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},As={h:0,s:0,l:0},bo={h:0,s:0,l:0};function xc(n,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?n+(e-n)*6*t:t<1/2?e:t<2/3?n+(e-n)*6*(2/3-t):n}class lt{constructor(e,t,i){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,i)}set(e,t,i){if(t===void 0&&i===void 0){const s=e;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(e,t,i);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=gi){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,vt.colorSpaceToWorking(this,t),this}setRGB(e,t,i,s=vt.workingColorSpace){return this.r=e,this.g=t,this.b=i,vt.colorSpaceToWorking(this,s),this}setHSL(e,t,i,s=vt.workingColorSpace){if(e=iy(e,1),t=pt(t,0,1),i=pt(i,0,1),t===0)this.r=this.g=this.b=i;else{const r=i<=.5?i*(1+t):i+t-i*t,a=2*i-r;this.r=xc(a,r,e+1/3),this.g=xc(a,r,e),this.b=xc(a,r,e-1/3)}return vt.colorSpaceToWorking(this,s),this}setStyle(e,t=gi){function i(r){r!==void 0&&parseFloat(r)<1&&je("Color: Alpha component of "+e+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(e)){let r;const a=s[1],o=s[2];switch(a){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return i(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return i(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,t);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return i(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:je("Color: Unknown color model "+e)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(e)){const r=s[1],a=r.length;if(a===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(a===6)return this.setHex(parseInt(r,16),t);je("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=gi){const i=rg[e.toLowerCase()];return i!==void 0?this.setHex(i,t):je("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=vs(e.r),this.g=vs(e.g),this.b=vs(e.b),this}copyLinearToSRGB(e){return this.r=Xr(e.r),this.g=Xr(e.g),this.b=Xr(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=gi){return vt.workingToColorSpace(Fn.copy(this),e),Math.round(pt(Fn.r*255,0,255))*65536+Math.round(pt(Fn.g*255,0,255))*256+Math.round(pt(Fn.b*255,0,255))}getHexString(e=gi){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=vt.workingColorSpace){vt.workingToColorSpace(Fn.copy(this),t);const i=Fn.r,s=Fn.g,r=Fn.b,a=Math.max(i,s,r),o=Math.min(i,s,r);let l,c;const u=(o+a)/2;if(o===a)l=0,c=0;else{const d=a-o;switch(c=u<=.5?d/(a+o):d/(2-a-o),a){case i:l=(s-r)/d+(s<r?6:0);break;case s:l=(r-i)/d+2;break;case r:l=(i-s)/d+4;break}l/=6}return e.h=l,e.s=c,e.l=u,e}getRGB(e,t=vt.workingColorSpace){return vt.workingToColorSpace(Fn.copy(this),t),e.r=Fn.r,e.g=Fn.g,e.b=Fn.b,e}getStyle(e=gi){vt.workingToColorSpace(Fn.copy(this),e);const t=Fn.r,i=Fn.g,s=Fn.b;return e!==gi?`color(${e} ${t.toFixed(3)} ${i.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(i*255)},${Math.round(s*255)})`}offsetHSL(e,t,i){return this.getHSL(As),this.setHSL(As.h+e,As.s+t,As.l+i)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,i){return this.r=e.r+(t.r-e.r)*i,this.g=e.g+(t.g-e.g)*i,this.b=e.b+(t.b-e.b)*i,this}lerpHSL(e,t){this.getHSL(As),e.getHSL(bo);const i=hc(As.h,bo.h,t),s=hc(As.s,bo.s,t),r=hc(As.l,bo.l,t);return this.setHSL(i,s,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){const t=this.r,i=this.g,s=this.b,r=e.elements;return this.r=r[0]*t+r[3]*i+r[6]*s,this.g=r[1]*t+r[4]*i+r[7]*s,this.b=r[2]*t+r[5]*i+r[8]*s,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}}const Fn=new lt;lt.NAMES=rg;class ag extends bn{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Bs,this.environmentIntensity=1,this.environmentRotation=new Bs,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){const t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}}const Ti=new z,ls=new z,yc=new z,cs=new z,Ar=new z,Tr=new z,yf=new z,bc=new z,wc=new z,Sc=new z,Mc=new rn,Ec=new rn,Ac=new rn;class xi{constructor(e=new z,t=new z,i=new z){this.a=e,this.b=t,this.c=i}static getNormal(e,t,i,s){s.subVectors(i,t),Ti.subVectors(e,t),s.cross(Ti);const r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(e,t,i,s,r){Ti.subVectors(s,t),ls.subVectors(i,t),yc.subVectors(e,t);const a=Ti.dot(Ti),o=Ti.dot(ls),l=Ti.dot(yc),c=ls.dot(ls),u=ls.dot(yc),d=a*c-o*o;if(d===0)return r.set(0,0,0),null;const h=1/d,m=(c*l-o*u)*h,g=(a*u-o*l)*h;return r.set(1-m-g,g,m)}static containsPoint(e,t,i,s){return this.getBarycoord(e,t,i,s,cs)===null?!1:cs.x>=0&&cs.y>=0&&cs.x+cs.y<=1}static getInterpolation(e,t,i,s,r,a,o,l){return this.getBarycoord(e,t,i,s,cs)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(r,cs.x),l.addScaledVector(a,cs.y),l.addScaledVector(o,cs.z),l)}static getInterpolatedAttribute(e,t,i,s,r,a){return Mc.setScalar(0),Ec.setScalar(0),Ac.setScalar(0),Mc.fromBufferAttribute(e,t),Ec.fromBufferAttribute(e,i),Ac.fromBufferAttribute(e,s),a.setScalar(0),a.addScaledVector(Mc,r.x),a.addScaledVector(Ec,r.y),a.addScaledVector(Ac,r.z),a}static isFrontFacing(e,t,i,s){return Ti.subVectors(i,t),ls.subVectors(e,t),Ti.cross(ls).dot(s)<0}set(e,t,i){return this.a.copy(e),this.b.copy(t),this.c.copy(i),this}setFromPointsAndIndices(e,t,i,s){return this.a.copy(e[t]),this.b.copy(e[i]),this.c.copy(e[s]),this}setFromAttributeAndIndices(e,t,i,s){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,i),this.c.fromBufferAttribute(e,s),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return Ti.subVectors(this.c,this.b),ls.subVectors(this.a,this.b),Ti.cross(ls).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return xi.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return xi.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,i,s,r){return xi.getInterpolation(e,this.a,this.b,this.c,t,i,s,r)}containsPoint(e){return xi.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return xi.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){const i=this.a,s=this.b,r=this.c;let a,o;Ar.subVectors(s,i),Tr.subVectors(r,i),bc.subVectors(e,i);const l=Ar.dot(bc),c=Tr.dot(bc);if(l<=0&&c<=0)return t.copy(i);wc.subVectors(e,s);const u=Ar.dot(wc),d=Tr.dot(wc);if(u>=0&&d<=u)return t.copy(s);const h=l*d-u*c;if(h<=0&&l>=0&&u<=0&&l-u>0)return a=l/(l-u),t.copy(i).addScaledVector(Ar,a);Sc.subVectors(e,r);const m=Ar.dot(Sc),g=Tr.dot(Sc);if(g>=0&&m<=g)return t.copy(r);const y=m*c-l*g;if(y<=0&&c>=0&&g<=0)return o=c/(c-g),t.copy(i).addScaledVector(Tr,o);const p=u*g-m*d;if(p<=0&&d-u>=0&&m-g>=0)return yf.subVectors(r,s),o=(d-u)/(d-u+(m-g)),t.copy(s).addScaledVector(yf,o);const f=1/(p+y+h);return a=y*f,o=h*f,t.copy(i).addScaledVector(Ar,a).addScaledVector(Tr,o)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}}class to{constructor(e=new z(1/0,1/0,1/0),t=new z(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t+=3)this.expandByPoint(Ri.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,i=e.count;t<i;t++)this.expandByPoint(Ri.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){const i=Ri.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(i),this.max.copy(e).add(i),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);const i=e.geometry;if(i!==void 0){const r=i.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let a=0,o=r.count;a<o;a++)e.isMesh===!0?e.getVertexPosition(a,Ri):Ri.fromBufferAttribute(r,a),Ri.applyMatrix4(e.matrixWorld),this.expandByPoint(Ri);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),wo.copy(e.boundingBox)):(i.boundingBox===null&&i.computeBoundingBox(),wo.copy(i.boundingBox)),wo.applyMatrix4(e.matrixWorld),this.union(wo)}const s=e.children;for(let r=0,a=s.length;r<a;r++)this.expandByObject(s[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,Ri),Ri.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,i;return e.normal.x>0?(t=e.normal.x*this.min.x,i=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,i=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,i+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,i+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,i+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,i+=e.normal.z*this.min.z),t<=-e.constant&&i>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(ya),So.subVectors(this.max,ya),Rr.subVectors(e.a,ya),Cr.subVectors(e.b,ya),Pr.subVectors(e.c,ya),Ts.subVectors(Cr,Rr),Rs.subVectors(Pr,Cr),qs.subVectors(Rr,Pr);let t=[0,-Ts.z,Ts.y,0,-Rs.z,Rs.y,0,-qs.z,qs.y,Ts.z,0,-Ts.x,Rs.z,0,-Rs.x,qs.z,0,-qs.x,-Ts.y,Ts.x,0,-Rs.y,Rs.x,0,-qs.y,qs.x,0];return!Tc(t,Rr,Cr,Pr,So)||(t=[1,0,0,0,1,0,0,0,1],!Tc(t,Rr,Cr,Pr,So))?!1:(Mo.crossVectors(Ts,Rs),t=[Mo.x,Mo.y,Mo.z],Tc(t,Rr,Cr,Pr,So))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,Ri).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(Ri).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(us[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),us[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),us[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),us[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),us[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),us[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),us[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),us[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(us),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}}const us=[new z,new z,new z,new z,new z,new z,new z,new z],Ri=new z,wo=new to,Rr=new z,Cr=new z,Pr=new z,Ts=new z,Rs=new z,qs=new z,ya=new z,So=new z,Mo=new z,Xs=new z;function Tc(n,e,t,i,s){for(let r=0,a=n.length-3;r<=a;r+=3){Xs.fromArray(n,r);const o=s.x*Math.abs(Xs.x)+s.y*Math.abs(Xs.y)+s.z*Math.abs(Xs.z),l=e.dot(Xs),c=t.dot(Xs),u=i.dot(Xs);if(Math.max(-Math.max(l,c,u),Math.min(l,c,u))>o)return!1}return!0}const fn=new z,Eo=new qe;let xy=0;class li extends Hs{constructor(e,t,i=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:xy++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=i,this.usage=eg,this.updateRanges=[],this.gpuType=Zi,this.version=0,this._normalizationScale=e!==void 0?kl(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,i){e*=this.itemSize,i*=t.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[e+s]=t.array[i+s];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,i=this.count;t<i;t++)Eo.fromBufferAttribute(this,t),Eo.applyMatrix3(e),this.setXY(t,Eo.x,Eo.y);else if(this.itemSize===3)for(let t=0,i=this.count;t<i;t++)fn.fromBufferAttribute(this,t),fn.applyMatrix3(e),this.setXYZ(t,fn.x,fn.y,fn.z);return this}applyMatrix4(e){for(let t=0,i=this.count;t<i;t++)fn.fromBufferAttribute(this,t),fn.applyMatrix4(e),this.setXYZ(t,fn.x,fn.y,fn.z);return this}applyNormalMatrix(e){for(let t=0,i=this.count;t<i;t++)fn.fromBufferAttribute(this,t),fn.applyNormalMatrix(e),this.setXYZ(t,fn.x,fn.y,fn.z);return this}transformDirection(e){for(let t=0,i=this.count;t<i;t++)fn.fromBufferAttribute(this,t),fn.transformDirection(e),this.setXYZ(t,fn.x,fn.y,fn.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let i=this.array[e*this.itemSize+t];return this.normalized&&(i=this._denormalize(i)),i}setComponent(e,t,i){return this.normalized&&(i=this._normalize(i)),this.array[e*this.itemSize+t]=i,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,i){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i)),this.array[e+0]=t,this.array[e+1]=i,this}setXYZ(e,t,i,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this}setXYZW(e,t,i,s,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){const e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){const t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):ng(e,this.array)}_normalize(e){const t=this._normalizationScale;return t!==void 0?Math.round(e*t):ig(e,this.array)}}class og extends li{constructor(e,t,i){super(new Uint16Array(e),t,i)}}class lg extends li{constructor(e,t,i){super(new Uint32Array(e),t,i)}}class an extends li{constructor(e,t,i){super(new Float32Array(e),t,i)}}const yy=new to,ba=new z,Rc=new z;class no{constructor(e=new z,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){const i=this.center;t!==void 0?i.copy(t):yy.setFromPoints(e).getCenter(i);let s=0;for(let r=0,a=e.length;r<a;r++)s=Math.max(s,i.distanceToSquared(e[r]));return this.radius=Math.sqrt(s),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){const t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){const i=this.center.distanceToSquared(e);return t.copy(e),i>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;ba.subVectors(e,this.center);const t=ba.lengthSq();if(t>this.radius*this.radius){const i=Math.sqrt(t),s=(i-this.radius)*.5;this.center.addScaledVector(ba,s/i),this.radius+=s}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(Rc.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(ba.copy(e.center).add(Rc)),this.expandByPoint(ba.copy(e.center).sub(Rc))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}}let by=0;const fi=new Dt,Cc=new bn,Lr=new z,si=new to,wa=new to,Pn=new z;class Ot extends Hs{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:by++}),this.uuid=or(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(Qx(e)?lg:og)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,i=0){this.groups.push({start:e,count:t,materialIndex:i})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){const t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);const i=this.attributes.normal;if(i!==void 0){const r=new it().getNormalMatrix(e);i.applyNormalMatrix(r),i.needsUpdate=!0}const s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(e),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return fi.makeRotationFromQuaternion(e),this.applyMatrix4(fi),this}rotateX(e){return fi.makeRotationX(e),this.applyMatrix4(fi),this}rotateY(e){return fi.makeRotationY(e),this.applyMatrix4(fi),this}rotateZ(e){return fi.makeRotationZ(e),this.applyMatrix4(fi),this}translate(e,t,i){return fi.makeTranslation(e,t,i),this.applyMatrix4(fi),this}scale(e,t,i){return fi.makeScale(e,t,i),this.applyMatrix4(fi),this}lookAt(e){return Cc.lookAt(e),Cc.updateMatrix(),this.applyMatrix4(Cc.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(Lr).negate(),this.translate(Lr.x,Lr.y,Lr.z),this}setFromPoints(e){const t=this.getAttribute("position");if(t===void 0){const i=[];for(let s=0,r=e.length;s<r;s++){const a=e[s];i.push(a.x,a.y,a.z||0)}this.setAttribute("position",new an(i,3))}else{const i=Math.min(e.length,t.count);for(let s=0;s<i;s++){const r=e[s];t.setXYZ(s,r.x,r.y,r.z||0)}e.length>t.count&&je("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new to);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){yt("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new z(-1/0,-1/0,-1/0),new z(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let i=0,s=t.length;i<s;i++){const r=t[i];si.setFromBufferAttribute(r),this.morphTargetsRelative?(Pn.addVectors(this.boundingBox.min,si.min),this.boundingBox.expandByPoint(Pn),Pn.addVectors(this.boundingBox.max,si.max),this.boundingBox.expandByPoint(Pn)):(this.boundingBox.expandByPoint(si.min),this.boundingBox.expandByPoint(si.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&yt('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new no);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){yt("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new z,1/0);return}if(e){const i=this.boundingSphere.center;if(si.setFromBufferAttribute(e),t)for(let r=0,a=t.length;r<a;r++){const o=t[r];wa.setFromBufferAttribute(o),this.morphTargetsRelative?(Pn.addVectors(si.min,wa.min),si.expandByPoint(Pn),Pn.addVectors(si.max,wa.max),si.expandByPoint(Pn)):(si.expandByPoint(wa.min),si.expandByPoint(wa.max))}si.getCenter(i);let s=0;for(let r=0,a=e.count;r<a;r++)Pn.fromBufferAttribute(e,r),s=Math.max(s,i.distanceToSquared(Pn));if(t)for(let r=0,a=t.length;r<a;r++){const o=t[r],l=this.morphTargetsRelative;for(let c=0,u=o.count;c<u;c++)Pn.fromBufferAttribute(o,c),l&&(Lr.fromBufferAttribute(e,c),Pn.add(Lr)),s=Math.max(s,i.distanceToSquared(Pn))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&yt('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){const e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){yt("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}const i=t.position,s=t.normal,r=t.uv;let a=this.getAttribute("tangent");(a===void 0||a.count!==i.count)&&(a=new li(new Float32Array(4*i.count),4),this.setAttribute("tangent",a));const o=[],l=[],c=new Uint8Array(i.count);for(let F=0;F<i.count;F++)o[F]=new z,l[F]=new z;const u=new z,d=new z,h=new z,m=new qe,g=new qe,y=new qe,p=new z,f=new z;function x(F,L,D){c[F]=c[L]=c[D]=1,u.fromBufferAttribute(i,F),d.fromBufferAttribute(i,L),h.fromBufferAttribute(i,D),m.fromBufferAttribute(r,F),g.fromBufferAttribute(r,L),y.fromBufferAttribute(r,D),d.sub(u),h.sub(u),g.sub(m),y.sub(m);const B=1/(g.x*y.y-y.x*g.y);isFinite(B)&&(p.copy(d).multiplyScalar(y.y).addScaledVector(h,-g.y).multiplyScalar(B),f.copy(h).multiplyScalar(g.x).addScaledVector(d,-y.x).multiplyScalar(B),o[F].add(p),o[L].add(p),o[D].add(p),l[F].add(f),l[L].add(f),l[D].add(f))}let R=this.groups;R.length===0&&(R=[{start:0,count:e.count}]);for(let F=0,L=R.length;F<L;++F){const D=R[F],B=D.start,G=D.count;for(let k=B,W=B+G;k<W;k+=3)x(e.getX(k+0),e.getX(k+1),e.getX(k+2))}const S=new z,C=new z,w=new z,v=new z;function M(F){w.fromBufferAttribute(s,F),v.copy(w);const L=o[F];S.copy(L),S.sub(w.multiplyScalar(w.dot(L))).normalize(),C.crossVectors(v,L);const B=C.dot(l[F])<0?-1:1;a.setXYZW(F,S.x,S.y,S.z,B)}for(let F=0,L=i.count;F<L;++F)c[F]&&M(F);this._transformed=!0}computeVertexNormals(){const e=this.index,t=this.getAttribute("position");if(t!==void 0){let i=this.getAttribute("normal");if(i===void 0||i.count!==t.count)i=new li(new Float32Array(t.count*3),3),this.setAttribute("normal",i);else for(let h=0,m=i.count;h<m;h++)i.setXYZ(h,0,0,0);const s=new z,r=new z,a=new z,o=new z,l=new z,c=new z,u=new z,d=new z;if(e)for(let h=0,m=e.count;h<m;h+=3){const g=e.getX(h+0),y=e.getX(h+1),p=e.getX(h+2);s.fromBufferAttribute(t,g),r.fromBufferAttribute(t,y),a.fromBufferAttribute(t,p),u.subVectors(a,r),d.subVectors(s,r),u.cross(d),o.fromBufferAttribute(i,g),l.fromBufferAttribute(i,y),c.fromBufferAttribute(i,p),o.add(u),l.add(u),c.add(u),i.setXYZ(g,o.x,o.y,o.z),i.setXYZ(y,l.x,l.y,l.z),i.setXYZ(p,c.x,c.y,c.z)}else for(let h=0,m=t.count;h<m;h+=3)s.fromBufferAttribute(t,h+0),r.fromBufferAttribute(t,h+1),a.fromBufferAttribute(t,h+2),u.subVectors(a,r),d.subVectors(s,r),u.cross(d),i.setXYZ(h+0,u.x,u.y,u.z),i.setXYZ(h+1,u.x,u.y,u.z),i.setXYZ(h+2,u.x,u.y,u.z);this.normalizeNormals(),i.needsUpdate=!0}}normalizeNormals(){const e=this.attributes.normal;for(let t=0,i=e.count;t<i;t++)Pn.fromBufferAttribute(e,t),Pn.normalize(),e.setXYZ(t,Pn.x,Pn.y,Pn.z)}toNonIndexed(){function e(o,l){const c=o.array,u=o.itemSize,d=o.normalized,h=new c.constructor(l.length*u);let m=0,g=0;for(let y=0,p=l.length;y<p;y++){o.isInterleavedBufferAttribute?m=l[y]*o.data.stride+o.offset:m=l[y]*u;for(let f=0;f<u;f++)h[g++]=c[m++]}return new li(h,u,d)}if(this.index===null)return je("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;const t=new Ot,i=this.index.array,s=this.attributes;for(const o in s){const l=s[o],c=e(l,i);t.setAttribute(o,c)}const r=this.morphAttributes;for(const o in r){const l=[],c=r[o];for(let u=0,d=c.length;u<d;u++){const h=c[u],m=e(h,i);l.push(m)}t.morphAttributes[o]=l}t.morphTargetsRelative=this.morphTargetsRelative;const a=this.groups;for(let o=0,l=a.length;o<l;o++){const c=a[o];t.addGroup(c.start,c.count,c.materialIndex)}return t}toJSON(){const e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){const l=this.parameters;for(const c in l)l[c]!==void 0&&(e[c]=l[c]);return e}e.data={attributes:{}};const t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});const i=this.attributes;for(const l in i){const c=i[l];e.data.attributes[l]=c.toJSON(e.data)}const s={};let r=!1;for(const l in this.morphAttributes){const c=this.morphAttributes[l],u=[];for(let d=0,h=c.length;d<h;d++){const m=c[d];u.push(m.toJSON(e.data))}u.length>0&&(s[l]=u,r=!0)}r&&(e.data.morphAttributes=s,e.data.morphTargetsRelative=this.morphTargetsRelative);const a=this.groups;a.length>0&&(e.data.groups=JSON.parse(JSON.stringify(a)));const o=this.boundingSphere;return o!==null&&(e.data.boundingSphere=o.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;const t={};this.name=e.name;const i=e.index;i!==null&&this.setIndex(i.clone());const s=e.attributes;for(const c in s){const u=s[c];this.setAttribute(c,u.clone(t))}const r=e.morphAttributes;for(const c in r){const u=[],d=r[c];for(let h=0,m=d.length;h<m;h++)u.push(d[h].clone(t));this.morphAttributes[c]=u}this.morphTargetsRelative=e.morphTargetsRelative;const a=e.groups;for(let c=0,u=a.length;c<u;c++){const d=a[c];this.addGroup(d.start,d.count,d.materialIndex)}const o=e.boundingBox;o!==null&&(this.boundingBox=o.clone());const l=e.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}}class wy{constructor(e,t){this.isInterleavedBuffer=!0,this.array=e,this.stride=t,this.count=e!==void 0?e.length/t:0,this.usage=eg,this.updateRanges=[],this.version=0,this.uuid=or()}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.array=new e.array.constructor(e.array),this.count=e.count,this.stride=e.stride,this.usage=e.usage,this}copyAt(e,t,i){e*=this.stride,i*=t.stride;for(let s=0,r=this.stride;s<r;s++)this.array[e+s]=t.array[i+s];return this}set(e,t=0){return this.array.set(e,t),this}clone(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});const t=bf(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=this.array.slice(0).buffer);const i=new this.array.constructor(e.arrayBuffers[t]),s=new this.constructor(i,this.stride);return s.setUsage(this.usage),s}onUpload(e){return this.onUploadCallback=e,this}toJSON(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});const t=bf(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=Array.from(new Uint32Array(this.array.slice(0).buffer)));const i={uuid:this.uuid,buffer:t,type:this.array.constructor.name,stride:this.stride};return i.usage=this.usage,i}}function bf(n){return n.buffer._uuid===void 0&&(n.buffer._uuid=or()),n.byteOffset===0&&n.byteLength===n.buffer.byteLength?n.buffer._uuid:n.buffer._uuid+":"+n.byteOffset+":"+n.byteLength}const qn=new z;class yl{constructor(e,t,i,s=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=e,this.itemSize=t,this.offset=i,this.normalized=s,this._normalizationScale=e!==void 0?kl(e.array):void 0}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(e){this.data.needsUpdate=e}applyMatrix4(e){for(let t=0,i=this.data.count;t<i;t++)qn.fromBufferAttribute(this,t),qn.applyMatrix4(e),this.setXYZ(t,qn.x,qn.y,qn.z);return this}applyNormalMatrix(e){for(let t=0,i=this.count;t<i;t++)qn.fromBufferAttribute(this,t),qn.applyNormalMatrix(e),this.setXYZ(t,qn.x,qn.y,qn.z);return this}transformDirection(e){for(let t=0,i=this.count;t<i;t++)qn.fromBufferAttribute(this,t),qn.transformDirection(e),this.setXYZ(t,qn.x,qn.y,qn.z);return this}getComponent(e,t){let i=this.array[e*this.data.stride+this.offset+t];return this.normalized&&(i=this._denormalize(i)),i}setComponent(e,t,i){return this.normalized&&(i=this._normalize(i)),this.data.array[e*this.data.stride+this.offset+t]=i,this}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset]=t,this}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+1]=t,this}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+2]=t,this}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+3]=t,this}getX(e){let t=this.data.array[e*this.data.stride+this.offset];return this.normalized&&(t=this._denormalize(t)),t}getY(e){let t=this.data.array[e*this.data.stride+this.offset+1];return this.normalized&&(t=this._denormalize(t)),t}getZ(e){let t=this.data.array[e*this.data.stride+this.offset+2];return this.normalized&&(t=this._denormalize(t)),t}getW(e){let t=this.data.array[e*this.data.stride+this.offset+3];return this.normalized&&(t=this._denormalize(t)),t}setXY(e,t,i){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),i=this._normalize(i)),this.data.array[e+0]=t,this.data.array[e+1]=i,this}setXYZ(e,t,i,s){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s)),this.data.array[e+0]=t,this.data.array[e+1]=i,this.data.array[e+2]=s,this}setXYZW(e,t,i,s,r){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s),r=this._normalize(r)),this.data.array[e+0]=t,this.data.array[e+1]=i,this.data.array[e+2]=s,this.data.array[e+3]=r,this}clone(e){if(e===void 0){xl("InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let i=0;i<this.count;i++){const s=i*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return new li(new this.array.constructor(t),this.itemSize,this.normalized)}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.clone(e)),new yl(e.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(e){if(e===void 0){xl("InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let i=0;i<this.count;i++){const s=i*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:t,normalized:this.normalized}}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.toJSON(e)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}_denormalize(e){const t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):ng(e,this.data.array)}_normalize(e){const t=this._normalizationScale;return t!==void 0?Math.round(e*t):ig(e,this.data.array)}}const Pc=new z,Sy=new z,My=new it;class Li{constructor(e=new z(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,i,s){return this.normal.set(e,t,i),this.constant=s,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,i){const s=Pc.subVectors(i,t).cross(Sy.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(s,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){const e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,i=!0){const s=e.delta(Pc),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;const a=-(e.start.dot(this.normal)+this.constant)/r;return i===!0&&(a<0||a>1)?null:t.copy(e.start).addScaledVector(s,a)}intersectsLine(e){const t=this.distanceToPoint(e.start),i=this.distanceToPoint(e.end);return t<0&&i>0||i<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){const i=t||My.getNormalMatrix(e),s=this.coplanarPoint(Pc).applyMatrix4(e),r=this.normal.applyMatrix3(i).normalize();return this.constant=-s.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}}let Ey=0;class lr extends Hs{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:Ey++}),this.uuid=or(),this.name="",this.type="Material",this.blending=Oa,this.side=Os,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=Nm,this.blendDst=Im,this.blendEquation=Br,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new lt(0,0,0),this.blendAlpha=0,this.depthFunc=Ga,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=$x,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=dc,this.stencilZFail=dc,this.stencilZPass=dc,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(const t in e){const i=e[t];if(i===void 0){je(`Material: parameter '${t}' has value of undefined.`);continue}const s=this[t];if(s===void 0){je(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(i):s&&s.isVector2&&i&&i.isVector2||s&&s.isEuler&&i&&i.isEuler||s&&s.isVector3&&i&&i.isVector3?s.copy(i):this[t]=i}}toJSON(e){const t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});const i={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};i.uuid=this.uuid,i.type=this.type,i.blending=this.blending,i.side=this.side,i.shadowSide=this.shadowSide,i.vertexColors=this.vertexColors,i.opacity=this.opacity,i.transparent=this.transparent,i.blendSrc=this.blendSrc,i.blendDst=this.blendDst,i.blendEquation=this.blendEquation,i.blendSrcAlpha=this.blendSrcAlpha,i.blendDstAlpha=this.blendDstAlpha,i.blendEquationAlpha=this.blendEquationAlpha,i.blendColor=this.blendColor.getHex(),i.blendAlpha=this.blendAlpha,i.depthFunc=this.depthFunc,i.depthTest=this.depthTest,i.depthWrite=this.depthWrite,i.colorWrite=this.colorWrite,i.clipIntersection=this.clipIntersection,i.clipShadows=this.clipShadows,i.stencilWriteMask=this.stencilWriteMask,i.stencilFunc=this.stencilFunc,i.stencilRef=this.stencilRef,i.stencilFuncMask=this.stencilFuncMask,i.stencilFail=this.stencilFail,i.stencilZFail=this.stencilZFail,i.stencilZPass=this.stencilZPass,i.stencilWrite=this.stencilWrite,i.polygonOffset=this.polygonOffset,i.polygonOffsetFactor=this.polygonOffsetFactor,i.polygonOffsetUnits=this.polygonOffsetUnits,i.dithering=this.dithering,i.alphaTest=this.alphaTest,i.alphaHash=this.alphaHash,i.alphaToCoverage=this.alphaToCoverage,i.premultipliedAlpha=this.premultipliedAlpha,i.forceSinglePass=this.forceSinglePass,i.allowOverride=this.allowOverride,i.visible=this.visible,i.toneMapped=this.toneMapped,i.name=this.name,this.color&&this.color.isColor&&(i.color=this.color.getHex()),this.roughness!==void 0&&(i.roughness=this.roughness),this.metalness!==void 0&&(i.metalness=this.metalness),this.sheen!==void 0&&(i.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(i.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(i.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(i.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(i.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(i.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(i.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(i.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(i.shininess=this.shininess),this.clearcoat!==void 0&&(i.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(i.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(i.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(i.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(i.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(i.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(i.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,i.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(i.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(i.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(i.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(i.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(i.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(i.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(i.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(i.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(i.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(i.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(i.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(i.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(i.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(i.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(i.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(i.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(i.lightMap=this.lightMap.toJSON(e).uuid,i.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(i.aoMap=this.aoMap.toJSON(e).uuid,i.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(i.bumpMap=this.bumpMap.toJSON(e).uuid,i.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(i.normalMap=this.normalMap.toJSON(e).uuid,i.normalMapType=this.normalMapType,i.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(i.displacementMap=this.displacementMap.toJSON(e).uuid,i.displacementScale=this.displacementScale,i.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(i.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(i.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(i.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(i.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(i.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(i.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(i.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(i.combine=this.combine)),this.envMapRotation!==void 0&&(i.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(i.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(i.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(i.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(i.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(i.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(i.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(i.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(i.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(i.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(i.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(i.size=this.size),this.sizeAttenuation!==void 0&&(i.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(i.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(i.rotation=this.rotation),this.depthPacking!==void 0&&(i.depthPacking=this.depthPacking),this.linewidth!==void 0&&(i.linewidth=this.linewidth),this.linecap!==void 0&&(i.linecap=this.linecap),this.linejoin!==void 0&&(i.linejoin=this.linejoin),this.dashSize!==void 0&&(i.dashSize=this.dashSize),this.gapSize!==void 0&&(i.gapSize=this.gapSize),this.scale!==void 0&&(i.scale=this.scale),this.wireframe!==void 0&&(i.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(i.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(i.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(i.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(i.flatShading=this.flatShading),this.fog!==void 0&&(i.fog=this.fog),Object.keys(this.userData).length>0&&(i.userData=this.userData);function s(r){const a=[];for(const o in r){const l=r[o];delete l.metadata,a.push(l)}return a}if(t){const r=s(e.textures),a=s(e.images);r.length>0&&(i.textures=r),a.length>0&&(i.images=a)}return i}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new lt().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(i=>new Li().fromJSON(i))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let i=e.normalScale;Array.isArray(i)===!1&&(i=[i,i]),this.normalScale=new qe().fromArray(i)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new qe().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;const t=e.clippingPlanes;let i=null;if(t!==null){const s=t.length;i=new Array(s);for(let r=0;r!==s;++r)i[r]=t[r].clone()}return this.clippingPlanes=i,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}}class cg extends lr{constructor(e){super(),this.isSpriteMaterial=!0,this.type="SpriteMaterial",this.color=new lt(16777215),this.map=null,this.alphaMap=null,this.rotation=0,this.sizeAttenuation=!0,this.transparent=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.rotation=e.rotation,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}}let Dr;const Sa=new z,Nr=new z,Ir=new z,kr=new qe,Ma=new qe,ug=new Dt,Ao=new z,Ea=new z,To=new z,wf=new qe,Lc=new qe,Sf=new qe;class dg extends bn{constructor(e=new cg){if(super(),this.isSprite=!0,this.type="Sprite",Dr===void 0){Dr=new Ot;const t=new Float32Array([-.5,-.5,0,0,0,.5,-.5,0,1,0,.5,.5,0,1,1,-.5,.5,0,0,1]),i=new wy(t,5);Dr.setIndex([0,1,2,0,2,3]),Dr.setAttribute("position",new yl(i,3,0,!1)),Dr.setAttribute("uv",new yl(i,2,3,!1))}this.geometry=Dr,this.material=e,this.center=new qe(.5,.5),this.count=1}intersectsFrustum(e){return e.intersectsSprite(this)}raycast(e,t){e.camera===null&&yt('Sprite: "Raycaster.camera" needs to be set in order to raycast against sprites.'),Nr.setFromMatrixScale(this.matrixWorld),ug.copy(e.camera.matrixWorld),this.modelViewMatrix.multiplyMatrices(e.camera.matrixWorldInverse,this.matrixWorld),Ir.setFromMatrixPosition(this.modelViewMatrix),e.camera.isPerspectiveCamera&&this.material.sizeAttenuation===!1&&Nr.multiplyScalar(-Ir.z);const i=this.material.rotation;let s,r;i!==0&&(r=Math.cos(i),s=Math.sin(i));const a=this.center;Ro(Ao.set(-.5,-.5,0),Ir,a,Nr,s,r),Ro(Ea.set(.5,-.5,0),Ir,a,Nr,s,r),Ro(To.set(.5,.5,0),Ir,a,Nr,s,r),wf.set(0,0),Lc.set(1,0),Sf.set(1,1);let o=e.ray.intersectTriangle(Ao,Ea,To,!1,Sa);if(o===null&&(Ro(Ea.set(-.5,.5,0),Ir,a,Nr,s,r),Lc.set(0,1),o=e.ray.intersectTriangle(Ao,To,Ea,!1,Sa),o===null))return;const l=e.ray.origin.distanceTo(Sa);l<e.near||l>e.far||t.push({distance:l,point:Sa.clone(),uv:xi.getInterpolation(Sa,Ao,Ea,To,wf,Lc,Sf,new qe),face:null,object:this})}copy(e,t){return super.copy(e,t),e.center!==void 0&&this.center.copy(e.center),this.material=e.material,this}toJSON(e){const t=super.toJSON(e);return t.object.center=this.center.toArray(),t}}function Ro(n,e,t,i,s,r){kr.subVectors(n,t).addScalar(.5).multiply(i),s!==void 0?(Ma.x=r*kr.x-s*kr.y,Ma.y=s*kr.x+r*kr.y):Ma.copy(kr),n.copy(e),n.x+=Ma.x,n.y+=Ma.y,n.applyMatrix4(ug)}const ds=new z,Dc=new z,Co=new z,Po=new z;class Fl{constructor(e=new z,t=new z(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,ds)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);const i=t.dot(this.direction);return i<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,i)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){const t=ds.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(ds.copy(this.origin).addScaledVector(this.direction,t),ds.distanceToSquared(e))}distanceSqToSegment(e,t,i,s){Dc.copy(e).add(t).multiplyScalar(.5),Co.copy(t).sub(e).normalize(),Po.copy(this.origin).sub(Dc);const r=e.distanceTo(t)*.5,a=-this.direction.dot(Co),o=Po.dot(this.direction),l=-Po.dot(Co),c=Po.lengthSq(),u=Math.abs(1-a*a);let d,h,m,g;if(u>0)if(d=a*l-o,h=a*o-l,g=r*u,d>=0)if(h>=-g)if(h<=g){const y=1/u;d*=y,h*=y,m=d*(d+a*h+2*o)+h*(a*d+h+2*l)+c}else h=r,d=Math.max(0,-(a*h+o)),m=-d*d+h*(h+2*l)+c;else h=-r,d=Math.max(0,-(a*h+o)),m=-d*d+h*(h+2*l)+c;else h<=-g?(d=Math.max(0,-(-a*r+o)),h=d>0?-r:Math.min(Math.max(-r,-l),r),m=-d*d+h*(h+2*l)+c):h<=g?(d=0,h=Math.min(Math.max(-r,-l),r),m=h*(h+2*l)+c):(d=Math.max(0,-(a*r+o)),h=d>0?r:Math.min(Math.max(-r,-l),r),m=-d*d+h*(h+2*l)+c);else h=a>0?-r:r,d=Math.max(0,-(a*h+o)),m=-d*d+h*(h+2*l)+c;return i&&i.copy(this.origin).addScaledVector(this.direction,d),s&&s.copy(Dc).addScaledVector(Co,h),m}intersectSphere(e,t){if(e.radius<0)return null;ds.subVectors(e.center,this.origin);const i=ds.dot(this.direction),s=ds.dot(ds)-i*i,r=e.radius*e.radius;if(s>r)return null;const a=Math.sqrt(r-s),o=i-a,l=i+a;return l<0?null:o<0?this.at(l,t):this.at(o,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){const t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;const i=-(this.origin.dot(e.normal)+e.constant)/t;return i>=0?i:null}intersectPlane(e,t){const i=this.distanceToPlane(e);return i===null?null:this.at(i,t)}intersectsPlane(e){const t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let i,s,r,a,o,l;const c=1/this.direction.x,u=1/this.direction.y,d=1/this.direction.z,h=this.origin;return c>=0?(i=(e.min.x-h.x)*c,s=(e.max.x-h.x)*c):(i=(e.max.x-h.x)*c,s=(e.min.x-h.x)*c),u>=0?(r=(e.min.y-h.y)*u,a=(e.max.y-h.y)*u):(r=(e.max.y-h.y)*u,a=(e.min.y-h.y)*u),i>a||r>s||((r>i||isNaN(i))&&(i=r),(a<s||isNaN(s))&&(s=a),d>=0?(o=(e.min.z-h.z)*d,l=(e.max.z-h.z)*d):(o=(e.max.z-h.z)*d,l=(e.min.z-h.z)*d),i>l||o>s)||((o>i||i!==i)&&(i=o),(l<s||s!==s)&&(s=l),s<0)?null:this.at(i>=0?i:s,t)}intersectsBox(e){return this.intersectBox(e,ds)!==null}intersectTriangle(e,t,i,s,r){const a=this.origin,o=this.direction,l=o.x,c=o.y,u=o.z,d=e.x-a.x,h=e.y-a.y,m=e.z-a.z,g=t.x-a.x,y=t.y-a.y,p=t.z-a.z,f=i.x-a.x,x=i.y-a.y,R=i.z-a.z,S=Math.abs(l),C=Math.abs(c),w=Math.abs(u);let v,M,F,L,D,B,G,k,W,Y,V,le;if(S>=C&&S>=w?(F=l,B=d,W=g,le=f,l>=0?(v=c,M=u,L=h,D=m,G=y,k=p,Y=x,V=R):(v=u,M=c,L=m,D=h,G=p,k=y,Y=R,V=x)):C>=w?(F=c,B=h,W=y,le=x,c>=0?(v=u,M=l,L=m,D=d,G=p,k=g,Y=R,V=f):(v=l,M=u,L=d,D=m,G=g,k=p,Y=f,V=R)):(F=u,B=m,W=p,le=R,u>=0?(v=l,M=c,L=d,D=h,G=g,k=y,Y=f,V=x):(v=c,M=l,L=h,D=d,G=y,k=g,Y=x,V=f)),F===0)return null;const j=v/F,Q=M/F,se=1/F,he=L-j*B,de=D-Q*B,ee=G-j*W,me=k-Q*W,_e=Y-j*le,Te=V-Q*le,we=_e*me-Te*ee,Ge=he*Te-de*_e,tt=ee*de-me*he;if(s){if(we<0||Ge<0||tt<0)return null}else if((we<0||Ge<0||tt<0)&&(we>0||Ge>0||tt>0))return null;const He=we+Ge+tt;if(He===0)return null;const ct=se*(we*B+Ge*W+tt*le);return(He>0?ct<0:ct>0)?null:this.at(ct/He,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}}class ks extends lr{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new lt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Bs,this.combine=km,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}}const Mf=new Dt,$s=new Fl,Lo=new no,Ef=new z,Do=new z,No=new z,Io=new z,Nc=new z,ko=new z,Af=new z,Fo=new z;class en extends bn{constructor(e=new Ot,t=new ks){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){const t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){const s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}getVertexPosition(e,t){const i=this.geometry,s=i.attributes.position,r=i.morphAttributes.position,a=i.morphTargetsRelative;t.fromBufferAttribute(s,e);const o=this.morphTargetInfluences;if(r&&o){ko.set(0,0,0);for(let l=0,c=r.length;l<c;l++){const u=o[l],d=r[l];u!==0&&(Nc.fromBufferAttribute(d,e),a?ko.addScaledVector(Nc,u):ko.addScaledVector(Nc.sub(t),u))}t.add(ko)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){const i=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(i.boundingSphere===null&&i.computeBoundingSphere(),Lo.copy(i.boundingSphere),Lo.applyMatrix4(r),$s.copy(e.ray).recast(e.near),!(Lo.containsPoint($s.origin)===!1&&($s.intersectSphere(Lo,Ef)===null||$s.origin.distanceToSquared(Ef)>(e.far-e.near)**2))&&(Mf.copy(r).invert(),$s.copy(e.ray).applyMatrix4(Mf),!(i.boundingBox!==null&&$s.intersectsBox(i.boundingBox)===!1)&&this._computeIntersections(e,t,$s)))}_computeIntersections(e,t,i){let s;const r=this.geometry,a=this.material,o=r.index,l=r.attributes.position,c=r.attributes.uv,u=r.attributes.uv1,d=r.attributes.normal,h=r.groups,m=r.drawRange;if(o!==null)if(Array.isArray(a))for(let g=0,y=h.length;g<y;g++){const p=h[g],f=a[p.materialIndex],x=Math.max(p.start,m.start),R=Math.min(o.count,Math.min(p.start+p.count,m.start+m.count));for(let S=x,C=R;S<C;S+=3){const w=o.getX(S),v=o.getX(S+1),M=o.getX(S+2);s=Uo(this,f,e,i,c,u,d,w,v,M),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{const g=Math.max(0,m.start),y=Math.min(o.count,m.start+m.count);for(let p=g,f=y;p<f;p+=3){const x=o.getX(p),R=o.getX(p+1),S=o.getX(p+2);s=Uo(this,a,e,i,c,u,d,x,R,S),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}else if(l!==void 0)if(Array.isArray(a))for(let g=0,y=h.length;g<y;g++){const p=h[g],f=a[p.materialIndex],x=Math.max(p.start,m.start),R=Math.min(l.count,Math.min(p.start+p.count,m.start+m.count));for(let S=x,C=R;S<C;S+=3){const w=S,v=S+1,M=S+2;s=Uo(this,f,e,i,c,u,d,w,v,M),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{const g=Math.max(0,m.start),y=Math.min(l.count,m.start+m.count);for(let p=g,f=y;p<f;p+=3){const x=p,R=p+1,S=p+2;s=Uo(this,a,e,i,c,u,d,x,R,S),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}}}function Ay(n,e,t,i,s,r,a,o){let l;if(e.side===Jn?l=i.intersectTriangle(a,r,s,!0,o):l=i.intersectTriangle(s,r,a,e.side===Os,o),l===null)return null;Fo.copy(o),Fo.applyMatrix4(n.matrixWorld);const c=t.ray.origin.distanceTo(Fo);return c<t.near||c>t.far?null:{distance:c,point:Fo.clone(),object:n}}function Uo(n,e,t,i,s,r,a,o,l,c){n.getVertexPosition(o,Do),n.getVertexPosition(l,No),n.getVertexPosition(c,Io);const u=Ay(n,e,t,i,Do,No,Io,Af);if(u){const d=new z;xi.getBarycoord(Af,Do,No,Io,d),s&&(u.uv=xi.getInterpolatedAttribute(s,o,l,c,d,new qe)),r&&(u.uv1=xi.getInterpolatedAttribute(r,o,l,c,d,new qe)),a&&(u.normal=xi.getInterpolatedAttribute(a,o,l,c,d,new z),u.normal.dot(i.direction)>0&&u.normal.multiplyScalar(-1));const h={a:o,b:l,c,normal:new z,materialIndex:0};xi.getNormal(Do,No,Io,h.normal),u.face=h,u.barycoord=d}return u}class Ty extends zn{constructor(e=null,t=1,i=1,s,r,a,o,l,c=Nn,u=Nn,d,h){super(null,a,o,l,c,u,s,r,d,h),this.isDataTexture=!0,this.image={data:e,width:t,height:i},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}}const Ks=new no,Ry=new qe(.5,.5),Oo=new z;class $a{constructor(e=new Li,t=new Li,i=new Li,s=new Li,r=new Li,a=new Li){this.planes=[e,t,i,s,r,a]}set(e,t,i,s,r,a){const o=this.planes;return o[0].copy(e),o[1].copy(t),o[2].copy(i),o[3].copy(s),o[4].copy(r),o[5].copy(a),this}copy(e){const t=this.planes;for(let i=0;i<6;i++)t[i].copy(e.planes[i]);return this}setFromProjectionMatrix(e,t=Ii,i=!1){const s=this.planes,r=e.elements,a=r[0],o=r[1],l=r[2],c=r[3],u=r[4],d=r[5],h=r[6],m=r[7],g=r[8],y=r[9],p=r[10],f=r[11],x=r[12],R=r[13],S=r[14],C=r[15];if(s[0].setComponents(c-a,m-u,f-g,C-x).normalize(),s[1].setComponents(c+a,m+u,f+g,C+x).normalize(),s[2].setComponents(c+o,m+d,f+y,C+R).normalize(),s[3].setComponents(c-o,m-d,f-y,C-R).normalize(),i)s[4].setComponents(l,h,p,S).normalize(),s[5].setComponents(c-l,m-h,f-p,C-S).normalize();else if(s[4].setComponents(c-l,m-h,f-p,C-S).normalize(),t===Ii)s[5].setComponents(c+l,m+h,f+p,C+S).normalize();else if(t===Xa)s[5].setComponents(l,h,p,S).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Ks.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{const t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Ks.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Ks)}intersectsSprite(e){Ks.center.set(0,0,0);const t=Ry.distanceTo(e.center);return Ks.radius=.7071067811865476+t,Ks.applyMatrix4(e.matrixWorld),this.intersectsSphere(Ks)}intersectsSphere(e){const t=this.planes,i=e.center,s=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(i)<s)return!1;return!0}intersectsBox(e){const t=this.planes;for(let i=0;i<6;i++){const s=t[i];if(Oo.x=s.normal.x>0?e.max.x:e.min.x,Oo.y=s.normal.y>0?e.max.y:e.min.y,Oo.z=s.normal.z>0?e.max.z:e.min.z,s.distanceToPoint(Oo)<0)return!1}return!0}containsPoint(e){const t=this.planes;for(let i=0;i<6;i++)if(t[i].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}}const Tf=new Dt;class Bd{constructor(){this.coordinateSystem=Ii,this._frustums=[],this._count=0}setFromArrayCamera(e){const t=e.cameras,i=this._frustums;for(let s=0;s<t.length;s++){const r=t[s];Tf.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),i[s]===void 0&&(i[s]=new $a),i[s].setFromProjectionMatrix(Tf,r.coordinateSystem,r.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){const t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsObject(e))return!0;return!1}intersectsSprite(e){const t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSprite(e))return!0;return!1}intersectsSphere(e){const t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSphere(e))return!0;return!1}intersectsBox(e){const t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsBox(e))return!0;return!1}containsPoint(e){const t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;const t=this._frustums,i=e._frustums;for(let s=0;s<e._count;s++)t[s]===void 0&&(t[s]=new $a),t[s].copy(i[s]);return this._count=e._count,this}clone(){return new Bd().copy(this)}}class ci extends lr{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new lt(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}}const bl=new z,wl=new z,Rf=new Dt,Aa=new Fl,zo=new no,Ic=new z,Cf=new z;class Fi extends bn{constructor(e=new Ot,t=new ci){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,i=[0];for(let s=1,r=t.count;s<r;s++)bl.fromBufferAttribute(t,s-1),wl.fromBufferAttribute(t,s),i[s]=i[s-1],i[s]+=bl.distanceTo(wl);e.setAttribute("lineDistance",new an(i,1))}else je("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){const i=this.geometry,s=this.matrixWorld,r=e.params.Line.threshold,a=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),zo.copy(i.boundingSphere),zo.applyMatrix4(s),zo.radius+=r,e.ray.intersectsSphere(zo)===!1)return;Rf.copy(s).invert(),Aa.copy(e.ray).applyMatrix4(Rf);const o=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=o*o,c=this.isLineSegments?2:1,u=i.index,h=i.attributes.position;if(u!==null){const m=Math.max(0,a.start),g=Math.min(u.count,a.start+a.count);for(let y=m,p=g-1;y<p;y+=c){const f=u.getX(y),x=u.getX(y+1),R=Bo(this,e,Aa,l,f,x,y);R&&t.push(R)}if(this.isLineLoop){const y=u.getX(g-1),p=u.getX(m),f=Bo(this,e,Aa,l,y,p,g-1);f&&t.push(f)}}else{const m=Math.max(0,a.start),g=Math.min(h.count,a.start+a.count);for(let y=m,p=g-1;y<p;y+=c){const f=Bo(this,e,Aa,l,y,y+1,y);f&&t.push(f)}if(this.isLineLoop){const y=Bo(this,e,Aa,l,g-1,m,g-1);y&&t.push(y)}}}updateMorphTargets(){const t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){const s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}}function Bo(n,e,t,i,s,r,a){const o=n.geometry.attributes.position;if(bl.fromBufferAttribute(o,s),wl.fromBufferAttribute(o,r),t.distanceSqToSegment(bl,wl,Ic,Cf)>i)return;Ic.applyMatrix4(n.matrixWorld);const c=e.ray.origin.distanceTo(Ic);if(!(c<e.near||c>e.far))return{distance:c,point:Cf.clone().applyMatrix4(n.matrixWorld),index:a,face:null,faceIndex:null,barycoord:null,object:n}}const Pf=new z,Lf=new z;class io extends Fi{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,i=[];for(let s=0,r=t.count;s<r;s+=2)Pf.fromBufferAttribute(t,s),Lf.fromBufferAttribute(t,s+1),i[s]=s===0?0:i[s-1],i[s+1]=i[s]+Pf.distanceTo(Lf);e.setAttribute("lineDistance",new an(i,1))}else je("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}}class Cy extends Fi{constructor(e,t){super(e,t),this.isLineLoop=!0,this.type="LineLoop"}}class hg extends zn{constructor(e=[],t=Jr,i,s,r,a,o,l,c,u){super(e,t,i,s,r,a,o,l,c,u),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}}class Py extends zn{constructor(e,t,i,s,r,a,o,l,c){super(e,t,i,s,r,a,o,l,c),this.isCanvasTexture=!0,this.needsUpdate=!0}}class ea extends zn{constructor(e,t,i=es,s,r,a,o=Nn,l=Nn,c,u=zs,d=1){if(u!==zs&&u!==Is)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");const h={width:e,height:t,depth:d};super(h,s,r,a,o,l,u,i,c),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new Od(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){const t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}}class fg extends ea{constructor(e,t=es,i=Jr,s,r,a=Nn,o=Nn,l,c=zs){const u={width:e,height:e,depth:1},d=[u,u,u,u,u,u];super(e,e,t,i,s,r,a,o,l,c),this.image=d,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}}class pg extends zn{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}}class oa extends Ot{constructor(e=1,t=1,i=1,s=1,r=1,a=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:i,widthSegments:s,heightSegments:r,depthSegments:a};const o=this;s=Math.floor(s),r=Math.floor(r),a=Math.floor(a);const l=[],c=[],u=[],d=[];let h=0,m=0;g("z","y","x",-1,-1,i,t,e,a,r,0),g("z","y","x",1,-1,i,t,-e,a,r,1),g("x","z","y",1,1,e,i,t,s,a,2),g("x","z","y",1,-1,e,i,-t,s,a,3),g("x","y","z",1,-1,e,t,i,s,r,4),g("x","y","z",-1,-1,e,t,-i,s,r,5),this.setIndex(l),this.setAttribute("position",new an(c,3)),this.setAttribute("normal",new an(u,3)),this.setAttribute("uv",new an(d,2));function g(y,p,f,x,R,S,C,w,v,M,F){const L=S/v,D=C/M,B=S/2,G=C/2,k=w/2,W=v+1,Y=M+1;let V=0,le=0;const j=new z;for(let Q=0;Q<Y;Q++){const se=Q*D-G;for(let he=0;he<W;he++){const de=he*L-B;j[y]=de*x,j[p]=se*R,j[f]=k,c.push(j.x,j.y,j.z),j[y]=0,j[p]=0,j[f]=w>0?1:-1,u.push(j.x,j.y,j.z),d.push(he/v),d.push(1-Q/M),V+=1}}for(let Q=0;Q<M;Q++)for(let se=0;se<v;se++){const he=h+se+W*Q,de=h+se+W*(Q+1),ee=h+(se+1)+W*(Q+1),me=h+(se+1)+W*Q;l.push(he,de,me),l.push(de,ee,me),le+=6}o.addGroup(m,le,F),m+=le,h+=V}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new oa(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}}class so extends Ot{constructor(e=1,t=1,i=1,s=32,r=1,a=!1,o=0,l=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:e,radiusBottom:t,height:i,radialSegments:s,heightSegments:r,openEnded:a,thetaStart:o,thetaLength:l};const c=this;s=Math.floor(s),r=Math.floor(r);const u=[],d=[],h=[],m=[];let g=0;const y=[],p=i/2;let f=0;x(),a===!1&&(e>0&&R(!0),t>0&&R(!1)),this.setIndex(u),this.setAttribute("position",new an(d,3)),this.setAttribute("normal",new an(h,3)),this.setAttribute("uv",new an(m,2));function x(){const S=new z,C=new z;let w=0;const v=(t-e)/i;for(let M=0;M<=r;M++){const F=[],L=M/r,D=L*(t-e)+e;for(let B=0;B<=s;B++){const G=B/s,k=G*l+o,W=Math.sin(k),Y=Math.cos(k);C.x=D*W,C.y=-L*i+p,C.z=D*Y,d.push(C.x,C.y,C.z),S.set(W,v,Y).normalize(),h.push(S.x,S.y,S.z),m.push(G,1-L),F.push(g++)}y.push(F)}for(let M=0;M<s;M++)for(let F=0;F<r;F++){const L=y[F][M],D=y[F+1][M],B=y[F+1][M+1],G=y[F][M+1];(e>0||F!==0)&&(u.push(L,D,G),w+=3),(t>0||F!==r-1)&&(u.push(D,B,G),w+=3)}c.addGroup(f,w,0),f+=w}function R(S){const C=g,w=new qe,v=new z;let M=0;const F=S===!0?e:t,L=S===!0?1:-1;for(let B=1;B<=s;B++)d.push(0,p*L,0),h.push(0,L,0),m.push(.5,.5),g++;const D=g;for(let B=0;B<=s;B++){const k=B/s*l+o,W=Math.cos(k),Y=Math.sin(k);v.x=F*Y,v.y=p*L,v.z=F*W,d.push(v.x,v.y,v.z),h.push(0,L,0),w.x=W*.5+.5,w.y=Y*.5*L+.5,m.push(w.x,w.y),g++}for(let B=0;B<s;B++){const G=C+B,k=D+B;S===!0?u.push(k,k+1,G):u.push(k+1,k,G),M+=3}c.addGroup(f,M,S===!0?1:2),f+=M}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new so(e.radiusTop,e.radiusBottom,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}}class Hd extends so{constructor(e=1,t=1,i=32,s=1,r=!1,a=0,o=Math.PI*2){super(0,e,t,i,s,r,a,o),this.type="ConeGeometry",this.parameters={radius:e,height:t,radialSegments:i,heightSegments:s,openEnded:r,thetaStart:a,thetaLength:o}}static fromJSON(e){return new Hd(e.radius,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}}class Ul extends Ot{constructor(e=1,t=1,i=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:i,heightSegments:s};const r=e/2,a=t/2,o=Math.floor(i),l=Math.floor(s),c=o+1,u=l+1,d=e/o,h=t/l,m=[],g=[],y=[],p=[];for(let f=0;f<u;f++){const x=f*h-a;for(let R=0;R<c;R++){const S=R*d-r;g.push(S,-x,0),y.push(0,0,1),p.push(R/o),p.push(1-f/l)}}for(let f=0;f<l;f++)for(let x=0;x<o;x++){const R=x+c*f,S=x+c*(f+1),C=x+1+c*(f+1),w=x+1+c*f;m.push(R,S,w),m.push(S,C,w)}this.setIndex(m),this.setAttribute("position",new an(g,3)),this.setAttribute("normal",new an(y,3)),this.setAttribute("uv",new an(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Ul(e.width,e.height,e.widthSegments,e.heightSegments)}}class fs extends Ot{constructor(e=1,t=32,i=16,s=0,r=Math.PI*2,a=0,o=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:e,widthSegments:t,heightSegments:i,phiStart:s,phiLength:r,thetaStart:a,thetaLength:o},t=Math.max(3,Math.floor(t)),i=Math.max(2,Math.floor(i));const l=Math.min(a+o,Math.PI);let c=0;const u=[],d=new z,h=new z,m=[],g=[],y=[],p=[];for(let f=0;f<=i;f++){const x=[],R=f/i,S=a+R*o,C=e*Math.cos(S),w=Math.sqrt(e*e-C*C);let v=0;f===0&&a===0?v=.5/t:f===i&&l===Math.PI&&(v=-.5/t);for(let M=0;M<=t;M++){const F=M/t,L=s+F*r;d.x=-w*Math.cos(L),d.y=C,d.z=w*Math.sin(L),g.push(d.x,d.y,d.z),h.copy(d).normalize(),y.push(h.x,h.y,h.z),p.push(F+v,1-R),x.push(c++)}u.push(x)}for(let f=0;f<i;f++)for(let x=0;x<t;x++){const R=u[f][x+1],S=u[f][x],C=u[f+1][x],w=u[f+1][x+1];(f!==0||a>0)&&m.push(R,S,w),(f!==i-1||l<Math.PI)&&m.push(S,C,w)}this.setIndex(m),this.setAttribute("position",new an(g,3)),this.setAttribute("normal",new an(y,3)),this.setAttribute("uv",new an(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new fs(e.radius,e.widthSegments,e.heightSegments,e.phiStart,e.phiLength,e.thetaStart,e.thetaLength)}}function ta(n){const e={};for(const t in n){e[t]={};for(const i in n[t]){const s=n[t][i];if(Df(s))s.isRenderTargetTexture?(je("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][i]=null):e[t][i]=s.clone();else if(Array.isArray(s))if(Df(s[0])){const r=[];for(let a=0,o=s.length;a<o;a++)r[a]=s[a].clone();e[t][i]=r}else e[t][i]=s.slice();else e[t][i]=s}}return e}function Xn(n){const e={};for(let t=0;t<n.length;t++){const i=ta(n[t]);for(const s in i)e[s]=i[s]}return e}function Df(n){return n&&(n.isColor||n.isMatrix3||n.isMatrix4||n.isVector2||n.isVector3||n.isVector4||n.isTexture||n.isQuaternion)}function Ly(n){const e=[];for(let t=0;t<n.length;t++)e.push(n[t].clone());return e}function mg(n){const e=n.getRenderTarget();return e===null?n.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:vt.workingColorSpace}const Dy={clone:ta,merge:Xn};var Ny=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,Iy=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`;class rr extends lr{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=Ny,this.fragmentShader=Iy,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=ta(e.uniforms),this.uniformsGroups=Ly(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){const t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(const s in this.uniforms){const a=this.uniforms[s].value;a&&a.isTexture?t.uniforms[s]={type:"t",value:a.toJSON(e).uuid}:a&&a.isColor?t.uniforms[s]={type:"c",value:a.getHex()}:a&&a.isVector2?t.uniforms[s]={type:"v2",value:a.toArray()}:a&&a.isVector3?t.uniforms[s]={type:"v3",value:a.toArray()}:a&&a.isVector4?t.uniforms[s]={type:"v4",value:a.toArray()}:a&&a.isMatrix3?t.uniforms[s]={type:"m3",value:a.toArray()}:a&&a.isMatrix4?t.uniforms[s]={type:"m4",value:a.toArray()}:t.uniforms[s]={value:a}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;const i={};for(const s in this.extensions)this.extensions[s]===!0&&(i[s]=!0);return Object.keys(i).length>0&&(t.extensions=i),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(const i in e.uniforms){const s=e.uniforms[i];switch(this.uniforms[i]={},s.type){case"t":this.uniforms[i].value=t[s.value]||null;break;case"c":this.uniforms[i].value=new lt().setHex(s.value);break;case"v2":this.uniforms[i].value=new qe().fromArray(s.value);break;case"v3":this.uniforms[i].value=new z().fromArray(s.value);break;case"v4":this.uniforms[i].value=new rn().fromArray(s.value);break;case"m3":this.uniforms[i].value=new it().fromArray(s.value);break;case"m4":this.uniforms[i].value=new Dt().fromArray(s.value);break;default:this.uniforms[i].value=s.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(const i in e.extensions)this.extensions[i]=e.extensions[i];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}}class ky extends rr{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}}class tr extends lr{constructor(e){super(),this.isMeshStandardMaterial=!0,this.type="MeshStandardMaterial",this.defines={STANDARD:""},this.color=new lt(16777215),this.roughness=1,this.metalness=0,this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new lt(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=Yu,this.normalScale=new qe(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.roughnessMap=null,this.metalnessMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Bs,this.envMapIntensity=1,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.defines={STANDARD:""},this.color.copy(e.color),this.roughness=e.roughness,this.metalness=e.metalness,this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.emissive.copy(e.emissive),this.emissiveMap=e.emissiveMap,this.emissiveIntensity=e.emissiveIntensity,this.bumpMap=e.bumpMap,this.bumpScale=e.bumpScale,this.normalMap=e.normalMap,this.normalMapType=e.normalMapType,this.normalScale.copy(e.normalScale),this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.roughnessMap=e.roughnessMap,this.metalnessMap=e.metalnessMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.envMapIntensity=e.envMapIntensity,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.flatShading=e.flatShading,this.fog=e.fog,this}}class Fy extends lr{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=qx,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}}class Uy extends lr{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}}class gg extends ci{constructor(e){super(),this.isLineDashedMaterial=!0,this.type="LineDashedMaterial",this.scale=1,this.dashSize=3,this.gapSize=1,this.setValues(e)}copy(e){return super.copy(e),this.scale=e.scale,this.dashSize=e.dashSize,this.gapSize=e.gapSize,this}}class vg extends bn{static registerNode(e){this.prototype._lightNode=e}constructor(e,t=1){super(),this.isLight=!0,this.type="Light",this.color=new lt(e),this.intensity=t}copy(e,t){return super.copy(e,t),this.color.copy(e.color),this.intensity=e.intensity,this}toJSON(e){const t=super.toJSON(e);return t.object.color=this.color.getHex(),t.object.intensity=this.intensity,t}}const kc=new Dt,Nf=new z,If=new z;class Oy{constructor(e){this.camera=e,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new qe(512,512),this.mapType=ai,this.map=null,this.mapPass=null,this.matrix=new Dt,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new $a,this._frameExtents=new qe(1,1),this._viewportCount=1,this._viewports=[new rn(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(e){const t=this.camera;Nf.setFromMatrixPosition(e.matrixWorld),t.position.copy(Nf),If.setFromMatrixPosition(e.target.matrixWorld),t.lookAt(If),t.updateMatrixWorld(),this._updateMatrix(t,this.matrix,this._frustum)}_updateMatrix(e,t,i,s){kc.multiplyMatrices(e.projectionMatrix,e.matrixWorldInverse),i.setFromProjectionMatrix(kc,e.coordinateSystem,e.reversedDepth);const r=this._frameExtents,a=s?s.z/r.x:1,o=s?s.w/r.y:1,l=s?s.x/r.x:0,c=s?s.y/r.y:0;e.coordinateSystem===Xa||e.reversedDepth?t.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,1,0,0,0,0,1):t.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,.5,.5,0,0,0,1),t.multiply(kc)}getViewport(e){return this._viewports[e]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(e){return this.camera=e.camera.clone(),this.intensity=e.intensity,this.bias=e.bias,this.radius=e.radius,this.autoUpdate=e.autoUpdate,this.needsUpdate=e.needsUpdate,this.normalBias=e.normalBias,this.blurSamples=e.blurSamples,this.mapSize.copy(e.mapSize),this.mapType=e.mapType,this.biasNode=e.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){const e={};return e.intensity=this.intensity,e.bias=this.bias,e.normalBias=this.normalBias,e.radius=this.radius,e.blurSamples=this.blurSamples,e.mapSize=this.mapSize.toArray(),e.mapType=this.mapType,e.camera=this.camera.toJSON(!1).object,delete e.camera.matrix,e}}const Ho=new z,Vo=new _s,qi=new z;class _g extends bn{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new Dt,this.projectionMatrix=new Dt,this.projectionMatrixInverse=new Dt,this.coordinateSystem=Ii,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(Ho,Vo,qi),qi.x===1&&qi.y===1&&qi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(Ho,Vo,qi.set(1,1,1)).invert()}updateWorldMatrix(e,t,i=!1){super.updateWorldMatrix(e,t,i),this.matrixWorld.decompose(Ho,Vo,qi),qi.x===1&&qi.y===1&&qi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(Ho,Vo,qi.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}}const Cs=new z,kf=new qe,Ff=new qe;class Zn extends _g{constructor(e=50,t=1,i=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=i,this.far=s,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){const t=.5*this.getFilmHeight()/e;this.fov=Zu*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){const e=Math.tan(za*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return Zu*2*Math.atan(Math.tan(za*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,i){Cs.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(Cs.x,Cs.y).multiplyScalar(-e/Cs.z),Cs.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),i.set(Cs.x,Cs.y).multiplyScalar(-e/Cs.z)}getViewSize(e,t){return this.getViewBounds(e,kf,Ff),t.subVectors(Ff,kf)}setViewOffset(e,t,i,s,r,a){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=this.near;let t=e*Math.tan(za*.5*this.fov)/this.zoom,i=2*t,s=this.aspect*i,r=-.5*s;const a=this.view;if(this.view!==null&&this.view.enabled){const l=a.fullWidth,c=a.fullHeight;r+=a.offsetX*s/l,t-=a.offsetY*i/c,s*=a.width/l,i*=a.height/c}const o=this.filmOffset;o!==0&&(r+=e*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,t,t-i,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}}class xg extends _g{constructor(e=-1,t=1,i=1,s=-1,r=.1,a=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=i,this.bottom=s,this.near=r,this.far=a,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,i,s,r,a){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),i=(this.right+this.left)/2,s=(this.top+this.bottom)/2;let r=i-e,a=i+e,o=s+t,l=s-t;if(this.view!==null&&this.view.enabled){const c=(this.right-this.left)/this.view.fullWidth/this.zoom,u=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=c*this.view.offsetX,a=r+c*this.view.width,o-=u*this.view.offsetY,l=o-u*this.view.height}this.projectionMatrix.makeOrthographic(r,a,o,l,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}}class zy extends Oy{constructor(){super(new xg(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}}class By extends vg{constructor(e,t){super(e,t),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(bn.DEFAULT_UP),this.updateMatrix(),this.target=new bn,this.shadow=new zy}dispose(){super.dispose(),this.shadow.dispose()}copy(e){return super.copy(e),this.target=e.target.clone(),this.shadow=e.shadow.clone(),this}toJSON(e){const t=super.toJSON(e);return t.object.shadow=this.shadow.toJSON(),t.object.target=this.target.uuid,t}}class Hy extends vg{constructor(e,t){super(e,t),this.isAmbientLight=!0,this.type="AmbientLight"}}const Uf=new Dt,Of=new Dt,Ys=new Dt;class yg{constructor(){this.type="StereoCamera",this.aspect=1,this.eyeSep=.064,this.cameraL=new Zn,this.cameraL.layers.enable(1),this.cameraL.matrixAutoUpdate=!1,this.cameraR=new Zn,this.cameraR.layers.enable(2),this.cameraR.matrixAutoUpdate=!1,this._cache={focus:null,fov:null,aspect:null,near:null,far:null,zoom:null,eyeSep:null}}update(e){const t=this._cache;if(t.focus!==e.focus||t.fov!==e.fov||t.aspect!==e.aspect*this.aspect||t.near!==e.near||t.far!==e.far||t.zoom!==e.zoom||t.eyeSep!==this.eyeSep){t.focus=e.focus,t.fov=e.fov,t.aspect=e.aspect*this.aspect,t.near=e.near,t.far=e.far,t.zoom=e.zoom,t.eyeSep=this.eyeSep,Ys.copy(e.projectionMatrix);const s=t.eyeSep/2,r=s*t.near/t.focus,a=t.near*Math.tan(za*t.fov*.5)/t.zoom;let o,l;Of.elements[12]=-s,Uf.elements[12]=s,o=-a*t.aspect+r,l=a*t.aspect+r,Ys.elements[0]=2*t.near/(l-o),Ys.elements[8]=(l+o)/(l-o),this.cameraL.projectionMatrix.copy(Ys),o=-a*t.aspect-r,l=a*t.aspect-r,Ys.elements[0]=2*t.near/(l-o),Ys.elements[8]=(l+o)/(l-o),this.cameraR.projectionMatrix.copy(Ys)}this.cameraL.matrix.copy(e.matrixWorld).multiply(Of),this.cameraL.matrixWorldNeedsUpdate=!0,this.cameraR.matrix.copy(e.matrixWorld).multiply(Uf),this.cameraR.matrixWorldNeedsUpdate=!0}}const Fr=-90,Ur=1;class ju extends bn{constructor(e,t,i){super(),this.type="CubeCamera",this.renderTarget=i,this.coordinateSystem=null,this.activeMipmapLevel=0;const s=new Zn(Fr,Ur,e,t);s.layers=this.layers,this.add(s);const r=new Zn(Fr,Ur,e,t);r.layers=this.layers,this.add(r);const a=new Zn(Fr,Ur,e,t);a.layers=this.layers,this.add(a);const o=new Zn(Fr,Ur,e,t);o.layers=this.layers,this.add(o);const l=new Zn(Fr,Ur,e,t);l.layers=this.layers,this.add(l);const c=new Zn(Fr,Ur,e,t);c.layers=this.layers,this.add(c)}updateCoordinateSystem(){const e=this.coordinateSystem,t=this.children.concat(),[i,s,r,a,o,l]=t;for(const c of t)this.remove(c);if(e===Ii)i.up.set(0,1,0),i.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),a.up.set(0,0,1),a.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(e===Xa)i.up.set(0,-1,0),i.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),a.up.set(0,0,-1),a.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(const c of t)this.add(c),c.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();const{renderTarget:i,activeMipmapLevel:s}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());const[r,a,o,l,c,u]=this.children,d=e.getRenderTarget(),h=e.getActiveCubeFace(),m=e.getActiveMipmapLevel(),g=e.xr.enabled;e.xr.enabled=!1;const y=i.texture.mipmapsAutoUpdate;i.texture.mipmapsAutoUpdate=!1;let p=!1;e.isWebGLRenderer===!0?p=e.state.buffers.depth.getReversed():p=e.reversedDepthBuffer,e.setRenderTarget(i,0,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,r),e.setRenderTarget(i,1,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(i,2,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(i,3,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),e.setRenderTarget(i,4,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),i.texture.mipmapsAutoUpdate=y,e.setRenderTarget(i,5,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,u),e.setRenderTarget(d,h,m),e.xr.enabled=g,i.texture.needsPMREMUpdate=!0}}class Vy extends Zn{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}}const zf=new Dt;class bg{constructor(e,t,i=0,s=1/0){this.ray=new Fl(e,t),this.near=i,this.far=s,this.camera=null,this.layers=new zd,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(e,t){this.ray.set(e,t)}setFromCamera(e,t){t.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(e.x,e.y,.5).unproject(t).sub(this.ray.origin).normalize(),this.camera=t):t.isOrthographicCamera?(this.ray.origin.set(e.x,e.y,t.projectionMatrix.elements[14]).unproject(t),this.ray.direction.set(0,0,-1).transformDirection(t.matrixWorld),this.camera=t):yt("Raycaster: Unsupported camera type: "+t.type)}setFromXRController(e){return zf.identity().extractRotation(e.matrixWorld),this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4(zf),this}intersectObject(e,t=!0,i=[]){return Ju(e,this,i,t),i.sort(Bf),i}intersectObjects(e,t=!0,i=[]){for(let s=0,r=e.length;s<r;s++)Ju(e[s],this,i,t);return i.sort(Bf),i}}function Bf(n,e){return n.distance-e.distance}function Ju(n,e,t,i){let s=!0;if(n.layers.test(e.layers)&&n.raycast(e,t)===!1&&(s=!1),s===!0&&i===!0){const r=n.children;for(let a=0,o=r.length;a<o;a++)Ju(r[a],e,t,!0)}}class Qu{constructor(e=1,t=0,i=0){this.radius=e,this.phi=t,this.theta=i}set(e,t,i){return this.radius=e,this.phi=t,this.theta=i,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=pt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,i){return this.radius=Math.sqrt(e*e+t*t+i*i),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,i),this.phi=Math.acos(pt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}}const Hf=new z;let Go,Fc;class wg extends bn{constructor(e=new z(0,0,1),t=new z(0,0,0),i=1,s=16776960,r=i*.2,a=r*.2){super(),this.type="ArrowHelper",Go===void 0&&(Go=new Ot,Go.setAttribute("position",new an([0,0,0,0,1,0],3)),Fc=new Hd(.5,1,5,1),Fc.translate(0,-.5,0)),this.position.copy(t),this.line=new Fi(Go,new ci({color:s,toneMapped:!1})),this.line.matrixAutoUpdate=!1,this.add(this.line),this.cone=new en(Fc,new ks({color:s,toneMapped:!1})),this.cone.matrixAutoUpdate=!1,this.add(this.cone),this.setDirection(e),this.setLength(i,r,a)}setDirection(e){if(e.y>.99999)this.quaternion.set(0,0,0,1);else if(e.y<-.99999)this.quaternion.set(1,0,0,0);else{Hf.set(e.z,0,-e.x).normalize();const t=Math.acos(e.y);this.quaternion.setFromAxisAngle(Hf,t)}}setLength(e,t=e*.2,i=t*.2){this.line.scale.set(1,Math.max(1e-4,e-t),1),this.line.updateMatrix(),this.cone.scale.set(i,t,i),this.cone.position.y=e,this.cone.updateMatrix()}setColor(e){this.line.material.color.set(e),this.cone.material.color.set(e)}copy(e){return super.copy(e,!1),this.line.copy(e.line),this.cone.copy(e.cone),this}dispose(){super.dispose(),this.line.geometry.dispose(),this.line.material.dispose(),this.cone.geometry.dispose(),this.cone.material.dispose()}}class Sg extends io{constructor(e=1){const t=[0,0,0,e,0,0,0,0,0,0,e,0,0,0,0,0,0,e],i=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new Ot;s.setAttribute("position",new an(t,3)),s.setAttribute("color",new an(i,3));const r=new ci({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(e,t,i){const s=new lt,r=this.geometry.attributes.color.array;return s.set(e),s.toArray(r,0),s.toArray(r,3),s.set(t),s.toArray(r,6),s.toArray(r,9),s.set(i),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}}let Gy=class extends Hs{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function Vf(n,e,t,i){const s=Wy(i);switch(t){case Km:return n*e;case Zm:return n*e/s.components*s.byteLength;case kd:return n*e/s.components*s.byteLength;case sr:return n*e*2/s.components*s.byteLength;case Fd:return n*e*2/s.components*s.byteLength;case Ym:return n*e*3/s.components*s.byteLength;case ji:return n*e*4/s.components*s.byteLength;case Ud:return n*e*4/s.components*s.byteLength;case nl:case il:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case sl:case rl:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case yu:case wu:return Math.max(n,16)*Math.max(e,8)/4;case xu:case bu:return Math.max(n,8)*Math.max(e,8)/2;case Su:case Mu:case Au:case Tu:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case Eu:case pl:case Ru:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case Cu:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case Pu:return Math.floor((n+4)/5)*Math.floor((e+3)/4)*16;case Lu:return Math.floor((n+4)/5)*Math.floor((e+4)/5)*16;case Du:return Math.floor((n+5)/6)*Math.floor((e+4)/5)*16;case Nu:return Math.floor((n+5)/6)*Math.floor((e+5)/6)*16;case Iu:return Math.floor((n+7)/8)*Math.floor((e+4)/5)*16;case ku:return Math.floor((n+7)/8)*Math.floor((e+5)/6)*16;case Fu:return Math.floor((n+7)/8)*Math.floor((e+7)/8)*16;case Uu:return Math.floor((n+9)/10)*Math.floor((e+4)/5)*16;case Ou:return Math.floor((n+9)/10)*Math.floor((e+5)/6)*16;case zu:return Math.floor((n+9)/10)*Math.floor((e+7)/8)*16;case Bu:return Math.floor((n+9)/10)*Math.floor((e+9)/10)*16;case Hu:return Math.floor((n+11)/12)*Math.floor((e+9)/10)*16;case Vu:return Math.floor((n+11)/12)*Math.floor((e+11)/12)*16;case Gu:case Wu:case qu:return Math.ceil(n/4)*Math.ceil(e/4)*16;case Xu:case $u:return Math.ceil(n/4)*Math.ceil(e/4)*8;case ml:case Ku:return Math.ceil(n/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function Wy(n){switch(n){case ai:case Wm:return{byteLength:1,components:1};case qa:case qm:case ts:return{byteLength:2,components:1};case Nd:case Id:return{byteLength:2,components:4};case es:case Dd:case Zi:return{byteLength:4,components:1};case Xm:case $m:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${n}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:Ld}}));typeof window<"u"&&(window.__THREE__?je("WARNING: Multiple instances of Three.js being imported."):window.__THREE__=Ld);function Mg(){let n=null,e=!1,t=null,i=null;function s(r,a){i=n.requestAnimationFrame(s),t(r,a)}return{start:function(){e!==!0&&t!==null&&n!==null&&(i=n.requestAnimationFrame(s),e=!0)},stop:function(){n!==null&&n.cancelAnimationFrame(i),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){n=r}}}function qy(n){const e=new WeakMap;function t(o,l){const c=o.array,u=o.usage,d=c.byteLength,h=n.createBuffer();n.bindBuffer(l,h),n.bufferData(l,c,u),o.onUploadCallback();let m;if(c instanceof Float32Array)m=n.FLOAT;else if(typeof Float16Array<"u"&&c instanceof Float16Array)m=n.HALF_FLOAT;else if(c instanceof Uint16Array)o.isFloat16BufferAttribute?m=n.HALF_FLOAT:m=n.UNSIGNED_SHORT;else if(c instanceof Int16Array)m=n.SHORT;else if(c instanceof Uint32Array)m=n.UNSIGNED_INT;else if(c instanceof Int32Array)m=n.INT;else if(c instanceof Int8Array)m=n.BYTE;else if(c instanceof Uint8Array)m=n.UNSIGNED_BYTE;else if(c instanceof Uint8ClampedArray)m=n.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+c);return{buffer:h,type:m,bytesPerElement:c.BYTES_PER_ELEMENT,version:o.version,size:d}}function i(o,l,c){const u=l.array,d=l.updateRanges;if(n.bindBuffer(c,o),d.length===0)n.bufferSubData(c,0,u);else{d.sort((m,g)=>m.start-g.start);let h=0;for(let m=1;m<d.length;m++){const g=d[h],y=d[m];y.start<=g.start+g.count+1?g.count=Math.max(g.count,y.start+y.count-g.start):(++h,d[h]=y)}d.length=h+1;for(let m=0,g=d.length;m<g;m++){const y=d[m];n.bufferSubData(c,y.start*u.BYTES_PER_ELEMENT,u,y.start,y.count)}l.clearUpdateRanges()}l.onUploadCallback()}function s(o){return o.isInterleavedBufferAttribute&&(o=o.data),e.get(o)}function r(o){o.isInterleavedBufferAttribute&&(o=o.data);const l=e.get(o);l&&(n.deleteBuffer(l.buffer),e.delete(o))}function a(o,l){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){const u=e.get(o);(!u||u.version<o.version)&&e.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}const c=e.get(o);if(c===void 0)e.set(o,t(o,l));else if(c.version<o.version){if(c.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");i(c.buffer,o,l),c.version=o.version}}return{get:s,remove:r,update:a}}var Xy=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,$y=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,Ky=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,Yy=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,Zy=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,jy=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,Jy=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,Qy=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,eb=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,tb=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,nb=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,ib=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,sb=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,rb=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,ab=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,ob=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,lb=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,cb=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,ub=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,db=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,hb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,fb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,pb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,mb=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,gb=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,vb=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,_b=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,xb=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,yb=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,bb="gl_FragColor = linearToOutputTexel( gl_FragColor );",wb=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,Sb=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,Mb=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,Eb=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,Ab=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,Tb=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,Rb=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,Cb=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,Pb=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,Lb=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,Db=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,Nb=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,Ib=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,kb=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,Fb=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,Ub=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,Ob=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,zb=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,Bb=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,Hb=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,Vb=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,Gb=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,Wb=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,qb=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,Xb=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,$b=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,Kb=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,Yb=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Zb=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,jb=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,Jb=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,Qb=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,ew=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,tw=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,nw=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,iw=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,sw=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,rw=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,aw=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,ow=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,lw=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,cw=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,uw=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,dw=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,hw=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,fw=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,pw=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,mw=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,gw=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,vw=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,_w=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,xw=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,yw=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,bw=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,ww=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,Sw=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,Mw=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,Ew=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,Aw=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,Tw=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,Rw=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,Cw=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,Pw=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,Lw=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,Dw=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,Nw=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,Iw=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,kw=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,Fw=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,Uw=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,Ow=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,zw=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,Bw=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,Hw=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Vw=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Gw=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,Ww=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`;const qw=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,Xw=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,$w=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Kw=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Yw=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Zw=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,jw=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,Jw=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,Qw=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,eS=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,tS=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,nS=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,iS=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,sS=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,rS=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,aS=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,oS=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,lS=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,cS=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,uS=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,dS=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,hS=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,fS=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,pS=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,mS=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,gS=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,vS=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,_S=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,xS=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,yS=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,bS=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,wS=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,SS=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,MS=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,ot={alphahash_fragment:Xy,alphahash_pars_fragment:$y,alphamap_fragment:Ky,alphamap_pars_fragment:Yy,alphatest_fragment:Zy,alphatest_pars_fragment:jy,aomap_fragment:Jy,aomap_pars_fragment:Qy,batching_pars_vertex:eb,batching_vertex:tb,begin_vertex:nb,beginnormal_vertex:ib,bsdfs:sb,iridescence_fragment:rb,bumpmap_pars_fragment:ab,clipping_planes_fragment:ob,clipping_planes_pars_fragment:lb,clipping_planes_pars_vertex:cb,clipping_planes_vertex:ub,color_fragment:db,color_pars_fragment:hb,color_pars_vertex:fb,color_vertex:pb,common:mb,defaultnormal_vertex:gb,displacementmap_pars_vertex:vb,displacementmap_vertex:_b,emissivemap_fragment:xb,emissivemap_pars_fragment:yb,colorspace_fragment:bb,colorspace_pars_fragment:wb,envmap_fragment:Sb,envmap_common_pars_fragment:Mb,envmap_pars_fragment:Eb,envmap_pars_vertex:Ab,envmap_physical_pars_fragment:Ub,envmap_vertex:Tb,fog_vertex:Rb,fog_pars_vertex:Cb,fog_fragment:Pb,fog_pars_fragment:Lb,gradientmap_pars_fragment:Db,lightmap_pars_fragment:Nb,lights_lambert_fragment:Ib,lights_lambert_pars_fragment:kb,lights_pars_begin:Fb,lights_toon_fragment:Ob,lights_toon_pars_fragment:zb,lights_phong_fragment:Bb,lights_phong_pars_fragment:Hb,lights_physical_fragment:Vb,lights_physical_pars_fragment:Gb,lights_fragment_begin:Wb,lights_fragment_maps:qb,lights_fragment_end:Xb,lightprobes_pars_fragment:$b,logdepthbuf_fragment:Kb,logdepthbuf_pars_fragment:Yb,logdepthbuf_pars_vertex:Zb,logdepthbuf_vertex:jb,map_fragment:Jb,map_pars_fragment:Qb,map_particle_fragment:ew,map_particle_pars_fragment:tw,metalnessmap_fragment:nw,metalnessmap_pars_fragment:iw,morphinstance_vertex:sw,morphcolor_vertex:rw,morphnormal_vertex:aw,morphtarget_pars_vertex:ow,morphtarget_vertex:lw,normal_fragment_begin:cw,normal_fragment_maps:uw,normal_pars_fragment:dw,normal_pars_vertex:hw,normal_vertex:fw,normalmap_pars_fragment:pw,clearcoat_normal_fragment_begin:mw,clearcoat_normal_fragment_maps:gw,clearcoat_pars_fragment:vw,iridescence_pars_fragment:_w,opaque_fragment:xw,packing:yw,premultiplied_alpha_fragment:bw,project_vertex:ww,dithering_fragment:Sw,dithering_pars_fragment:Mw,roughnessmap_fragment:Ew,roughnessmap_pars_fragment:Aw,shadowmap_pars_fragment:Tw,shadowmap_pars_vertex:Rw,shadowmap_vertex:Cw,shadowmask_pars_fragment:Pw,skinbase_vertex:Lw,skinning_pars_vertex:Dw,skinning_vertex:Nw,skinnormal_vertex:Iw,specularmap_fragment:kw,specularmap_pars_fragment:Fw,tonemapping_fragment:Uw,tonemapping_pars_fragment:Ow,transmission_fragment:zw,transmission_pars_fragment:Bw,uv_pars_fragment:Hw,uv_pars_vertex:Vw,uv_vertex:Gw,worldpos_vertex:Ww,background_vert:qw,background_frag:Xw,backgroundCube_vert:$w,backgroundCube_frag:Kw,cube_vert:Yw,cube_frag:Zw,depth_vert:jw,depth_frag:Jw,distance_vert:Qw,distance_frag:eS,equirect_vert:tS,equirect_frag:nS,linedashed_vert:iS,linedashed_frag:sS,meshbasic_vert:rS,meshbasic_frag:aS,meshlambert_vert:oS,meshlambert_frag:lS,meshmatcap_vert:cS,meshmatcap_frag:uS,meshnormal_vert:dS,meshnormal_frag:hS,meshphong_vert:fS,meshphong_frag:pS,meshphysical_vert:mS,meshphysical_frag:gS,meshtoon_vert:vS,meshtoon_frag:_S,points_vert:xS,points_frag:yS,shadow_vert:bS,shadow_frag:wS,sprite_vert:SS,sprite_frag:MS},De={common:{diffuse:{value:new lt(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new it},alphaMap:{value:null},alphaMapTransform:{value:new it},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new it}},envmap:{envMap:{value:null},envMapRotation:{value:new it},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new it}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new it}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new it},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new it},normalScale:{value:new qe(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new it},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new it}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new it}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new it}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new lt(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new lt(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new it},alphaTest:{value:0},uvTransform:{value:new it}},sprite:{diffuse:{value:new lt(16777215)},opacity:{value:1},center:{value:new qe(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new it},alphaMap:{value:null},alphaMapTransform:{value:new it},alphaTest:{value:0}}},Yi={basic:{uniforms:Xn([De.common,De.specularmap,De.envmap,De.aomap,De.lightmap,De.fog]),vertexShader:ot.meshbasic_vert,fragmentShader:ot.meshbasic_frag},lambert:{uniforms:Xn([De.common,De.specularmap,De.envmap,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.fog,De.lights,{emissive:{value:new lt(0)},envMapIntensity:{value:1}}]),vertexShader:ot.meshlambert_vert,fragmentShader:ot.meshlambert_frag},phong:{uniforms:Xn([De.common,De.specularmap,De.envmap,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.fog,De.lights,{emissive:{value:new lt(0)},specular:{value:new lt(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:ot.meshphong_vert,fragmentShader:ot.meshphong_frag},standard:{uniforms:Xn([De.common,De.envmap,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.roughnessmap,De.metalnessmap,De.fog,De.lights,{emissive:{value:new lt(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:ot.meshphysical_vert,fragmentShader:ot.meshphysical_frag},toon:{uniforms:Xn([De.common,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.gradientmap,De.fog,De.lights,{emissive:{value:new lt(0)}}]),vertexShader:ot.meshtoon_vert,fragmentShader:ot.meshtoon_frag},matcap:{uniforms:Xn([De.common,De.bumpmap,De.normalmap,De.displacementmap,De.fog,{matcap:{value:null}}]),vertexShader:ot.meshmatcap_vert,fragmentShader:ot.meshmatcap_frag},points:{uniforms:Xn([De.points,De.fog]),vertexShader:ot.points_vert,fragmentShader:ot.points_frag},dashed:{uniforms:Xn([De.common,De.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:ot.linedashed_vert,fragmentShader:ot.linedashed_frag},depth:{uniforms:Xn([De.common,De.displacementmap]),vertexShader:ot.depth_vert,fragmentShader:ot.depth_frag},normal:{uniforms:Xn([De.common,De.bumpmap,De.normalmap,De.displacementmap,{opacity:{value:1}}]),vertexShader:ot.meshnormal_vert,fragmentShader:ot.meshnormal_frag},sprite:{uniforms:Xn([De.sprite,De.fog]),vertexShader:ot.sprite_vert,fragmentShader:ot.sprite_frag},background:{uniforms:{uvTransform:{value:new it},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:ot.background_vert,fragmentShader:ot.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new it}},vertexShader:ot.backgroundCube_vert,fragmentShader:ot.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:ot.cube_vert,fragmentShader:ot.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:ot.equirect_vert,fragmentShader:ot.equirect_frag},distance:{uniforms:Xn([De.common,De.displacementmap,{referencePosition:{value:new z},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:ot.distance_vert,fragmentShader:ot.distance_frag},shadow:{uniforms:Xn([De.lights,De.fog,{color:{value:new lt(0)},opacity:{value:1}}]),vertexShader:ot.shadow_vert,fragmentShader:ot.shadow_frag}};Yi.physical={uniforms:Xn([Yi.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new it},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new it},clearcoatNormalScale:{value:new qe(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new it},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new it},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new it},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new it},sheen:{value:0},sheenColor:{value:new lt(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new it},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new it},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new it},transmissionSamplerSize:{value:new qe},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new it},attenuationDistance:{value:0},attenuationColor:{value:new lt(0)},specularColor:{value:new lt(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new it},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new it},anisotropyVector:{value:new qe},anisotropyMap:{value:null},anisotropyMapTransform:{value:new it}}]),vertexShader:ot.meshphysical_vert,fragmentShader:ot.meshphysical_frag};const Wo={r:0,b:0,g:0},ES=new Dt,Eg=new it;Eg.set(-1,0,0,0,1,0,0,0,1);function AS(n,e,t,i,s,r){const a=new lt(0);let o=s===!0?0:1,l,c,u=null,d=0,h=null;function m(x){let R=x.isScene===!0?x.background:null;if(R&&R.isTexture){const S=x.backgroundBlurriness>0;R=e.get(R,S)}return R}function g(x){let R=!1;const S=m(x);S===null?p(a,o):S&&S.isColor&&(p(S,1),R=!0);const C=n.xr.getEnvironmentBlendMode();C==="additive"?t.buffers.color.setClear(0,0,0,1,r):C==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,r),(n.autoClear||R)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),n.clear(n.autoClearColor,n.autoClearDepth,n.autoClearStencil))}function y(x,R){const S=m(R);S&&S.isCubeTexture?(c===void 0&&(c=new en(new oa(1,1,1),new rr({name:"BackgroundCubeMaterial",uniforms:ta(Yi.backgroundCube.uniforms),vertexShader:Yi.backgroundCube.vertexShader,fragmentShader:Yi.backgroundCube.fragmentShader,side:Jn,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),c.geometry.deleteAttribute("uv"),c.onBeforeRender=function(C,w,v){this.matrixWorld.copyPosition(v.matrixWorld)},Object.defineProperty(c.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),i.update(c)),c.material.uniforms.envMap.value=S,c.material.uniforms.backgroundBlurriness.value=R.backgroundBlurriness,c.material.uniforms.backgroundIntensity.value=R.backgroundIntensity,c.material.uniforms.backgroundRotation.value.setFromMatrix4(ES.makeRotationFromEuler(R.backgroundRotation)).transpose(),S.isRenderTargetTexture===!1&&c.material.uniforms.backgroundRotation.value.premultiply(Eg),c.material.toneMapped=vt.getTransfer(S.colorSpace)!==Lt,(u!==S||d!==S.version||h!==n.toneMapping)&&(c.material.needsUpdate=!0,u=S,d=S.version,h=n.toneMapping),c.layers.enableAll(),x.unshift(c,c.geometry,c.material,0,0,null)):S&&S.isTexture&&(l===void 0&&(l=new en(new Ul(2,2),new rr({name:"BackgroundMaterial",uniforms:ta(Yi.background.uniforms),vertexShader:Yi.background.vertexShader,fragmentShader:Yi.background.fragmentShader,side:Os,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),i.update(l)),l.material.uniforms.t2D.value=S,l.material.uniforms.backgroundIntensity.value=R.backgroundIntensity,l.material.toneMapped=vt.getTransfer(S.colorSpace)!==Lt,S.matrixAutoUpdate===!0&&S.updateMatrix(),l.material.uniforms.uvTransform.value.copy(S.matrix),(u!==S||d!==S.version||h!==n.toneMapping)&&(l.material.needsUpdate=!0,u=S,d=S.version,h=n.toneMapping),l.layers.enableAll(),x.unshift(l,l.geometry,l.material,0,0,null))}function p(x,R){x.getRGB(Wo,mg(n)),t.buffers.color.setClear(Wo.r,Wo.g,Wo.b,R,r)}function f(){c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0),l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0)}return{getClearColor:function(){return a},setClearColor:function(x,R=1){a.set(x),o=R,p(a,o)},getClearAlpha:function(){return o},setClearAlpha:function(x){o=x,p(a,o)},render:g,addToRenderList:y,dispose:f}}function TS(n,e){const t=n.getParameter(n.MAX_VERTEX_ATTRIBS),i={},s=h(null);let r=s,a=!1;function o(D,B,G,k,W){let Y=!1;const V=d(D,k,G,B);r!==V&&(r=V,c(r.object)),Y=m(D,k,G,W),Y&&g(D,k,G,W),W!==null&&e.update(W,n.ELEMENT_ARRAY_BUFFER),(Y||a)&&(a=!1,S(D,B,G,k),W!==null&&n.bindBuffer(n.ELEMENT_ARRAY_BUFFER,e.get(W).buffer))}function l(){return n.createVertexArray()}function c(D){return n.bindVertexArray(D)}function u(D){return n.deleteVertexArray(D)}function d(D,B,G,k){const W=k.wireframe===!0;let Y=i[B.id];Y===void 0&&(Y={},i[B.id]=Y);const V=D.isInstancedMesh===!0?D.id:0;let le=Y[V];le===void 0&&(le={},Y[V]=le);let j=le[G.id];j===void 0&&(j={},le[G.id]=j);let Q=j[W];return Q===void 0&&(Q=h(l()),j[W]=Q),Q}function h(D){const B=[],G=[],k=[];for(let W=0;W<t;W++)B[W]=0,G[W]=0,k[W]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:B,enabledAttributes:G,attributeDivisors:k,object:D,attributes:{},index:null}}function m(D,B,G,k){const W=r.attributes,Y=B.attributes;let V=0;const le=G.getAttributes();for(const j in le)if(le[j].location>=0){const se=W[j];let he=Y[j];if(he===void 0&&(j==="instanceMatrix"&&D.instanceMatrix&&(he=D.instanceMatrix),j==="instanceColor"&&D.instanceColor&&(he=D.instanceColor)),se===void 0||se.attribute!==he||he&&se.data!==he.data)return!0;V++}return r.attributesNum!==V||r.index!==k}function g(D,B,G,k){const W={},Y=B.attributes;let V=0;const le=G.getAttributes();for(const j in le)if(le[j].location>=0){let se=Y[j];se===void 0&&(j==="instanceMatrix"&&D.instanceMatrix&&(se=D.instanceMatrix),j==="instanceColor"&&D.instanceColor&&(se=D.instanceColor));const he={};he.attribute=se,se&&se.data&&(he.data=se.data),W[j]=he,V++}r.attributes=W,r.attributesNum=V,r.index=k}function y(){const D=r.newAttributes;for(let B=0,G=D.length;B<G;B++)D[B]=0}function p(D){f(D,0)}function f(D,B){const G=r.newAttributes,k=r.enabledAttributes,W=r.attributeDivisors;G[D]=1,k[D]===0&&(n.enableVertexAttribArray(D),k[D]=1),W[D]!==B&&(n.vertexAttribDivisor(D,B),W[D]=B)}function x(){const D=r.newAttributes,B=r.enabledAttributes;for(let G=0,k=B.length;G<k;G++)B[G]!==D[G]&&(n.disableVertexAttribArray(G),B[G]=0)}function R(D,B,G,k,W,Y,V){V===!0?n.vertexAttribIPointer(D,B,G,W,Y):n.vertexAttribPointer(D,B,G,k,W,Y)}function S(D,B,G,k){y();const W=k.attributes,Y=G.getAttributes(),V=B.defaultAttributeValues;for(const le in Y){const j=Y[le];if(j.location>=0){let Q=W[le];if(Q===void 0&&(le==="instanceMatrix"&&D.instanceMatrix&&(Q=D.instanceMatrix),le==="instanceColor"&&D.instanceColor&&(Q=D.instanceColor)),Q!==void 0){const se=Q.normalized,he=Q.itemSize,de=e.get(Q);if(de===void 0)continue;const ee=de.buffer,me=de.type,_e=de.bytesPerElement,Te=me===n.INT||me===n.UNSIGNED_INT||Q.gpuType===Dd;if(Q.isInterleavedBufferAttribute){const we=Q.data,Ge=we.isInterleavedBuffer===!0?we.stride:we.itemSize,tt=Q.offset;if(we.isInstancedInterleavedBuffer||we.isInstancedBufferAttribute){for(let He=0;He<j.locationSize;He++)f(j.location+He,we.meshPerAttribute);D.isInstancedMesh!==!0&&k._maxInstanceCount===void 0&&(k._maxInstanceCount=we.meshPerAttribute*we.count)}else for(let He=0;He<j.locationSize;He++)p(j.location+He);n.bindBuffer(n.ARRAY_BUFFER,ee);for(let He=0;He<j.locationSize;He++)R(j.location+He,he/j.locationSize,me,se,Ge*_e,(tt+he/j.locationSize*He)*_e,Te)}else{if(Q.isInstancedBufferAttribute){for(let we=0;we<j.locationSize;we++)f(j.location+we,Q.meshPerAttribute);D.isInstancedMesh!==!0&&k._maxInstanceCount===void 0&&(k._maxInstanceCount=Q.meshPerAttribute*Q.count)}else for(let we=0;we<j.locationSize;we++)p(j.location+we);n.bindBuffer(n.ARRAY_BUFFER,ee);for(let we=0;we<j.locationSize;we++)R(j.location+we,he/j.locationSize,me,se,he*_e,he/j.locationSize*we*_e,Te)}}else if(V!==void 0){const se=V[le];if(se!==void 0)switch(se.length){case 2:n.vertexAttrib2fv(j.location,se);break;case 3:n.vertexAttrib3fv(j.location,se);break;case 4:n.vertexAttrib4fv(j.location,se);break;default:n.vertexAttrib1fv(j.location,se)}}}}x()}function C(){F();for(const D in i){const B=i[D];for(const G in B){const k=B[G];for(const W in k){const Y=k[W];for(const V in Y)u(Y[V].object),delete Y[V];delete k[W]}}delete i[D]}}function w(D){if(i[D.id]===void 0)return;const B=i[D.id];for(const G in B){const k=B[G];for(const W in k){const Y=k[W];for(const V in Y)u(Y[V].object),delete Y[V];delete k[W]}}delete i[D.id]}function v(D){for(const B in i){const G=i[B];for(const k in G){const W=G[k];if(W[D.id]===void 0)continue;const Y=W[D.id];for(const V in Y)u(Y[V].object),delete Y[V];delete W[D.id]}}}function M(D){for(const B in i){const G=i[B],k=D.isInstancedMesh===!0?D.id:0,W=G[k];if(W!==void 0){for(const Y in W){const V=W[Y];for(const le in V)u(V[le].object),delete V[le];delete W[Y]}delete G[k],Object.keys(G).length===0&&delete i[B]}}}function F(){L(),a=!0,r!==s&&(r=s,c(r.object))}function L(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:o,reset:F,resetDefaultState:L,dispose:C,releaseStatesOfGeometry:w,releaseStatesOfObject:M,releaseStatesOfProgram:v,initAttributes:y,enableAttribute:p,disableUnusedAttributes:x}}function RS(n,e,t){let i;function s(l){i=l}function r(l,c){n.drawArrays(i,l,c),t.update(c,i,1)}function a(l,c,u){u!==0&&(n.drawArraysInstanced(i,l,c,u),t.update(c,i,u))}function o(l,c,u){if(u===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(i,l,0,c,0,u);let h=0;for(let m=0;m<u;m++)h+=c[m];t.update(h,i,1)}this.setMode=s,this.render=r,this.renderInstances=a,this.renderMultiDraw=o}function CS(n,e,t,i){let s;function r(){if(s!==void 0)return s;if(e.has("EXT_texture_filter_anisotropic")===!0){const v=e.get("EXT_texture_filter_anisotropic");s=n.getParameter(v.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function a(v){return!(v!==ji&&i.convert(v)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(v){const M=v===ts&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(v!==ai&&v!==Zi&&!M&&i.convert(v)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_TYPE))}function l(v){if(v==="highp"){if(n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.HIGH_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.HIGH_FLOAT).precision>0)return"highp";v="mediump"}return v==="mediump"&&n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.MEDIUM_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let c=t.precision!==void 0?t.precision:"highp";const u=l(c);u!==c&&(je("WebGLRenderer:",c,"not supported, using",u,"instead."),c=u);const d=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),h=t.logarithmicDepthBuffer===!0&&d===!1;t.reversedDepthBuffer===!0&&d===!1&&je("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&d===!0&&je("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");const m=n.getParameter(n.MAX_TEXTURE_IMAGE_UNITS),g=n.getParameter(n.MAX_VERTEX_TEXTURE_IMAGE_UNITS),y=n.getParameter(n.MAX_TEXTURE_SIZE),p=n.getParameter(n.MAX_CUBE_MAP_TEXTURE_SIZE),f=n.getParameter(n.MAX_VERTEX_ATTRIBS),x=n.getParameter(n.MAX_VERTEX_UNIFORM_VECTORS),R=n.getParameter(n.MAX_VARYING_VECTORS),S=n.getParameter(n.MAX_FRAGMENT_UNIFORM_VECTORS),C=n.getParameter(n.MAX_SAMPLES),w=n.getParameter(n.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:l,textureFormatReadable:a,textureTypeReadable:o,precision:c,logarithmicDepthBuffer:h,reversedDepthBuffer:d,maxTextures:m,maxVertexTextures:g,maxTextureSize:y,maxCubemapSize:p,maxAttributes:f,maxVertexUniforms:x,maxVaryings:R,maxFragmentUniforms:S,maxSamples:C,samples:w}}function PS(n){const e=this;let t=null,i=0,s=!1,r=!1;const a=new Li,o=new it,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(d,h){const m=d.length!==0||h||i!==0||s;return s=h,i=d.length,m},this.beginShadows=function(){r=!0,u(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(d,h){t=u(d,h,0)},this.setState=function(d,h,m){const g=d.clippingPlanes,y=d.clipIntersection,p=d.clipShadows,f=n.get(d);if(!s||g===null||g.length===0||r&&!p)r?u(null):c();else{const x=r?0:i,R=x*4;let S=f.clippingState||null;l.value=S,S=u(g,h,R,m);for(let C=0;C!==R;++C)S[C]=t[C];f.clippingState=S,this.numIntersection=y?this.numPlanes:0,this.numPlanes+=x}};function c(){l.value!==t&&(l.value=t,l.needsUpdate=i>0),e.numPlanes=i,e.numIntersection=0}function u(d,h,m,g){const y=d!==null?d.length:0;let p=null;if(y!==0){if(p=l.value,g!==!0||p===null){const f=m+y*4,x=h.matrixWorldInverse;o.getNormalMatrix(x),(p===null||p.length<f)&&(p=new Float32Array(f));for(let R=0,S=m;R!==y;++R,S+=4)a.copy(d[R]).applyMatrix4(x,o),a.normal.toArray(p,S),p[S+3]=a.constant}l.value=p,l.needsUpdate=!0}return e.numPlanes=y,e.numIntersection=0,p}}class Vd extends Ji{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;const i={width:e,height:e,depth:1},s=[i,i,i,i,i,i];this.texture=new hg(s),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;const i={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},s=new oa(5,5,5),r=new rr({name:"CubemapFromEquirect",uniforms:ta(i.uniforms),vertexShader:i.vertexShader,fragmentShader:i.fragmentShader,side:Jn,blending:qr});r.uniforms.tEquirect.value=t;const a=new en(s,r),o=t.minFilter;return t.minFilter===Ns&&(t.minFilter=jn),new ju(1,10,this).update(e,a),t.minFilter=o,a.geometry.dispose(),a.material.dispose(),this}clear(e,t=!0,i=!0,s=!0){const r=e.getRenderTarget();for(let a=0;a<6;a++)e.setRenderTarget(this,a),e.clear(t,i,s);e.setRenderTarget(r)}}const Gf=256,LS=3,DS=20,Ag=256,Tg=16,NS=3,IS=new z,kS=new lt;class Sl{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new ju(1,10,null),this._boxMesh=new en(new oa(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,i=.1,s=100,r={}){const{size:a=256,position:o=IS}=r,l=this._renderer;this._setSize(a);const c=this._allocateTarget(),u=this._getSourceTarget(!0);t>0&&(u.texture.mipmapsAutoUpdate=!1);const d=l.autoClear,h=l.autoClearColor,m=l.autoClearDepth,g=l.autoClearStencil,y=e.background;l.autoClear=!0,l.autoClearColor=!0,l.autoClearDepth=!0,l.autoClearStencil=!0,y===null&&(e.background=l.getClearColor(kS));const p=new ju(i,s,u);return p.position.copy(o),p.update(l,e),l.autoClear=d,l.autoClearColor=h,l.autoClearDepth=m,l.autoClearStencil=g,e.background=y,t>0&&(u.texture.mipmapsAutoUpdate=!0,this._blur(c,t)),this._applyPMREM(c),c}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=Xf(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=qf(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(Gf,sy(e))}_fromTexture(e,t){e.mapping===Jr||e.mapping===Wa?this._setSize(e.image.length===0?Gf:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);const i=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(i),i}_allocateTarget(){const e=this._cubeSize,t=Wf(e,!1,!1),i=Math.log2(e)-LS;for(let s=0;s<=i;s++)t.texture.mipmaps.push({width:e>>s,height:e>>s});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){const t=this._cubeSize,i=this._sourceTarget;return(i===null||i.width!==t||e&&i.depthBuffer===!1)&&(i!==null&&i.dispose(),this._sourceTarget=Wf(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,i){const s=this._boxMesh,r=this._cubeCamera;s.material=i,r.renderTarget=e,r.activeMipmapLevel=t;const a=e.width>>t;e.viewport.set(0,0,a,a),r.update(this._renderer,s),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===Jr||e.mapping===Wa?(this._cubemapMaterial===null&&(this._cubemapMaterial=Xf()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=qf()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=FS(),this._integrationMaterial=US());const t=this._cubeSize,i=e.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;const r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(t/Tg);for(let a=0;a<=i;a++){const o=Sl.lodToRoughness(a,i);if(a>i-NS)r.roughness.value=o,this._renderCube(e,a,this._integrationMaterial);else{const l=o>0?Math.log2(t)+.5*Math.log2(6/(Ag*Math.pow(o,4)))+.5:0;s.roughness.value=o,s.lodBias.value=l,this._renderCube(e,a,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=OS());const i=this._blurMaterial,s=i.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(e,0,i),s.envMap.value=e.texture,this._renderCube(r,0,i)}}function Wf(n,e,t){return new Vd(n,{minFilter:Ns,generateMipmaps:e,type:ts,colorSpace:gl,depthBuffer:t})}function ro(n,e,t){return new rr({name:n,uniforms:e,vertexShader:ot.cube_vert,fragmentShader:t,side:Jn,blending:qr,depthTest:!1,depthWrite:!1})}function FS(){return ro("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${Ag}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function US(){return ro("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:Tg}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function OS(){return ro("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${DS}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function qf(){return ro("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function Xf(){return ro("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function zS(n){let e=new WeakMap,t=new WeakMap,i=null;function s(h,m=!1){return h==null?null:m?a(h):r(h)}function r(h){if(h&&h.isTexture){const m=h.mapping;if(m===lc||m===cc)if(e.has(h)){const g=e.get(h).texture;return o(g,h.mapping)}else{const g=h.image;if(g&&g.height>0){const y=new Vd(g.height);return y.fromEquirectangularTexture(n,h),e.set(h,y),h.addEventListener("dispose",c),o(y.texture,h.mapping)}else return null}}return h}function a(h){if(h&&h.isTexture&&h.isPMREMTexture!==!0){const m=h.mapping,g=m===lc||m===cc,y=m===Jr||m===Wa;if(g||y){let p=t.get(h);const f=p!==void 0?p.texture.pmremVersion:0;if(h.isRenderTargetTexture&&h.pmremVersion!==f)return i===null&&(i=new Sl(n)),p=g?i.fromEquirectangular(h,p):i.fromCubemap(h,p),p.texture.pmremVersion=h.pmremVersion,t.set(h,p),p.texture;if(p!==void 0)return p.texture;{const x=h.image;return g&&x&&x.height>0||y&&x&&l(x)?(i===null&&(i=new Sl(n)),p=g?i.fromEquirectangular(h):i.fromCubemap(h),p.texture.pmremVersion=h.pmremVersion,t.set(h,p),h.addEventListener("dispose",u),p.texture):null}}}return h}function o(h,m){return m===lc?h.mapping=Jr:m===cc&&(h.mapping=Wa),h}function l(h){let m=0;const g=6;for(let y=0;y<g;y++)h[y]!==void 0&&m++;return m===g}function c(h){const m=h.target;m.removeEventListener("dispose",c);const g=e.get(m);g!==void 0&&(e.delete(m),g.dispose())}function u(h){const m=h.target;m.removeEventListener("dispose",u);const g=t.get(m);g!==void 0&&(t.delete(m),g.dispose())}function d(){e=new WeakMap,t=new WeakMap,i!==null&&(i.dispose(),i=null)}return{get:s,dispose:d}}function BS(n){const e={};function t(i){if(e[i]!==void 0)return e[i];const s=n.getExtension(i);return e[i]=s,s}return{has:function(i){return t(i)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(i){const s=t(i);return s===null&&al("WebGLRenderer: "+i+" extension not supported."),s}}}function HS(n,e,t,i){const s={},r=new WeakMap,a=new FinalizationRegistry(g=>delete s[g]);function o(g){l(g.target)}function l(g){g.index!==null&&e.remove(g.index);for(const p in g.attributes)e.remove(g.attributes[p]);g.removeEventListener("dispose",o),delete s[g.id],a.unregister(g);const y=r.get(g);y&&(e.remove(y),r.delete(g)),i.releaseStatesOfGeometry(g),g.isInstancedBufferGeometry===!0&&delete g._maxInstanceCount,t.memory.geometries--}function c(g,y){return s[y.id]!==void 0||(y.addEventListener("dispose",o),s[y.id]=new WeakRef(y),a.register(y,y.id,y),t.memory.geometries++),y}function u(g){const y=g.attributes;for(const p in y)e.update(y[p],n.ARRAY_BUFFER)}function d(g){const y=g.index,p=g.attributes.position;let f=0;if(p===void 0)return;const x=y!==null?y.array.length:p.array.length/3-1,R=p.count>=65535?lg:og,S=new R(Math.ceil(x/3)*6,1),C=S.array;if(y!==null){const v=y.array;f=y.version;for(let M=0,F=0;M<x;M+=3){const L=v[M+0],D=v[M+1],B=v[M+2];C[F++]=L,C[F++]=D,C[F++]=D,C[F++]=B,C[F++]=B,C[F++]=L}}else{f=p.version;for(let v=0,M=0;v<x;v+=3){const F=v+0,L=v+1,D=v+2;C[M++]=F,C[M++]=L,C[M++]=L,C[M++]=D,C[M++]=D,C[M++]=F}}S.version=f;const w=r.get(g);w&&e.remove(w),r.set(g,S)}function h(g){const y=r.get(g);if(y){const p=g.index;p!==null&&y.version<p.version&&d(g)}else d(g);return r.get(g)}function m(){for(const g in s){const y=s[g].deref();y!==void 0&&l(y)}}return{get:c,update:u,getWireframeAttribute:h,dispose:m}}function VS(n,e,t){let i;function s(d){i=d}let r,a;function o(d){r=d.type,a=d.bytesPerElement}function l(d,h){n.drawElements(i,h,r,d*a),t.update(h,i,1)}function c(d,h,m){m!==0&&(n.drawElementsInstanced(i,h,r,d*a,m),t.update(h,i,m))}function u(d,h,m){if(m===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(i,h,0,r,d,0,m);let y=0;for(let p=0;p<m;p++)y+=h[p];t.update(y,i,1)}this.setMode=s,this.setIndex=o,this.render=l,this.renderInstances=c,this.renderMultiDraw=u}function GS(n){const e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function i(r,a,o){switch(t.calls++,a){case n.TRIANGLES:t.triangles+=o*(r/3);break;case n.LINES:t.lines+=o*(r/2);break;case n.LINE_STRIP:t.lines+=o*(r-1);break;case n.LINE_LOOP:t.lines+=o*r;break;case n.POINTS:t.points+=o*r;break;default:yt("WebGLInfo: Unknown draw mode:",a);break}}function s(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:s,update:i}}function WS(n,e,t){const i=new WeakMap,s=new rn;function r(a,o,l){const c=a.morphTargetInfluences,u=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,d=u!==void 0?u.length:0;let h=i.get(o);if(h===void 0||h.count!==d){let L=function(){M.dispose(),i.delete(o),o.removeEventListener("dispose",L)};var m=L;h!==void 0&&h.texture.dispose();const g=o.morphAttributes.position!==void 0,y=o.morphAttributes.normal!==void 0,p=o.morphAttributes.color!==void 0,f=o.morphAttributes.position||[],x=o.morphAttributes.normal||[],R=o.morphAttributes.color||[];let S=0;g===!0&&(S=1),y===!0&&(S=2),p===!0&&(S=3);let C=o.attributes.position.count*S,w=1;C>e.maxTextureSize&&(w=Math.ceil(C/e.maxTextureSize),C=e.maxTextureSize);const v=new Float32Array(C*w*4*d),M=new sg(v,C,w,d);M.type=Zi,M.needsUpdate=!0;const F=S*4;for(let D=0;D<d;D++){const B=f[D],G=x[D],k=R[D],W=C*w*4*D;for(let Y=0;Y<B.count;Y++){const V=Y*F;g===!0&&(s.fromBufferAttribute(B,Y),v[W+V+0]=s.x,v[W+V+1]=s.y,v[W+V+2]=s.z,v[W+V+3]=0),y===!0&&(s.fromBufferAttribute(G,Y),v[W+V+4]=s.x,v[W+V+5]=s.y,v[W+V+6]=s.z,v[W+V+7]=0),p===!0&&(s.fromBufferAttribute(k,Y),v[W+V+8]=s.x,v[W+V+9]=s.y,v[W+V+10]=s.z,v[W+V+11]=k.itemSize===4?s.w:1)}}h={count:d,texture:M,size:new qe(C,w)},i.set(o,h),o.addEventListener("dispose",L)}if(a.isInstancedMesh===!0&&a.morphTexture!==null)l.getUniforms().setValue(n,"morphTexture",a.morphTexture,t);else{let g=0;for(let p=0;p<c.length;p++)g+=c[p];const y=o.morphTargetsRelative?1:1-g;l.getUniforms().setValue(n,"morphTargetBaseInfluence",y),l.getUniforms().setValue(n,"morphTargetInfluences",c)}l.getUniforms().setValue(n,"morphTargetsTexture",h.texture,t),l.getUniforms().setValue(n,"morphTargetsTextureSize",h.size)}return{update:r}}function qS(n,e,t,i,s){let r=new WeakMap;function a(c){const u=s.render.frame,d=c.geometry,h=e.get(c,d);if(r.get(h)!==u&&(e.update(h),r.set(h,u)),c.isInstancedMesh&&(c.hasEventListener("dispose",l)===!1&&c.addEventListener("dispose",l),r.get(c)!==u&&(t.update(c.instanceMatrix,n.ARRAY_BUFFER),c.instanceColor!==null&&t.update(c.instanceColor,n.ARRAY_BUFFER),r.set(c,u))),c.isSkinnedMesh){const m=c.skeleton;r.get(m)!==u&&(m.update(),r.set(m,u))}return h}function o(){r=new WeakMap}function l(c){const u=c.target;u.removeEventListener("dispose",l),i.releaseStatesOfObject(u),t.remove(u.instanceMatrix),u.instanceColor!==null&&t.remove(u.instanceColor)}return{update:a,dispose:o}}const XS={[Fm]:"LINEAR_TONE_MAPPING",[Um]:"REINHARD_TONE_MAPPING",[Om]:"CINEON_TONE_MAPPING",[zm]:"ACES_FILMIC_TONE_MAPPING",[Hm]:"AGX_TONE_MAPPING",[Vm]:"NEUTRAL_TONE_MAPPING",[Bm]:"CUSTOM_TONE_MAPPING"};function $S(n,e,t,i,s,r){const a=new Ji(e,t,{type:n,depthBuffer:s,stencilBuffer:r,samples:i?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1});let o=null,l=null,c=null;const u=new Ot;u.setAttribute("position",new an([-1,3,0,-1,-1,0,3,-1,0],3)),u.setAttribute("uv",new an([0,2,0,0,2,0],2));const d=new ky({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),h=new en(u,d),m=new xg(-1,1,1,-1,0,1);let g=null,y=null,p=!1,f,x=null,R=[],S=!1;this.setSize=function(C,w){a.setSize(C,w),o!==null&&o.setSize(C,w),l!==null&&l.setSize(C,w);for(let v=0;v<R.length;v++){const M=R[v];M.setSize&&M.setSize(C,w)}},this.setEffects=function(C){R=C,S=R.length>0&&R[0].isRenderPass===!0;const w=a.width,v=a.height;R.length>0&&o===null&&(o=new Ji(w,v,{type:ts,depthBuffer:!1,stencilBuffer:!1}),l=new Ji(w,v,{type:ts,depthBuffer:!1,stencilBuffer:!1}));const M=s===!0&&R.some(F=>F.needsDepthTexture===!0);M!==(a.depthTexture!==null)&&(M===!0&&c===null&&(c=new ea(w,v),r===!0&&(c.format=Is,c.type=Qr)),a.dispose(),a.depthTexture=M?c:null,a.resolveDepthBuffer=M,a.storeMultisampledDepthBuffer=M);for(let F=0;F<R.length;F++){const L=R[F];L.setSize&&L.setSize(w,v),M&&L.needsDepthTexture===!0&&L.setDepthTexture&&L.setDepthTexture(c)}},this.begin=function(C,w){if(p||C.toneMapping===gs&&R.length===0)return!1;if(x=w,w!==null){const v=w.width,M=w.height;(a.width!==v||a.height!==M)&&this.setSize(v,M)}return S===!1&&C.setRenderTarget(a),f=C.toneMapping,C.toneMapping=gs,!0},this.hasRenderPass=function(){return S},this.end=function(C,w){C.toneMapping=f,p=!0;let v=a,M=o;for(let F=0;F<R.length;F++){const L=R[F];L.enabled!==!1&&(L.render(C,M,v,w),L.needsSwap!==!1&&(v=M,M=M===o?l:o))}if(g!==C.outputColorSpace||y!==C.toneMapping){g=C.outputColorSpace,y=C.toneMapping,d.defines={},vt.getTransfer(g)===Lt&&(d.defines.SRGB_TRANSFER="");const F=XS[y];F&&(d.defines[F]=""),d.needsUpdate=!0}d.uniforms.tDiffuse.value=v.texture,C.setRenderTarget(x),C.render(h,m),x=null,p=!1},this.isCompositing=function(){return p},this.dispose=function(){a.dispose(),o!==null&&o.dispose(),l!==null&&l.dispose(),u.dispose(),d.dispose()}}const Rg=new zn,Cg=new ea(1,1),Pg=new fg(1),Lg=new sg,Dg=new dy,Ng=new hg,$f=[],Kf=[],Yf=new Float32Array(16),Zf=new Float32Array(9),jf=new Float32Array(4);function la(n,e,t){const i=n[0];if(i<=0||i>0)return n;const s=e*t;let r=$f[s];if(r===void 0&&(r=new Float32Array(s),$f[s]=r),e!==0){i.toArray(r,0);for(let a=1,o=0;a!==e;++a)o+=t,n[a].toArray(r,o)}return r}function wn(n,e){if(n.length!==e.length)return!1;for(let t=0,i=n.length;t<i;t++)if(n[t]!==e[t])return!1;return!0}function Sn(n,e){for(let t=0,i=e.length;t<i;t++)n[t]=e[t]}function Ol(n,e){let t=Kf[e];t===void 0&&(t=new Int32Array(e),Kf[e]=t);for(let i=0;i!==e;++i)t[i]=n.allocateTextureUnit();return t}function KS(n,e){const t=this.cache;t[0]!==e&&(n.uniform1f(this.addr,e),t[0]=e)}function YS(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(wn(t,e))return;n.uniform2fv(this.addr,e),Sn(t,e)}}function ZS(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(n.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(wn(t,e))return;n.uniform3fv(this.addr,e),Sn(t,e)}}function jS(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(wn(t,e))return;n.uniform4fv(this.addr,e),Sn(t,e)}}function JS(n,e){const t=this.cache,i=e.elements;if(i===void 0){if(wn(t,e))return;n.uniformMatrix2fv(this.addr,!1,e),Sn(t,e)}else{if(wn(t,i))return;jf.set(i),n.uniformMatrix2fv(this.addr,!1,jf),Sn(t,i)}}function QS(n,e){const t=this.cache,i=e.elements;if(i===void 0){if(wn(t,e))return;n.uniformMatrix3fv(this.addr,!1,e),Sn(t,e)}else{if(wn(t,i))return;Zf.set(i),n.uniformMatrix3fv(this.addr,!1,Zf),Sn(t,i)}}function eM(n,e){const t=this.cache,i=e.elements;if(i===void 0){if(wn(t,e))return;n.uniformMatrix4fv(this.addr,!1,e),Sn(t,e)}else{if(wn(t,i))return;Yf.set(i),n.uniformMatrix4fv(this.addr,!1,Yf),Sn(t,i)}}function tM(n,e){const t=this.cache;t[0]!==e&&(n.uniform1i(this.addr,e),t[0]=e)}function nM(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(wn(t,e))return;n.uniform2iv(this.addr,e),Sn(t,e)}}function iM(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(wn(t,e))return;n.uniform3iv(this.addr,e),Sn(t,e)}}function sM(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(wn(t,e))return;n.uniform4iv(this.addr,e),Sn(t,e)}}function rM(n,e){const t=this.cache;t[0]!==e&&(n.uniform1ui(this.addr,e),t[0]=e)}function aM(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(wn(t,e))return;n.uniform2uiv(this.addr,e),Sn(t,e)}}function oM(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(wn(t,e))return;n.uniform3uiv(this.addr,e),Sn(t,e)}}function lM(n,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(wn(t,e))return;n.uniform4uiv(this.addr,e),Sn(t,e)}}function zl(n){return n.version===0&&(n.compareFunction=Qm,n.needsUpdate=!0),n}function cM(n,e,t){const i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_2D_SHADOW?r=zl(Cg):r=Rg,t.setTexture2D(e||r,s)}function uM(n,e,t){const i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture3D(e||Dg,s)}function dM(n,e,t){const i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_CUBE_SHADOW?r=zl(Pg):r=Ng,t.setTextureCube(e||r,s)}function hM(n,e,t){const i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture2DArray(e||Lg,s)}function fM(n){switch(n){case 5126:return KS;case 35664:return YS;case 35665:return ZS;case 35666:return jS;case 35674:return JS;case 35675:return QS;case 35676:return eM;case 5124:case 35670:return tM;case 35667:case 35671:return nM;case 35668:case 35672:return iM;case 35669:case 35673:return sM;case 5125:return rM;case 36294:return aM;case 36295:return oM;case 36296:return lM;case 35678:case 36198:case 36298:case 36306:case 35682:return cM;case 35679:case 36299:case 36307:return uM;case 35680:case 36300:case 36308:case 36293:return dM;case 36289:case 36303:case 36311:case 36292:return hM}}function pM(n,e){n.uniform1fv(this.addr,e)}function mM(n,e){const t=la(e,this.size,2);n.uniform2fv(this.addr,t)}function gM(n,e){const t=la(e,this.size,3);n.uniform3fv(this.addr,t)}function vM(n,e){const t=la(e,this.size,4);n.uniform4fv(this.addr,t)}function _M(n,e){const t=la(e,this.size,4);n.uniformMatrix2fv(this.addr,!1,t)}function xM(n,e){const t=la(e,this.size,9);n.uniformMatrix3fv(this.addr,!1,t)}function yM(n,e){const t=la(e,this.size,16);n.uniformMatrix4fv(this.addr,!1,t)}function bM(n,e){n.uniform1iv(this.addr,e)}function wM(n,e){n.uniform2iv(this.addr,e)}function SM(n,e){n.uniform3iv(this.addr,e)}function MM(n,e){n.uniform4iv(this.addr,e)}function EM(n,e){n.uniform1uiv(this.addr,e)}function AM(n,e){n.uniform2uiv(this.addr,e)}function TM(n,e){n.uniform3uiv(this.addr,e)}function RM(n,e){n.uniform4uiv(this.addr,e)}function CM(n,e,t){const i=this.cache,s=e.length,r=Ol(t,s);wn(i,r)||(n.uniform1iv(this.addr,r),Sn(i,r));let a;this.type===n.SAMPLER_2D_SHADOW?a=zl(Cg):a=Rg;for(let o=0;o!==s;++o)t.setTexture2D(e[o]||a,r[o])}function PM(n,e,t){const i=this.cache,s=e.length,r=Ol(t,s);wn(i,r)||(n.uniform1iv(this.addr,r),Sn(i,r));for(let a=0;a!==s;++a)t.setTexture3D(e[a]||Dg,r[a])}function LM(n,e,t){const i=this.cache,s=e.length,r=Ol(t,s);wn(i,r)||(n.uniform1iv(this.addr,r),Sn(i,r));let a;this.type===n.SAMPLER_CUBE_SHADOW?a=zl(Pg):a=Ng;for(let o=0;o!==s;++o)t.setTextureCube(e[o]||a,r[o])}function DM(n,e,t){const i=this.cache,s=e.length,r=Ol(t,s);wn(i,r)||(n.uniform1iv(this.addr,r),Sn(i,r));for(let a=0;a!==s;++a)t.setTexture2DArray(e[a]||Lg,r[a])}function NM(n){switch(n){case 5126:return pM;case 35664:return mM;case 35665:return gM;case 35666:return vM;case 35674:return _M;case 35675:return xM;case 35676:return yM;case 5124:case 35670:return bM;case 35667:case 35671:return wM;case 35668:case 35672:return SM;case 35669:case 35673:return MM;case 5125:return EM;case 36294:return AM;case 36295:return TM;case 36296:return RM;case 35678:case 36198:case 36298:case 36306:case 35682:return CM;case 35679:case 36299:case 36307:return PM;case 35680:case 36300:case 36308:case 36293:return LM;case 36289:case 36303:case 36311:case 36292:return DM}}class IM{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.setValue=fM(t.type)}}class kM{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=NM(t.type)}}class FM{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,i){const s=this.seq;for(let r=0,a=s.length;r!==a;++r){const o=s[r];o.setValue(e,t[o.id],i)}}}const Uc=/(\w+)(\])?(\[|\.)?/g;function Jf(n,e){n.seq.push(e),n.map[e.id]=e}function UM(n,e,t){const i=n.name,s=i.length;for(Uc.lastIndex=0;;){const r=Uc.exec(i),a=Uc.lastIndex;let o=r[1];const l=r[2]==="]",c=r[3];if(l&&(o=o|0),c===void 0||c==="["&&a+2===s){Jf(t,c===void 0?new IM(o,n,e):new kM(o,n,e));break}else{let d=t.map[o];d===void 0&&(d=new FM(o),Jf(t,d)),t=d}}}class ol{constructor(e,t){this.seq=[],this.map={};const i=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let a=0;a<i;++a){const o=e.getActiveUniform(t,a),l=e.getUniformLocation(t,o.name);UM(o,l,this)}const s=[],r=[];for(const a of this.seq)a.type===e.SAMPLER_2D_SHADOW||a.type===e.SAMPLER_CUBE_SHADOW||a.type===e.SAMPLER_2D_ARRAY_SHADOW?s.push(a):r.push(a);s.length>0&&(this.seq=s.concat(r))}setValue(e,t,i,s){const r=this.map[t];r!==void 0&&r.setValue(e,i,s)}setOptional(e,t,i){const s=t[i];s!==void 0&&this.setValue(e,i,s)}static upload(e,t,i,s){for(let r=0,a=t.length;r!==a;++r){const o=t[r],l=i[o.id];l.needsUpdate!==!1&&o.setValue(e,l.value,s)}}static seqWithValue(e,t){const i=[];for(let s=0,r=e.length;s!==r;++s){const a=e[s];a.id in t&&i.push(a)}return i}}function Qf(n,e,t){const i=n.createShader(e);return n.shaderSource(i,t),n.compileShader(i),i}const OM=37297;let zM=0;function BM(n,e){const t=n.split(`
`),i=[],s=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let a=s;a<r;a++){const o=a+1;i.push(`${o===e?">":" "} ${o}: ${t[a]}`)}return i.join(`
`)}const ep=new it;function HM(n){vt._getMatrix(ep,vt.workingColorSpace,n);const e=`mat3( ${ep.elements.map(t=>t.toFixed(4))} )`;switch(vt.getTransfer(n)){case vl:return[e,"LinearTransferOETF"];case Lt:return[e,"sRGBTransferOETF"];default:return je("WebGLProgram: Unsupported color space: ",n),[e,"LinearTransferOETF"]}}function tp(n,e,t){const i=n.getShaderParameter(e,n.COMPILE_STATUS),r=(n.getShaderInfoLog(e)||"").trim();if(i&&r==="")return"";const a=/ERROR: 0:(\d+)/.exec(r);if(a){const o=parseInt(a[1]);return t.toUpperCase()+`

`+r+`

`+BM(n.getShaderSource(e),o)}else return r}function VM(n,e){const t=HM(e);return[`vec4 ${n}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}const GM={[Fm]:"Linear",[Um]:"Reinhard",[Om]:"Cineon",[zm]:"ACESFilmic",[Hm]:"AgX",[Vm]:"Neutral",[Bm]:"Custom"};function WM(n,e){const t=GM[e];return t===void 0?(je("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+n+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+n+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}const qo=new z;function qM(){vt.getLuminanceCoefficients(qo);const n=qo.x.toFixed(4),e=qo.y.toFixed(4),t=qo.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${n}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function XM(n){return[n.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",n.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(Na).join(`
`)}function $M(n){const e=[];for(const t in n){const i=n[t];i!==!1&&e.push("#define "+t+" "+i)}return e.join(`
`)}function KM(n,e){const t={},i=n.getProgramParameter(e,n.ACTIVE_ATTRIBUTES);for(let s=0;s<i;s++){const r=n.getActiveAttrib(e,s),a=r.name;let o=1;r.type===n.FLOAT_MAT2&&(o=2),r.type===n.FLOAT_MAT3&&(o=3),r.type===n.FLOAT_MAT4&&(o=4),t[a]={type:r.type,location:n.getAttribLocation(e,a),locationSize:o}}return t}function Na(n){return n!==""}function np(n,e){const t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return n.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function ip(n,e){return n.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}const YM=/^[ \t]*#include +<([\w\d./]+)>/gm;function ed(n){return n.replace(YM,ZM)}function ZM(n,e){const t=ot[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return ed(t)}const jM=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function sp(n){return n.replace(jM,JM)}function JM(n,e,t,i){let s="";for(let r=parseInt(e);r<parseInt(t);r++)s+=i.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function rp(n){let e=`precision ${n.precision} float;
	precision ${n.precision} int;
	precision ${n.precision} sampler2D;
	precision ${n.precision} samplerCube;
	precision ${n.precision} sampler3D;
	precision ${n.precision} sampler2DArray;
	precision ${n.precision} sampler2DShadow;
	precision ${n.precision} samplerCubeShadow;
	precision ${n.precision} sampler2DArrayShadow;
	precision ${n.precision} isampler2D;
	precision ${n.precision} isampler3D;
	precision ${n.precision} isamplerCube;
	precision ${n.precision} isampler2DArray;
	precision ${n.precision} usampler2D;
	precision ${n.precision} usampler3D;
	precision ${n.precision} usamplerCube;
	precision ${n.precision} usampler2DArray;
	`;return n.precision==="highp"?e+=`
#define HIGH_PRECISION`:n.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:n.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}const QM={[tl]:"SHADOWMAP_TYPE_PCF",[Da]:"SHADOWMAP_TYPE_VSM"};function eE(n){return QM[n.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}const tE={[Wa]:"ENVMAP_MODE_REFRACTION"};function nE(n){return n.envMap===!1?"ENVMAP_MODE_REFLECTION":tE[n.envMapMode]||"ENVMAP_MODE_REFLECTION"}const iE={[km]:"ENVMAP_BLENDING_MULTIPLY",[Vx]:"ENVMAP_BLENDING_MIX",[Gx]:"ENVMAP_BLENDING_ADD"};function sE(n){return n.envMap===!1?"ENVMAP_BLENDING_NONE":iE[n.combine]||"ENVMAP_BLENDING_NONE"}function rE(n,e,t,i){const s=n.getContext(),r=t.defines;let a=t.vertexShader,o=t.fragmentShader;const l=eE(t),c=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",u=nE(t),d=sE(t),h=XM(t),m=$M(r),g=s.createProgram();let y,p,f=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(y=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Na).join(`
`),y.length>0&&(y+=`
`),p=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Na).join(`
`),p.length>0&&(p+=`
`)):(y=[rp(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+u:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(Na).join(`
`),p=[rp(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+c:"",t.envMap?"#define "+u:"",t.envMap?"#define "+d:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==gs?"#define TONE_MAPPING":"",t.toneMapping!==gs?ot.tonemapping_pars_fragment:"",t.toneMapping!==gs?WM("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",ot.colorspace_pars_fragment,VM("linearToOutputTexel",t.outputColorSpace),qM(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(Na).join(`
`)),a=ed(a),a=np(a,t),a=ip(a,t),o=ed(o),o=np(o,t),o=ip(o,t),a=sp(a),o=sp(o),t.isRawShaderMaterial!==!0&&(f=`#version 300 es
`,y=[h,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+y,p=["#define varying in",t.glslVersion===lf?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===lf?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+p);const x=f+y+a,R=f+p+o,S=Qf(s,s.VERTEX_SHADER,x),C=Qf(s,s.FRAGMENT_SHADER,R);s.attachShader(g,S),s.attachShader(g,C),t.index0AttributeName!==void 0?s.bindAttribLocation(g,0,t.index0AttributeName):t.hasPositionAttribute===!0&&s.bindAttribLocation(g,0,"position"),s.linkProgram(g);function w(L){if(n.debug.checkShaderErrors){const D=s.getProgramInfoLog(g)||"",B=s.getShaderInfoLog(S)||"",G=s.getShaderInfoLog(C)||"",k=D.trim(),W=B.trim(),Y=G.trim();let V=!0,le=!0;if(s.getProgramParameter(g,s.LINK_STATUS)===!1)if(V=!1,typeof n.debug.onShaderError=="function")n.debug.onShaderError(s,g,S,C);else{const j=tp(s,S,"vertex"),Q=tp(s,C,"fragment");yt("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(g,s.VALIDATE_STATUS)+`

Material Name: `+L.name+`
Material Type: `+L.type+`

Program Info Log: `+k+`
`+j+`
`+Q)}else k!==""?je("WebGLProgram: Program Info Log:",k):(W===""||Y==="")&&(le=!1);le&&(L.diagnostics={runnable:V,programLog:k,vertexShader:{log:W,prefix:y},fragmentShader:{log:Y,prefix:p}})}s.deleteShader(S),s.deleteShader(C),v=new ol(s,g),M=KM(s,g)}let v;this.getUniforms=function(){return v===void 0&&w(this),v};let M;this.getAttributes=function(){return M===void 0&&w(this),M};let F=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return F===!1&&(F=s.getProgramParameter(g,OM)),F},this.destroy=function(){i.releaseStatesOfProgram(this),s.deleteProgram(g),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=zM++,this.cacheKey=e,this.usedTimes=1,this.program=g,this.vertexShader=S,this.fragmentShader=C,this}let aE=0;class oE{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,i){const s=this._getShaderCacheForMaterial(e);return s.has(t)===!1&&(s.add(t),t.usedTimes++),s.has(i)===!1&&(s.add(i),i.usedTimes++),this}remove(e){const t=this.materialCache.get(e);for(const i of t)i.usedTimes--,i.usedTimes===0&&this.shaderCache.delete(i.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){const t=this.materialCache;let i=t.get(e);return i===void 0&&(i=new Set,t.set(e,i)),i}_getShaderStage(e){const t=this.shaderCache;let i=t.get(e);return i===void 0&&(i=new lE(e),t.set(e,i)),i}}class lE{constructor(e){this.id=aE++,this.code=e,this.usedTimes=0}}function cE(n){return n===sr||n===pl||n===ml}function uE(n,e,t,i,s,r){const a=new zd,o=new oE,l=new Set,c=[],u=new Map,d=i.logarithmicDepthBuffer,h={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function m(v){return l.add(v),v===0?"uv":`uv${v}`}function g(v,M,F,L,D,B){const G=L.fog,k=D.geometry,W=v.isMeshStandardMaterial||v.isMeshLambertMaterial||v.isMeshPhongMaterial?L.environment:null,Y=v.isMeshStandardMaterial||v.isMeshLambertMaterial&&!v.envMap||v.isMeshPhongMaterial&&!v.envMap,V=e.get(v.envMap||W,Y),le=h[v.type];let j=i.precision;v.precision!==null&&(j=i.getMaxPrecision(v.precision),j!==v.precision&&je("WebGLProgram.getParameters:",v.precision,"not supported, using",j,"instead."));const Q=k.morphAttributes.position||k.morphAttributes.normal||k.morphAttributes.color,se=Q!==void 0?Q.length:0;let he=0;k.morphAttributes.position!==void 0&&(he=1),k.morphAttributes.normal!==void 0&&(he=2),k.morphAttributes.color!==void 0&&(he=3);let de,ee,me,_e;if(le){const Re=Yi[le];de=Re.vertexShader,ee=Re.fragmentShader}else{de=v.vertexShader,ee=v.fragmentShader;const Re=o.getVertexShaderStage(v),st=o.getFragmentShaderStage(v);o.update(v,Re,st),me=Re.id,_e=st.id}const Te=n.getRenderTarget(),we=n.state.buffers.depth.getReversed(),Ge=D.isInstancedMesh===!0,tt=D.isBatchedMesh===!0,He=!!v.map,ct=!!v.matcap,rt=!!V,Qe=rt&&V.isPMREMTexture===!0,qt=!!v.aoMap,zt=!!v.lightMap,on=!!v.bumpMap&&v.wireframe===!1,Nt=!!v.normalMap,En=!!v.displacementMap,_t=!!v.emissiveMap,mn=!!v.metalnessMap,Kt=!!v.roughnessMap,ln=v.anisotropy>0,O=v.clearcoat>0,Ce=v.diffuseRoughness>0,$e=v.dispersion>0,nt=v.retroreflectivity>0,Se=v.iridescence>0,kt=v.sheen>0,Be=v.transmission>0,Xe=ln&&!!v.anisotropyMap,P=O&&!!v.clearcoatMap,b=O&&!!v.clearcoatNormalMap,X=O&&!!v.clearcoatRoughnessMap,ue=Ce&&!!v.diffuseRoughnessMap,ae=Se&&!!v.iridescenceMap,ve=Se&&!!v.iridescenceThicknessMap,xe=kt&&!!v.sheenColorMap,te=kt&&!!v.sheenRoughnessMap,ie=!!v.specularMap,pe=!!v.specularColorMap,U=!!v.specularIntensityMap,re=Be&&!!v.transmissionMap,ne=Be&&!!v.thicknessMap,Me=!!v.gradientMap,ge=!!v.alphaMap,be=v.alphaTest>0,Ve=!!v.alphaHash,Ye=!!v.extensions;let ce=gs;v.toneMapped&&(Te===null||Te.isXRRenderTarget===!0)&&(ce=n.toneMapping);const Ue=Qe?V.isCompressedCubeTexture?V.image[0].mipmaps:V.mipmaps:null,Ze={shaderID:le,shaderType:v.type,shaderName:v.name,vertexShader:de,fragmentShader:ee,defines:v.defines,customVertexShaderID:me,customFragmentShaderID:_e,isRawShaderMaterial:v.isRawShaderMaterial===!0,glslVersion:v.glslVersion,precision:j,batching:tt,batchingColor:tt&&D._colorsTexture!==null,instancing:Ge,instancingColor:Ge&&D.instanceColor!==null,instancingMorph:Ge&&D.morphTexture!==null,outputColorSpace:Te===null?n.outputColorSpace:Te.isXRRenderTarget===!0?Te.texture.colorSpace:vt.workingColorSpace,alphaToCoverage:!!v.alphaToCoverage,map:He,matcap:ct,envMap:rt,envMapMode:rt&&V.mapping,envMapPMREM:Qe,envMapMaxLod:Qe?Ue.length-1:null,envMapSize:Qe?Ue[0].width:null,aoMap:qt,lightMap:zt,bumpMap:on,normalMap:Nt,displacementMap:En,emissiveMap:_t,normalMapObjectSpace:Nt&&v.normalMapType===Xx,normalMapTangentSpace:Nt&&v.normalMapType===Yu,packedNormalMap:Nt&&v.normalMapType===Yu&&cE(v.normalMap.format),metalnessMap:mn,roughnessMap:Kt,anisotropy:ln,anisotropyMap:Xe,clearcoat:O,clearcoatMap:P,clearcoatNormalMap:b,clearcoatRoughnessMap:X,diffuseRoughness:Ce,diffuseRoughnessMap:ue,dispersion:$e,retroreflection:nt,iridescence:Se,iridescenceMap:ae,iridescenceThicknessMap:ve,sheen:kt,sheenColorMap:xe,sheenRoughnessMap:te,specularMap:ie,specularColorMap:pe,specularIntensityMap:U,transmission:Be,transmissionMap:re,thicknessMap:ne,gradientMap:Me,opaque:v.transparent===!1&&v.blending===Oa&&v.alphaToCoverage===!1,alphaMap:ge,alphaTest:be,alphaHash:Ve,combine:v.combine,mapUv:He&&m(v.map.channel),aoMapUv:qt&&m(v.aoMap.channel),lightMapUv:zt&&m(v.lightMap.channel),bumpMapUv:on&&m(v.bumpMap.channel),normalMapUv:Nt&&m(v.normalMap.channel),displacementMapUv:En&&m(v.displacementMap.channel),emissiveMapUv:_t&&m(v.emissiveMap.channel),metalnessMapUv:mn&&m(v.metalnessMap.channel),roughnessMapUv:Kt&&m(v.roughnessMap.channel),anisotropyMapUv:Xe&&m(v.anisotropyMap.channel),clearcoatMapUv:P&&m(v.clearcoatMap.channel),clearcoatNormalMapUv:b&&m(v.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:X&&m(v.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:ue&&m(v.diffuseRoughnessMap.channel),iridescenceMapUv:ae&&m(v.iridescenceMap.channel),iridescenceThicknessMapUv:ve&&m(v.iridescenceThicknessMap.channel),sheenColorMapUv:xe&&m(v.sheenColorMap.channel),sheenRoughnessMapUv:te&&m(v.sheenRoughnessMap.channel),specularMapUv:ie&&m(v.specularMap.channel),specularColorMapUv:pe&&m(v.specularColorMap.channel),specularIntensityMapUv:U&&m(v.specularIntensityMap.channel),transmissionMapUv:re&&m(v.transmissionMap.channel),thicknessMapUv:ne&&m(v.thicknessMap.channel),alphaMapUv:ge&&m(v.alphaMap.channel),vertexTangents:!!k.attributes.tangent&&(Nt||ln),vertexNormals:!!k.attributes.normal,vertexColors:v.vertexColors,vertexAlphas:v.vertexColors===!0&&!!k.attributes.color&&k.attributes.color.itemSize===4,pointsUvs:D.isPoints===!0&&!!k.attributes.uv&&(He||ge),fog:!!G,useFog:v.fog===!0,fogExp2:!!G&&G.isFogExp2,flatShading:v.wireframe===!1&&(v.flatShading===!0||k.attributes.normal===void 0&&Nt===!1&&(v.isMeshLambertMaterial||v.isMeshPhongMaterial||v.isMeshStandardMaterial||v.isMeshPhysicalMaterial)),sizeAttenuation:v.sizeAttenuation===!0,logarithmicDepthBuffer:d,reversedDepthBuffer:we,skinning:D.isSkinnedMesh===!0,hasPositionAttribute:k.attributes.position!==void 0,morphTargets:k.morphAttributes.position!==void 0,morphNormals:k.morphAttributes.normal!==void 0,morphColors:k.morphAttributes.color!==void 0,morphTargetsCount:se,morphTextureStride:he,numSunLights:M.sun.length,numDirLights:M.directional.length,numPointLights:M.point.length,numSpotLights:M.spot.length,numSpotLightMaps:M.spotLightMap.length,numRectAreaLights:M.rectArea.length,numHemiLights:M.hemi.length,numSunLightShadows:M.sunShadowMap.length,numDirLightShadows:M.directionalShadowMap.length,numPointLightShadows:M.pointShadowMap.length,numSpotLightShadows:M.spotShadowMap.length,numSpotLightShadowsWithMaps:M.numSpotLightShadowsWithMaps,numLightProbes:M.numLightProbes,numLightProbeGrids:B.filter(Re=>Re.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:v.dithering,shadowMapEnabled:n.shadowMap.enabled&&F.length>0,shadowMapType:n.shadowMap.type,toneMapping:ce,decodeVideoTexture:He&&v.map.isVideoTexture===!0&&vt.getTransfer(v.map.colorSpace)===Lt,decodeVideoTextureEmissive:_t&&v.emissiveMap.isVideoTexture===!0&&vt.getTransfer(v.emissiveMap.colorSpace)===Lt,premultipliedAlpha:v.premultipliedAlpha,doubleSided:v.side===_i,flipSided:v.side===Jn,useDepthPacking:v.depthPacking>=0,depthPacking:v.depthPacking||0,index0AttributeName:v.index0AttributeName,extensionClipCullDistance:Ye&&v.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Ye&&v.extensions.multiDraw===!0||tt)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:v.customProgramCacheKey()};return Ze.vertexUv1s=l.has(1),Ze.vertexUv2s=l.has(2),Ze.vertexUv3s=l.has(3),l.clear(),Ze}function y(v){const M=[];if(v.shaderID?M.push(v.shaderID):(M.push(v.customVertexShaderID),M.push(v.customFragmentShaderID)),v.defines!==void 0)for(const F in v.defines)M.push(F),M.push(v.defines[F]);return v.isRawShaderMaterial===!1&&(p(M,v),f(M,v),M.push(n.outputColorSpace)),M.push(v.customProgramCacheKey),M.join()}function p(v,M){v.push(M.precision),v.push(M.outputColorSpace),v.push(M.envMapMode),v.push(M.envMapPMREM),v.push(M.envMapMaxLod),v.push(M.envMapSize),v.push(M.mapUv),v.push(M.alphaMapUv),v.push(M.lightMapUv),v.push(M.aoMapUv),v.push(M.bumpMapUv),v.push(M.normalMapUv),v.push(M.displacementMapUv),v.push(M.emissiveMapUv),v.push(M.metalnessMapUv),v.push(M.roughnessMapUv),v.push(M.anisotropyMapUv),v.push(M.clearcoatMapUv),v.push(M.clearcoatNormalMapUv),v.push(M.clearcoatRoughnessMapUv),v.push(M.diffuseRoughnessMapUv),v.push(M.iridescenceMapUv),v.push(M.iridescenceThicknessMapUv),v.push(M.sheenColorMapUv),v.push(M.sheenRoughnessMapUv),v.push(M.specularMapUv),v.push(M.specularColorMapUv),v.push(M.specularIntensityMapUv),v.push(M.transmissionMapUv),v.push(M.thicknessMapUv),v.push(M.combine),v.push(M.fogExp2),v.push(M.sizeAttenuation),v.push(M.morphTargetsCount),v.push(M.numSunLights),v.push(M.numDirLights),v.push(M.numPointLights),v.push(M.numSpotLights),v.push(M.numSpotLightMaps),v.push(M.numHemiLights),v.push(M.numRectAreaLights),v.push(M.numSunLightShadows),v.push(M.numDirLightShadows),v.push(M.numPointLightShadows),v.push(M.numSpotLightShadows),v.push(M.numSpotLightShadowsWithMaps),v.push(M.numLightProbes),v.push(M.numLightProbeGrids),v.push(M.shadowMapType),v.push(M.toneMapping),v.push(M.numClippingPlanes),v.push(M.numClipIntersection),v.push(M.depthPacking)}function f(v,M){a.disableAll(),M.instancing&&a.enable(0),M.instancingColor&&a.enable(1),M.instancingMorph&&a.enable(2),M.matcap&&a.enable(3),M.envMap&&a.enable(4),M.normalMapObjectSpace&&a.enable(5),M.normalMapTangentSpace&&a.enable(6),M.clearcoat&&a.enable(7),M.iridescence&&a.enable(8),M.alphaTest&&a.enable(9),M.vertexColors&&a.enable(10),M.vertexAlphas&&a.enable(11),M.vertexUv1s&&a.enable(12),M.vertexUv2s&&a.enable(13),M.vertexUv3s&&a.enable(14),M.vertexTangents&&a.enable(15),M.anisotropy&&a.enable(16),M.alphaHash&&a.enable(17),M.batching&&a.enable(18),M.dispersion&&a.enable(19),M.retroreflection&&a.enable(24),M.diffuseRoughness&&a.enable(25),M.batchingColor&&a.enable(20),M.gradientMap&&a.enable(21),M.packedNormalMap&&a.enable(22),M.vertexNormals&&a.enable(23),v.push(a.mask),a.disableAll(),M.fog&&a.enable(0),M.useFog&&a.enable(1),M.flatShading&&a.enable(2),M.logarithmicDepthBuffer&&a.enable(3),M.reversedDepthBuffer&&a.enable(4),M.skinning&&a.enable(5),M.morphTargets&&a.enable(6),M.morphNormals&&a.enable(7),M.morphColors&&a.enable(8),M.premultipliedAlpha&&a.enable(9),M.shadowMapEnabled&&a.enable(10),M.doubleSided&&a.enable(11),M.flipSided&&a.enable(12),M.useDepthPacking&&a.enable(13),M.dithering&&a.enable(14),M.transmission&&a.enable(15),M.sheen&&a.enable(16),M.opaque&&a.enable(17),M.pointsUvs&&a.enable(18),M.decodeVideoTexture&&a.enable(19),M.decodeVideoTextureEmissive&&a.enable(20),M.alphaToCoverage&&a.enable(21),M.numLightProbeGrids>0&&a.enable(22),M.hasPositionAttribute&&a.enable(23),v.push(a.mask)}function x(v){const M=h[v.type];let F;if(M){const L=Yi[M];F=Dy.clone(L.uniforms)}else F=v.uniforms;return F}function R(v,M){let F=u.get(M);return F!==void 0?++F.usedTimes:(F=new rE(n,M,v,s),c.push(F),u.set(M,F)),F}function S(v){if(--v.usedTimes===0){const M=c.indexOf(v);c[M]=c[c.length-1],c.pop(),u.delete(v.cacheKey),v.destroy()}}function C(v){o.remove(v)}function w(){o.dispose()}return{getParameters:g,getProgramCacheKey:y,getUniforms:x,acquireProgram:R,releaseProgram:S,releaseShaderCache:C,programs:c,dispose:w}}function dE(){let n=new WeakMap;function e(a){return n.has(a)}function t(a){let o=n.get(a);return o===void 0&&(o={},n.set(a,o)),o}function i(a){n.delete(a)}function s(a,o,l){n.get(a)[o]=l}function r(){n=new WeakMap}return{has:e,get:t,remove:i,update:s,dispose:r}}function hE(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.material.id!==e.material.id?n.material.id-e.material.id:n.materialVariant!==e.materialVariant?n.materialVariant-e.materialVariant:n.z!==e.z?n.z-e.z:n.id-e.id}function ap(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.z!==e.z?e.z-n.z:n.id-e.id}function op(){const n=[];let e=0;const t=[],i=[],s=[];function r(){e=0,t.length=0,i.length=0,s.length=0}function a(h){let m=0;return h.isInstancedMesh&&(m+=2),h.isSkinnedMesh&&(m+=1),m}function o(h,m,g,y,p,f){let x=n[e];return x===void 0?(x={id:h.id,object:h,geometry:m,material:g,materialVariant:a(h),groupOrder:y,renderOrder:h.renderOrder,z:p,group:f},n[e]=x):(x.id=h.id,x.object=h,x.geometry=m,x.material=g,x.materialVariant=a(h),x.groupOrder=y,x.renderOrder=h.renderOrder,x.z=p,x.group=f),e++,x}function l(h,m,g,y,p,f,x){x.reversedDepth===!0&&(p=-p);const R=o(h,m,g,y,p,f);g.transmission>0?i.push(R):g.transparent===!0?s.push(R):t.push(R)}function c(h,m,g,y,p,f){const x=o(h,m,g,y,p,f);g.transmission>0?i.unshift(x):g.transparent===!0?s.unshift(x):t.unshift(x)}function u(h,m){t.length>1&&t.sort(h||hE),i.length>1&&i.sort(m||ap),s.length>1&&s.sort(m||ap)}function d(){for(let h=e,m=n.length;h<m;h++){const g=n[h];if(g.id===null)break;g.id=null,g.object=null,g.geometry=null,g.material=null,g.group=null}}return{opaque:t,transmissive:i,transparent:s,init:r,push:l,unshift:c,finish:d,sort:u}}function fE(){let n=new WeakMap;function e(i,s){const r=n.get(i);let a;return r===void 0?(a=new op,n.set(i,[a])):s>=r.length?(a=new op,r.push(a)):a=r[s],a}function t(){n=new WeakMap}return{get:e,dispose:t}}function pE(){const n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new z,color:new lt};break;case"SpotLight":t={position:new z,direction:new z,color:new lt,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new z,color:new lt,distance:0,decay:0};break;case"HemisphereLight":t={direction:new z,skyColor:new lt,groundColor:new lt};break;case"RectAreaLight":t={color:new lt,position:new z,halfWidth:new z,halfHeight:new z};break}return n[e.id]=t,t}}}function mE(){const n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new qe};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new qe};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new qe,shadowCameraNear:1,shadowCameraFar:1e3};break}return n[e.id]=t,t}}}let gE=0;function vE(n,e){return(e.castShadow?2:0)-(n.castShadow?2:0)+(e.map?1:0)-(n.map?1:0)}function _E(n){const e=new pE,t=mE(),i={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let c=0;c<9;c++)i.probe.push(new z);const s=new z,r=new Dt,a=new Dt;function o(c){let u=0,d=0,h=0;for(let B=0;B<9;B++)i.probe[B].set(0,0,0);let m=0,g=0,y=0,p=0,f=0,x=0,R=0,S=0,C=0,w=0,v=0,M=0,F=0,L=0;c.sort(vE);for(let B=0,G=c.length;B<G;B++){const k=c[B],W=k.color,Y=k.intensity,V=k.distance;let le=null;if(k.shadow&&k.shadow.map&&(k.shadow.map.texture.format===sr?le=k.shadow.map.texture:le=k.shadow.map.depthTexture||k.shadow.map.texture),k.isAmbientLight)u+=W.r*Y,d+=W.g*Y,h+=W.b*Y;else if(k.isLightProbe){for(let j=0;j<9;j++)i.probe[j].addScaledVector(k.sh.coefficients[j],Y);L++}else if(k.isSunLight){const j=e.get(k);if(j.color.copy(k.color).multiplyScalar(k.intensity),k.castShadow){const Q=k.shadow,se=t.get(k);se.shadowIntensity=Q.intensity,se.shadowBias=Q.bias,se.shadowNormalBias=Q.normalBias,se.shadowRadius=Q.radius,se.shadowMapSize.copy(Q.mapSize).multiply(Q.getFrameExtents()),i.sunShadow[g]=se,i.sunShadowMap[g]=le;const he=Q.getViewportCount();for(let de=0;de<he;de++)i.sunShadowMatrix[y+de]=Q.getMatrix(de),i.sunShadowCascade[y+de]=Q._cascadeData[de];y+=he,g++}i.sun[m]=j,m++}else if(k.isDirectionalLight){const j=e.get(k);if(j.color.copy(k.color).multiplyScalar(k.intensity),k.castShadow){const Q=k.shadow,se=t.get(k);se.shadowIntensity=Q.intensity,se.shadowBias=Q.bias,se.shadowNormalBias=Q.normalBias,se.shadowRadius=Q.radius,se.shadowMapSize=Q.mapSize,i.directionalShadow[p]=se,i.directionalShadowMap[p]=le,i.directionalShadowMatrix[p]=k.shadow.matrix,C++}i.directional[p]=j,p++}else if(k.isSpotLight){const j=e.get(k);j.position.setFromMatrixPosition(k.matrixWorld),j.color.copy(W).multiplyScalar(Y),j.distance=V,j.coneCos=Math.cos(k.angle),j.penumbraCos=Math.cos(k.angle*(1-k.penumbra)),j.decay=k.decay,i.spot[x]=j;const Q=k.shadow;if(k.map&&(i.spotLightMap[M]=k.map,M++,Q.updateMatrices(k),k.castShadow&&F++),i.spotLightMatrix[x]=Q.matrix,k.castShadow){const se=t.get(k);se.shadowIntensity=Q.intensity,se.shadowBias=Q.bias,se.shadowNormalBias=Q.normalBias,se.shadowRadius=Q.radius,se.shadowMapSize=Q.mapSize,i.spotShadow[x]=se,i.spotShadowMap[x]=le,v++}x++}else if(k.isRectAreaLight){const j=e.get(k);j.color.copy(W).multiplyScalar(Y),j.halfWidth.set(k.width*.5,0,0),j.halfHeight.set(0,k.height*.5,0),i.rectArea[R]=j,R++}else if(k.isPointLight){const j=e.get(k);if(j.color.copy(k.color).multiplyScalar(k.intensity),j.distance=k.distance,j.decay=k.decay,k.castShadow){const Q=k.shadow,se=t.get(k);se.shadowIntensity=Q.intensity,se.shadowBias=Q.bias,se.shadowNormalBias=Q.normalBias,se.shadowRadius=Q.radius,se.shadowMapSize=Q.mapSize,se.shadowCameraNear=Q.camera.near,se.shadowCameraFar=Q.camera.far,i.pointShadow[f]=se,i.pointShadowMap[f]=le,i.pointShadowMatrix[f]=k.shadow.matrix,w++}i.point[f]=j,f++}else if(k.isHemisphereLight){const j=e.get(k);j.skyColor.copy(k.color).multiplyScalar(Y),j.groundColor.copy(k.groundColor).multiplyScalar(Y),i.hemi[S]=j,S++}}R>0&&(n.has("OES_texture_float_linear")===!0?(i.rectAreaLTC1=De.LTC_FLOAT_1,i.rectAreaLTC2=De.LTC_FLOAT_2):(i.rectAreaLTC1=De.LTC_HALF_1,i.rectAreaLTC2=De.LTC_HALF_2)),i.ambient[0]=u,i.ambient[1]=d,i.ambient[2]=h;const D=i.hash;(D.sunLength!==m||D.directionalLength!==p||D.pointLength!==f||D.spotLength!==x||D.rectAreaLength!==R||D.hemiLength!==S||D.numSunShadows!==g||D.numDirectionalShadows!==C||D.numPointShadows!==w||D.numSpotShadows!==v||D.numSpotMaps!==M||D.numLightProbes!==L)&&(i.sun.length=m,i.directional.length=p,i.spot.length=x,i.rectArea.length=R,i.point.length=f,i.hemi.length=S,i.sunShadow.length=g,i.sunShadowMap.length=g,i.sunShadowMatrix.length=y,i.sunShadowCascade.length=y,i.directionalShadow.length=C,i.directionalShadowMap.length=C,i.directionalShadowMatrix.length=C,i.pointShadow.length=w,i.pointShadowMap.length=w,i.pointShadowMatrix.length=w,i.spotShadow.length=v,i.spotShadowMap.length=v,i.spotLightMatrix.length=v+M-F,i.spotLightMap.length=M,i.numSpotLightShadowsWithMaps=F,i.numLightProbes=L,D.sunLength=m,D.directionalLength=p,D.pointLength=f,D.spotLength=x,D.rectAreaLength=R,D.hemiLength=S,D.numSunShadows=g,D.numDirectionalShadows=C,D.numPointShadows=w,D.numSpotShadows=v,D.numSpotMaps=M,D.numLightProbes=L,i.version=gE++)}function l(c,u){let d=0,h=0,m=0,g=0,y=0,p=0;const f=u.matrixWorldInverse;for(let x=0,R=c.length;x<R;x++){const S=c[x];if(S.isSunLight){const C=i.sun[d];C.direction.setFromMatrixPosition(S.matrixWorld),C.direction.transformDirection(f),d++}else if(S.isDirectionalLight){const C=i.directional[h];C.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(f),h++}else if(S.isSpotLight){const C=i.spot[g];C.position.setFromMatrixPosition(S.matrixWorld),C.position.applyMatrix4(f),C.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(f),g++}else if(S.isRectAreaLight){const C=i.rectArea[y];C.position.setFromMatrixPosition(S.matrixWorld),C.position.applyMatrix4(f),a.identity(),r.copy(S.matrixWorld),r.premultiply(f),a.extractRotation(r),C.halfWidth.set(S.width*.5,0,0),C.halfHeight.set(0,S.height*.5,0),C.halfWidth.applyMatrix4(a),C.halfHeight.applyMatrix4(a),y++}else if(S.isPointLight){const C=i.point[m];C.position.setFromMatrixPosition(S.matrixWorld),C.position.applyMatrix4(f),m++}else if(S.isHemisphereLight){const C=i.hemi[p];C.direction.setFromMatrixPosition(S.matrixWorld),C.direction.transformDirection(f),p++}}}return{setup:o,setupView:l,state:i}}function lp(n){const e=new _E(n),t=[],i=[],s=[];function r(d){u.camera=d,t.length=0,i.length=0,s.length=0}function a(d){d.isLightProbeGrid?s.push(d):t.push(d)}function o(d){i.push(d)}function l(){e.setup(t),s.sort((d,h)=>d.priority-h.priority||d.id-h.id)}function c(d){e.setupView(t,d)}const u={lightsArray:t,shadowsArray:i,lightProbeGridArray:s,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:u,setupLights:l,setupLightsView:c,pushLight:a,pushShadow:o}}function xE(n){let e=new WeakMap;function t(s,r=0){const a=e.get(s);let o;return a===void 0?(o=new lp(n),e.set(s,[o])):r>=a.length?(o=new lp(n),a.push(o)):o=a[r],o}function i(){e=new WeakMap}return{get:t,dispose:i}}const yE=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,bE=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,wE=[new z(1,0,0),new z(-1,0,0),new z(0,1,0),new z(0,-1,0),new z(0,0,1),new z(0,0,-1)],SE=[new z(0,-1,0),new z(0,-1,0),new z(0,0,1),new z(0,0,-1),new z(0,-1,0),new z(0,-1,0)],cp=new Dt,Ta=new z,Oc=new z;function ME(n,e,t){let i=new $a;const s=new qe,r=new qe,a=new rn,o=new Fy,l=new Uy,c={},u=t.maxTextureSize,d={[Os]:Jn,[Jn]:Os,[_i]:_i},h=new rr({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new qe},radius:{value:4}},vertexShader:yE,fragmentShader:bE}),m=h.clone();m.defines.HORIZONTAL_PASS=1;const g=new Ot;g.setAttribute("position",new li(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));const y=new en(g,h),p=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=tl;let f=this.type;this.render=function(w,v,M){if(p.enabled===!1||p.autoUpdate===!1&&p.needsUpdate===!1||w.length===0)return;this.type===Sx&&(je("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=tl);const F=n.getRenderTarget(),L=n.getActiveCubeFace(),D=n.getActiveMipmapLevel(),B=n.state;B.setBlending(qr),B.buffers.depth.getReversed()===!0?B.buffers.color.setClear(0,0,0,0):B.buffers.color.setClear(1,1,1,1),B.buffers.depth.setTest(!0),B.setScissorTest(!1);const G=f!==this.type;G&&v.traverse(function(k){k.material&&(Array.isArray(k.material)?k.material.forEach(W=>W.needsUpdate=!0):k.material.needsUpdate=!0)});for(let k=0,W=w.length;k<W;k++){const Y=w[k],V=Y.shadow;if(V===void 0){je("WebGLShadowMap:",Y,"has no shadow.");continue}if(V.autoUpdate===!1&&V.needsUpdate===!1)continue;s.copy(V.mapSize);const le=V.getFrameExtents();s.multiply(le),r.copy(V.mapSize),(s.x>u||s.y>u)&&(s.x>u&&(r.x=Math.floor(u/le.x),s.x=r.x*le.x,V.mapSize.x=r.x),s.y>u&&(r.y=Math.floor(u/le.y),s.y=r.y*le.y,V.mapSize.y=r.y));const j=n.state.buffers.depth.getReversed();if(V.camera._reversedDepth=j,V.map===null||G===!0){if(V.map!==null&&(V.map.depthTexture!==null&&(V.map.depthTexture.dispose(),V.map.depthTexture=null),V.map.dispose()),this.type===Da){if(Y.isPointLight){je("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}V.map=new Ji(s.x,s.y,{format:sr,type:ts,minFilter:jn,magFilter:jn,generateMipmaps:!1}),V.map.texture.name=Y.name+".shadowMap",V.map.depthTexture=new ea(s.x,s.y,Zi),V.map.depthTexture.name=Y.name+".shadowMapDepth",V.map.depthTexture.format=zs,V.map.depthTexture.compareFunction=null,V.map.depthTexture.minFilter=Nn,V.map.depthTexture.magFilter=Nn}else Y.isPointLight?(V.map=new Vd(s.x),V.map.depthTexture=new fg(s.x,es)):(V.map=new Ji(s.x,s.y),V.map.depthTexture=new ea(s.x,s.y,es)),V.map.depthTexture.name=Y.name+".shadowMap",V.map.depthTexture.format=zs,this.type===tl?(V.map.depthTexture.compareFunction=j?Jm:jm,V.map.depthTexture.minFilter=jn,V.map.depthTexture.magFilter=jn):(V.map.depthTexture.compareFunction=null,V.map.depthTexture.minFilter=Nn,V.map.depthTexture.magFilter=Nn);V.camera.updateProjectionMatrix()}V.map.isWebGLCubeRenderTarget!==!0&&(V.map.width!==s.x||V.map.height!==s.y)&&V.map.setSize(s.x,s.y);const Q=V.map.isWebGLCubeRenderTarget?6:V.getViewportCount();Y.isPointLight!==!0&&V.updateMatrices(Y,M);const se=(V.camera.layers.mask&4294967294)!==0?V.camera.layers:M.layers;for(let he=0;he<Q;he++){const de=V.getCamera(he);if(Y.isPointLight){const ee=V.camera,me=V.matrix,_e=Y.distance||ee.far;_e!==ee.far&&(ee.far=_e,ee.updateProjectionMatrix()),Ta.setFromMatrixPosition(Y.matrixWorld),ee.position.copy(Ta),Oc.copy(ee.position),Oc.add(wE[he]),ee.up.copy(SE[he]),ee.lookAt(Oc),ee.updateMatrixWorld(),me.makeTranslation(-Ta.x,-Ta.y,-Ta.z),cp.multiplyMatrices(ee.projectionMatrix,ee.matrixWorldInverse),V._frustum.setFromProjectionMatrix(cp,ee.coordinateSystem,ee.reversedDepth)}if(V.map.isWebGLCubeRenderTarget)n.setRenderTarget(V.map,he),n.clear();else{he===0&&(n.setRenderTarget(V.map),n.clear());const ee=V.getViewport(he);a.set(r.x*ee.x,r.y*ee.y,r.x*ee.z,r.y*ee.w),B.viewport(a)}i=V.getFrustum(he),S(v,M,de,Y,se,this.type)}V.isPointLightShadow!==!0&&this.type===Da&&x(V,M),V.needsUpdate=!1}f=this.type,p.needsUpdate=!1,n.setRenderTarget(F,L,D)};function x(w,v){const M=e.update(y);h.defines.VSM_SAMPLES!==w.blurSamples&&(h.defines.VSM_SAMPLES=w.blurSamples,m.defines.VSM_SAMPLES=w.blurSamples,h.needsUpdate=!0,m.needsUpdate=!0),w.mapPass===null?w.mapPass=new Ji(s.x,s.y,{format:sr,type:ts}):(w.mapPass.width!==w.map.width||w.mapPass.height!==w.map.height)&&w.mapPass.setSize(w.map.width,w.map.height),h.uniforms.shadow_pass.value=w.map.depthTexture,h.uniforms.resolution.value.set(w.map.width,w.map.height),h.uniforms.radius.value=w.radius,n.setRenderTarget(w.mapPass),n.clear(),n.renderBufferDirect(v,null,M,h,y,null),m.uniforms.shadow_pass.value=w.mapPass.texture,m.uniforms.resolution.value.set(w.map.width,w.map.height),m.uniforms.radius.value=w.radius,n.setRenderTarget(w.map),n.clear(),n.renderBufferDirect(v,null,M,m,y,null)}function R(w,v,M,F){let L=null;const D=M.isPointLight===!0?w.customDistanceMaterial:w.customDepthMaterial;if(D!==void 0)L=D;else if(L=M.isPointLight===!0?l:o,n.localClippingEnabled&&v.clipShadows===!0&&Array.isArray(v.clippingPlanes)&&v.clippingPlanes.length!==0||v.displacementMap&&v.displacementScale!==0||v.alphaMap&&v.alphaTest>0||v.map&&v.alphaTest>0||v.alphaToCoverage===!0){const B=L.uuid,G=v.uuid;let k=c[B];k===void 0&&(k={},c[B]=k);let W=k[G];W===void 0&&(W=L.clone(),k[G]=W,v.addEventListener("dispose",C)),L=W}if(L.visible=v.visible,L.wireframe=v.wireframe,F===Da?L.side=v.shadowSide!==null?v.shadowSide:v.side:L.side=v.shadowSide!==null?v.shadowSide:d[v.side],L.alphaMap=v.alphaMap,L.alphaTest=v.alphaToCoverage===!0?.5:v.alphaTest,L.map=v.map,L.clipShadows=v.clipShadows,L.clippingPlanes=v.clippingPlanes,L.clipIntersection=v.clipIntersection,L.displacementMap=v.displacementMap,L.displacementScale=v.displacementScale,L.displacementBias=v.displacementBias,L.wireframeLinewidth=v.wireframeLinewidth,L.linewidth=v.linewidth,M.isPointLight===!0&&L.isMeshDistanceMaterial===!0){const B=n.properties.get(L);B.light=M}return L}function S(w,v,M,F,L,D){if(w.visible===!1)return;if(w.layers.test(L)&&(w.isMesh||w.isLine||w.isPoints)&&(w.castShadow||w.receiveShadow&&D===Da)&&(!w.frustumCulled||w.intersectsFrustum(i))){w.modelViewMatrix.multiplyMatrices(M.matrixWorldInverse,w.matrixWorld);const k=e.update(w),W=w.material;if(Array.isArray(W)){const Y=k.groups;for(let V=0,le=Y.length;V<le;V++){const j=Y[V],Q=W[j.materialIndex];if(Q&&Q.visible){const se=R(w,Q,F,D);w.onBeforeShadow(n,w,v,M,k,se,j),n.renderBufferDirect(M,null,k,se,w,j),w.onAfterShadow(n,w,v,M,k,se,j)}}}else if(W.visible){const Y=R(w,W,F,D);w.onBeforeShadow(n,w,v,M,k,Y,null),n.renderBufferDirect(M,null,k,Y,w,null),w.onAfterShadow(n,w,v,M,k,Y,null)}}const G=w.children;for(let k=0,W=G.length;k<W;k++)S(G[k],v,M,F,L,D)}function C(w){w.target.removeEventListener("dispose",C);for(const M in c){const F=c[M],L=w.target.uuid;L in F&&(F[L].dispose(),delete F[L])}}}function EE(n,e){function t(){let U=!1;const re=new rn;let ne=null;const Me=new rn(0,0,0,0);return{setMask:function(ge){ne!==ge&&!U&&(n.colorMask(ge,ge,ge,ge),ne=ge)},setLocked:function(ge){U=ge},setClear:function(ge,be,Ve,Ye,ce){ce===!0&&(ge*=Ye,be*=Ye,Ve*=Ye),re.set(ge,be,Ve,Ye),Me.equals(re)===!1&&(n.clearColor(ge,be,Ve,Ye),Me.copy(re))},reset:function(){U=!1,ne=null,Me.set(-1,0,0,0)}}}function i(){let U=!1,re=!1,ne=null,Me=null,ge=null;return{setReversed:function(be){if(re!==be){const Ve=e.get("EXT_clip_control");be?Ve.clipControlEXT(Ve.LOWER_LEFT_EXT,Ve.ZERO_TO_ONE_EXT):Ve.clipControlEXT(Ve.LOWER_LEFT_EXT,Ve.NEGATIVE_ONE_TO_ONE_EXT),re=be;const Ye=ge;ge=null,this.setClear(Ye)}},getReversed:function(){return re},setTest:function(be){be?we(n.DEPTH_TEST):Ge(n.DEPTH_TEST)},setMask:function(be){ne!==be&&!U&&(n.depthMask(be),ne=be)},setFunc:function(be){if(re&&(be=ny[be]),Me!==be){switch(be){case uu:n.depthFunc(n.NEVER);break;case du:n.depthFunc(n.ALWAYS);break;case hu:n.depthFunc(n.LESS);break;case Ga:n.depthFunc(n.LEQUAL);break;case fu:n.depthFunc(n.EQUAL);break;case pu:n.depthFunc(n.GEQUAL);break;case mu:n.depthFunc(n.GREATER);break;case gu:n.depthFunc(n.NOTEQUAL);break;default:n.depthFunc(n.LEQUAL)}Me=be}},setLocked:function(be){U=be},setClear:function(be){ge!==be&&(ge=be,re&&(be=1-be),n.clearDepth(be))},reset:function(){U=!1,ne=null,Me=null,ge=null,re=!1}}}function s(){let U=!1,re=null,ne=null,Me=null,ge=null,be=null,Ve=null,Ye=null,ce=null;return{setTest:function(Ue){U||(Ue?we(n.STENCIL_TEST):Ge(n.STENCIL_TEST))},setMask:function(Ue){re!==Ue&&!U&&(n.stencilMask(Ue),re=Ue)},setFunc:function(Ue,Ze,Re){(ne!==Ue||Me!==Ze||ge!==Re)&&(n.stencilFunc(Ue,Ze,Re),ne=Ue,Me=Ze,ge=Re)},setOp:function(Ue,Ze,Re){(be!==Ue||Ve!==Ze||Ye!==Re)&&(n.stencilOp(Ue,Ze,Re),be=Ue,Ve=Ze,Ye=Re)},setLocked:function(Ue){U=Ue},setClear:function(Ue){ce!==Ue&&(n.clearStencil(Ue),ce=Ue)},reset:function(){U=!1,re=null,ne=null,Me=null,ge=null,be=null,Ve=null,Ye=null,ce=null}}}const r=new t,a=new i,o=new s;let l={};const c=new WeakMap;let u={},d={},h={},m=new WeakMap,g=[],y=null,p=!1,f=null,x=null,R=null,S=null,C=null,w=null,v=null,M=new lt(0,0,0),F=0,L=!1,D=null,B=null,G=null,k=null,W=null;const Y=n.getParameter(n.MAX_COMBINED_TEXTURE_IMAGE_UNITS);let V=!1,le=0;const j=n.getParameter(n.VERSION);j.indexOf("WebGL")!==-1?(le=parseFloat(/^WebGL (\d)/.exec(j)[1]),V=le>=1):j.indexOf("OpenGL ES")!==-1&&(le=parseFloat(/^OpenGL ES (\d)/.exec(j)[1]),V=le>=2);let Q=null,se={};const he=n.getParameter(n.SCISSOR_BOX),de=n.getParameter(n.VIEWPORT),ee=new rn().fromArray(he),me=new rn().fromArray(de);function _e(U,re,ne,Me){const ge=new Uint8Array(4),be=n.createTexture();n.bindTexture(U,be),n.texParameteri(U,n.TEXTURE_MIN_FILTER,n.NEAREST),n.texParameteri(U,n.TEXTURE_MAG_FILTER,n.NEAREST);for(let Ve=0;Ve<ne;Ve++)U===n.TEXTURE_3D||U===n.TEXTURE_2D_ARRAY?n.texImage3D(re,0,n.RGBA,1,1,Me,0,n.RGBA,n.UNSIGNED_BYTE,ge):n.texImage2D(re+Ve,0,n.RGBA,1,1,0,n.RGBA,n.UNSIGNED_BYTE,ge);return be}const Te={};Te[n.TEXTURE_2D]=_e(n.TEXTURE_2D,n.TEXTURE_2D,1),Te[n.TEXTURE_CUBE_MAP]=_e(n.TEXTURE_CUBE_MAP,n.TEXTURE_CUBE_MAP_POSITIVE_X,6),Te[n.TEXTURE_2D_ARRAY]=_e(n.TEXTURE_2D_ARRAY,n.TEXTURE_2D_ARRAY,1,1),Te[n.TEXTURE_3D]=_e(n.TEXTURE_3D,n.TEXTURE_3D,1,1),r.setClear(0,0,0,1),a.setClear(1),o.setClear(0),we(n.DEPTH_TEST),a.setFunc(Ga),on(!1),Nt(sf),we(n.CULL_FACE),qt(qr);function we(U){u[U]!==!0&&(n.enable(U),u[U]=!0)}function Ge(U){u[U]!==!1&&(n.disable(U),u[U]=!1)}function tt(U,re){return h[U]!==re?(n.bindFramebuffer(U,re),h[U]=re,U===n.DRAW_FRAMEBUFFER&&(h[n.FRAMEBUFFER]=re),U===n.FRAMEBUFFER&&(h[n.DRAW_FRAMEBUFFER]=re),!0):!1}function He(U,re){let ne=g,Me=!1;if(U){ne=m.get(re),ne===void 0&&(ne=[],m.set(re,ne));const ge=U.textures;if(ne.length!==ge.length||ne[0]!==n.COLOR_ATTACHMENT0){for(let be=0,Ve=ge.length;be<Ve;be++)ne[be]=n.COLOR_ATTACHMENT0+be;ne.length=ge.length,Me=!0}}else ne[0]!==n.BACK&&(ne[0]=n.BACK,Me=!0);Me&&n.drawBuffers(ne)}function ct(U){return y!==U?(n.useProgram(U),y=U,!0):!1}const rt={[Br]:n.FUNC_ADD,[Ex]:n.FUNC_SUBTRACT,[Ax]:n.FUNC_REVERSE_SUBTRACT};rt[Tx]=n.MIN,rt[Rx]=n.MAX;const Qe={[Cx]:n.ZERO,[Px]:n.ONE,[Lx]:n.SRC_COLOR,[Nm]:n.SRC_ALPHA,[Ux]:n.SRC_ALPHA_SATURATE,[kx]:n.DST_COLOR,[Nx]:n.DST_ALPHA,[Dx]:n.ONE_MINUS_SRC_COLOR,[Im]:n.ONE_MINUS_SRC_ALPHA,[Fx]:n.ONE_MINUS_DST_COLOR,[Ix]:n.ONE_MINUS_DST_ALPHA,[Ox]:n.CONSTANT_COLOR,[zx]:n.ONE_MINUS_CONSTANT_COLOR,[Bx]:n.CONSTANT_ALPHA,[Hx]:n.ONE_MINUS_CONSTANT_ALPHA};function qt(U,re,ne,Me,ge,be,Ve,Ye,ce,Ue){if(U===qr){p===!0&&(Ge(n.BLEND),p=!1);return}if(p===!1&&(we(n.BLEND),p=!0),U!==Mx){if(U!==f||Ue!==L){if((x!==Br||C!==Br)&&(n.blendEquation(n.FUNC_ADD),x=Br,C=Br),Ue)switch(U){case Oa:n.blendFuncSeparate(n.ONE,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case rf:n.blendFunc(n.ONE,n.ONE);break;case af:n.blendFuncSeparate(n.ZERO,n.ONE_MINUS_SRC_COLOR,n.ZERO,n.ONE);break;case of:n.blendFuncSeparate(n.DST_COLOR,n.ONE_MINUS_SRC_ALPHA,n.ZERO,n.ONE);break;default:yt("WebGLState: Invalid blending: ",U);break}else switch(U){case Oa:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case rf:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE,n.ONE,n.ONE);break;case af:yt("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case of:yt("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:yt("WebGLState: Invalid blending: ",U);break}R=null,S=null,w=null,v=null,M.set(0,0,0),F=0,f=U,L=Ue}return}ge=ge||re,be=be||ne,Ve=Ve||Me,(re!==x||ge!==C)&&(n.blendEquationSeparate(rt[re],rt[ge]),x=re,C=ge),(ne!==R||Me!==S||be!==w||Ve!==v)&&(n.blendFuncSeparate(Qe[ne],Qe[Me],Qe[be],Qe[Ve]),R=ne,S=Me,w=be,v=Ve),(Ye.equals(M)===!1||ce!==F)&&(n.blendColor(Ye.r,Ye.g,Ye.b,ce),M.copy(Ye),F=ce),f=U,L=!1}function zt(U,re){U.side===_i?Ge(n.CULL_FACE):we(n.CULL_FACE);let ne=U.side===Jn;re&&(ne=!ne),on(ne),U.blending===Oa&&U.transparent===!1?qt(qr):qt(U.blending,U.blendEquation,U.blendSrc,U.blendDst,U.blendEquationAlpha,U.blendSrcAlpha,U.blendDstAlpha,U.blendColor,U.blendAlpha,U.premultipliedAlpha),a.setFunc(U.depthFunc),a.setTest(U.depthTest),a.setMask(U.depthWrite),r.setMask(U.colorWrite);const Me=U.stencilWrite;o.setTest(Me),Me&&(o.setMask(U.stencilWriteMask),o.setFunc(U.stencilFunc,U.stencilRef,U.stencilFuncMask),o.setOp(U.stencilFail,U.stencilZFail,U.stencilZPass)),_t(U.polygonOffset,U.polygonOffsetFactor,U.polygonOffsetUnits),U.alphaToCoverage===!0?we(n.SAMPLE_ALPHA_TO_COVERAGE):Ge(n.SAMPLE_ALPHA_TO_COVERAGE)}function on(U){D!==U&&(U?n.frontFace(n.CW):n.frontFace(n.CCW),D=U)}function Nt(U){U!==bx?(we(n.CULL_FACE),U!==B&&(U===sf?n.cullFace(n.BACK):U===wx?n.cullFace(n.FRONT):n.cullFace(n.FRONT_AND_BACK))):Ge(n.CULL_FACE),B=U}function En(U){U!==G&&(V&&n.lineWidth(U),G=U)}function _t(U,re,ne){U?(we(n.POLYGON_OFFSET_FILL),(k!==re||W!==ne)&&(k=re,W=ne,a.getReversed()&&(re=-re,ne=-ne),n.polygonOffset(re,ne))):Ge(n.POLYGON_OFFSET_FILL)}function mn(U){U?we(n.SCISSOR_TEST):Ge(n.SCISSOR_TEST)}function Kt(U){U===void 0&&(U=n.TEXTURE0+Y-1),Q!==U&&(n.activeTexture(U),Q=U)}function ln(U,re,ne){ne===void 0&&(Q===null?ne=n.TEXTURE0+Y-1:ne=Q);let Me=se[ne];Me===void 0&&(Me={type:void 0,texture:void 0},se[ne]=Me),(Me.type!==U||Me.texture!==re)&&(Q!==ne&&(n.activeTexture(ne),Q=ne),n.bindTexture(U,re||Te[U]),Me.type=U,Me.texture=re)}function O(){const U=se[Q];U!==void 0&&U.type!==void 0&&(n.bindTexture(U.type,null),U.type=void 0,U.texture=void 0)}function Ce(){try{n.compressedTexImage2D(...arguments)}catch(U){yt("WebGLState:",U)}}function $e(){try{n.compressedTexImage3D(...arguments)}catch(U){yt("WebGLState:",U)}}function nt(){try{n.texSubImage2D(...arguments)}catch(U){yt("WebGLState:",U)}}function Se(){try{n.texSubImage3D(...arguments)}catch(U){yt("WebGLState:",U)}}function kt(){try{n.compressedTexSubImage2D(...arguments)}catch(U){yt("WebGLState:",U)}}function Be(){try{n.compressedTexSubImage3D(...arguments)}catch(U){yt("WebGLState:",U)}}function Xe(){try{n.texStorage2D(...arguments)}catch(U){yt("WebGLState:",U)}}function P(){try{n.texStorage3D(...arguments)}catch(U){yt("WebGLState:",U)}}function b(){try{n.texImage2D(...arguments)}catch(U){yt("WebGLState:",U)}}function X(){try{n.texImage3D(...arguments)}catch(U){yt("WebGLState:",U)}}function ue(U){return d[U]!==void 0?d[U]:n.getParameter(U)}function ae(U,re){d[U]!==re&&(n.pixelStorei(U,re),d[U]=re)}function ve(U){ee.equals(U)===!1&&(n.scissor(U.x,U.y,U.z,U.w),ee.copy(U))}function xe(U){me.equals(U)===!1&&(n.viewport(U.x,U.y,U.z,U.w),me.copy(U))}function te(U,re){let ne=c.get(re);ne===void 0&&(ne=new WeakMap,c.set(re,ne));let Me=ne.get(U);Me===void 0&&(Me=n.getUniformBlockIndex(re,U.name),n.uniformBlockBinding(re,Me,Me),ne.set(U,Me))}function ie(U,re,ne){const ge=c.get(re).get(U);l[ge]!==ne&&(n.bindBufferBase(n.UNIFORM_BUFFER,ge,ne),l[ge]=ne)}function pe(){n.disable(n.BLEND),n.disable(n.CULL_FACE),n.disable(n.DEPTH_TEST),n.disable(n.POLYGON_OFFSET_FILL),n.disable(n.SCISSOR_TEST),n.disable(n.STENCIL_TEST),n.disable(n.SAMPLE_ALPHA_TO_COVERAGE),n.blendEquation(n.FUNC_ADD),n.blendFunc(n.ONE,n.ZERO),n.blendFuncSeparate(n.ONE,n.ZERO,n.ONE,n.ZERO),n.blendColor(0,0,0,0),n.colorMask(!0,!0,!0,!0),n.clearColor(0,0,0,0),n.depthMask(!0),n.depthFunc(n.LESS),a.setReversed(!1),n.clearDepth(1),n.stencilMask(4294967295),n.stencilFunc(n.ALWAYS,0,4294967295),n.stencilOp(n.KEEP,n.KEEP,n.KEEP),n.clearStencil(0),n.cullFace(n.BACK),n.frontFace(n.CCW),n.polygonOffset(0,0),n.activeTexture(n.TEXTURE0),n.bindFramebuffer(n.FRAMEBUFFER,null),n.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),n.bindFramebuffer(n.READ_FRAMEBUFFER,null),n.useProgram(null),n.lineWidth(1),n.scissor(0,0,n.canvas.width,n.canvas.height),n.viewport(0,0,n.canvas.width,n.canvas.height),n.pixelStorei(n.PACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,!1),n.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),n.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,n.BROWSER_DEFAULT_WEBGL),n.pixelStorei(n.PACK_ROW_LENGTH,0),n.pixelStorei(n.PACK_SKIP_PIXELS,0),n.pixelStorei(n.PACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_ROW_LENGTH,0),n.pixelStorei(n.UNPACK_IMAGE_HEIGHT,0),n.pixelStorei(n.UNPACK_SKIP_PIXELS,0),n.pixelStorei(n.UNPACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_SKIP_IMAGES,0),u={},d={},Q=null,se={},h={},l={},m=new WeakMap,g=[],y=null,p=!1,f=null,x=null,R=null,S=null,C=null,w=null,v=null,M=new lt(0,0,0),F=0,L=!1,D=null,B=null,G=null,k=null,W=null,ee.set(0,0,n.canvas.width,n.canvas.height),me.set(0,0,n.canvas.width,n.canvas.height),r.reset(),a.reset(),o.reset()}return{buffers:{color:r,depth:a,stencil:o},enable:we,disable:Ge,bindFramebuffer:tt,drawBuffers:He,useProgram:ct,setBlending:qt,setMaterial:zt,setFlipSided:on,setCullFace:Nt,setLineWidth:En,setPolygonOffset:_t,setScissorTest:mn,activeTexture:Kt,bindTexture:ln,unbindTexture:O,compressedTexImage2D:Ce,compressedTexImage3D:$e,texImage2D:b,texImage3D:X,pixelStorei:ae,getParameter:ue,updateUBOMapping:te,uniformBlockBinding:ie,texStorage2D:Xe,texStorage3D:P,texSubImage2D:nt,texSubImage3D:Se,compressedTexSubImage2D:kt,compressedTexSubImage3D:Be,scissor:ve,viewport:xe,reset:pe}}function AE(n,e,t,i,s,r,a){const o=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),c=new qe,u=new WeakMap,d=new Set;let h;const m=new WeakMap,g=new Set,y=new FinalizationRegistry(P=>g.delete(P));let p=!1;try{p=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function f(P,b){return p?new OffscreenCanvas(P,b):_l("canvas")}function x(P,b,X){let ue=1;const ae=Xe(P);if((ae.width>X||ae.height>X)&&(ue=X/Math.max(ae.width,ae.height)),ue<1)if(typeof HTMLImageElement<"u"&&P instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&P instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&P instanceof ImageBitmap||typeof VideoFrame<"u"&&P instanceof VideoFrame){const ve=Math.floor(ue*ae.width),xe=Math.floor(ue*ae.height);h===void 0&&(h=f(ve,xe));const te=b?f(ve,xe):h;return te.width=ve,te.height=xe,te.getContext("2d").drawImage(P,0,0,ve,xe),je("WebGLRenderer: Texture has been resized from ("+ae.width+"x"+ae.height+") to ("+ve+"x"+xe+")."),te}else return"data"in P&&je("WebGLRenderer: Image in DataTexture is too big ("+ae.width+"x"+ae.height+")."),P;return P}function R(P){return P.generateMipmaps}function S(P){n.generateMipmap(P)}function C(P){return P.isWebGLCubeRenderTarget?n.TEXTURE_CUBE_MAP:P.isWebGL3DRenderTarget?n.TEXTURE_3D:P.isWebGLArrayRenderTarget||P.isCompressedArrayTexture?n.TEXTURE_2D_ARRAY:n.TEXTURE_2D}function w(P,b,X,ue,ae,ve=!1){if(P!==null){if(n[P]!==void 0)return n[P];je("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+P+"'")}let xe;ue&&(xe=e.get("EXT_texture_norm16"),xe||je("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let te=b;if(b===n.RED&&(X===n.FLOAT&&(te=n.R32F),X===n.HALF_FLOAT&&(te=n.R16F),X===n.UNSIGNED_BYTE&&(te=n.R8),X===n.UNSIGNED_SHORT&&xe&&(te=xe.R16_EXT),X===n.SHORT&&xe&&(te=xe.R16_SNORM_EXT)),b===n.RED_INTEGER&&(X===n.UNSIGNED_BYTE&&(te=n.R8UI),X===n.UNSIGNED_SHORT&&(te=n.R16UI),X===n.UNSIGNED_INT&&(te=n.R32UI),X===n.BYTE&&(te=n.R8I),X===n.SHORT&&(te=n.R16I),X===n.INT&&(te=n.R32I)),b===n.RG&&(X===n.FLOAT&&(te=n.RG32F),X===n.HALF_FLOAT&&(te=n.RG16F),X===n.UNSIGNED_BYTE&&(te=n.RG8),X===n.UNSIGNED_SHORT&&xe&&(te=xe.RG16_EXT),X===n.SHORT&&xe&&(te=xe.RG16_SNORM_EXT)),b===n.RG_INTEGER&&(X===n.UNSIGNED_BYTE&&(te=n.RG8UI),X===n.UNSIGNED_SHORT&&(te=n.RG16UI),X===n.UNSIGNED_INT&&(te=n.RG32UI),X===n.BYTE&&(te=n.RG8I),X===n.SHORT&&(te=n.RG16I),X===n.INT&&(te=n.RG32I)),b===n.RGB_INTEGER&&(X===n.UNSIGNED_BYTE&&(te=n.RGB8UI),X===n.UNSIGNED_SHORT&&(te=n.RGB16UI),X===n.UNSIGNED_INT&&(te=n.RGB32UI),X===n.BYTE&&(te=n.RGB8I),X===n.SHORT&&(te=n.RGB16I),X===n.INT&&(te=n.RGB32I)),b===n.RGBA_INTEGER&&(X===n.UNSIGNED_BYTE&&(te=n.RGBA8UI),X===n.UNSIGNED_SHORT&&(te=n.RGBA16UI),X===n.UNSIGNED_INT&&(te=n.RGBA32UI),X===n.BYTE&&(te=n.RGBA8I),X===n.SHORT&&(te=n.RGBA16I),X===n.INT&&(te=n.RGBA32I)),b===n.RGB&&(X===n.UNSIGNED_SHORT&&xe&&(te=xe.RGB16_EXT),X===n.SHORT&&xe&&(te=xe.RGB16_SNORM_EXT),X===n.UNSIGNED_INT_5_9_9_9_REV&&(te=n.RGB9_E5),X===n.UNSIGNED_INT_10F_11F_11F_REV&&(te=n.R11F_G11F_B10F)),b===n.RGBA){const ie=ve?vl:vt.getTransfer(ae);X===n.FLOAT&&(te=n.RGBA32F),X===n.HALF_FLOAT&&(te=n.RGBA16F),X===n.UNSIGNED_BYTE&&(te=ie===Lt?n.SRGB8_ALPHA8:n.RGBA8),X===n.UNSIGNED_SHORT&&xe&&(te=xe.RGBA16_EXT),X===n.SHORT&&xe&&(te=xe.RGBA16_SNORM_EXT),X===n.UNSIGNED_SHORT_4_4_4_4&&(te=n.RGBA4),X===n.UNSIGNED_SHORT_5_5_5_1&&(te=n.RGB5_A1)}return(te===n.R16F||te===n.R32F||te===n.RG16F||te===n.RG32F||te===n.RGBA16F||te===n.RGBA32F)&&e.get("EXT_color_buffer_float"),te}function v(P,b){let X;return P?b===null||b===es||b===Qr?X=n.DEPTH24_STENCIL8:b===Zi?X=n.DEPTH32F_STENCIL8:b===qa&&(X=n.DEPTH24_STENCIL8,je("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):b===null||b===es||b===Qr?X=n.DEPTH_COMPONENT24:b===Zi?X=n.DEPTH_COMPONENT32F:b===qa&&(X=n.DEPTH_COMPONENT16),X}function M(P,b){return R(P)===!0||P.isFramebufferTexture&&P.minFilter!==Nn&&P.minFilter!==jn?Math.log2(Math.max(b.width,b.height))+1:P.mipmaps.length>0?P.mipmaps.length:P.isCompressedTexture&&Array.isArray(P.image)?b.mipmaps.length:1}function F(P){const b=new WeakRef(P);i.get(P).__ref=b,g.add(b),y.register(P,b,b)}function L(P){const b=i.get(P).__ref;b!==void 0&&(g.delete(b),y.unregister(b))}function D(P){G(P.target)}function B(P){k(P.target)}function G(P){P.removeEventListener("dispose",D),L(P),Y(P),P.isVideoTexture&&u.delete(P),P.isHTMLTexture&&d.delete(P)}function k(P){P.removeEventListener("dispose",B),L(P),le(P)}function W(){for(const P of g){const b=P.deref();b!==void 0&&(b.isRenderTarget===!0?k(b):G(b))}g.clear(),d.clear()}function Y(P){const b=i.get(P);if(b.__webglInit===void 0)return;const X=P.source,ue=m.get(X);if(ue){const ae=ue[b.__cacheKey];ae.usedTimes--,ae.usedTimes===0&&V(P),Object.keys(ue).length===0&&m.delete(X)}i.remove(P)}function V(P){const b=i.get(P);n.deleteTexture(b.__webglTexture);const X=P.source,ue=m.get(X);delete ue[b.__cacheKey],a.memory.textures--}function le(P){const b=i.get(P);b.__depthDisposeCallback&&b.__depthDisposeCallback();const X=P.depthTexture;if(X&&X.renderTarget===P&&G(X),P.isWebGLCubeRenderTarget)for(let ae=0;ae<6;ae++){if(Array.isArray(b.__webglFramebuffer[ae]))for(let ve=0;ve<b.__webglFramebuffer[ae].length;ve++)n.deleteFramebuffer(b.__webglFramebuffer[ae][ve]);else n.deleteFramebuffer(b.__webglFramebuffer[ae]);b.__webglDepthbuffer&&n.deleteRenderbuffer(b.__webglDepthbuffer[ae])}else{if(Array.isArray(b.__webglFramebuffer))for(let ae=0;ae<b.__webglFramebuffer.length;ae++)n.deleteFramebuffer(b.__webglFramebuffer[ae]);else n.deleteFramebuffer(b.__webglFramebuffer);if(b.__webglDepthbuffer&&n.deleteRenderbuffer(b.__webglDepthbuffer),b.__webglMultisampledFramebuffer&&n.deleteFramebuffer(b.__webglMultisampledFramebuffer),b.__webglColorRenderbuffer)for(let ae=0;ae<b.__webglColorRenderbuffer.length;ae++)b.__webglColorRenderbuffer[ae]&&n.deleteRenderbuffer(b.__webglColorRenderbuffer[ae]);b.__webglDepthRenderbuffer&&n.deleteRenderbuffer(b.__webglDepthRenderbuffer)}const ue=P.textures;for(let ae=0,ve=ue.length;ae<ve;ae++){const xe=i.get(ue[ae]);xe.__webglTexture&&(n.deleteTexture(xe.__webglTexture),a.memory.textures--),i.remove(ue[ae])}i.remove(P)}let j=0;function Q(){j=0}function se(){return j}function he(P){j=P}function de(){const P=j;return P>=s.maxTextures&&je("WebGLTextures: Trying to use "+(P+1)+" texture units while this GPU supports only "+s.maxTextures),j+=1,P}function ee(P){const b=[];return b.push(P.wrapS),b.push(P.wrapT),b.push(P.wrapR||0),b.push(P.magFilter),b.push(P.minFilter),b.push(P.anisotropy),b.push(P.internalFormat),b.push(P.format),b.push(P.type),b.push(P.generateMipmaps),b.push(P.mipmapsAutoUpdate),b.push(P.premultiplyAlpha),b.push(P.flipY),b.push(P.unpackAlignment),b.push(P.colorSpace),b.join()}function me(P,b){const X=i.get(P);if(P.isVideoTexture&&kt(P),P.isRenderTargetTexture===!1&&P.isExternalTexture!==!0&&P.version>0&&X.__version!==P.version){const ue=P.image;if(ue===null)je("WebGLRenderer: Texture marked for update but no image data found.");else if(ue.complete===!1)je("WebGLRenderer: Texture marked for update but image is incomplete");else{zt(X,P,b);return}}else P.isExternalTexture&&(X.__webglTexture=P.sourceTexture?P.sourceTexture:null);t.bindTexture(n.TEXTURE_2D,X.__webglTexture,n.TEXTURE0+b)}function _e(P,b){const X=i.get(P);if(P.isRenderTargetTexture===!1&&P.version>0&&X.__version!==P.version){zt(X,P,b);return}else P.isExternalTexture&&(X.__webglTexture=P.sourceTexture?P.sourceTexture:null);t.bindTexture(n.TEXTURE_2D_ARRAY,X.__webglTexture,n.TEXTURE0+b)}function Te(P,b){const X=i.get(P);if(P.isRenderTargetTexture===!1&&P.version>0&&X.__version!==P.version){zt(X,P,b);return}t.bindTexture(n.TEXTURE_3D,X.__webglTexture,n.TEXTURE0+b)}function we(P,b){const X=i.get(P);if(P.version>0&&X.__version!==P.version){on(X,P,b);return}t.bindTexture(n.TEXTURE_CUBE_MAP,X.__webglTexture,n.TEXTURE0+b)}const Ge={[vu]:n.REPEAT,[hs]:n.CLAMP_TO_EDGE,[_u]:n.MIRRORED_REPEAT},tt={[Nn]:n.NEAREST,[Wx]:n.NEAREST_MIPMAP_NEAREST,[_o]:n.NEAREST_MIPMAP_LINEAR,[jn]:n.LINEAR,[uc]:n.LINEAR_MIPMAP_NEAREST,[Ns]:n.LINEAR_MIPMAP_LINEAR},He={[Kx]:n.NEVER,[Qm]:n.ALWAYS,[Yx]:n.LESS,[jm]:n.LEQUAL,[Zx]:n.EQUAL,[Jm]:n.GEQUAL,[jx]:n.GREATER,[Jx]:n.NOTEQUAL};function ct(P,b){if(b.type===Zi&&e.has("OES_texture_float_linear")===!1&&(b.magFilter===jn||b.magFilter===uc||b.magFilter===_o||b.magFilter===Ns||b.minFilter===jn||b.minFilter===uc||b.minFilter===_o||b.minFilter===Ns)&&je("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),n.texParameteri(P,n.TEXTURE_WRAP_S,Ge[b.wrapS]),n.texParameteri(P,n.TEXTURE_WRAP_T,Ge[b.wrapT]),(P===n.TEXTURE_3D||P===n.TEXTURE_2D_ARRAY)&&n.texParameteri(P,n.TEXTURE_WRAP_R,Ge[b.wrapR]),n.texParameteri(P,n.TEXTURE_MAG_FILTER,tt[b.magFilter]),n.texParameteri(P,n.TEXTURE_MIN_FILTER,tt[b.minFilter]),b.compareFunction&&(n.texParameteri(P,n.TEXTURE_COMPARE_MODE,n.COMPARE_REF_TO_TEXTURE),n.texParameteri(P,n.TEXTURE_COMPARE_FUNC,He[b.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(b.magFilter===Nn||b.minFilter!==_o&&b.minFilter!==Ns||b.type===Zi&&e.has("OES_texture_float_linear")===!1)return;if(b.anisotropy>1||i.get(b).__currentAnisotropy){const X=e.get("EXT_texture_filter_anisotropic");n.texParameterf(P,X.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(b.anisotropy,s.getMaxAnisotropy())),i.get(b).__currentAnisotropy=b.anisotropy}}}function rt(P,b){let X=!1;P.__webglInit===void 0&&(P.__webglInit=!0,b.addEventListener("dispose",D),F(b));const ue=b.source;let ae=m.get(ue);ae===void 0&&(ae={},m.set(ue,ae));const ve=ee(b);if(ve!==P.__cacheKey){ae[ve]===void 0&&(ae[ve]={texture:n.createTexture(),usedTimes:0},a.memory.textures++,X=!0),ae[ve].usedTimes++;const xe=ae[P.__cacheKey];xe!==void 0&&(ae[P.__cacheKey].usedTimes--,xe.usedTimes===0&&V(b)),P.__cacheKey=ve,P.__webglTexture=ae[ve].texture}return X}function Qe(P,b,X){return Math.floor(Math.floor(P/X)/b)}function qt(P,b,X,ue){const ve=P.updateRanges;if(ve.length===0)t.texSubImage2D(n.TEXTURE_2D,0,0,0,b.width,b.height,X,ue,b.data);else{ve.sort((U,re)=>U.start-re.start);let xe=0;for(let U=1;U<ve.length;U++){const re=ve[xe],ne=ve[U],Me=re.start+re.count,ge=Qe(ne.start,b.width,4),be=Qe(re.start,b.width,4);ne.start<=Me+1&&ge===be&&Qe(ne.start+ne.count-1,b.width,4)===ge?re.count=Math.max(re.count,ne.start+ne.count-re.start):(++xe,ve[xe]=ne)}ve.length=xe+1;const te=t.getParameter(n.UNPACK_ROW_LENGTH),ie=t.getParameter(n.UNPACK_SKIP_PIXELS),pe=t.getParameter(n.UNPACK_SKIP_ROWS);t.pixelStorei(n.UNPACK_ROW_LENGTH,b.width);for(let U=0,re=ve.length;U<re;U++){const ne=ve[U],Me=Math.floor(ne.start/4),ge=Math.ceil(ne.count/4),be=Me%b.width,Ve=Math.floor(Me/b.width),Ye=ge,ce=1;t.pixelStorei(n.UNPACK_SKIP_PIXELS,be),t.pixelStorei(n.UNPACK_SKIP_ROWS,Ve),t.texSubImage2D(n.TEXTURE_2D,0,be,Ve,Ye,ce,X,ue,b.data)}P.clearUpdateRanges(),t.pixelStorei(n.UNPACK_ROW_LENGTH,te),t.pixelStorei(n.UNPACK_SKIP_PIXELS,ie),t.pixelStorei(n.UNPACK_SKIP_ROWS,pe)}}function zt(P,b,X){let ue=n.TEXTURE_2D;(b.isDataArrayTexture||b.isCompressedArrayTexture)&&(ue=n.TEXTURE_2D_ARRAY),b.isData3DTexture&&(ue=n.TEXTURE_3D);const ae=rt(P,b),ve=b.source;t.bindTexture(ue,P.__webglTexture,n.TEXTURE0+X);const xe=i.get(ve);if(ve.version!==xe.__version||ae===!0){if(t.activeTexture(n.TEXTURE0+X),(typeof ImageBitmap<"u"&&b.image instanceof ImageBitmap)===!1){const ce=vt.getPrimaries(vt.workingColorSpace),Ue=b.colorSpace===Ds?null:vt.getPrimaries(b.colorSpace),Ze=b.colorSpace===Ds||ce===Ue?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,b.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,b.premultiplyAlpha),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,Ze)}t.pixelStorei(n.UNPACK_ALIGNMENT,b.unpackAlignment);let ie=x(b.image,!1,s.maxTextureSize);ie=Be(b,ie);const pe=r.convert(b.format,b.colorSpace),U=r.convert(b.type);let re=w(b.internalFormat,pe,U,b.normalized,b.colorSpace,b.isVideoTexture);ct(ue,b);let ne;const Me=b.mipmaps,ge=b.isVideoTexture!==!0,be=xe.__version===void 0||ae===!0,Ve=ve.dataReady,Ye=M(b,ie);if(b.isDepthTexture)re=v(b.format===Is,b.type),be&&(ge?t.texStorage2D(n.TEXTURE_2D,1,re,ie.width,ie.height):t.texImage2D(n.TEXTURE_2D,0,re,ie.width,ie.height,0,pe,U,null));else if(b.isDataTexture)if(Me.length>0){ge&&be&&t.texStorage2D(n.TEXTURE_2D,Ye,re,Me[0].width,Me[0].height);for(let ce=0,Ue=Me.length;ce<Ue;ce++)ne=Me[ce],ge?Ve&&t.texSubImage2D(n.TEXTURE_2D,ce,0,0,ne.width,ne.height,pe,U,ne.data):t.texImage2D(n.TEXTURE_2D,ce,re,ne.width,ne.height,0,pe,U,ne.data);b.generateMipmaps=!1}else ge?(be&&t.texStorage2D(n.TEXTURE_2D,Ye,re,ie.width,ie.height),Ve&&qt(b,ie,pe,U)):t.texImage2D(n.TEXTURE_2D,0,re,ie.width,ie.height,0,pe,U,ie.data);else if(b.isCompressedTexture)if(b.isCompressedArrayTexture){ge&&be&&t.texStorage3D(n.TEXTURE_2D_ARRAY,Ye,re,Me[0].width,Me[0].height,ie.depth);for(let ce=0,Ue=Me.length;ce<Ue;ce++)if(ne=Me[ce],b.format!==ji)if(pe!==null)if(ge){if(Ve)if(b.layerUpdates.size>0){const Ze=Vf(ne.width,ne.height,b.format,b.type);for(const Re of b.layerUpdates){const st=ne.data.subarray(Re*Ze/ne.data.BYTES_PER_ELEMENT,(Re+1)*Ze/ne.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,ce,0,0,Re,ne.width,ne.height,1,pe,st)}}else t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,ce,0,0,0,ne.width,ne.height,ie.depth,pe,ne.data)}else t.compressedTexImage3D(n.TEXTURE_2D_ARRAY,ce,re,ne.width,ne.height,ie.depth,0,ne.data,0,0);else je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else ge?Ve&&t.texSubImage3D(n.TEXTURE_2D_ARRAY,ce,0,0,0,ne.width,ne.height,ie.depth,pe,U,ne.data):t.texImage3D(n.TEXTURE_2D_ARRAY,ce,re,ne.width,ne.height,ie.depth,0,pe,U,ne.data);b.layerUpdates.size>0&&b.clearLayerUpdates()}else{ge&&be&&t.texStorage2D(n.TEXTURE_2D,Ye,re,Me[0].width,Me[0].height);for(let ce=0,Ue=Me.length;ce<Ue;ce++)ne=Me[ce],b.format!==ji?pe!==null?ge?Ve&&t.compressedTexSubImage2D(n.TEXTURE_2D,ce,0,0,ne.width,ne.height,pe,ne.data):t.compressedTexImage2D(n.TEXTURE_2D,ce,re,ne.width,ne.height,0,ne.data):je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):ge?Ve&&t.texSubImage2D(n.TEXTURE_2D,ce,0,0,ne.width,ne.height,pe,U,ne.data):t.texImage2D(n.TEXTURE_2D,ce,re,ne.width,ne.height,0,pe,U,ne.data)}else if(b.isDataArrayTexture)if(ge){if(be&&t.texStorage3D(n.TEXTURE_2D_ARRAY,Ye,re,ie.width,ie.height,ie.depth),Ve)if(b.layerUpdates.size>0){const ce=Vf(ie.width,ie.height,b.format,b.type);for(const Ue of b.layerUpdates){const Ze=ie.data.subarray(Ue*ce/ie.data.BYTES_PER_ELEMENT,(Ue+1)*ce/ie.data.BYTES_PER_ELEMENT);t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,Ue,ie.width,ie.height,1,pe,U,Ze)}b.clearLayerUpdates()}else t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,0,ie.width,ie.height,ie.depth,pe,U,ie.data)}else t.texImage3D(n.TEXTURE_2D_ARRAY,0,re,ie.width,ie.height,ie.depth,0,pe,U,ie.data);else if(b.isData3DTexture)ge?(be&&t.texStorage3D(n.TEXTURE_3D,Ye,re,ie.width,ie.height,ie.depth),Ve&&t.texSubImage3D(n.TEXTURE_3D,0,0,0,0,ie.width,ie.height,ie.depth,pe,U,ie.data)):t.texImage3D(n.TEXTURE_3D,0,re,ie.width,ie.height,ie.depth,0,pe,U,ie.data);else if(b.isFramebufferTexture){if(be)if(ge)t.texStorage2D(n.TEXTURE_2D,Ye,re,ie.width,ie.height);else{let ce=ie.width,Ue=ie.height;for(let Ze=0;Ze<Ye;Ze++)t.texImage2D(n.TEXTURE_2D,Ze,re,ce,Ue,0,pe,U,null),ce>>=1,Ue>>=1}}else if(b.isHTMLTexture){if("texElementImage2D"in n){const ce=n.canvas;if(ce.hasAttribute("layoutsubtree")||ce.setAttribute("layoutsubtree","true"),ie.parentNode!==ce){ce.appendChild(ie),d.add(b),ce.onpaint=Ue=>{const Ze=Ue.changedElements;for(const Re of d)Ze.includes(Re.image)&&(Re.needsUpdate=!0)},ce.requestPaint();return}if(n.texElementImage2D.length===3)n.texElementImage2D(n.TEXTURE_2D,n.RGBA8,ie);else{const Ze=n.RGBA,Re=n.RGBA,st=n.UNSIGNED_BYTE;n.texElementImage2D(n.TEXTURE_2D,0,Ze,Re,st,ie)}n.texParameteri(n.TEXTURE_2D,n.TEXTURE_MIN_FILTER,n.LINEAR),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_S,n.CLAMP_TO_EDGE),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_T,n.CLAMP_TO_EDGE)}}else if(Me.length>0){if(ge&&be){const ce=Xe(Me[0]);t.texStorage2D(n.TEXTURE_2D,Ye,re,ce.width,ce.height)}for(let ce=0,Ue=Me.length;ce<Ue;ce++)ne=Me[ce],ge?Ve&&t.texSubImage2D(n.TEXTURE_2D,ce,0,0,pe,U,ne):t.texImage2D(n.TEXTURE_2D,ce,re,pe,U,ne);b.generateMipmaps=!1}else if(ge){if(be){const ce=Xe(ie);t.texStorage2D(n.TEXTURE_2D,Ye,re,ce.width,ce.height)}Ve&&t.texSubImage2D(n.TEXTURE_2D,0,0,0,pe,U,ie)}else t.texImage2D(n.TEXTURE_2D,0,re,pe,U,ie);R(b)&&b.mipmapsAutoUpdate===!0&&S(ue),xe.__version=ve.version,b.onUpdate&&b.onUpdate(b)}P.__version=b.version}function on(P,b,X){if(b.image.length!==6)return;const ue=rt(P,b),ae=b.source;t.bindTexture(n.TEXTURE_CUBE_MAP,P.__webglTexture,n.TEXTURE0+X);const ve=i.get(ae);if(ae.version!==ve.__version||ue===!0){t.activeTexture(n.TEXTURE0+X);const xe=vt.getPrimaries(vt.workingColorSpace),te=b.colorSpace===Ds?null:vt.getPrimaries(b.colorSpace),ie=b.colorSpace===Ds||xe===te?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,b.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,b.premultiplyAlpha),t.pixelStorei(n.UNPACK_ALIGNMENT,b.unpackAlignment),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,ie);const pe=b.isCompressedTexture||b.image[0].isCompressedTexture,U=b.image[0]&&b.image[0].isDataTexture,re=[];for(let Re=0;Re<6;Re++)!pe&&!U?re[Re]=x(b.image[Re],!0,s.maxCubemapSize):re[Re]=U?b.image[Re].image:b.image[Re],re[Re]=Be(b,re[Re]);const ne=re[0],Me=r.convert(b.format,b.colorSpace),ge=r.convert(b.type);let be=w(b.internalFormat,Me,ge,b.normalized,b.colorSpace);const Ve=b.isVideoTexture!==!0,Ye=ve.__version===void 0||ue===!0,ce=ae.dataReady;let Ue=M(b,ne);ct(n.TEXTURE_CUBE_MAP,b);let Ze;if(b.isDepthTexture){if(be=v(b.format===Is,b.type),Ye)if(Ve)t.texStorage2D(n.TEXTURE_CUBE_MAP,1,be,ne.width,ne.height);else for(let Re=0;Re<6;Re++)t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,be,ne.width,ne.height,0,Me,ge,null)}else if(pe){Ve&&Ye&&t.texStorage2D(n.TEXTURE_CUBE_MAP,Ue,be,ne.width,ne.height);for(let Re=0;Re<6;Re++){Ze=re[Re].mipmaps;for(let st=0;st<Ze.length;st++){const Bt=Ze[st];b.format!==ji?Me!==null?Ve?ce&&t.compressedTexSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st,0,0,Bt.width,Bt.height,Me,Bt.data):t.compressedTexImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st,be,Bt.width,Bt.height,0,Bt.data):je("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Ve?ce&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st,0,0,Bt.width,Bt.height,Me,ge,Bt.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st,be,Bt.width,Bt.height,0,Me,ge,Bt.data)}}}else{if(Ze=b.mipmaps,Ve&&Ye){Ze.length>0&&Ue++;const Re=Xe(re[0]);t.texStorage2D(n.TEXTURE_CUBE_MAP,Ue,be,Re.width,Re.height)}for(let Re=0;Re<6;Re++)if(U){Ve?ce&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,0,0,re[Re].width,re[Re].height,Me,ge,re[Re].data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,be,re[Re].width,re[Re].height,0,Me,ge,re[Re].data);for(let st=0;st<Ze.length;st++){const Bn=Ze[st].image[Re].image;Ve?ce&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st+1,0,0,Bn.width,Bn.height,Me,ge,Bn.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st+1,be,Bn.width,Bn.height,0,Me,ge,Bn.data)}}else{Ve?ce&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,0,0,Me,ge,re[Re]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,be,Me,ge,re[Re]);for(let st=0;st<Ze.length;st++){const Bt=Ze[st];Ve?ce&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st+1,0,0,Me,ge,Bt.image[Re]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st+1,be,Me,ge,Bt.image[Re])}}}R(b)&&b.mipmapsAutoUpdate===!0&&S(n.TEXTURE_CUBE_MAP),ve.__version=ae.version,b.onUpdate&&b.onUpdate(b)}P.__version=b.version}function Nt(P,b,X,ue,ae,ve){const xe=r.convert(X.format,X.colorSpace),te=r.convert(X.type),ie=w(X.internalFormat,xe,te,X.normalized,X.colorSpace),pe=i.get(b),U=i.get(X);if(U.__renderTarget=b,!pe.__hasExternalTextures){const re=Math.max(1,b.width>>ve),ne=Math.max(1,b.height>>ve);ae===n.TEXTURE_3D||ae===n.TEXTURE_2D_ARRAY?t.texImage3D(ae,ve,ie,re,ne,b.depth,0,xe,te,null):t.texImage2D(ae,ve,ie,re,ne,0,xe,te,null)}t.bindFramebuffer(n.FRAMEBUFFER,P),Se(b)?o.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,ue,ae,U.__webglTexture,0,nt(b)):(ae===n.TEXTURE_2D||ae>=n.TEXTURE_CUBE_MAP_POSITIVE_X&&ae<=n.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&n.framebufferTexture2D(n.FRAMEBUFFER,ue,ae,U.__webglTexture,ve),t.bindFramebuffer(n.FRAMEBUFFER,null)}function En(P,b,X){if(n.bindRenderbuffer(n.RENDERBUFFER,P),b.depthBuffer){const ue=b.depthTexture,ae=ue&&ue.isDepthTexture?ue.type:null,ve=v(b.stencilBuffer,ae),xe=b.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;Se(b)?o.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,nt(b),ve,b.width,b.height):X?n.renderbufferStorageMultisample(n.RENDERBUFFER,nt(b),ve,b.width,b.height):n.renderbufferStorage(n.RENDERBUFFER,ve,b.width,b.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,xe,n.RENDERBUFFER,P)}else{const ue=b.textures;for(let ae=0;ae<ue.length;ae++){const ve=ue[ae],xe=r.convert(ve.format,ve.colorSpace),te=r.convert(ve.type),ie=w(ve.internalFormat,xe,te,ve.normalized,ve.colorSpace);Se(b)?o.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,nt(b),ie,b.width,b.height):X?n.renderbufferStorageMultisample(n.RENDERBUFFER,nt(b),ie,b.width,b.height):n.renderbufferStorage(n.RENDERBUFFER,ie,b.width,b.height)}}n.bindRenderbuffer(n.RENDERBUFFER,null)}function _t(P,b,X){const ue=b.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(n.FRAMEBUFFER,P),!(b.depthTexture&&b.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");const ae=i.get(b.depthTexture);ae.__renderTarget=b;const ve=ue?b.depthTexture.image[0]:b.depthTexture.image;(!ae.__webglTexture||ve.width!==b.width||ve.height!==b.height)&&(ve.width=b.width,ve.height=b.height,b.depthTexture.needsUpdate=!0),ue?we(b.depthTexture,0):me(b.depthTexture,0);const xe=ae.__webglTexture,te=nt(b),ie=ue?n.TEXTURE_CUBE_MAP_POSITIVE_X+X:n.TEXTURE_2D,pe=b.depthTexture.format===Is?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;if(b.depthTexture.format===zs)Se(b)?o.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,pe,ie,xe,0,te):n.framebufferTexture2D(n.FRAMEBUFFER,pe,ie,xe,0);else if(b.depthTexture.format===Is)Se(b)?o.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,pe,ie,xe,0,te):n.framebufferTexture2D(n.FRAMEBUFFER,pe,ie,xe,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function mn(P){const b=i.get(P),X=P.isWebGLCubeRenderTarget===!0;if(b.__boundDepthTexture!==P.depthTexture){const ue=P.depthTexture;if(b.__depthDisposeCallback&&b.__depthDisposeCallback(),ue){const ae=()=>{delete b.__boundDepthTexture,delete b.__depthDisposeCallback,ue.removeEventListener("dispose",ae)};ue.addEventListener("dispose",ae),b.__depthDisposeCallback=ae}b.__boundDepthTexture=ue}if(P.depthTexture&&!b.__autoAllocateDepthBuffer)if(X)for(let ue=0;ue<6;ue++)_t(b.__webglFramebuffer[ue],P,ue);else P.texture.mipmaps.length>0?_t(b.__webglFramebuffer[0],P,0):_t(b.__webglFramebuffer,P,0);else if(X){b.__webglDepthbuffer=[];for(let ue=0;ue<6;ue++)if(t.bindFramebuffer(n.FRAMEBUFFER,b.__webglFramebuffer[ue]),b.__webglDepthbuffer[ue]===void 0)b.__webglDepthbuffer[ue]=n.createRenderbuffer(),En(b.__webglDepthbuffer[ue],P,!1);else{const ae=P.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,ve=b.__webglDepthbuffer[ue];n.bindRenderbuffer(n.RENDERBUFFER,ve),n.framebufferRenderbuffer(n.FRAMEBUFFER,ae,n.RENDERBUFFER,ve)}}else if(P.texture.mipmaps.length>0?t.bindFramebuffer(n.FRAMEBUFFER,b.__webglFramebuffer[0]):t.bindFramebuffer(n.FRAMEBUFFER,b.__webglFramebuffer),b.__webglDepthbuffer===void 0)b.__webglDepthbuffer=n.createRenderbuffer(),En(b.__webglDepthbuffer,P,!1);else{const ae=P.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,ve=b.__webglDepthbuffer;n.bindRenderbuffer(n.RENDERBUFFER,ve),n.framebufferRenderbuffer(n.FRAMEBUFFER,ae,n.RENDERBUFFER,ve)}t.bindFramebuffer(n.FRAMEBUFFER,null)}function Kt(P,b,X){const ue=i.get(P);b!==void 0&&Nt(ue.__webglFramebuffer,P,P.texture,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,0),X!==void 0&&mn(P)}function ln(P){const b=P.texture,X=i.get(P),ue=i.get(b);P.addEventListener("dispose",B),F(P);const ae=P.textures,ve=P.isWebGLCubeRenderTarget===!0,xe=ae.length>1;if(xe||(ue.__webglTexture===void 0&&(ue.__webglTexture=n.createTexture()),ue.__version=b.version,a.memory.textures++),ve){X.__webglFramebuffer=[];for(let te=0;te<6;te++)if(b.mipmaps.length>0){X.__webglFramebuffer[te]=[];for(let ie=0;ie<b.mipmaps.length;ie++)X.__webglFramebuffer[te][ie]=n.createFramebuffer()}else X.__webglFramebuffer[te]=n.createFramebuffer()}else{if(b.mipmaps.length>0){X.__webglFramebuffer=[];for(let te=0;te<b.mipmaps.length;te++)X.__webglFramebuffer[te]=n.createFramebuffer()}else X.__webglFramebuffer=n.createFramebuffer();if(xe)for(let te=0,ie=ae.length;te<ie;te++){const pe=i.get(ae[te]);pe.__webglTexture===void 0&&(pe.__webglTexture=n.createTexture(),a.memory.textures++)}if(P.samples>0&&Se(P)===!1){X.__webglMultisampledFramebuffer=n.createFramebuffer(),X.__webglColorRenderbuffer=[],t.bindFramebuffer(n.FRAMEBUFFER,X.__webglMultisampledFramebuffer);for(let te=0;te<ae.length;te++){const ie=ae[te];X.__webglColorRenderbuffer[te]=n.createRenderbuffer(),n.bindRenderbuffer(n.RENDERBUFFER,X.__webglColorRenderbuffer[te]);const pe=r.convert(ie.format,ie.colorSpace),U=r.convert(ie.type),re=w(ie.internalFormat,pe,U,ie.normalized,ie.colorSpace,P.isXRRenderTarget===!0),ne=nt(P);n.renderbufferStorageMultisample(n.RENDERBUFFER,ne,re,P.width,P.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+te,n.RENDERBUFFER,X.__webglColorRenderbuffer[te])}n.bindRenderbuffer(n.RENDERBUFFER,null),P.depthBuffer&&(X.__webglDepthRenderbuffer=n.createRenderbuffer(),En(X.__webglDepthRenderbuffer,P,!0)),t.bindFramebuffer(n.FRAMEBUFFER,null)}}if(ve){t.bindTexture(n.TEXTURE_CUBE_MAP,ue.__webglTexture),ct(n.TEXTURE_CUBE_MAP,b);for(let te=0;te<6;te++)if(b.mipmaps.length>0)for(let ie=0;ie<b.mipmaps.length;ie++)Nt(X.__webglFramebuffer[te][ie],P,b,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+te,ie);else Nt(X.__webglFramebuffer[te],P,b,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+te,0);R(b)?S(n.TEXTURE_CUBE_MAP):b.mipmaps.length>0&&n.texParameteri(n.TEXTURE_CUBE_MAP,n.TEXTURE_MAX_LEVEL,b.mipmaps.length-1),t.unbindTexture()}else if(xe){for(let te=0,ie=ae.length;te<ie;te++){const pe=ae[te],U=i.get(pe);let re=n.TEXTURE_2D;(P.isWebGL3DRenderTarget||P.isWebGLArrayRenderTarget)&&(re=P.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(re,U.__webglTexture),ct(re,pe),Nt(X.__webglFramebuffer,P,pe,n.COLOR_ATTACHMENT0+te,re,0),R(pe)&&S(re)}t.unbindTexture()}else{let te=n.TEXTURE_2D;if((P.isWebGL3DRenderTarget||P.isWebGLArrayRenderTarget)&&(te=P.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(te,ue.__webglTexture),ct(te,b),b.mipmaps.length>0)for(let ie=0;ie<b.mipmaps.length;ie++)Nt(X.__webglFramebuffer[ie],P,b,n.COLOR_ATTACHMENT0,te,ie);else Nt(X.__webglFramebuffer,P,b,n.COLOR_ATTACHMENT0,te,0);R(b)?S(te):b.mipmaps.length>0&&n.texParameteri(te,n.TEXTURE_MAX_LEVEL,b.mipmaps.length-1),t.unbindTexture()}P.depthBuffer&&mn(P)}function O(P){const b=P.textures;for(let X=0,ue=b.length;X<ue;X++){const ae=b[X];if(R(ae)&&ae.mipmapsAutoUpdate===!0){const ve=C(P),xe=i.get(ae).__webglTexture;t.bindTexture(ve,xe),S(ve),t.unbindTexture()}}}const Ce=[];function $e(P){if(P.samples>0){if(Se(P)===!1){const b=P.textures,X=P.width,ue=P.height;let ae=n.COLOR_BUFFER_BIT;const ve=P.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,xe=i.get(P),te=b.length>1;if(te)for(let pe=0;pe<b.length;pe++)t.bindFramebuffer(n.FRAMEBUFFER,xe.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+pe,n.RENDERBUFFER,null),t.bindFramebuffer(n.FRAMEBUFFER,xe.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+pe,n.TEXTURE_2D,null,0);t.bindFramebuffer(n.READ_FRAMEBUFFER,xe.__webglMultisampledFramebuffer),P.texture.mipmaps.length>0?t.bindFramebuffer(n.DRAW_FRAMEBUFFER,xe.__webglFramebuffer[0]):t.bindFramebuffer(n.DRAW_FRAMEBUFFER,xe.__webglFramebuffer);for(let pe=0;pe<b.length;pe++){if(P.resolveDepthBuffer&&(P.depthBuffer&&(ae|=n.DEPTH_BUFFER_BIT),P.stencilBuffer&&P.resolveStencilBuffer&&(ae|=n.STENCIL_BUFFER_BIT)),te){n.framebufferRenderbuffer(n.READ_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.RENDERBUFFER,xe.__webglColorRenderbuffer[pe]);const U=i.get(b[pe]).__webglTexture;n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,U,0)}n.blitFramebuffer(0,0,X,ue,0,0,X,ue,ae,n.NEAREST),l===!0&&(Ce.length=0,Ce.push(n.COLOR_ATTACHMENT0+pe),P.depthBuffer&&P.storeMultisampledDepthBuffer===!1&&Ce.push(ve),n.invalidateFramebuffer(n.READ_FRAMEBUFFER,Ce))}if(t.bindFramebuffer(n.READ_FRAMEBUFFER,null),t.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),te)for(let pe=0;pe<b.length;pe++){t.bindFramebuffer(n.FRAMEBUFFER,xe.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+pe,n.RENDERBUFFER,xe.__webglColorRenderbuffer[pe]);const U=i.get(b[pe]).__webglTexture;t.bindFramebuffer(n.FRAMEBUFFER,xe.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+pe,n.TEXTURE_2D,U,0)}t.bindFramebuffer(n.DRAW_FRAMEBUFFER,xe.__webglMultisampledFramebuffer)}else if(P.depthBuffer&&P.storeMultisampledDepthBuffer===!1&&l){const b=P.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;n.invalidateFramebuffer(n.DRAW_FRAMEBUFFER,[b])}}}function nt(P){return Math.min(s.maxSamples,P.samples)}function Se(P){const b=i.get(P);return P.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&b.__useRenderToTexture!==!1}function kt(P){const b=a.render.frame;u.get(P)!==b&&(u.set(P,b),P.update())}function Be(P,b){const X=P.colorSpace,ue=P.format,ae=P.type;return P.isCompressedTexture===!0||P.isVideoTexture===!0||X!==gl&&X!==Ds&&(vt.getTransfer(X)===Lt?(ue!==ji||ae!==ai)&&je("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):yt("WebGLTextures: Unsupported texture color space:",X)),b}function Xe(P){return typeof HTMLImageElement<"u"&&P instanceof HTMLImageElement?(c.width=P.naturalWidth||P.width,c.height=P.naturalHeight||P.height):typeof VideoFrame<"u"&&P instanceof VideoFrame?(c.width=P.displayWidth,c.height=P.displayHeight):(c.width=P.width,c.height=P.height),c}this.allocateTextureUnit=de,this.resetTextureUnits=Q,this.getTextureUnits=se,this.setTextureUnits=he,this.setTexture2D=me,this.setTexture2DArray=_e,this.setTexture3D=Te,this.setTextureCube=we,this.rebindTextures=Kt,this.setupRenderTarget=ln,this.updateRenderTargetMipmap=O,this.updateMultisampleRenderTarget=$e,this.setupDepthRenderbuffer=mn,this.setupFrameBufferTexture=Nt,this.useMultisampledRTT=Se,this.dispose=W}function TE(n,e){function t(i,s=Ds){let r;const a=vt.getTransfer(s);if(i===ai)return n.UNSIGNED_BYTE;if(i===Nd)return n.UNSIGNED_SHORT_4_4_4_4;if(i===Id)return n.UNSIGNED_SHORT_5_5_5_1;if(i===Xm)return n.UNSIGNED_INT_5_9_9_9_REV;if(i===$m)return n.UNSIGNED_INT_10F_11F_11F_REV;if(i===Wm)return n.BYTE;if(i===qm)return n.SHORT;if(i===qa)return n.UNSIGNED_SHORT;if(i===Dd)return n.INT;if(i===es)return n.UNSIGNED_INT;if(i===Zi)return n.FLOAT;if(i===ts)return n.HALF_FLOAT;if(i===Km)return n.ALPHA;if(i===Ym)return n.RGB;if(i===ji)return n.RGBA;if(i===zs)return n.DEPTH_COMPONENT;if(i===Is)return n.DEPTH_STENCIL;if(i===Zm)return n.RED;if(i===kd)return n.RED_INTEGER;if(i===sr)return n.RG;if(i===Fd)return n.RG_INTEGER;if(i===Ud)return n.RGBA_INTEGER;if(i===nl||i===il||i===sl||i===rl)if(a===Lt)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(i===nl)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(i===il)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(i===sl)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(i===rl)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(i===nl)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(i===il)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(i===sl)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(i===rl)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(i===xu||i===yu||i===bu||i===wu)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(i===xu)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(i===yu)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(i===bu)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(i===wu)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(i===Su||i===Mu||i===Eu||i===Au||i===Tu||i===pl||i===Ru)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(i===Su||i===Mu)return a===Lt?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(i===Eu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(i===Au)return r.COMPRESSED_R11_EAC;if(i===Tu)return r.COMPRESSED_SIGNED_R11_EAC;if(i===pl)return r.COMPRESSED_RG11_EAC;if(i===Ru)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(i===Cu||i===Pu||i===Lu||i===Du||i===Nu||i===Iu||i===ku||i===Fu||i===Uu||i===Ou||i===zu||i===Bu||i===Hu||i===Vu)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(i===Cu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(i===Pu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(i===Lu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(i===Du)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(i===Nu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(i===Iu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(i===ku)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(i===Fu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(i===Uu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(i===Ou)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(i===zu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(i===Bu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(i===Hu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(i===Vu)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(i===Gu||i===Wu||i===qu)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(i===Gu)return a===Lt?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(i===Wu)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(i===qu)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(i===Xu||i===$u||i===ml||i===Ku)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(i===Xu)return r.COMPRESSED_RED_RGTC1_EXT;if(i===$u)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(i===ml)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(i===Ku)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return i===Qr?n.UNSIGNED_INT_24_8:n[i]!==void 0?n[i]:null}return{convert:t}}const RE=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,CE=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`;class PE{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){const i=new pg(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=i}}getMesh(e){if(this.texture!==null&&this.mesh===null){const t=e.cameras[0].viewport,i=new rr({vertexShader:RE,fragmentShader:CE,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new en(new Ul(20,20),i)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}}class LE extends Hs{constructor(e,t){super();const i=this;let s=null,r=1,a=null,o="local-floor",l=1,c=null,u=null,d=null,h=null,m=null,g=null;const y=typeof XRWebGLBinding<"u",p=new PE,f={},x=t.getContextAttributes();let R=null,S=null;const C=[],w=[],v=new qe;let M=null,F=null;const L=new Zn;L.viewport=new rn;const D=new Zn;D.viewport=new rn;const B=[L,D],G=new Vy;let k=null,W=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(ee){let me=C[ee];return me===void 0&&(me=new _c,C[ee]=me),me.getTargetRaySpace()},this.getControllerGrip=function(ee){let me=C[ee];return me===void 0&&(me=new _c,C[ee]=me),me.getGripSpace()},this.getHand=function(ee){let me=C[ee];return me===void 0&&(me=new _c,C[ee]=me),me.getHandSpace()};function Y(ee){const me=w.indexOf(ee.inputSource);if(me===-1)return;const _e=C[me];_e!==void 0&&(_e.update(ee.inputSource,ee.frame,c||a),_e.dispatchEvent({type:ee.type,data:ee.inputSource}))}function V(){s.removeEventListener("select",Y),s.removeEventListener("selectstart",Y),s.removeEventListener("selectend",Y),s.removeEventListener("squeeze",Y),s.removeEventListener("squeezestart",Y),s.removeEventListener("squeezeend",Y),s.removeEventListener("end",V),s.removeEventListener("inputsourceschange",le);for(let ee=0;ee<C.length;ee++){const me=w[ee];me!==null&&(w[ee]=null,C[ee].disconnect(me))}k=null,W=null,p.reset();for(const ee in f)delete f[ee];if(e.setRenderTarget(R),m=null,h=null,d=null,s=null,S=null,de.stop(),i.isPresenting=!1,e.setPixelRatio(M),e.setSize(v.width,v.height,!1),F!==null){const ee=F.camera;ee.fov=F.fov,ee.zoom=F.zoom,ee.updateProjectionMatrix(),F=null}i.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(ee){r=ee,i.isPresenting===!0&&je("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(ee){o=ee,i.isPresenting===!0&&je("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return c||a},this.setReferenceSpace=function(ee){c=ee},this.getBaseLayer=function(){return h!==null?h:m},this.getBinding=function(){return d===null&&y&&(d=new XRWebGLBinding(s,t)),d},this.getFrame=function(){return g},this.getSession=function(){return s},this.setSession=async function(ee){if(s=ee,s!==null){if(R=e.getRenderTarget(),s.addEventListener("select",Y),s.addEventListener("selectstart",Y),s.addEventListener("selectend",Y),s.addEventListener("squeeze",Y),s.addEventListener("squeezestart",Y),s.addEventListener("squeezeend",Y),s.addEventListener("end",V),s.addEventListener("inputsourceschange",le),x.xrCompatible!==!0&&await t.makeXRCompatible(),M=e.getPixelRatio(),e.getSize(v),y&&"createProjectionLayer"in XRWebGLBinding.prototype){let _e=null,Te=null,we=null;x.depth&&(we=x.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,_e=x.stencil?Is:zs,Te=x.stencil?Qr:es);const Ge={colorFormat:t.RGBA8,depthFormat:we,scaleFactor:r};d=this.getBinding(),h=d.createProjectionLayer(Ge),s.updateRenderState({layers:[h]}),e.setPixelRatio(1),e.setSize(h.textureWidth,h.textureHeight,!1),S=new Ji(h.textureWidth,h.textureHeight,{format:ji,type:ai,depthTexture:new ea(h.textureWidth,h.textureHeight,Te,void 0,void 0,void 0,void 0,void 0,void 0,_e),stencilBuffer:x.stencil,colorSpace:e.outputColorSpace,samples:x.antialias?4:0,resolveDepthBuffer:h.ignoreDepthValues===!1,resolveStencilBuffer:h.ignoreDepthValues===!1,storeMultisampledDepthBuffer:h.ignoreDepthValues===!1,storeMultisampledStencilBuffer:h.ignoreDepthValues===!1})}else{const _e={antialias:x.antialias,alpha:!0,depth:x.depth,stencil:x.stencil,framebufferScaleFactor:r};m=new XRWebGLLayer(s,t,_e),s.updateRenderState({baseLayer:m}),e.setPixelRatio(1),e.setSize(m.framebufferWidth,m.framebufferHeight,!1),S=new Ji(m.framebufferWidth,m.framebufferHeight,{format:ji,type:ai,colorSpace:e.outputColorSpace,stencilBuffer:x.stencil,resolveDepthBuffer:m.ignoreDepthValues===!1,resolveStencilBuffer:m.ignoreDepthValues===!1,storeMultisampledDepthBuffer:m.ignoreDepthValues===!1,storeMultisampledStencilBuffer:m.ignoreDepthValues===!1})}S.isXRRenderTarget=!0,this.setFoveation(l),c=null,a=await s.requestReferenceSpace(o),de.setContext(s),de.start(),i.isPresenting=!0,i.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return p.getDepthTexture()};function le(ee){for(let me=0;me<ee.removed.length;me++){const _e=ee.removed[me],Te=w.indexOf(_e);Te>=0&&(w[Te]=null,C[Te].disconnect(_e))}for(let me=0;me<ee.added.length;me++){const _e=ee.added[me];let Te=w.indexOf(_e);if(Te===-1){for(let Ge=0;Ge<C.length;Ge++)if(Ge>=w.length){w.push(_e),Te=Ge;break}else if(w[Ge]===null){w[Ge]=_e,Te=Ge;break}if(Te===-1)break}const we=C[Te];we&&we.connect(_e)}}function j(ee,me){me===null?ee.matrixWorld.copy(ee.matrix):ee.matrixWorld.multiplyMatrices(me.matrixWorld,ee.matrix),ee.matrixWorldInverse.copy(ee.matrixWorld).invert()}this.updateCamera=function(ee){if(s===null)return;let me=ee.near,_e=ee.far;p.texture!==null&&(p.depthNear>0&&(me=p.depthNear),p.depthFar>0&&(_e=p.depthFar)),G.near=D.near=L.near=me,G.far=D.far=L.far=_e,(k!==G.near||W!==G.far)&&(s.updateRenderState({depthNear:G.near,depthFar:G.far}),k=G.near,W=G.far),G.layers.mask=ee.layers.mask|6,L.layers.mask=G.layers.mask&-5,D.layers.mask=G.layers.mask&-3;const Te=ee.parent,we=G.cameras;j(G,Te);for(let Ge=0;Ge<we.length;Ge++)j(we[Ge],Te);G.projectionMatrix.copy(L.projectionMatrix),G.projectionMatrixInverse.copy(L.projectionMatrixInverse),F===null&&ee.isPerspectiveCamera&&(F={camera:ee,fov:ee.fov,zoom:ee.zoom}),Q(ee,G,Te)};function Q(ee,me,_e){_e===null?ee.matrix.copy(me.matrixWorld):(ee.matrix.copy(_e.matrixWorld),ee.matrix.invert(),ee.matrix.multiply(me.matrixWorld)),ee.matrix.decompose(ee.position,ee.quaternion,ee.scale),ee.updateMatrixWorld(!0),ee.projectionMatrix.copy(me.projectionMatrix),ee.projectionMatrixInverse.copy(me.projectionMatrixInverse),ee.isPerspectiveCamera&&(ee.fov=Zu*2*Math.atan(1/ee.projectionMatrix.elements[5]),ee.zoom=1)}this.getCamera=function(){return G},this.getFoveation=function(){if(!(h===null&&m===null))return l},this.setFoveation=function(ee){l=ee,h!==null&&(h.fixedFoveation=ee),m!==null&&m.fixedFoveation!==void 0&&(m.fixedFoveation=ee)},this.hasDepthSensing=function(){return p.texture!==null},this.getDepthSensingMesh=function(){return p.getMesh(G)},this.getCameraTexture=function(ee){return f[ee]};let se=null;function he(ee,me){if(u=me.getViewerPose(c||a),g=me,u!==null){const _e=u.views;m!==null&&(e.setRenderTargetFramebuffer(S,m.framebuffer),e.setRenderTarget(S));let Te=!1;_e.length!==G.cameras.length&&(G.cameras.length=0,Te=!0);for(let He=0;He<_e.length;He++){const ct=_e[He];let rt=null;if(m!==null)rt=m.getViewport(ct);else{const qt=d.getViewSubImage(h,ct);rt=qt.viewport,He===0&&(e.setRenderTargetTextures(S,qt.colorTexture,qt.depthStencilTexture),e.setRenderTarget(S))}let Qe=B[He];Qe===void 0&&(Qe=new Zn,Qe.layers.enable(He),Qe.viewport=new rn,B[He]=Qe),Qe.matrix.fromArray(ct.transform.matrix),Qe.matrix.decompose(Qe.position,Qe.quaternion,Qe.scale),Qe.projectionMatrix.fromArray(ct.projectionMatrix),Qe.projectionMatrixInverse.copy(Qe.projectionMatrix).invert(),Qe.viewport.set(rt.x,rt.y,rt.width,rt.height),He===0&&(G.matrix.copy(Qe.matrix),G.matrix.decompose(G.position,G.quaternion,G.scale)),Te===!0&&G.cameras.push(Qe)}const we=s.enabledFeatures;if(we&&we.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&y){d=i.getBinding();const He=d.getDepthInformation(_e[0]);He&&He.isValid&&He.texture&&p.init(He,s.renderState)}if(we&&we.includes("camera-access")&&y){e.state.unbindTexture(),d=i.getBinding();for(let He=0;He<_e.length;He++){const ct=_e[He].camera;if(ct){let rt=f[ct];rt||(rt=new pg,f[ct]=rt);const Qe=d.getCameraImage(ct);rt.sourceTexture=Qe}}}}for(let _e=0;_e<C.length;_e++){const Te=w[_e],we=C[_e];Te!==null&&we!==void 0&&we.update(Te,me,c||a)}se&&se(ee,me),me.detectedPlanes&&i.dispatchEvent({type:"planesdetected",data:me}),g=null}const de=new Mg;de.setAnimationLoop(he),this.setAnimationLoop=function(ee){se=ee},this.dispose=function(){}}}const DE=new Dt,Ig=new it;Ig.set(-1,0,0,0,1,0,0,0,1);function NE(n,e){function t(p,f){p.matrixAutoUpdate===!0&&p.updateMatrix(),f.value.copy(p.matrix)}function i(p,f){f.color.getRGB(p.fogColor.value,mg(n)),f.isFog?(p.fogNear.value=f.near,p.fogFar.value=f.far):f.isFogExp2&&(p.fogDensity.value=f.density)}function s(p,f,x,R,S){f.isNodeMaterial?f.uniformsNeedUpdate=!1:f.isMeshBasicMaterial?r(p,f):f.isMeshLambertMaterial?(r(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshToonMaterial?(r(p,f),d(p,f)):f.isMeshPhongMaterial?(r(p,f),u(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshStandardMaterial?(r(p,f),h(p,f),f.isMeshPhysicalMaterial&&m(p,f,S)):f.isMeshMatcapMaterial?(r(p,f),g(p,f)):f.isMeshDepthMaterial?r(p,f):f.isMeshDistanceMaterial?(r(p,f),y(p,f)):f.isMeshNormalMaterial?r(p,f):f.isLineBasicMaterial?(a(p,f),f.isLineDashedMaterial&&o(p,f)):f.isPointsMaterial?l(p,f,x,R):f.isSpriteMaterial?c(p,f):f.isShadowMaterial?(p.color.value.copy(f.color),p.opacity.value=f.opacity):f.isShaderMaterial&&(f.uniformsNeedUpdate=!1)}function r(p,f){p.opacity.value=f.opacity,f.color&&p.diffuse.value.copy(f.color),f.emissive&&p.emissive.value.copy(f.emissive).multiplyScalar(f.emissiveIntensity),f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.bumpMap&&(p.bumpMap.value=f.bumpMap,t(f.bumpMap,p.bumpMapTransform),p.bumpScale.value=f.bumpScale,f.side===Jn&&(p.bumpScale.value*=-1)),f.normalMap&&(p.normalMap.value=f.normalMap,t(f.normalMap,p.normalMapTransform),p.normalScale.value.copy(f.normalScale),f.side===Jn&&p.normalScale.value.negate()),f.displacementMap&&(p.displacementMap.value=f.displacementMap,t(f.displacementMap,p.displacementMapTransform),p.displacementScale.value=f.displacementScale,p.displacementBias.value=f.displacementBias),f.emissiveMap&&(p.emissiveMap.value=f.emissiveMap,t(f.emissiveMap,p.emissiveMapTransform)),f.specularMap&&(p.specularMap.value=f.specularMap,t(f.specularMap,p.specularMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest);const x=e.get(f),R=x.envMap,S=x.envMapRotation;R&&(p.envMap.value=R,p.envMapRotation.value.setFromMatrix4(DE.makeRotationFromEuler(S)).transpose(),R.isCubeTexture&&R.isRenderTargetTexture===!1&&p.envMapRotation.value.premultiply(Ig),p.reflectivity.value=f.reflectivity,p.ior.value=f.ior,p.refractionRatio.value=f.refractionRatio),f.lightMap&&(p.lightMap.value=f.lightMap,p.lightMapIntensity.value=f.lightMapIntensity,t(f.lightMap,p.lightMapTransform)),f.aoMap&&(p.aoMap.value=f.aoMap,p.aoMapIntensity.value=f.aoMapIntensity,t(f.aoMap,p.aoMapTransform))}function a(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform))}function o(p,f){p.dashSize.value=f.dashSize,p.totalSize.value=f.dashSize+f.gapSize,p.scale.value=f.scale}function l(p,f,x,R){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.size.value=f.size*x,p.scale.value=R*.5,f.map&&(p.map.value=f.map,t(f.map,p.uvTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function c(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.rotation.value=f.rotation,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function u(p,f){p.specular.value.copy(f.specular),p.shininess.value=Math.max(f.shininess,1e-4)}function d(p,f){f.gradientMap&&(p.gradientMap.value=f.gradientMap)}function h(p,f){p.metalness.value=f.metalness,f.metalnessMap&&(p.metalnessMap.value=f.metalnessMap,t(f.metalnessMap,p.metalnessMapTransform)),p.roughness.value=f.roughness,f.roughnessMap&&(p.roughnessMap.value=f.roughnessMap,t(f.roughnessMap,p.roughnessMapTransform)),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)}function m(p,f,x){p.ior.value=f.ior,f.diffuseRoughness>0&&(p.diffuseRoughness.value=f.diffuseRoughness,f.diffuseRoughnessMap&&(p.diffuseRoughnessMap.value=f.diffuseRoughnessMap,t(f.diffuseRoughnessMap,p.diffuseRoughnessMapTransform))),f.sheen>0&&(p.sheenColor.value.copy(f.sheenColor).multiplyScalar(f.sheen),p.sheenRoughness.value=f.sheenRoughness,f.sheenColorMap&&(p.sheenColorMap.value=f.sheenColorMap,t(f.sheenColorMap,p.sheenColorMapTransform)),f.sheenRoughnessMap&&(p.sheenRoughnessMap.value=f.sheenRoughnessMap,t(f.sheenRoughnessMap,p.sheenRoughnessMapTransform))),f.clearcoat>0&&(p.clearcoat.value=f.clearcoat,p.clearcoatRoughness.value=f.clearcoatRoughness,f.clearcoatMap&&(p.clearcoatMap.value=f.clearcoatMap,t(f.clearcoatMap,p.clearcoatMapTransform)),f.clearcoatRoughnessMap&&(p.clearcoatRoughnessMap.value=f.clearcoatRoughnessMap,t(f.clearcoatRoughnessMap,p.clearcoatRoughnessMapTransform)),f.clearcoatNormalMap&&(p.clearcoatNormalMap.value=f.clearcoatNormalMap,t(f.clearcoatNormalMap,p.clearcoatNormalMapTransform),p.clearcoatNormalScale.value.copy(f.clearcoatNormalScale),f.side===Jn&&p.clearcoatNormalScale.value.negate())),f.dispersion>0&&(p.dispersion.value=f.dispersion),f.retroreflectivity>0&&(p.retroreflectivity.value=f.retroreflectivity),f.iridescence>0&&(p.iridescence.value=f.iridescence,p.iridescenceIOR.value=f.iridescenceIOR,p.iridescenceThicknessMinimum.value=f.iridescenceThicknessMinimum,p.iridescenceThicknessMaximum.value=f.iridescenceThicknessMaximum,f.iridescenceMap&&(p.iridescenceMap.value=f.iridescenceMap,t(f.iridescenceMap,p.iridescenceMapTransform)),f.iridescenceThicknessMap&&(p.iridescenceThicknessMap.value=f.iridescenceThicknessMap,t(f.iridescenceThicknessMap,p.iridescenceThicknessMapTransform))),f.transmission>0&&(p.transmission.value=f.transmission,p.transmissionSamplerMap.value=x.texture,p.transmissionSamplerSize.value.set(x.width,x.height),f.transmissionMap&&(p.transmissionMap.value=f.transmissionMap,t(f.transmissionMap,p.transmissionMapTransform)),p.thickness.value=f.thickness,f.thicknessMap&&(p.thicknessMap.value=f.thicknessMap,t(f.thicknessMap,p.thicknessMapTransform)),p.attenuationDistance.value=f.attenuationDistance,p.attenuationColor.value.copy(f.attenuationColor)),f.anisotropy>0&&(p.anisotropyVector.value.set(f.anisotropy*Math.cos(f.anisotropyRotation),f.anisotropy*Math.sin(f.anisotropyRotation)),f.anisotropyMap&&(p.anisotropyMap.value=f.anisotropyMap,t(f.anisotropyMap,p.anisotropyMapTransform))),p.specularIntensity.value=f.specularIntensity,p.specularColor.value.copy(f.specularColor),f.specularColorMap&&(p.specularColorMap.value=f.specularColorMap,t(f.specularColorMap,p.specularColorMapTransform)),f.specularIntensityMap&&(p.specularIntensityMap.value=f.specularIntensityMap,t(f.specularIntensityMap,p.specularIntensityMapTransform))}function g(p,f){f.matcap&&(p.matcap.value=f.matcap)}function y(p,f){const x=e.get(f).light;p.referencePosition.value.setFromMatrixPosition(x.matrixWorld),p.nearDistance.value=x.shadow.camera.near,p.farDistance.value=x.shadow.camera.far}return{refreshFogUniforms:i,refreshMaterialUniforms:s}}function IE(n,e,t,i){let s={},r={};function a(x,R){const S=R.program;i.uniformBlockBinding(x,S,s[x.id])}function o(x,R){let S=s[x.id];S===void 0&&(g(x),S=l(x),s[x.id]=S,x.addEventListener("dispose",p));const C=R.program;i.updateUBOMapping(x,C);const w=e.render.frame;r[x.id]!==w&&(c(x),r[x.id]=w)}function l(x){const R=n.createBuffer(),S=x.__size,C=x.usage;return n.bindBuffer(n.UNIFORM_BUFFER,R),n.bufferData(n.UNIFORM_BUFFER,S,C),n.bindBuffer(n.UNIFORM_BUFFER,null),R}function c(x){const R=s[x.id],S=x.uniforms,C=x.__cache;n.bindBuffer(n.UNIFORM_BUFFER,R);for(let w=0,v=S.length;w<v;w++){const M=S[w];if(Array.isArray(M))for(let F=0,L=M.length;F<L;F++)u(M[F],w,F,C);else u(M,w,0,C)}n.bindBuffer(n.UNIFORM_BUFFER,null)}function u(x,R,S,C){if(h(x,R,S,C)===!0){const w=x.__offset,v=x.value;if(Array.isArray(v)){let M=0;for(let F=0;F<v.length;F++){const L=v[F],D=y(L,!0);d(L,x.__data,M),M+=D.storage/Float32Array.BYTES_PER_ELEMENT}}else d(v,x.__data,0);n.bufferSubData(n.UNIFORM_BUFFER,w,x.__data)}}function d(x,R,S){typeof x=="number"||typeof x=="boolean"?R[S]=x:x.isMatrix3?(R[S]=x.elements[0],R[S+1]=x.elements[1],R[S+2]=x.elements[2],R[S+3]=0,R[S+4]=x.elements[3],R[S+5]=x.elements[4],R[S+6]=x.elements[5],R[S+7]=0,R[S+8]=x.elements[6],R[S+9]=x.elements[7],R[S+10]=x.elements[8],R[S+11]=0):ArrayBuffer.isView(x)?R.set(x.subarray(0,R.length-S),S):x.toArray(R,S)}function h(x,R,S,C){const w=x.value,v=R+"_"+S;if(Array.isArray(w)){C[v]===void 0&&(C[v]=[]);const M=C[v];let F=!1;for(let L=0;L<w.length;L++)m(w[L],M,L)===!0&&(F=!0);return F}return m(w,C,v)}function m(x,R,S){if(R[S]===void 0)return typeof x=="number"||typeof x=="boolean"?R[S]=x:ArrayBuffer.isView(x)?R[S]=x.slice():R[S]=x.clone(),!0;{const C=R[S];if(typeof x=="number"||typeof x=="boolean"){if(C!==x)return R[S]=x,!0}else{if(ArrayBuffer.isView(x))return!0;if(C.equals(x)===!1)return C.copy(x),!0}}return!1}function g(x){const R=x.uniforms;let S=0;const C=16;for(let v=0,M=R.length;v<M;v++){const F=Array.isArray(R[v])?R[v]:[R[v]];for(let L=0,D=F.length;L<D;L++){const B=F[L],G=Array.isArray(B.value)?B.value:[B.value],k=Array.isArray(R[v])||Array.isArray(B.value);let W=S;for(let V=0,le=G.length;V<le;V++){const j=G[V],Q=y(j,k),se=S%C,he=se%Q.boundary,de=se+he;S+=he,de!==0&&C-de<Q.storage&&(S+=C-de),V===0&&(W=S),S+=Q.storage}const Y=B.type==="int"?Int32Array:B.type==="uint"?Uint32Array:Float32Array;B.__data=new Y((S-W)/Float32Array.BYTES_PER_ELEMENT),B.__offset=W}}const w=S%C;return w>0&&(S+=C-w),x.__size=S,x.__cache={},this}function y(x,R){const S={boundary:0,storage:0};return typeof x=="number"||typeof x=="boolean"?(S.boundary=4,S.storage=4):x.isVector2?(S.boundary=8,S.storage=8):x.isVector3||x.isColor?(S.boundary=16,S.storage=12):x.isVector4?(S.boundary=16,S.storage=16):x.isMatrix3?(S.boundary=16,S.storage=48):x.isMatrix4?(S.boundary=16,S.storage=64):x.isTexture?je("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(x)?(S.boundary=16,S.storage=x.byteLength):je("WebGLRenderer: Unsupported uniform value type.",x),R===!0&&(S.boundary=16,S.storage=Math.ceil(S.storage/16)*16),S}function p(x){const R=x.target;R.removeEventListener("dispose",p),n.deleteBuffer(s[R.id]),delete s[R.id],delete r[R.id]}function f(){for(const x in s)n.deleteBuffer(s[x]);s={},r={}}return{bind:a,update:o,dispose:f}}const kE=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]);let Xi=null;function FE(){return Xi===null&&(Xi=new Ty(kE,16,16,sr,ts),Xi.name="DFG_LUT",Xi.minFilter=jn,Xi.magFilter=jn,Xi.wrapS=hs,Xi.wrapT=hs,Xi.generateMipmaps=!1,Xi.needsUpdate=!0),Xi}class kg{constructor(e={}){const{canvas:t=ey(),context:i=null,depth:s=!0,stencil:r=!1,alpha:a=!1,antialias:o=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:c=!1,powerPreference:u="default",failIfMajorPerformanceCaveat:d=!1,reversedDepthBuffer:h=!1,outputBufferType:m=ai}=e;this.isWebGLRenderer=!0;let g;if(i!==null){if(typeof WebGLRenderingContext<"u"&&i instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");g=i.getContextAttributes().alpha}else g=a;const y=m,p=new Set([Ud,Fd,kd]),f=new Set([ai,es,qa,Qr,Nd,Id]),x=new Uint32Array(4),R=new Int32Array(4),S={textures:[],min:[],max:[],resolution:[]};let C=null,w=null;const v=[],M=[];let F=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=gs,this.toneMappingExposure=1,this.transmissionResolutionScale=1;const L=this;let D=!1,B=null,G=null,k=null,W=null;this._outputColorSpace=gi;let Y=0,V=0,le=null,j=-1,Q=null;const se=new rn,he=new rn;let de=null;const ee=new lt(0);let me=0,_e=t.width,Te=t.height,we=1,Ge=null,tt=null;const He=new rn(0,0,_e,Te),ct=new rn(0,0,_e,Te);let rt=!1;const Qe=new $a,qt=new Bd;let zt=!1,on=!1;const Nt=new Dt,En=new z,_t=new rn,mn={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0};let Kt=!1;function ln(){return le===null?we:1}let O=i;function Ce(A,H){return t.getContext(A,H)}let $e,nt,Se,kt,Be,Xe,P,b,X,ue,ae,ve,xe,te,ie,pe,U,re,ne,Me,ge,be,Ve;try{const A={alpha:!0,depth:s,stencil:r,antialias:o,premultipliedAlpha:l,preserveDrawingBuffer:c,powerPreference:u,failIfMajorPerformanceCaveat:d};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${Ld}`),t.addEventListener("webglcontextlost",Ue,!1),t.addEventListener("webglcontextrestored",Ze,!1),t.addEventListener("webglcontextcreationerror",Re,!1),O===null){const H="webgl2";if(O=Ce(H,A),O===null)throw Ce(H)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}Ye()}catch(A){throw t.removeEventListener("webglcontextlost",Ue,!1),t.removeEventListener("webglcontextrestored",Ze,!1),t.removeEventListener("webglcontextcreationerror",Re,!1),yt("WebGLRenderer: "+A.message),A}function Ye(){$e=new BS(O),$e.init(),ge=new TE(O,$e),nt=new CS(O,$e,e,ge),Se=new EE(O,$e),nt.reversedDepthBuffer&&h&&Se.buffers.depth.setReversed(!0),G=O.createFramebuffer(),k=O.createFramebuffer(),W=O.createFramebuffer(),kt=new GS(O),Be=new dE,Xe=new AE(O,$e,Se,Be,nt,ge,kt),P=new zS(L),b=new qy(O),be=new TS(O,b),X=new HS(O,b,kt,be),ue=new qS(O,X,b,be,kt),re=new WS(O,nt,Xe),ie=new PS(Be),ae=new uE(L,P,$e,nt,be,ie),ve=new NE(L,Be),xe=new fE,te=new xE($e),U=new AS(L,P,Se,ue,g,l),pe=new ME(L,ue,nt),Ve=new IE(O,kt,nt,Se),ne=new RS(O,$e,kt),Me=new VS(O,$e,kt),kt.programs=ae.programs,L.capabilities=nt,L.extensions=$e,L.properties=Be,L.renderLists=xe,L.shadowMap=pe,L.state=Se,L.info=kt}y!==ai&&(F=new $S(y,t.width,t.height,o,s,r));const ce=new LE(L,O);this.xr=ce,this.getContext=function(){return O},this.getContextAttributes=function(){return O.getContextAttributes()},this.forceContextLoss=function(){const A=$e.get("WEBGL_lose_context");A&&A.loseContext()},this.forceContextRestore=function(){const A=$e.get("WEBGL_lose_context");A&&A.restoreContext()},this.getPixelRatio=function(){return we},this.setPixelRatio=function(A){A!==void 0&&(we=A,this.setSize(_e,Te,!1))},this.getSize=function(A){return A.set(_e,Te)},this.setSize=function(A,H,J=!0){if(ce.isPresenting){je("WebGLRenderer: Can't change size while VR device is presenting.");return}_e=A,Te=H,t.width=Math.floor(A*we),t.height=Math.floor(H*we),J===!0&&(t.style.width=A+"px",t.style.height=H+"px"),F!==null&&F.setSize(t.width,t.height),this.setViewport(0,0,A,H)},this.getDrawingBufferSize=function(A){return A.set(_e*we,Te*we).floor()},this.setDrawingBufferSize=function(A,H,J){_e=A,Te=H,we=J,t.width=Math.floor(A*J),t.height=Math.floor(H*J),this.setViewport(0,0,A,H)},this.setEffects=function(A){if(y===ai){yt("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(A){for(let H=0;H<A.length;H++)if(A[H].isOutputPass===!0){je("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}F.setEffects(A||[])},this.getCurrentViewport=function(A){return A.copy(se)},this.getViewport=function(A){return A.copy(He)},this.setViewport=function(A,H,J,$){A.isVector4?He.set(A.x,A.y,A.z,A.w):He.set(A,H,J,$),Se.viewport(se.copy(He).multiplyScalar(ln()).round())},this.getScissor=function(A){return A.copy(ct)},this.setScissor=function(A,H,J,$){A.isVector4?ct.set(A.x,A.y,A.z,A.w):ct.set(A,H,J,$),Se.scissor(he.copy(ct).multiplyScalar(ln()).round())},this.getScissorTest=function(){return rt},this.setScissorTest=function(A){Se.setScissorTest(rt=A)},this.setOpaqueSort=function(A){Ge=A},this.setTransparentSort=function(A){tt=A},this.getClearColor=function(A){return A.copy(U.getClearColor())},this.setClearColor=function(){U.setClearColor(...arguments)},this.getClearAlpha=function(){return U.getClearAlpha()},this.setClearAlpha=function(){U.setClearAlpha(...arguments)},this.clear=function(A=!0,H=!0,J=!0){let $=0;if(A){let K=!1;if(le!==null){const Ee=le.texture.format;K=p.has(Ee)}if(K){const Ee=le.texture.type,Pe=f.has(Ee),Ae=U.getClearColor(),Le=U.getClearAlpha(),ze=Ae.r,Je=Ae.g,ut=Ae.b;Pe?(x[0]=ze,x[1]=Je,x[2]=ut,x[3]=Le,O.clearBufferuiv(O.COLOR,0,x)):(R[0]=ze,R[1]=Je,R[2]=ut,R[3]=Le,O.clearBufferiv(O.COLOR,0,R))}else $|=O.COLOR_BUFFER_BIT}H&&($|=O.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),J&&($|=O.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),$!==0&&O.clear($)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(A){A.setRenderer(this),B=A},this.dispose=function(){t.removeEventListener("webglcontextlost",Ue,!1),t.removeEventListener("webglcontextrestored",Ze,!1),t.removeEventListener("webglcontextcreationerror",Re,!1),U.dispose(),xe.dispose(),te.dispose(),Xe.dispose(),Be.dispose(),P.dispose(),ue.dispose(),X.dispose(),be.dispose(),Ve.dispose(),ae.dispose(),ce.dispose(),ce.removeEventListener("sessionstart",ao),ce.removeEventListener("sessionend",Ui),ns.stop()};function Ue(A){A.preventDefault(),xl("WebGLRenderer: Context Lost."),D=!0}function Ze(){xl("WebGLRenderer: Context Restored."),D=!1;const A=kt.autoReset,H=pe.enabled,J=pe.autoUpdate,$=pe.needsUpdate,K=pe.type;Ye(),kt.autoReset=A,pe.enabled=H,pe.autoUpdate=J,pe.needsUpdate=$,pe.type=K}function Re(A){yt("WebGLRenderer: A WebGL context could not be created. Reason: ",A.statusMessage)}function st(A){const H=A.target;H.removeEventListener("dispose",st),Bt(H)}function Bt(A){Bn(A),Be.remove(A)}function Bn(A){const H=Be.get(A).programs;H!==void 0&&(H.forEach(function(J){ae.releaseProgram(J)}),A.isShaderMaterial&&ae.releaseShaderCache(A))}this.renderBufferDirect=function(A,H,J,$,K,Ee){H===null&&(H=mn);const Pe=K.isMesh&&K.matrixWorld.determinantAffine()<0,Ae=ha(A,H,J,$,K);Se.setMaterial($,Pe);let Le=J.index,ze=1;if($.wireframe===!0){if(Le=X.getWireframeAttribute(J),Le===void 0)return;ze=2}const Je=J.drawRange,ut=J.attributes.position;let Oe=Je.start*ze,dt=(Je.start+Je.count)*ze;Ee!==null&&(Oe=Math.max(Oe,Ee.start*ze),dt=Math.min(dt,(Ee.start+Ee.count)*ze)),Le!==null?(Oe=Math.max(Oe,0),dt=Math.min(dt,Le.count)):ut!=null&&(Oe=Math.max(Oe,0),dt=Math.min(dt,ut.count));const $t=dt-Oe;if($t<0||$t===1/0)return;be.setup(K,$,Ae,J,Le);let Rt,Ct=ne;if(Le!==null&&(Rt=b.get(Le),Ct=Me,Ct.setIndex(Rt)),K.isMesh)$.wireframe===!0?(Se.setLineWidth($.wireframeLinewidth*ln()),Ct.setMode(O.LINES)):Ct.setMode(O.TRIANGLES);else if(K.isLine){let gn=$.linewidth;gn===void 0&&(gn=1),Se.setLineWidth(gn*ln()),K.isLineSegments?Ct.setMode(O.LINES):K.isLineLoop?Ct.setMode(O.LINE_LOOP):Ct.setMode(O.LINE_STRIP)}else K.isPoints?Ct.setMode(O.POINTS):K.isSprite&&Ct.setMode(O.TRIANGLES);if(K.isBatchedMesh)if($e.get("WEBGL_multi_draw"))Ct.renderMultiDraw(K._multiDrawStarts,K._multiDrawCounts,K._multiDrawCount);else{const gn=K._multiDrawStarts,ke=K._multiDrawCounts,cn=K._multiDrawCount,mt=Le?b.get(Le).bytesPerElement:1,ss=Be.get($).currentProgram.getUniforms();for(let un=0;un<cn;un++)ss.setValue(O,"_gl_DrawID",un),Ct.render(gn[un]/mt,ke[un])}else if(K.isInstancedMesh)Ct.renderInstances(Oe,$t,K.count);else if(J.isInstancedBufferGeometry){const gn=J._maxInstanceCount!==void 0?J._maxInstanceCount:1/0,ke=Math.min(J.instanceCount,gn);Ct.renderInstances(Oe,$t,ke)}else Ct.render(Oe,$t)};function ca(A,H,J,$){B!==null&&A.isNodeMaterial&&B.setObject($,A),zt===!0&&ie.setState(A,J,!1),A.transparent===!0&&A.side===_i&&A.forceSinglePass===!1?(A.side=Jn,A.needsUpdate=!0,Oi(A,H,$),A.side=Os,A.needsUpdate=!0,Oi(A,H,$),A.side=_i):Oi(A,H,$)}this.compile=function(A,H,J=null){J===null&&(J=A),B!==null&&B.renderStart(A,H,J),w=te.get(J),w.init(H),M.push(w),J.traverseVisible(function(K){K.isLight&&K.layers.test(H.layers)&&(w.pushLight(K),K.castShadow&&w.pushShadow(K))}),A!==J&&A.traverseVisible(function(K){K.isLight&&K.layers.test(H.layers)&&(w.pushLight(K),K.castShadow&&w.pushShadow(K))}),w.setupLights(),B!==null&&B.updateLights(w.state.lightsArray),on=this.localClippingEnabled,zt=ie.init(this.clippingPlanes,on),zt===!0&&ie.setGlobalState(this.clippingPlanes,H),B!==null&&pe.render(w.state.shadowsArray,J,H);const $=new Set;return A.traverse(function(K){if(!(K.isMesh||K.isPoints||K.isLine||K.isSprite))return;const Ee=K.material;if(Ee)if(Array.isArray(Ee))for(let Pe=0;Pe<Ee.length;Pe++){const Ae=Ee[Pe];ca(Ae,J,H,K),$.add(Ae)}else ca(Ee,J,H,K),$.add(Ee)}),w=M.pop(),B!==null&&B.renderEnd(),$},this.compileAsync=function(A,H,J=null){const $=this.compile(A,H,J);return new Promise(K=>{function Ee(){if($.forEach(function(Pe){const Le=Be.get(Pe).currentProgram;(Le===void 0||Le.isReady())&&$.delete(Pe)}),$.size===0){K(A);return}setTimeout(Ee,10)}$e.get("KHR_parallel_shader_compile")!==null?Ee():setTimeout(Ee,10)})};let cr=null;function Bl(A){cr&&cr(A)}function ao(){ns.stop()}function Ui(){ns.start()}const ns=new Mg;ns.setAnimationLoop(Bl),typeof self<"u"&&ns.setContext(self),this.setAnimationLoop=function(A){cr=A,ce.setAnimationLoop(A),A===null?ns.stop():ns.start()},ce.addEventListener("sessionstart",ao),ce.addEventListener("sessionend",Ui),this.render=function(A,H){if(H!==void 0&&H.isCamera!==!0){yt("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(D===!0)return;B!==null&&B.renderStart(A,H);const J=ce.enabled===!0&&ce.isPresenting===!0,$=F!==null&&(le===null||J)&&F.begin(L,le);if(A.matrixWorldAutoUpdate===!0&&A.updateMatrixWorld(),H.parent===null&&H.matrixWorldAutoUpdate===!0&&H.updateMatrixWorld(),ce.enabled===!0&&ce.isPresenting===!0&&(F===null||F.isCompositing()===!1)&&(ce.cameraAutoUpdate===!0&&ce.updateCamera(H),H=ce.getCamera()),A.isScene===!0&&A.onBeforeRender(L,A,H,le),w=te.get(A,M.length),w.init(H),w.state.textureUnits=Xe.getTextureUnits(),M.push(w),Nt.multiplyMatrices(H.projectionMatrix,H.matrixWorldInverse),H.isArrayCamera?qt.setFromArrayCamera(H):Qe.setFromProjectionMatrix(Nt,Ii,H.reversedDepth),on=this.localClippingEnabled,zt=ie.init(this.clippingPlanes,on),C=xe.get(A,v.length),C.init(),v.push(C),this.info.render.frame++,ce.enabled===!0&&ce.isPresenting===!0){const Pe=L.xr.getDepthSensingMesh();Pe!==null&&is(Pe,H,-1/0,L.sortObjects)}is(A,H,0,L.sortObjects),C.finish(),B!==null&&B.updateLights(w.state.lightsArray),L.sortObjects===!0&&C.sort(Ge,tt),Kt=ce.enabled===!1||ce.isPresenting===!1||ce.hasDepthSensing()===!1,Kt&&U.addToRenderList(C,A),this.info.autoReset===!0&&this.info.reset(),zt===!0&&ie.beginShadows();const K=w.state.shadowsArray;if(pe.render(K,A,H),zt===!0&&ie.endShadows(),($&&F.hasRenderPass())===!1){const Pe=C.opaque,Ae=C.transmissive;if(w.setupLights(),H.isArrayCamera){const Le=H.cameras;if(Ae.length>0)for(let ze=0,Je=Le.length;ze<Je;ze++){const ut=Le[ze];wi(Pe,Ae,A,ut)}Kt&&U.render(A);for(let ze=0,Je=Le.length;ze<Je;ze++){const ut=Le[ze];ua(C,A,ut,ut.viewport)}}else Ae.length>0&&wi(Pe,Ae,A,H),Kt&&U.render(A),ua(C,A,H)}le!==null&&V===0&&(Xe.updateMultisampleRenderTarget(le),Xe.updateRenderTargetMipmap(le)),$&&F.end(L),A.isScene===!0&&A.onAfterRender(L,A,H),be.resetDefaultState(),j=-1,Q=null,M.pop(),M.length>0?(w=M[M.length-1],Xe.setTextureUnits(w.state.textureUnits),zt===!0&&ie.setGlobalState(L.clippingPlanes,w.state.camera)):w=null,v.pop(),v.length>0?C=v[v.length-1]:C=null,B!==null&&B.renderEnd()};function is(A,H,J,$){if(A.visible===!1)return;if(A.layers.test(H.layers)){if(A.isGroup)J=A.renderOrder;else if(A.isLOD)A.autoUpdate===!0&&A.update(H);else if(A.isLight)w.pushLight(A),A.castShadow&&w.pushShadow(A);else if(A.isSprite){const Pe=H.isArrayCamera?qt:Qe;if(!A.frustumCulled||A.intersectsFrustum(Pe)){$&&_t.setFromMatrixPosition(A.matrixWorld).applyMatrix4(Nt);const Ae=ue.update(A),Le=A.material;Le.visible&&C.push(A,Ae,Le,J,_t.z,null,H)}}else if(A.isMesh||A.isLine||A.isPoints){const Pe=H.isArrayCamera?qt:Qe;if(!A.frustumCulled||A.intersectsFrustum(Pe)){const Ae=ue.update(A),Le=A.material;if($&&(A.boundingSphere!==void 0?(A.boundingSphere===null&&A.computeBoundingSphere(),_t.copy(A.boundingSphere.center)):(Ae.boundingSphere===null&&Ae.computeBoundingSphere(),_t.copy(Ae.boundingSphere.center)),_t.applyMatrix4(A.matrixWorld).applyMatrix4(Nt)),Array.isArray(Le)){const ze=Ae.groups;for(let Je=0,ut=ze.length;Je<ut;Je++){const Oe=ze[Je],dt=Le[Oe.materialIndex];dt&&dt.visible&&C.push(A,Ae,dt,J,_t.z,Oe,H)}}else Le.visible&&C.push(A,Ae,Le,J,_t.z,null,H)}}}const Ee=A.children;for(let Pe=0,Ae=Ee.length;Pe<Ae;Pe++)is(Ee[Pe],H,J,$)}function ua(A,H,J,$){const{opaque:K,transmissive:Ee,transparent:Pe}=A;w.setupLightsView(J),zt===!0&&ie.setGlobalState(L.clippingPlanes,J),$&&Se.viewport(se.copy($)),K.length>0&&Yt(K,H,J),Ee.length>0&&Yt(Ee,H,J),Pe.length>0&&Yt(Pe,H,J),Se.buffers.depth.setTest(!0),Se.buffers.depth.setMask(!0),Se.buffers.color.setMask(!0),Se.setPolygonOffset(!1)}function wi(A,H,J,$){if((J.isScene===!0?J.overrideMaterial:null)!==null)return;if(w.state.transmissionRenderTarget[$.id]===void 0){const Oe=$e.has("EXT_color_buffer_half_float")||$e.has("EXT_color_buffer_float");w.state.transmissionRenderTarget[$.id]=new Ji(1,1,{generateMipmaps:!0,type:Oe?ts:ai,minFilter:Ns,samples:Math.max(4,nt.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:vt.workingColorSpace})}const Ee=w.state.transmissionRenderTarget[$.id],Pe=$.viewport||se;Ee.setSize(Pe.z*L.transmissionResolutionScale,Pe.w*L.transmissionResolutionScale);const Ae=L.getRenderTarget(),Le=L.getActiveCubeFace(),ze=L.getActiveMipmapLevel();L.setRenderTarget(Ee),L.getClearColor(ee),me=L.getClearAlpha(),me<1&&L.setClearColor(16777215,.5),L.clear(),Kt&&U.render(J);const Je=L.toneMapping;L.toneMapping=gs;const ut=$.viewport;if($.viewport!==void 0&&($.viewport=void 0),w.setupLightsView($),zt===!0&&ie.setGlobalState(L.clippingPlanes,$),Yt(A,J,$),Xe.updateMultisampleRenderTarget(Ee),Xe.updateRenderTargetMipmap(Ee),$e.has("WEBGL_multisampled_render_to_texture")===!1){let Oe=!1;for(let dt=0,$t=H.length;dt<$t;dt++){const Rt=H[dt],{object:Ct,geometry:gn,material:ke,group:cn}=Rt;if(ke.side===_i&&Ct.layers.test($.layers)){const mt=ke.side;ke.side=Jn,ke.needsUpdate=!0,tn(Ct,J,$,gn,ke,cn),ke.side=mt,ke.needsUpdate=!0,Oe=!0}}Oe===!0&&(Xe.updateMultisampleRenderTarget(Ee),Xe.updateRenderTargetMipmap(Ee))}L.setRenderTarget(Ae,Le,ze),L.setClearColor(ee,me),ut!==void 0&&($.viewport=ut),L.toneMapping=Je}function Yt(A,H,J){const $=H.isScene===!0?H.overrideMaterial:null;for(let K=0,Ee=A.length;K<Ee;K++){const Pe=A[K],{object:Ae,geometry:Le,group:ze}=Pe;let Je=Pe.material;Je.allowOverride===!0&&$!==null&&(Je=$),Ae.layers.test(J.layers)&&tn(Ae,H,J,Le,Je,ze)}}function tn(A,H,J,$,K,Ee){B!==null&&K.isNodeMaterial&&B.setObject(A,K),A.onBeforeRender(L,H,J,$,K,Ee),A.modelViewMatrix.multiplyMatrices(J.matrixWorldInverse,A.matrixWorld),A.normalMatrix.getNormalMatrix(A.modelViewMatrix),K.onBeforeRender(L,H,J,$,A,Ee),K.transparent===!0&&K.side===_i&&K.forceSinglePass===!1?(K.side=Jn,K.needsUpdate=!0,L.renderBufferDirect(J,H,$,K,A,Ee),K.side=Os,K.needsUpdate=!0,L.renderBufferDirect(J,H,$,K,A,Ee),K.side=_i):L.renderBufferDirect(J,H,$,K,A,Ee),A.onAfterRender(L,H,J,$,K,Ee)}function nn(A){let H=0;for(const J of A)J.texture!==null&&H++;return H}function Oi(A,H,J){H.isScene!==!0&&(H=mn);const $=Be.get(A),K=w.state.lights,Ee=w.state.shadowsArray,Pe=K.state.version,Ae=ae.getParameters(A,K.state,Ee,H,J,w.state.lightProbeGridArray),Le=ae.getProgramCacheKey(Ae);let ze=$.programs;$.environment=A.isMeshStandardMaterial||A.isMeshLambertMaterial||A.isMeshPhongMaterial?H.environment:null,$.fog=H.fog;const Je=A.isMeshStandardMaterial||A.isMeshLambertMaterial&&!A.envMap||A.isMeshPhongMaterial&&!A.envMap;$.envMap=P.get(A.envMap||$.environment,Je),$.envMapRotation=$.environment!==null&&A.envMap===null?H.environmentRotation:A.envMapRotation,ze===void 0&&(A.addEventListener("dispose",st),ze=new Map,$.programs=ze,$.programVariants=new Map);let ut=ze.get(Le);if(ut!==void 0){if($.currentProgram===ut&&$.lightsStateVersion===Pe)return da(A,Ae),ut}else Ae.uniforms=ae.getUniforms(A),B!==null&&A.isNodeMaterial&&B.build(A,J,Ae),A.onBeforeCompile(Ae,L),ut=ae.acquireProgram(Ae,Le),ze.set(Le,ut),$.uniforms=Ae.uniforms;const Oe=$.uniforms;return(!A.isShaderMaterial&&!A.isRawShaderMaterial||A.clipping===!0)&&(Oe.clippingPlanes=ie.uniform),da(A,Ae),$.needsLights=ys(A),$.lightsStateVersion=Pe,$.needsLights&&(Oe.ambientLightColor.value=K.state.ambient,Oe.lightProbe.value=K.state.probe,Oe.sunLights.value=K.state.sun,Oe.sunLightShadows.value=K.state.sunShadow,Oe.directionalLights.value=K.state.directional,Oe.directionalLightShadows.value=K.state.directionalShadow,Oe.spotLights.value=K.state.spot,Oe.spotLightShadows.value=K.state.spotShadow,Oe.rectAreaLights.value=K.state.rectArea,Oe.ltc_1.value=K.state.rectAreaLTC1,Oe.ltc_2.value=K.state.rectAreaLTC2,Oe.pointLights.value=K.state.point,Oe.pointLightShadows.value=K.state.pointShadow,Oe.hemisphereLights.value=K.state.hemi,Oe.sunShadowMatrix.value=K.state.sunShadowMatrix,Oe.sunShadowCascade.value=K.state.sunShadowCascade,Oe.directionalShadowMatrix.value=K.state.directionalShadowMatrix,Oe.spotLightMatrix.value=K.state.spotLightMatrix,Oe.spotLightMap.value=K.state.spotLightMap,Oe.pointShadowMatrix.value=K.state.pointShadowMatrix),$.numLightProbeGrids=nn(w.state.lightProbeGridArray),$.currentProgram=ut,$.uniformsList=null,ut}function Qn(A,H,J,$,K){const Ee=Be.get(A),Pe=Ee.currentProgram.id+","+$+","+K;let Ae=Ee.programVariants.get(Pe);return Ae===void 0?(Ae=Oi(A,H,J),Ee.programVariants.set(Pe,Ae)):(Ee.currentProgram=Ae,Ee.uniformsList=null,Ee.outputColorSpace=$,Ee.toneMapping=K),Ae}function xs(A){if(A.uniformsList===null){const H=A.currentProgram.getUniforms();A.uniformsList=ol.seqWithValue(H.seq,A.uniforms)}return A.uniformsList}function da(A,H){const J=Be.get(A);J.outputColorSpace=H.outputColorSpace,J.batching=H.batching,J.batchingColor=H.batchingColor,J.instancing=H.instancing,J.instancingColor=H.instancingColor,J.instancingMorph=H.instancingMorph,J.skinning=H.skinning,J.morphTargets=H.morphTargets,J.morphNormals=H.morphNormals,J.morphColors=H.morphColors,J.morphTargetsCount=H.morphTargetsCount,J.numClippingPlanes=H.numClippingPlanes,J.numIntersection=H.numClipIntersection,J.vertexAlphas=H.vertexAlphas,J.vertexTangents=H.vertexTangents,J.toneMapping=H.toneMapping}function ha(A,H,J,$,K){H.isScene!==!0&&(H=mn),Xe.resetTextureUnits();const Ee=H.fog,Pe=$.isMeshStandardMaterial||$.isMeshLambertMaterial||$.isMeshPhongMaterial?H.environment:null,Ae=le===null?L.outputColorSpace:le.isXRRenderTarget===!0?le.texture.colorSpace:vt.workingColorSpace,Le=$.isMeshStandardMaterial||$.isMeshLambertMaterial&&!$.envMap||$.isMeshPhongMaterial&&!$.envMap,ze=P.get($.envMap||Pe,Le),Je=$.vertexColors===!0&&!!J.attributes.color&&J.attributes.color.itemSize===4,ut=!!J.attributes.tangent&&(!!$.normalMap||$.anisotropy>0),Oe=!!J.morphAttributes.position,dt=!!J.morphAttributes.normal,$t=!!J.morphAttributes.color;let Rt=gs;$.toneMapped&&(le===null||le.isXRRenderTarget===!0)&&(Rt=L.toneMapping);const Ct=J.morphAttributes.position||J.morphAttributes.normal||J.morphAttributes.color,gn=Ct!==void 0?Ct.length:0,ke=Be.get($),cn=w.state.lights;if(zt===!0&&(on===!0||A!==Q)){const Pt=A===Q&&$.id===j;ie.setState($,A,Pt)}let mt=!1,ss=!1;$.version===ke.__version?ke.needsLights&&ke.lightsStateVersion!==cn.state.version||K.isBatchedMesh&&ke.batching===!1||!K.isBatchedMesh&&ke.batching===!0||K.isBatchedMesh&&ke.batchingColor===!0&&K._colorsTexture===null||K.isBatchedMesh&&ke.batchingColor===!1&&K._colorsTexture!==null||K.isInstancedMesh&&ke.instancing===!1||!K.isInstancedMesh&&ke.instancing===!0||K.isSkinnedMesh&&ke.skinning===!1||!K.isSkinnedMesh&&ke.skinning===!0||K.isInstancedMesh&&ke.instancingColor===!0&&K.instanceColor===null||K.isInstancedMesh&&ke.instancingColor===!1&&K.instanceColor!==null||K.isInstancedMesh&&ke.instancingMorph===!0&&K.morphTexture===null||K.isInstancedMesh&&ke.instancingMorph===!1&&K.morphTexture!==null||ke.envMap!==ze||$.fog===!0&&ke.fog!==Ee||ke.numClippingPlanes!==void 0&&(ke.numClippingPlanes!==ie.numPlanes||ke.numIntersection!==ie.numIntersection)||ke.vertexAlphas!==Je||ke.vertexTangents!==ut||ke.morphTargets!==Oe||ke.morphNormals!==dt||ke.morphColors!==$t||ke.morphTargetsCount!==gn||ke.numLightProbeGrids!==nn(w.state.lightProbeGridArray)?mt=!0:(ke.outputColorSpace!==Ae||ke.toneMapping!==Rt)&&(ss=!0):(mt=!0,ke.__version=$.version);let un=ke.currentProgram;(mt===!0||ss===!0)&&(un=ss===!0?Qn($,H,K,Ae,Rt):Oi($,H,K),B&&$.isNodeMaterial&&B.onUpdateProgram($,un,ke));let hr=!1,zi=!1,rs=!1;const at=un.getUniforms(),Zt=ke.uniforms;if(Se.useProgram(un.program)&&(hr=!0,zi=!0,rs=!0),$.id!==j&&(j=$.id,zi=!0),hr||Q!==A){Se.buffers.depth.getReversed()&&A.reversedDepth!==!0&&(A._reversedDepth=!0,A.updateProjectionMatrix()),at.setValue(O,"projectionMatrix",A.projectionMatrix),at.setValue(O,"viewMatrix",A.matrixWorldInverse);const dn=at.map.cameraPosition;dn!==void 0&&dn.setValue(O,En.setFromMatrixPosition(A.matrixWorld)),nt.logarithmicDepthBuffer&&at.setValue(O,"logDepthBufFC",2/(Math.log(A.far+1)/Math.LN2)),($.isMeshPhongMaterial||$.isMeshToonMaterial||$.isMeshLambertMaterial||$.isMeshBasicMaterial||$.isMeshStandardMaterial||$.isShaderMaterial)&&at.setValue(O,"isOrthographic",A.isOrthographicCamera===!0),Q!==A&&(Q=A,zi=!0,rs=!0)}if(ke.needsLights&&(cn.state.sunShadowMap.length>0&&at.setValue(O,"sunShadowMap",cn.state.sunShadowMap,Xe),cn.state.directionalShadowMap.length>0&&at.setValue(O,"directionalShadowMap",cn.state.directionalShadowMap,Xe),cn.state.spotShadowMap.length>0&&at.setValue(O,"spotShadowMap",cn.state.spotShadowMap,Xe),cn.state.pointShadowMap.length>0&&at.setValue(O,"pointShadowMap",cn.state.pointShadowMap,Xe)),K.isSkinnedMesh){at.setOptional(O,K,"bindMatrix"),at.setOptional(O,K,"bindMatrixInverse");const Pt=K.skeleton;Pt&&(Pt.boneTexture===null&&Pt.computeBoneTexture(),at.setValue(O,"boneTexture",Pt.boneTexture,Xe))}K.isBatchedMesh&&(at.setOptional(O,K,"batchingTexture"),at.setValue(O,"batchingTexture",K._matricesTexture,Xe),at.setOptional(O,K,"batchingIdTexture"),at.setValue(O,"batchingIdTexture",K._indirectTexture,Xe),at.setOptional(O,K,"batchingColorTexture"),K._colorsTexture!==null&&at.setValue(O,"batchingColorTexture",K._colorsTexture,Xe));const Hn=J.morphAttributes;if((Hn.position!==void 0||Hn.normal!==void 0||Hn.color!==void 0)&&re.update(K,J,un),(zi||ke.receiveShadow!==K.receiveShadow)&&(ke.receiveShadow=K.receiveShadow,at.setValue(O,"receiveShadow",K.receiveShadow)),($.isMeshStandardMaterial||$.isMeshLambertMaterial||$.isMeshPhongMaterial)&&$.envMap===null&&H.environment!==null&&(Zt.envMapIntensity.value=H.environmentIntensity),Zt.dfgLUT!==void 0&&(Zt.dfgLUT.value=FE()),zi){if(at.setValue(O,"toneMappingExposure",L.toneMappingExposure),ke.needsLights&&ur(Zt,rs),Ee&&$.fog===!0&&ve.refreshFogUniforms(Zt,Ee),ve.refreshMaterialUniforms(Zt,$,we,Te,w.state.transmissionRenderTarget[A.id]),ke.needsLights&&ke.numLightProbeGrids>0){const Pt=S;let dn=0;for(const In of w.state.lightProbeGridArray)In.texture!==null&&(Pt.textures[dn]=In.texture,Pt.min[dn]=In.boundingBox.min,Pt.max[dn]=In.boundingBox.max,Pt.resolution[dn]=In.resolution,dn++);for(const In in Pt)Pt[In].length=dn;Zt.probesSH.value=Pt.textures,Zt.probesMin.value=Pt.min,Zt.probesMax.value=Pt.max,Zt.probesResolution.value=Pt.resolution}ol.upload(O,xs(ke),Zt,Xe)}if($.isShaderMaterial&&$.uniformsNeedUpdate===!0&&(ol.upload(O,xs(ke),Zt,Xe),$.uniformsNeedUpdate=!1),$.isSpriteMaterial&&at.setValue(O,"center",K.center),at.setValue(O,"modelViewMatrix",K.modelViewMatrix),at.setValue(O,"normalMatrix",K.normalMatrix),at.setValue(O,"modelMatrix",K.matrixWorld),$.uniformsGroups!==void 0){const Pt=$.uniformsGroups;for(let dn=0,In=Pt.length;dn<In;dn++){const oo=Pt[dn];Ve.update(oo,un),Ve.bind(oo,un)}}return un}function ur(A,H){A.ambientLightColor.needsUpdate=H,A.lightProbe.needsUpdate=H,A.sunLights.needsUpdate=H,A.sunLightShadows.needsUpdate=H,A.directionalLights.needsUpdate=H,A.directionalLightShadows.needsUpdate=H,A.pointLights.needsUpdate=H,A.pointLightShadows.needsUpdate=H,A.spotLights.needsUpdate=H,A.spotLightShadows.needsUpdate=H,A.rectAreaLights.needsUpdate=H,A.hemisphereLights.needsUpdate=H}function ys(A){return A.isMeshLambertMaterial||A.isMeshToonMaterial||A.isMeshPhongMaterial||A.isMeshStandardMaterial||A.isShadowMaterial||A.isShaderMaterial&&A.lights===!0}this.getActiveCubeFace=function(){return Y},this.getActiveMipmapLevel=function(){return V},this.getRenderTarget=function(){return le},this.setRenderTargetTextures=function(A,H,J){const $=Be.get(A);$.__autoAllocateDepthBuffer=A.resolveDepthBuffer===!1,$.__autoAllocateDepthBuffer===!1&&($.__useRenderToTexture=!1),Be.get(A.texture).__webglTexture=H,Be.get(A.depthTexture).__webglTexture=$.__autoAllocateDepthBuffer?void 0:J,$.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(A,H){const J=Be.get(A);J.__webglFramebuffer=H,J.__useDefaultFramebuffer=H===void 0},this.setRenderTarget=function(A,H=0,J=0){le=A,Y=H,V=J;let $=null,K=!1,Ee=!1;if(A){const Ae=Be.get(A);if(Ae.__useDefaultFramebuffer!==void 0){Se.bindFramebuffer(O.FRAMEBUFFER,Ae.__webglFramebuffer),se.copy(A.viewport),he.copy(A.scissor),de=A.scissorTest,Se.viewport(se),Se.scissor(he),Se.setScissorTest(de),j=-1;return}else if(Ae.__webglFramebuffer===void 0)Xe.setupRenderTarget(A);else if(Ae.__hasExternalTextures)Xe.rebindTextures(A,Be.get(A.texture).__webglTexture,Be.get(A.depthTexture).__webglTexture);else if(A.depthBuffer){const Je=A.depthTexture;if(Ae.__boundDepthTexture!==Je){if(Je!==null&&Be.has(Je)&&(A.width!==Je.image.width||A.height!==Je.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Xe.setupDepthRenderbuffer(A)}}const Le=A.texture;(Le.isData3DTexture||Le.isDataArrayTexture||Le.isCompressedArrayTexture)&&(Ee=!0);const ze=Be.get(A).__webglFramebuffer;A.isWebGLCubeRenderTarget?(Array.isArray(ze[H])?$=ze[H][J]:$=ze[H],K=!0):A.samples>0&&Xe.useMultisampledRTT(A)===!1?$=Be.get(A).__webglMultisampledFramebuffer:Array.isArray(ze)?$=ze[J]:$=ze,se.copy(A.viewport),he.copy(A.scissor),de=A.scissorTest}else se.copy(He).multiplyScalar(we).floor(),he.copy(ct).multiplyScalar(we).floor(),de=rt;if(J!==0&&($=G),Se.bindFramebuffer(O.FRAMEBUFFER,$)&&Se.drawBuffers(A,$),Se.viewport(se),Se.scissor(he),Se.setScissorTest(de),K){const Ae=Be.get(A.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_CUBE_MAP_POSITIVE_X+H,Ae.__webglTexture,J)}else if(Ee){const Ae=H;for(let Le=0;Le<A.textures.length;Le++){const ze=Be.get(A.textures[Le]);O.framebufferTextureLayer(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0+Le,ze.__webglTexture,J,Ae)}}else if(A!==null&&J!==0){const Ae=Be.get(A.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,Ae.__webglTexture,J)}j=-1};function dr(A){const H=Be.get(A);return(H.__readFormat!==A.format||H.__readType!==A.type)&&(H.__readFormat=A.format,H.__readType=A.type,H.__formatReadable=nt.textureFormatReadable(A.format),H.__typeReadable=nt.textureTypeReadable(A.type)),H}this.readRenderTargetPixels=function(A,H,J,$,K,Ee,Pe,Ae=0){if(!(A&&A.isWebGLRenderTarget)){yt("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Le=Be.get(A).__webglFramebuffer;if(A.isWebGLCubeRenderTarget&&Pe!==void 0&&(Le=Le[Pe],Array.isArray(Le)&&(Le=Le[0])),Le){Se.bindFramebuffer(O.FRAMEBUFFER,Le);try{const ze=A.textures[Ae],Je=ze.format,ut=ze.type;A.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Ae);const Oe=dr(ze);if(Oe.__formatReadable===!1){yt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(Oe.__typeReadable===!1){yt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}H>=0&&H<=A.width-$&&J>=0&&J<=A.height-K&&O.readPixels(H,J,$,K,ge.convert(Je),ge.convert(ut),Ee)}finally{const ze=le!==null?Be.get(le).__webglFramebuffer:null;Se.bindFramebuffer(O.FRAMEBUFFER,ze)}}},this.readRenderTargetPixelsAsync=async function(A,H,J,$,K,Ee,Pe,Ae=0){if(!(A&&A.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Le=Be.get(A).__webglFramebuffer;if(A.isWebGLCubeRenderTarget&&Pe!==void 0&&(Le=Le[Pe],Array.isArray(Le)&&(Le=Le[0])),Le)if(H>=0&&H<=A.width-$&&J>=0&&J<=A.height-K){Se.bindFramebuffer(O.FRAMEBUFFER,Le);const ze=A.textures[Ae],Je=ze.format,ut=ze.type;A.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Ae);const Oe=dr(ze);if(Oe.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(Oe.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");const dt=O.createBuffer();O.bindBuffer(O.PIXEL_PACK_BUFFER,dt),O.bufferData(O.PIXEL_PACK_BUFFER,Ee.byteLength,O.STREAM_READ),O.readPixels(H,J,$,K,ge.convert(Je),ge.convert(ut),0),O.bindBuffer(O.PIXEL_PACK_BUFFER,null);const $t=le!==null?Be.get(le).__webglFramebuffer:null;Se.bindFramebuffer(O.FRAMEBUFFER,$t);const Rt=O.fenceSync(O.SYNC_GPU_COMMANDS_COMPLETE,0);return O.flush(),await ty(O,Rt,4),O.bindBuffer(O.PIXEL_PACK_BUFFER,dt),O.getBufferSubData(O.PIXEL_PACK_BUFFER,0,Ee),O.bindBuffer(O.PIXEL_PACK_BUFFER,null),O.deleteBuffer(dt),O.deleteSync(Rt),Ee}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(A,H=null,J=0){const $=Math.pow(2,-J),K=Math.floor(A.image.width*$),Ee=Math.floor(A.image.height*$),Pe=H!==null?H.x:0,Ae=H!==null?H.y:0;Xe.setTexture2D(A,0),O.copyTexSubImage2D(O.TEXTURE_2D,J,0,0,Pe,Ae,K,Ee),Se.unbindTexture()},this.copyTextureToTexture=function(A,H,J=null,$=null,K=0,Ee=0){let Pe,Ae,Le,ze,Je,ut,Oe,dt,$t;const Rt=A.isCompressedTexture?A.mipmaps[Ee]:A.image;if(J!==null)Pe=J.max.x-J.min.x,Ae=J.max.y-J.min.y,Le=J.isBox3?J.max.z-J.min.z:1,ze=J.min.x,Je=J.min.y,ut=J.isBox3?J.min.z:0;else{const at=Math.pow(2,-K);Pe=Math.floor(Rt.width*at),Ae=Math.floor(Rt.height*at),A.isDataArrayTexture?Le=Rt.depth:A.isData3DTexture?Le=Math.floor(Rt.depth*at):Le=1,ze=0,Je=0,ut=0}$!==null?(Oe=$.x,dt=$.y,$t=$.z):(Oe=0,dt=0,$t=0);const Ct=ge.convert(H.format),gn=ge.convert(H.type);let ke;H.isData3DTexture?(Xe.setTexture3D(H,0),ke=O.TEXTURE_3D):H.isDataArrayTexture||H.isCompressedArrayTexture?(Xe.setTexture2DArray(H,0),ke=O.TEXTURE_2D_ARRAY):(Xe.setTexture2D(H,0),ke=O.TEXTURE_2D),Se.activeTexture(O.TEXTURE0),Se.pixelStorei(O.UNPACK_FLIP_Y_WEBGL,H.flipY),Se.pixelStorei(O.UNPACK_PREMULTIPLY_ALPHA_WEBGL,H.premultiplyAlpha),Se.pixelStorei(O.UNPACK_ALIGNMENT,H.unpackAlignment);const cn=Se.getParameter(O.UNPACK_ROW_LENGTH),mt=Se.getParameter(O.UNPACK_IMAGE_HEIGHT),ss=Se.getParameter(O.UNPACK_SKIP_PIXELS),un=Se.getParameter(O.UNPACK_SKIP_ROWS),hr=Se.getParameter(O.UNPACK_SKIP_IMAGES);Se.pixelStorei(O.UNPACK_ROW_LENGTH,Rt.width),Se.pixelStorei(O.UNPACK_IMAGE_HEIGHT,Rt.height),Se.pixelStorei(O.UNPACK_SKIP_PIXELS,ze),Se.pixelStorei(O.UNPACK_SKIP_ROWS,Je),Se.pixelStorei(O.UNPACK_SKIP_IMAGES,ut);const zi=A.isDataArrayTexture||A.isData3DTexture,rs=H.isDataArrayTexture||H.isData3DTexture;if(A.isDepthTexture){const at=Be.get(A),Zt=Be.get(H),Hn=Be.get(at.__renderTarget),Pt=Be.get(Zt.__renderTarget);Se.bindFramebuffer(O.READ_FRAMEBUFFER,Hn.__webglFramebuffer),Se.bindFramebuffer(O.DRAW_FRAMEBUFFER,Pt.__webglFramebuffer);for(let dn=0;dn<Le;dn++)zi&&(O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Be.get(A).__webglTexture,K,ut+dn),O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Be.get(H).__webglTexture,Ee,$t+dn)),O.blitFramebuffer(ze,Je,ze+Pe,Je+Ae,Oe,dt,Oe+Pe,dt+Ae,O.DEPTH_BUFFER_BIT,O.NEAREST);Se.bindFramebuffer(O.READ_FRAMEBUFFER,null),Se.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else if(K!==0||A.isRenderTargetTexture||Be.has(A)){const at=Be.get(A),Zt=Be.get(H);Se.bindFramebuffer(O.READ_FRAMEBUFFER,k),Se.bindFramebuffer(O.DRAW_FRAMEBUFFER,W);for(let Hn=0;Hn<Le;Hn++)zi?O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,at.__webglTexture,K,ut+Hn):O.framebufferTexture2D(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,at.__webglTexture,K),rs?O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Zt.__webglTexture,Ee,$t+Hn):O.framebufferTexture2D(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,Zt.__webglTexture,Ee),K!==0?O.blitFramebuffer(ze,Je,ze+Pe,Je+Ae,Oe,dt,Oe+Pe,dt+Ae,O.COLOR_BUFFER_BIT,O.NEAREST):rs?O.copyTexSubImage3D(ke,Ee,Oe,dt,$t+Hn,ze,Je,Pe,Ae):O.copyTexSubImage2D(ke,Ee,Oe,dt,ze,Je,Pe,Ae);Se.bindFramebuffer(O.READ_FRAMEBUFFER,null),Se.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else rs?A.isDataTexture||A.isData3DTexture?O.texSubImage3D(ke,Ee,Oe,dt,$t,Pe,Ae,Le,Ct,gn,Rt.data):H.isCompressedArrayTexture?O.compressedTexSubImage3D(ke,Ee,Oe,dt,$t,Pe,Ae,Le,Ct,Rt.data):O.texSubImage3D(ke,Ee,Oe,dt,$t,Pe,Ae,Le,Ct,gn,Rt):A.isDataTexture?O.texSubImage2D(O.TEXTURE_2D,Ee,Oe,dt,Pe,Ae,Ct,gn,Rt.data):A.isCompressedTexture?O.compressedTexSubImage2D(O.TEXTURE_2D,Ee,Oe,dt,Rt.width,Rt.height,Ct,Rt.data):O.texSubImage2D(O.TEXTURE_2D,Ee,Oe,dt,Pe,Ae,Ct,gn,Rt);Se.pixelStorei(O.UNPACK_ROW_LENGTH,cn),Se.pixelStorei(O.UNPACK_IMAGE_HEIGHT,mt),Se.pixelStorei(O.UNPACK_SKIP_PIXELS,ss),Se.pixelStorei(O.UNPACK_SKIP_ROWS,un),Se.pixelStorei(O.UNPACK_SKIP_IMAGES,hr),Ee===0&&H.generateMipmaps===!0&&H.mipmapsAutoUpdate===!0&&O.generateMipmap(ke),Se.unbindTexture()},this.initRenderTarget=function(A){Be.get(A).__webglFramebuffer===void 0&&Xe.setupRenderTarget(A)},this.initTexture=function(A){A.isCubeTexture?Xe.setTextureCube(A,0):A.isData3DTexture?Xe.setTexture3D(A,0):A.isDataArrayTexture||A.isCompressedArrayTexture?Xe.setTexture2DArray(A,0):Xe.setTexture2D(A,0),Se.unbindTexture()},this.resetState=function(){Y=0,V=0,le=null,Se.reset(),be.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Ii}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;const t=this.getContext();t.drawingBufferColorSpace=vt._getDrawingBufferColorSpace(e),t.unpackColorSpace=vt._getUnpackColorSpace()}}const up={type:"change"},Gd={type:"start"},Fg={type:"end"},Xo=new Fl,dp=new Li,UE=Math.cos(70*ry.DEG2RAD),_n=new z,Yn=2*Math.PI,At={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},zc=1e-6;class Ug extends Gy{constructor(e,t=null){super(e,t),this.state=At.NONE,this.target=new z,this.cursor=new z,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:Wr.ROTATE,MIDDLE:Wr.DOLLY,RIGHT:Wr.PAN},this.touches={ONE:Hr.ROTATE,TWO:Hr.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new z,this._lastQuaternion=new _s,this._lastTargetPosition=new z,this._quat=new _s().setFromUnitVectors(e.up,new z(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new Qu,this._sphericalDelta=new Qu,this._scale=1,this._panOffset=new z,this._rotateStart=new qe,this._rotateEnd=new qe,this._rotateDelta=new qe,this._panStart=new qe,this._panEnd=new qe,this._panDelta=new qe,this._dollyStart=new qe,this._dollyEnd=new qe,this._dollyDelta=new qe,this._dollyDirection=new z,this._mouse=new qe,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=zE.bind(this),this._onPointerDown=OE.bind(this),this._onPointerUp=BE.bind(this),this._onContextMenu=$E.bind(this),this._onMouseWheel=GE.bind(this),this._onKeyDown=WE.bind(this),this._onTouchStart=qE.bind(this),this._onTouchMove=XE.bind(this),this._onMouseDown=HE.bind(this),this._onMouseMove=VE.bind(this),this._interceptControlDown=KE.bind(this),this._interceptControlUp=YE.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=At.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(up),this.update(),this.state=At.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){const t=this.object.position;_n.copy(t).sub(this.target),_n.applyQuaternion(this._quat),this._spherical.setFromVector3(_n),this.autoRotate&&this.state===At.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let i=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(i)&&isFinite(s)&&(i<-Math.PI?i+=Yn:i>Math.PI&&(i-=Yn),s<-Math.PI?s+=Yn:s>Math.PI&&(s-=Yn),i<=s?this._spherical.theta=Math.max(i,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(i+s)/2?Math.max(i,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{const a=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=a!=this._spherical.radius}if(_n.setFromSpherical(this._spherical),_n.applyQuaternion(this._quatInverse),t.copy(this.target).add(_n),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let a=null;if(this.object.isPerspectiveCamera){const o=_n.length();a=this._clampDistance(o*this._scale);const l=o-a;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),r=!!l}else if(this.object.isOrthographicCamera){const o=new z(this._mouse.x,this._mouse.y,0);o.unproject(this.object);const l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=l!==this.object.zoom;const c=new z(this._mouse.x,this._mouse.y,0);c.unproject(this.object),this.object.position.sub(c).add(o),this.object.updateMatrixWorld(),a=_n.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;a!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(a).add(this.object.position):(Xo.origin.copy(this.object.position),Xo.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(Xo.direction))<UE?this.object.lookAt(this.target):(dp.setFromNormalAndCoplanarPoint(this.object.up,this.target),Xo.intersectPlane(dp,this.target))))}else if(this.object.isOrthographicCamera){const a=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),a!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>zc||8*(1-this._lastQuaternion.dot(this.object.quaternion))>zc||this._lastTargetPosition.distanceToSquared(this.target)>zc?(this.dispatchEvent(up),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?Yn/60*this.autoRotateSpeed*e:Yn/60/60*this.autoRotateSpeed}_getZoomScale(e){const t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){_n.setFromMatrixColumn(t,0),_n.multiplyScalar(-e),this._panOffset.add(_n)}_panUp(e,t){this.screenSpacePanning===!0?_n.setFromMatrixColumn(t,1):(_n.setFromMatrixColumn(t,0),_n.crossVectors(this.object.up,_n)),_n.multiplyScalar(e),this._panOffset.add(_n)}_pan(e,t){const i=this.domElement;if(this.object.isPerspectiveCamera){const s=this.object.position;_n.copy(s).sub(this.target);let r=_n.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/i.clientHeight,this.object.matrix),this._panUp(2*t*r/i.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/i.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/i.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;const i=this.domElement.getBoundingClientRect(),s=e-i.left,r=t-i.top,a=i.width,o=i.height;this._mouse.x=s/a*2-1,this._mouse.y=-(r/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(Yn*this._rotateDelta.x/t.clientHeight),this._rotateUp(Yn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(Yn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-Yn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(Yn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-Yn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._rotateStart.set(i,s)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panStart.set(i,s)}}_handleTouchStartDolly(e){const t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{const i=this._getSecondPointerPosition(e),s=.5*(e.pageX+i.x),r=.5*(e.pageY+i.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(Yn*this._rotateDelta.x/t.clientHeight),this._rotateUp(Yn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panEnd.set(i,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){const t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);const a=(e.pageX+t.x)*.5,o=(e.pageY+t.y)*.5;this._updateZoomParameters(a,o)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new qe,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){const t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){const t=e.deltaMode,i={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:i.deltaY*=16;break;case 2:i.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(i.deltaY*=10),i}}function OE(n){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(n.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(n)&&(this._addPointer(n),n.pointerType==="touch"?this._onTouchStart(n):this._onMouseDown(n),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function zE(n){this.enabled!==!1&&(n.pointerType==="touch"?this._onTouchMove(n):this._onMouseMove(n))}function BE(n){switch(this._removePointer(n),this._pointers.length){case 0:this.domElement.releasePointerCapture(n.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(Fg),this.state=At.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:const e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function HE(n){let e;switch(n.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case Wr.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(n),this.state=At.DOLLY;break;case Wr.ROTATE:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=At.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=At.ROTATE}break;case Wr.PAN:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=At.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=At.PAN}break;default:this.state=At.NONE}this.state!==At.NONE&&this.dispatchEvent(Gd)}function VE(n){switch(this.state){case At.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(n);break;case At.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(n);break;case At.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(n);break}}function GE(n){this.enabled===!1||this.enableZoom===!1||this.state!==At.NONE||(n.preventDefault(),this.dispatchEvent(Gd),this._handleMouseWheel(this._customWheelEvent(n)),this.dispatchEvent(Fg))}function WE(n){this.enabled!==!1&&this._handleKeyDown(n)}function qE(n){switch(this._trackPointer(n),this._pointers.length){case 1:switch(this.touches.ONE){case Hr.ROTATE:if(this.enableRotate===!1){this.state=At.NONE;break}this._handleTouchStartRotate(n),this.state=At.TOUCH_ROTATE;break;case Hr.PAN:if(this.enablePan===!1){this.state=At.NONE;break}this._handleTouchStartPan(n),this.state=At.TOUCH_PAN;break;default:this.state=At.NONE}break;case 2:switch(this.touches.TWO){case Hr.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(n),this.state=At.TOUCH_DOLLY_PAN;break;case Hr.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(n),this.state=At.TOUCH_DOLLY_ROTATE;break;default:this.state=At.NONE}break;default:this.state=At.NONE}this.state!==At.NONE&&this.dispatchEvent(Gd)}function XE(n){switch(this._trackPointer(n),this.state){case At.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(n),this.update();break;case At.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(n),this.update();break;case At.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(n),this.update();break;case At.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(n),this.update();break;default:this.state=At.NONE}}function $E(n){this.enabled!==!1&&n.preventDefault()}function KE(n){n.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function YE(n){n.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function ZE(n,e){const t=e*e;return[n.x[2]/e,n.v[2]/e,(n.v[0]**2+n.v[1]**2+n.v[2]**2)/t]}function jE(n){const e=Math.max(...n.surface.sigma2.map(Math.abs),1e-9),t=Math.max(...n.orbit.sigma3,n.point[2],1e-9);return{s2:e,s3top:1.6*t+1e-9}}class Wd{constructor(e,t){this.container=e;const i=document.createElement("div");i.className="curve-title",i.textContent=T("data.reduced"),e.appendChild(i),this.renderer=new kg({antialias:t.antialias,preserveDrawingBuffer:!0}),this.renderer.localClippingEnabled=!0,this.renderer.setPixelRatio(t.pixelRatio),this.renderer.domElement.className="reduced-canvas",e.appendChild(this.renderer.domElement),this.note=document.createElement("p"),this.note.className="note",e.appendChild(this.note),this.scene.background=new lt(1448482),this.camera.up.set(0,0,1),this.camera.position.set(3.2,-3.6,2.2),this.controls=new Ug(this.camera,this.renderer.domElement),this.point=new en(new fs(.05,16,12),new ks({color:16747586,depthTest:!1,transparent:!0})),this.point.renderOrder=3,this.point.visible=!1,this.scene.add(this.group,this.point,new Sg(1.2)),this.resize(),new ResizeObserver(()=>this.resize()).observe(e),new IntersectionObserver(s=>{this.visible=s.some(r=>r.isIntersecting)}).observe(this.renderer.domElement),this.controls.addEventListener("change",()=>{this.dirty=!0})}container;renderer;camera=new Zn(35,1,.01,100);controls;scene=new ag;group=new ki;point;scales=null;note;visible=!1;lastDrawn=-1/0;dirty=!0;resize(){const e=Math.max(200,this.container.clientWidth-8),t=220;this.renderer.setSize(e,t,!1),this.renderer.domElement.style.width=`${e}px`,this.renderer.domElement.style.height=`${t}px`,this.camera.aspect=e/t,this.camera.updateProjectionMatrix()}setNote(e){this.note.textContent=e??"",e!==null&&this.set(null)}set(e){for(const w of[...this.group.children]){this.group.remove(w);const v=w;v.geometry?.dispose(),v.material?.dispose()}if(this.scales=e===null?null:jE(e),this.dirty=!0,e===null||this.scales===null)return;const{s2:t,s3top:i}=this.scales,s=(w,v,M)=>new z(w,v/t,2*M/i-1),r=[new Li(new z(0,0,-1),1)],{sigma1:a,sigma2:o,sigma3:l}=e.surface,c=[];a.forEach((w,v)=>o.forEach((M,F)=>c.push(...s(w,M,l[v]?.[F]??NaN).toArray())));const u=[],d=o.length;for(let w=0;w+1<a.length;w++)for(let v=0;v+1<d;v++){const M=w*d+v;u.push(M,M+d,M+1,M+1,M+d,M+d+1)}const h=new Ot;h.setAttribute("position",new an(c,3)),h.setIndex(u);const m={color:9417727,transparent:!0,opacity:.25,side:_i,clippingPlanes:r};this.group.add(new en(h,new ks({...m,depthWrite:!1}))),this.group.add(new en(h.clone(),new ks({...m,wireframe:!0,opacity:.25})));const{h:g,gamma:y}=e.plane,p=(w,v)=>s(w,v,2*(g-y*w)),f=new Ot().setFromPoints([p(-1,-t),p(1,-t),p(1,t),p(-1,t)]);f.setIndex([0,1,2,0,2,3]);const x=new ks({color:16757575,transparent:!0,opacity:.22,side:_i,depthWrite:!1,clippingPlanes:[...r,new Li(new z(0,0,1),1)]});this.group.add(new en(f,x));const R=e.orbit,S=new Ot().setFromPoints(R.sigma1.map((w,v)=>s(w,R.sigma2[v]??NaN,R.sigma3[v]??NaN))),C=new Fi(S,new ci({color:5882879,depthTest:!1,transparent:!0}));C.renderOrder=2,this.group.add(C),this.point.visible=!0}update(e,t){if(this.scales!==null&&e!==null){const[s,r,a]=ZE(e,t);this.point.position.set(s,r/this.scales.s2,2*a/this.scales.s3top-1)}this.point.visible=this.scales!==null&&e!==null;const i=performance.now();!this.visible||!this.dirty&&i-this.lastDrawn<Wd.MIN_INTERVAL||(this.lastDrawn=i,this.dirty=!1,this.controls.update(),this.renderer.render(this.scene,this.camera))}static MIN_INTERVAL=250}class JE{constructor(e){const t=new yg;t.aspect=.5;const i=new qe;this.setEyeSeparation=function(s){t.eyeSep=s},this.setSize=function(s,r){e.setSize(s,r)},this.render=function(s,r){s.matrixWorldAutoUpdate===!0&&s.updateMatrixWorld(),r.parent===null&&r.matrixWorldAutoUpdate===!0&&r.updateMatrixWorld(),t.update(r);const a=e.autoClear;e.getSize(i),e.autoClear=!1,e.clear(),e.setScissorTest(!0),e.setScissor(0,0,i.width/2,i.height),e.setViewport(0,0,i.width/2,i.height),e.render(s,t.cameraL),e.setScissor(i.width/2,0,i.width/2,i.height),e.setViewport(i.width/2,0,i.width/2,i.height),e.render(s,t.cameraR),e.setScissorTest(!1),e.autoClear=a}}}const $o=(n,e)=>n[0]*e[0]+n[1]*e[1]+n[2]*e[2],Bc=(n,e)=>[n[0]+e[0],n[1]+e[1],n[2]+e[2]],Hc=(n,e)=>[n[0]-e[0],n[1]-e[1],n[2]-e[2]],Ki=(n,e)=>[n[0]*e,n[1]*e,n[2]*e];function QE(n,e){return 4*Math.sqrt(Math.max(Math.abs(e),1)*Math.max(n,0))}function eA(n,e,t,i,s){const r=Math.hypot(...t),a=Math.hypot(...n.direction);if(!(r>0)||!(a>0)||!(i>0)||!Number.isFinite(r)||!Number.isFinite(a)||![...e,...n.origin].every(Number.isFinite))return null;const o=Ki(t,1/r),l=Ki(n.direction,1/a),c=Bc(e,t),u=Hc(c,n.origin),d=$o(o,l),h=Math.abs(d)>1e-9?$o(o,u)/d:-1,m=h>0?Bc(n.origin,Ki(l,h)):Bc(n.origin,Ki(l,Math.max($o(u,l),0)));let g=Hc(m,c);g=Hc(g,Ki(o,$o(g,o)));let y=Ki(g,1/i);const p=Math.hypot(...y);if(!Number.isFinite(p))return null;const f=Math.max(s,0);return p>f?(y=p>0?Ki(y,f/p):[0,0,0],{v:y,speed:f,capped:!0}):{v:y,speed:p,capped:!1}}function tA(n,e,t,i){const s=Ki(e,t),r=Math.hypot(...s);if(r>=i)return s;if(r>1e-12*i)return Ki(s,i/r);const a=[-n[1],n[0],0],o=Math.hypot(...a);return o>1e-12*Math.hypot(...n)&&o>0?Ki(a,i/o):[i,0,0]}function nA(n,e,t){const i=n.intersectSphere(new no(e,t),new z);if(i!==null)return i.sub(e);const s=n.closestPointToPoint(e,new z).sub(e),r=s.length();return r>0?s.multiplyScalar(t/r):new z(0,0,-t)}class iA{constructor(e,t,i,s,r,a){this.canvas=e,this.camera=t,this.controls=i,this.bob=s,this.onDrag=r,this.sphere=a,e.addEventListener("pointerdown",o=>this.down(o),{capture:!0}),e.addEventListener("pointermove",o=>this.move(o)),e.addEventListener("pointerup",o=>this.up(o)),e.addEventListener("pointercancel",o=>this.up(o))}canvas;camera;controls;bob;onDrag;sphere;dragging=!1;raycaster=new bg;get active(){return this.dragging}ray(e){const t=this.canvas.getBoundingClientRect(),i=new qe((e.clientX-t.left)/t.width*2-1,-((e.clientY-t.top)/t.height)*2+1);return this.raycaster.setFromCamera(i,this.camera),this.raycaster.ray}position(e){const{pivot:t,length:i}=this.sphere(),s=nA(this.ray(e),t,i);return[s.x,s.y,s.z]}down(e){e.button!==0||!this.bob.visible||(this.ray(e),this.raycaster.intersectObject(this.bob,!1).length!==0&&(this.dragging=!0,this.controls.enabled=!1,this.canvas.setPointerCapture?.(e.pointerId),e.stopImmediatePropagation(),this.onDrag(this.position(e),"start")))}move(e){this.dragging&&this.onDrag(this.position(e),"move")}up(e){this.dragging&&(this.dragging=!1,this.controls.enabled=!0,this.onDrag(this.position(e),"end"))}}class sA{constructor(e,t,i,s,r,a,o,l){this.canvas=e,this.camera=t,this.controls=i,this.handle=s,this.occluder=r,this.grabRadius=a,this.pullBasis=o,this.onPull=l,e.addEventListener("pointerdown",c=>this.down(c),{capture:!0}),e.addEventListener("pointermove",c=>this.move(c)),e.addEventListener("pointerup",c=>this.up(c)),e.addEventListener("pointercancel",c=>this.up(c))}canvas;camera;controls;handle;occluder;grabRadius;pullBasis;onPull;basis=null;last=null;moved=!1;raycaster=new bg;tmp=new z;get active(){return this.basis!==null}ray(e){const t=this.canvas.getBoundingClientRect(),i=new qe((e.clientX-t.left)/t.width*2-1,-((e.clientY-t.top)/t.height)*2+1);return this.raycaster.setFromCamera(i,this.camera),this.raycaster.ray}pulled(e){if(this.basis===null)return null;const t=this.ray(e),{pivot:i,x:s,arrowScale:r,vmax:a}=this.basis;return eA({origin:[t.origin.x,t.origin.y,t.origin.z],direction:[t.direction.x,t.direction.y,t.direction.z]},i,s,r,a)}released(e,t,i){const{pivot:s,x:r,arrowScale:a}=t,o=this.tmp.set(s[0]+r[0]+i[0]*a,s[1]+r[1]+i[1]*a,s[2]+r[2]+i[2]*a).project(this.camera),l=this.canvas.getBoundingClientRect(),c={x:l.left+(o.x+1)/2*l.width,y:l.top+(1-o.y)/2*l.height};return{pointer:{x:e.clientX,y:e.clientY},tip:c,v:[...i]}}down(e){if(e.button!==0||!this.handle.visible)return;const t=this.ray(e),i=this.handle.getWorldPosition(this.tmp),s=this.grabRadius();if(t.distanceToPoint(i)>s)return;const r=this.raycaster.intersectObject(this.occluder,!1)[0];if(r!==void 0&&r.distance<i.sub(t.origin).dot(t.direction)-s)return;const a=this.pullBasis();a!==null&&(this.basis=a,this.moved=!1,this.controls.enabled=!1,this.canvas.setPointerCapture?.(e.pointerId),e.stopImmediatePropagation(),this.onPull(a.x,null,"start"))}move(e){this.basis!==null&&(this.moved=!0,this.onPull(this.basis.x,this.pulled(e),"move"))}up(e){if(this.basis===null)return;const t=this.moved?this.pulled(e):null,i=this.basis.x;t!==null&&(this.last=this.released(e,this.basis,t.v)),this.basis=null,this.controls.enabled=!0,this.onPull(i,t,"end")}}const hp=(n,e)=>[n[1]*e[2]-n[2]*e[1],n[2]*e[0]-n[0]*e[2],n[0]*e[1]-n[1]*e[0]],Ia=(n,e)=>[n[0]*e,n[1]*e,n[2]*e],rA=(n,e)=>[n[0]-e[0],n[1]-e[1],n[2]-e[2]];function aA(n){const e=[n?.gravity_x??0,n?.gravity_y??0,n?.gravity_z??-1],t=Math.hypot(...e);return t>0?Ia(e,1/t):[0,0,-1]}function oA(n,e,t,i,s){const r=Math.hypot(...n.x),a=Ia(n.v,e),o=Ia(n.a,e),l=rA(n.x,s);return{velocity:n.v,momentum:a,gravity:Ia(i,e*t),tension:r>0?Ia(n.x,-n.tension/r):[0,0,0],net:o,angularMomentum:hp(l,a),torque:hp(l,o)}}function td(n,e,t){const i=Math.max(Math.abs(t),1),s=.5*n/(e*i),r=Math.sqrt(i/n);return{velocity:.25,momentum:.25,gravity:s,tension:s,net:s,angularMomentum:.5*n/(e*n*n*r),torque:s/n}}const Og=15127459;function lA(n){const e=n/20,t=10**Math.floor(Math.log10(e)),i=e/t;return(i<1.5?1:i<3.5?2:5)*t}class Vc{sprite;canvas=document.createElement("canvas");texture;text="";constructor(e,t){this.canvas.width=256,this.canvas.height=64,this.texture=new Py(this.canvas),this.sprite=new dg(new cg({map:this.texture,depthTest:!1,transparent:!0})),this.sprite.scale.set(4*t,t,1),this.set(e)}set(e){if(e===this.text)return;this.text=e;const t=this.canvas.getContext("2d");t!==null&&(t.clearRect(0,0,256,64),t.font="bold 44px system-ui, sans-serif",t.fillStyle=`#${Og.toString(16)}`,t.textAlign="center",t.textBaseline="middle",t.fillText(e,128,32),this.texture.needsUpdate=!0)}}function fp(n){const e=new Ot().setFromPoints(n);return new io(e,new ci({color:Og}))}class cA{ruler=new ki;protractor=new ki;dial=new ki;thetaLabel=new Vc("",.1);built=-1;pivot=new z;moved={ruler:[0,0],protractor:[0,0]};constructor(){this.ruler.visible=!1,this.protractor.visible=!1,this.protractor.add(this.dial,this.thetaLabel.sprite)}build(e){if(e===this.built)return;this.built=e;for(const l of[this.ruler,this.dial])for(const c of[...l.children])l.remove(c),(c instanceof en||c instanceof io||c instanceof dg)&&(c.geometry.dispose(),c.material.dispose());const t=lA(2*e),i=1.1*e,s=[new z(i,0,-e),new z(i,0,e)],r=Math.floor(e/t+1e-9);for(let l=-r;l<=r;l++){const c=l*t,u=l%5===0;if(s.push(new z(i,0,c),new z(i-(u?.08:.04)*e,0,c)),u){const d=new Vc(`${+c.toPrecision(6)} m`,.07*e);d.sprite.position.set(i+.16*e,0,c),this.ruler.add(d.sprite)}}this.ruler.add(fp(s));const a=.4*e,o=[];for(let l=0;l<360;l+=2){const c=l*Math.PI/180,u=(l+2)*Math.PI/180;o.push(new z(a*Math.sin(c),0,-a*Math.cos(c)),new z(a*Math.sin(u),0,-a*Math.cos(u)))}for(let l=0;l<360;l+=10){const c=l*Math.PI/180,u=l%30===0?.85:.92;if(o.push(new z(a*Math.sin(c),0,-a*Math.cos(c)),new z(u*a*Math.sin(c),0,-u*a*Math.cos(c))),l%30===0&&l<=180){const d=new Vc(`${l}°`,.06*e);d.sprite.position.set(1.2*a*Math.sin(c),0,-1.2*a*Math.cos(c)),this.dial.add(d.sprite)}}o.push(new z(0,0,-a),new z(0,0,a)),this.dial.add(fp(o))}face(e){const t=this.ruler.position;this.ruler.rotation.set(0,0,Math.atan2(e.x-t.x,-(e.y-t.y))),this.placeRuler()}placeRuler(){const e=this.ruler.rotation.z,[t,i]=this.moved.ruler,s=this.built>0?this.built:1;this.ruler.position.set(this.pivot.x+t*s*Math.cos(e),this.pivot.y+t*s*Math.sin(e),this.pivot.z+i*s)}update(e,t,i,s,r,a,o={ruler:[0,0],protractor:[0,0]}){if(this.ruler.visible=s,this.protractor.visible=r,!s&&!r)return;this.build(i),this.moved=o,this.pivot.copy(e),this.ruler.position.copy(e),this.face(a);const l=Math.atan2(t[1],t[0]),[c,u]=o.protractor,d=Number.isFinite(l)?Math.cos(l):1,h=Number.isFinite(l)?Math.sin(l):0;this.protractor.position.set(e.x+c*i*d,e.y+c*i*h,e.z+u*i);const m=Math.atan2(Math.hypot(t[0],t[1]),-t[2]);this.dial.rotation.set(0,0,Number.isFinite(l)?l:0);const g=.72*i,y=m/2;this.thetaLabel.sprite.position.set(g*Math.sin(y)*Math.cos(l),g*Math.sin(y)*Math.sin(l),-g*Math.cos(y)),this.thetaLabel.sprite.scale.set(.4*i,.1*i,1),this.thetaLabel.set(`θ = ${(m*180/Math.PI).toFixed(1)}°`)}}class uA{constructor(e){this.renderer=e,this.stereo.aspect=1}renderer;stereo=new yg;render(e,t,i,s,r){const a=this.renderer,o=a.getContext();t.focus=s,t.updateMatrixWorld(),this.stereo.eyeSep=i,this.stereo.update(t);const l=a.autoClear,c=e.background;a.autoClear=!1,e.background=null,a.setClearColor(r,1),a.clear();try{o.colorMask(!0,!1,!1,!0),a.render(e,this.stereo.cameraL),a.clearDepth(),o.colorMask(!1,!0,!0,!0),a.render(e,this.stereo.cameraR)}finally{o.colorMask(!0,!0,!0,!0),e.background=c,a.autoClear=l}}}function dA(n,e,t,i=.9){const s=e*Math.PI/360,r=Math.atan(Math.tan(s)*Math.max(t,.001)),a=Math.min(s,r);return n/Math.sin(a*i)}function hA(n,e){const t=[],s=a=>{for(let o=0;o<96;o++)t.push(a(2*Math.PI*o/96),a(2*Math.PI*(o+1)/96))};for(let a=0;a<6;a++){const o=a*Math.PI/6;s(l=>new z(Math.sin(l)*Math.cos(o),Math.sin(l)*Math.sin(o),Math.cos(l)))}for(const a of[-.75,-.5,-.25,.25,.5,.75]){const o=Math.sqrt(1-a*a);s(l=>new z(o*Math.cos(l),o*Math.sin(l),a))}const r=new io(new Ot().setFromPoints(t),new ci({color:n,transparent:!0,opacity:e}));return r.visible=!1,r}function fA(n,e,t,i){const s=t.position.clone().sub(n).normalize(),r=new z().crossVectors(s,new z(0,0,1));r.lengthSq()<1e-12&&r.set(1,0,0),r.normalize();const a=new z().crossVectors(s,r).normalize(),o=t.position.distanceTo(n),l=e*Math.sqrt(Math.max(0,1-e*e/(o*o))),c=n.clone().addScaledVector(s,e*e/o),u=i.getBoundingClientRect(),d={left:1/0,right:-1/0,top:1/0,bottom:-1/0};for(let h=0;h<64;h++){const m=2*Math.PI*h/64,g=c.clone().addScaledVector(r,l*Math.cos(m)).addScaledVector(a,l*Math.sin(m)).project(t),y=u.left+(g.x+1)/2*u.width,p=u.top+(1-g.y)/2*u.height;d.left=Math.min(d.left,y),d.right=Math.max(d.right,y),d.top=Math.min(d.top,p),d.bottom=Math.max(d.bottom,p)}return d}const sn=180/Math.PI;function Ka(n){return{theta:Math.atan2(Math.hypot(n[0],n[1]),-n[2]),phi:Math.atan2(n[1],n[0])}}function pp(n){let e=n%(2*Math.PI);return e<=-Math.PI&&(e+=2*Math.PI),e>Math.PI&&(e-=2*Math.PI),e}class pA{constructor(e=8){this.maxLaps=e}maxLaps;acc=0;since=null;laps=[];get running(){return this.since!==null}reading(e){return this.acc+(this.since===null?0:Math.max(0,e-this.since))}start(e){this.since===null&&(this.since=e)}stop(e){this.since!==null&&(this.acc=this.reading(e),this.since=null)}lap(e){this.laps.push(this.reading(e)),this.laps.length>this.maxLaps&&this.laps.shift()}reset(){[this.acc,this.since,this.laps]=[0,null,[]]}}const Ko={kind:null,period:null,advance:null,precession:null,lowPerPeriod:1,intervals:0,amplitude:null,thetaMin:null,thetaMax:null,from:null,to:null};function zg(n,e,t){const i=e.t-n.t,[s,r,a,o,l,c]=[n.x[t],e.x[t],i*n.v[t],i*e.v[t],i*i*n.a[t],i*i*e.a[t]];if(!Number.isFinite(l)||!Number.isFinite(c)){const g=r-s;return[s,a,3*g-2*a-o,-2*g+a+o,0,0]}const u=l/2,d=r-s-a-u,h=o-a-2*u,m=c-2*u;return[s,a,u,10*d-4*h+m/2,-15*d+7*h-m,6*d-3*h+m/2]}function mp(n,e,t,i){const s=zg(n,e,t),r=s[0]+i*(s[1]+i*(s[2]+i*(s[3]+i*(s[4]+i*s[5])))),a=s[1]+i*(2*s[2]+i*(3*s[3]+i*(4*s[4]+i*5*s[5])));return[r,a/(e.t-n.t)]}function mA(n,e){const t=zg(n,e,2),i=a=>t[1]+a*(2*t[2]+a*(3*t[3]+a*(4*t[4]+a*5*t[5])));let[s,r]=[0,1];if(!(i(s)<0&&i(r)>=0))return-n.v[2]/(e.v[2]-n.v[2]);for(;r-s>1e-16;){const a=.5*(s+r);if(a<=s||a>=r)break;i(a)<0?s=a:r=a}return .5*(s+r)}class gA{constructor(e=1e-7,t=10,i=.02){this.minRise=e,this.keep=t,this.planarRatio=i}minRise;keep;planarRatio;prev=null;phi=0;lows=[];lowCount=0;zLow=1/0;zHigh=-1/0;rMax=0;thMax=0;thMin=1/0;reset(){this.prev=null,this.phi=0,this.lows=[],this.lowCount=0,this.zLow=1/0,this.zHigh=-1/0,this.rMax=0,this.thMax=0,this.thMin=1/0}push(e){const t=this.prev;if(t!==null&&e.t<=t.t)return;const i=Math.atan2(e.x[1],e.x[0]),s=Math.hypot(e.x[0],e.x[1]),r=Math.atan2(s,-e.x[2]);if(t===null){this.phi=i,this.prev=e,this.zLow=this.zHigh=e.x[2],[this.rMax,this.thMax,this.thMin]=[s,r,r];return}const a=this.phi;this.phi=a+pp(i-Math.atan2(t.x[1],t.x[0])),this.zLow=Math.min(this.zLow,e.x[2]),this.zHigh=Math.max(this.zHigh,e.x[2]);const[o,l]=[t.v[2],e.v[2]];if(o<0&&l>=0){const c=mA(t,e),u=t.t+c*(e.t-t.t),[d,h]=mp(t,e,0,c),[m,g]=mp(t,e,1,c),y=a+pp(Math.atan2(m,d)-Math.atan2(t.x[1],t.x[0]));if(this.lows.length===0||this.zHigh-this.zLow>this.minRise){const p=Math.hypot(h,g)||1,f=Math.hypot(d,m),x=Math.max(this.rMax,f);this.lows.push({t:u,phi:y,dir:[h/p,g/p],through:x>0&&f<=this.planarRatio*x,thetaMax:this.thMax,thetaMin:Math.min(this.thMin,r)}),this.lows.length>2*this.keep+1&&this.lows.shift(),this.lowCount++}this.zLow=this.zHigh=e.x[2],[this.rMax,this.thMax,this.thMin]=[s,r,r],this.prev=e;return}this.rMax=Math.max(this.rMax,s),this.thMax=Math.max(this.thMax,r),this.thMin=Math.min(this.thMin,r),this.prev=e}reading(){const e=this.lows,t=e[e.length-1];if(t===void 0||e.length<2)return{...Ko};const i={thetaMin:Math.min(t.thetaMin,this.thMin),thetaMax:Math.max(t.thetaMax,this.thMax)};if(t.through){const l=[];let c=0;for(let p=e.length-1;p>=0&&l.length<=this.keep;p--){const f=e[p];if(!f.through)break;f.dir[0]*t.dir[0]+f.dir[1]*t.dir[1]>0&&l.push(f),c=p}const u=l.length-1,d=l[u],h=e[e.length-2],m=h.dir[0]*t.dir[0]+h.dir[1]*t.dir[1]>0?1:2,g=e.slice(Math.max(c,e.indexOf(d))+1),y=g.length>0?Math.sqrt(g.reduce((p,f)=>p+f.thetaMax**2,0)/g.length):t.thetaMax;return{...Ko,kind:"swing",period:u<1?null:(t.t-d.t)/u,lowPerPeriod:m,intervals:Math.max(u,0),amplitude:y,...i,from:u<1?null:d.t,to:t.t}}let s=e.length-1;for(;s>0&&e.length-1-s<this.keep&&!e[s-1].through;)s--;const r=e[s],a=e.length-1-s;if(a<1)return{...Ko,kind:"orbit",...i};const o=(t.phi-r.phi)/a;return{...Ko,kind:"orbit",period:(t.t-r.t)/a,advance:o,precession:Math.sign(o)*(2*Math.abs(o)-2*Math.PI),intervals:a,...i,from:r.t,to:t.t}}}function vA(n){let[e,t]=[1,Math.sqrt(1-n)];for(let i=0;i<40&&Math.abs(e-t)>1e-16*e;i++)[e,t]=[(e+t)/2,Math.sqrt(e*t)];return Math.PI/(2*e)}function _A(n,e,t,i){if(!(e>0)||!(n>0)||!(i>=0)||i>=Math.PI)return null;const s=e/n,r=Math.sqrt(s-t**2/4);return r>0?4*vA(Math.sin(i/2)**2)/r:null}function Bg(n,e,t,i,s){const r=.5*e*(n.v[0]**2+n.v[1]**2+n.v[2]**2),a=n.energy-r+e*Math.abs(t)*i,o=-s;return{kinetic:r,potential:a,lost:o,total:r+a+o}}function xA(n,e){return .5*(n.power+e.power)*(e.t-n.t)}function yA(n,e,t=null){const i=n.kind===null?e?.kind==="planar":n.kind==="swing",s=e===null||e.period_z_infinite||e.period_z===null?null:e.period_z;let r=s;i&&s!==null&&e?.kind!=="planar"&&(r=n.lowPerPeriod*s),e===null&&(r=t);const a=e?.azimuth_advance??null,o=l=>l===null?null:Math.sign(l)*(2*Math.abs(l)-2*Math.PI);return{swing:i,period:[n.period,r],advance:[i?null:n.advance,i?null:a],precession:[i?null:n.precession,i?null:o(a)]}}const gp=512,nr=4e3,bA=4e3,wA=2e5,SA=3,MA="unfused",EA=["t [s]","x1 [m]","x2 [m]","x3 [m]","v1 [m/s]","v2 [m/s]","v3 [m/s]","energy [J]","j3 [kg m^2/s]","tension [N]","power [W]","a1 [m/s^2]","a2 [m/s^2]","a3 [m/s^2]","pivot1 [m]","pivot2 [m]","pivot3 [m]","taut [1]","error_x [m]"];function vp(){return{t:[],dE:[],dJ3:[],z:[],zdot:[],tension:[],frames:[]}}function $i(n,e,t){return n+(e-n)*t}function AA(n,e,t){const i=(o,l)=>[$i(o[0],l[0],t),$i(o[1],l[1],t),$i(o[2],l[2],t)],s=i(n.x,e.x),r=$i(Math.hypot(...n.x),Math.hypot(...e.x),t),a=Math.hypot(...s);if(a>0)for(let o=0;o<3;o++)s[o]=s[o]*(r/a);return{t:$i(n.t,e.t,t),x:s,v:i(n.v,e.v),energy:$i(n.energy,e.energy,t),j3:$i(n.j3,e.j3,t),tension:$i(n.tension,e.tension,t),power:$i(n.power,e.power,t),a:i(n.a,e.a),pivot:i(n.pivot,e.pivot),taut:n.taut&&e.taut,errorX:n.errorX<0||e.errorX<0?-1:$i(n.errorX,e.errorX,t)}}function TA(n,e,t){return n===null||e.epoch!==n.epoch||t!==null&&e.t<t}function _p(n,e,t){let i=0,s=n.length;for(;i<s;){const r=i+s>>1,a=n[r].t;(t?a<e:a<=e)?i=r+1:s=r}return i}class qd{status=null;frames=[];trail=[];history=vp();trajectory=[];trajectoryTruncated=!1;methods=[];reference=null;tensionExtremes=null;playT=null;exact=null;exactError=null;errors=[];events=[];connected=!1;tickHz=60;work=0;periodTimer=new gA;historyStride=1;historyCount=0;disconnected=!1;listeners=new Set;subscribe(e){return this.listeners.add(e),()=>this.listeners.delete(e)}emit(){for(const e of this.listeners)e()}onStatus(e){const t=this.disconnected||TA(this.status,e,this.latest()?.t??null);this.disconnected=!1,this.status=e,t&&this.clear();const i=this.methods[this.methods.length-1];t||i===void 0?this.methods=[{t:e.t,method:e.method,dt:e.dt}]:(i.method!==e.method||i.dt!==e.dt)&&this.methods.push({t:e.t,method:e.method,dt:e.dt}),this.emit()}clear(){this.frames=[],this.trail=[],this.history=vp(),this.trajectory=[],this.trajectoryTruncated=!1,this.reference=null,this.tensionExtremes=null,this.playT=null,this.exact=null,this.exactError=null,this.events=[],this.work=0,this.periodTimer.reset(),this.historyStride=1,this.historyCount=0}onError(e){this.errors.push(e),this.errors.length>20&&this.errors.shift(),this.emit()}onEvent(e){const t=this.events;this.events=i_(t,e,this.status?.epoch??null),this.events!==t&&(this.work-=e.energy_lost,this.emit())}setConnected(e){this.connected=e,e||(this.disconnected=!0),this.emit()}setExact(e,t=null){this.exact=e,this.exactError=t,this.emit()}onFrames(e){for(const t of e){const i=this.frames[this.frames.length-1];if(i!==void 0&&t.t<i.t)continue;i!==void 0&&t.t===i.t?this.frames.pop():i!==void 0&&(this.work+=xA(i,t)),this.frames.push(t),this.periodTimer.push(t),this.reference===null&&(this.reference={energy:t.energy,j3:t.j3});const s=this.tensionExtremes;s===null?this.tensionExtremes={min:t.tension,tMin:t.t,max:t.tension,tMax:t.t}:(t.tension<s.min&&([s.min,s.tMin]=[t.tension,t.t]),t.tension>s.max&&([s.max,s.tMax]=[t.tension,t.t])),this.pushTrail(t),this.pushHistory(t),this.trajectory.length<wA?this.trajectory.push(t):this.trajectoryTruncated=!0,this.playT===null&&(this.playT=t.t)}this.frames.length>gp&&this.frames.splice(0,this.frames.length-gp)}pushTrail(e){const t=this.trail[this.trail.length-1];t!==void 0&&t.t===e.t&&this.trail.pop(),this.trail.push(e),this.trail.length>nr&&this.trail.splice(0,this.trail.length-nr)}pushHistory(e){const t=this.reference;if(t===null)return;const i=this.history;if(!(i.t.length>0&&e.t<=i.t[i.t.length-1])&&this.historyCount++%this.historyStride===0&&(i.t.push(e.t),i.dE.push(e.energy-t.energy),i.dJ3.push(e.j3-t.j3),i.z.push(e.x[2]),i.zdot.push(e.v[2]),i.tension.push(e.tension),i.frames.push(e),i.t.length>bA)){const s=r=>r.filter((a,o)=>o%2===0);this.history={t:s(i.t),dE:s(i.dE),dJ3:s(i.dJ3),z:s(i.z),zdot:s(i.zdot),tension:s(i.tension),frames:s(i.frames)},this.historyStride*=2,this.historyCount=1}}latest(){return this.frames[this.frames.length-1]??null}advancePlayhead(e){const t=this.latest(),i=this.frames[0];if(t==null||i===void 0)return this.playT=null;const s=this.status;if(s===null||s.paused||this.playT===null)return this.playT=t.t,this.playT;const r=SA*s.time_scale/this.tickHz;let a=this.playT+Math.max(0,e)*s.time_scale;return a=Math.min(a,t.t),a=Math.max(a,t.t-r,i.t),this.playT=a,a}displayed(){const e=this.playT,t=this.frames;if(e===null||t.length===0)return null;const i=t[t.length-1];if(e>=i.t)return i;let s=0,r=t.length-1;if(e<=t[0].t)return t[0];for(;r-s>1;){const c=s+r>>1;t[c].t<=e?s=c:r=c}const a=t[s],o=t[r],l=o.t-a.t;return AA(a,o,l>0?(e-a.t)/l:1)}trailRange(e){const t=this.playT;if(t===null)return{start:0,end:0};const i=_p(this.trail,t,!1),s=_p(this.trail,t-e,!0);return{start:Math.min(s,i),end:i}}trailWindow(e){const{start:t,end:i}=this.trailRange(e);return this.trail.slice(t,i)}toCSV(){const e=this.status,t=this.trajectory[0],i={software:"pendulab",source:"pendulab lab",scenario:e?.scenario??null,pendulum:e===null?null:{model:e.model,...e.params,...e.model_params},params:e?.params??null,model:e?.model??null,model_params:e?.model_params??null,method:e?.method??null,adaptive:e?.adaptive??null,dt:e===null||e.adaptive?null:e.dt,start:t===void 0?null:{t:t.t,x:t.x,v:t.v},options:e===null?null:{arithmetic:MA,...e.adaptive?{}:{dt:e.dt},t0:t?.t??e.t0},method_changes:this.methods.slice(1),truncated:this.trajectoryTruncated},s=EA.join(","),r=this.trajectory.map(a=>[a.t,...a.x,...a.v,a.energy,a.j3,a.tension,a.power,...a.a,...a.pivot,a.taut?1:0,a.errorX].map(o=>String(o)).join(","));return[`# pendulab lab trajectory; metadata (JSON): ${Yc(i)}`,s,...r].join(`
`)+`
`}}const RA=13170016,CA=[16743129,7328767],PA=new z(0,1,0);class xp{group=new ki;bob;rod;pivotMark;trail;positions=new Float32Array(3*(nr+1));tmpX=new z;tmpPivot=new z;tmpDir=new z;length=1;offset=new z;constructor(e=RA){this.bob=new en(new fs(1,24,16),new tr({color:e,roughness:.4})),this.rod=new en(new so(1,1,1,8),new tr({color:e,metalness:.3,roughness:.5}));const t=new Ot;t.setAttribute("position",new li(this.positions,3)),t.setDrawRange(0,0),this.trail=new Fi(t,new ci({color:e,transparent:!0,opacity:.6})),this.trail.frustumCulled=!1,this.pivotMark=new en(new fs(1,12,8),new tr({color:e})),this.pivotMark.visible=!1,this.group.add(this.bob,this.rod,this.trail,this.pivotMark),this.group.visible=!1}setLength(e,t=e){this.length=t,this.bob.scale.setScalar(.045*t)}setOffset(e){e===null?this.offset.set(0,0,0):this.offset.fromArray(e),this.pivotMark.visible=e!==null,this.pivotMark.position.copy(this.offset),this.pivotMark.scale.setScalar(.03*this.length)}update(e,t){if(this.group.visible=e!==null,e===null)return;const i=this.tmpX.fromArray(e.x),s=this.tmpPivot.fromArray(e.pivot).add(this.offset);this.bob.position.copy(i).add(s);const r=i.length();r>0&&(this.rod.position.copy(i).multiplyScalar(.5).add(s),this.rod.quaternion.setFromUnitVectors(PA,this.tmpDir.copy(i).divideScalar(r)),this.rod.scale.set(.005*this.length,r,.005*this.length));const a=Math.max(0,Math.min(t.end-t.start,nr)),o=this.positions;for(let u=0;u<a;u++){const d=t.frames[t.end-a+u];o[3*u]=d.x[0]+d.pivot[0]+this.offset.x,o[3*u+1]=d.x[1]+d.pivot[1]+this.offset.y,o[3*u+2]=d.x[2]+d.pivot[2]+this.offset.z}const l=this.trail.geometry;l.setDrawRange(0,a);const c=l.getAttribute("position");c.clearUpdateRanges(),c.addUpdateRange(0,3*Math.max(a,1)),c.needsUpdate=!0}}const LA=16766720,DA=4e3;function NA(n,e=[0,0,0]){const t=n.filter(s=>s.every(Number.isFinite)).slice(0,DA),i=new Float32Array(3*t.length);return t.forEach((s,r)=>{i[3*r]=s[0]+e[0],i[3*r+1]=s[1]+e[1],i[3*r+2]=s[2]+e[2]}),i}function IA(n,e){const t=e>1?n/(e-1):0,i=Math.max(t/3,1e-4);return{dash:i,gap:Math.max(2*i,1e-4)}}class kA{line;material=new gg({color:LA,dashSize:.01,gapSize:.02});constructor(){this.line=new Fi(new Ot,this.material),this.line.frustumCulled=!1,this.line.visible=!1,this.line.name="measured-path"}set(e){this.line.geometry.dispose();const t=new Ot,i=NA(e??[]);t.setAttribute("position",new li(i,3)),this.line.geometry=t;const s=i.length/3;if(this.line.visible=s>1,s<2)return;this.line.computeLineDistances();const r=t.getAttribute("lineDistance"),{dash:a,gap:o}=IA(r.getX(s-1),s);this.material.dashSize=a,this.material.gapSize=o}get points(){return this.line.visible?this.line.geometry.getAttribute("position").count:0}}const Hg=["off","anaglyph","side by side"],Ml={trail:!0,trailSeconds:10,sphere:!0,axes:!0,velocity:!0,momentum:!1,gravity:!1,tension:!1,net:!1,angularMomentum:!1,torque:!1,originX:0,originY:0,originZ:0,stereo:"off",ruler:!1,protractor:!1,rulerShift:0,rulerLift:0,protractorShift:0,protractorLift:0,present:!1,simple:!0},Xd={velocity:14711807,momentum:10194175,gravity:16757575,tension:16735603,net:16777215,angularMomentum:5102016,torque:16769357},FA=["angularMomentum","torque"];function UA(n){const e=new wg(new z(1,0,0),new z,1,n);return e.visible=!1,e}class OA{arrows=Object.fromEntries(Object.entries(Xd).map(([e,t])=>[e,UA(t)]));tmpVec=new z;tmpOrigin=new z;objects(){return Object.values(this.arrows)}hide(){for(const e of Object.values(this.arrows))e.visible=!1}update(e,t,i,s,r,a,o,l){const c=Object.keys(this.arrows);if(!c.some(g=>t[g])){for(const g of c)this.arrows[g].visible=!1;return}const u=[t.originX,t.originY,t.originZ],d=oA(e,i,s,r,u),h=td(l,i,s),m=this.tmpOrigin.fromArray(u).add(a);for(const g of c){const y=FA.includes(g)?m:o,p=this.tmpVec.fromArray(d[g]).multiplyScalar(h[g]);zA(this.arrows[g],t[g],y,p,l)}}}function zA(n,e,t,i,s){const r=i.length();if(n.visible=e&&r>1e-6*s,!n.visible)return;n.position.copy(t),n.setDirection(i.divideScalar(r));const a=Math.min(.25*r,.08*s);n.setLength(r,a,.5*a)}const BA=/swiftshader|llvmpipe|softpipe|software|basic render driver|lavapipe/i;function HA(n){return n!==null&&BA.test(n)}function VA(n,e){return 1-(1-n)**e}function GA(n,e){const t=HA(n),i=Number.isFinite(e)&&e>0?e:1;return{renderer:n,software:t,antialias:!t,pixelRatio:Math.min(i,t?1:2),reachLayers:t?0:2}}function WA(){const n=document.createElement("canvas"),e=n.getContext("webgl2")??n.getContext("webgl");if(e===null)return null;let t=e.getParameter(e.RENDERER);if(typeof t!="string"||t===""||/^webkit webgl$/i.test(t)){const i=e.getExtension("WEBGL_debug_renderer_info");i!==null&&(t=e.getParameter(i.UNMASKED_RENDERER_WEBGL))}return e.getExtension("WEBGL_lose_context")?.loseContext(),typeof t=="string"&&t!==""&&!/^webkit webgl$/i.test(t)?t:null}const Vg=(n,e)=>[n[0]-e[0],n[1]-e[1],n[2]-e[2]],Ya=n=>Math.hypot(n[0],n[1],n[2]),Za=(n,e)=>[n[0]*e,n[1]*e,n[2]*e],nd=(n,e)=>[n[1]*e[2]-n[2]*e[1],n[2]*e[0]-n[0]*e[2],n[0]*e[1]-n[1]*e[0]];function Gg(n,e){const t=e[0]*n[0]+e[1]*n[1]+e[2]*n[2];let i=Vg(e,Za(n,t));return Ya(i)<1e-9&&(i=Math.abs(n[0])<.9?nd(n,[1,0,0]):nd(n,[0,1,0])),Za(i,1/Ya(i))}function qA(n,e,t,i){const s=Ya(n);if(!(s>0))return[[0,0,0],[...n]];const r=Za(n,1/s),a=Gg(r,[0,0,1]),o=nd(r,a),l=[];for(let c=0;c<=i;c++){const u=c/i,d=t*Math.min(1,u/.05,(1-u)/.05),h=2*Math.PI*e*u,[m,g]=[Math.cos(h)*d,Math.sin(h)*d];l.push([n[0]*u+a[0]*m+o[0]*g,n[1]*u+a[1]*m+o[1]*g,n[2]*u+a[2]*m+o[2]*g])}return l}function XA(n){let e=0;for(let t=1;t<n.length;t++)e+=Ya(Vg(n[t],n[t-1]));return e}function yp(n,e,t){const i=[];for(let s=0;s<=t;s++){const r=s/t,[a,o]=[2*r*(1-r),r*r];i.push([e[0]*a+n[0]*o,e[1]*a+n[1]*o,e[2]*a+n[2]*o])}return i}function $A(n,e,t,i=[0,0,-1]){const s=Ya(n),r=Za(n,.5);if(!(s>0)||s>=e)return yp(n,r,t);const a=Gg(Za(n,1/s),i),o=u=>yp(n,[r[0]+a[0]*u,r[1]+a[1]*u,r[2]+a[2]*u],t);let[l,c]=[0,e];for(let u=0;u<40&&c-l>1e-4*e;u++){const d=.5*(l+c);XA(o(d))<e?l=d:c=d}return o(.5*(l+c))}const bp=400,wp=48;class KA{group=new ki;coil;slack;constructor(){this.coil=new Fi(new Ot().setFromPoints(Array.from({length:bp+1},()=>new z)),new ci({color:14211288})),this.slack=new Fi(new Ot().setFromPoints(Array.from({length:wp+1},()=>new z)),new gg({color:15918793,dashSize:.04,gapSize:.03}));for(const e of[this.coil,this.slack])e.frustumCulled=!1,e.visible=!1;this.group.add(this.coil,this.slack)}update(e,t,i,s,r){if(this.coil.visible=e==="coil",this.slack.visible=e==="slack string",this.group.position.set(...i),e==="coil"&&this.fill(this.coil,qA(t,14,.035*s,bp)),e==="slack string"){this.fill(this.slack,$A(t,s,wp,r));const a=this.slack.material;a.dashSize=.04*s,a.gapSize=.03*s,this.slack.computeLineDistances()}}fill(e,t){const i=e.geometry.getAttribute("position");t.forEach((s,r)=>i.setXYZ(r,s[0],s[1],s[2])),i.needsUpdate=!0}}const Sp=.06,YA=new z(0,1,0),ZA=.025,jA=.06,JA=.085;class QA{sphere;equator;reachLines=hA(9417727,.18);fill;rod;bob;pivot;axes;boom;handle;tether=new KA;tmpX=new z;tmpDir=new z;tmpHandle=new z;bobAt=new z;model="ideal";length=1;constructor(e){this.fill=e.reachLayers>0,this.sphere=new en(new fs(1,48,32),new ks({color:9417727,transparent:!0,opacity:e.reachLayers===2?Sp:VA(Sp,2),depthWrite:!1,side:e.reachLayers===2?_i:Os}));const t=new Ot().setFromPoints(Array.from({length:128},(i,s)=>{const r=2*Math.PI*s/128;return new z(Math.cos(r),Math.sin(r),0)}));this.equator=new Cy(t,new ci({color:9417727,transparent:!0,opacity:.25})),this.pivot=new en(new fs(.02,16,12),new tr({color:13421772})),this.rod=new en(new so(1,1,1,12),new tr({color:14211288,metalness:.6,roughness:.3})),this.bob=new en(new fs(1,32,24),new tr({color:16747586,roughness:.35})),this.axes=new Sg(1.3),this.handle=new en(new fs(1,16,12),new ks({color:15911167})),this.handle.name="velocity handle",this.handle.visible=!1,this.boom=new Fi(new Ot().setFromPoints([new z,new z]),new ci({color:10134712})),this.boom.visible=!1,this.boom.frustumCulled=!1}objects(){return[this.sphere,this.equator,this.reachLines,this.pivot,this.rod,this.bob,this.axes,this.tether.group,this.handle,this.boom]}setLength(e){this.length=e,this.sphere.scale.setScalar(e),this.equator.scale.setScalar(e),this.reachLines.scale.setScalar(e),this.pivot.scale.setScalar(e),this.bob.scale.setScalar(.05*e),this.handle.scale.setScalar(ZA*e),this.axes.scale.setScalar(e)}show(e,t,i,s){const r=i||!this.fill;this.sphere.visible=t.sphere&&!r,this.reachLines.visible=t.sphere&&r,this.equator.visible=t.sphere,this.axes.visible=t.axes;const a=e!==null,o=Kc(this.model,e?.taut??!0);this.rod.visible=a&&(o==="rod"||o==="taut string"),this.bob.visible=a,this.handle.visible=a&&t.velocity,e===null&&this.tether.update("rod",[0,0,0],[0,0,0],this.length,s)}place(e,t,i,s,r){const a=Kc(this.model,e.taut??!0),o=Math.hypot(t.x,t.y);if(this.boom.visible=o>1e-9*this.length,this.boom.visible){const h=this.boom.geometry.getAttribute("position");h.setXYZ(0,0,0,t.z),h.setXYZ(1,t.x,t.y,t.z),h.needsUpdate=!0}for(const h of[this.sphere,this.equator,this.reachLines,this.pivot])h.position.copy(t);const l=this.tmpX.fromArray(e.x),c=l.length(),u=this.bobAt.copy(l).add(t);if(this.bob.position.copy(u),c>0){this.rod.position.copy(l).multiplyScalar(.5).add(t),this.rod.quaternion.setFromUnitVectors(YA,this.tmpDir.copy(l).divideScalar(c));const h=a==="taut string"?.003:.008;this.rod.scale.set(h*this.length,c,h*this.length)}const d=i<0?[-s[0],-s[1],-s[2]]:s;if(this.tether.update(a,e.x,e.pivot,this.length,d),this.handle.visible){const h=tA(e.x,e.v,r,JA*this.length);this.handle.position.copy(this.tmpHandle.fromArray(h).add(u))}return u}}class eT{constructor(e,t,i){this.inputs=t,this.invalidate=i,this.camera.up.set(0,0,1),this.controls=new Ug(this.camera,e),this.controls.enableDamping=!0}inputs;invalidate;camera=new Zn(40,1,.01,1e3);controls;length=1;extent=1;reach=1;follow=!1;followAt=null;topView=!1;tmp=new z;setLength(e){const t=Math.abs(e-this.length)>1e-12*e;this.length=e,t&&(this.extent=this.reach=e,this.reset())}setModel(e){this.follow=e==="slewing",this.followAt=null,this.extent=this.reach=this.length,this.reset()}setTopView(e){this.topView=e,this.reset()}reset(){const e=this.inputs.row(),t=e[e.length-1]??null,i=t===null?0:.5*Math.hypot(...t.offset),s=t===null?this.extent:i+Math.max(this.extent,...e.map(c=>c.length)),r=1.1*s,a=this.inputs.halfWidth()?this.camera.aspect/2:this.camera.aspect,o=dA(r,this.camera.fov,a),l=this.follow&&this.followAt!==null?this.followAt.clone():new z;t!==null&&l.add(new z(...t.offset).multiplyScalar(.5)),this.topView?this.camera.position.set(0,-1e-4*o,o).add(l):this.camera.position.set(3.3,-3.9,1.5).normalize().multiplyScalar(o).add(l),this.controls.target.copy(l),this.camera.near=.01*this.length,this.camera.far=100*s,this.camera.updateProjectionMatrix(),this.controls.update(),this.invalidate()}setAspect(e){this.camera.aspect=e,this.camera.updateProjectionMatrix(),this.reset()}track(e,t){this.followPivot(e),this.reach=Math.max(this.reach,Math.hypot(...t)),this.fit(this.reach+(this.follow?0:e.length()))}fit(e){Math.abs(e-this.extent)<=.2*this.extent||(this.extent=e,this.reset())}followPivot(e){if(!this.follow)return;if(this.followAt===null){this.followAt=e.clone(),this.reset();return}const t=this.tmp.copy(e).sub(this.followAt);t.lengthSq()!==0&&(this.camera.position.add(t),this.controls.target.add(t),this.followAt.copy(e))}orbitBy(e,t,i=1){const s=this.camera.position.clone().sub(this.controls.target),r=new Qu().setFromCartesianCoords(s.x,s.z,-s.y);r.theta+=e,r.phi=Math.min(Math.max(r.phi-t,.05),Math.PI-.05),r.radius*=i;const a=new z().setFromSpherical(r);this.camera.position.set(a.x,-a.z,a.y).add(this.controls.target),this.camera.lookAt(this.controls.target),this.controls.update(),this.invalidate()}}const tT={frames:[],start:0,end:0},nT=new lt(5882879);class iT{constructor(e){this.background=e;const t=new Ot;t.setAttribute("position",new li(this.positions,3)),t.setAttribute("color",new li(this.colors,3)),t.setDrawRange(0,0),this.line=new Fi(t,new ci({vertexColors:!0})),this.line.frustumCulled=!1}background;line;positions=new Float32Array(3*(nr+1));colors=new Float32Array(3*(nr+1));colored=-1;hide(){this.line.geometry.setDrawRange(0,0)}update(e,t){const i=Math.min(e.end-e.start,nr),s=this.line.geometry;if(i<=0){s.setDrawRange(0,0);return}const r=e.end-i,a=this.positions,o=i+1;for(let c=0;c<o;c++){const u=c<i?e.frames[r+c]:t;a[3*c]=u.x[0]+u.pivot[0],a[3*c+1]=u.x[1]+u.pivot[1],a[3*c+2]=u.x[2]+u.pivot[2]}s.setDrawRange(0,o);const l=s.getAttribute("position");l.clearUpdateRanges(),l.addUpdateRange(0,3*o),l.needsUpdate=!0,o!==this.colored&&this.fade(o)}fade(e){this.colored=e;const t=this.colors,i=new lt;for(let r=0;r<e;r++)i.copy(this.background).lerp(nT,(r+1)/e),t[3*r]=i.r,t[3*r+1]=i.g,t[3*r+2]=i.b;const s=this.line.geometry.getAttribute("color");s.clearUpdateRanges(),s.addUpdateRange(0,3*e),s.needsUpdate=!0}}const Gc=new lt(1119259);class sT{constructor(e,t){this.container=e,this.renderer=new kg({antialias:t.antialias}),this.renderer.setPixelRatio(t.pixelRatio),this.renderer.domElement.id="scene-canvas",e.appendChild(this.renderer.domElement),this.scene.background=Gc,this.rig=new eT(this.renderer.domElement,{row:()=>this.twinLayout===null?[]:[this.twinLayout,...this.extraLayouts],halfWidth:()=>this.stereo==="side by side"},()=>this.invalid=!0),this.camera=this.rig.camera,this.controls=this.rig.controls,this.scene.add(new Hy(16777215,.6));const i=new By(16777215,1.6);i.position.set(2,-3,4),this.scene.add(i),this.body=new QA(t),this.scene.add(...this.body.objects(),this.trail.line,this.twin.group,...this.extras.map(s=>s.group),this.measured.line,this.instruments.ruler,this.instruments.protractor,...this.arrows.objects()),this.setLength(1),this.resetCamera(),new ResizeObserver(()=>this.resize()).observe(e),this.resize()}container;renderer;camera;controls;scene=new ag;rig;body;trail=new iT(Gc);arrows=new OA;length=1;stereo="off";anaglyph=null;sideBySide=null;instruments=new cA;twin=new xp;extras=CA.map(e=>new xp(e));extraLayouts=[];extrasKey="";twinLayoutKey="";twinLayout=null;measured=new kA;drag=null;pull=null;drawn=null;velocityScale=td(1,1,9.81).velocity;gNow=9.81;pivotNow=new z;invalid=!0;crane=null;setLength(e){e>0&&(this.length=e,this.body.setLength(e),this.twin.setLength(this.twinLayout?.length??e,Math.max(this.twinLayout?.length??0,e)),this.extras.forEach((t,i)=>t.setLength(this.extraLayouts[i]?.length??e,Math.max(this.extraLayouts[i]?.length??0,e))),this.rig.setLength(e),this.invalid=!0)}resetCamera(){this.rig.reset()}setModel(e){e!==this.body.model&&(this.invalid=!0,this.body.model=e,this.rig.setModel(e))}setTopView(e){this.rig.setTopView(e)}enableDrag(e,t){const i=this.renderer.domElement;this.pull=new sA(i,this.camera,this.controls,this.body.handle,this.body.bob,()=>jA*this.length,()=>this.pullBasis(),t),this.drag=new iA(i,this.camera,this.controls,this.body.bob,e,()=>({pivot:this.pivotNow,length:this.length}))}pullBasis(){const e=this.drawn;return e===null?null:{pivot:[...e.pivot],x:[...e.x],arrowScale:this.velocityScale,vmax:QE(this.length,this.gNow)}}setStereo(e){this.stereo=e,e==="anaglyph"&&this.anaglyph===null&&(this.anaglyph=new uA(this.renderer)),e==="side by side"&&this.sideBySide===null&&(this.sideBySide=new JE(this.renderer)),this.resize(),this.resetCamera()}resize(){const e=Math.max(1,this.container.clientWidth),t=Math.max(1,this.container.clientHeight);this.renderer.setSize(e,t,!1),this.stereo==="side by side"&&this.sideBySide?.setSize(e,t),this.renderer.domElement.style.width="",this.renderer.domElement.style.height="",this.rig.setAspect(e/t),this.invalid=!0}update(e,t,i,s,r,a){if(this.updateBody(e,t,i,s,r,a),this.crane?.afterUpdate(e),this.crane?.hidesBody()===!0)for(const o of this.body.objects())o.visible=!1}addDrawing(e){this.scene.add(e),this.invalid=!0}updateBody(e,t,i,s,r,a){if(this.body.show(e,i,this.stereo==="anaglyph",a),this.drawn=e,this.gNow=r,this.velocityScale=td(this.length,s,r).velocity,e===null){this.trail.hide(),this.arrows.hide();return}const o=this.pivotNow.fromArray(e.pivot);this.rig.track(o,e.x),this.instruments.update(o,e.x,this.length,i.ruler,i.protractor,this.camera.position,{ruler:[i.rulerShift,i.rulerLift],protractor:[i.protractorShift,i.protractorLift]});const l=this.body.place(e,o,r,a,this.velocityScale);this.trail.update(i.trail?t:tT,e),this.arrows.update(e,i,s,r,a,o,l,this.length)}orbitBy(e,t,i=1){this.rig.orbitBy(e,t,i)}onScreen(e){if(!e.visible)return null;const t=e.position.clone().project(this.camera),i=this.renderer.domElement.getBoundingClientRect();return{x:i.left+(t.x+1)/2*i.width,y:i.top+(1-t.y)/2*i.height}}bobOnScreen(){return this.onScreen(this.body.bob)}handleOnScreen(){return this.onScreen(this.body.handle)}lastPull(){return this.pull?.last??null}handleAt(){const e=this.body.handle;return e.visible?{at:[e.position.x,e.position.y,e.position.z],scale:this.velocityScale}:null}setTwinLayout(e){const t=e===null?"":`${e.offset.join(",")}|${e.length}`;t!==this.twinLayoutKey&&(this.twinLayoutKey=t,this.twinLayout=e,this.twin.setLength(e?.length??this.length,Math.max(e?.length??0,this.length)),this.twin.setOffset(e?.offset??null),this.resetCamera())}setExtras(e){const t=e.map(i=>`${i.offset.join(",")}|${i.length}`).join(";");t!==this.extrasKey&&(this.extrasKey=t,this.extraLayouts=e,this.extras.forEach((i,s)=>{const r=e[s];if(r===void 0)return i.update(null,{frames:[],start:0,end:0});i.setLength(r.length,Math.max(r.length,this.length)),i.setOffset(r.offset)}),this.resetCamera())}updateExtras(e){this.extras.forEach((t,i)=>t.update(e[i]?.frame??null,e[i]?.trail??{frames:[],start:0,end:0})),this.invalid=!0}extrasOnScreen(){return this.extras.filter(e=>e.group.visible).flatMap(e=>this.onScreen(e.bob)??[])}updateTwin(e,t){this.twin.update(e,t),this.invalid=!0}setMeasured(e){this.measured.set(e),this.invalid=!0}measuredPoints(){return this.measured.points}sphereOnScreen(){return fA(this.body.sphere.position,this.body.sphere.scale.x,this.camera,this.renderer.domElement)}instrumentsOnScreen(){return{ruler:this.onScreen(this.instruments.ruler),protractor:this.onScreen(this.instruments.protractor)}}twinOnScreen(){return this.twin.group.visible?this.onScreen(this.twin.bob):null}draw(e){const t=this.controls.update();return t&&this.instruments.ruler.visible&&this.instruments.face(this.camera.position),!e&&!t&&!this.invalid?!1:(this.invalid=!1,this.render(),!0)}render(){const e=this.camera.position.distanceTo(this.controls.target);this.stereo==="anaglyph"&&this.anaglyph!==null?this.anaglyph.render(this.scene,this.camera,e/30,e,Gc):this.stereo==="side by side"&&this.sideBySide!==null?(this.camera.focus=e,this.sideBySide.setEyeSeparation(e/30),this.sideBySide.render(this.scene,this.camera)):this.renderer.render(this.scene,this.camera)}screenshot(){return this.render(),this.renderer.domElement.toDataURL("image/png")}}class rT{constructor(e){this.intervalMs=e}intervalMs;last=-1/0;due(e){return e-this.last<this.intervalMs?!1:(this.last=e,!0)}reset(){this.last=-1/0}}class aT{last=null;changed(e){const t=this.last;return t!==null&&t.length===e.length&&e.every((i,s)=>Object.is(i,t[s]))?!1:(this.last=[...e],!0)}}class oT{sums=new Map;add(e,t){const i=this.sums.get(e);i===void 0?this.sums.set(e,{ms:t,count:1}):(i.ms+=t,i.count++)}take(){const e={};for(const[t,i]of this.sums)e[t]={ms:i.ms/i.count,count:i.count};return this.sums.clear(),e}}const lT={kinetic:"#7dff8a",potential:"#59c3ff",lost:"#ff5d73",total:"#e8e8e8"};class cT{canvas;ctx;scale=1;width=null;shown=null;constructor(e){const t=document.createElement("h3");t.textContent=T("energy.title"),e.appendChild(t),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("role","img"),this.canvas.setAttribute("aria-label",T("energy.title")),e.appendChild(this.canvas),this.ctx=this.canvas.getContext("2d"),new ResizeObserver(()=>this.width=e.clientWidth).observe(e)}rescale(){this.scale=1}draw(e,t){this.shown=e;const i=this.ctx;if(i===null)return;const s=Math.min(window.devicePixelRatio||1,2);this.width??=this.canvas.parentElement?.clientWidth??300;const r=Math.max(200,this.width-4),a=130;if(this.canvas.width!==Math.round(r*s)&&(this.canvas.width=Math.round(r*s),this.canvas.height=Math.round(a*s),this.canvas.style.width=`${r}px`,this.canvas.style.height=`${a}px`),i.setTransform(s,0,0,s,0,0),i.clearRect(0,0,r,a),e===null)return;const o=[["kinetic",T("energy.kinetic"),e.kinetic],["potential",T("energy.potential"),e.potential]];t&&o.push(["lost",T("energy.lost"),e.lost]),o.push(["total",T("energy.total"),e.total]);const l=Math.max(...o.map(([,,m])=>Math.abs(m)),1e-12);this.scale=l>this.scale?l:Math.max(l,.995*this.scale);const c=14,u=a-30,d=u,h=r/o.length;i.font="11px system-ui, sans-serif",i.textAlign="center",o.forEach(([m,g,y],p)=>{const f=h*p+h*.2,x=h*.6,R=Math.abs(y)/this.scale*(u-c);i.fillStyle=lT[m],y>=0?i.fillRect(f,d-R,x,R):(i.globalAlpha=.5,i.fillRect(f,d-R,x,R),i.globalAlpha=1),i.fillStyle="#dde3ee",i.fillText(g,f+x/2,a-16),i.fillText(`${y.toPrecision(4)} J`,f+x/2,a-3)}),i.strokeStyle="#555",i.beginPath(),i.moveTo(0,d+.5),i.lineTo(r,d+.5),i.stroke()}}const Mp=(n,e)=>.5*e.mass*(n.v[0]**2+n.v[1]**2+n.v[2]**2),El=[{name:"t",label:"var.t",unit:"s",get:n=>n.t},{name:"theta",label:"var.theta",unit:"°",get:n=>Ka(n.x).theta*sn},{name:"phi",label:"var.phi",unit:"°",get:n=>Ka(n.x).phi*sn},{name:"x",label:"var.x",unit:"m",get:n=>n.x[0]},{name:"y",label:"var.y",unit:"m",get:n=>n.x[1]},{name:"z",label:"var.z",unit:"m",get:n=>n.x[2]},{name:"zdot",label:"var.zdot",unit:"m/s",get:n=>n.v[2]},{name:"speed",label:"var.speed",unit:"m/s",get:n=>Math.hypot(...n.v)},{name:"energy",label:"var.energy",unit:"J",get:n=>n.energy},{name:"kinetic",label:"var.kinetic",unit:"J",get:Mp},{name:"potential",label:"var.potential",unit:"J",get:(n,e)=>n.energy-Mp(n,e)},{name:"j3",label:"var.j3",unit:"kg m²/s",get:n=>n.j3},{name:"tension",label:"var.tension",unit:"N",get:n=>n.tension},{name:"power",label:"var.power",unit:"W",get:n=>n.power},{name:"radius",label:"var.radius",unit:"m",get:n=>Math.hypot(...n.x)}];function Ba(n){return El.find(e=>e.name===n)??El[0]}function Ep(n,e,t,i){const[s,r]=[Ba(e),Ba(t)];return{x:n.map(a=>s.get(a,i)),y:n.map(a=>r.get(a,i))}}class uT{constructor(e){this.container=e;const t=document.createElement("div");t.className="tools chosen",t.dataset.tool="chosen";const i=document.createElement("h3");i.textContent=T("chosen.title"),t.appendChild(i);for(const s of["y","x"]){const r=document.createElement("label");r.append(`${T(s==="x"?"chosen.xAxis":"chosen.yAxis")} `);const a=document.createElement("select");a.dataset.input=`chosen-${s}`;for(const o of El){const l=document.createElement("option");l.value=o.name,l.textContent=`${T(o.label)} [${o.unit}]`,a.appendChild(l)}a.value=this.choice[s],this.selects[s]=a,a.addEventListener("change",()=>{this.choice[s]=a.value,this.labels()}),r.appendChild(a),t.append(r," ")}e.appendChild(t),this.plot=new Ua(e,"","","",170),this.plot.canvas.dataset.plot="chosen",this.visibility.watch(this.plot.canvas),this.labels()}container;plot;visibility=new Il;choice={x:"t",y:"theta"};selects={};choose(e,t){return[e,t].every(i=>El.some(s=>s.name===i))?(this.choice.x=e,this.choice.y=t,this.selects.x&&(this.selects.x.value=e),this.selects.y&&(this.selects.y.value=t),this.labels(),!0):!1}labels(){const[e,t]=[Ba(this.choice.x),Ba(this.choice.y)];this.plot.xLabel=`${T(e.label)} [${e.unit}]`,this.plot.yLabel=`${T(t.label)} [${t.unit}]`}update(e,t,i=null){if(!this.visibility.visible(this.plot.canvas))return;const r=[{...Ep(e,this.choice.x,this.choice.y,t),color:"#59c3ff",label:T(i?"twin.first":Ba(this.choice.y).label)}];i!==null&&r.push({...Ep(i,this.choice.x,this.choice.y,t),color:"#c8f560",label:T("twin.second")});const a=r.flatMap(l=>l.x),o=r.flatMap(l=>l.y);this.plot.draw(this.container.clientWidth-8,r,er(a,.02),er(o))}}const ll=2;function Wg(n,e){const t=1.1*(n+e),i=Math.hypot(3.9,3.3);return[t*3.9/i,t*3.3/i,0]}function dT(n,e){const t=Math.hypot(...n),i=Math.atan2(Math.hypot(n[0],n[1]),-n[2])+e,s=Math.atan2(n[1],n[0]);return[t*Math.sin(i)*Math.cos(s),t*Math.sin(i)*Math.sin(s),-t*Math.cos(i)]}function qg(n){const e=Number.isFinite;return n.mode==="own"?e(n.length)&&n.length>0&&e(n.mass)&&n.mass>0&&n.theta>=0&&n.theta<=Math.PI?null:"own":n.mode==="epsilon"?e(n.epsilon)?null:"bad":n.mode==="damped"?e(n.damping)&&n.damping>=0?null:"bad":null}function Xg(n,e){const t=[];n.scenario&&t.push({type:"load_scenario",name:n.scenario});const i=e.mode==="damped",s=e.mode==="own",r=i&&n.model==="ideal"?"damped":n.model,a={...n.model_params};if(i&&(a.damping=e.damping),t.push({type:"set_model",model:r,params:a}),t.push({type:"set_params",length:s?e.length:n.params.length,mass:s?e.mass:n.params.mass,g:n.params.g}),t.push({type:"set_method",method:e.mode==="method"?e.method:n.method,dt:n.dt}),s)t.push({type:"set_state",theta:e.theta,phi:0,theta_dot:0,phi_dot:0});else{const o=e.mode==="epsilon"?dT(n.start.x,e.epsilon):n.start.x;t.push({type:"set_state",x:o,v:n.start.v,project:!0})}return t.push({type:"set_time_scale",time_scale:n.time_scale}),t.push({type:"reset"}),t.push({type:n.paused?"pause":"resume"}),t}function hT(n,e){const t=n.length;if(t===0)return null;const i=n[0],s=n[t-1];if(e<i.t||e>s.t)return null;let r=0,a=t-1;for(;a-r>1;){const p=r+a>>1;n[p].t<=e?r=p:a=p}const o=n[r],l=n[a],c=l.t-o.t;if(!(c>0))return[o.x[0]+o.pivot[0],o.x[1]+o.pivot[1],o.x[2]+o.pivot[2]];const u=(e-o.t)/c,[d,h,m,g]=[2*u**3-3*u**2+1,u**3-2*u**2+u,-2*u**3+3*u**2,u**3-u**2],y=p=>d*o.x[p]+h*c*o.v[p]+m*l.x[p]+g*c*l.v[p]+(1-u)*o.pivot[p]+u*l.pivot[p];return[y(0),y(1),y(2)]}function Ap(n,e){const t=[],i=[];for(const s of n){const r=hT(e,s.t);r!==null&&(t.push(s.t),i.push(Math.hypot(s.x[0]+s.pivot[0]-r[0],s.x[1]+s.pivot[1]-r[1],s.x[2]+s.pivot[2]-r[2])))}return{t,d:i}}function fT(n){const e=[];let t=[0,0,0];for(let i=1;i<n.length;i++){const s=Wg(n[i-1],n[i]);t=[t[0]+s[0],t[1]+s[1],t[2]+s[2]],e.push(t)}return e}function $r(n,e,t,i,s){const r=document.createElement("label");r.append(`${e} `);const a=document.createElement("input");return a.type="number",a.step=s,a.value=i,a.dataset.input=t,a.style.width="4.5em",r.appendChild(a),n.appendChild(r),a}function $g(n,e){const t=n.findIndex(i=>qg({...i,mode:"own"})!==null);return t<0?null:T("twin.badOwn",{n:e+t})}function pT(n){return qg(n)===null?null:n.mode==="own"?$g([n],2):T(n.mode==="epsilon"?"twin.badEpsilon":"twin.badDamping")}class mT{constructor(e,t,i){this.socket=t,this.explain=i,this.list=document.createElement("div"),this.list.dataset.output="extras",this.add=document.createElement("button"),this.add.type="button",this.add.dataset.action="extra-add",this.add.textContent=T("extras.add"),this.add.addEventListener("click",()=>this.addRow());const s=document.createElement("section");s.className="tools",s.dataset.tool="extras";const r=document.createElement("h3");r.textContent=T("extras.title");const a=document.createElement("p");a.textContent=T("extras.hint"),s.append(r,a,this.list,this.add),e.appendChild(s)}socket;explain;extras=[];list;add;show(){this.add.hidden=this.extras.length>=ll,this.extras.forEach((e,t)=>{const i=e.row.querySelector("button");i!==null&&(i.hidden=t!==this.extras.length-1)})}values(){return this.extras.map(e=>({length:Number(e.inputs.length.value),mass:Number(e.inputs.mass.value),theta:Number(e.inputs.theta.value)/sn}))}setRows(e){for(;this.extras.length>0;)this.removeLast();for(const t of e.slice(0,ll)){const i=this.addRow();if(i===null)return;i.inputs.length.value=String(t.length),i.inputs.mass.value=String(t.mass),i.inputs.theta.value=String(Number((t.theta*sn).toPrecision(12)))}}addRow(){if(this.extras.length>=ll)return null;const e=this.extras.length+3,t=document.createElement("p");t.dataset.extra=String(e),t.append(`${T("extras.pendulum",{n:e})}: `);const i={length:$r(t,"l [m]",`extra-length-${e}`,"0.75","0.05"),mass:$r(t,"m [kg]",`extra-mass-${e}`,"1","0.1"),theta:$r(t,"θ₀ [°]",`extra-theta-${e}`,"10","1")},s=document.createElement("button");s.type="button",s.dataset.action=`extra-remove-${e}`,s.textContent="✕",s.title=T("extras.remove",{n:e}),s.setAttribute("aria-label",s.title),s.addEventListener("click",()=>this.removeLast()),t.appendChild(s),this.list.appendChild(t);const r={store:new qd,row:t,inputs:i,conn:null,pending:[]};return this.extras.push(r),this.show(),r}removeLast(){const e=this.extras.pop();e!==void 0&&(e.conn?.close(),e.row.remove(),this.show())}start(e){const t=this.extras.map(s=>({mode:"own",epsilon:0,method:e.method,damping:0,length:Di(s.inputs.length),mass:Di(s.inputs.mass),theta:Di(s.inputs.theta)/sn})),i=$g(t,3);return i!==null?(this.explain(i),!1):(this.extras.forEach((s,r)=>{s.pending=Xg(e,t[r]),s.conn===null?s.conn=this.connect(s):this.flush(s)}),!0)}connect(e){return new dd(this.socket,{onOpen:()=>this.flush(e),onClose:()=>e.store.setConnected(!1),onFrames:t=>e.store.onFrames(t),onNotice:t=>{t.type==="status"?e.store.onStatus(t):t.type==="event"?e.store.onEvent(t):this.explain(`${T("extras.pendulum",{n:e.row.dataset.extra??""})}: ${t.message}`)},onProtocolError:t=>this.explain(t)})}flush(e){if(!(e.conn===null||!e.conn.isOpen)){for(const t of e.pending)e.conn.send(t);e.pending=[]}}running(){return this.extras.filter(e=>e.conn!==null&&e.store.status!==null).map(e=>e.store)}stop(){for(const e of this.extras)e.conn?.close(),e.conn=null,e.store.clear(),e.store.status=null}mirror(e){if(!(e.type!=="pause"&&e.type!=="resume"&&e.type!=="reset"&&e.type!=="step"))for(const t of this.extras)t.conn?.send(e)}}function Tp(n,e,t){if(e===null||n.frames.length===0)return null;const i=n.frames;n.playT=Math.min(Math.max(e,i[0].t),i[i.length-1].t);const{start:s,end:r}=n.trailRange(t);return{frame:n.displayed(),trail:{frames:n.trail,start:s,end:r}}}class gT{constructor(e,t,i,s,r){this.first=t,this.socket=s,this.actions=r;const a=document.createElement("section");a.className="tools",a.dataset.tool="twin";const o=document.createElement("h3");o.textContent=T("twin.title"),a.appendChild(o);const l=document.createElement("label");l.append(`${T("twin.mode")} `);const c=document.createElement("select");c.dataset.input="twin-mode";const u=[["off",T("twin.off")],["own",T("twin.own")],["epsilon",T("twin.epsilon")],["method",T("twin.method")],["damped",T("twin.damped")]];for(const[v,M]of u){const F=document.createElement("option");F.value=v,F.textContent=M,c.appendChild(F)}l.appendChild(c);const d=document.createElement("label");d.append("ε [°] ");const h=document.createElement("input");h.type="number",h.step="0.01",h.value="0.01",h.dataset.input="twin-epsilon",h.style.width="5em",d.appendChild(h);const m=document.createElement("label");m.append(`${T("twin.methodPick")} `);const g=document.createElement("select");g.dataset.input="twin-method";for(const v of i){const M=document.createElement("option");M.value=v.name,M.textContent=ul(v.name,v.order),g.appendChild(M)}g.value=i.some(v=>v.name==="rk4")?"rk4":i[0]?.name??"",m.appendChild(g);const y=document.createElement("label");y.append(`${T("twin.damping")} `);const p=document.createElement("input");p.type="number",p.step="0.1",p.min="0",p.value="0.5",p.dataset.input="twin-damping",p.style.width="5em",y.appendChild(p);const f=document.createElement("span"),x=$r(f,T("twin.length"),"twin-length","0.5","0.05"),R=$r(f,T("twin.mass"),"twin-mass","1","0.1"),S=$r(f,T("twin.theta"),"twin-theta","10","1"),C=document.createElement("button");C.type="button",C.dataset.action="twin-start",C.textContent=T("twin.start");const w=()=>{d.hidden=c.value!=="epsilon",m.hidden=c.value!=="method",y.hidden=c.value!=="damped",f.hidden=c.value!=="own",C.hidden=c.value==="off"};c.addEventListener("change",()=>{w(),c.value==="off"&&this.stop()}),C.addEventListener("click",()=>{const v={...this.options,mode:c.value,epsilon:Di(h)/sn,method:g.value,damping:Di(p),length:Di(x),mass:Di(R),theta:Di(S)/sn},M=pT(v);if(M!==null){r.explain(M);return}Object.assign(this.options,v),this.start()}),w(),this.setInputs=v=>{c.value=v.mode,h.value=String(v.epsilon*sn),g.value=v.method,p.value=String(v.damping),x.value=String(v.length),R.value=String(v.mass),S.value=String(v.theta*sn),w()},this.periods=document.createElement("table"),this.periods.dataset.readout="twin-periods",this.periods.hidden=!0,a.append(l," ",d,m,y,f," ",C,this.periods),e.appendChild(a),this.plot=new Ua(e,T("twin.separation"),"t [s]","|r₁ − r₂| [m]",140),this.plot.canvas.dataset.plot="separation",this.plot.canvas.parentElement?.setAttribute("hidden",""),this.visibility.watch(this.plot.canvas)}first;socket;actions;store=new qd;options={mode:"off",epsilon:.01/sn,method:"rk4",damping:.5,length:.5,mass:1,theta:10/sn};periods;setInputs;conn=null;pending=[];plot;visibility=new Il;extras=null;get on(){return this.conn!==null}layout(){const[e,t]=[this.first.status,this.store.status];return this.conn===null||this.options.mode!=="own"||e===null||t===null?null:{offset:Wg(e.params.length,t.params.length),length:t.params.length}}extraLayouts(){const e=this.first.status,t=this.store.status,i=this.extras?.running()??[];if(this.layout()===null||e===null||t===null||i.length===0)return[];const s=i.map(a=>a.status.params.length),r=fT([e.params.length,t.params.length,...s]);return s.map((a,o)=>({offset:r[o+1],length:a}))}drawnExtras(e,t){return this.conn===null||this.options.mode!=="own"?[]:(this.extras?.running()??[]).map(i=>Tp(i,e,t)??{frame:null,trail:{frames:[],start:0,end:0}})}restore(e){Object.assign(this.options,e),this.setInputs(e),this.extras?.setRows(e.extras??[]),e.mode!=="off"&&this.start()}start(){const e=this.first.status;if(e===null)return this.actions.explain(T("msg.notConnected"));if(this.options.mode==="own"&&this.extras!==null){if(!this.extras.start(e))return;this.options.extras=this.extras.values()}else this.extras?.stop(),delete this.options.extras;this.pending=Xg(e,this.options),this.conn===null?this.conn=new dd(this.socket,{onOpen:()=>this.flush(),onClose:()=>this.store.setConnected(!1),onFrames:t=>this.store.onFrames(t),onNotice:t=>{t.type==="status"?this.store.onStatus(t):t.type==="event"?this.store.onEvent(t):this.actions.explain(`${T("twin.second")}: ${t.message}`)},onProtocolError:t=>this.actions.explain(`${T("twin.second")}: ${t}`)}):this.flush(),this.actions.send({type:"reset"}),this.plot.canvas.parentElement?.removeAttribute("hidden"),this.periods.hidden=!1}flush(){if(!(this.conn===null||!this.conn.isOpen)){for(const e of this.pending)this.conn.send(e);this.pending=[]}}stop(){this.extras?.stop(),this.conn?.close(),this.conn=null,this.store.clear(),this.store.status=null,this.plot.canvas.parentElement?.setAttribute("hidden",""),this.periods.hidden=!0}mirror(e){this.conn!==null&&(this.extras?.mirror(e),(e.type==="pause"||e.type==="resume"||e.type==="reset"||e.type==="step")&&this.conn.send(e))}drawn(e,t){return this.conn===null?null:Tp(this.store,e,t)}update(e){if(this.conn!==null&&this.fillPeriods(),this.conn===null||!this.visibility.visible(this.plot.canvas))return;const t=Ap(this.first.history.frames,this.store.trajectory);this.plot.draw(e,[{x:t.t,y:t.d,color:"#c8f560",label:T("twin.separation")}],er(t.t,.02),er([0,...t.d]))}fillPeriods(){const e=(i,s)=>{const r=s.status,a=s.periodTimer.reading(),o=r===null?null:Math.atan2(Math.hypot(r.start.x[0],r.start.x[1]),-r.start.x[2])*sn;return[i,r===null?"—":r.params.length.toPrecision(3),r===null?"—":r.params.mass.toPrecision(3),o===null?"—":o.toFixed(1),a.period===null?"—":`${a.period.toFixed(4)} (${a.intervals})`]},t=[["",T("twin.colLength"),T("twin.colMass"),T("twin.colTheta"),T("twin.colPeriod")],e(T("twin.first"),this.first),e(T("twin.second"),this.store),...(this.extras?.running()??[]).map((i,s)=>e(T("extras.pendulum",{n:s+3}),i))];for(;this.periods.rows.length>t.length;)this.periods.deleteRow(-1);t.forEach((i,s)=>{const r=this.periods.rows[s]??this.periods.insertRow();for(;r.cells.length<i.length;)r.insertCell();i.forEach((a,o)=>{const l=r.cells[o];l&&l.textContent!==a&&(l.textContent=a)})})}separationNow(){return Ap(this.first.history.frames,this.store.trajectory)}}const vT=[["gloss.period","gloss.periodText"],["gloss.amplitude","gloss.amplitudeText"],["gloss.lowest","gloss.lowestText"],["gloss.friction","gloss.frictionText"],["gloss.gravity","gloss.gravityText"],["gloss.energy","gloss.energyText"],["gloss.spin","gloss.spinText"],["gloss.precession","gloss.precessionText"],["gloss.method","gloss.methodText"],["gloss.drift","gloss.driftText"]];class _T{constructor(e){const t=document.createElement("section");t.className="tools glossary",t.dataset.tool="glossary";const i=document.createElement("h3");i.textContent=T("gloss.title"),t.appendChild(i);for(const[a,o]of vT){const l=document.createElement("details"),c=document.createElement("summary");c.textContent=T(a);const u=document.createElement("p");u.textContent=T(o),l.append(c,u),t.appendChild(l)}const s=document.createElement("label"),r=document.createElement("input");r.type="checkbox",r.dataset.input="advanced",r.checked=Jo(),r.addEventListener("change",()=>a_(r.checked)),s.append(r,` ${T("gloss.advanced")}`),t.appendChild(s),e.appendChild(t)}}function xT(n,e){if(e)return null;switch(n){case" ":case"Spacebar":return"run";case"r":case"R":return"reset";case"s":case"S":return"step";case"?":return"help";case"Escape":return"close";default:return null}}function yT(n){switch(n){case"ArrowUp":case"ArrowRight":return 1;case"ArrowDown":case"ArrowLeft":return-1;case"PageUp":return 10;case"PageDown":return-10;case"Home":return-1/0;case"End":return 1/0;default:return null}}function id(n,e=""){return typeof HTMLElement>"u"||!(n instanceof HTMLElement)?!1:e===" "&&(n instanceof HTMLButtonElement||n instanceof HTMLInputElement&&["checkbox","radio","button"].includes(n.type))||n.isContentEditable||n instanceof HTMLSelectElement||n instanceof HTMLTextAreaElement?!0:n instanceof HTMLInputElement?!["checkbox","radio","button"].includes(n.type):n.getAttribute("role")==="slider"}function Yo(n){const e=Number(n);return Number.isFinite(e)?e.toLocaleString("en-US",{useGrouping:!1,maximumFractionDigits:20}):String(n)}function Kg(n){for(const e of n.controllersRecursive()){const t=e.$slider;t!==void 0&&(t.setAttribute("aria-valuenow",Yo(e.getValue())),t.dataset.keys!=="1"&&(t.dataset.keys="1",t.tabIndex=0,t.setAttribute("role","slider"),t.setAttribute("aria-label",e.$name.textContent??""),e._min!==void 0&&t.setAttribute("aria-valuemin",Yo(e._min)),e._max!==void 0&&t.setAttribute("aria-valuemax",Yo(e._max)),t.addEventListener("keydown",i=>{const s=yT(i.key);if(s===null)return;i.preventDefault(),i.stopPropagation();const[r,a,o]=[e._min??-1/0,e._max??1/0,e._step??.01],l=Number(e.getValue()),c=s===1/0?a:s===-1/0?r:Math.min(a,Math.max(r,l+s*o));Number.isFinite(c)&&e.setValue(+c.toPrecision(12)),t.setAttribute("aria-valuenow",Yo(e.getValue()))})))}}function bT(n,e){const t=5*Math.PI/180;if(e&&n==="ArrowLeft")return{bob:-1};if(e&&n==="ArrowRight")return{bob:1};switch(n){case"ArrowLeft":return{orbit:[-t,0],zoom:1};case"ArrowRight":return{orbit:[t,0],zoom:1};case"ArrowUp":return{orbit:[0,t],zoom:1};case"ArrowDown":return{orbit:[0,-t],zoom:1};case"+":case"=":return{orbit:[0,0],zoom:1/1.1};case"-":return{orbit:[0,0],zoom:1.1};default:return null}}function xt(n){const e=document.getElementById(n);if(e===null)throw new Error(`#${n} missing from index.html`);return e}function Yg(n,e){const t=document.createElement("a");t.href=e,t.download=n,document.body.appendChild(t),t.click(),t.remove()}function $d(n,e){const t=URL.createObjectURL(e);Yg(n,t),setTimeout(()=>URL.revokeObjectURL(t),1e4)}const wT='input, select, textarea, button, [tabindex]:not([tabindex="-1"])';function ST(n){for(const e of n)if(!e.classList.contains("lil-title")&&!e.matches(":disabled")&&e.getClientRects().length>0)return e;return null}function MT(){const n=xt("skip");n.textContent=T("page.skip"),n.addEventListener("click",e=>{e.preventDefault();const t=ST(xt("gui").querySelectorAll(wT));t?.focus(),t?.scrollIntoView({block:"nearest"})})}function ET(){const n=Yv(new URLSearchParams(window.location.search).get("lang"),window.localStorage?.getItem("pendulab.lang")??null,navigator.languages??[navigator.language]);Zv(n),document.documentElement.lang=n,r_(),document.title=T("page.title"),xt("page-title").textContent=T("page.title"),xt("units").textContent=T("page.units"),xt("scene").setAttribute("aria-label",T("page.scene")),xt("panel").setAttribute("aria-label",T("page.panel")),xt("panel-title").textContent=T("page.panel");const e={tools:"page.tools",energy:"page.energy",data:"page.data",plots:"page.plots",portraits:"page.portraits",reduced:"page.reduced"};for(const[t,i]of Object.entries(e))xt(t).setAttribute("aria-label",T(i));MT()}class AT{constructor(e){this.el=e}el;timer=null;explain=(e,t=!1)=>{this.el.textContent=e,this.el.classList.toggle("info",t),this.el.classList.add("shown"),this.timer!==null&&clearTimeout(this.timer),this.timer=setTimeout(()=>this.el.classList.remove("shown"),6e3)};clearNews(){this.el.classList.contains("info")&&this.el.classList.remove("shown")}}const Ha=180/Math.PI;function TT(n,e){const t={};for(const[i,s]of Object.entries(n))i in e&&e[i]!==s&&(t[i]=s);return t}function Zg(n){const e=t=>Un(Number((t*Ha).toPrecision(12)));return n.mode==="own"?[`own:${Un(n.length)}:${Un(n.mass)}:${e(n.theta)}`,...(n.extras??[]).map(t=>`${Un(t.length)}:${Un(t.mass)}:${e(t.theta)}`)].join(","):n.mode==="epsilon"?`eps:${e(n.epsilon)}`:n.mode==="method"?`method:${n.method}`:n.mode==="damped"?`damped:${Un(n.damping)}`:null}function Un(n){return Object.is(n,-0)?"-0":String(n)}function RT(n){const e=new URLSearchParams;n.scenario!==void 0&&e.set("s",n.scenario),n.model!==void 0&&e.set("model",n.model),n.modelParams!==void 0&&Object.keys(n.modelParams).length>0&&e.set("mp",Object.entries(n.modelParams).map(([i,s])=>`${i}:${Un(s)}`).join(",")),n.length!==void 0&&e.set("l",Un(n.length)),n.mass!==void 0&&e.set("m",Un(n.mass)),n.g!==void 0&&e.set("g",Un(n.g)),n.method!==void 0&&e.set("method",n.method),n.dt!==void 0&&e.set("dt",Un(n.dt)),n.timeScale!==void 0&&e.set("ts",Un(n.timeScale)),n.x!==void 0&&e.set("x",n.x.map(Un).join(",")),n.v!==void 0&&e.set("v",n.v.map(Un).join(",")),n.paused===!0&&e.set("paused","1"),n.at!==void 0&&n.at>0&&e.set("at",Un(n.at)),n.view!==void 0&&Object.keys(n.view).length>0&&e.set("view",Object.entries(n.view).map(([i,s])=>typeof s=="boolean"?s?i:`-${i}`:`${i}:${typeof s=="number"?Un(s):s}`).join(",")),n.plot!==void 0&&e.set("plot",n.plot.join(","));const t=n.twin===void 0?null:Zg(n.twin);return t!==null&&e.set("twin",t),n.lang!==void 0&&e.set("lang",n.lang),e.toString()}const jg=/^[A-Za-z0-9_.-]{1,100}$/;function Vr(n){if(!/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(n.trim()))return null;const e=Number(n);return Number.isFinite(e)?e:null}function CT(n){const e=new URLSearchParams(n.startsWith("?")?n.slice(1):n),t={},i=[],s=new Set(["s","model","mp","l","m","g","method","dt","ts","x","v","paused","lang","at","view","plot","twin"]);for(const F of e.keys())s.has(F)||i.push(T("url.unknownKey",{key:F}));const r=F=>{const L=e.get(F);if(L!==null){if(!jg.test(L)){i.push(T("url.notName",{key:F,value:JSON.stringify(L)}));return}return L}},a=F=>{const L=e.get(F);if(L===null)return;const D=Vr(L);return D===null&&i.push(T("url.notNumber",{key:F,value:JSON.stringify(L)})),D??void 0},o=F=>{const L=e.get(F);if(L===null)return;const D=L.split(",").map(Vr);if(D.length!==3||D.some(B=>B===null)){i.push(T("url.notThree",{key:F,value:JSON.stringify(L)}));return}return D},l=r("s");l!==void 0&&(t.scenario=l);const c=r("model");c!==void 0&&(t.model=c);const u=e.get("mp");if(u!==null){const F={};for(const L of u.split(",")){const[D,B,...G]=L.split(":"),k=B===void 0?null:Vr(B);if(D===void 0||!/^[A-Za-z_][A-Za-z0-9_]{0,40}$/.test(D)||k===null||G.length>0){i.push(T("url.notPair",{value:JSON.stringify(L)}));continue}F[D]=k}Object.keys(F).length>0&&(t.modelParams=F)}const d=a("l");d!==void 0&&(t.length=d);const h=a("m");h!==void 0&&(t.mass=h);const m=a("g");m!==void 0&&(t.g=m);const g=r("method");g!==void 0&&(t.method=g);const y=a("dt");y!==void 0&&(t.dt=y);const p=a("ts");p!==void 0&&(t.timeScale=p);const f=o("x"),x=o("v");f===void 0!=(x===void 0)&&i.length===0?i.push(T("url.startXv")):f!==void 0&&x!==void 0&&(t.x=f,t.v=x);const R=e.get("paused");R!==null&&(t.paused=R==="1"||R==="true");const S=e.get("lang");S!==null&&/^[a-z]{2}$/.test(S)&&(t.lang=S);const C=a("at");C!==void 0&&(C>=0&&C<=1e6?t.at=C:i.push(T("url.notTime",{value:JSON.stringify(e.get("at"))})));const w=e.get("view");if(w!==null){const F={};for(const L of w.split(",").filter(Boolean)){const D=/^(-?)([A-Za-z]{1,30})(?::([A-Za-z0-9 .+-]{1,30}))?$/.exec(L);if(D===null){i.push(T("url.notView",{value:JSON.stringify(L)}));continue}const[,B,G,k]=D;k===void 0?F[G]=B!=="-":F[G]=Vr(k)??k}t.view=F}const v=e.get("plot");if(v!==null){const F=v.split(",");F.length===2&&F.every(L=>/^[a-z0-9_]{1,20}$/i.test(L))?t.plot=[F[0],F[1]]:i.push(T("url.notPlot",{value:JSON.stringify(v)}))}const M=e.get("twin");if(M!==null){const F=LT(M);F===null?i.push(T("url.notTwin",{value:JSON.stringify(M)})):t.twin=F}return{value:t,problems:i}}function PT(n){const e=n.map(Vr);if(e.length!==3||e.some(r=>r===null))return null;const[t,i,s]=e;return t>0&&i>0&&s>=0&&s<=180?{length:t,mass:i,theta:s/Ha}:null}function LT(n){const e={mode:"off",epsilon:.01/Ha,method:"rk4",damping:.5,length:.5,mass:1,theta:10/Ha},[t="",...i]=n.split(","),[s,...r]=t.split(":"),a=r.map(Vr);if(s==="own"){const o=[r,...i.map(u=>u.split(":"))].map(PT);if(o.length>1+ll||o.some(u=>u===null))return null;const[l,...c]=o;return{...e,mode:"own",...l,...c.length>0?{extras:c}:{}}}return i.length>0?null:s==="eps"&&a.length===1&&a[0]!==null?{...e,mode:"epsilon",epsilon:a[0]/Ha}:s==="damped"&&a.length===1&&(a[0]??-1)>=0?{...e,mode:"damped",damping:a[0]}:s==="method"&&r.length===1&&jg.test(r[0])?{...e,mode:"method",method:r[0]}:null}function Rp(n){const e={model:n.model,length:n.params.length,mass:n.params.mass,g:n.params.g,method:n.method,timeScale:n.time_scale,x:n.start.x,v:n.start.v};return n.adaptive||(e.dt=n.dt),n.scenario!==null&&(e.scenario=n.scenario),Object.keys(n.model_params).length>0&&(e.modelParams={...n.model_params}),n.paused&&(e.paused=!0),n.paused&&!n.adaptive&&n.t>n.t0&&(e.at=n.t-n.t0),e}function sd(n){const e=[];n.scenario!==void 0&&e.push({type:"load_scenario",name:n.scenario}),n.model==="crane"?e.push({type:"crane",on:!0},{type:"set_params",params:{...n.modelParams}}):n.model!==void 0&&e.push({type:"set_model",model:n.model,params:{...n.modelParams}});const t={type:"set_params"};n.length!==void 0&&(t.length=n.length),n.mass!==void 0&&(t.mass=n.mass),n.g!==void 0&&(t.g=n.g),Object.keys(t).length>1&&e.push(t);const i={type:"set_method"};if(n.method!==void 0&&(i.method=n.method),n.dt!==void 0&&(i.dt=n.dt),Object.keys(i).length>1&&e.push(i),n.timeScale!==void 0&&e.push({type:"set_time_scale",time_scale:n.timeScale}),n.x!==void 0&&n.v!==void 0&&e.push({type:"set_state",x:n.x,v:n.v}),e.length>0&&e.push({type:"reset"}),n.paused===!0&&e.push({type:"pause"}),n.paused===!0&&n.at!==void 0&&n.at>0&&n.dt!==void 0&&n.dt>0){let s=Math.round(n.at/n.dt);for(s>1e7&&(s=0);s>0;){const r=Math.min(s,1e5);e.push({type:"step",n:r}),s-=r}}return e}function DT(n){const e=[T("link.scenario")];n.paused===!0&&e.push(n.at!==void 0&&n.at>0?T("link.pausedAt",{t:n.at.toFixed(3)}):T("link.paused"));const t=Object.entries(n.view??{}).map(([s,r])=>typeof r=="boolean"?r?s:`−${s}`:`${s} ${r}`);t.length>0&&e.push(T("link.view",{list:t.join(", ")})),n.plot!==void 0&&e.push(T("link.plot",{x:n.plot[0],y:n.plot[1]}));const i=n.twin===void 0?null:Zg(n.twin);return i!==null&&e.push(T("link.twin",{what:i})),n.lang!==void 0&&e.push(T("link.lang",{lang:n.lang})),e.join("; ")}function NT(n,e){const t=[];for(const[i,s]of Object.entries(e)){const r=Ml[i];r!==void 0&&typeof r==typeof s&&(i!=="stereo"||Hg.includes(s))?n[i]=s:t.push(`view: ${i} = ${String(s)} is not a view option`)}return t}class IT{constructor(e,t,i){this.store=e,this.view=t;const s=CT(window.location.search);this.value=s.value,s.problems.push(...NT(t,s.value.view??{})),s.problems.length>0&&i(T("msg.linkProblems",{what:s.problems.join("; ")})),this.startup=sd(s.value),s.value.twin!==void 0&&(this.replay=this.startup.filter(r=>r.type==="step"),this.startup=this.startup.filter(r=>r.type!=="step")),this.twinToRestore=s.value.twin??null}store;view;value;startup;replay=[];twinToRestore;chosen=null;twin=null;attach(e,t){this.chosen=e,this.twin=t,this.value.plot&&e.choose(...this.value.plot)}takeStartup(){const e=this.startup;return this.startup=[],e}restoreShown(){this.store.status!==null&&(this.startup=sd(Rp(this.store.status)))}lab(){const e=this.store.status,t=e===null?{}:Rp(e);t.view=TT(this.view,Ml),t.view.simple=this.view.simple;const i=this.chosen?.choice;return i!==void 0&&(i.x!=="t"||i.y!=="theta")&&(t.plot=[i.x,i.y]),this.twin?.on&&this.twin.options.mode!=="off"&&(t.twin={...this.twin.options}),t.lang=eo(),t}write(){if(this.startup.length>0||this.store.status===null)return;const e=`?${RT(this.lab())}`;e!==window.location.search&&window.history.replaceState(null,"",e)}}class kT{constructor(e,t){this.store=e,this.explain=t}store;explain;conn=null;twin=null;send=e=>{this.conn===null||!this.conn.send(e)?this.explain(T("msg.notConnected")):this.twin?.mirror(e)};run=()=>this.send({type:this.store.status?.paused===!1?"pause":"resume"});reset=()=>this.send({type:"reset"});step=()=>this.send({type:"step",n:1});sent(){return this.conn?.sent??0}}const FT=n=>`#${n.toString(16).padStart(6,"0")}`,UT={velocity:"vec.velocity",momentum:"vec.momentum",gravity:"vec.gravity",tension:"vec.tension",net:"vec.net",angularMomentum:"vec.angularMomentum",torque:"vec.torque"};class OT{constructor(e){this.el=e,e.setAttribute("aria-label",T("help.title"));const t=document.createElement("div");t.className="help-box";const i=document.createElement("h2");i.textContent=T("help.title");const s=document.createElement("table"),r=[[T("key.space"),"help.space"],["R","help.r"],["S","help.s"],["← → ↑ ↓","help.arrows"],[T("key.page"),"help.page"],["← → ↑ ↓ / + −","help.camera"],[`${T("key.shift")} + ← →`,"help.bobKeys"],["D","help.describe"],["Tab","help.tab"],["?","help.help"],["Esc","help.esc"]];for(const[u,d]of r){const h=s.insertRow(),m=h.insertCell(),g=document.createElement("kbd");g.textContent=u,m.appendChild(g),h.insertCell().textContent=T(d)}const a=document.createElement("h3");a.textContent=T("help.colours");const o=document.createElement("ul");o.className="colour-key";const l=[["#ff8c42",T("help.bob")],["#59c3ff",T("help.trail")],["#c8f560",T("help.twin")],...Object.entries(UT).map(([u,d])=>[FT(Xd[u]),T(d)]),["#e6d3a3",T("help.ruler")]];for(const[u,d]of l){const h=document.createElement("li"),m=document.createElement("span");m.className="swatch",m.style.background=u,h.append(m,` ${d}`),o.appendChild(h)}const c=document.createElement("button");c.type="button",c.dataset.action="help-close",c.textContent=T("help.close"),c.addEventListener("click",()=>this.toggle(!1)),t.append(i,s,a,o,c),e.appendChild(t),e.addEventListener("click",u=>u.target===e&&this.toggle(!1)),e.addEventListener("keydown",u=>{if(u.key!=="Tab")return;const d=[...e.querySelectorAll('button, [href], input, select, [tabindex]:not([tabindex="-1"])')],h=d[0],m=d[d.length-1];h===void 0||m===void 0||(u.shiftKey&&document.activeElement===h?(u.preventDefault(),m.focus()):!u.shiftKey&&document.activeElement===m&&(u.preventDefault(),h.focus()))}),document.addEventListener("focusin",u=>{this.open&&u.target instanceof Node&&!e.contains(u.target)&&this.el.querySelector("button")?.focus()})}el;returnFocus=null;get open(){return!this.el.hidden}toggle(e=!this.open){e!==this.open&&(e?(this.returnFocus=document.activeElement instanceof HTMLElement?document.activeElement:null,this.el.hidden=!1,this.el.querySelector("button")?.focus()):(this.el.hidden=!0,this.returnFocus?.focus()))}}const Cp="(max-width: 700px), (max-aspect-ratio: 3/4)";function rd(n,e){const t=n.replace(/^[^\p{L}\p{N}]+/u,"").trim(),i=a=>a.toLocaleLowerCase().split(/[^\p{L}\p{N}]+/u).filter(Boolean),s=i(e);return t===""||(a=>a.length>0&&s.some((o,l)=>a.every((c,u)=>s[l+u]===c)))(i(t))?e:`${t}: ${e}`}function Ps(n,e,t,i=!1){const s=document.createElement("button");return s.type="button",s.dataset.action=n,s.textContent=e,s.title=t,s.setAttribute("aria-label",rd(e,t)),i&&s.classList.add("when-open"),s}class zT{constructor(e,t,i){this.panel=t,e.setAttribute("aria-label",T("toolbar.label")),this.toggle=Ps("panel","",T("toolbar.collapse")),this.toggle.setAttribute("aria-controls","panel-body"),this.toggle.addEventListener("click",()=>{this.setCollapsed(!t.classList.contains("collapsed")),i.collapsed(t.classList.contains("collapsed"))}),this.runButton=Ps("run",T("toolbar.pauseShort"),T("toolbar.pause")),this.runButton.addEventListener("click",()=>i.run());const s=Ps("reset",T("toolbar.resetShort"),T("toolbar.reset"));s.addEventListener("click",()=>i.reset());const r=Ps("step",T("toolbar.stepShort"),T("toolbar.step"));r.addEventListener("click",()=>i.step()),this.recordButton=Ps("record",T("toolbar.recordShort"),T("toolbar.record")),this.recordButton.setAttribute("aria-pressed","false"),this.recordButton.addEventListener("click",()=>i.record());const a=Ps("help","?",T("toolbar.help"));a.addEventListener("click",()=>i.help()),this.presentButton=Ps("present","A⁺",T("toolbar.present"),!0),this.presentButton.setAttribute("aria-pressed","false"),this.presentButton.addEventListener("click",()=>i.present(this.presentButton.getAttribute("aria-pressed")!=="true")),this.simpleButton=Ps("simple",T("toolbar.simpleShort"),T("toolbar.simple"),!0),this.simpleButton.setAttribute("aria-pressed","false"),this.simpleButton.addEventListener("click",()=>i.simple(this.simpleButton.getAttribute("aria-pressed")!=="true"));const o=document.createElement("select");o.dataset.input="language",o.classList.add("when-open"),o.setAttribute("aria-label",T("toolbar.language"));for(const[l,c]of Object.entries(Ja)){const u=document.createElement("option");u.value=l,u.textContent=c.name,o.appendChild(u)}o.value=eo(),o.addEventListener("change",()=>i.language(o.value)),e.append(this.toggle,this.runButton,s,r,this.recordButton,a,this.simpleButton,this.presentButton,o),this.setCollapsed(!1),window.matchMedia(Cp).addEventListener("change",()=>this.setCollapsed(t.classList.contains("collapsed")))}panel;runButton;recordButton;toggle;presentButton;simpleButton;showPresenting(e){this.presentButton.setAttribute("aria-pressed",String(e))}showSimple(e){this.simpleButton.setAttribute("aria-pressed",String(e))}setCollapsed(e){this.panel.classList.toggle("collapsed",e),this.toggle.setAttribute("aria-expanded",String(!e));const t=window.matchMedia(Cp).matches;this.toggle.textContent=t?e?"▴":"▾":e?"◂":"▸",this.toggle.title=T(e?"toolbar.expand":"toolbar.collapse"),this.toggle.setAttribute("aria-label",this.toggle.title)}showRunning(e){const t=T(e?"toolbar.startShort":"toolbar.pauseShort");this.runButton.textContent!==t&&(this.runButton.textContent=t,this.runButton.title=T(e?"toolbar.start":"toolbar.pause"),this.runButton.setAttribute("aria-label",rd(t,this.runButton.title)))}showRecording(e){this.recordButton.setAttribute("aria-pressed",String(e)),this.recordButton.textContent=T(e?"toolbar.recordStopShort":"toolbar.recordShort"),this.recordButton.title=T(e?"toolbar.recordStop":"toolbar.record"),this.recordButton.setAttribute("aria-label",rd(this.recordButton.textContent,this.recordButton.title))}}const BT=300,HT=25e5;function VT(n){for(const e of["video/webm;codecs=vp9","video/webm;codecs=vp8","video/webm"])if(n(e))return e;return null}class GT{constructor(e,t){this.canvas=e,this.done=t}canvas;done;recorder=null;chunks=[];timer=null;get recording(){return this.recorder!==null}start(){if(this.recorder!==null)return null;if(typeof MediaRecorder>"u"||typeof this.canvas.captureStream!="function")return"no MediaRecorder";const e=VT(s=>MediaRecorder.isTypeSupported(s));if(e===null)return"no WebM";const t=this.canvas.captureStream(30),i=new MediaRecorder(t,{mimeType:e,videoBitsPerSecond:HT});return this.chunks=[],i.ondataavailable=s=>{s.data.size>0&&this.chunks.push(s.data)},i.onstop=()=>{for(const s of t.getTracks())s.stop();this.done(new Blob(this.chunks,{type:"video/webm"})),this.chunks=[]},i.start(1e3),this.recorder=i,this.timer=setTimeout(()=>this.stop(),BT*1e3),null}stop(){this.timer!==null&&clearTimeout(this.timer),this.timer=null;const e=this.recorder;this.recorder=null,e!==null&&e.state!=="inactive"&&e.stop()}}function WT(n,e){window.localStorage?.setItem("pendulab.lang",e);const t=$c(()=>n.store.status?.commands,()=>n.session.sent(),2e3);Promise.all([t,xx(2e3)]).then(()=>{const i=new URLSearchParams(window.location.search);i.set("lang",e),window.location.search=i.toString()})}const Jg="pendulab.simple";function qT(n){let e=null;try{e=window.localStorage?.getItem(Jg)??null}catch{e=null}return e==="1"?!0:e==="0"?!1:n}function XT(n){try{window.localStorage?.setItem(Jg,n?"1":"0")}catch{}}function $T(n){const{store:e,scene:t,view:i,session:s,explain:r}=n;let a=null;const o=new GT(t.renderer.domElement,u=>{u.slice(0,4).arrayBuffer().then(d=>{a={size:u.size,head:[...new Uint8Array(d)].map(h=>h.toString(16).padStart(2,"0")).join("")}}),$d(`pendulab-${e.status?.scenario??"lab"}.webm`,u),r(T("msg.recorded",{mb:(u.size/1e6).toFixed(1)}),!0)}),l=new OT(xt("help")),c=new zT(xt("toolbar"),xt("panel"),{run:s.run,reset:s.reset,step:s.step,record:()=>{if(o.recording)o.stop();else{const u=o.start();r(u!==null?T("msg.noRecording",{why:u}):T("msg.recording"),u===null)}c.showRecording(o.recording)},help:()=>l.toggle(),language:u=>WT(n,u),collapsed:()=>{},present:u=>{i.present=u,document.body.classList.toggle("present",u),c.showPresenting(u)},simple:u=>{i.simple=u,XT(u),document.body.classList.toggle("simple",u),c.showSimple(u)}});return document.body.classList.toggle("present",i.present),c.showPresenting(i.present),document.body.classList.toggle("simple",i.simple),c.showSimple(i.simple),{toolbar:c,help:l,lastVideo:()=>a}}function Qg(n,e,t=1e-6){if(n===null)return T("describe.none");const i=Ka(n.x).theta*sn,s=Math.hypot(...n.v),r=n.v[2],a=s<t?T("describe.rest"):Math.abs(r)<.001*s?T("describe.turning"):r>0?T("describe.rising"):T("describe.falling");let o=T("describe.text",{theta:i.toFixed(0),dir:a,v:s.toFixed(2)});if(e!==null){const l=Math.abs(e.kinetic)+Math.abs(e.potential)+Math.abs(e.lost);if(l>0){const c=u=>Math.round(100*u/l);o+=T("describe.energy",{k:c(e.kinetic),u:c(e.potential)}),Math.abs(e.lost)>.005*l&&(o+=T("describe.lost",{p:c(e.lost)}))}}return o}function KT(n){const{scene:e,store:t,session:i,explain:s}=n,r=e.renderer.domElement;r.tabIndex=0,r.setAttribute("aria-label",`${T("page.scene")}. ${T("help.camera")}; ${T("key.shift")} + ← →: ${T("help.bobKeys")}`),r.addEventListener("keydown",a=>{const o=bT(a.key,a.shiftKey);if(o===null||a.ctrlKey||a.metaKey||a.altKey)return;if(a.preventDefault(),"orbit"in o){e.orbitBy(o.orbit[0],o.orbit[1],o.zoom);return}const l=t.status;if(l===null)return;l.paused||i.send({type:"pause"});const c=Ka(l.start.x),u=Math.min(Math.max(c.theta+o.bob/sn,0),Math.PI);i.send({type:"set_state",theta:u,phi:c.phi,theta_dot:0,phi_dot:0}),s(T("describe.text",{theta:(u*sn).toFixed(0),dir:T("describe.rest"),v:"0.00"}),!0)})}function YT(n,e){const{store:t}=n,i=t.latest(),s=t.status?.params,r=i?Bg(i,s?.mass??1,s?.g??9.81,s?.length??1,t.work):null;e.describe(Qg(t.displayed(),r),performance.now(),!0)}function ZT(n,e,t){KT(n);const{session:i}=n;document.addEventListener("keydown",s=>{const r=!s.ctrlKey&&!s.metaKey&&!s.altKey;if((s.key==="d"||s.key==="D")&&r&&!id(s.target,s.key)&&!e.open){YT(n,t);return}const a=xT(s.key,!r);if(a!==null){if(a==="close"){e.open&&e.toggle(!1);return}id(s.target,s.key)||e.open&&a!=="help"||(s.preventDefault(),a==="run"?i.run():a==="reset"?i.reset():a==="step"?i.step():e.toggle())}})}const ad=[["gravity.earth",9.81],["gravity.moon",1.62],["gravity.mars",3.71],["gravity.jupiter",24.79],["gravity.zero",0],["gravity.negative",-9.81]];function jT(n,e){return n===null?null:"damping"in(n.model_params??{})?{type:"set_params",params:{damping:e}}:n.model==="ideal"&&e>0?{type:"set_model",model:"damped",params:{damping:e}}:null}function JT(n,e,t){for(const[i,s]of[["θ₀",n],["φ₀",e],["φ̇₀",t]])if(!Number.isFinite(s))return T("start.notNumber",{name:i});return n<0||n>180?T("start.thetaRange",{value:n}):{type:"set_state",theta:n/sn,phi:e/sn,theta_dot:0,phi_dot:t/sn}}function QT(n){let e=Math.round((2+18*n)*100)/100;for(const[,t]of ad)Math.abs(e-t)<.3&&(e=Math.round((e+.6)*100)/100);return e}function e1(n){return Math.min(1760,440*2**(Math.max(0,n)/2))}function Mt(n,e={},t=""){const i=document.createElement(n);for(const[s,r]of Object.entries(e))i.setAttribute(s,r);return t&&(i.textContent=t),i}function Or(n,e,t){const i=Mt("section",{class:"tools","data-tool":t});return i.appendChild(Mt("h3",{},e)),n.appendChild(i),i}function Wc(n,e,t,i){const s=Mt("label");s.append(`${n} `);const r=Mt("input",{type:"number",step:i,name:e,"data-input":e});return r.value=String(t),r.style.width="5.5em",s.appendChild(r),[s,r]}class t1{constructor(e,t,i){this.store=t;const s=()=>this.now=t.playT??this.now,r=Or(e,T("tools.start"),"start"),[a,o]=Wc("θ₀ [°]","theta0",30,"1"),[l,c]=Wc("φ₀ [°]","phi0",0,"1"),[u,d]=Wc("φ̇₀ [°/s]","phidot0",0,"10");o.title=T("tools.thetaHelp"),c.title=T("tools.phiHelp"),d.title=T("tools.phiDotHelp");const h=Mt("button",{type:"button","data-action":"set-start"},T("tools.setStart")),m=()=>{const L=JT(Di(o),Di(c),Di(d));typeof L=="string"?i.explain(L):i.send(L)};h.addEventListener("click",m);for(const L of[o,c,d])L.addEventListener("keydown",D=>D.key==="Enter"&&m());r.append(a,l,u,h);const g=Or(e,T("tools.world"),"world"),y=Mt("label");y.append(`${T("tools.gravity")} `),this.gravity=Mt("select",{"data-input":"gravity-preset"}),this.gravity.appendChild(Mt("option",{value:""},T("gravity.custom")));for(const[L,D]of ad)this.gravity.appendChild(Mt("option",{value:String(D)},`${T(L)} (${D} m/s²)`));this.gravity.appendChild(Mt("option",{value:"mystery"},T("tools.mystery")));const p=Mt("button",{type:"button","data-action":"reveal-g",hidden:""},T("tools.reveal"));this.reveal=p,this.gravity.addEventListener("change",()=>{this.gravity.value==="mystery"?(this.mysteryG=QT(Math.random()),document.body.classList.add("mystery"),p.hidden=!1,i.send({type:"set_params",g:this.mysteryG}),i.explain(T("tools.mysteryOn"),!0)):this.gravity.value!==""&&i.send({type:"set_params",g:Number(this.gravity.value)})}),p.addEventListener("click",()=>{i.explain(T("tools.revealed",{g:this.mysteryG??"?"}),!0),this.endMystery()}),y.append(this.gravity," ",p);const f=Mt("label");f.append(`${T("tools.friction")} `),this.friction=Mt("input",{type:"range",min:"0",max:"2",step:"0.01","data-input":"friction"}),this.friction.value="0",this.friction.title=T("tools.frictionHelp"),this.frictionValue=Mt("output"),this.friction.addEventListener("input",()=>{this.frictionValue.textContent=`${Number(this.friction.value).toFixed(2)} 1/s`}),this.friction.addEventListener("change",()=>{const L=jT(t.status,Number(this.friction.value));L!==null?i.send(L):Number(this.friction.value)>0&&i.explain(T("tools.noFriction",{model:bi(t.status?.model??"?",t.status?.model??"?")}))}),f.append(this.friction," ",this.frictionValue),g.append(y,f);const x=Or(e,T("tools.now"),"angles");this.angleText=Mt("div",{class:"big","data-readout":"angles","aria-live":"off"}),this.description=Mt("p",{class:"describe","data-readout":"describe","aria-live":"off","aria-atomic":"true"});const R=Mt("label");this.describeLive=Mt("input",{type:"checkbox","data-input":"describe"}),R.append(this.describeLive,` ${T("describe.toggle")}`);const S=Mt("label");this.sound=Mt("input",{type:"checkbox","data-input":"sound"}),S.append(this.sound,` ${T("tools.sound")}`),x.append(this.angleText,this.description,R,S);const C=Or(e,T("tools.stopwatch"),"stopwatch");this.watchText=Mt("div",{class:"big","data-readout":"stopwatch"},"0.000 s"),this.watchButton=Mt("button",{type:"button","data-action":"stopwatch"},T("tools.swStart"));const w=Mt("button",{type:"button","data-action":"lap"},T("tools.swLap")),v=Mt("button",{type:"button","data-action":"stopwatch-reset"},T("tools.swReset"));this.lapList=Mt("ol",{class:"laps"}),this.watchButton.addEventListener("click",()=>{this.stopwatch.running?this.stopwatch.stop(s()):this.stopwatch.start(s()),this.watchButton.textContent=this.stopwatch.running?T("tools.swStop"):T("tools.swStart")}),w.addEventListener("click",()=>this.stopwatch.lap(s())),v.addEventListener("click",()=>{this.stopwatch.reset(),this.watchButton.textContent=T("tools.swStart")}),C.append(this.watchText,this.watchButton," ",w," ",v,this.lapList);const M=Or(e,T("tools.period"),"period");M.title=T("tools.periodHelp"),this.periodTable=Mt("table",{"data-readout":"period"}),M.appendChild(this.periodTable);const F=Or(e,T("tools.overlays"),"overlays");for(const L of["ruler","protractor"]){const D=Mt("label"),B=Mt("input",{type:"checkbox","data-input":L});B.addEventListener("change",()=>i.overlay(L,B.checked)),this.overlayBoxes[L]=B;const G=Mt("span",{class:"move-pad",role:"group","aria-label":T("tools.moveGroup",{what:T(L==="ruler"?"tools.ruler":"tools.protractor")})}),k=[["◀","tools.moveLeft",[-.05,0]],["▶","tools.moveRight",[.05,0]],["▲","tools.moveUp",[0,.05]],["▼","tools.moveDown",[0,-.05]],["⟲","tools.moveBack",null]];for(const[W,Y,V]of k){const le=Mt("button",{type:"button","data-action":`move-${L}`,"aria-label":T(Y),title:T(Y)},W);le.addEventListener("click",()=>i.move(L,V)),G.appendChild(le)}D.append(B,` ${T(L==="ruler"?"tools.ruler":"tools.protractor")}`),F.append(D,G)}}store;stopwatch=new pA;angleText;watchText;lapList;watchButton;periodTable;friction;frictionValue;gravity;now=0;mysteryG=null;reveal;description;describeLive;describedAt=-1/0;sound;audio=null;heard=0;tones=0;listen(e){const t=this.store.periodTimer.lowCount;if(t<this.heard&&(this.heard=t),t===this.heard||(this.heard=t,!this.sound.checked||typeof AudioContext>"u"))return;this.audio??=new AudioContext;const i=this.audio,s=i.createOscillator(),r=i.createGain();s.frequency.value=e1(e),r.gain.setValueAtTime(.15,i.currentTime),r.gain.exponentialRampToValueAtTime(.001,i.currentTime+.12),s.connect(r).connect(i.destination),s.start(),s.stop(i.currentTime+.12),this.tones++}spokenUntil=-1/0;endMystery(){this.mysteryG=null,document.body.classList.remove("mystery"),this.reveal.hidden=!0}describe(e,t,i=!1){const s=this.describeLive.checked;i&&(this.spokenUntil=t+3e3),this.description.setAttribute("aria-live",s||t<this.spokenUntil?"polite":"off"),!(!i&&s&&t-this.describedAt<5e3)&&(!i&&!s&&t-this.describedAt<1e3||(this.describedAt=t,this.description.textContent!==e?this.description.textContent=e:i&&(this.description.textContent="",requestAnimationFrame(()=>this.description.textContent=e))))}overlayBoxes={};showOverlay(e,t){const i=this.overlayBoxes[e];i&&(i.checked=t)}sync(e){const t=ad.find(([,s])=>s===e.params.g);this.mysteryG!==null&&e.params.g!==this.mysteryG&&this.endMystery(),document.activeElement!==this.gravity&&(this.gravity.value=this.mysteryG!==null?"mystery":t?String(t[1]):"");const i=e.model_params?.damping;document.activeElement!==this.friction&&(this.friction.value=String(i??0),this.friction.disabled=i===void 0&&e.model!=="ideal",this.frictionValue.textContent=`${(i??0).toFixed(2)} 1/s`)}update(e,t,i=0){t!==null&&(this.now=t),this.listen(i);const s=e===null?null:Ka(e),r=s===null?"—":`θ = ${(s.theta*sn).toFixed(1)}°   φ = ${(s.phi*sn).toFixed(1)}°`;this.angleText.textContent!==r&&(this.angleText.textContent=r);const a=`${this.stopwatch.reading(this.now).toFixed(3)} s`;this.watchText.textContent!==a&&(this.watchText.textContent=a);const o=this.stopwatch.laps.map(l=>`${l.toFixed(3)} s`).join("|");this.lapList.dataset.shown!==o&&(this.lapList.dataset.shown=o,this.lapList.replaceChildren(...this.stopwatch.laps.map(l=>Mt("li",{},`${l.toFixed(3)} s`)))),this.fillPeriod()}fillPeriod(){const e=this.store.periodTimer.reading(),t=e.kind==="swing"&&e.amplitude!==null?n1(this.store.status,e.amplitude):null,i=yA(e,this.store.exact,t),s=([d,h])=>d===null||h===null||h===0?"":`${((d-h)/h*100).toFixed(2)} %`,r=d=>d===null?"—":(d*sn).toFixed(2),a=e.kind===null?T("tools.kindNone"):e.kind==="orbit"?T("tools.kindOrbit"):e.lowPerPeriod===1?T("tools.kindOver"):T("tools.kindSwing"),o=this.store.exact!==null?T("tools.exact"):T("tools.theory"),l=[["head","",T("tools.measured"),o,T("tools.difference")],["kind",T("tools.motion"),a,"",""]];i.swing?(l.push(["period",T("tools.periodSwing"),ft(i.period[0],5),ft(i.period[1],5),s(i.period)]),l.push(["amplitude",T("tools.amplitude"),r(e.amplitude),"",""])):(l.push(["period",T("tools.periodZ"),ft(i.period[0],5),ft(i.period[1],5),s(i.period)]),l.push(["advance",T("tools.advance"),r(i.advance[0]),r(i.advance[1]),s(i.advance)]),l.push(["precession",T("tools.precession"),r(i.precession[0]),r(i.precession[1]),""]),l.push(["band",T("tools.band"),e.thetaMin===null?"—":`${r(e.thetaMin)} … ${r(e.thetaMax)}`,"",""]));const c=this.periodTable;for(;c.rows.length>l.length;)c.deleteRow(-1);l.forEach(([d,...h],m)=>{const g=c.rows[m]??c.insertRow();for(g.dataset.row=d;g.cells.length<4;)g.insertCell();h.forEach((y,p)=>{const f=g.cells[p];f&&f.textContent!==y&&(f.textContent=y)})});const u=e.intervals===0?T("tools.periodWait"):T(i.swing?"tools.periodCount":"tools.periodCountZ",{n:e.intervals});c.caption?.textContent!==u&&(c.createCaption().textContent=u),c.dataset.period=e.period===null?"":String(e.period),c.dataset.kind=e.kind??""}}function n1(n,e){if(n===null)return null;const t=n.model_params??{},i=s=>(t[s]??0)===0;return n.model==="damped"&&!(i("drag")&&i("forcing_amplitude")&&i("gravity_x")&&i("gravity_y"))||n.model!=="ideal"&&n.model!=="damped"?null:_A(n.params.length,n.params.g,t.damping??0,e)}const od=2*2**20,i1=["damped","ideal","rotating","slewing","vibrating"];function s1(n,e,t,i,s){if(t>od)return`${n}: ${(t/2**20).toFixed(1)} MiB; the lab fits files of at most ${od/2**20} MiB (use pendulab fit for larger ones)`;if(e.trim()==="")return`${n}: the file is empty`;const r={csv:e,name:n,model:i},a=s.split(/[\s,]+/).filter(o=>o!=="");return a.length>0&&(r.fit=a),r}const ev=n=>typeof n=="number"&&Number.isFinite(n),r1=n=>Array.isArray(n)&&n.length===3&&n.every(ev);function Kd(n){if(typeof n!="object"||n===null)return null;const e=n,t=e.key;if(t!==null&&typeof t!="string")return null;const i={};if(typeof e.values=="object"&&e.values!==null)for(const[r,a]of Object.entries(e.values))typeof a=="string"&&(i[r]=a);const s={key:t,values:i};return typeof e.text=="string"&&(s.text=e.text),Array.isArray(e.clauses)&&(s.clauses=e.clauses.map(Kd).filter(r=>r!==null)),s}const Pp=n=>Array.isArray(n)?n.map(Kd).filter(e=>e!==null):[];function a1(n){if(typeof n!="object"||n===null)return"the fit answer is not an object";const e=n;if(typeof e.report!="string"||typeof e.scenario_toml!="string")return"the fit answer has no report";const t=e.measured;if(t!=null){const i=t,s=i.t,r=i.x;if(!Array.isArray(s)||!Array.isArray(r)||s.length!==r.length||!s.every(ev)||!r.every(r1))return"the fit answer has a malformed measured path"}return{report:e.report,warnings:Array.isArray(e.warnings)?e.warnings.filter(i=>typeof i=="string"):[],notes:Pp(e.notes),items:Pp(e.items),params:e.params??{},converged:e.converged===!0,scenario_toml:e.scenario_toml,lab:e.lab??null,measured:t??null}}function o1(n){const e={model:n.model,modelParams:{...n.model_params},length:n.params.length,mass:n.params.mass,g:n.params.g,method:n.method,dt:n.dt,x:n.start.x,v:n.start.v};return sd(e)}const tv={explainsLittle:"{kind}: the fitted motion explains only {percent} % of how much the data vary: the data may not show a pendulum's swing above their noise, or the model or the starting values are far off",correlatedNoise:"{kind}: the misses follow each other (lag-1 autocorrelation {lag1}) like the noise of video tracking or a filter, not like a wrong model: the error bars were widened for it",systematicDrift:"{kind}: the fit misses the data systematically, with a slow drift: the misses (rms {rms}) are {ratio} times the data's own noise ({floor}). The model lacks something (another kind of friction, a moving pivot, a wrong scale), or the noise itself is correlated",systematic:"{kind}: the fit misses the data systematically: the misses (rms {rms}) are {ratio} times the data's own noise ({floor}). The model lacks something (another kind of friction, a sensor offset, a moving pivot, a wrong scale), or the noise itself is correlated",correlatedSmall:"{kind}: the misses follow each other (lag-1 autocorrelation {lag1}) though they are no larger than the data's noise: correlated noise, or a small effect the model lacks; the error bars were widened for it",aboveFloor:"{kind}: the misses (rms {rms}) are {ratio} times the noise read off the data ({floor}): the model does not fit, or the noise is not random",outliers:"{kind}: {n} values lie far from the fit (more than {sigmas} standard deviations): outliers?",chi2Large:"the fitted motion misses the data by {factor} times their given noise (chi2 = {chi2}): improbable for a right model. The model lacks something (friction, a moving pivot), the noise given is too small, or the fit is stuck (try other starting values)",chi2Small:"chi2/dof = {reduced} is improbably small for {dof} degrees of freedom: the noise given is too large, and so are the error bars",blocksDisagree:"the record's {n} parts, each fitted on its own, disagree: {param} = {values} (the parts in time order), {scale} times their error bars apart. The model misses something that changes along the record (friction that depends on the amplitude, a drifting sensor, a hinge that is not ideal): the error bars were widened for it",blocksTimeLimit:"the lab's fits stop after {seconds} s, before the check that compares fits to the record's parts was made: the model misses the data, and the error bars were not widened for it, so they may be too narrow. Fit the data file on your computer with pendulab fit FILE --time-limit none (or pl.fit(..., time_limit=None)), or start the lab with a longer pendulab serve --fit-time-limit",blocksCtrlC:"Ctrl-C stopped the fit before the check that compares fits to the record's parts was made: the model misses the data, and the error bars were not widened for it, so they may be too narrow. Fit again and let it finish",bandPower:"; near {hz} Hz the misses have {ratio} times the power of the rest of their spectrum (p = {p}): a pattern at a few frequencies, not random noise",dampingDry:"; the damping fitted to each part grows as the swing dies down (the swing shrinks more linearly than exponentially), as dry friction makes: fit {param} as well",dampingDrag:"; the damping fitted to each part falls as the swing dies down (the large swings lose more), as air drag makes: fit {param} as well",stopTimeLimit:"; the lab's fits stop after {seconds} s, before the profile likelihood that checks these error bars was computed: fit the data file on your computer with pendulab fit FILE --time-limit none (or pl.fit(..., time_limit=None))",stopCtrlC:"; Ctrl-C stopped the fit before the profile likelihood that checks these error bars was computed",stopRobust:"; the profile likelihood that checks these error bars is not computed with a robust loss ({loss}): fit again with the linear loss once the outliers are removed",gFar:"the fitted g = {g} m/s² is far from any planet's (Earth: 9.81 m/s²): are the data in SI units (metres, not mm or pixels; seconds; radians)?",pivotFitted:"the positions do not hang from the origin: where the pivot is was fitted too",timeLimit:"the fit stopped at its time limit of {seconds} s: the values are the best reached",notConverged:"the fit did not converge: the values are the best reached",dropped:"{n} of {total} rows had a missing or infinite value and were left out",sorted:"the times were not in increasing order: the rows were sorted",lengthHint:"the positions lie {radius} m from the pivot, but the pendulum is {length} m long: are the positions in metres and is the pivot right? The fit starts from the data's distance",shortUndetermined:"{others} are not determined: the record spans only {periods} of a swing (a small-swing period is {period} s), too short to tell the length from g, and the error bars from the fit's curvature would be far too narrow. Record at least one full swing",shortWidened:"the record spans only {periods} of a swing (a small-swing period is {period} s): the error bars of {others} were taken from their 95 % profile-likelihood intervals, which the fit's curvature understates. Record at least one full swing to narrow them",mirrorPlanar:"the data are consistent with a swing in one plane: held in the plane (no sideways start angle or speed) the misfit rises by only {rise} (the 95 % level for the two is {level}). Seen from the side, the sideways motion shows only weakly near the plane, so its error bars were taken from the profile of the misfit. Fit the swing as planar if it swings in a plane",mirrorWidened:"seen from the side near its plane, the sideways motion shows only weakly: the error bars of {others} were taken from their 95 % profile-likelihood intervals, which the fit's curvature understates",mirrorUndetermined:"seen from the side, the sideways motion is not determined ({others}): near its plane it shows only weakly, and the error bars from the fit's curvature would be too narrow. Fit the swing as planar if it swings in a plane",notFinite:"the model's response to it is not finite at the fit",flat:"the data do not change with it (a symmetry of the data, or a rate of 0 seen from the side)",combination:"the data determine only a combination of it with {others}",shortRecord:"a record of {periods} of a swing does not determine it",mirrorUnchecked:"the fit stopped before the error bars of the sideways motion were checked (seen from the side near its plane, the curvature's bars would be too narrow)",mirrorOpen:"seen from the side near its plane, the data do not bound the sideways motion (its profile likelihood does not close)",header:"fit of the {model} to {samples} measurements ({kinds}), starting at t = {t0} s",droppedRows:"({n} rows with missing values were left out)",combinationValue:"determined instead: {label} = {value} ± {err}",mirror:"the data cannot tell this motion from its mirror image (y → −y): the direction of the sideways motion is a choice",planar:"the swing was fitted in one plane (a hinge): no sideways start angle or speed",residual:"{kind}: the fit misses the data by {rms} {unit} (rms); the data's own noise is about {floor} {unit}; lag-1 autocorrelation of the misses {lag1} (near 0: random misses, near 1: misses that follow a pattern)",chi2:"chi2/dof = {reduced} (chi2 = {chi2} for {dof} degrees of freedom): the misses measured in units of the noise given; about 1 means the fit is as close as the noise allows, much more means the model misses something",chi2Estimated:"chi2/dof = {reduced} (chi2 = {chi2} for {dof} degrees of freedom): the noise was estimated from the misses themselves, so chi2/dof is 1 by construction and says nothing here; see the lines above",noise:"noise of the {kind}: {sigma} {unit}",fixed:"held fixed: {param} = {value} {unit}",converged:"the fit converged ({runs} model runs, {seconds} s)",notConvergedItem:"the fit did NOT converge ({runs} model runs, {seconds} s): the values are the best reached",aicBic:"information criteria: AIC = {aic}, BIC = {bic}; only for comparing fits of the same data (another model, other parameters): the lower one fits better for the parameters it uses",compound:"compound pendulum (a body, not a point mass): equivalent length l_eq = I_O/(M h) = {inertia} kg m² / ({mass} kg × {centre} m) = {leq} m",compoundLengthHeld:"the length was held at the body's equivalent length l_eq; fit the length to test the body's measurements",compoundLength:"the fitted length {value} ± {err} m is {off} standard errors from the body's equivalent length l_eq",compoundTorque:"{param} = {value} ± {err} {unit} (the fitted value times the moment of inertia I_O)","p.damping_torque":"damping torque at the pivot","p.friction_torque":"dry friction torque at the pivot","p.length":"length l","p.g":"gravity g","p.mass":"mass m","p.damping":"friction (damping)","p.drag":"air drag","p.theta0":"start angle from the vertical","p.phi0":"start direction around the vertical","p.theta_dot0":"start speed of the swing (angle per second)","p.phi_dot0":"start speed around the vertical (angle per second)","p.pivot_x":"pivot position x","p.pivot_y":"pivot position y","p.pivot_z":"pivot position z","p.t_offset":"time offset of the data","p.scale":"scale of the positions","p.angle_offset":"zero of the angle sensor","p.force_bias":"offset of the accelerometer","p.rate_bias":"offset of the gyroscope","p.perspective":"camera perspective (1/distance)","k.positions":"positions","k.horizontal":"horizontal positions","k.angles":"angles","k.planar_angle":"swing angle","k.specific_force":"accelerometer readings","k.angular_speed":"gyroscope readings","m.ideal":"ideal pendulum","m.damped":"pendulum with friction","m.rotating":"pendulum on the turning Earth","m.slewing":"pendulum on a slewing crane","m.vibrating":"pendulum on a shaken pivot","m.spring":"swinging spring",notDetermined:"not determined: {reason}"},l1={explainsLittle:"{kind}: die angepasste Bewegung erklärt nur {percent} % der Schwankung der Daten: die Daten zeigen vielleicht kein Pendelschwingen über ihrem Rauschen, oder Modell oder Startwerte liegen weit daneben",correlatedNoise:"{kind}: die Abweichungen folgen aufeinander (Autokorrelation bei Abstand 1: {lag1}) wie das Rauschen einer Videoverfolgung oder eines Filters, nicht wie ein falsches Modell: die Fehlerbalken wurden dafür verbreitert",systematicDrift:"{kind}: die Anpassung verfehlt die Daten systematisch, mit einer langsamen Drift: die Abweichungen (rms {rms}) sind {ratio}-mal so groß wie das eigene Rauschen der Daten ({floor}). Dem Modell fehlt etwas (eine andere Art Reibung, ein bewegter Aufhängepunkt, ein falscher Maßstab), oder das Rauschen selbst ist korreliert",systematic:"{kind}: die Anpassung verfehlt die Daten systematisch: die Abweichungen (rms {rms}) sind {ratio}-mal so groß wie das eigene Rauschen der Daten ({floor}). Dem Modell fehlt etwas (eine andere Art Reibung, ein Sensor-Versatz, ein bewegter Aufhängepunkt, ein falscher Maßstab), oder das Rauschen selbst ist korreliert",correlatedSmall:"{kind}: die Abweichungen folgen aufeinander (Autokorrelation bei Abstand 1: {lag1}), sind aber nicht größer als das Rauschen der Daten: korreliertes Rauschen oder ein kleiner Effekt, der dem Modell fehlt; die Fehlerbalken wurden dafür verbreitert",aboveFloor:"{kind}: die Abweichungen (rms {rms}) sind {ratio}-mal so groß wie das aus den Daten abgelesene Rauschen ({floor}): das Modell passt nicht, oder das Rauschen ist nicht zufällig",outliers:"{kind}: {n} Werte liegen weit neben der Anpassung (mehr als {sigmas} Standardabweichungen): Ausreißer?",chi2Large:"die angepasste Bewegung verfehlt die Daten um das {factor}-Fache ihres angegebenen Rauschens (chi2 = {chi2}): für ein richtiges Modell unwahrscheinlich. Dem Modell fehlt etwas (Reibung, ein bewegter Aufhängepunkt), das angegebene Rauschen ist zu klein, oder die Anpassung hängt fest (andere Startwerte versuchen)",chi2Small:"chi2/dof = {reduced} ist für {dof} Freiheitsgrade unwahrscheinlich klein: das angegebene Rauschen ist zu groß, und damit auch die Fehlerbalken",blocksDisagree:"die {n} Abschnitte der Aufnahme, jeder für sich angepasst, widersprechen sich: {param} = {values} (die Abschnitte zeitlich geordnet), um das {scale}-Fache ihrer Fehlerbalken auseinander. Dem Modell fehlt etwas, das sich entlang der Aufnahme ändert (Reibung, die von der Amplitude abhängt, ein driftender Sensor, ein nicht ideales Scharnier): die Fehlerbalken wurden dafür verbreitert",blocksTimeLimit:"die Anpassungen des Labors enden nach {seconds} s, bevor die Prüfung gemacht war, die Anpassungen an Abschnitte der Aufnahme vergleicht: das Modell verfehlt die Daten, und die Fehlerbalken wurden dafür nicht verbreitert, sie sind also vielleicht zu schmal. Die Datendatei auf dem eigenen Rechner anpassen mit pendulab fit DATEI --time-limit none (oder pl.fit(..., time_limit=None)), oder das Labor mit einem längeren pendulab serve --fit-time-limit starten",blocksCtrlC:"Strg+C hat die Anpassung angehalten, bevor die Prüfung gemacht war, die Anpassungen an Abschnitte der Aufnahme vergleicht: das Modell verfehlt die Daten, und die Fehlerbalken wurden dafür nicht verbreitert, sie sind also vielleicht zu schmal. Noch einmal anpassen und zu Ende laufen lassen",bandPower:"; bei {hz} Hz haben die Abweichungen das {ratio}-Fache der Leistung ihres übrigen Spektrums (p = {p}): ein Muster bei wenigen Frequenzen, kein zufälliges Rauschen",dampingDry:"; die an jeden Abschnitt angepasste Dämpfung wächst, während die Schwingung abklingt (sie nimmt eher linear als exponentiell ab), wie es trockene Reibung bewirkt: {param} zusätzlich anpassen",dampingDrag:"; die an jeden Abschnitt angepasste Dämpfung sinkt, während die Schwingung abklingt (die großen Schwingungen verlieren mehr), wie es Luftwiderstand bewirkt: {param} zusätzlich anpassen",stopTimeLimit:"; die Anpassungen des Labors enden nach {seconds} s, bevor die Profil-Likelihood berechnet war, die diese Fehlerbalken prüft: die Datendatei auf dem eigenen Rechner anpassen mit pendulab fit DATEI --time-limit none (oder pl.fit(..., time_limit=None))",stopCtrlC:"; Strg+C hat die Anpassung angehalten, bevor die Profil-Likelihood berechnet war, die diese Fehlerbalken prüft",stopRobust:"; die Profil-Likelihood, die diese Fehlerbalken prüft, wird mit einer robusten Verlustfunktion ({loss}) nicht berechnet: nach dem Entfernen der Ausreißer mit der linearen Verlustfunktion erneut anpassen",gFar:"das angepasste g = {g} m/s² passt zu keinem Planeten (Erde: 9,81 m/s²): sind die Daten in SI-Einheiten (Meter, nicht mm oder Pixel; Sekunden; Radiant)?",pivotFitted:"die Positionen hängen nicht am Ursprung: der Ort des Aufhängepunkts wurde mit angepasst",timeLimit:"die Anpassung hielt an ihrer Zeitgrenze von {seconds} s an: die Werte sind die besten erreichten",notConverged:"die Anpassung ist nicht konvergiert: die Werte sind die besten erreichten",dropped:"{n} von {total} Zeilen hatten einen fehlenden oder unendlichen Wert und wurden weggelassen",sorted:"die Zeiten waren nicht aufsteigend: die Zeilen wurden sortiert",lengthHint:"die Positionen liegen {radius} m vom Aufhängepunkt, das Pendel ist aber {length} m lang: sind die Positionen in Metern und stimmt der Aufhängepunkt? Die Anpassung startet mit dem Abstand aus den Daten",shortUndetermined:"{others} sind nicht bestimmt: die Aufnahme umfasst nur {periods} einer Schwingung (eine Periode kleiner Schwingungen dauert {period} s), zu kurz, um die Länge von g zu trennen, und die Fehlerbalken aus der Krümmung der Anpassung wären viel zu schmal. Mindestens eine ganze Schwingung aufnehmen",shortWidened:"die Aufnahme umfasst nur {periods} einer Schwingung (eine Periode kleiner Schwingungen dauert {period} s): die Fehlerbalken von {others} wurden aus ihren 95-%-Profil-Likelihood-Intervallen genommen, die die Krümmung der Anpassung unterschätzt. Mindestens eine ganze Schwingung aufnehmen, um sie zu verkleinern",mirrorPlanar:"die Daten passen zu einer Schwingung in einer Ebene: in der Ebene festgehalten (kein seitlicher Startwinkel und keine seitliche Startgeschwindigkeit) steigt die Abweichung nur um {rise} (die 95-%-Schwelle für beide ist {level}). Von der Seite gesehen zeigt sich die seitliche Bewegung nahe der Ebene nur schwach, deshalb wurden ihre Fehlerbalken aus dem Profil der Abweichung genommen. Eine Schwingung in einer Ebene als eben anpassen",mirrorWidened:"von der Seite gesehen zeigt sich die seitliche Bewegung nahe ihrer Ebene nur schwach: die Fehlerbalken von {others} wurden aus ihren 95-%-Profil-Likelihood-Intervallen genommen, die die Krümmung der Anpassung unterschätzt",mirrorUndetermined:"von der Seite gesehen ist die seitliche Bewegung nicht bestimmt ({others}): nahe ihrer Ebene zeigt sie sich nur schwach, und die Fehlerbalken aus der Krümmung der Anpassung wären zu schmal. Eine Schwingung in einer Ebene als eben anpassen",notFinite:"die Antwort des Modells darauf ist bei der Anpassung nicht endlich",flat:"die Daten ändern sich damit nicht (eine Symmetrie der Daten, oder eine Rate 0 von der Seite gesehen)",combination:"die Daten bestimmen nur eine Kombination mit {others}",shortRecord:"eine Aufnahme von {periods} einer Schwingung bestimmt ihn nicht",mirrorUnchecked:"die Anpassung endete, bevor die Fehlerbalken der seitlichen Bewegung geprüft wurden (von der Seite gesehen wären die Balken aus der Krümmung nahe der Ebene zu schmal)",mirrorOpen:"von der Seite gesehen begrenzen die Daten die seitliche Bewegung nahe ihrer Ebene nicht (ihre Profil-Likelihood schließt sich nicht)",header:"Anpassung des Modells „{model}“ an {samples} Messwerte ({kinds}), Beginn bei t = {t0} s",droppedRows:"({n} Zeilen mit fehlenden Werten wurden weggelassen)",combinationValue:"stattdessen bestimmt: {label} = {value} ± {err}",mirror:"die Daten können diese Bewegung nicht von ihrem Spiegelbild (y → −y) unterscheiden: die Richtung der Seitwärtsbewegung ist eine Wahl",planar:"die Schwingung wurde in einer Ebene angepasst (ein Scharnier): kein seitlicher Startwinkel und keine seitliche Startgeschwindigkeit",residual:"{kind}: die Anpassung verfehlt die Daten um {rms} {unit} (rms); das eigene Rauschen der Daten ist etwa {floor} {unit}; Autokorrelation der Abweichungen bei Abstand 1: {lag1} (nahe 0: zufällige Abweichungen, nahe 1: Abweichungen mit Muster)",chi2:"chi2/dof = {reduced} (chi2 = {chi2} bei {dof} Freiheitsgraden): die Abweichungen in Einheiten des angegebenen Rauschens; etwa 1 heißt, die Anpassung ist so nah, wie das Rauschen erlaubt, viel mehr heißt, dem Modell fehlt etwas",chi2Estimated:"chi2/dof = {reduced} (chi2 = {chi2} bei {dof} Freiheitsgraden): das Rauschen wurde aus den Abweichungen selbst geschätzt, daher ist chi2/dof per Konstruktion 1 und sagt hier nichts; siehe die Zeilen darüber",noise:"Rauschen der {kind}: {sigma} {unit}",fixed:"festgehalten: {param} = {value} {unit}",converged:"die Anpassung ist konvergiert ({runs} Modellläufe, {seconds} s)",notConvergedItem:"die Anpassung ist NICHT konvergiert ({runs} Modellläufe, {seconds} s): die Werte sind die besten erreichten",aicBic:"Informationskriterien: AIC = {aic}, BIC = {bic}; nur zum Vergleich von Anpassungen an dieselben Daten (ein anderes Modell, andere Parameter): die kleinere passt besser für die Zahl ihrer Parameter",compound:"physikalisches Pendel (ein Körper, kein Massenpunkt): reduzierte Pendellänge l_eq = I_O/(M h) = {inertia} kg m² / ({mass} kg × {centre} m) = {leq} m",compoundLengthHeld:"die Länge wurde auf der reduzierten Pendellänge l_eq des Körpers festgehalten; die Länge anpassen, um die Maße des Körpers zu prüfen",compoundLength:"die angepasste Länge {value} ± {err} m liegt {off} Standardfehler von der reduzierten Pendellänge l_eq des Körpers entfernt",compoundTorque:"{param} = {value} ± {err} {unit} (der angepasste Wert mal dem Trägheitsmoment I_O)","p.damping_torque":"Dämpfungsmoment am Aufhängepunkt","p.friction_torque":"Reibungsmoment (trocken) am Aufhängepunkt","p.length":"Länge l","p.g":"Schwerebeschleunigung g","p.mass":"Masse m","p.damping":"Reibung (Dämpfung)","p.drag":"Luftwiderstand","p.theta0":"Startwinkel zur Senkrechten","p.phi0":"Startrichtung um die Senkrechte","p.theta_dot0":"Startgeschwindigkeit der Schwingung (Winkel pro Sekunde)","p.phi_dot0":"Startgeschwindigkeit um die Senkrechte (Winkel pro Sekunde)","p.pivot_x":"Aufhängepunkt x","p.pivot_y":"Aufhängepunkt y","p.pivot_z":"Aufhängepunkt z","p.t_offset":"Zeitversatz der Daten","p.scale":"Maßstab der Positionen","p.angle_offset":"Nullpunkt des Winkelsensors","p.force_bias":"Versatz des Beschleunigungssensors","p.rate_bias":"Versatz des Drehratensensors","p.perspective":"Kameraperspektive (1/Abstand)","k.positions":"Positionen","k.horizontal":"waagrechten Positionen","k.angles":"Winkel","k.planar_angle":"Schwingwinkel","k.specific_force":"Beschleunigungsmesswerte","k.angular_speed":"Drehratenmesswerte","m.ideal":"ideales Pendel","m.damped":"Pendel mit Reibung","m.rotating":"Pendel auf der drehenden Erde","m.slewing":"Pendel am Drehkran","m.vibrating":"Pendel an gerütteltem Aufhängepunkt","m.spring":"Schwingfeder",notDetermined:"nicht bestimmt: {reason}"},c1={explainsLittle:"{kind} : le mouvement ajusté n’explique que {percent} % de la variation des données : les données ne montrent peut-être pas d’oscillation au-dessus de leur bruit, ou le modèle ou les valeurs de départ sont très loin",correlatedNoise:"{kind} : les écarts se suivent (autocorrélation au pas 1 : {lag1}) comme le bruit d’un suivi vidéo ou d’un filtre, pas comme un mauvais modèle : les barres d’erreur ont été élargies en conséquence",systematicDrift:"{kind} : l’ajustement manque les données systématiquement, avec une lente dérive : les écarts (rms {rms}) valent {ratio} fois le bruit propre des données ({floor}). Il manque quelque chose au modèle (un autre frottement, un pivot qui bouge, une mauvaise échelle), ou le bruit lui-même est corrélé",systematic:"{kind} : l’ajustement manque les données systématiquement : les écarts (rms {rms}) valent {ratio} fois le bruit propre des données ({floor}). Il manque quelque chose au modèle (un autre frottement, un décalage du capteur, un pivot qui bouge, une mauvaise échelle), ou le bruit lui-même est corrélé",correlatedSmall:"{kind} : les écarts se suivent (autocorrélation au pas 1 : {lag1}) sans dépasser le bruit des données : bruit corrélé, ou petit effet absent du modèle ; les barres d’erreur ont été élargies en conséquence",aboveFloor:"{kind} : les écarts (rms {rms}) valent {ratio} fois le bruit lu dans les données ({floor}) : le modèle ne convient pas, ou le bruit n’est pas aléatoire",outliers:"{kind} : {n} valeurs sont loin de l’ajustement (plus de {sigmas} écarts-types) : des valeurs aberrantes ?",chi2Large:"le mouvement ajusté manque les données de {factor} fois leur bruit donné (chi2 = {chi2}) : improbable pour un bon modèle. Il manque quelque chose au modèle (frottement, pivot qui bouge), le bruit donné est trop petit, ou l’ajustement est bloqué (essayer d’autres valeurs de départ)",chi2Small:"chi2/dof = {reduced} est improbablement petit pour {dof} degrés de liberté : le bruit donné est trop grand, et les barres d’erreur aussi",blocksDisagree:"les {n} parties de l’enregistrement, ajustées chacune seule, sont en désaccord : {param} = {values} (les parties dans l’ordre du temps), écartées de {scale} fois leurs barres d’erreur. Il manque au modèle quelque chose qui change le long de l’enregistrement (un frottement qui dépend de l’amplitude, un capteur qui dérive, une charnière imparfaite) : les barres d’erreur ont été élargies en conséquence",blocksTimeLimit:"les ajustements du labo s’arrêtent après {seconds} s, avant la vérification qui compare les ajustements des parties de l’enregistrement : le modèle manque les données, et les barres d’erreur n’ont pas été élargies en conséquence, elles sont donc peut-être trop étroites. Ajuster le fichier de données sur votre ordinateur avec pendulab fit FICHIER --time-limit none (ou pl.fit(..., time_limit=None)), ou lancer le labo avec un pendulab serve --fit-time-limit plus long",blocksCtrlC:"Ctrl-C a arrêté l’ajustement avant la vérification qui compare les ajustements des parties de l’enregistrement : le modèle manque les données, et les barres d’erreur n’ont pas été élargies en conséquence, elles sont donc peut-être trop étroites. Ajuster à nouveau et le laisser finir",bandPower:" ; vers {hz} Hz, les écarts ont {ratio} fois la puissance du reste de leur spectre (p = {p}) : un motif à quelques fréquences, pas un bruit aléatoire",dampingDry:" ; l’amortissement ajusté à chaque partie croît à mesure que l’oscillation s’éteint (elle décroît plus linéairement qu’exponentiellement), comme le fait un frottement sec : ajuster aussi {param}",dampingDrag:" ; l’amortissement ajusté à chaque partie diminue à mesure que l’oscillation s’éteint (les grandes oscillations perdent plus), comme le fait la résistance de l’air : ajuster aussi {param}",stopTimeLimit:" ; les ajustements du labo s’arrêtent après {seconds} s, avant le calcul de la vraisemblance profilée qui vérifie ces barres d’erreur : ajuster le fichier de données sur votre ordinateur avec pendulab fit FICHIER --time-limit none (ou pl.fit(..., time_limit=None))",stopCtrlC:" ; Ctrl-C a arrêté l’ajustement avant le calcul de la vraisemblance profilée qui vérifie ces barres d’erreur",stopRobust:" ; la vraisemblance profilée qui vérifie ces barres d’erreur n’est pas calculée avec une perte robuste ({loss}) : ajuster de nouveau avec la perte linéaire une fois les valeurs aberrantes retirées",gFar:"le g ajusté = {g} m/s² ne correspond à aucune planète (Terre : 9,81 m/s²) : les données sont-elles en unités SI (mètres, pas mm ni pixels ; secondes ; radians) ?",pivotFitted:"les positions ne pendent pas de l’origine : la position du pivot a aussi été ajustée",timeLimit:"l’ajustement s’est arrêté à sa limite de {seconds} s : les valeurs sont les meilleures atteintes",notConverged:"l’ajustement n’a pas convergé : les valeurs sont les meilleures atteintes",dropped:"{n} lignes sur {total} avaient une valeur manquante ou infinie et ont été écartées",sorted:"les temps n’étaient pas croissants : les lignes ont été triées",lengthHint:"les positions sont à {radius} m du pivot, mais le pendule mesure {length} m : les positions sont-elles en mètres et le pivot est-il juste ? L’ajustement part de la distance des données",shortUndetermined:"{others} ne sont pas déterminés : l’enregistrement ne couvre que {periods} d’une oscillation (une période des petites oscillations dure {period} s), trop peu pour séparer la longueur de g, et les barres d’erreur tirées de la courbure de l’ajustement seraient bien trop étroites. Enregistrer au moins une oscillation complète",shortWidened:"l’enregistrement ne couvre que {periods} d’une oscillation (une période des petites oscillations dure {period} s) : les barres d’erreur de {others} ont été prises de leurs intervalles de vraisemblance profilée à 95 %, que la courbure de l’ajustement sous-estime. Enregistrer au moins une oscillation complète pour les réduire",mirrorPlanar:"les données sont compatibles avec une oscillation dans un plan : maintenue dans le plan (sans angle ni vitesse latérale au départ), l’écart n’augmente que de {rise} (le seuil à 95 % pour les deux est {level}). Vu de côté, le mouvement latéral ne se voit que faiblement près du plan, et ses barres d’erreur ont été prises du profil de l’écart. Ajuster l’oscillation comme plane si elle oscille dans un plan",mirrorWidened:"vu de côté près de son plan, le mouvement latéral ne se voit que faiblement : les barres d’erreur de {others} ont été prises de leurs intervalles de vraisemblance profilée à 95 %, que la courbure de l’ajustement sous-estime",mirrorUndetermined:"vu de côté, le mouvement latéral n’est pas déterminé ({others}) : près de son plan, il ne se voit que faiblement, et les barres d’erreur tirées de la courbure de l’ajustement seraient trop étroites. Ajuster l’oscillation comme plane si elle oscille dans un plan",notFinite:"la réponse du modèle n’est pas finie à l’ajustement",flat:"les données ne changent pas avec lui (une symétrie des données, ou une vitesse nulle vue de côté)",combination:"les données ne déterminent qu’une combinaison avec {others}",shortRecord:"un enregistrement de {periods} d’une oscillation ne le détermine pas",mirrorUnchecked:"l’ajustement s’est arrêté avant que les barres d’erreur du mouvement latéral soient vérifiées (vu de côté près du plan, les barres tirées de la courbure seraient trop étroites)",mirrorOpen:"vu de côté près de son plan, les données ne bornent pas le mouvement latéral (sa vraisemblance profilée ne se referme pas)",header:"ajustement du modèle « {model} » à {samples} mesures ({kinds}), début à t = {t0} s",droppedRows:"({n} lignes avec des valeurs manquantes ont été écartées)",combinationValue:"déterminé à la place : {label} = {value} ± {err}",mirror:"les données ne distinguent pas ce mouvement de son image miroir (y → −y) : le sens du mouvement latéral est un choix",planar:"l’oscillation a été ajustée dans un plan (une charnière) : ni angle ni vitesse latérale au départ",residual:"{kind} : l’ajustement manque les données de {rms} {unit} (rms) ; le bruit propre des données est d’environ {floor} {unit} ; autocorrélation des écarts au pas 1 : {lag1} (près de 0 : écarts aléatoires, près de 1 : écarts qui suivent un motif)",chi2:"chi2/dof = {reduced} (chi2 = {chi2} pour {dof} degrés de liberté) : les écarts mesurés en unités du bruit donné ; environ 1 signifie que l’ajustement est aussi proche que le bruit le permet, beaucoup plus qu’il manque quelque chose au modèle",chi2Estimated:"chi2/dof = {reduced} (chi2 = {chi2} pour {dof} degrés de liberté) : le bruit a été estimé à partir des écarts eux-mêmes, donc chi2/dof vaut 1 par construction et ne dit rien ici ; voir les lignes au-dessus",noise:"bruit des {kind} : {sigma} {unit}",fixed:"fixé : {param} = {value} {unit}",converged:"l’ajustement a convergé ({runs} calculs du modèle, {seconds} s)",notConvergedItem:"l’ajustement n’a PAS convergé ({runs} calculs du modèle, {seconds} s) : les valeurs sont les meilleures atteintes",aicBic:"critères d’information : AIC = {aic}, BIC = {bic} ; seulement pour comparer des ajustements des mêmes données (un autre modèle, d’autres paramètres) : le plus petit s’ajuste mieux pour le nombre de ses paramètres",compound:"pendule pesant (un corps, pas un point matériel) : longueur équivalente l_eq = I_O/(M h) = {inertia} kg m² / ({mass} kg × {centre} m) = {leq} m",compoundLengthHeld:"la longueur a été fixée à la longueur équivalente l_eq du corps ; ajuster la longueur pour vérifier les mesures du corps",compoundLength:"la longueur ajustée {value} ± {err} m est à {off} erreurs types de la longueur équivalente l_eq du corps",compoundTorque:"{param} = {value} ± {err} {unit} (la valeur ajustée fois le moment d’inertie I_O)","p.damping_torque":"couple d’amortissement au point de suspension","p.friction_torque":"couple de frottement sec au point de suspension","p.length":"longueur l","p.g":"pesanteur g","p.mass":"masse m","p.damping":"frottement (amortissement)","p.drag":"résistance de l’air","p.theta0":"angle de départ par rapport à la verticale","p.phi0":"direction de départ autour de la verticale","p.theta_dot0":"vitesse de départ de l’oscillation (angle par seconde)","p.phi_dot0":"vitesse de départ autour de la verticale (angle par seconde)","p.pivot_x":"position du pivot x","p.pivot_y":"position du pivot y","p.pivot_z":"position du pivot z","p.t_offset":"décalage temporel des données","p.scale":"échelle des positions","p.angle_offset":"zéro du capteur d’angle","p.force_bias":"décalage de l’accéléromètre","p.rate_bias":"décalage du gyroscope","p.perspective":"perspective de la caméra (1/distance)","k.positions":"positions","k.horizontal":"positions horizontales","k.angles":"angles","k.planar_angle":"angle d’oscillation","k.specific_force":"mesures de l’accéléromètre","k.angular_speed":"mesures du gyroscope","m.ideal":"pendule idéal","m.damped":"pendule avec frottement","m.rotating":"pendule sur la Terre qui tourne","m.slewing":"pendule sur une grue pivotante","m.vibrating":"pendule à pivot secoué","m.spring":"ressort oscillant",notDetermined:"non déterminé : {reason}"},u1={en:tv,de:l1,fr:c1};function na(n){return u1[eo()][n]??tv[n]}function cl(n){return na(`p.${n}`)??hd(n,n,"")[0]}function Lp(n){return na(`k.${n}`)??n}function d1(n){return na(`m.${n}`)??bi(n,n)}function h1(n,e){const t=i=>i.replace(/[A-Za-z_][A-Za-z_0-9]*/g,s=>na(`p.${s}`)!==void 0?cl(s):s);return n==="kind"?Lp(e):n==="kinds"?e.split(",").map(Lp).join(", "):n==="param"?cl(e):n==="model"?d1(e):n==="others"?e.split(/,\s*/).map(cl).join(", "):n==="label"?t(e):e}function ia(n){const e=n.key===null?void 0:na(n.key);return e===void 0?n.text??n.key??"":e.replace(/\{(\w+)\}/g,(i,s)=>{const r=n.values[s];return r===void 0?i:h1(s,r)})+(n.clauses??[]).map(i=>i.key!==null&&na(i.key)!==void 0?ia(i):"").join("")}function f1(n,e){const t=e.unit&&e.unit!=="1"?` ${e.unit}`:"",i=`${cl(n)} = ${e.value.toPrecision(6)}`;if(e.determined&&e.stderr!==null)return`${i} ± ${e.stderr.toPrecision(2)}${t}`;const s=Kd(e.reason),r=s===null?"":ia(s);return`${i}${t} (${ia({key:"notDetermined",values:{reason:r}})})`.replace(/\s*:\s*\)$/,")")}function p1(n,e){const[t,...i]=n,s=t===void 0?[]:[ia(t)];return s.push(...Object.entries(e).map(([r,a])=>`  ${f1(r,a)}`)),s.push(...i.map(r=>`  ${ia(r)}`)),s}function Dn(n,e={},t=""){const i=document.createElement(n);for(const[s,r]of Object.entries(e))i.setAttribute(s,r);return t&&(i.textContent=t),i}class m1{constructor(e,t){this.actions=t;const i=Dn("section",{class:"tools","data-tool":"fit"});i.appendChild(Dn("h3",{},T("fit.title")));const s=Dn("label");s.append(`${T("fit.load")} `),this.input=Dn("input",{type:"file",accept:".csv,.txt,.tsv,text/csv,text/plain","data-input":"fit-file"}),s.appendChild(this.input),s.title=T("fit.help");const r=Dn("label");r.append(`${T("fit.model")} `),this.model=Dn("select",{"data-input":"fit-model"});for(const o of i1)this.model.appendChild(Dn("option",{value:o},bi(o,o)));r.appendChild(this.model);const a=Dn("label");a.append(`${T("fit.params")} `),this.names=Dn("input",{type:"text","data-input":"fit-params",placeholder:T("fit.paramsDefault")}),this.names.style.width="12em",a.appendChild(this.names),a.title=T("fit.paramsHelp"),this.clear=Dn("button",{type:"button","data-action":"fit-clear"},T("fit.clear")),this.clear.disabled=!0,this.clear.addEventListener("click",()=>this.reset()),this.report=Dn("pre",{class:"fit-report","data-output":"fit-report","aria-live":"polite"}),this.report.hidden=!0,this.warnings=Dn("ul",{class:"fit-warnings","data-output":"fit-warnings"}),this.warnings.hidden=!0;for(const o of[s,r,a,this.clear]){const l=Dn("p");l.appendChild(o),i.appendChild(l)}this.full.append(Dn("summary",{},T("fit.fullReport")),this.fullText),this.full.hidden=!0,i.append(this.warnings,this.report,this.full),e.appendChild(i),this.input.addEventListener("change",()=>{const o=this.input.files?.[0];o!==void 0&&this.send(o)})}actions;input;model;names;clear;report;warnings;full=Dn("details",{class:"fit-full","data-output":"fit-full"});fullText=Dn("pre",{class:"fit-report"});busy=!1;reset(){this.report.hidden=!0,this.report.textContent="",this.warnings.hidden=!0,this.warnings.replaceChildren(),this.full.hidden=!0,this.clear.disabled=!0,this.input.value="",this.actions.cleared()}async send(e){if(this.busy)return;const t=e.size>od?"":await e.text(),i=s1(e.name,t,e.size,this.model.value,this.names.value);if(typeof i=="string")return this.actions.explain(i);this.busy=!0,this.input.disabled=!0,this.report.hidden=!1,this.report.textContent=T("fit.running",{name:e.name});try{const s=await fetch("api/fit",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(i)}),r=await s.json().catch(()=>({detail:`HTTP ${s.status}`}));if(!s.ok)throw new Error(fd(r,`HTTP ${s.status}`));const a=a1(r);if(typeof a=="string")throw new Error(a);const o=T(a.converged?"fit.converged":"fit.notConverged"),l=a.notes.length>0?a.notes.map(ia):a.warnings,c=[...p1(a.items,a.params),...l.map(d=>`⚠ ${d}`)];a.items.length===0&&c.unshift(T("fit.summary",{model:bi(this.model.value,this.model.value),state:o})),this.fullText.textContent=a.report,this.full.hidden=!1,a.measured===null&&c.push(T("fit.noPath")),this.report.textContent=c.join(`
`);const u=[...new Set(l)];this.warnings.replaceChildren(...u.map(d=>Dn("li",{},`⚠ ${d}`))),this.warnings.hidden=u.length===0,this.clear.disabled=!1,this.actions.loaded(a,e.name)}catch(s){const r=s instanceof Error?s.message:String(s);this.report.textContent=`${e.name}: ${r}`,this.actions.explain(T("fit.failed",{why:r}))}finally{this.busy=!1,this.input.disabled=!1}}}function g1(n){const{store:e,scene:t,view:i,session:s,explain:r}=n,a=new t1(xt("tools"),e,{send:s.send,explain:r,overlay:(o,l)=>{i[o]=l},move:(o,l)=>{const[c,u]=o==="ruler"?["rulerShift","rulerLift"]:["protractorShift","protractorLift"],d=h=>Math.round(h*1e3)/1e3;i[c]=l===null?0:d(i[c]+l[0]),i[u]=l===null?0:d(i[u]+l[1]),i[o]=!0,a.showOverlay(o,!0)}});return new m1(xt("tools"),{loaded:(o,l)=>{if(t.setMeasured(o.measured?.x??null),o.lab!==null)for(const c of o1(o.lab))s.send(c);r(T("fit.loaded",{name:l}),!0)},cleared:()=>t.setMeasured(null),explain:r}),a.showOverlay("ruler",i.ruler),a.showOverlay("protractor",i.protractor),a}class Qi{constructor(e,t,i,s,r="div"){this.parent=e,this.object=t,this.property=i,this._disabled=!1,this._hidden=!1,this.initialValue=this.getValue(),this.domElement=document.createElement(r),this.domElement.classList.add("lil-controller"),this.domElement.classList.add(s),this.$name=document.createElement("div"),this.$name.classList.add("lil-name"),Qi.nextNameID=Qi.nextNameID||0,this.$name.id=`lil-gui-name-${++Qi.nextNameID}`,this.$widget=document.createElement("div"),this.$widget.classList.add("lil-widget"),this.$disable=this.$widget,this.domElement.appendChild(this.$name),this.domElement.appendChild(this.$widget),this.domElement.addEventListener("keydown",a=>a.stopPropagation()),this.domElement.addEventListener("keyup",a=>a.stopPropagation()),this.parent.children.push(this),this.parent.controllers.push(this),this.parent.$children.appendChild(this.domElement),this._listenCallback=this._listenCallback.bind(this),this.name(i)}name(e){return this._name=e,this.$name.textContent=e,this}onChange(e){return this._onChange=e,this}_callOnChange(){this.parent._callOnChange(this),this._onChange!==void 0&&this._onChange.call(this,this.getValue()),this._changed=!0}onFinishChange(e){return this._onFinishChange=e,this}_callOnFinishChange(){this._changed&&(this.parent._callOnFinishChange(this),this._onFinishChange!==void 0&&this._onFinishChange.call(this,this.getValue())),this._changed=!1}reset(){return this.setValue(this.initialValue),this._callOnFinishChange(),this}enable(e=!0){return this.disable(!e)}disable(e=!0){return e===this._disabled?this:(this._disabled=e,this.domElement.classList.toggle("lil-disabled",e),this.$disable.toggleAttribute("disabled",e),this)}show(e=!0){return this._hidden=!e,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}options(e){const t=this.parent.add(this.object,this.property,e);return t.name(this._name),this.destroy(),t}min(e){return this}max(e){return this}step(e){return this}decimals(e){return this}listen(e=!0){return this._listening=e,this._listenCallbackID!==void 0&&(cancelAnimationFrame(this._listenCallbackID),this._listenCallbackID=void 0),this._listening&&this._listenCallback(),this}_listenCallback(){this._listenCallbackID=requestAnimationFrame(this._listenCallback);const e=this.save();e!==this._listenPrevValue&&this.updateDisplay(),this._listenPrevValue=e}getValue(){return this.object[this.property]}setValue(e){return this.getValue()!==e&&(this.object[this.property]=e,this._callOnChange(),this.updateDisplay()),this}updateDisplay(){return this}load(e){return this.setValue(e),this._callOnFinishChange(),this}save(){return this.getValue()}destroy(){this.listen(!1),this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.controllers.splice(this.parent.controllers.indexOf(this),1),this.parent.$children.removeChild(this.domElement)}}class v1 extends Qi{constructor(e,t,i){super(e,t,i,"lil-boolean","label"),this.$input=document.createElement("input"),this.$input.setAttribute("type","checkbox"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$widget.appendChild(this.$input),this.$input.addEventListener("change",()=>{this.setValue(this.$input.checked),this._callOnFinishChange()}),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.checked=this.getValue(),this}}function ld(n){let e,t;return(e=n.match(/(#|0x)?([a-f0-9]{6})/i))?t=e[2]:(e=n.match(/rgb\(\s*(\d*)\s*,\s*(\d*)\s*,\s*(\d*)\s*\)/))?t=parseInt(e[1]).toString(16).padStart(2,0)+parseInt(e[2]).toString(16).padStart(2,0)+parseInt(e[3]).toString(16).padStart(2,0):(e=n.match(/^#?([a-f0-9])([a-f0-9])([a-f0-9])$/i))&&(t=e[1]+e[1]+e[2]+e[2]+e[3]+e[3]),t?"#"+t:!1}const _1={isPrimitive:!0,match:n=>typeof n=="string",fromHexString:ld,toHexString:ld},ja={isPrimitive:!0,match:n=>typeof n=="number",fromHexString:n=>parseInt(n.substring(1),16),toHexString:n=>"#"+n.toString(16).padStart(6,0)},x1={isPrimitive:!1,match:n=>Array.isArray(n)||ArrayBuffer.isView(n),fromHexString(n,e,t=1){const i=ja.fromHexString(n);e[0]=(i>>16&255)/255*t,e[1]=(i>>8&255)/255*t,e[2]=(i&255)/255*t},toHexString([n,e,t],i=1){i=255/i;const s=n*i<<16^e*i<<8^t*i<<0;return ja.toHexString(s)}},y1={isPrimitive:!1,match:n=>Object(n)===n,fromHexString(n,e,t=1){const i=ja.fromHexString(n);e.r=(i>>16&255)/255*t,e.g=(i>>8&255)/255*t,e.b=(i&255)/255*t},toHexString({r:n,g:e,b:t},i=1){i=255/i;const s=n*i<<16^e*i<<8^t*i<<0;return ja.toHexString(s)}},b1=[_1,ja,x1,y1];function w1(n){return b1.find(e=>e.match(n))}class S1 extends Qi{constructor(e,t,i,s){super(e,t,i,"lil-color"),this.$input=document.createElement("input"),this.$input.setAttribute("type","color"),this.$input.setAttribute("tabindex",-1),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$text=document.createElement("input"),this.$text.setAttribute("type","text"),this.$text.setAttribute("spellcheck","false"),this.$text.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$display.appendChild(this.$input),this.$widget.appendChild(this.$display),this.$widget.appendChild(this.$text),this._format=w1(this.initialValue),this._rgbScale=s,this._initialValueHexString=this.save(),this._textFocused=!1,this.$input.addEventListener("input",()=>{this._setValueFromHexString(this.$input.value)}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$text.addEventListener("input",()=>{const r=ld(this.$text.value);r&&this._setValueFromHexString(r)}),this.$text.addEventListener("focus",()=>{this._textFocused=!0,this.$text.select()}),this.$text.addEventListener("blur",()=>{this._textFocused=!1,this.updateDisplay(),this._callOnFinishChange()}),this.$disable=this.$text,this.updateDisplay()}reset(){return this._setValueFromHexString(this._initialValueHexString),this}_setValueFromHexString(e){if(this._format.isPrimitive){const t=this._format.fromHexString(e);this.setValue(t)}else this._format.fromHexString(e,this.getValue(),this._rgbScale),this._callOnChange(),this.updateDisplay()}save(){return this._format.toHexString(this.getValue(),this._rgbScale)}load(e){return this._setValueFromHexString(e),this._callOnFinishChange(),this}updateDisplay(){return this.$input.value=this._format.toHexString(this.getValue(),this._rgbScale),this._textFocused||(this.$text.value=this.$input.value.substring(1)),this.$display.style.backgroundColor=this.$input.value,this}}class qc extends Qi{constructor(e,t,i){super(e,t,i,"lil-function"),this.$button=document.createElement("button"),this.$button.appendChild(this.$name),this.$widget.appendChild(this.$button),this.$button.addEventListener("click",s=>{s.preventDefault(),this.getValue().call(this.object),this._callOnChange()}),this.$button.addEventListener("touchstart",()=>{},{passive:!0}),this.$disable=this.$button}}class M1 extends Qi{constructor(e,t,i,s,r,a){super(e,t,i,"lil-number"),this._initInput(),this.min(s),this.max(r);const o=a!==void 0;this.step(o?a:this._getImplicitStep(),o),this.updateDisplay()}decimals(e){return this._decimals=e,this.updateDisplay(),this}min(e){return this._min=e,this._onUpdateMinMax(),this}max(e){return this._max=e,this._onUpdateMinMax(),this}step(e,t=!0){return this._step=e,this._stepExplicit=t,this}updateDisplay(){const e=this.getValue();if(this._hasSlider){let t=(e-this._min)/(this._max-this._min);t=Math.max(0,Math.min(t,1)),this.$fill.style.width=t*100+"%"}return this._inputFocused||(this.$input.value=this._decimals===void 0?e:e.toFixed(this._decimals)),this}_initInput(){this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("aria-labelledby",this.$name.id),window.matchMedia("(pointer: coarse)").matches&&(this.$input.setAttribute("type","number"),this.$input.setAttribute("step","any")),this.$widget.appendChild(this.$input),this.$disable=this.$input;const t=()=>{let x=parseFloat(this.$input.value);isNaN(x)||(this._stepExplicit&&(x=this._snap(x)),this.setValue(this._clamp(x)))},i=x=>{const R=parseFloat(this.$input.value);isNaN(R)||(this._snapClampSetValue(R+x),this.$input.value=this.getValue())},s=x=>{x.key==="Enter"&&this.$input.blur(),x.code==="ArrowUp"&&(x.preventDefault(),i(this._step*this._arrowKeyMultiplier(x))),x.code==="ArrowDown"&&(x.preventDefault(),i(this._step*this._arrowKeyMultiplier(x)*-1))},r=x=>{this._inputFocused&&(x.preventDefault(),i(this._step*this._normalizeMouseWheel(x)))};let a=!1,o,l,c,u,d;const h=5,m=x=>{o=x.clientX,l=c=x.clientY,a=!0,u=this.getValue(),d=0,window.addEventListener("mousemove",g),window.addEventListener("mouseup",y)},g=x=>{if(a){const R=x.clientX-o,S=x.clientY-l;Math.abs(S)>h?(x.preventDefault(),this.$input.blur(),a=!1,this._setDraggingStyle(!0,"vertical")):Math.abs(R)>h&&y()}if(!a){const R=x.clientY-c;d-=R*this._step*this._arrowKeyMultiplier(x),u+d>this._max?d=this._max-u:u+d<this._min&&(d=this._min-u),this._snapClampSetValue(u+d)}c=x.clientY},y=()=>{this._setDraggingStyle(!1,"vertical"),this._callOnFinishChange(),window.removeEventListener("mousemove",g),window.removeEventListener("mouseup",y)},p=()=>{this._inputFocused=!0},f=()=>{this._inputFocused=!1,this.updateDisplay(),this._callOnFinishChange()};this.$input.addEventListener("input",t),this.$input.addEventListener("keydown",s),this.$input.addEventListener("wheel",r,{passive:!1}),this.$input.addEventListener("mousedown",m),this.$input.addEventListener("focus",p),this.$input.addEventListener("blur",f)}_initSlider(){this._hasSlider=!0,this.$slider=document.createElement("div"),this.$slider.classList.add("lil-slider"),this.$fill=document.createElement("div"),this.$fill.classList.add("lil-fill"),this.$slider.appendChild(this.$fill),this.$widget.insertBefore(this.$slider,this.$input),this.domElement.classList.add("lil-has-slider");const e=(f,x,R,S,C)=>(f-x)/(R-x)*(C-S)+S,t=f=>{const x=this.$slider.getBoundingClientRect();let R=e(f,x.left,x.right,this._min,this._max);this._snapClampSetValue(R)},i=f=>{this._setDraggingStyle(!0),t(f.clientX),window.addEventListener("mousemove",s),window.addEventListener("mouseup",r)},s=f=>{t(f.clientX)},r=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("mousemove",s),window.removeEventListener("mouseup",r)};let a=!1,o,l;const c=f=>{f.preventDefault(),this._setDraggingStyle(!0),t(f.touches[0].clientX),a=!1},u=f=>{f.touches.length>1||(this._hasScrollBar?(o=f.touches[0].clientX,l=f.touches[0].clientY,a=!0):c(f),window.addEventListener("touchmove",d,{passive:!1}),window.addEventListener("touchend",h))},d=f=>{if(a){const x=f.touches[0].clientX-o,R=f.touches[0].clientY-l;Math.abs(x)>Math.abs(R)?c(f):(window.removeEventListener("touchmove",d),window.removeEventListener("touchend",h))}else f.preventDefault(),t(f.touches[0].clientX)},h=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("touchmove",d),window.removeEventListener("touchend",h)},m=this._callOnFinishChange.bind(this),g=400;let y;const p=f=>{if(Math.abs(f.deltaX)<Math.abs(f.deltaY)&&this._hasScrollBar)return;f.preventDefault();const R=this._normalizeMouseWheel(f)*this._step;this._snapClampSetValue(this.getValue()+R),this.$input.value=this.getValue(),clearTimeout(y),y=setTimeout(m,g)};this.$slider.addEventListener("mousedown",i),this.$slider.addEventListener("touchstart",u,{passive:!1}),this.$slider.addEventListener("wheel",p,{passive:!1})}_setDraggingStyle(e,t="horizontal"){this.$slider&&this.$slider.classList.toggle("lil-active",e),document.body.classList.toggle("lil-dragging",e),document.body.classList.toggle(`lil-${t}`,e)}_getImplicitStep(){return this._hasMin&&this._hasMax?(this._max-this._min)/1e3:.1}_onUpdateMinMax(){!this._hasSlider&&this._hasMin&&this._hasMax&&(this._stepExplicit||this.step(this._getImplicitStep(),!1),this._initSlider(),this.updateDisplay())}_normalizeMouseWheel(e){let{deltaX:t,deltaY:i}=e;return Math.floor(e.deltaY)!==e.deltaY&&e.wheelDelta&&(t=0,i=-e.wheelDelta/120,i*=this._stepExplicit?1:10),t+-i}_arrowKeyMultiplier(e){let t=this._stepExplicit?1:10;return e.shiftKey?t*=10:e.altKey&&(t/=10),t}_snap(e){let t=0;return this._hasMin?t=this._min:this._hasMax&&(t=this._max),e-=t,e=Math.round(e/this._step)*this._step,e+=t,e=parseFloat(e.toPrecision(15)),e}_clamp(e){return e<this._min&&(e=this._min),e>this._max&&(e=this._max),e}_snapClampSetValue(e){this.setValue(this._clamp(this._snap(e)))}get _hasScrollBar(){const e=this.parent.root.$children;return e.scrollHeight>e.clientHeight}get _hasMin(){return this._min!==void 0}get _hasMax(){return this._max!==void 0}}class E1 extends Qi{constructor(e,t,i,s){super(e,t,i,"lil-option"),this.$select=document.createElement("select"),this.$select.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$select.addEventListener("change",()=>{this.setValue(this._values[this.$select.selectedIndex]),this._callOnFinishChange()}),this.$select.addEventListener("focus",()=>{this.$display.classList.add("lil-focus")}),this.$select.addEventListener("blur",()=>{this.$display.classList.remove("lil-focus")}),this.$widget.appendChild(this.$select),this.$widget.appendChild(this.$display),this.$disable=this.$select,this.options(s)}options(e){return this._values=Array.isArray(e)?e:Object.values(e),this._names=Array.isArray(e)?e:Object.keys(e),this.$select.replaceChildren(),this._names.forEach(t=>{const i=document.createElement("option");i.textContent=t,this.$select.appendChild(i)}),this.updateDisplay(),this}updateDisplay(){const e=this.getValue(),t=this._values.indexOf(e);return this.$select.selectedIndex=t,this.$display.textContent=t===-1?e:this._names[t],this}}class A1 extends Qi{constructor(e,t,i){super(e,t,i,"lil-string"),this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("spellcheck","false"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$input.addEventListener("input",()=>{this.setValue(this.$input.value)}),this.$input.addEventListener("keydown",s=>{s.code==="Enter"&&this.$input.blur()}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$widget.appendChild(this.$input),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.value=this.getValue(),this}}var T1=`.lil-gui {
  font-family: var(--font-family);
  font-size: var(--font-size);
  line-height: 1;
  font-weight: normal;
  font-style: normal;
  text-align: left;
  color: var(--text-color);
  user-select: none;
  -webkit-user-select: none;
  touch-action: manipulation;
  --background-color: #1f1f1f;
  --text-color: #ebebeb;
  --title-background-color: #111111;
  --title-text-color: #ebebeb;
  --widget-color: #424242;
  --hover-color: #4f4f4f;
  --focus-color: #595959;
  --number-color: #2cc9ff;
  --string-color: #a2db3c;
  --font-size: 11px;
  --input-font-size: 11px;
  --font-family: -apple-system, BlinkMacSystemFont, "Segoe UI", Roboto, Arial, sans-serif;
  --font-family-mono: Menlo, Monaco, Consolas, "Droid Sans Mono", monospace;
  --padding: 4px;
  --spacing: 4px;
  --widget-height: 20px;
  --title-height: calc(var(--widget-height) + var(--spacing) * 1.25);
  --name-width: 45%;
  --slider-knob-width: 2px;
  --slider-input-width: 27%;
  --color-input-width: 27%;
  --slider-input-min-width: 45px;
  --color-input-min-width: 45px;
  --folder-indent: 7px;
  --widget-padding: 0 0 0 3px;
  --widget-border-radius: 2px;
  --checkbox-size: calc(0.75 * var(--widget-height));
  --scrollbar-width: 5px;
}
.lil-gui, .lil-gui * {
  box-sizing: border-box;
  margin: 0;
  padding: 0;
}
.lil-gui.lil-root {
  width: var(--width, 245px);
  display: flex;
  flex-direction: column;
  background: var(--background-color);
}
.lil-gui.lil-root > .lil-title {
  background: var(--title-background-color);
  color: var(--title-text-color);
}
.lil-gui.lil-root > .lil-children {
  overflow-x: hidden;
  overflow-y: auto;
}
.lil-gui.lil-root > .lil-children::-webkit-scrollbar {
  width: var(--scrollbar-width);
  height: var(--scrollbar-width);
  background: var(--background-color);
}
.lil-gui.lil-root > .lil-children::-webkit-scrollbar-thumb {
  border-radius: var(--scrollbar-width);
  background: var(--focus-color);
}
@media (pointer: coarse) {
  .lil-gui.lil-allow-touch-styles, .lil-gui.lil-allow-touch-styles .lil-gui {
    --widget-height: 28px;
    --padding: 6px;
    --spacing: 6px;
    --font-size: 13px;
    --input-font-size: 16px;
    --folder-indent: 10px;
    --scrollbar-width: 7px;
    --slider-input-min-width: 50px;
    --color-input-min-width: 65px;
  }
}
.lil-gui.lil-force-touch-styles, .lil-gui.lil-force-touch-styles .lil-gui {
  --widget-height: 28px;
  --padding: 6px;
  --spacing: 6px;
  --font-size: 13px;
  --input-font-size: 16px;
  --folder-indent: 10px;
  --scrollbar-width: 7px;
  --slider-input-min-width: 50px;
  --color-input-min-width: 65px;
}
.lil-gui.lil-auto-place, .lil-gui.autoPlace {
  max-height: 100%;
  position: fixed;
  top: 0;
  right: 15px;
  z-index: 1001;
}

.lil-controller {
  display: flex;
  align-items: center;
  padding: 0 var(--padding);
  margin: var(--spacing) 0;
}
.lil-controller.lil-disabled {
  opacity: 0.5;
}
.lil-controller.lil-disabled, .lil-controller.lil-disabled * {
  pointer-events: none !important;
}
.lil-controller > .lil-name {
  min-width: var(--name-width);
  flex-shrink: 0;
  white-space: pre;
  padding-right: var(--spacing);
  line-height: var(--widget-height);
}
.lil-controller .lil-widget {
  position: relative;
  display: flex;
  align-items: center;
  width: 100%;
  min-height: var(--widget-height);
}
.lil-controller.lil-string input {
  color: var(--string-color);
}
.lil-controller.lil-boolean {
  cursor: pointer;
}
.lil-controller.lil-color .lil-display {
  width: 100%;
  height: var(--widget-height);
  border-radius: var(--widget-border-radius);
  position: relative;
}
@media (hover: hover) {
  .lil-controller.lil-color .lil-display:hover:before {
    content: " ";
    display: block;
    position: absolute;
    border-radius: var(--widget-border-radius);
    border: 1px solid #fff9;
    top: 0;
    right: 0;
    bottom: 0;
    left: 0;
  }
}
.lil-controller.lil-color input[type=color] {
  opacity: 0;
  width: 100%;
  height: 100%;
  cursor: pointer;
}
.lil-controller.lil-color input[type=text] {
  margin-left: var(--spacing);
  font-family: var(--font-family-mono);
  min-width: var(--color-input-min-width);
  width: var(--color-input-width);
  flex-shrink: 0;
}
.lil-controller.lil-option select {
  opacity: 0;
  position: absolute;
  width: 100%;
  max-width: 100%;
}
.lil-controller.lil-option .lil-display {
  position: relative;
  pointer-events: none;
  border-radius: var(--widget-border-radius);
  height: var(--widget-height);
  line-height: var(--widget-height);
  max-width: 100%;
  overflow: hidden;
  word-break: break-all;
  padding-left: 0.55em;
  padding-right: 1.75em;
  background: var(--widget-color);
}
@media (hover: hover) {
  .lil-controller.lil-option .lil-display.lil-focus {
    background: var(--focus-color);
  }
}
.lil-controller.lil-option .lil-display.lil-active {
  background: var(--focus-color);
}
.lil-controller.lil-option .lil-display:after {
  font-family: "lil-gui";
  content: "↕";
  position: absolute;
  top: 0;
  right: 0;
  bottom: 0;
  padding-right: 0.375em;
}
.lil-controller.lil-option .lil-widget,
.lil-controller.lil-option select {
  cursor: pointer;
}
@media (hover: hover) {
  .lil-controller.lil-option .lil-widget:hover .lil-display {
    background: var(--hover-color);
  }
}
.lil-controller.lil-number input {
  color: var(--number-color);
}
.lil-controller.lil-number.lil-has-slider input {
  margin-left: var(--spacing);
  width: var(--slider-input-width);
  min-width: var(--slider-input-min-width);
  flex-shrink: 0;
}
.lil-controller.lil-number .lil-slider {
  width: 100%;
  height: var(--widget-height);
  background: var(--widget-color);
  border-radius: var(--widget-border-radius);
  padding-right: var(--slider-knob-width);
  overflow: hidden;
  cursor: ew-resize;
  touch-action: pan-y;
}
@media (hover: hover) {
  .lil-controller.lil-number .lil-slider:hover {
    background: var(--hover-color);
  }
}
.lil-controller.lil-number .lil-slider.lil-active {
  background: var(--focus-color);
}
.lil-controller.lil-number .lil-slider.lil-active .lil-fill {
  opacity: 0.95;
}
.lil-controller.lil-number .lil-fill {
  height: 100%;
  border-right: var(--slider-knob-width) solid var(--number-color);
  box-sizing: content-box;
}

.lil-dragging .lil-gui {
  --hover-color: var(--widget-color);
}
.lil-dragging * {
  cursor: ew-resize !important;
}
.lil-dragging.lil-vertical * {
  cursor: ns-resize !important;
}

.lil-gui .lil-title {
  height: var(--title-height);
  font-weight: 600;
  padding: 0 var(--padding);
  width: 100%;
  text-align: left;
  background: none;
  text-decoration-skip: objects;
}
.lil-gui .lil-title:before {
  font-family: "lil-gui";
  content: "▾";
  padding-right: 2px;
  display: inline-block;
}
.lil-gui .lil-title:active {
  background: var(--title-background-color);
  opacity: 0.75;
}
@media (hover: hover) {
  body:not(.lil-dragging) .lil-gui .lil-title:hover {
    background: var(--title-background-color);
    opacity: 0.85;
  }
  .lil-gui .lil-title:focus {
    text-decoration: underline var(--focus-color);
  }
}
.lil-gui.lil-root > .lil-title:focus {
  text-decoration: none !important;
}
.lil-gui.lil-closed > .lil-title:before {
  content: "▸";
}
.lil-gui.lil-closed > .lil-children {
  transform: translateY(-7px);
  opacity: 0;
}
.lil-gui.lil-closed:not(.lil-transition) > .lil-children {
  display: none;
}
.lil-gui.lil-transition > .lil-children {
  transition-duration: 300ms;
  transition-property: height, opacity, transform;
  transition-timing-function: cubic-bezier(0.2, 0.6, 0.35, 1);
  overflow: hidden;
  pointer-events: none;
}
.lil-gui .lil-children:empty:before {
  content: "Empty";
  padding: 0 var(--padding);
  margin: var(--spacing) 0;
  display: block;
  height: var(--widget-height);
  font-style: italic;
  line-height: var(--widget-height);
  opacity: 0.5;
}
.lil-gui.lil-root > .lil-children > .lil-gui > .lil-title {
  border: 0 solid var(--widget-color);
  border-width: 1px 0;
  transition: border-color 300ms;
}
.lil-gui.lil-root > .lil-children > .lil-gui.lil-closed > .lil-title {
  border-bottom-color: transparent;
}
.lil-gui + .lil-controller {
  border-top: 1px solid var(--widget-color);
  margin-top: 0;
  padding-top: var(--spacing);
}
.lil-gui .lil-gui .lil-gui > .lil-title {
  border: none;
}
.lil-gui .lil-gui .lil-gui > .lil-children {
  border: none;
  margin-left: var(--folder-indent);
  border-left: 2px solid var(--widget-color);
}
.lil-gui .lil-gui .lil-controller {
  border: none;
}

.lil-gui label, .lil-gui input, .lil-gui button {
  -webkit-tap-highlight-color: transparent;
}
.lil-gui input {
  border: 0;
  outline: none;
  font-family: var(--font-family);
  font-size: var(--input-font-size);
  border-radius: var(--widget-border-radius);
  height: var(--widget-height);
  background: var(--widget-color);
  color: var(--text-color);
  width: 100%;
}
@media (hover: hover) {
  .lil-gui input:hover {
    background: var(--hover-color);
  }
  .lil-gui input:active {
    background: var(--focus-color);
  }
}
.lil-gui input:disabled {
  opacity: 1;
}
.lil-gui input[type=text],
.lil-gui input[type=number] {
  padding: var(--widget-padding);
  -moz-appearance: textfield;
}
.lil-gui input[type=text]:focus,
.lil-gui input[type=number]:focus {
  background: var(--focus-color);
}
.lil-gui input[type=checkbox] {
  appearance: none;
  width: var(--checkbox-size);
  height: var(--checkbox-size);
  border-radius: var(--widget-border-radius);
  text-align: center;
  cursor: pointer;
}
.lil-gui input[type=checkbox]:checked:before {
  font-family: "lil-gui";
  content: "✓";
  font-size: var(--checkbox-size);
  line-height: var(--checkbox-size);
}
@media (hover: hover) {
  .lil-gui input[type=checkbox]:focus {
    box-shadow: inset 0 0 0 1px var(--focus-color);
  }
}
.lil-gui button {
  outline: none;
  cursor: pointer;
  font-family: var(--font-family);
  font-size: var(--font-size);
  color: var(--text-color);
  width: 100%;
  border: none;
}
.lil-gui .lil-controller button {
  height: var(--widget-height);
  text-transform: none;
  background: var(--widget-color);
  border-radius: var(--widget-border-radius);
}
@media (hover: hover) {
  .lil-gui .lil-controller button:hover {
    background: var(--hover-color);
  }
  .lil-gui .lil-controller button:focus {
    box-shadow: inset 0 0 0 1px var(--focus-color);
  }
}
.lil-gui .lil-controller button:active {
  background: var(--focus-color);
}

@font-face {
  font-family: "lil-gui";
  src: url("data:application/font-woff2;charset=utf-8;base64,d09GMgABAAAAAALkAAsAAAAABtQAAAKVAAEAAAAAAAAAAAAAAAAAAAAAAAAAAAAAHFQGYACDMgqBBIEbATYCJAMUCwwABCAFhAoHgQQbHAbIDiUFEYVARAAAYQTVWNmz9MxhEgodq49wYRUFKE8GWNiUBxI2LBRaVnc51U83Gmhs0Q7JXWMiz5eteLwrKwuxHO8VFxUX9UpZBs6pa5ABRwHA+t3UxUnH20EvVknRerzQgX6xC/GH6ZUvTcAjAv122dF28OTqCXrPuyaDER30YBA1xnkVutDDo4oCi71Ca7rrV9xS8dZHbPHefsuwIyCpmT7j+MnjAH5X3984UZoFFuJ0yiZ4XEJFxjagEBeqs+e1iyK8Xf/nOuwF+vVK0ur765+vf7txotUi0m3N0m/84RGSrBCNrh8Ee5GjODjF4gnWP+dJrH/Lk9k4oT6d+gr6g/wssA2j64JJGP6cmx554vUZnpZfn6ZfX2bMwPPrlANsB86/DiHjhl0OP+c87+gaJo/gY084s3HoYL/ZkWHTRfBXvvoHnnkHvngKun4KBE/ede7tvq3/vQOxDXB1/fdNz6XbPdcr0Vhpojj9dG+owuSKFsslCi1tgEjirjXdwMiov2EioadxmqTHUCIwo8NgQaeIasAi0fTYSPTbSmwbMOFduyh9wvBrESGY0MtgRjtgQR8Q1bRPohn2UoCRZf9wyYANMXFeJTysqAe0I4mrherOekFdKMrYvJjLvOIUM9SuwYB5DVZUwwVjJJOaUnZCmcEkIZZrKqNvRGRMvmFZsmhP4VMKCSXBhSqUBxgMS7h0cZvEd71AWkEhGWaeMFcNnpqyJkyXgYL7PQ1MoSq0wDAkRtJIijkZSmqYTiSImfLiSWXIZwhRh3Rug2X0kk1Dgj+Iu43u5p98ghopcpSo0Uyc8SnjlYX59WUeaMoDqmVD2TOWD9a4pCRAzf2ECgwGcrHjPOWY9bNxq/OL3I/QjwEAAAA=") format("woff2");
}`;function R1(n){const e=document.createElement("style");e.innerHTML=n;const t=document.querySelector("head link[rel=stylesheet], head style");t?document.head.insertBefore(e,t):document.head.appendChild(e)}let Dp=!1;class Yd{constructor({parent:e,autoPlace:t=e===void 0,container:i,width:s,title:r="Controls",closeFolders:a=!1,injectStyles:o=!0,touchStyles:l=!0}={}){if(this.parent=e,this.root=e?e.root:this,this.children=[],this.controllers=[],this.folders=[],this._closed=!1,this._hidden=!1,this.domElement=document.createElement("div"),this.domElement.classList.add("lil-gui"),this.$title=document.createElement("button"),this.$title.classList.add("lil-title"),this.$title.setAttribute("aria-expanded",!0),this.$title.addEventListener("click",()=>this.openAnimated(this._closed)),this.$title.addEventListener("touchstart",()=>{},{passive:!0}),this.$children=document.createElement("div"),this.$children.classList.add("lil-children"),this.domElement.appendChild(this.$title),this.domElement.appendChild(this.$children),this.title(r),this.parent){this.parent.children.push(this),this.parent.folders.push(this),this.parent.$children.appendChild(this.domElement);return}this.domElement.classList.add("lil-root"),l&&this.domElement.classList.add("lil-allow-touch-styles"),!Dp&&o&&(R1(T1),Dp=!0),i?i.appendChild(this.domElement):t&&(this.domElement.classList.add("lil-auto-place","autoPlace"),document.body.appendChild(this.domElement)),s&&this.domElement.style.setProperty("--width",s+"px"),this._closeFolders=a}add(e,t,i,s,r){if(Object(i)===i)return new E1(this,e,t,i);const a=e[t];switch(typeof a){case"number":return new M1(this,e,t,i,s,r);case"boolean":return new v1(this,e,t);case"string":return new A1(this,e,t);case"function":return new qc(this,e,t)}console.error(`gui.add failed
	property:`,t,`
	object:`,e,`
	value:`,a)}addColor(e,t,i=1){return new S1(this,e,t,i)}addFolder(e){const t=new Yd({parent:this,title:e});return this.root._closeFolders&&t.close(),t}load(e,t=!0){return e.controllers&&this.controllers.forEach(i=>{i instanceof qc||i._name in e.controllers&&i.load(e.controllers[i._name])}),t&&e.folders&&this.folders.forEach(i=>{i._title in e.folders&&i.load(e.folders[i._title])}),this}save(e=!0){const t={controllers:{},folders:{}};return this.controllers.forEach(i=>{if(!(i instanceof qc)){if(i._name in t.controllers)throw new Error(`Cannot save GUI with duplicate property "${i._name}"`);t.controllers[i._name]=i.save()}}),e&&this.folders.forEach(i=>{if(i._title in t.folders)throw new Error(`Cannot save GUI with duplicate folder "${i._title}"`);t.folders[i._title]=i.save()}),t}open(e=!0){return this._setClosed(!e),this.$title.setAttribute("aria-expanded",!this._closed),this.domElement.classList.toggle("lil-closed",this._closed),this}close(){return this.open(!1)}_setClosed(e){this._closed!==e&&(this._closed=e,this._callOnOpenClose(this))}show(e=!0){return this._hidden=!e,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}openAnimated(e=!0){return this._setClosed(!e),this.$title.setAttribute("aria-expanded",!this._closed),requestAnimationFrame(()=>{const t=this.$children.clientHeight;this.$children.style.height=t+"px",this.domElement.classList.add("lil-transition");const i=r=>{r.target===this.$children&&(this.$children.style.height="",this.domElement.classList.remove("lil-transition"),this.$children.removeEventListener("transitionend",i))};this.$children.addEventListener("transitionend",i);const s=e?this.$children.scrollHeight:0;this.domElement.classList.toggle("lil-closed",!e),requestAnimationFrame(()=>{this.$children.style.height=s+"px"})}),this}title(e){return this._title=e,this.$title.textContent=e,this}reset(e=!0){return(e?this.controllersRecursive():this.controllers).forEach(i=>i.reset()),this}onChange(e){return this._onChange=e,this}_callOnChange(e){this.parent&&this.parent._callOnChange(e),this._onChange!==void 0&&this._onChange.call(this,{object:e.object,property:e.property,value:e.getValue(),controller:e})}onFinishChange(e){return this._onFinishChange=e,this}_callOnFinishChange(e){this.parent&&this.parent._callOnFinishChange(e),this._onFinishChange!==void 0&&this._onFinishChange.call(this,{object:e.object,property:e.property,value:e.getValue(),controller:e})}onOpenClose(e){return this._onOpenClose=e,this}_callOnOpenClose(e){this.parent&&this.parent._callOnOpenClose(e),this._onOpenClose!==void 0&&this._onOpenClose.call(this,e)}destroy(){this.parent&&(this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.folders.splice(this.parent.folders.indexOf(this),1)),this.domElement.parentElement&&this.domElement.parentElement.removeChild(this.domElement),Array.from(this.children).forEach(e=>e.destroy())}controllersRecursive(){let e=Array.from(this.controllers);return this.folders.forEach(t=>{e=e.concat(t.controllersRecursive())}),e}foldersRecursive(){let e=Array.from(this.folders);return this.folders.forEach(t=>{e=e.concat(t.foldersRecursive())}),e}}function nv(n){return n==="1"?"":n.replace("^2","²").replace("^3","³")}function iv(n){return hd(n.name,n.label??n.name,n.description)}function C1(n){const e=nv(n.unit),[t]=iv(n);return e?`${t} [${e}]`:t}function cd(n){const e=nv(n.unit),t=e?` ${e}`:"";return n.min!==null&&n.max!==null?`${n.min} … ${n.max}${t}`:n.min!==null?`≥ ${n.min}${t}`:n.max!==null?`≤ ${n.max}${t}`:"any finite number"}function P1(n,e){return Number.isFinite(e)&&(n.min===null||e>=n.min)&&(n.max===null||e<=n.max)?null:T("msg.notAllowed",{name:n.name,value:e,allowed:n.allowed??cd(n),range:cd(n)})}class L1{constructor(e,t,i,s){this.p=e,this.send=t,this.explain=i,this.restore=s}p;send;explain;restore;typed=null;changed(e,t){if(t){this.typed=e;return}this.typed=null,this.commit(e)}finished(){const e=this.typed;this.typed=null,e!==null&&this.commit(e)}left(e){Number.isNaN(Number.parseFloat(e))&&(this.typed=null,this.explain(T("start.notNumber",{name:this.p.name})),this.restore())}commit(e){const t=P1(this.p,e);if(t===null){this.send(e);return}this.explain(t),this.restore()}}function sv(n,e,t,i,s,r){typeof e[t.name]!="number"&&(e[t.name]=t.default);const a=n.add(e,t.name,t.ui_min,t.ui_max).name(C1(t)),o=a.domElement.querySelector("input"),l=new L1(t,i,s,()=>{e[t.name]=r()??t.default,a.updateDisplay()});a.onChange(d=>l.changed(d,o!==null&&document.activeElement===o)),a.onFinishChange(()=>l.finished()),a.domElement.addEventListener("blur",d=>d.target===o&&o!==null&&l.left(o.value),!0);const[,c]=iv(t);a.domElement.title=T("gui.paramHelp",{help:c,name:t.name,unit:t.unit,range:cd(t),default:t.default}),a.domElement.dataset.param=t.name,a.step(t.step,!1);const u=a;return typeof u._clamp=="function"&&(u._clamp=d=>d),a}function Zd(n,e){let t=-1/0,i=null,s=null;return(...r)=>{s=r;const a=t+e-performance.now();a<=0&&i===null?(t=performance.now(),n(...r),s=null):i===null&&(i=setTimeout(()=>{i=null,t=performance.now(),s!==null&&n(...s),s=null},Math.max(0,a)))}}const D1={damped:{damping:.3}};function N1(n){const e=D1[n];return e?{type:"set_model",model:n,params:{...e}}:{type:"set_model",model:n}}function I1(n){const e={};for(const t of n)e[t.label?`${bi(t.name,t.label)} (${t.name})`:t.name]=t.name;return e}class k1{constructor(e,t,i){this.parent=e,this.schema=t,this.actions=i,this.picker=e.add(this.state,"model",I1(t.models)).name(T("gui.model")).onChange(s=>i.send(N1(s))),this.picker.domElement.dataset.control="model",this.picker.domElement.title=[T("gui.modelsHelp"),...t.models.map(s=>`${bi(s.name,s.label??s.name)} (${s.name}): ${jv(s.name,s.summary)}`)].join(`
`),this.sendParam=Zd((s,r)=>{i.send({type:"set_params",params:{[s]:r}})},50)}parent;schema;actions;state={model:"ideal"};picker;paramsFolder=null;paramControls=[];values={};inEffect=null;shown=null;sendParam;spec(e){return this.schema.models.find(t=>t.name===e)}rebuild(e){this.paramsFolder?.destroy(),this.paramsFolder=null,this.paramControls=[],this.values={},this.shown=e;const t=this.spec(e);if(t===void 0||t.params.length===0)return;const i=this.parent.addFolder(T("gui.modelParams",{model:bi(e,t.label??e)}));for(const s of t.params){this.values[s.name]=s.default;const r=sv(i,this.values,s,a=>this.sendParam(s.name,a),this.actions.explain,()=>this.inEffect?.[s.name]);this.paramControls.push(r)}this.paramsFolder=i}sync(e){const t=e.model??"ideal";this.state.model=t,this.picker.updateDisplay();const i=this.picker.$display;i&&!this.spec(t)&&(i.textContent=bi(t,t)),this.shown!==t&&this.rebuild(t),this.inEffect=e.model_params??{};for(const[s,r]of Object.entries(this.inEffect))this.values[s]=r;for(const s of this.paramControls)s.domElement.contains(document.activeElement)||s.updateDisplay()}}const F1={velocity:["vec.velocity","vec.velocityHelp"],momentum:["vec.momentum","vec.momentumHelp"],gravity:["vec.gravity","vec.gravityHelp"],tension:["vec.tension","vec.tensionHelp"],net:["vec.net","vec.netHelp"],angularMomentum:["vec.angularMomentum","vec.angularMomentumHelp"],torque:["vec.torque","vec.torqueHelp"]};function U1(n,e,t,i){const s=n.addFolder(T("gui.view"));s.add(e,"trail").name(T("gui.trail")).onChange(t),s.add(e,"trailSeconds",1,120,1).name(T("gui.trailSeconds")).onChange(t),s.add(e,"sphere").name(T("gui.sphere")).onChange(t),s.add(e,"axes").name(T("gui.axes")).onChange(t);const r={topView:!1};s.add(r,"topView").name(T("gui.topView")).onChange(u=>{i(u),t()});const a={off:"stereo.off",anaglyph:"stereo.anaglyph","side by side":"stereo.sideBySide"},o=Object.fromEntries(Hg.map(u=>[a[u]?T(a[u]):u,u])),l=s.add(e,"stereo",o).name(T("gui.stereo")).onChange(t);l.domElement.title=T("gui.stereoHelp"),l.domElement.dataset.control="stereo",s.close();const c=n.addFolder(T("gui.vectors"));for(const[u,[d,h]]of Object.entries(F1)){const m=c.add(e,u).name(T(d)).onChange(t);m.domElement.title=T(h),m.domElement.dataset.vector=u,m.$name.style.borderLeft=`10px solid #${Xd[u].toString(16).padStart(6,"0")}`,m.$name.style.paddingLeft="4px"}for(const u of["X","Y","Z"]){const d=`origin${u}`;c.add(e,d,-5,5,.01).name(T("gui.origin",{axis:u.toLowerCase()})).onChange(t).domElement.title=T("gui.originHelp")}return c.close(),s}function Np(n,e,t){const i=n.addFolder(e);return i.domElement.dataset.folder=t,i}class O1{constructor(e,t,i,s,r){this.view=s,this.gui=new Yd({container:e,title:T("gui.title"),width:270});const a={};this.model=a;const o=Np(this.gui,T("gui.pendulum"),"pendulum"),l=Zd((w,v)=>{r.send({type:"set_params",[w]:v})},50);for(const w of t.model.params){const v=F=>l(w.name,F),M=()=>this.status?.params?.[w.name];this.synced.push(sv(o,a,w,v,r.explain,M))}this.modelControls=new k1(o,t,r);const c=this.gui.addFolder(T("gui.integrator")).close(),u={};for(const w of t.methods)u[ul(w.name,w.order)]=w.name;a.method=t.methods.find(w=>w.default)?.name??t.methods[0]?.name??"rattle";const d=c.add(a,"method",u).name(T("gui.method")).onChange(w=>r.send({type:"set_method",method:w}));d.domElement.title=t.methods.map(w=>`${ul(w.name,w.order)} — ${w.name}${eo()==="en"?`: ${w.summary}`:""}`).join(`
`),this.synced.push(d);const h=t.controls.dt;a.dt=h.default??.001;const m=c.add(a,"dt").name("dt [s]").decimals(6).onFinishChange(w=>{w>=h.min&&w<=h.max?r.send({type:"set_method",dt:w}):this.refuse(r,m,"dt",T("gui.dtRange",{min:h.min,max:h.max}))});m.domElement.title=T("gui.dtHelp",{min:h.min,max:h.max}),this.saysNotNumber(r,m,"dt"),this.synced.push(m);const g=Np(this.gui,T("gui.run"),"run"),y=t.controls.time_scale;a.time_scale=y.default??1;const p=g.add(a,"time_scale").name(T("gui.timeScale")).decimals(3).onFinishChange(w=>{w>=y.min&&w<=y.max?r.send({type:"set_time_scale",time_scale:w}):this.refuse(r,p,"time_scale",T("gui.tsRange",{min:y.min,max:y.max}))});p.domElement.title=T("gui.tsHelp",{min:y.min,max:y.max}),this.saysNotNumber(r,p,"time_scale"),this.synced.push(p),a.paused=!1,a.run=()=>r.send({type:a.paused===!0?"resume":"pause"}),this.runButton=g.add(a,"run").name(T("toolbar.pause")),a.stepN=1;const f=t.controls.step_n;g.add(a,"stepN",f.min,Math.min(f.max,1e3),1).name(T("gui.stepN")),a.step=()=>r.send({type:"step",n:Math.round(Number(a.stepN))}),g.add(a,"step").name(T("toolbar.step")),a.reset=()=>r.send({type:"reset"}),g.add(a,"reset").name(T("toolbar.reset"));const x={};for(const w of i)w.error===void 0&&(x[gh(w.name,w.title)]=w.name);a.scenario="";const R=g.add(a,"scenario",x).name(T("gui.scenario")).onChange(w=>r.send({type:"load_scenario",name:w}));R.domElement.title=i.filter(w=>w.error===void 0).map(w=>`${w.name}: ${gh(w.name,w.title)}`).join(`
`),this.synced.push(R),U1(this.gui,s,()=>r.viewChanged(this.view,this.topView),w=>{this.topView=w});const S=this.gui.addFolder(T("gui.export")).close();a.csv=()=>r.downloadCSV(),S.add(a,"csv").name(T("gui.csv")).domElement.dataset.control="csv",a.toml=()=>r.downloadTOML();const C=S.add(a,"toml").name(T("gui.toml"));C.domElement.dataset.control="toml",C.domElement.title=T("gui.tomlHelp"),a.png=()=>r.screenshot(),S.add(a,"png").name(T("gui.png")),a.link=()=>r.copyLink(),S.add(a,"link").name(T("gui.link"))}view;gui;model;synced=[];runButton;modelControls;topView=!1;status=null;refuse(e,t,i,s){e.explain(s);const r=this.status?.[i];r!==void 0&&(this.model[i]=r),t.updateDisplay()}saysNotNumber(e,t,i){t.domElement.addEventListener("blur",s=>{const r=s.target;r instanceof HTMLInputElement&&Number.isNaN(Number.parseFloat(r.value))&&this.refuse(e,t,i,T("start.notNumber",{name:i}))},!0)}sync(e){this.status=e;const t=this.model;t.length=e.params.length,t.mass=e.params.mass,t.g=e.params.g,t.method=e.method,t.dt=e.dt,t.time_scale=e.time_scale,t.paused=e.paused,t.scenario=e.scenario??"";for(const i of this.synced)i.domElement.contains(document.activeElement)||i.updateDisplay();this.runButton.name(e.paused?T("toolbar.start"):T("toolbar.pause")),this.modelControls.sync(e)}}function z1(n){const e={model:n.model,length:n.params.length,mass:n.params.mass,g:n.params.g,params:{...n.model_params},x:n.start.x,v:n.start.v,method:n.method,t0:n.t0,t_end:Math.max(n.t0+100,Math.ceil(n.t))};n.adaptive?(n.rtol!==void 0&&(e.rtol=n.rtol),n.atol!==void 0&&(e.atol=n.atol)):e.dt=n.dt;const t=n.title??n.scenario;return t&&(e.title=`${t} (from the lab)`),e}function B1(n){const e=n.store.status;if(e===null)return n.explain(T("msg.notConnected"));fetch("api/scenario.toml",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(z1(e))}).then(async t=>{if(!t.ok)throw new Error(fd(await t.json().catch(()=>({})),`HTTP ${t.status}`));$d(`pendulab-${e.scenario??"lab"}.toml`,await t.blob())}).catch(t=>n.explain(T("msg.downloadFailed",{why:t instanceof Error?t.message:String(t)})))}function H1(n,e){e.write();const t=window.location.href,i=DT(e.lab()),s=()=>n.explain(`${t} — ${i}`,!0),r=navigator.clipboard?.writeText(t);r===void 0?s():r.then(()=>n.explain(T("msg.linkCopied",{what:i}),!0),s)}function V1(n,e,t,i){const{store:s,scene:r,view:a,session:o,explain:l}=n,c=u=>`pendulab-${s.status?.scenario??"lab"}.${u}`;return new O1(xt("gui"),e,t,a,{send:o.send,explain:l,downloadCSV:()=>$d(c("csv"),new Blob([s.toCSV()],{type:"text/csv"})),downloadTOML:()=>B1(n),screenshot:()=>Yg(c("png"),r.screenshot()),copyLink:()=>H1(n,i),viewChanged:(u,d)=>{r.setTopView(d),r.setStereo(u.stereo)}})}function yi(n){Ip.has(n)||(Ip.add(n),performance.mark(`pendulab:${n}`))}const Ip=new Set;function G1(n,e,t,i,s){const{store:r,scene:a}=n,o=r.status;r.onStatus(s),o!==null&&(o.scenario!==s.scenario||o.model!==s.model)&&t.clearNews(),(o===null||o.epoch!==s.epoch)&&e.energy.rescale(),e.controls.sync(s),Kg(e.controls.gui),e.tools.sync(s),e.toolbar.showRunning(s.paused),a.setLength(s.params.length),a.setModel(s.model),e.portraits.setModel(s.model),i.write()}function W1(n,e){const t=e.twinToRestore,i=n.session.twin;t===null||i===null||(e.twinToRestore=null,$c(()=>n.store.status?.commands,()=>n.session.sent(),5e3).then(()=>(i.restore(t),$c(()=>i.store.status?.paused?1:void 0,()=>1,5e3))).then(()=>{for(const s of e.replay)n.session.send(s);e.replay=[]}))}function q1(n,e,t,i,s){if(s.type==="error"){n.store.onError(s);const r=Hp(s);n.explain(s.command&&s.key===void 0?`${s.command}: ${r}`:r);return}if(s.type==="event"){n.store.onEvent(s),n.explain(t_(s),!0);return}yi("first status"),G1(n,e,t,i,s);for(const r of i.takeStartup())n.session.send(r);W1(n,i)}class X1{real=null;held=[];call(e){this.real!==null?e(this.real):this.held.push(e)}onOpen(){this.call(e=>e.onOpen())}onClose(){this.call(e=>e.onClose())}onFrames(e){this.call(t=>t.onFrames(e))}onNotice(e){this.call(t=>t.onNotice(e))}onProtocolError(e){this.call(t=>t.onProtocolError(e))}attach(e){this.real=e;for(const t of this.held.splice(0))t(e)}}function $1(){const n=new X1;return yi("socket opening"),{conn:new dd(Xc(window.location),n),held:n}}function K1(n,e,t,i,s,r,a){const{store:o}=n;e.attach({onOpen:()=>{yi("socket open"),o.setConnected(!0),xt("conn").textContent=T("conn.connected"),xt("offline").hidden=!0},onClose:()=>{o.setConnected(!1),xt("conn").textContent=T("conn.retrying"),xt("offline").textContent=T("conn.gone"),xt("offline").hidden=!1,s.restoreShown()},onFrames:l=>{yi("first frames");const c=performance.now();o.onFrames(l),r.onFrames(),a.add("frames received",performance.now()-c)},onNotice:l=>q1(n,t,i,s,l),onProtocolError:l=>n.explain(`protocol: ${l}`)})}function Y1(n){const{store:e,scene:t,session:i,explain:s}=n,r=Zd((o,l)=>{i.send({type:"set_state",x:o,v:l,project:!0})},50),a=()=>{e.status?.paused===!1&&i.send({type:"pause"})};t.enableDrag((o,l)=>{l==="start"&&a(),r(o,[0,0,0]),l==="end"&&s(T("msg.dragged"),!0)},(o,l,c)=>{if(c==="start"){a(),s(T("msg.pull"),!0);return}if(l===null)return;r(o,l.v);const u=l.capped?T("msg.capped"):"",d={v:l.speed.toFixed(2),cap:u};s(T(c==="end"?"msg.velocitySet":"msg.velocity",d),!0)})}function rv(n){const e=n.store.status?.params;return{mass:e?.mass??1,g:e?.g??9.81,length:e?.length??1}}function Z1(n,e,t){const{store:i,scene:s,view:r,session:a}=n,o=performance.now(),l=i.displayed(),{mass:c,g:u}=rv(n),d=aA(i.status?.model_params),{start:h,end:m}=i.trailRange(r.trailSeconds),g=a.twin,y=g?.drawn(i.playT,r.trailSeconds)??null;s.setTwinLayout(g?.layout()??null),s.setExtras(g?.extraLayouts()??[]);const p=g?.drawnExtras(i.playT,r.trailSeconds)??[],f=[l,i.trail,h,m,c,u,...d,...Object.values(r),y?.frame??null,y?.trail.end??0,...p.map(C=>C.frame)],x=e.changed(f);x&&(s.update(l,{frames:i.trail,start:h,end:m},r,c,u,d),s.updateTwin(y?.frame??null,y?.trail??{frames:[],start:0,end:0}),s.updateExtras(p));const R=performance.now();t.add("scene update",R-o);const S=s.draw(x);return S&&t.add("scene render (submit)",performance.now()-R),S}function j1(n,e,t,i,s){const{store:r,session:a}=n,o=r.displayed(),{mass:l,g:c,length:u}=rv(n),d=a.twin;let h=performance.now();const m=r.reference;e.plots.update(r.history,r.events,hx(m?.energy??0,m?.j3??0,l,c,u)),e.chosen.update(r.history.frames,{mass:l,g:c,length:u},d?.on?d.store.history.frames:null),d?.update(xt("plots").clientWidth-8);let g=performance.now();i.add("plots setData",g-h),e.portraits.update(r.history,o,e.analyses.veff,l,c,u),e.portraits.updateEM(e.analyses.em,o),h=performance.now(),i.add("portraits",h-g),e.reduced.update(o,u),g=performance.now(),i.add("reduced view",g-h);const y=r.latest(),p=y?Bg(y,l,c,u,r.work):null;e.energy.draw(p,r.status?.model!=="ideal"),h=performance.now(),i.add("energy bars",h-g),e.tools.update(o?.x??null,o?.t??null,o?Math.hypot(...o.v):0),e.tools.describe(Qg(o,p),s),t.write(),g=performance.now(),i.add("tools and link",g-h),e.data.update(o,r),i.add("data panel",performance.now()-g)}function J1(n,e,t,i){let s=0,r=performance.now();const a=new rT(100),o=new aT,l=c=>{yi("loop"),n.store.advancePlayhead((c-r)/1e3),r=c,Z1(n,o,i)&&(s++,yi("first render"),n.store.frames.length>0&&yi("first frame drawn")),a.due(c)&&(j1(n,e,t,i,c),yi("panels drawn")),requestAnimationFrame(l)};return requestAnimationFrame(l),()=>s}const Q1=80,eR=1,tR=.4,nR=8;function Zo(n,e,t,i){return new en(new oa(n,e,t),new tr({color:i,roughness:.6}))}function kp(n,e,t=!1){const i=new Ot;i.setAttribute("position",new li(new Float32Array(e*3),3));const s=new ci({color:n}),r=t?new io(i,s):new Fi(i,s);return r.frustumCulled=!1,r}function Fp(n,...e){const t=n.geometry.getAttribute("position");e.forEach((i,s)=>t.setXYZ(s,i.x,i.y,i.z)),t.needsUpdate=!0}const iR=new z(0,0,-1);class sR{group=new ki;girder=Zo(Q1,.5,.7,15906304);trolley=Zo(1.4,1.1,.5,14708768);rope=kp(13620960,2);hook=Zo(.45,.3,.6,15909376);load=Zo(1.6,1.2,1,4881360);slings=kp(11581632,4,!0);wind=new wg(new z(1,0,0),new z,1,6741503,.6,.4);p=new z;end=new z;u=new z;constructor(){this.group.add(this.girder,this.trolley,this.rope,this.hook,this.load,this.slings,this.wind),this.group.visible=!1}update(e,t){if(this.group.visible=e!==null,e===null)return;const i=this.p.fromArray(e.pivot),s=this.end.fromArray(e.x).add(i),r=Math.hypot(...e.x),a=this.u.fromArray(e.x).divideScalar(r>0?r:1);this.girder.position.set(0,i.y,i.z+.6),this.trolley.position.set(i.x,i.y,i.z+.25);const o=a.clone().multiplyScalar(-Math.min(eR,.5*r)).add(s);Fp(this.rope,i,o);const l=new _s().setFromUnitVectors(iR,a);this.hook.position.copy(o),this.hook.quaternion.copy(l),this.load.position.copy(a.clone().multiplyScalar(.5).add(s)),this.load.quaternion.copy(l);const c=d=>new z(.7*d,0,0).applyQuaternion(l).add(s);Fp(this.slings,o,c(-1),o,c(1));const u=t===null?0:Math.hypot(t[0],t[1]);if(this.wind.visible=u>0,t!==null&&u>0){const d=Math.min(nR,Math.max(1,tR*u)),h=new z(t[0]/u,t[1]/u,0);this.wind.setDirection(h),this.wind.setLength(d,.6,.4),this.wind.position.copy(s).addScaledVector(h,-d-1.5)}}}const rR={title:"Crane",on:"Crane mode",onHelp:"a load on a hoisted rope below a trolley you drive (the core steps it; keys J L: trolley, I K: across)",off:"Back to the pendulum",left:"drive the trolley in −x (hold; key J)",right:"drive the trolley in +x (hold; key L)",back:"drive the crane in +y (hold; key I)",fwd:"drive the crane in −y (hold; key K)",moveBy:"move {d} m",moveHelp:"move the trolley by {d} m along x and stop",stop:"Stop",shaping:"Command shaping",shapingHelp:"the trolley’s command convolved with a shaper designed for the current rope (ZV: 2 impulses, ZVD: 3)",shapingOff:"off",rope:"Rope length (m)",ropeHelp:"the hoist winds the rope to this length, live",wind:"Wind speed (m/s)",windDir:"Wind direction (°)",windHelp:"steady wind on the load: drag ½ρ c_W A |w − v|(w − v)",sway:"Sway angle",residual:"Residual sway (largest in the last 10 s)",readout:"Trolley at x = {x} m, y = {y} m · rope {l} m",predicted:"Last move: residual sway {u}° without shaping, {s}° with {shaper} (linear theory)"},aR={title:"Kran",on:"Kranmodus",onHelp:"eine Last am Hubseil unter einer Laufkatze, die Sie fahren (der Kern rechnet; Tasten J L: Katze, I K: quer)",off:"Zurück zum Pendel",left:"Laufkatze in −x fahren (halten; Taste J)",right:"Laufkatze in +x fahren (halten; Taste L)",back:"Kran in +y fahren (halten; Taste I)",fwd:"Kran in −y fahren (halten; Taste K)",moveBy:"{d} m fahren",moveHelp:"die Laufkatze um {d} m in x fahren und anhalten",stop:"Halt",shaping:"Eingangsformung",shapingHelp:"der Fahrbefehl gefaltet mit einem Shaper für die aktuelle Seillänge (ZV: 2 Impulse, ZVD: 3)",shapingOff:"aus",rope:"Seillänge (m)",ropeHelp:"das Hubwerk wickelt das Seil live auf diese Länge",wind:"Windgeschwindigkeit (m/s)",windDir:"Windrichtung (°)",windHelp:"stetiger Wind auf die Last: Widerstand ½ρ c_W A |w − v|(w − v)",sway:"Pendelwinkel",residual:"Restpendeln (größter Winkel der letzten 10 s)",readout:"Laufkatze bei x = {x} m, y = {y} m · Seil {l} m",predicted:"Letzte Fahrt: Restpendeln {u}° ohne Formung, {s}° mit {shaper} (lineare Theorie)"},oR={title:"Grue",on:"Mode grue",onHelp:"une charge au câble de levage sous un chariot que vous pilotez (le cœur calcule ; touches J L : chariot, I K : travers)",off:"Retour au pendule",left:"déplacer le chariot vers −x (maintenir ; touche J)",right:"déplacer le chariot vers +x (maintenir ; touche L)",back:"déplacer la grue vers +y (maintenir ; touche I)",fwd:"déplacer la grue vers −y (maintenir ; touche K)",moveBy:"avancer de {d} m",moveHelp:"déplacer le chariot de {d} m selon x puis s’arrêter",stop:"Arrêt",shaping:"Mise en forme de la commande",shapingHelp:"la commande du chariot convoluée avec un filtre conçu pour la longueur de câble actuelle (ZV : 2 impulsions, ZVD : 3)",shapingOff:"sans",rope:"Longueur du câble (m)",ropeHelp:"le treuil enroule le câble jusqu’à cette longueur, en direct",wind:"Vitesse du vent (m/s)",windDir:"Direction du vent (°)",windHelp:"vent constant sur la charge : traînée ½ρ c_W A |w − v|(w − v)",sway:"Angle de balancement",residual:"Balancement résiduel (le plus grand des 10 dernières s)",readout:"Chariot en x = {x} m, y = {y} m · câble {l} m",predicted:"Dernier déplacement : balancement résiduel {u}° sans mise en forme, {s}° avec {shaper} (théorie linéaire)"},lR={en:rR,de:aR,fr:oR};function $n(n,e={}){return zp(lR[eo()][n],e)}function av(n){return Math.atan2(Math.hypot(n[0],n[1]),-n[2])}function cR(n,e){let t=0;const i=n[n.length-1];if(i===void 0)return 0;for(let s=n.length-1;s>=0;s--){const r=n[s];if(r===void 0||r.t<i.t-e)break;t=Math.max(t,av(r.x))}return t}function uR(n){return Math.hypot(n[0],n[1],n[2])}function dR(n,e){const t=e*Math.PI/180,i=s=>Math.round(s*1e9)/1e9;return[i(n*Math.cos(t)),i(n*Math.sin(t))]}function hR(n){const[e=0,t=0]=n,i=Math.atan2(t,e)*180/Math.PI;return{speed:Math.hypot(e,t),degrees:Math.round((i%360+360)%360)}}const jo=180/Math.PI,Up=15,ov=10,Op=5;function Qt(n,e={},t=""){const i=document.createElement(n);for(const[s,r]of Object.entries(e))i.setAttribute(s,r);return t&&(i.textContent=t),i}function Ra(n,e,t){const i=Qt("label",{class:"crane-row"});return i.append(`${$n(n)} `,e),t&&(i.title=$n(t)),i}class fR{constructor(e,t,i,s){this.send=t,this.vMax=i,this.gNow=s,this.root=Qt("section",{class:"tools crane","data-tool":"crane"}),this.root.appendChild(Qt("h3",{},$n("title"))),this.toggle=Qt("button",{type:"button","data-crane":"toggle",title:$n("onHelp")},$n("on")),this.toggle.addEventListener("click",()=>this.switchMode()),this.root.append(this.toggle,this.controls),this.buildDrive(),this.buildSettings(),this.buildGauge(),this.controls.hidden=!0,e.prepend(this.root)}send;vMax;gNow;root;toggle;controls=Qt("div",{class:"crane-controls"});shaping=Qt("select",{"data-crane":"shaping"});rope=Qt("input",{type:"range",min:"1",max:"50",step:"0.5","data-crane":"rope"});ropeOut=Qt("output");windSpeed=Qt("input",{type:"range",min:"0",max:"30",step:"1","data-crane":"wind"});windDir=Qt("input",{type:"range",min:"0",max:"355",step:"5","data-crane":"wind-dir"});windOut=Qt("output");gauge=Qt("meter",{min:"0",max:String(Up),"data-crane":"sway"});swayText=Qt("span",{"data-crane":"sway-text"});residualText=Qt("span",{"data-crane":"residual"});readout=Qt("p",{"data-crane":"readout"});predicted=Qt("p",{"data-crane":"predicted"});on=!1;switchMode(){if(this.on){this.send({type:"set_model",model:"ideal"});return}const e=this.gNow();this.send({type:"set_params",length:10,mass:1e3,g:e>0?e:9.81}),this.send({type:"set_state",theta:0,phi:0,theta_dot:0,phi_dot:0}),this.send({type:"crane",on:!0}),this.send({type:"resume"})}hold(e,t){const i=r=>{r.preventDefault(),this.drive(t)},s=()=>this.drive([0,0]);e.addEventListener("pointerdown",i),e.addEventListener("pointerup",s),e.addEventListener("pointerleave",r=>r.buttons!==0&&s()),e.addEventListener("keydown",r=>(r.key==="Enter"||r.key===" ")&&!r.repeat&&i(r)),e.addEventListener("keyup",r=>(r.key==="Enter"||r.key===" ")&&s())}drive(e){const t=this.vMax();this.send(e[0]===0&&e[1]===0?{type:"crane",stop:!0}:{type:"crane",drive:[e[0]*t,e[1]*t]})}buildDrive(){const e=Qt("div",{class:"crane-drive",role:"group"}),t=[["◀","left",[-1,0]],["▲","back",[0,1]],["▼","fwd",[0,-1]],["▶","right",[1,0]]];for(const[s,r,a]of t){const o=Qt("button",{type:"button","aria-label":$n(r),title:$n(r),"data-crane":r},s);this.hold(o,a),e.appendChild(o)}const i=Qt("button",{type:"button","data-crane":"stop"},$n("stop"));i.addEventListener("click",()=>this.drive([0,0])),e.appendChild(i);for(const s of[-Op,Op]){const r=Qt("button",{type:"button",title:$n("moveHelp",{d:s}),"data-crane":`move${s}`},$n("moveBy",{d:s>0?`+${s}`:s}));r.addEventListener("click",()=>this.send({type:"crane",move:[s,0]})),e.appendChild(r)}this.controls.appendChild(e)}buildSettings(){const e=[["0",$n("shapingOff")],["1","ZV"],["2","ZVD"]];for(const[s,r]of e)this.shaping.appendChild(Qt("option",{value:s},r));this.shaping.addEventListener("change",()=>this.send({type:"set_params",params:{shaping:Number(this.shaping.value)}})),this.controls.appendChild(Ra("shaping",this.shaping,"shapingHelp")),this.rope.addEventListener("input",()=>this.ropeOut.textContent=`${this.rope.value} m`),this.rope.addEventListener("change",()=>this.send({type:"crane",rope:Number(this.rope.value)}));const t=Ra("rope",this.rope,"ropeHelp");t.appendChild(this.ropeOut),this.controls.appendChild(t);const i=()=>{const[s,r]=dR(Number(this.windSpeed.value),Number(this.windDir.value));this.windOut.textContent=`${this.windSpeed.value} m/s → ${this.windDir.value}°`,this.send({type:"set_params",params:{wind_x:s,wind_y:r}})};this.windSpeed.addEventListener("change",i),this.windDir.addEventListener("change",i),this.controls.append(Ra("wind",this.windSpeed,"windHelp"),Ra("windDir",this.windDir,"windHelp"),this.windOut)}buildGauge(){const e=Ra("sway",this.gauge);e.append(" ",this.swayText);const t=Qt("p");t.append(`${$n("residual")}: `,this.residualText),this.controls.append(e,t,this.readout,this.predicted)}sync(e){if(this.on=e!=null,this.controls.hidden=!this.on,this.toggle.textContent=$n(this.on?"off":"on"),this.toggle.setAttribute("aria-pressed",String(this.on)),!this.on||e===null||e===void 0)return;const t=r=>document.activeElement!==r;t(this.shaping)&&(this.shaping.value=String(["off","zv","zvd"].indexOf(e.shaping))),t(this.rope)&&(this.rope.value=String(e.rope_target),this.ropeOut.textContent=`${e.rope_target} m`);const i=hR(e.wind);t(this.windSpeed)&&t(this.windDir)&&(this.windSpeed.value=String(Math.round(i.speed)),this.windDir.value=String(i.degrees),this.windOut.textContent=`${i.speed.toFixed(1)} m/s → ${i.degrees}°`);const s=e.last_move;this.predicted.textContent=s===null?"":$n("predicted",{u:(s.residual_unshaped*jo).toFixed(2),s:(s.residual_shaped*jo).toFixed(2),shaper:s.shaping==="off"?"ZVD":s.shaping.toUpperCase()})}show(e,t){if(!this.on||t===null)return;const i=av(t.x)*jo;this.gauge.value=Math.min(i,Up),this.swayText.textContent=`${i.toFixed(2)}°`,this.residualText.textContent=`${(cR(e,ov)*jo).toFixed(2)}°`;const s=t.pivot;this.readout.textContent=$n("readout",{x:s[0].toFixed(2),y:s[1].toFixed(2),l:uR(t.x).toFixed(2)})}}const pR={j:[-1,0],l:[1,0],i:[0,1],k:[0,-1]};class mR{constructor(e,t){this.lab=e;const{scene:i,session:s,store:r}=e;this.panel=new fR(t,s.send,()=>r.status?.crane?.v_max??.5,()=>r.status?.params.g??9.81),i.addDrawing(this.drawing.group),i.crane={afterUpdate:o=>this.drawing.update(this.active()?o:null,r.status?.crane?.wind??null),hidesBody:()=>this.active()},document.addEventListener("keydown",o=>this.key(o,!0)),document.addEventListener("keyup",o=>this.key(o,!1));let a=null;setInterval(()=>{const o=r.status;o!==a&&(a=o,this.panel.sync(o?.crane)),this.panel.show(r.trailWindow(ov),r.latest())},100)}lab;panel;drawing=new sR;held=null;active(){return(this.lab.store.status?.crane??null)!==null}key(e,t){const i=e.key.toLowerCase(),s=pR[i];s===void 0||!this.active()||e.ctrlKey||e.metaKey||e.altKey||id(e.target,e.key)||(e.preventDefault(),t&&!e.repeat&&this.held!==i?(this.held=i,this.panel.drive(s)):!t&&this.held===i&&(this.held=null,this.panel.drive([0,0])))}}function gR(n){n.software&&(xt("render").textContent=` · ${T("page.software")}`,xt("render").title=T("page.softwareHelp",{renderer:n.renderer??""}));const e=new sT(xt("scene"),n);return e.renderer.domElement.setAttribute("role","img"),e.renderer.domElement.setAttribute("aria-label",T("page.scene")),e}function vR(n,e,t,i,s,r){const{store:a,scene:o,session:l}=n;return{...r,store:a,send:l.send,screenshot:()=>o.screenshot(),bobOnScreen:()=>o.bobOnScreen(),handleOnScreen:()=>o.handleOnScreen(),lastPull:()=>o.lastPull(),handleAt:()=>o.handleAt(),quality:()=>t,frameCosts:()=>i.take(),twinOnScreen:()=>o.twinOnScreen(),extras:()=>l.twin?.extras?.running()??[],extrasOnScreen:()=>o.extrasOnScreen(),instrumentsOnScreen:()=>o.instrumentsOnScreen(),tones:()=>e.tools.tones,sphereOnScreen:()=>o.sphereOnScreen(),separation:()=>l.twin?.separationNow()??{t:[],d:[]},energy:()=>e.energy.shown,plotScales:()=>e.plots.scales(),measuredPoints:()=>o.measuredPoints(),engine:()=>s}}async function _R(){yi("start");const n=await Av(),e=$1();ET();const t=new qd,i=new AT(xt("message")),s=i.explain,[r,a]=await Promise.all([lu("api/schema"),lu("api/scenarios")]);t.tickHz=r.tick_hz,yi("schema");const o=GA(WA(),window.devicePixelRatio),l=gR(o);yi("scene");const c=new oT,u=new uT(xt("plots")),d=new px(xt("plots"),G=>c.add("plots drawn (uPlot)",G)),h=new vx(xt("portraits")),m=new Wd(xt("reduced"),o),g=new h_(xt("data")),y={...Ml,simple:qT(Ml.simple)},p=new IT(t,y,s),f=new kT(t,s);f.conn=e.conn;const x={store:t,scene:l,view:y,session:f,explain:s},{toolbar:R,help:S,lastVideo:C}=$T(x),w=g1(x);ZT(x,S,w);const v=new cT(xt("energy")),M=V1(x,r,a,p);l.setStereo(y.stereo);const F=new yx(t,m,s),L=new gT(xt("tools"),t,r.methods,Xc(window.location),{send:f.send,explain:s});f.twin=L,L.extras=new mT(xt("tools"),Xc(window.location),s),p.attach(u,L),new _T(xt("tools")),new mR(x,xt("tools")),Kg(M.gui),yi("panels"),K1(x,e.held,{controls:M,tools:w,toolbar:R,portraits:h,energy:v},i,p,F,c),Y1(x);const D={plots:d,chosen:u,portraits:h,reduced:m,data:g,energy:v,tools:w,analyses:F};let B=()=>0;window.pendulab=vR(x,D,o,c,n,{drawn:()=>B(),lastVideo:C,twin:L.store}),B=J1(x,D,p,c)}_R().catch(n=>{const e=document.getElementById("offline");e&&(e.textContent=`${T("conn.noStart")} ${n instanceof Error?n.message:String(n)}`,e.hidden=!1),console.error(n)});
