(function(){const e=document.createElement("link").relList;if(e&&e.supports&&e.supports("modulepreload"))return;for(const s of document.querySelectorAll('link[rel="modulepreload"]'))n(s);new MutationObserver(s=>{for(const r of s)if(r.type==="childList")for(const a of r.addedNodes)a.tagName==="LINK"&&a.rel==="modulepreload"&&n(a)}).observe(document,{childList:!0,subtree:!0});function t(s){const r={};return s.integrity&&(r.integrity=s.integrity),s.referrerPolicy&&(r.referrerPolicy=s.referrerPolicy),s.crossOrigin==="use-credentials"?r.credentials="include":s.crossOrigin==="anonymous"?r.credentials="omit":r.credentials="same-origin",r}function n(s){if(s.ep)return;s.ep=!0;const r=t(s);fetch(s.href,r)}})();const Hg=["t","x1","x2","x3","v1","v2","v3","energy","j3","tension","power","a1","a2","a3","pivot1","pivot2","pivot3","taut","error_x"],Gg={fields:Hg},Zh=Gg.fields,Vg=Zh.length,no=8*Vg;function gn(i){const e=Zh.indexOf(i);if(e<0)throw new Error(`frame.json lacks the field ${i}`);return e}const Mi={t:gn("t"),x:[gn("x1"),gn("x2"),gn("x3")],v:[gn("v1"),gn("v2"),gn("v3")],energy:gn("energy"),j3:gn("j3"),tension:gn("tension"),power:gn("power"),a:[gn("a1"),gn("a2"),gn("a3")],pivot:[gn("pivot1"),gn("pivot2"),gn("pivot3")],taut:gn("taut"),errorX:gn("error_x")};class fi extends Error{}function Wg(i){if(i.byteLength===0||i.byteLength%no!==0)throw new fi(`a frame message has a multiple of ${no} bytes, got ${i.byteLength}`);const e=new DataView(i),t=i.byteLength/no,n=[];for(let s=0;s<t;s++){const r=s*no,a=l=>e.getFloat64(r+8*l,!0),o=l=>[a(l[0]),a(l[1]),a(l[2])];n.push({t:a(Mi.t),x:o(Mi.x),v:o(Mi.v),energy:a(Mi.energy),j3:a(Mi.j3),tension:a(Mi.tension),power:a(Mi.power),a:o(Mi.a),pivot:o(Mi.pivot),taut:a(Mi.taut)!==0,errorX:a(Mi.errorX)})}return n}function Bl(i){return typeof i=="object"&&i!==null&&!Array.isArray(i)}function Xg(i){let e;try{e=JSON.parse(i)}catch(t){throw new fi(`notice is not JSON: ${String(t)}`)}if(!Bl(e))throw new fi("notice is not a JSON object");if(e.type==="error"&&typeof e.message=="string"){const t=typeof e.command=="string"?e.command:null,n={type:"error",message:e.message,command:t},s=e.values;return typeof e.key=="string"&&Bl(s)&&Object.values(s).every(r=>typeof r=="string"||typeof r=="number")&&(n.key=e.key,n.values=s),n}if(e.type==="status"){const t=e.params;if(!Bl(t)||typeof e.epoch!="number"||typeof e.method!="string")throw new fi("status notice lacks epoch, method or params");const n=e.frame_fields;if(Array.isArray(n)&&n.join(",")!==Zh.join(","))throw new fi(`server frame layout ${n.join(",")} differs from the page's`);return e}if(e.type==="event")return $g(e);throw new fi(`unknown notice type ${JSON.stringify(e.type)}`)}function zl(i){return typeof i=="number"&&Number.isFinite(i)}function $g(i){const{kind:e,t,energy_lost:n,x:s,epoch:r}=i,a=i.skipped??0;if(e!=="slack"&&e!=="taut")throw new fi(`event notice: kind ${JSON.stringify(e)} is not "slack" or "taut"`);if(!zl(t))throw new fi("event notice: t is not a finite number");if(!zl(n)||n<0)throw new fi("event notice: energy_lost is not a finite number ≥ 0");if(!Array.isArray(s)||s.length!==3||!s.every(zl))throw new fi("event notice: x is not 3 finite numbers");if(!Number.isInteger(r)||!Number.isInteger(a)||a<0)throw new fi("event notice: epoch or skipped is not an integer");return{type:"event",kind:e,t,energy_lost:n,x:[s[0],s[1],s[2]],epoch:r,skipped:a}}async function qg(){return"server"}function Yg(i){return new WebSocket(i)}function Uc(i){const e=i.protocol==="https:"?"wss:":"ws:",t=i.pathname.endsWith("/")?i.pathname:i.pathname.replace(/[^/]*$/,"");return`${e}//${i.host}${t}ws`}function Fc(i,e,t,n=20){const s=Date.now()+t;return new Promise(r=>{const a=()=>{(i()??-1)>=e()?r(!0):Date.now()>=s?r(!1):setTimeout(a,n)};a()})}class Jh{constructor(e,t){this.url=e,this.handlers=t,this.open()}url;handlers;sent=0;ws=null;retryMs=500;closedByUs=!1;open(){const e=Yg(this.url);e.binaryType="arraybuffer",e.onopen=()=>{this.retryMs=500,this.sent=0,this.handlers.onOpen()},e.onmessage=t=>{try{t.data instanceof ArrayBuffer?this.handlers.onFrames(Wg(t.data)):typeof t.data=="string"&&this.handlers.onNotice(Xg(t.data))}catch(n){if(n instanceof fi)this.handlers.onProtocolError(n.message);else throw n}},e.onclose=()=>{this.ws=null,this.handlers.onClose(),this.closedByUs||(setTimeout(()=>this.open(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))},this.ws=e}get isOpen(){return this.ws!==null&&this.ws.readyState===1}send(e){return!this.isOpen||this.ws===null?!1:(this.ws.send(JSON.stringify(e)),this.sent++,!0)}close(){this.closedByUs=!0,this.ws?.close()}}const er={"page.title":"Pendulab lab — the spherical pendulum","page.units":"SI units, z up","page.scene":"3-D view of the pendulum (drag to orbit, scroll to zoom)","page.panel":"controls and measurements","page.software":"software WebGL: no antialiasing","conn.connected":"connected","conn.retrying":"disconnected: retrying…","conn.gone":"The lab’s server is not answering: the pendulum has stopped. Is pendulab serve still running? Trying to reconnect …","conn.noStart":"The lab could not start:","toolbar.label":"run controls","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Reset","toolbar.stepShort":"Step","toolbar.recordShort":"● Record","toolbar.recordStopShort":"■ Stop","toolbar.start":"start (Space)","toolbar.pause":"pause (Space)","toolbar.reset":"reset to the start (R)","toolbar.step":"one step (S)","toolbar.record":"record a video (WebM)","toolbar.recordStop":"stop recording and download the video","toolbar.help":"keyboard shortcuts and colour key (?)","toolbar.present":"presentation mode: large type for a projector","toolbar.language":"language","toolbar.collapse":"hide the panel","toolbar.expand":"show the panel","gui.title":"Pendulab lab","gui.pendulum":"Pendulum","gui.model":"model","gui.modelParams":"{model}: parameters","gui.paramHelp":"{help} — key {name} [{unit}]; allowed: {range}; default {default}","gui.integrator":"Integrator","gui.method":"method","gui.order":"order {n}","gui.symplectic":"symplectic","gui.adaptive":"adaptive","method.rk4":"Runge–Kutta, 4th order (classic; drifts off the sphere)","method.dop853":"Adaptive, very accurate (Dormand–Prince, 8th order)","method.rattle":"Symplectic (RATTLE, 2nd order; the default)","method.rattle4":"Symplectic (RATTLE, 4th order)","method.rattle6":"Symplectic (RATTLE, 6th order)","method.rattle8":"Symplectic (RATTLE, 8th order)","method.rkmk4":"Rotation steps on the sphere (Munthe-Kaas, 4th order)","method.rk4_angles":"Runge–Kutta 4 in angles (breaks down at the poles)","method.other":"{name} (order {n})","kind.generic":"goes round and round in a rosette","kind.conical":"circles at one height (conical pendulum)","kind.planar":"swings to and fro in a plane","kind.planar_rotating":"swings over the top in a plane","kind.separatrix":"creeps towards the top for ever","kind.rest":"at rest","kind.great_circle":"goes round a great circle (no gravity)","data.energy":"energy E","data.energyChange":"energy change E − E₀","data.spin":"angular momentum about the vertical J₃","data.spinChange":"its change J₃ − J₃(0)","data.height":"height z","data.turning":"lowest and highest height z₁, z₂","gui.dtRange":"dt must be between {min} and {max} s","gui.dtHelp":"step size of fixed-step methods; {min} … {max} s (dop853 chooses its own)","gui.run":"Run","gui.timeScale":"time scale [×]","gui.tsRange":"the time scale must be between {min} and {max}","gui.tsHelp":"simulated seconds per second (slow motion below 1); {min} … {max}","gui.stepN":"steps per step","gui.scenario":"scenario","gui.view":"View","gui.trail":"trail","gui.trailSeconds":"trail [s]","gui.sphere":"sphere of reach","gui.axes":"axes","gui.topView":"top view","gui.stereo":"stereo","gui.stereoHelp":"anaglyph: red–cyan glasses; side by side: a stereo viewer","stereo.off":"off","stereo.anaglyph":"anaglyph","stereo.sideBySide":"side by side","gui.vectors":"Vectors","gui.origin":"origin {axis} [m]","gui.originHelp":"origin of L and τ relative to the pivot (0: the pivot)","gui.export":"Share and export","gui.csv":"download trajectory (CSV)","gui.toml":"download scenario (TOML)","gui.tomlHelp":"the scenario as it stands (model, parameters, start, method) as a file for `pendulab run`","gui.png":"screenshot (PNG)","gui.link":"copy link to this lab (what it carries: on copying)","vec.velocity":"velocity v","vec.velocityHelp":"v [m/s], drawn as 0.25 s of travel","vec.momentum":"momentum m v","vec.momentumHelp":"m v [kg m/s], 0.25 m per kg m/s","vec.gravity":"gravity m g","vec.gravityHelp":"the weight m g d [N] (d: the gravity direction); forces: m·max(|g|, 1) N ↔ 0.5 l","vec.tension":"rod force (tension)","vec.tensionHelp":"the rod force −T x/|x| [N], T from the server","vec.net":"net force m a","vec.netHelp":"m a [N]: a = ẍ computed by the server’s core (relative to the pivot)","vec.angularMomentum":"angular momentum L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] about the origin o, drawn from o","vec.torque":"torque τ","vec.torqueHelp":"τ = (x − o) × m a [N m] about the origin o, drawn from o; dL/dt = τ","data.now":"Now (from the server)","data.exact":"Exact solution of this orbit","data.tension":"tension","data.tensionMin":"tension min","data.tensionMax":"tension max","data.method":"method","data.state":"state","data.paused":"paused","data.running":"running","data.lagging":" (lagging: slower than asked)","data.model":"model","data.kind":"kind of motion","data.periodZ":"z-period T_z","data.swingPeriod":"swing period T","data.advance":"azimuthal advance Δφ per T_z","data.rotation":"rotation number W = Δφ/2π","data.reduced":"reduced view (σ₁, σ₂, σ₃): J₃ surface ∩ energy plane","portrait.phase":"phase portrait: vertical speed ż against height z","portrait.veff":"effective potential V_eff(θ); energy E dashed, θ now dotted","portrait.em":"energy–momentum map: E against J₃ (dot: now)","portrait.orbit":"orbit","portrait.emBoundary":"boundary (conical orbits)","note.spring":"the swinging spring leaves the sphere (its length varies): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.string":"the string goes slack (free flight inside the sphere): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.exactIdeal":"the exact solution exists for the ideal pendulum only; this is the {model} model","note.reducedIdeal":"the reduced view is the ideal pendulum’s; this is the {model} model","event.slack":"the string went slack (tension 0: free flight)","event.taut":"the string snapped taut, lost {lost} J","event.skippedOne":" ({n} earlier event of this moment not shown)","event.skippedMany":" ({n} earlier events of this moment not shown)","event.slackRow":"went slack","event.tautRow":"snapped taut","event.tautValue":"t = {t} s, lost {lost}","data.power":"power P = dE/dt","data.springForce":"spring force k(|r| − l₀)","data.springLength":"spring length |r|","data.stretch":"stretch |r| − l₀","data.string":"string","data.slackZero":"slack (0)","data.slack":"slack: free flight, |x| = {r} m","data.taut":"taut","data.events":"events","data.noEvents":"none yet (slack, snaps)","data.z3":"z₃ (outside)","data.dynamic":"Δφ dynamic","data.geometric":"Δφ geometric","data.error":"position error |Δx|","data.errorRel":"position error / l","data.errorHow":"error obtained by","data.errorPaused":"estimate paused (the server’s work budget is used up; it catches up when there is time)","data.errorNone":"no estimate","data.howExact":"the true error: against the exact solution (since t = {since} s)","data.howRichardson":"estimate: Richardson against a companion at dt/2 = {dt} s, order p = {p} (since t = {since} s)","data.howCompanion":"estimate: a companion run at rtol = {rtol} (since t = {since} s)","page.softwareHelp":"{renderer}: drawn without multisampling for the frame rate","tools.start":"Start angle","tools.thetaHelp":"θ₀: the angle from the downward vertical, in degrees (0 … 180)","tools.phiHelp":"φ₀: the azimuth around the vertical, in degrees","tools.phiDotHelp":"φ̇₀: how fast the bob starts going round, in degrees per second (0: a planar swing)","tools.setStart":"set start","tools.world":"Gravity and friction","tools.gravity":"gravity","tools.friction":"friction","tools.frictionHelp":"linear damping c [1/s]: the force −m c v; on the ideal pendulum it switches to the damped model","tools.noFriction":"the {model} model has no friction parameter","tools.now":"Angles now","tools.stopwatch":"Stopwatch (simulated time)","tools.swStart":"start","tools.swStop":"stop","tools.swLap":"lap","tools.swReset":"reset","tools.period":"Period timer","tools.periodHelp":"measured from the motion: the lowest points of the bob; a swing’s period ends when the bob passes the bottom again the same way. Compared with the exact value (ideal pendulum) or the theory (small-swing formula with friction)","tools.periodCount":"mean over {n} periods","tools.periodCountZ":"mean over {n} lowest-to-lowest times","tools.periodWait":"waiting for the bob to pass its lowest point twice","tools.motion":"motion","tools.kindNone":"—","tools.kindSwing":"swings to and fro","tools.kindOver":"swings over the top","tools.kindOrbit":"goes round (never through the bottom)","tools.periodSwing":"period T [s]","tools.periodZ":"lowest point to lowest point [s]","tools.advance":"turn between lowest points [°]","tools.precession":"pattern turns per round [°]","tools.amplitude":"amplitude (largest angle) [°]","tools.band":"angle from the vertical [°]","tools.theory":"theory","tools.measured":"measured","tools.exact":"exact","tools.difference":"difference","tools.overlays":"Ruler and protractor","tools.ruler":"ruler (metres)","tools.protractor":"protractor (θ in degrees)","gloss.title":"Words (glossary)","gloss.advanced":"show formula numbers and extra rows (advanced)","gloss.period":"period T","gloss.periodText":"the time for one whole swing: from one side to the other and back, until the bob passes the bottom again the same way. Measured in seconds.","gloss.amplitude":"amplitude","gloss.amplitudeText":"the largest angle between the rod and the vertical during a swing. With friction it gets smaller swing by swing.","gloss.lowest":"lowest point","gloss.lowestText":"where the bob is lowest in a swing. A swing passes through the very bottom; a bob going round passes its lowest point beside it.","gloss.friction":"friction (damping)","gloss.frictionText":"a force against the motion that takes energy out, so the swings die away. The number c says how strong it is (per second).","gloss.gravity":"gravity g","gloss.gravityText":"how strongly the planet pulls: 9.81 m/s² on Earth, 1.62 on the Moon. A stronger pull makes the pendulum swing faster.","gloss.energy":"kinetic and potential energy","gloss.energyText":"kinetic energy is energy of motion (fast bob: much); potential energy is energy of height (high bob: much). They turn into each other as the bob swings; friction takes some away.","gloss.spin":"angular momentum J₃","gloss.spinText":"how much the bob goes round the vertical. Zero for a swing in a plane; it stays the same for the ideal pendulum.","gloss.precession":"precession","gloss.precessionText":"a bob going round does not close its path: the pattern turns a little every round, and the top view becomes a rosette.","gloss.method":"method (integrator)","gloss.methodText":"the way the computer works out the motion in small time steps. Symplectic methods keep the energy right for a long time; others drift.","gloss.drift":"energy drift","gloss.driftText":"how far the computed energy has wandered from where it started. For the ideal pendulum it should stay zero; what is left is the computer’s rounding.","tools.moveGroup":"move the {what}","tools.moveLeft":"move left","tools.moveRight":"move right","tools.moveUp":"move up","tools.moveDown":"move down","tools.moveBack":"back to its place","describe.none":"no motion yet","describe.text":"angle {theta}° from the vertical, {dir}, speed {v} m/s","describe.rest":"at rest","describe.turning":"at a turning point","describe.rising":"rising","describe.falling":"falling towards the bottom","describe.energy":"; energy {k} % kinetic, {u} % potential","describe.lost":", {p} % lost to friction","describe.toggle":"describe the motion every 5 s (screen readers; D: now)","tools.sound":"sound: a tone at each lowest point (higher when faster)","tools.mystery":"mystery planet (find g from the period)","tools.reveal":"reveal g","tools.mysteryOn":"a mystery planet: time the swings and work out g = 4π² l / T²","tools.revealed":"the mystery planet’s g is {g} m/s²","start.notNumber":"{name} must be a number","start.thetaRange":"θ₀ = {value}° is not allowed: 0 … 180°","gravity.custom":"custom","gravity.earth":"Earth","gravity.moon":"Moon","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"zero","gravity.negative":"negative (upwards)","energy.title":"Energy","energy.kinetic":"kinetic","energy.potential":"potential","energy.lost":"lost","energy.total":"total","plot.dE":"energy drift |ΔE|/E_s (log)","plot.dJ3":"J₃ drift |ΔJ₃|/J_s (log)","plot.z":"height z(t)","plot.tension":"rod tension T(t)","plot.time":"time t [s]","plot.floor":"float64 roundoff 2.2e-16","alt.empty":"no data yet","alt.summary":"{y} from {yLo} to {yHi} against {x} from {xLo} to {xHi}; now {yNow} at {xNow}","chosen.title":"Plot any variables","chosen.xAxis":"across","chosen.yAxis":"up","var.t":"time t","var.theta":"angle θ","var.phi":"azimuth φ","var.x":"x","var.y":"y","var.z":"height z","var.zdot":"vertical speed ż","var.speed":"speed |v|","var.energy":"energy E","var.kinetic":"kinetic energy K","var.potential":"potential energy U","var.j3":"angular momentum J₃","var.tension":"tension T","var.power":"power P","var.radius":"distance |x|","twin.title":"Two pendulums","twin.mode":"second pendulum","twin.off":"off","twin.epsilon":"start differs by ε","twin.method":"another integrator","twin.damped":"damped beside this one","twin.own":"its own length, mass and start (side by side)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"the second pendulum needs a length > 0, a mass > 0 and a start angle 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"period T [s] (periods)","twin.methodPick":"integrator","twin.damping":"damping [1/s]","twin.start":"start both","twin.bad":"ε must be a number and the damping ≥ 0","twin.first":"pendulum 1","twin.second":"pendulum 2","twin.separation":"separation of the bobs |r₁ − r₂| [m]","help.title":"Keyboard shortcuts and colour key","help.space":"start / pause","help.r":"reset to the start","help.s":"one step (paused)","help.arrows":"on a focused slider: one step down / up","help.page":"on a focused slider: ten steps","help.camera":"on the 3-D view: turn the camera / zoom","help.bobKeys":"on the 3-D view: move the bob’s start by 1° (pauses)","help.describe":"describe the motion now (screen readers)","help.tab":"move between controls","help.help":"this overlay","help.esc":"close this overlay","help.colours":"Colours","help.close":"close","help.bob":"bob","help.trail":"trail","help.twin":"second pendulum","help.ruler":"ruler and protractor","msg.notConnected":"not connected to the server","link.scenario":"the scenario (model, parameters, method, start)","link.paused":"paused","link.pausedAt":"paused at {t} s","link.view":"view: {list}","link.plot":"plot {y} against {x}","link.twin":"second pendulum {what}","link.lang":"language {lang}","msg.linkCopied":"link copied; it carries {what}","msg.dragged":"start set by dragging (at rest there): press start to release it","msg.pull":"pull the arrow to set the start velocity","msg.capped":" (capped: the most the arrow sets, 4√(g l))","msg.velocitySet":"start velocity set: |v| = {v} m/s{cap}; press start to run from it","msg.velocity":"start velocity |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} is not allowed: {allowed} ({range})","msg.recording":"recording the view…","msg.recorded":"video saved ({mb} MB, WebM)","msg.noRecording":"this browser cannot record the view ({why})","fit.title":"Measured data","fit.load":"Load measured data…","fit.help":"a CSV file of measurements in SI units (columns t, x, y, z or x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): the server fits the pendulum to it, loads the fitted motion and draws the measured path dotted beside it","fit.model":"model","fit.params":"fit","fit.paramsDefault":"what the data determine","fit.paramsHelp":"the parameters to fit, comma separated (e.g. length,g,damping,pivot); empty: what the data can determine","fit.clear":"clear measured path","fit.running":"fitting {name} …","fit.noPath":"(frame-free data: no measured path to draw)","fit.failed":"fit: {why}","fit.loaded":"fitted {name}: the fitted motion is loaded, the measured path dotted in gold","page.tools":"measuring tools","page.energy":"energy bar chart","page.data":"data panel","page.plots":"live plots","page.portraits":"phase portrait, effective potential, energy–momentum map","page.reduced":"reduced view in σ-space","gui.modelsHelp":"the models (code name in brackets):","fit.summary":"{model}: {state}","fit.converged":"the fit converged","fit.notConverged":"the fit did not converge","fit.notDetermined":"(not determined by these data)","fit.fullReport":"the fit’s full report (as pendulab fit prints it, in English)","server.too_small":"{name} = {value}: at least {limit} allowed","server.too_small_strict":"{name} = {value}: must be more than {limit}","server.too_large":"{name} = {value}: at most {limit} allowed","server.too_large_strict":"{name} = {value}: must be less than {limit}","server.missing":"{name} is missing","server.unknown_key":"unknown key {name}","server.nonfinite_motion":"the motion left floating point at t = {t} s ({fields} not finite): parameters or a start this extreme; paused — reset, or change the parameters","server.integration_stopped":"the computation stopped ({detail}); paused","server.throttled":"throttled: {lost} command(s) dropped; send at most {per_second} per second","server.server_full":"the server is full: {active} lab sessions are open, the most it serves at once; close another tab or try again later","server.device_full":"too many lab sessions from your device: {have} are open, the most one device may have; close another tab","server.device_busy":"too many computations at once from your device: at most {most} may run or wait for one device; wait for the answers, then try again","server.internal_error":"internal error of the server: {detail}","scenario.conical":"Conical pendulum at 45°","scenario.damped":"Damped rosette (c = 0.05 1/s)","scenario.foucault":"Foucault pendulum at 49° N, Earth’s rotation exaggerated (Ω = 0.02 rad/s)","scenario.inverted_g":"Inverted gravity: the rosette mirrored","scenario.near_top":"Released just below the top","scenario.over_the_top":"Over the top: planar revolutions","scenario.planar_large":"Planar swing of amplitude 150°","scenario.rosette":"Rosette: 60° release with sideways spin","scenario.slewing_crane":"Slewing crane: R = 5 m, ω = 0.3 rad/s, l = 10 m","scenario.small_ellipse":"Small ellipse with Airy precession","scenario.string_slack":"String pendulum: slack at z = l/2, inelastic snap","scenario.swinging_spring":"Swinging spring at the 1:1:2 resonance","scenario.zero_g":"Zero gravity: a great circle","modelHelp.ideal":"a rod without friction: the textbook pendulum","modelHelp.damped":"with friction, air drag or a periodic push","modelHelp.rotating":"seen from the turning Earth: the swing plane turns (Foucault)","modelHelp.slewing":"hanging from the boom of a turning crane","modelHelp.vibrating":"the pivot shaken up and down: it can stand upside down (Kapitza)","modelHelp.sampled_pivot":"the pivot moves along a given path","modelHelp.spring":"a spring instead of a rod: it swings and bounces","modelHelp.string":"a string instead of a rod: it can go slack and snap taut","key.space":"Space","key.page":"Page ↑ / Page ↓","key.shift":"Shift","toolbar.simpleShort":"Simple","toolbar.simple":"simple view: only the classroom tools (length, mass, gravity, friction, stopwatch, period, ruler, energy); press again for everything","extras.add":"+ another pendulum (own length, mass, start)","extras.pendulum":"pendulum {n}","extras.remove":"remove pendulum {n}","extras.title":"Up to four pendulums","extras.hint":"With the second pendulum on “its own length, mass and start”: add pendulums 3 and 4, then “start both” starts all, each timed by its own period timer."},Kg={"page.title":"Pendulab-Labor — das Kugelpendel","page.units":"SI-Einheiten, z nach oben","page.scene":"3-D-Ansicht des Pendels (ziehen zum Drehen, scrollen zum Zoomen)","page.panel":"Steuerung und Messungen","page.software":"Software-WebGL: ohne Kantenglättung","conn.connected":"verbunden","conn.retrying":"getrennt: neuer Versuch…","conn.gone":"Der Server des Labors antwortet nicht: das Pendel steht. Läuft pendulab serve noch? Neuer Verbindungsversuch …","conn.noStart":"Das Labor konnte nicht starten:","toolbar.label":"Ablauf","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Zurück","toolbar.stepShort":"Schritt","toolbar.recordShort":"● Aufnahme","toolbar.recordStopShort":"■ Stopp","toolbar.start":"Start (Leertaste)","toolbar.pause":"Pause (Leertaste)","toolbar.reset":"zurück zum Start (R)","toolbar.step":"ein Schritt (S)","toolbar.record":"Video aufnehmen (WebM)","toolbar.recordStop":"Aufnahme beenden und Video speichern","toolbar.help":"Tastenkürzel und Farben (?)","toolbar.present":"Präsentationsmodus: große Schrift für einen Beamer","toolbar.language":"Sprache","toolbar.collapse":"Leiste ausblenden","toolbar.expand":"Leiste einblenden","gui.title":"Pendulab-Labor","gui.pendulum":"Pendel","gui.model":"Modell","gui.modelParams":"{model}: Parameter","gui.paramHelp":"{help} — Schlüssel {name} [{unit}]; erlaubt: {range}; Vorgabe {default}","gui.integrator":"Integrator","gui.method":"Verfahren","gui.order":"Ordnung {n}","gui.symplectic":"symplektisch","gui.adaptive":"adaptiv","method.rk4":"Runge–Kutta, 4. Ordnung (klassisch; verlässt die Kugel)","method.dop853":"Adaptiv, sehr genau (Dormand–Prince, 8. Ordnung)","method.rattle":"Symplektisch (RATTLE, 2. Ordnung; Voreinstellung)","method.rattle4":"Symplektisch (RATTLE, 4. Ordnung)","method.rattle6":"Symplektisch (RATTLE, 6. Ordnung)","method.rattle8":"Symplektisch (RATTLE, 8. Ordnung)","method.rkmk4":"Drehschritte auf der Kugel (Munthe-Kaas, 4. Ordnung)","method.rk4_angles":"Runge–Kutta 4 in Winkeln (versagt an den Polen)","method.other":"{name} ({n}. Ordnung)","kind.generic":"kreist in einer Rosette","kind.conical":"kreist in einer Höhe (Kegelpendel)","kind.planar":"schwingt in einer Ebene hin und her","kind.planar_rotating":"schwingt in einer Ebene über den höchsten Punkt","kind.separatrix":"kriecht für immer auf den höchsten Punkt zu","kind.rest":"in Ruhe","kind.great_circle":"läuft auf einem Großkreis (ohne Schwerkraft)","data.energy":"Energie E","data.energyChange":"Energieänderung E − E₀","data.spin":"Drehimpuls um die Senkrechte J₃","data.spinChange":"seine Änderung J₃ − J₃(0)","data.height":"Höhe z","data.turning":"tiefste und höchste Höhe z₁, z₂","gui.dtRange":"dt muss zwischen {min} und {max} s liegen","gui.dtHelp":"Schrittweite der Verfahren mit festem Schritt; {min} … {max} s (dop853 wählt selbst)","gui.run":"Ablauf","gui.timeScale":"Zeitfaktor [×]","gui.tsRange":"der Zeitfaktor muss zwischen {min} und {max} liegen","gui.tsHelp":"simulierte Sekunden pro Sekunde (Zeitlupe unter 1); {min} … {max}","gui.stepN":"Schritte pro Schritt","gui.scenario":"Szenario","gui.view":"Ansicht","gui.trail":"Spur","gui.trailSeconds":"Spur [s]","gui.sphere":"Kugel der Reichweite","gui.axes":"Achsen","gui.topView":"Draufsicht","gui.stereo":"Stereo","gui.stereoHelp":"Anaglyphe: Rot-Cyan-Brille; nebeneinander: ein Stereobetrachter","stereo.off":"aus","stereo.anaglyph":"Anaglyphe (Rot–Cyan)","stereo.sideBySide":"nebeneinander","gui.vectors":"Vektoren","gui.origin":"Ursprung {axis} [m]","gui.originHelp":"Ursprung von L und τ relativ zum Aufhängepunkt (0: der Aufhängepunkt)","gui.export":"Teilen und exportieren","gui.csv":"Bahn herunterladen (CSV)","gui.toml":"Szenario herunterladen (TOML)","gui.tomlHelp":"das Szenario, wie es ist (Modell, Parameter, Start, Verfahren), als Datei für `pendulab run`","gui.png":"Bildschirmfoto (PNG)","gui.link":"Link zu diesem Labor kopieren (was er enthält: beim Kopieren)","vec.velocity":"Geschwindigkeit v","vec.velocityHelp":"v [m/s], gezeichnet als Weg in 0,25 s","vec.momentum":"Impuls m v","vec.momentumHelp":"m v [kg m/s], 0,25 m pro kg m/s","vec.gravity":"Gewichtskraft m g","vec.gravityHelp":"die Gewichtskraft m g d [N] (d: Richtung der Schwerkraft); Kräfte: m·max(|g|, 1) N ↔ 0,5 l","vec.tension":"Stangenkraft (Zugkraft)","vec.tensionHelp":"die Stangenkraft −T x/|x| [N], T vom Server","vec.net":"Gesamtkraft m a","vec.netHelp":"m a [N]: a = ẍ vom Kern des Servers berechnet (relativ zum Aufhängepunkt)","vec.angularMomentum":"Drehimpuls L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] um den Ursprung o, von o aus gezeichnet","vec.torque":"Drehmoment τ","vec.torqueHelp":"τ = (x − o) × m a [N m] um den Ursprung o, von o aus gezeichnet; dL/dt = τ","data.now":"Jetzt (vom Server)","data.exact":"Exakte Lösung dieser Bahn","data.tension":"Zugkraft","data.tensionMin":"Zugkraft min","data.tensionMax":"Zugkraft max","data.method":"Verfahren","data.state":"Zustand","data.paused":"angehalten","data.running":"läuft","data.lagging":" (hinkt nach: langsamer als verlangt)","data.model":"Modell","data.kind":"Art der Bewegung","data.periodZ":"z-Periode T_z","data.swingPeriod":"Schwingungsdauer T","data.advance":"Azimutvorschub Δφ pro T_z","data.rotation":"Umlaufzahl W = Δφ/2π","data.reduced":"reduzierte Ansicht (σ₁, σ₂, σ₃): J₃-Fläche ∩ Energieebene","portrait.phase":"Phasenporträt: Vertikalgeschwindigkeit ż gegen Höhe z","portrait.veff":"effektives Potential V_eff(θ); Energie E gestrichelt, θ jetzt gepunktet","portrait.em":"Energie-Impuls-Abbildung: E gegen J₃ (Punkt: jetzt)","portrait.orbit":"Bahn","portrait.emBoundary":"Rand (konische Bahnen)","note.spring":"die Schwingfeder verlässt die Kugel (ihre Länge ändert sich): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.string":"die Schnur wird schlaff (freier Flug in der Kugel): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.exactIdeal":"die exakte Lösung gibt es nur für das ideale Pendel; dies ist das Modell {model}","note.reducedIdeal":"die reduzierte Ansicht ist die des idealen Pendels; dies ist das Modell {model}","event.slack":"die Schnur wurde schlaff (Zugkraft 0: freier Flug)","event.taut":"die Schnur straffte sich ruckartig, verlor {lost} J","event.skippedOne":" ({n} früheres Ereignis dieses Moments nicht gezeigt)","event.skippedMany":" ({n} frühere Ereignisse dieses Moments nicht gezeigt)","event.slackRow":"schlaff geworden","event.tautRow":"gestrafft","event.tautValue":"t = {t} s, verlor {lost}","data.power":"Leistung P = dE/dt","data.springForce":"Federkraft k(|r| − l₀)","data.springLength":"Federlänge |r|","data.stretch":"Dehnung |r| − l₀","data.string":"Schnur","data.slackZero":"schlaff (0)","data.slack":"schlaff: freier Flug, |x| = {r} m","data.taut":"straff","data.events":"Ereignisse","data.noEvents":"noch keine (schlaff, Straffen)","data.z3":"z₃ (außerhalb)","data.dynamic":"Δφ dynamisch","data.geometric":"Δφ geometrisch","data.error":"Lagefehler |Δx|","data.errorRel":"Lagefehler / l","data.errorHow":"Fehler ermittelt durch","data.errorPaused":"Schätzung pausiert (das Rechenbudget des Servers ist aufgebraucht; sie holt auf, sobald Zeit ist)","data.errorNone":"keine Schätzung","data.howExact":"den wahren Fehler: gegen die exakte Lösung (seit t = {since} s)","data.howRichardson":"Schätzung: Richardson gegen einen Begleitlauf mit dt/2 = {dt} s, Ordnung p = {p} (seit t = {since} s)","data.howCompanion":"Schätzung: einen Begleitlauf mit rtol = {rtol} (seit t = {since} s)","page.softwareHelp":"{renderer}: ohne Multisampling gezeichnet, für die Bildrate","tools.start":"Startwinkel","tools.thetaHelp":"θ₀: der Winkel zur Senkrechten nach unten, in Grad (0 … 180)","tools.phiHelp":"φ₀: der Winkel um die Senkrechte, in Grad","tools.phiDotHelp":"φ̇₀: wie schnell die Kugel zu kreisen beginnt, in Grad pro Sekunde (0: ebene Schwingung)","tools.setStart":"Start setzen","tools.world":"Schwerkraft und Reibung","tools.gravity":"Schwerkraft","tools.friction":"Reibung","tools.frictionHelp":"lineare Dämpfung c [1/s]: die Kraft −m c v; beim idealen Pendel wird auf das gedämpfte Modell gewechselt","tools.noFriction":"das Modell {model} hat keinen Reibungsparameter","tools.now":"Winkel jetzt","tools.stopwatch":"Stoppuhr (simulierte Zeit)","tools.swStart":"Start","tools.swStop":"Stopp","tools.swLap":"Runde","tools.swReset":"Null","tools.period":"Periodenmessung","tools.periodHelp":"aus der Bewegung gemessen: den tiefsten Punkten der Kugel; eine Periode der Schwingung endet, wenn die Kugel den tiefsten Punkt wieder in derselben Richtung durchläuft. Verglichen mit dem exakten Wert (ideales Pendel) oder der Theorie (Formel für kleine Ausschläge mit Reibung)","tools.periodCount":"Mittel über {n} Perioden","tools.periodCountZ":"Mittel über {n} Zeiten von tiefstem zu tiefstem Punkt","tools.periodWait":"wartet, bis die Kugel zweimal den tiefsten Punkt durchlaufen hat","tools.motion":"Bewegung","tools.kindNone":"—","tools.kindSwing":"schwingt hin und her","tools.kindOver":"schwingt über den höchsten Punkt","tools.kindOrbit":"kreist (nie durch den tiefsten Punkt)","tools.periodSwing":"Periode T [s]","tools.periodZ":"tiefster bis tiefster Punkt [s]","tools.advance":"Drehung zwischen tiefsten Punkten [°]","tools.precession":"Bahn dreht sich pro Umlauf um [°]","tools.amplitude":"Amplitude (größter Winkel) [°]","tools.band":"Winkel zur Senkrechten [°]","tools.theory":"Theorie","tools.measured":"gemessen","tools.exact":"exakt","tools.difference":"Abweichung","tools.overlays":"Lineal und Winkelmesser","tools.ruler":"Lineal (Meter)","tools.protractor":"Winkelmesser (θ in Grad)","gloss.title":"Wörter (Glossar)","gloss.advanced":"Formelnummern und weitere Zeilen zeigen (für Fortgeschrittene)","gloss.period":"Periode T","gloss.periodText":"die Zeit für eine ganze Schwingung: von einer Seite zur anderen und zurück, bis die Kugel den tiefsten Punkt wieder in derselben Richtung durchläuft. In Sekunden.","gloss.amplitude":"Amplitude","gloss.amplitudeText":"der größte Winkel zwischen Stange und Senkrechter während einer Schwingung. Mit Reibung wird er von Schwingung zu Schwingung kleiner.","gloss.lowest":"tiefster Punkt","gloss.lowestText":"wo die Kugel in einer Schwingung am tiefsten ist. Eine Schwingung geht durch den untersten Punkt; eine kreisende Kugel läuft daneben vorbei.","gloss.friction":"Reibung (Dämpfung)","gloss.frictionText":"eine Kraft gegen die Bewegung, die Energie wegnimmt, so dass die Schwingungen abklingen. Die Zahl c sagt, wie stark (pro Sekunde).","gloss.gravity":"Schwerebeschleunigung g","gloss.gravityText":"wie stark der Planet zieht: 9,81 m/s² auf der Erde, 1,62 auf dem Mond. Stärkerer Zug lässt das Pendel schneller schwingen.","gloss.energy":"kinetische und potentielle Energie","gloss.energyText":"kinetische Energie ist Bewegungsenergie (schnelle Kugel: viel); potentielle Energie ist Höhenenergie (hohe Kugel: viel). Beim Schwingen wandeln sie sich ineinander um; Reibung nimmt etwas weg.","gloss.spin":"Drehimpuls J₃","gloss.spinText":"wie sehr die Kugel um die Senkrechte kreist. Null für eine Schwingung in einer Ebene; beim idealen Pendel bleibt er gleich.","gloss.precession":"Präzession","gloss.precessionText":"eine kreisende Kugel schließt ihre Bahn nicht: das Muster dreht sich bei jedem Umlauf ein wenig, und von oben entsteht eine Rosette.","gloss.method":"Verfahren (Integrator)","gloss.methodText":"wie der Computer die Bewegung in kleinen Zeitschritten ausrechnet. Symplektische Verfahren halten die Energie lange richtig; andere driften.","gloss.drift":"Energiedrift","gloss.driftText":"wie weit die berechnete Energie von ihrem Anfangswert abgewandert ist. Beim idealen Pendel sollte sie null bleiben; was übrig ist, ist Rundung des Computers.","tools.moveGroup":"{what} verschieben","tools.moveLeft":"nach links","tools.moveRight":"nach rechts","tools.moveUp":"nach oben","tools.moveDown":"nach unten","tools.moveBack":"zurück an seinen Platz","describe.none":"noch keine Bewegung","describe.text":"Winkel {theta}° zur Senkrechten, {dir}, Geschwindigkeit {v} m/s","describe.rest":"in Ruhe","describe.turning":"am Umkehrpunkt","describe.rising":"steigt","describe.falling":"fällt zum tiefsten Punkt","describe.energy":"; Energie {k} % kinetisch, {u} % potentiell","describe.lost":", {p} % durch Reibung verloren","describe.toggle":"Bewegung alle 5 s beschreiben (Bildschirmleser; D: jetzt)","tools.sound":"Ton: ein Ton an jedem tiefsten Punkt (höher, wenn schneller)","tools.mystery":"geheimer Planet (g aus der Periode bestimmen)","tools.reveal":"g zeigen","tools.mysteryOn":"ein geheimer Planet: Schwingungen stoppen und g = 4π² l / T² ausrechnen","tools.revealed":"g des geheimen Planeten ist {g} m/s²","start.notNumber":"{name} muss eine Zahl sein","start.thetaRange":"θ₀ = {value}° ist nicht erlaubt: 0 … 180°","gravity.custom":"eigene","gravity.earth":"Erde","gravity.moon":"Mond","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"null","gravity.negative":"negativ (nach oben)","energy.title":"Energie","energy.kinetic":"kinetisch","energy.potential":"potentiell","energy.lost":"verloren","energy.total":"gesamt","plot.dE":"Energiedrift |ΔE|/E_s (log)","plot.dJ3":"J₃-Drift |ΔJ₃|/J_s (log)","plot.z":"Höhe z(t)","plot.tension":"Stangenkraft T(t)","plot.time":"Zeit t [s]","plot.floor":"float64-Rundung 2,2e-16","alt.empty":"noch keine Daten","alt.summary":"{y} von {yLo} bis {yHi} gegen {x} von {xLo} bis {xHi}; jetzt {yNow} bei {xNow}","chosen.title":"Beliebige Größen zeichnen","chosen.xAxis":"waagerecht","chosen.yAxis":"senkrecht","var.t":"Zeit t","var.theta":"Winkel θ","var.phi":"Azimut φ","var.x":"x","var.y":"y","var.z":"Höhe z","var.zdot":"Vertikalgeschwindigkeit ż","var.speed":"Geschwindigkeit |v|","var.energy":"Energie E","var.kinetic":"kinetische Energie K","var.potential":"potentielle Energie U","var.j3":"Drehimpuls J₃","var.tension":"Zugkraft T","var.power":"Leistung P","var.radius":"Abstand |x|","twin.title":"Zwei Pendel","twin.mode":"zweites Pendel","twin.off":"aus","twin.epsilon":"Start um ε verschieden","twin.method":"anderer Integrator","twin.damped":"gedämpft daneben","twin.own":"eigene Länge, Masse und Start (nebeneinander)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"das zweite Pendel braucht eine Länge > 0, eine Masse > 0 und einen Startwinkel 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"Periode T [s] (Perioden)","twin.methodPick":"Integrator","twin.damping":"Dämpfung [1/s]","twin.start":"beide starten","twin.bad":"ε muss eine Zahl sein und die Dämpfung ≥ 0","twin.first":"Pendel 1","twin.second":"Pendel 2","twin.separation":"Abstand der Kugeln |r₁ − r₂| [m]","help.title":"Tastenkürzel und Farben","help.space":"Start / Pause","help.r":"zurück zum Start","help.s":"ein Schritt (angehalten)","help.arrows":"auf einem Schieberegler: einen Schritt runter / hoch","help.page":"auf einem Schieberegler: zehn Schritte","help.camera":"in der 3-D-Ansicht: Kamera drehen / zoomen","help.bobKeys":"in der 3-D-Ansicht: Start der Kugel um 1° verschieben (hält an)","help.describe":"die Bewegung jetzt beschreiben (Bildschirmleser)","help.tab":"zwischen Bedienelementen wechseln","help.help":"diese Übersicht","help.esc":"diese Übersicht schließen","help.colours":"Farben","help.close":"schließen","help.bob":"Kugel","help.trail":"Spur","help.twin":"zweites Pendel","help.ruler":"Lineal und Winkelmesser","msg.notConnected":"keine Verbindung zum Server","link.scenario":"das Szenario (Modell, Parameter, Verfahren, Start)","link.paused":"angehalten","link.pausedAt":"angehalten bei {t} s","link.view":"Ansicht: {list}","link.plot":"Diagramm {y} gegen {x}","link.twin":"zweites Pendel {what}","link.lang":"Sprache {lang}","msg.linkCopied":"Link kopiert; er enthält {what}","msg.dragged":"Start durch Ziehen gesetzt (dort in Ruhe): Start drücken, um loszulassen","msg.pull":"den Pfeil ziehen, um die Startgeschwindigkeit zu setzen","msg.capped":" (begrenzt: höchstens 4√(g l))","msg.velocitySet":"Startgeschwindigkeit gesetzt: |v| = {v} m/s{cap}; Start drücken","msg.velocity":"Startgeschwindigkeit |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} ist nicht erlaubt: {allowed} ({range})","msg.recording":"die Ansicht wird aufgenommen…","msg.recorded":"Video gespeichert ({mb} MB, WebM)","msg.noRecording":"dieser Browser kann die Ansicht nicht aufnehmen ({why})","fit.title":"Messdaten","fit.load":"Messdaten laden…","fit.help":"eine CSV-Datei mit Messwerten in SI-Einheiten (Spalten t, x, y, z oder x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): der Server passt das Pendel an, lädt die angepasste Bewegung und zeichnet die gemessene Bahn gepunktet daneben","fit.model":"Modell","fit.params":"anpassen","fit.paramsDefault":"was die Daten bestimmen","fit.paramsHelp":"die anzupassenden Parameter, durch Kommas getrennt (z. B. length,g,damping,pivot); leer: was die Daten bestimmen können","fit.clear":"gemessene Bahn löschen","fit.running":"{name} wird angepasst …","fit.noPath":"(Daten ohne Bezugssystem: keine Bahn zu zeichnen)","fit.failed":"Anpassung: {why}","fit.loaded":"{name} angepasst: die angepasste Bewegung ist geladen, die gemessene Bahn golden gepunktet","page.tools":"Messwerkzeuge","page.energy":"Energie-Balkendiagramm","page.data":"Datenfeld","page.plots":"Live-Diagramme","page.portraits":"Phasenporträt, effektives Potential, Energie-Impuls-Abbildung","page.reduced":"reduzierte Ansicht im σ-Raum","gui.modelsHelp":"die Modelle (Codename in Klammern):","fit.summary":"{model}: {state}","fit.converged":"die Anpassung ist konvergiert","fit.notConverged":"die Anpassung ist nicht konvergiert","fit.notDetermined":"(durch diese Daten nicht bestimmt)","fit.fullReport":"der vollständige Bericht der Anpassung (wie pendulab fit ihn ausgibt, auf Englisch)","server.too_small":"{name} = {value}: mindestens {limit} erlaubt","server.too_small_strict":"{name} = {value}: muss größer als {limit} sein","server.too_large":"{name} = {value}: höchstens {limit} erlaubt","server.too_large_strict":"{name} = {value}: muss kleiner als {limit} sein","server.missing":"{name} fehlt","server.unknown_key":"unbekannter Schlüssel {name}","server.nonfinite_motion":"die Bewegung hat bei t = {t} s den Zahlenbereich verlassen ({fields} nicht endlich): zu extreme Parameter oder Startwerte; angehalten — zurücksetzen oder die Parameter ändern","server.integration_stopped":"die Rechnung ist stehen geblieben ({detail}); angehalten","server.throttled":"zu viele Befehle: {lost} verworfen; höchstens {per_second} pro Sekunde senden","server.server_full":"der Server ist voll: {active} Laborsitzungen sind offen, mehr bedient er nicht gleichzeitig; einen anderen Tab schließen oder später versuchen","server.device_full":"zu viele Laborsitzungen von diesem Gerät: {have} sind offen, mehr darf ein Gerät nicht haben; einen anderen Tab schließen","server.device_busy":"zu viele Berechnungen gleichzeitig von diesem Gerät: höchstens {most} dürfen für ein Gerät laufen oder warten; die Antworten abwarten, dann erneut versuchen","server.internal_error":"interner Fehler des Servers: {detail}","scenario.conical":"Kegelpendel bei 45°","scenario.damped":"Gedämpfte Rosette (c = 0.05 1/s)","scenario.foucault":"Foucault-Pendel bei 49° N, Erddrehung übertrieben (Ω = 0.02 rad/s)","scenario.inverted_g":"Umgekehrte Schwerkraft: die Rosette gespiegelt","scenario.near_top":"Knapp unter dem höchsten Punkt losgelassen","scenario.over_the_top":"Über Kopf: ebene Überschläge","scenario.planar_large":"Ebene Schwingung mit 150° Amplitude","scenario.rosette":"Rosette: bei 60° mit seitlichem Schwung losgelassen","scenario.slewing_crane":"Drehkran: R = 5 m, ω = 0.3 rad/s, l = 10 m","scenario.small_ellipse":"Kleine Ellipse mit Airy-Präzession","scenario.string_slack":"Pendel an einer Schnur: schlaff bei z = l/2, unelastischer Ruck","scenario.swinging_spring":"Schwingfeder in der 1:1:2-Resonanz","scenario.zero_g":"Schwerelos: ein Großkreis","modelHelp.ideal":"eine Stange ohne Reibung: das Pendel aus dem Lehrbuch","modelHelp.damped":"mit Reibung, Luftwiderstand oder periodischem Antrieb","modelHelp.rotating":"von der sich drehenden Erde aus gesehen: die Schwingebene dreht sich (Foucault)","modelHelp.slewing":"am Ausleger eines sich drehenden Krans","modelHelp.vibrating":"der Aufhängepunkt wird auf und ab gerüttelt: es kann kopfüber stehen (Kapitza)","modelHelp.sampled_pivot":"der Aufhängepunkt bewegt sich auf einer vorgegebenen Bahn","modelHelp.spring":"eine Feder statt einer Stange: es schwingt und federt","modelHelp.string":"eine Schnur statt einer Stange: sie kann schlaff werden und sich ruckartig spannen","key.space":"Leertaste","key.page":"Bild ↑ / Bild ↓","key.shift":"Umschalt","toolbar.simpleShort":"Einfach","toolbar.simple":"einfache Ansicht: nur die Werkzeuge für den Unterricht (Länge, Masse, Schwerkraft, Reibung, Stoppuhr, Periode, Lineal, Energie); noch einmal drücken für alles","extras.add":"+ noch ein Pendel (eigene Länge, Masse, Start)","extras.pendulum":"Pendel {n}","extras.remove":"Pendel {n} entfernen","extras.title":"Bis zu vier Pendel","extras.hint":"Mit dem zweiten Pendel auf „eigene Länge, Masse und Start“: Pendel 3 und 4 hinzufügen, dann startet „beide starten“ alle, jedes mit seiner eigenen Periodenmessung."},Zg={length:["Länge l","Länge der Stange vom Aufhängepunkt zur Kugel"],mass:["Masse m","Masse der Kugel"],g:["Schwerebeschleunigung g","Stärke der Schwerkraft (jedes Vorzeichen; 0 erlaubt)"],damping:["Reibung (lineare Dämpfung) c","Reibungskraft −m c v, proportional zur Geschwindigkeit"],drag:["Luftwiderstand c_q","Kraft −m c_q |v| v, quadratisch in der Geschwindigkeit"],forcing_amplitude:["Antrieb: Stärke A","periodische Kraft pro Masse A cos(ω t + ψ) in Richtung e"],forcing_omega:["Antrieb: Kreisfrequenz ω","wie schnell der Antrieb schwingt"],forcing_phase:["Antrieb: Phase ψ","Phase des Antriebs bei t = 0"],forcing_x:["Antriebsrichtung e: x","x-Komponente der Antriebsrichtung (wird normiert)"],forcing_y:["Antriebsrichtung e: y","y-Komponente der Antriebsrichtung"],forcing_z:["Antriebsrichtung e: z","z-Komponente der Antriebsrichtung"],gravity_x:["Schwerkraftrichtung d: x","x-Komponente der Richtung der Schwerkraft (wird normiert)"],gravity_y:["Schwerkraftrichtung d: y","y-Komponente der Richtung der Schwerkraft"],gravity_z:["Schwerkraftrichtung d: z","z-Komponente der Richtung der Schwerkraft"],frame_rate:["Drehrate des Bezugssystems |Ω|","wie schnell sich das Bezugssystem dreht (Erde: 7,292e-5)"],latitude:["geografische Breite λ","Breite des Ortes (Foucault-Pendel)"],radius:["Auslegerradius R","Abstand des Aufhängepunkts von der Drehachse des Krans"],rate:["Drehrate des Krans ω","wie schnell sich der Ausleger dreht"],height:["Höhe des Aufhängepunkts h","Höhe des Auslegers"],amplitude:["Rüttelamplitude A","Amplitude der senkrechten Schwingung des Aufhängepunkts"],frequency:["Rüttelfrequenz ν","Kreisfrequenz der Schwingung des Aufhängepunkts"],stiffness:["Federkonstante k","Steifigkeit der Feder; die Länge l ist die entspannte Länge"],restitution:["Stoßzahl e","wie elastisch die Schnur beim Straffen zurückfedert (0 … 1)"]},Jg={ideal:"Ideales Pendel",damped:"Gedämpft und angetrieben",rotating:"Auf der drehenden Erde (Foucault)",slewing:"Drehkran",vibrating:"Gerüttelter Aufhängepunkt (Kapitza)",sampled_pivot:"Aufhängepunkt auf vorgegebener Bahn",spring:"Schwingfeder",string:"Pendel an einer Schnur"},jg={"page.title":"Laboratoire Pendulab — le pendule sphérique","page.units":"unités SI, z vers le haut","page.scene":"vue 3D du pendule (glisser pour tourner, molette pour zoomer)","page.panel":"commandes et mesures","page.software":"WebGL logiciel : sans anticrénelage","conn.connected":"connecté","conn.retrying":"déconnecté : nouvel essai…","conn.gone":"Le serveur du laboratoire ne répond pas : le pendule est arrêté. pendulab serve tourne-t-il encore ? Nouvel essai de connexion …","conn.noStart":"Le laboratoire n’a pas pu démarrer :","toolbar.label":"commandes de marche","toolbar.startShort":"▶ Démarrer","toolbar.pauseShort":"Pause","toolbar.resetShort":"Revenir","toolbar.stepShort":"Pas","toolbar.recordShort":"● Filmer","toolbar.recordStopShort":"■ Arrêter","toolbar.start":"démarrer (Espace)","toolbar.pause":"pause (Espace)","toolbar.reset":"revenir au départ (R)","toolbar.step":"un pas (S)","toolbar.record":"filmer la vue (WebM)","toolbar.recordStop":"arrêter de filmer et télécharger la vidéo","toolbar.help":"raccourcis clavier et légende des couleurs (?)","toolbar.present":"mode présentation : gros caractères pour un vidéoprojecteur","toolbar.language":"langue","toolbar.collapse":"masquer le panneau","toolbar.expand":"afficher le panneau","gui.title":"Laboratoire Pendulab","gui.pendulum":"Pendule","gui.model":"modèle","gui.modelParams":"{model} : paramètres","gui.paramHelp":"{help} — clé {name} [{unit}] ; permis : {range} ; par défaut {default}","gui.integrator":"Méthode de calcul","gui.method":"méthode","gui.order":"ordre {n}","gui.symplectic":"symplectique","gui.adaptive":"adaptative","method.rk4":"Runge–Kutta, ordre 4 (classique ; quitte la sphère)","method.dop853":"Adaptative, très précise (Dormand–Prince, ordre 8)","method.rattle":"Symplectique (RATTLE, ordre 2 ; par défaut)","method.rattle4":"Symplectique (RATTLE, ordre 4)","method.rattle6":"Symplectique (RATTLE, ordre 6)","method.rattle8":"Symplectique (RATTLE, ordre 8)","method.rkmk4":"Pas de rotation sur la sphère (Munthe-Kaas, ordre 4)","method.rk4_angles":"Runge–Kutta 4 en angles (échoue aux pôles)","method.other":"{name} (ordre {n})","kind.generic":"tourne en rosace","kind.conical":"tourne à hauteur constante (pendule conique)","kind.planar":"oscille dans un plan","kind.planar_rotating":"fait des tours complets dans un plan","kind.separatrix":"monte vers le sommet sans jamais l’atteindre","kind.rest":"au repos","kind.great_circle":"parcourt un grand cercle (sans pesanteur)","data.energy":"énergie E","data.energyChange":"variation de l’énergie E − E₀","data.spin":"moment cinétique autour de la verticale J₃","data.spinChange":"sa variation J₃ − J₃(0)","data.height":"hauteur z","data.turning":"hauteurs la plus basse et la plus haute z₁, z₂","gui.dtRange":"dt doit être entre {min} et {max} s","gui.dtHelp":"pas de temps des méthodes à pas fixe ; {min} … {max} s (dop853 choisit le sien)","gui.run":"Marche","gui.timeScale":"échelle de temps [×]","gui.tsRange":"l’échelle de temps doit être entre {min} et {max}","gui.tsHelp":"secondes simulées par seconde (ralenti en dessous de 1) ; {min} … {max}","gui.stepN":"pas par clic","gui.scenario":"scénario","gui.view":"Vue","gui.trail":"trace","gui.trailSeconds":"trace [s]","gui.sphere":"sphère atteignable","gui.axes":"axes","gui.topView":"vue de dessus","gui.stereo":"stéréo","gui.stereoHelp":"anaglyphe : lunettes rouge–cyan ; côte à côte : visionneuse stéréo","stereo.off":"non","stereo.anaglyph":"anaglyphe (rouge–cyan)","stereo.sideBySide":"côte à côte","gui.vectors":"Vecteurs","gui.origin":"origine {axis} [m]","gui.originHelp":"origine de L et τ par rapport au point de suspension (0 : le point de suspension)","gui.export":"Partager et exporter","gui.csv":"télécharger la trajectoire (CSV)","gui.toml":"télécharger le scénario (TOML)","gui.tomlHelp":"le scénario tel qu’il est (modèle, paramètres, départ, méthode) en fichier pour `pendulab run`","gui.png":"capture d’écran (PNG)","gui.link":"copier le lien vers ce laboratoire (son contenu : à la copie)","vec.velocity":"vitesse v","vec.velocityHelp":"v [m/s], dessinée comme 0,25 s de trajet","vec.momentum":"quantité de mouvement m v","vec.momentumHelp":"m v [kg m/s], 0,25 m par kg m/s","vec.gravity":"poids m g","vec.gravityHelp":"le poids m g d [N] (d : direction de la pesanteur) ; forces : m·max(|g|, 1) N ↔ 0,5 l","vec.tension":"force de la tige (tension)","vec.tensionHelp":"la force de la tige −T x/|x| [N], T venant du serveur","vec.net":"force résultante m a","vec.netHelp":"m a [N] : a = ẍ calculée par le cœur du serveur (par rapport au point de suspension)","vec.angularMomentum":"moment cinétique L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] par rapport à l’origine o, dessiné depuis o","vec.torque":"moment de force τ","vec.torqueHelp":"τ = (x − o) × m a [N m] par rapport à l’origine o, dessiné depuis o ; dL/dt = τ","data.now":"Maintenant (du serveur)","data.exact":"Solution exacte de cette orbite","data.tension":"tension","data.tensionMin":"tension min","data.tensionMax":"tension max","data.method":"méthode","data.state":"état","data.paused":"en pause","data.running":"en marche","data.lagging":" (en retard : plus lent que demandé)","data.model":"modèle","data.kind":"type de mouvement","data.periodZ":"du point le plus bas au suivant T_z","data.swingPeriod":"période d’oscillation T","data.advance":"rotation entre deux points les plus bas Δφ","data.rotation":"nombre de rotation W = Δφ/2π","data.reduced":"vue réduite (σ₁, σ₂, σ₃) : surface J₃ ∩ plan d’énergie","portrait.phase":"portrait de phase : vitesse verticale ż selon la hauteur z","portrait.veff":"potentiel effectif V_eff(θ) ; énergie E en tirets, θ actuel en pointillés","portrait.em":"carte énergie–moment : E selon J₃ (point : maintenant)","portrait.orbit":"orbite","portrait.emBoundary":"bord (orbites coniques)","note.spring":"le ressort quitte la sphère (sa longueur varie) : V_eff, la carte énergie–moment, la vue réduite et la solution exacte sont celles du pendule à tige et ne sont pas affichées","note.string":"le fil se détend (vol libre dans la sphère) : V_eff, la carte énergie–moment, la vue réduite et la solution exacte sont celles du pendule à tige et ne sont pas affichées","note.exactIdeal":"la solution exacte n’existe que pour le pendule idéal ; ceci est le modèle {model}","note.reducedIdeal":"la vue réduite est celle du pendule idéal ; ceci est le modèle {model}","event.slack":"le fil s’est détendu (tension 0 : vol libre)","event.taut":"le fil s’est tendu d’un coup, {lost} J perdus","event.skippedOne":" ({n} événement antérieur de cet instant non affiché)","event.skippedMany":" ({n} événements antérieurs de cet instant non affichés)","event.slackRow":"détendu","event.tautRow":"tendu d’un coup","event.tautValue":"t = {t} s, perdu {lost}","data.power":"puissance P = dE/dt","data.springForce":"force du ressort k(|r| − l₀)","data.springLength":"longueur du ressort |r|","data.stretch":"allongement |r| − l₀","data.string":"fil","data.slackZero":"détendu (0)","data.slack":"détendu : vol libre, |x| = {r} m","data.taut":"tendu","data.events":"événements","data.noEvents":"aucun pour l’instant (détentes, à-coups)","data.z3":"z₃ (hors de la sphère)","data.dynamic":"Δφ dynamique","data.geometric":"Δφ géométrique","data.error":"erreur de position |Δx|","data.errorRel":"erreur de position / l","data.errorHow":"erreur obtenue par","data.errorPaused":"estimation en pause (le budget de calcul du serveur est épuisé ; elle rattrape quand il y a du temps)","data.errorNone":"pas d’estimation","data.howExact":"l’erreur vraie : comparée à la solution exacte (depuis t = {since} s)","data.howRichardson":"estimation : Richardson avec un calcul compagnon à dt/2 = {dt} s, ordre p = {p} (depuis t = {since} s)","data.howCompanion":"estimation : un calcul compagnon à rtol = {rtol} (depuis t = {since} s)","page.softwareHelp":"{renderer} : dessiné sans multiéchantillonnage pour la fluidité","tools.start":"Angle de départ","tools.thetaHelp":"θ₀ : l’angle avec la verticale vers le bas, en degrés (0 … 180)","tools.phiHelp":"φ₀ : l’azimut autour de la verticale, en degrés","tools.phiDotHelp":"φ̇₀ : à quelle vitesse la masse commence à tourner, en degrés par seconde (0 : une oscillation plane)","tools.setStart":"fixer le départ","tools.world":"Pesanteur et frottement","tools.gravity":"pesanteur","tools.friction":"frottement","tools.frictionHelp":"amortissement linéaire c [1/s] : la force −m c v ; sur le pendule idéal, passe au modèle amorti","tools.noFriction":"le modèle {model} n’a pas de paramètre de frottement","tools.now":"Angles maintenant","tools.stopwatch":"Chronomètre (temps simulé)","tools.swStart":"démarrer","tools.swStop":"arrêter","tools.swLap":"tour","tools.swReset":"remettre à zéro","tools.period":"Mesure de la période","tools.periodHelp":"mesurée sur le mouvement : les points les plus bas de la masse ; une période d’oscillation se termine quand la masse repasse en bas dans le même sens. Comparée à la valeur exacte (pendule idéal) ou à la théorie (formule des petites oscillations avec frottement)","tools.periodCount":"moyenne sur {n} périodes","tools.periodCountZ":"moyenne sur {n} passages d’un point le plus bas au suivant","tools.periodWait":"attend que la masse passe deux fois par son point le plus bas","tools.motion":"mouvement","tools.kindNone":"—","tools.kindSwing":"oscille d’avant en arrière","tools.kindOver":"fait des tours complets","tools.kindOrbit":"tourne (ne passe jamais par le bas)","tools.periodSwing":"période T [s]","tools.periodZ":"d’un point le plus bas au suivant [s]","tools.advance":"rotation entre deux points les plus bas [°]","tools.precession":"la figure tourne par tour de [°]","tools.amplitude":"amplitude (plus grand angle) [°]","tools.band":"angle avec la verticale [°]","tools.theory":"théorie","tools.measured":"mesuré","tools.exact":"exact","tools.difference":"écart","tools.overlays":"Règle et rapporteur","tools.ruler":"règle (mètres)","tools.protractor":"rapporteur (θ en degrés)","gloss.title":"Mots (glossaire)","gloss.advanced":"afficher les numéros de formules et les lignes en plus (avancé)","gloss.period":"période T","gloss.periodText":"le temps d’une oscillation complète : d’un côté à l’autre et retour, jusqu’à ce que la masse repasse en bas dans le même sens. En secondes.","gloss.amplitude":"amplitude","gloss.amplitudeText":"le plus grand angle entre la tige et la verticale pendant une oscillation. Avec frottement, il diminue d’une oscillation à l’autre.","gloss.lowest":"point le plus bas","gloss.lowestText":"là où la masse est la plus basse pendant une oscillation. Une oscillation passe tout en bas ; une masse qui tourne passe à côté.","gloss.friction":"frottement (amortissement)","gloss.frictionText":"une force contre le mouvement qui enlève de l’énergie, si bien que les oscillations s’éteignent. Le nombre c dit sa force (par seconde).","gloss.gravity":"pesanteur g","gloss.gravityText":"la force avec laquelle la planète attire : 9,81 m/s² sur Terre, 1,62 sur la Lune. Une attraction plus forte fait osciller le pendule plus vite.","gloss.energy":"énergie cinétique et potentielle","gloss.energyText":"l’énergie cinétique est l’énergie du mouvement (masse rapide : beaucoup) ; l’énergie potentielle est l’énergie de hauteur (masse haute : beaucoup). Elles se transforment l’une en l’autre ; le frottement en enlève.","gloss.spin":"moment cinétique J₃","gloss.spinText":"à quel point la masse tourne autour de la verticale. Nul pour une oscillation dans un plan ; il reste constant pour le pendule idéal.","gloss.precession":"précession","gloss.precessionText":"une masse qui tourne ne referme pas sa trajectoire : la figure tourne un peu à chaque tour, et vue de dessus devient une rosace.","gloss.method":"méthode (intégrateur)","gloss.methodText":"la façon dont l’ordinateur calcule le mouvement par petits pas de temps. Les méthodes symplectiques gardent l’énergie juste longtemps ; les autres dérivent.","gloss.drift":"dérive de l’énergie","gloss.driftText":"de combien l’énergie calculée s’est éloignée de sa valeur de départ. Pour le pendule idéal elle devrait rester nulle ; ce qui reste est l’arrondi de l’ordinateur.","tools.moveGroup":"déplacer : {what}","tools.moveLeft":"vers la gauche","tools.moveRight":"vers la droite","tools.moveUp":"vers le haut","tools.moveDown":"vers le bas","tools.moveBack":"remettre à sa place","describe.none":"pas encore de mouvement","describe.text":"angle de {theta}° avec la verticale, {dir}, vitesse {v} m/s","describe.rest":"au repos","describe.turning":"à un point de rebroussement","describe.rising":"monte","describe.falling":"descend vers le bas","describe.energy":" ; énergie {k} % cinétique, {u} % potentielle","describe.lost":", {p} % perdue par frottement","describe.toggle":"décrire le mouvement toutes les 5 s (lecteurs d’écran ; D : maintenant)","tools.sound":"son : un ton à chaque point le plus bas (plus aigu si plus rapide)","tools.mystery":"planète mystère (trouver g avec la période)","tools.reveal":"révéler g","tools.mysteryOn":"une planète mystère : chronométrer les oscillations et calculer g = 4π² l / T²","tools.revealed":"g de la planète mystère vaut {g} m/s²","start.notNumber":"{name} doit être un nombre","start.thetaRange":"θ₀ = {value}° n’est pas permis : 0 … 180°","gravity.custom":"autre","gravity.earth":"Terre","gravity.moon":"Lune","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"nulle","gravity.negative":"négative (vers le haut)","energy.title":"Énergie","energy.kinetic":"cinétique","energy.potential":"potentielle","energy.lost":"perdue","energy.total":"totale","plot.dE":"dérive de l’énergie |ΔE|/E_s (log)","plot.dJ3":"dérive de J₃ |ΔJ₃|/J_s (log)","plot.z":"hauteur z(t)","plot.tension":"tension de la tige T(t)","plot.time":"temps t [s]","plot.floor":"arrondi float64 2,2e-16","alt.empty":"pas encore de données","alt.summary":"{y} de {yLo} à {yHi} selon {x} de {xLo} à {xHi} ; maintenant {yNow} à {xNow}","chosen.title":"Tracer des grandeurs au choix","chosen.xAxis":"en abscisse","chosen.yAxis":"en ordonnée","var.t":"temps t","var.theta":"angle θ","var.phi":"azimut φ","var.x":"x","var.y":"y","var.z":"hauteur z","var.zdot":"vitesse verticale ż","var.speed":"vitesse |v|","var.energy":"énergie E","var.kinetic":"énergie cinétique K","var.potential":"énergie potentielle U","var.j3":"moment cinétique J₃","var.tension":"tension T","var.power":"puissance P","var.radius":"distance |x|","twin.title":"Deux pendules","twin.mode":"second pendule","twin.off":"aucun","twin.epsilon":"départ différent de ε","twin.method":"une autre méthode de calcul","twin.damped":"amorti à côté de celui-ci","twin.own":"sa propre longueur, masse et départ (côte à côte)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"le second pendule demande une longueur > 0, une masse > 0 et un angle de départ 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"période T [s] (périodes)","twin.methodPick":"méthode","twin.damping":"amortissement [1/s]","twin.start":"démarrer les deux","twin.bad":"ε doit être un nombre et l’amortissement ≥ 0","twin.first":"pendule 1","twin.second":"pendule 2","twin.separation":"distance entre les masses |r₁ − r₂| [m]","help.title":"Raccourcis clavier et légende des couleurs","help.space":"démarrer / pause","help.r":"revenir au départ","help.s":"un pas (en pause)","help.arrows":"sur un curseur sélectionné : un pas vers le bas / le haut","help.page":"sur un curseur sélectionné : dix pas","help.camera":"dans la vue 3D : tourner la caméra / zoomer","help.bobKeys":"dans la vue 3D : déplacer le départ de la masse de 1° (met en pause)","help.describe":"décrire le mouvement maintenant (lecteurs d’écran)","help.tab":"passer d’une commande à l’autre","help.help":"cette fenêtre","help.esc":"fermer cette fenêtre","help.colours":"Couleurs","help.close":"fermer","help.bob":"masse","help.trail":"trace","help.twin":"second pendule","help.ruler":"règle et rapporteur","msg.notConnected":"pas de connexion au serveur","link.scenario":"le scénario (modèle, paramètres, méthode, départ)","link.paused":"en pause","link.pausedAt":"en pause à {t} s","link.view":"vue : {list}","link.plot":"graphique {y} selon {x}","link.twin":"second pendule {what}","link.lang":"langue {lang}","msg.linkCopied":"lien copié ; il contient {what}","msg.dragged":"départ fixé en glissant (au repos à cet endroit) : appuyer sur démarrer pour le lâcher","msg.pull":"tirer la flèche pour fixer la vitesse de départ","msg.capped":" (limitée : le maximum de la flèche, 4√(g l))","msg.velocitySet":"vitesse de départ fixée : |v| = {v} m/s{cap} ; appuyer sur démarrer pour partir de là","msg.velocity":"vitesse de départ |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} n’est pas permis : {allowed} ({range})","msg.recording":"la vue est filmée…","msg.recorded":"vidéo enregistrée ({mb} Mo, WebM)","msg.noRecording":"ce navigateur ne peut pas filmer la vue ({why})","fit.title":"Données mesurées","fit.load":"Charger des mesures…","fit.help":"un fichier CSV de mesures en unités SI (colonnes t, x, y, z ou x, z ; theta, phi ; angle ; specific_force ; angular_speed — docs/fit.md) : le serveur y ajuste le pendule, charge le mouvement ajusté et dessine le chemin mesuré en pointillés à côté","fit.model":"modèle","fit.params":"ajuster","fit.paramsDefault":"ce que les données déterminent","fit.paramsHelp":"les paramètres à ajuster, séparés par des virgules (p. ex. length,g,damping,pivot) ; vide : ce que les données peuvent déterminer","fit.clear":"effacer le chemin mesuré","fit.running":"ajustement de {name} …","fit.noPath":"(données sans repère : pas de chemin mesuré à dessiner)","fit.failed":"ajustement : {why}","fit.loaded":"{name} ajusté : le mouvement ajusté est chargé, le chemin mesuré en pointillés dorés","page.tools":"outils de mesure","page.energy":"diagramme en barres de l’énergie","page.data":"panneau de données","page.plots":"courbes en direct","page.portraits":"portrait de phase, potentiel effectif, carte énergie–moment","page.reduced":"vue réduite dans l’espace σ","gui.modelsHelp":"les modèles (nom de code entre parenthèses) :","fit.summary":"{model} : {state}","fit.converged":"l’ajustement a convergé","fit.notConverged":"l’ajustement n’a pas convergé","fit.notDetermined":"(non déterminé par ces données)","fit.fullReport":"le rapport complet de l’ajustement (tel que pendulab fit l’affiche, en anglais)","server.too_small":"{name} = {value} : au moins {limit}","server.too_small_strict":"{name} = {value} : doit être supérieur à {limit}","server.too_large":"{name} = {value} : au plus {limit}","server.too_large_strict":"{name} = {value} : doit être inférieur à {limit}","server.missing":"{name} manque","server.unknown_key":"clé inconnue {name}","server.nonfinite_motion":"le mouvement a quitté les nombres à virgule flottante à t = {t} s ({fields} non finis) : paramètres ou départ trop extrêmes ; en pause — réinitialiser ou changer les paramètres","server.integration_stopped":"le calcul s’est arrêté ({detail}) ; en pause","server.throttled":"trop de commandes : {lost} ignorées ; en envoyer au plus {per_second} par seconde","server.server_full":"le serveur est plein : {active} sessions du labo sont ouvertes, le maximum qu’il sert à la fois ; fermer un autre onglet ou réessayer plus tard","server.device_full":"trop de sessions du labo depuis votre appareil : {have} sont ouvertes, le maximum par appareil ; fermer un autre onglet","server.device_busy":"trop de calculs à la fois depuis votre appareil : au plus {most} peuvent tourner ou attendre pour un appareil ; attendre les réponses, puis réessayer","server.internal_error":"erreur interne du serveur : {detail}","scenario.conical":"Pendule conique à 45°","scenario.damped":"Rosette amortie (c = 0.05 1/s)","scenario.foucault":"Pendule de Foucault à 49° N, rotation de la Terre exagérée (Ω = 0.02 rad/s)","scenario.inverted_g":"Gravité inversée : la rosette en miroir","scenario.near_top":"Lâché juste sous le sommet","scenario.over_the_top":"Par-dessus le sommet : tours dans un plan","scenario.planar_large":"Oscillation plane d’amplitude 150°","scenario.rosette":"Rosette : lâché à 60° avec un élan latéral","scenario.slewing_crane":"Grue pivotante : R = 5 m, ω = 0.3 rad/s, l = 10 m","scenario.small_ellipse":"Petite ellipse avec précession d’Airy","scenario.string_slack":"Pendule à fil : fil détendu à z = l/2, choc inélastique","scenario.swinging_spring":"Ressort oscillant à la résonance 1:1:2","scenario.zero_g":"Gravité nulle : un grand cercle","modelHelp.ideal":"une tige sans frottement : le pendule des manuels","modelHelp.damped":"avec frottement, résistance de l’air ou poussée périodique","modelHelp.rotating":"vu depuis la Terre qui tourne : le plan d’oscillation tourne (Foucault)","modelHelp.slewing":"suspendu à la flèche d’une grue qui tourne","modelHelp.vibrating":"le point d’attache secoué de haut en bas : il peut tenir à l’envers (Kapitza)","modelHelp.sampled_pivot":"le point d’attache suit une trajectoire donnée","modelHelp.spring":"un ressort au lieu d’une tige : il oscille et rebondit","modelHelp.string":"un fil au lieu d’une tige : il peut se détendre puis se tendre d’un coup","key.space":"Espace","key.page":"Pg préc. / Pg suiv.","key.shift":"Maj","toolbar.simpleShort":"Simple","toolbar.simple":"vue simple : seulement les outils de classe (longueur, masse, gravité, frottement, chronomètre, période, règle, énergie) ; appuyer à nouveau pour tout voir","extras.add":"+ un autre pendule (longueur, masse, départ propres)","extras.pendulum":"pendule {n}","extras.remove":"retirer le pendule {n}","extras.title":"Jusqu’à quatre pendules","extras.hint":"Avec le deuxième pendule sur « longueur, masse et départ propres » : ajouter les pendules 3 et 4, puis « démarrer les deux » les démarre tous, chacun chronométré par sa propre mesure de période."},Qg={length:["longueur l","longueur de la tige du point de suspension à la masse"],mass:["masse m","masse de la boule"],g:["pesanteur g","intensité de la pesanteur (tout signe ; 0 permis)"],damping:["frottement (amortissement linéaire) c","force de frottement −m c v, proportionnelle à la vitesse"],drag:["résistance de l’air c_q","force −m c_q |v| v, quadratique en vitesse"],forcing_amplitude:["forçage : intensité A","force périodique par masse A cos(ω t + ψ) dans la direction e"],forcing_omega:["forçage : pulsation ω","à quelle vitesse le forçage oscille"],forcing_phase:["forçage : phase ψ","phase du forçage à t = 0"],forcing_x:["direction du forçage e : x","composante x de la direction du forçage (normalisée)"],forcing_y:["direction du forçage e : y","composante y de la direction du forçage"],forcing_z:["direction du forçage e : z","composante z de la direction du forçage"],gravity_x:["direction de la pesanteur d : x","composante x de la direction de la pesanteur (normalisée)"],gravity_y:["direction de la pesanteur d : y","composante y de la direction de la pesanteur"],gravity_z:["direction de la pesanteur d : z","composante z de la direction de la pesanteur"],frame_rate:["vitesse de rotation du référentiel |Ω|","à quelle vitesse tourne le référentiel (Terre : 7,292e-5)"],latitude:["latitude λ","latitude du lieu (pendule de Foucault)"],radius:["rayon de la flèche R","distance du point de suspension à l’axe de rotation de la grue"],rate:["vitesse de rotation de la grue ω","à quelle vitesse tourne la flèche"],height:["hauteur du point de suspension h","hauteur de la flèche"],amplitude:["amplitude de vibration A","amplitude de l’oscillation verticale du point de suspension"],frequency:["fréquence de vibration ν","pulsation de l’oscillation du point de suspension"],stiffness:["raideur du ressort k","raideur du ressort ; la longueur l est la longueur au repos"],restitution:["coefficient de restitution e","élasticité du fil quand il se tend d’un coup (0 … 1)"]},e0={ideal:"Pendule idéal",damped:"Amorti et forcé",rotating:"Sur la Terre qui tourne (Foucault)",slewing:"Grue pivotante",vibrating:"Point de suspension vibrant (Kapitza)",sampled_pivot:"Point de suspension sur un chemin donné",spring:"Ressort oscillant",string:"Pendule à fil"},Xa={en:{name:"English",words:er,params:{},models:{}},de:{name:"Deutsch",words:Kg,params:Zg,models:Jg},fr:{name:"Français",words:jg,params:Qg,models:e0}};let $a="en";function Hl(i){return typeof i=="string"&&Object.hasOwn(Xa,i)}function t0(i,e,t){if(Hl(i))return i;if(Hl(e))return e;for(const n of t){const s=n.toLowerCase().split("-")[0];if(Hl(s))return s}return"en"}function n0(i){$a=i}function fl(){return $a}function R(i,e={}){return(Xa[$a].words[i]??er[i]).replace(/\{(\w+)\}/g,(s,r)=>r in e?String(e[r]):s)}function gp(i,e,t){return Xa[$a].params[i]??[e,t]}function Wr(i,e){return Xa[$a].models[i]??e}function jo(i,e){const t=`method.${i}`;return Object.hasOwn(er,t)?R(t):R("method.other",{name:i,n:e})}function i0(i){const e=`kind.${i}`;return Object.hasOwn(er,e)?R(e):i}function ed(i,e){const t=`scenario.${i}`;return Object.hasOwn(er,t)?R(t):e??i}function s0(i,e){const t=`modelHelp.${i}`;return Object.hasOwn(er,t)?R(t):e}function r0(i){const e=`server.${i.key??""}`;return i.key!==void 0&&Object.hasOwn(er,e)?R(e,i.values??{}):i.message}const a0=["spring","string"];function o0(i){return!a0.includes(i??"ideal")}function jh(i){return i==="spring"?R("note.spring"):i==="string"?R("note.string"):null}function Oc(i,e){return i==="spring"?"coil":i==="string"?e?"taut string":"slack string":"rod"}function ft(i,e=6){if(i==null||Number.isNaN(i))return"—";if(!Number.isFinite(i))return i>0?"∞":"−∞";if(i===0)return"0";const t=Math.abs(i);return t>=.001&&t<1e6?i.toPrecision(e):i.toExponential(e-1)}const l0=5;function c0(i){const e=i.kind==="slack"?R("event.slack"):R("event.taut",{lost:ft(i.energy_lost,3)}),t=i.skipped>0?R(i.skipped>1?"event.skippedMany":"event.skippedOne",{n:i.skipped}):"";return`t = ${i.t.toFixed(3)} s: ${e}${t}`}function h0(i){return i.kind==="slack"?[R("event.slackRow"),`t = ${ft(i.t,6)} s`,""]:[R("event.tautRow"),R("event.tautValue",{t:ft(i.t,6),lost:ft(i.energy_lost,4)}),"J"]}function u0(i,e,t,n=l0){if(t===null||e.epoch!==t)return i;const s=[...i,e];return s.length>n?s.slice(s.length-n):s}function d0(i){return i.replace(/\s*\((?:docs\/theory\.md\s*)?(?:T-\d+\.\d+|§\s?\d+)(?:[,;]\s*(?:T-\d+\.\d+|§\s?\d+))*\)/g,"").replace(/\s*(?:docs\/theory\.md\s*)?(?:T-\d+\.\d+|§\s?\d+)/g,"").replace(/\s+([,;.:)])/g,"$1").replace(/[,;]+\)/g,")").replace(/\(\s*\)/g,"").replace(/\s{2,}/g," ").trim()}let Qh=!1;function Ho(){return Qh}function kc(i){if(!(i instanceof HTMLElement)||!i.hasAttribute("title"))return;const e=i.title;e!==i.dataset.titleShown&&(i.dataset.titleFull=e);const t=i.dataset.titleFull??e,n=Qh?t:d0(t);i.dataset.titleShown=n,e!==n&&(i.title=n)}function _p(i){i instanceof Element&&kc(i);for(const e of i.querySelectorAll("[title]"))kc(e)}function vp(i){Qh=i,document.body.classList.toggle("advanced",i),_p(document.body)}function f0(){let i=!1;try{i=window.localStorage?.getItem("pendulab.advanced")==="1"}catch{i=!1}vp(i),new MutationObserver(e=>{for(const t of e){t.type==="attributes"&&t.target instanceof Element&&kc(t.target);for(const n of t.addedNodes)n instanceof Element&&_p(n)}}).observe(document.body,{subtree:!0,childList:!0,attributes:!0,attributeFilter:["title"]})}function p0(i){try{window.localStorage?.setItem("pendulab.advanced",i?"1":"0")}catch{}vp(i)}function m0(i,e){const t=e.reference,n=e.status,s=e.tensionExtremes,r=[["t",ft(i?.t,7),"s"],[R("data.energy"),ft(i?.energy,10),"J"],[R("data.energyChange"),i&&t?ft(i.energy-t.energy,3):"—","J"],[R("data.spin"),ft(i?.j3,10),"kg m²/s"],[R("data.spinChange"),i&&t?ft(i.j3-t.j3,3):"—","kg m²/s"],[R("data.tension"),ft(i?.tension,6),"N"],[R("data.tensionMin"),s?`${ft(s.min,6)} (t = ${ft(s.tMin,4)} s)`:"—","N"],[R("data.tensionMax"),s?`${ft(s.max,6)} (t = ${ft(s.tMax,4)} s)`:"—","N"],[R("data.height"),ft(i?.x[2],6),"m"],[R("data.method"),n?`${jo(n.method,0)}${n.adaptive?"":`, dt = ${n.dt} s`}`:"—",""],[R("data.state"),n?`${n.paused?R("data.paused"):R("data.running")}${n.lagging?R("data.lagging"):""}`:"—",""],...g0(i,n)];n&&n.model!=="ideal"&&(r.splice(1,0,[R("data.model"),Wr(n.model,n.model),""]),r.splice(4,0,[R("data.power"),ft(i?.power,6),"W"]));const a=r.findIndex(l=>l[0]===R("data.tension")),o=Oc(n?.model,i?.taut??!0);if(o==="coil"&&n){const l=i?Math.hypot(...i.x):null;r[a]=[R("data.springForce"),ft(i?.tension,6),"N"],r.splice(a+1,0,[R("data.springLength"),ft(l,6),"m"],[R("data.stretch"),l===null?"—":ft(l-n.params.length,4),"m"])}else o==="slack string"?(r[a]=[R("data.tension"),R("data.slackZero"),"N"],r.splice(a+1,0,[R("data.string"),R("data.slack",{r:ft(i?Math.hypot(...i.x):null,5)}),""])):o==="taut string"&&r.splice(a+1,0,[R("data.string"),R("data.taut"),""]);if(n?.model==="string"){const l=[...e.events].reverse().map(h0);r.push(...l.length>0?l:[[R("data.events"),R("data.noEvents"),""]])}return r}function g0(i,e){const t=e?.error_estimate;if(!e||!t)return[];if(t.how===null)return[[R("data.errorHow"),t.note??R("data.errorNone"),""]];const n=ft(t.since,6),s=t.how==="exact"?R("data.howExact",{since:n}):t.how==="richardson"?R("data.howRichardson",{dt:ft(t.reference.dt,3),p:t.order??"?",since:n}):R("data.howCompanion",{rtol:ft(t.reference.rtol,3),since:n}),r=i?.errorX,a=r!==void 0&&r>=0;return[[R("data.error"),a?ft(r,3):r===void 0?"—":R("data.errorPaused"),a?"m":""],[R("data.errorRel"),a?ft(r/e.params.length,3):"—",""],[R("data.errorHow"),s,""]]}function _0(i){const e=i.status,t=jh(e?.model);return t!==null?t:e&&e.model!=="ideal"?R("note.exactIdeal",{model:e.model}):i.exactError??i.exact?.phases_note??""}function v0(i){if(i===null)return[];const e=i.turning_heights,t=[[R("data.kind"),i0(i.kind),""],[R("data.turning"),`${ft(e[0])}, ${ft(e[1])}`,"m"]];return e.length>2&&Ho()&&t.push([R("data.z3"),ft(e[2]),"m"]),t.push([i.kind==="planar"?R("data.swingPeriod"):R("data.periodZ"),i.period_z_infinite?"∞":ft(i.period_z),"s"]),i.azimuth_advance!==null&&t.push([R("data.advance"),ft(i.azimuth_advance),"rad"]),i.rotation_number!==null&&Ho()&&t.push([R("data.rotation"),ft(i.rotation_number),""]),i.phases!==null&&Ho()&&(t.push([R("data.dynamic"),ft(i.phases.dynamic),"rad"]),t.push([R("data.geometric"),ft(i.phases.geometric),"rad"])),t}class x0{live;exactTable;note;constructor(e){const t=n=>{const s=document.createElement("h3");s.textContent=n,e.appendChild(s)};t(R("data.now")),this.live=document.createElement("table"),e.appendChild(this.live),t(R("data.exact")),this.exactTable=document.createElement("table"),e.appendChild(this.exactTable),this.note=document.createElement("p"),this.note.className="note",e.appendChild(this.note)}fill(e,t){for(;e.rows.length>t.length;)e.deleteRow(-1);t.forEach(([n,s,r],a)=>{const o=e.rows[a]??e.insertRow();for(;o.cells.length<3;)o.insertCell();const[l,c,h]=[o.cells[0],o.cells[1],o.cells[2]];l&&l.textContent!==n&&(l.textContent=n),c&&c.textContent!==s&&(c.textContent=s),h&&h.textContent!==r&&(h.textContent=r)})}update(e,t){this.fill(this.live,m0(e,t)),this.fill(this.exactTable,v0(t.exact));const n=_0(t);this.note.textContent!==n&&(this.note.textContent=n)}}const y0=!0,bn="u-",S0="uplot",M0=bn+"hz",b0=bn+"vt",w0=bn+"title",E0=bn+"wrap",T0=bn+"under",A0=bn+"over",R0=bn+"axis",qs=bn+"off",C0=bn+"select",P0=bn+"cursor-x",L0=bn+"cursor-y",D0=bn+"cursor-pt",N0=bn+"legend",I0=bn+"live",U0=bn+"inline",F0=bn+"series",O0=bn+"marker",td=bn+"label",k0=bn+"value",Ma="width",ba="height",ua="top",nd="bottom",mr="left",Gl="right",eu="#000",id=eu+"0",Vl="mousemove",sd="mousedown",Wl="mouseup",rd="mouseenter",ad="mouseleave",od="dblclick",B0="resize",z0="scroll",ld="change",Qo="dppxchange",tu="--",Qr=typeof window<"u",Bc=Qr?document:null,kr=Qr?window:null,H0=Qr?navigator:null;let wt,io;function zc(){let i=devicePixelRatio;wt!=i&&(wt=i,io&&Gc(ld,io,zc),io=matchMedia(`(min-resolution: ${wt-.001}dppx) and (max-resolution: ${wt+.001}dppx)`),Ys(ld,io,zc),kr.dispatchEvent(new CustomEvent(Qo)))}function ii(i,e){if(e!=null){let t=i.classList;!t.contains(e)&&t.add(e)}}function Hc(i,e){let t=i.classList;t.contains(e)&&t.remove(e)}function Wt(i,e,t){i.style[e]=t+"px"}function Ti(i,e,t,n){let s=Bc.createElement(i);return e!=null&&ii(s,e),t?.insertBefore(s,n),s}function hi(i,e){return Ti("div",i,e)}const cd=new WeakMap;function ki(i,e,t,n,s){let r="translate("+e+"px,"+t+"px)",a=cd.get(i);r!=a&&(i.style.transform=r,cd.set(i,r),e<0||t<0||e>n||t>s?ii(i,qs):Hc(i,qs))}const hd=new WeakMap;function ud(i,e,t){let n=e+t,s=hd.get(i);n!=s&&(hd.set(i,n),i.style.background=e,i.style.borderColor=t)}const dd=new WeakMap;function fd(i,e,t,n){let s=e+""+t,r=dd.get(i);s!=r&&(dd.set(i,s),i.style.height=t+"px",i.style.width=e+"px",i.style.marginLeft=n?-e/2+"px":0,i.style.marginTop=n?-t/2+"px":0)}const nu={passive:!0},G0={...nu,capture:!0};function Ys(i,e,t,n){e.addEventListener(i,t,n?G0:nu)}function Gc(i,e,t,n){e.removeEventListener(i,t,nu)}Qr&&zc();function Ai(i,e,t,n){let s;t=t||0,n=n||e.length-1;let r=n<=2147483647;for(;n-t>1;)s=r?t+n>>1:ri((t+n)/2),e[s]<i?t=s:n=s;return i-e[t]<=e[n]-i?t:n}function xp(i){return(t,n,s)=>{let r=-1,a=-1;for(let o=n;o<=s;o++)if(i(t[o])){r=o;break}for(let o=s;o>=n;o--)if(i(t[o])){a=o;break}return[r,a]}}const yp=i=>i!=null,Sp=i=>i!=null&&i>0,pl=xp(yp),V0=xp(Sp);function W0(i,e,t,n=0,s=!1){let r=s?V0:pl,a=s?Sp:yp;[e,t]=r(i,e,t);let o=i[e],l=i[e];if(e>-1)if(n==1)o=i[e],l=i[t];else if(n==-1)o=i[t],l=i[e];else for(let c=e;c<=t;c++){let h=i[c];a(h)&&(h<o?o=h:h>l&&(l=h))}return[o??Ft,l??-Ft]}function ml(i,e,t,n){let s=gd(i),r=gd(e);i==e&&(s==-1?(i*=t,e/=t):(i/=t,e*=t));let a=t==10?hs:Mp,o=s==1?ri:ui,l=r==1?ui:ri,c=o(a(xn(i))),h=l(a(xn(e))),d=Xr(t,c),u=Xr(t,h);return t==10&&(c<0&&(d=Ot(d,-c)),h<0&&(u=Ot(u,-h))),n||t==2?(i=d*s,e=u*r):(i=Tp(i,d),e=gl(e,u)),[i,e]}function iu(i,e,t,n){let s=ml(i,e,t,n);return i==0&&(s[0]=0),e==0&&(s[1]=0),s}const su=.1,pd={mode:3,pad:su},Ra={pad:0,soft:null,mode:0},X0={min:Ra,max:Ra};function el(i,e,t,n){return _l(t)?md(i,e,t):(Ra.pad=t,Ra.soft=n?0:null,Ra.mode=n?3:0,md(i,e,X0))}function St(i,e){return i??e}function $0(i,e,t){for(e=St(e,0),t=St(t,i.length-1);e<=t;){if(i[e]!=null)return!0;e++}return!1}function md(i,e,t){let n=t.min,s=t.max,r=St(n.pad,0),a=St(s.pad,0),o=St(n.hard,-Ft),l=St(s.hard,Ft),c=St(n.soft,Ft),h=St(s.soft,-Ft),d=St(n.mode,0),u=St(s.mode,0),m=e-i,_=hs(m),y=$n(xn(i),xn(e)),p=hs(y),f=xn(p-_);(m<1e-24||f>10)&&(m=0,(i==0||e==0)&&(m=1e-24,d==2&&c!=Ft&&(r=0),u==2&&h!=-Ft&&(a=0)));let x=m||y||1e3,A=hs(x),M=Xr(10,ri(A)),C=x*(m==0?i==0?.1:1:r),b=Ot(Tp(i-C,M/10),24),g=i>=c&&(d==1||d==3&&b<=c||d==2&&b>=c)?c:Ft,w=$n(o,b<g&&i>=g?g:Ci(g,b)),F=x*(m==0?e==0?.1:1:a),L=Ot(gl(e+F,M/10),24),D=e<=h&&(u==1||u==3&&L>=h||u==2&&L<=h)?h:-Ft,z=Ci(l,L>D&&e<=D?D:$n(D,L));return w==z&&w==0&&(z=100),[w,z]}const q0=new Intl.NumberFormat(Qr?H0.language:"en-US"),ru=i=>q0.format(i),ai=Math,Go=ai.PI,xn=ai.abs,ri=ai.floor,vn=ai.round,ui=ai.ceil,Ci=ai.min,$n=ai.max,Xr=ai.pow,gd=ai.sign,hs=ai.log10,Mp=ai.log2,Y0=(i,e=1)=>ai.sinh(i)*e,Xl=(i,e=1)=>ai.asinh(i/e),Ft=1/0;function _d(i){return(hs((i^i>>31)-(i>>31))|0)+1}function Vc(i,e,t){return Ci($n(i,e),t)}function bp(i){return typeof i=="function"}function gt(i){return bp(i)?i:()=>i}const K0=()=>{},wp=i=>i,Ep=(i,e)=>e,Z0=i=>null,vd=i=>!0,xd=(i,e)=>i==e,J0=/\.\d*?(?=9{6,}|0{6,})/gm,Js=i=>{if(Rp(i)||Ls.has(i))return i;const e=`${i}`,t=e.match(J0);if(t==null)return i;let n=t[0].length-1;if(e.indexOf("e-")!=-1){let[s,r]=e.split("e");return+`${Js(s)}e${r}`}return Ot(i,n)};function Xs(i,e){return Js(Ot(Js(i/e))*e)}function gl(i,e){return Js(ui(Js(i/e))*e)}function Tp(i,e){return Js(ri(Js(i/e))*e)}function Ot(i,e=0){if(Rp(i))return i;let t=10**e,n=i*t*(1+Number.EPSILON);return vn(n)/t}const Ls=new Map;function Ap(i){return((""+i).split(".")[1]||"").length}function Ua(i,e,t,n){let s=[],r=n.map(Ap);for(let a=e;a<t;a++){let o=xn(a),l=Ot(Xr(i,a),o);for(let c=0;c<n.length;c++){let h=i==10?+`${n[c]}e${a}`:n[c]*l,d=(a>=0?0:o)+(a>=r[c]?0:r[c]),u=i==10?h:Ot(h,d);s.push(u),Ls.set(u,d)}}return s}const Ca={},au=[],$r=[null,null],Ts=Array.isArray,Rp=Number.isInteger,j0=i=>i===void 0;function yd(i){return typeof i=="string"}function _l(i){let e=!1;if(i!=null){let t=i.constructor;e=t==null||t==Object}return e}function Q0(i){return i!=null&&typeof i=="object"}const e_=Object.getPrototypeOf(Uint8Array),Cp="__proto__";function qr(i,e=_l){let t;if(Ts(i)){let n=i.find(s=>s!=null);if(Ts(n)||e(n)){t=Array(i.length);for(let s=0;s<i.length;s++)t[s]=qr(i[s],e)}else t=i.slice()}else if(i instanceof e_)t=i.slice();else if(e(i)){t={};for(let n in i)n!=Cp&&(t[n]=qr(i[n],e))}else t=i;return t}function fn(i){let e=arguments;for(let t=1;t<e.length;t++){let n=e[t];for(let s in n)s!=Cp&&(_l(i[s])?fn(i[s],qr(n[s])):i[s]=qr(n[s]))}return i}const t_=0,n_=1,i_=2;function s_(i,e,t){for(let n=0,s,r=-1;n<e.length;n++){let a=e[n];if(a>r){for(s=a-1;s>=0&&i[s]==null;)i[s--]=null;for(s=a+1;s<t&&i[s]==null;)i[r=s++]=null}}}function r_(i,e){if(l_(i)){let a=i[0].slice();for(let o=1;o<i.length;o++)a.push(...i[o].slice(1));return c_(a[0])||(a=o_(a)),a}let t=new Set;for(let a=0;a<i.length;a++){let l=i[a][0],c=l.length;for(let h=0;h<c;h++)t.add(l[h])}let n=[Array.from(t).sort((a,o)=>a-o)],s=n[0].length,r=new Map;for(let a=0;a<s;a++)r.set(n[0][a],a);for(let a=0;a<i.length;a++){let o=i[a],l=o[0];for(let c=1;c<o.length;c++){let h=o[c],d=Array(s).fill(void 0),u=e?e[a][c]:n_,m=[];for(let _=0;_<h.length;_++){let y=h[_],p=r.get(l[_]);y===null?u!=t_&&(d[p]=y,u==i_&&m.push(p)):d[p]=y}s_(d,m,s),n.push(d)}}return n}const a_=typeof queueMicrotask>"u"?i=>Promise.resolve().then(i):queueMicrotask;function o_(i){let e=i[0],t=e.length,n=Array(t);for(let r=0;r<n.length;r++)n[r]=r;n.sort((r,a)=>e[r]-e[a]);let s=[];for(let r=0;r<i.length;r++){let a=i[r],o=Array(t);for(let l=0;l<t;l++)o[l]=a[n[l]];s.push(o)}return s}function l_(i){let e=i[0][0],t=e.length;for(let n=1;n<i.length;n++){let s=i[n][0];if(s.length!=t)return!1;if(s!=e){for(let r=0;r<t;r++)if(s[r]!=e[r])return!1}}return!0}function c_(i,e=100){const t=i.length;if(t<=1)return!0;let n=0,s=t-1;for(;n<=s&&i[n]==null;)n++;for(;s>=n&&i[s]==null;)s--;if(s<=n)return!0;const r=$n(1,ri((s-n+1)/e));for(let a=i[n],o=n+r;o<=s;o+=r){const l=i[o];if(l!=null){if(l<=a)return!1;a=l}}return!0}const Pp=["January","February","March","April","May","June","July","August","September","October","November","December"],Lp=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function Dp(i){return i.slice(0,3)}const h_=Lp.map(Dp),u_=Pp.map(Dp),d_={MMMM:Pp,MMM:u_,WWWW:Lp,WWW:h_};function da(i){return(i<10?"0":"")+i}function f_(i){return(i<10?"00":i<100?"0":"")+i}const p_={YYYY:i=>i.getFullYear(),YY:i=>(i.getFullYear()+"").slice(2),MMMM:(i,e)=>e.MMMM[i.getMonth()],MMM:(i,e)=>e.MMM[i.getMonth()],MM:i=>da(i.getMonth()+1),M:i=>i.getMonth()+1,DD:i=>da(i.getDate()),D:i=>i.getDate(),WWWW:(i,e)=>e.WWWW[i.getDay()],WWW:(i,e)=>e.WWW[i.getDay()],HH:i=>da(i.getHours()),H:i=>i.getHours(),h:i=>{let e=i.getHours();return e==0?12:e>12?e-12:e},AA:i=>i.getHours()>=12?"PM":"AM",aa:i=>i.getHours()>=12?"pm":"am",a:i=>i.getHours()>=12?"p":"a",mm:i=>da(i.getMinutes()),m:i=>i.getMinutes(),ss:i=>da(i.getSeconds()),s:i=>i.getSeconds(),fff:i=>f_(i.getMilliseconds())};function ou(i,e){e=e||d_;let t=[],n=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=n.exec(i);)t.push(s[0][0]=="{"?p_[s[1]]:s[0]);return r=>{let a="";for(let o=0;o<t.length;o++)a+=typeof t[o]=="string"?t[o]:t[o](r,e);return a}}const m_=new Intl.DateTimeFormat().resolvedOptions().timeZone;function g_(i,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+i+i.getTimezoneOffset()*6e4):e==m_?t=i:(t=new Date(i.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(i.getMilliseconds())),t}const Np=i=>i%1==0,tl=[1,2,2.5,5],__=Ua(10,-32,0,tl),Ip=Ua(10,0,32,tl),v_=Ip.filter(Np),$s=__.concat(Ip),lu=`
`,Up="{YYYY}",Sd=lu+Up,Fp="{M}/{D}",wa=lu+Fp,so=wa+"/{YY}",Op="{aa}",x_="{h}:{mm}",Ir=x_+Op,Md=lu+Ir,bd=":{ss}",At=null;function kp(i){let e=i*1e3,t=e*60,n=t*60,s=n*24,r=s*30,a=s*365,l=(i==1?Ua(10,0,3,tl).filter(Np):Ua(10,-3,0,tl)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,n,n*2,n*3,n*4,n*6,n*8,n*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,a,a*2,a*5,a*10,a*25,a*50,a*100]);const c=[[a,Up,At,At,At,At,At,At,1],[s*28,"{MMM}",Sd,At,At,At,At,At,1],[s,Fp,Sd,At,At,At,At,At,1],[n,"{h}"+Op,so,At,wa,At,At,At,1],[t,Ir,so,At,wa,At,At,At,1],[e,bd,so+" "+Ir,At,wa+" "+Ir,At,Md,At,1],[i,bd+".{fff}",so+" "+Ir,At,wa+" "+Ir,At,Md,At,1]];function h(d){return(u,m,_,y,p,f)=>{let x=[],A=p>=a,M=p>=r&&p<a,C=d(_),b=Ot(C*i,3),g=$l(C.getFullYear(),A?0:C.getMonth(),M||A?1:C.getDate()),w=Ot(g*i,3);if(M||A){let F=M?p/r:0,L=A?p/a:0,D=b==w?b:Ot($l(g.getFullYear()+L,g.getMonth()+F,1)*i,3),z=new Date(vn(D/i)),V=z.getFullYear(),U=z.getMonth();for(let W=0;D<=y;W++){let K=$l(V+L*W,U+F*W,1),G=K-d(Ot(K*i,3));D=Ot((+K+G)*i,3),D<=y&&x.push(D)}}else{let F=p>=s?s:p,L=ri(_)-ri(b),D=w+L+gl(b-w,F);x.push(D);let z=d(D),V=z.getHours()+z.getMinutes()/t+z.getSeconds()/n,U=p/n,W=u.axes[m]._space,K=f/W;for(;D=Ot(D+p,i==1?0:3),!(D>y);)if(U>1){let G=ri(Ot(V+U,6))%24,Q=d(D).getHours()-G;Q>1&&(Q=-1),D-=Q*n,V=(V+U)%24;let se=x[x.length-1];Ot((D-se)/p,3)*K>=.7&&x.push(D)}else x.push(D)}return x}}return[l,c,h]}const[y_,S_,M_]=kp(1),[b_,w_,E_]=kp(.001);Ua(2,-53,53,[1]);function wd(i,e){return i.map(t=>t.map((n,s)=>s==0||s==8||n==null?n:e(s==1||t[8]==0?n:t[1]+n)))}function Ed(i,e){return(t,n,s,r,a)=>{let o=e.find(_=>a>=_[0])||e[e.length-1],l,c,h,d,u,m;return n.map(_=>{let y=i(_),p=y.getFullYear(),f=y.getMonth(),x=y.getDate(),A=y.getHours(),M=y.getMinutes(),C=y.getSeconds(),b=p!=l&&o[2]||f!=c&&o[3]||x!=h&&o[4]||A!=d&&o[5]||M!=u&&o[6]||C!=m&&o[7]||o[1];return l=p,c=f,h=x,d=A,u=M,m=C,b(y)})}}function T_(i,e){let t=ou(e);return(n,s,r,a,o)=>s.map(l=>t(i(l)))}function $l(i,e,t){return new Date(i,e,t)}function Td(i,e){return e(i)}const A_="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function Ad(i,e){return(t,n,s,r)=>r==null?tu:e(i(n))}function R_(i,e){let t=i.series[e];return t.width?t.stroke(i,e):t.points.width?t.points.stroke(i,e):null}function C_(i,e){return i.series[e].fill(i,e)}const P_={show:!0,live:!0,isolate:!1,mount:K0,markers:{show:!0,width:2,stroke:R_,fill:C_,dash:"solid"},idx:null,idxs:null,values:[]};function L_(i,e){let t=i.cursor.points,n=hi(),s=t.size(i,e);Wt(n,Ma,s),Wt(n,ba,s);let r=s/-2;Wt(n,"marginLeft",r),Wt(n,"marginTop",r);let a=t.width(i,e,s);return a&&Wt(n,"borderWidth",a),n}function D_(i,e){let t=i.series[e].points;return t._fill||t._stroke}function N_(i,e){let t=i.series[e].points;return t._stroke||t._fill}function I_(i,e){return i.series[e].points.size}const ql=[0,0];function U_(i,e,t){return ql[0]=e,ql[1]=t,ql}function ro(i,e,t,n=!0){return s=>{s.button==0&&(!n||s.target==e)&&t(s)}}function Yl(i,e,t,n=!0){return s=>{(!n||s.target==e)&&t(s)}}const F_={show:!0,x:!0,y:!0,lock:!1,move:U_,points:{one:!1,show:L_,size:I_,width:0,stroke:N_,fill:D_},bind:{mousedown:ro,mouseup:ro,click:ro,dblclick:ro,mousemove:Yl,mouseleave:Yl,mouseenter:Yl},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(i,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(i,e,t,n,s)=>n-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},Bp={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},cu=fn({},Bp,{filter:Ep}),zp=fn({},cu,{size:10}),Hp=fn({},Bp,{show:!1}),hu='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',Gp="bold "+hu,Vp=1.5,Rd={show:!0,scale:"x",stroke:eu,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Gp,side:2,grid:cu,ticks:zp,border:Hp,font:hu,lineGap:Vp,rotate:0},O_="Value",k_="Time",Cd={show:!0,scale:"x",auto:!1,sorted:1,min:Ft,max:-Ft,idxs:[]};function B_(i,e,t,n,s){return e.map(r=>r==null?"":ru(r))}function z_(i,e,t,n,s,r,a){let o=[],l=Ls.get(s)||0;t=a?t:Ot(gl(t,s),l);for(let c=t;c<=n;c=Ot(c+s,l))o.push(Object.is(c,-0)?0:c);return o}function Wc(i,e,t,n,s,r,a){const o=[],l=i.scales[i.axes[e].scale].log,c=l==10?hs:Mp,h=ri(c(t));s=Xr(l,h),l==10&&(s=$s[Ai(s,$s)]);let d=t,u=s*l;l==10&&(u=$s[Ai(u,$s)]);do o.push(d),d=d+s,l==10&&!Ls.has(d)&&(d=Ot(d,Ls.get(s))),d>=u&&(s=d,u=s*l,l==10&&(u=$s[Ai(u,$s)]));while(d<=n);return o}function H_(i,e,t,n,s,r,a){let l=i.scales[i.axes[e].scale].asinh,c=n>l?Wc(i,e,$n(l,t),n,s):[l],h=n>=0&&t<=0?[0]:[];return(t<-l?Wc(i,e,$n(l,-n),-t,s):[l]).reverse().map(u=>-u).concat(h,c)}const Wp=/./,G_=/[12357]/,V_=/[125]/,Pd=/1/,Xc=(i,e,t,n)=>i.map((s,r)=>e==4&&s==0||r%n==0&&t.test(s.toExponential()[s<0?1:0])?s:null);function W_(i,e,t,n,s){let r=i.axes[t],a=r.scale,o=i.scales[a],l=i.valToPos,c=r._space,h=l(10,a),d=l(9,a)-h>=c?Wp:l(7,a)-h>=c?G_:l(5,a)-h>=c?V_:Pd;if(d==Pd){let u=xn(l(1,a)-h);if(u<c)return Xc(e.slice().reverse(),o.distr,d,ui(c/u)).reverse()}return Xc(e,o.distr,d,1)}function X_(i,e,t,n,s){let r=i.axes[t],a=r.scale,o=r._space,l=i.valToPos,c=xn(l(1,a)-l(2,a));return c<o?Xc(e.slice().reverse(),3,Wp,ui(o/c)).reverse():e}function $_(i,e,t,n){return n==null?tu:e==null?"":ru(e)}const Ld={show:!0,scale:"y",stroke:eu,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Gp,side:3,grid:cu,ticks:zp,border:Hp,font:hu,lineGap:Vp,rotate:0};function q_(i,e){let t=3+(i||1)*2;return Ot(t*e,3)}function Y_(i,e){let{scale:t,idxs:n}=i.series[0],s=i._data[0],r=i.valToPos(s[n[0]],t,!0),a=i.valToPos(s[n[1]],t,!0),o=xn(a-r),l=i.series[e],c=o/(l.points.space*wt);return n[1]-n[0]<=c}const Dd={scale:null,auto:!0,sorted:0,min:Ft,max:-Ft},Xp=(i,e,t,n,s)=>s,Nd={show:!0,auto:!0,sorted:0,gaps:Xp,alpha:1,facets:[fn({},Dd,{scale:"x"}),fn({},Dd,{scale:"y"})]},Id={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:Xp,alpha:1,points:{show:Y_,filter:null},values:null,min:Ft,max:-Ft,idxs:[],path:null,clip:null};function K_(i,e,t,n,s){return t/10}const $p={time:y0,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},Z_=fn({},$p,{time:!1,ori:1}),Ud={};function qp(i,e){let t=Ud[i];return t||(t={key:i,plots:[],sub(n){t.plots.push(n)},unsub(n){t.plots=t.plots.filter(s=>s!=n)},pub(n,s,r,a,o,l,c){for(let h=0;h<t.plots.length;h++)t.plots[h]!=s&&t.plots[h].pub(n,s,r,a,o,l,c)}},i!=null&&(Ud[i]=t)),t}const Yr=1,$c=2;function tr(i,e,t){const n=i.mode,s=i.series[e],r=n==2?i._data[e]:i._data,a=i.scales,o=i.bbox;let l=r[0],c=n==2?r[1]:r[e],h=n==2?a[s.facets[0].scale]:a[i.series[0].scale],d=n==2?a[s.facets[1].scale]:a[s.scale],u=o.left,m=o.top,_=o.width,y=o.height,p=i.valToPosH,f=i.valToPosV;return h.ori==0?t(s,l,c,h,d,p,f,u,m,_,y,xl,ea,Sl,Kp,Jp):t(s,l,c,h,d,f,p,m,u,y,_,yl,ta,fu,Zp,jp)}function uu(i,e){let t=0,n=0,s=St(i.bands,au);for(let r=0;r<s.length;r++){let a=s[r];a.series[0]==e?t=a.dir:a.series[1]==e&&(a.dir==1?n|=1:n|=2)}return[t,n==1?-1:n==2?1:n==3?2:0]}function J_(i,e,t,n,s){let r=i.mode,a=i.series[e],o=r==2?a.facets[1].scale:a.scale,l=i.scales[o];return s==-1?l.min:s==1?l.max:l.distr==3?l.dir==1?l.min:l.max:0}function us(i,e,t,n,s,r){return tr(i,e,(a,o,l,c,h,d,u,m,_,y,p)=>{let f=a.pxRound;const x=c.dir*(c.ori==0?1:-1),A=c.ori==0?ea:ta;let M,C;x==1?(M=t,C=n):(M=n,C=t);let b=f(d(o[M],c,y,m)),g=f(u(l[M],h,p,_)),w=f(d(o[C],c,y,m)),F=f(u(r==1?h.max:h.min,h,p,_)),L=new Path2D(s);return A(L,w,F),A(L,b,F),A(L,b,g),L})}function vl(i,e,t,n,s,r){let a=null;if(i.length>0){a=new Path2D;const o=e==0?Sl:fu;let l=t;for(let d=0;d<i.length;d++){let u=i[d];if(u[1]>u[0]){let m=u[0]-l;m>0&&o(a,l,n,m,n+r),l=u[1]}}let c=t+s-l,h=10;c>0&&o(a,l,n-h/2,c,n+r+h)}return a}function j_(i,e,t){let n=i[i.length-1];n&&n[0]==e?n[1]=t:i.push([e,t])}function du(i,e,t,n,s,r,a){let o=[],l=i.length;for(let c=s==1?t:n;c>=t&&c<=n;c+=s)if(e[c]===null){let d=c,u=c;if(s==1)for(;++c<=n&&e[c]===null;)u=c;else for(;--c>=t&&e[c]===null;)u=c;let m=r(i[d]),_=u==d?m:r(i[u]),y=d-s;m=a<=0&&y>=0&&y<l?r(i[y]):m;let f=u+s;_=a>=0&&f>=0&&f<l?r(i[f]):_,_>=m&&o.push([m,_])}return o}function Fd(i){return i==0?wp:i==1?vn:e=>Xs(e,i)}function Yp(i){let e=i==0?xl:yl,t=i==0?(s,r,a,o,l,c)=>{s.arcTo(r,a,o,l,c)}:(s,r,a,o,l,c)=>{s.arcTo(a,r,l,o,c)},n=i==0?(s,r,a,o,l)=>{s.rect(r,a,o,l)}:(s,r,a,o,l)=>{s.rect(a,r,l,o)};return(s,r,a,o,l,c=0,h=0)=>{c==0&&h==0?n(s,r,a,o,l):(c=Ci(c,o/2,l/2),h=Ci(h,o/2,l/2),e(s,r+c,a),t(s,r+o,a,r+o,a+l,c),t(s,r+o,a+l,r,a+l,h),t(s,r,a+l,r,a,h),t(s,r,a,r+o,a,c),s.closePath())}}const xl=(i,e,t)=>{i.moveTo(e,t)},yl=(i,e,t)=>{i.moveTo(t,e)},ea=(i,e,t)=>{i.lineTo(e,t)},ta=(i,e,t)=>{i.lineTo(t,e)},Sl=Yp(0),fu=Yp(1),Kp=(i,e,t,n,s,r)=>{i.arc(e,t,n,s,r)},Zp=(i,e,t,n,s,r)=>{i.arc(t,e,n,s,r)},Jp=(i,e,t,n,s,r,a)=>{i.bezierCurveTo(e,t,n,s,r,a)},jp=(i,e,t,n,s,r,a)=>{i.bezierCurveTo(t,e,s,n,a,r)};function Qp(i){return(e,t,n,s,r)=>tr(e,t,(a,o,l,c,h,d,u,m,_,y,p)=>{let{pxRound:f,points:x}=a,A,M;c.ori==0?(A=xl,M=Kp):(A=yl,M=Zp);const C=Ot(x.width*wt,3);let b=(x.size-x.width)/2*wt,g=Ot(b*2,3),w=new Path2D,F=new Path2D,{left:L,top:D,width:z,height:V}=e.bbox;Sl(F,L-g,D-g,z+g*2,V+g*2);const U=W=>{if(l[W]!=null){let K=f(d(o[W],c,y,m)),G=f(u(l[W],h,p,_));A(w,K+b,G),M(w,K,G,b,0,Go*2)}};if(r)r.forEach(U);else for(let W=n;W<=s;W++)U(W);return{stroke:C>0?w:null,fill:w,clip:F,flags:Yr|$c}})}function em(i){return(e,t,n,s,r,a)=>{n!=s&&(r!=n&&a!=n&&i(e,t,n),r!=s&&a!=s&&i(e,t,s),i(e,t,a))}}const Q_=em(ea),ev=em(ta);function tm(i){const e=St(i?.alignGaps,0);return(t,n,s,r)=>tr(t,n,(a,o,l,c,h,d,u,m,_,y,p)=>{[s,r]=pl(l,s,r);let f=a.pxRound,x=V=>f(d(V,c,y,m)),A=V=>f(u(V,h,p,_)),M,C;c.ori==0?(M=ea,C=Q_):(M=ta,C=ev);const b=c.dir*(c.ori==0?1:-1),g={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:Yr},w=g.stroke;let F=!1;if(r-s>=y*4){let V=ue=>t.posToVal(ue,c.key,!0),U=null,W=null,K,G,le,J=x(o[b==1?s:r]),Q=x(o[s]),se=x(o[r]),de=V(b==1?Q+1:se-1);for(let ue=b==1?s:r;ue>=s&&ue<=r;ue+=b){let ee=o[ue],ve=(b==1?ee<de:ee>de)?J:x(ee),Ae=l[ue];ve==J?Ae!=null?(G=Ae,U==null?(M(w,ve,A(G)),K=U=W=G):G<U?U=G:G>W&&(W=G)):Ae===null&&(F=!0):(U!=null&&C(w,J,A(U),A(W),A(K),A(G)),Ae!=null?(G=Ae,M(w,ve,A(G)),U=W=K=G):(U=W=null,Ae===null&&(F=!0)),J=ve,de=V(J+b))}U!=null&&U!=W&&le!=J&&C(w,J,A(U),A(W),A(K),A(G))}else for(let V=b==1?s:r;V>=s&&V<=r;V+=b){let U=l[V];U===null?F=!0:U!=null&&M(w,x(o[V]),A(U))}let[D,z]=uu(t,n);if(a.fill!=null||D!=0){let V=g.fill=new Path2D(w),U=a.fillTo(t,n,a.min,a.max,D),W=A(U),K=x(o[s]),G=x(o[r]);b==-1&&([G,K]=[K,G]),M(V,G,W),M(V,K,W)}if(!a.spanGaps){let V=[];F&&V.push(...du(o,l,s,r,b,x,e)),g.gaps=V=a.gaps(t,n,s,r,V),g.clip=vl(V,c.ori,m,_,y,p)}return z!=0&&(g.band=z==2?[us(t,n,s,r,w,-1),us(t,n,s,r,w,1)]:us(t,n,s,r,w,z)),g})}function tv(i){const e=St(i.align,1),t=St(i.ascDesc,!1),n=St(i.alignGaps,0),s=St(i.extend,!1);return(r,a,o,l)=>tr(r,a,(c,h,d,u,m,_,y,p,f,x,A)=>{[o,l]=pl(d,o,l);let M=c.pxRound,{left:C,width:b}=r.bbox,g=Q=>M(_(Q,u,x,p)),w=Q=>M(y(Q,m,A,f)),F=u.ori==0?ea:ta;const L={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:Yr},D=L.stroke,z=u.dir*(u.ori==0?1:-1);let V=w(d[z==1?o:l]),U=g(h[z==1?o:l]),W=U,K=U;s&&e==-1&&(K=C,F(D,K,V)),F(D,U,V);for(let Q=z==1?o:l;Q>=o&&Q<=l;Q+=z){let se=d[Q];if(se==null)continue;let de=g(h[Q]),ue=w(se);e==1?F(D,de,V):F(D,W,ue),F(D,de,ue),V=ue,W=de}let G=W;s&&e==1&&(G=C+b,F(D,G,V));let[le,J]=uu(r,a);if(c.fill!=null||le!=0){let Q=L.fill=new Path2D(D),se=c.fillTo(r,a,c.min,c.max,le),de=w(se);F(Q,G,de),F(Q,K,de)}if(!c.spanGaps){let Q=[];Q.push(...du(h,d,o,l,z,g,n));let se=c.width*wt/2,de=t||e==1?se:-se,ue=t||e==-1?-se:se;Q.forEach(ee=>{ee[0]+=de,ee[1]+=ue}),L.gaps=Q=c.gaps(r,a,o,l,Q),L.clip=vl(Q,u.ori,p,f,x,A)}return J!=0&&(L.band=J==2?[us(r,a,o,l,D,-1),us(r,a,o,l,D,1)]:us(r,a,o,l,D,J)),L})}function Od(i,e,t,n,s,r,a=Ft){if(i.length>1){let o=null;for(let l=0,c=1/0;l<i.length;l++)if(e[l]!==void 0){if(o!=null){let h=xn(i[l]-i[o]);h<c&&(c=h,a=xn(t(i[l],n,s,r)-t(i[o],n,s,r)))}o=l}}return a}function nv(i){i=i||Ca;const e=St(i.size,[.6,Ft,1]),t=i.align||0,n=i.gap||0;let s=i.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;const r=gt(s),a=1-e[0],o=St(e[1],Ft),l=St(e[2],1),c=St(i.disp,Ca),h=St(i.each,m=>{}),{fill:d,stroke:u}=c;return(m,_,y,p)=>tr(m,_,(f,x,A,M,C,b,g,w,F,L,D)=>{let z=f.pxRound,V=t,U=n*wt,W=o*wt,K=l*wt,G,le;M.ori==0?[G,le]=r(m,_):[le,G]=r(m,_);const J=M.dir*(M.ori==0?1:-1);let Q=M.ori==0?Sl:fu,se=M.ori==0?h:(Ce,qe,nt,be,Ut,ze,$e)=>{h(Ce,qe,nt,Ut,be,$e,ze)},de=St(m.bands,au).find(Ce=>Ce.series[0]==_),ue=de!=null?de.dir:0,ee=f.fillTo(m,_,f.min,f.max,ue),me=z(g(ee,C,D,F)),ve,Ae,Me,Ve=L,tt=z(f.width*wt),He=!1,ct=null,rt=null,Qe=null,Xt=null;d!=null&&(tt==0||u!=null)&&(He=!0,ct=d.values(m,_,y,p),rt=new Map,new Set(ct).forEach(Ce=>{Ce!=null&&rt.set(Ce,new Path2D)}),tt>0&&(Qe=u.values(m,_,y,p),Xt=new Map,new Set(Qe).forEach(Ce=>{Ce!=null&&Xt.set(Ce,new Path2D)})));let{x0:kt,size:an}=c;if(kt!=null&&an!=null){V=1,x=kt.values(m,_,y,p),kt.unit==2&&(x=x.map(nt=>m.posToVal(w+nt*L,M.key,!0)));let Ce=an.values(m,_,y,p);an.unit==2?Ae=Ce[0]*L:Ae=b(Ce[0],M,L,w)-b(0,M,L,w),Ve=Od(x,A,b,M,L,w,Ve),Me=Ve-Ae+U}else Ve=Od(x,A,b,M,L,w,Ve),Me=Ve*a+U,Ae=Ve-Me;Me<1&&(Me=0),tt>=Ae/2&&(tt=0),Me<5&&(z=wp);let Nt=Me>0,wn=Ve-Me-(Nt?tt:0);Ae=z(Vc(wn,K,W)),ve=(V==0?Ae/2:V==J?0:Ae)-V*J*((V==0?U/2:0)+(Nt?tt/2:0));const vt={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},pn=He?null:new Path2D;let Yt=null;if(de!=null)Yt=m.data[de.series[1]];else{let{y0:Ce,y1:qe}=c;Ce!=null&&qe!=null&&(A=qe.values(m,_,y,p),Yt=Ce.values(m,_,y,p))}let on=G*Ae,k=le*Ae;for(let Ce=J==1?y:p;Ce>=y&&Ce<=p;Ce+=J){let qe=A[Ce];if(qe==null)continue;if(Yt!=null){let $=Yt[Ce]??0;if(qe-$==0)continue;me=g($,C,D,F)}let nt=M.distr!=2||c!=null?x[Ce]:Ce,be=b(nt,M,L,w),Ut=g(St(qe,ee),C,D,F),ze=z(be-ve),$e=z($n(Ut,me)),P=z(Ci(Ut,me)),S=$e-P;if(qe!=null){let $=qe<0?k:on,he=qe<0?on:k;He?(tt>0&&Qe[Ce]!=null&&Q(Xt.get(Qe[Ce]),ze,P+ri(tt/2),Ae,$n(0,S-tt),$,he),ct[Ce]!=null&&Q(rt.get(ct[Ce]),ze,P+ri(tt/2),Ae,$n(0,S-tt),$,he)):Q(pn,ze,P+ri(tt/2),Ae,$n(0,S-tt),$,he),se(m,_,Ce,ze-tt/2,P,Ae+tt,S)}}return tt>0?vt.stroke=He?Xt:pn:He||(vt._fill=f.width==0?f._fill:f._stroke??f._fill,vt.width=0),vt.fill=He?rt:pn,vt})}function iv(i,e){const t=St(e?.alignGaps,0);return(n,s,r,a)=>tr(n,s,(o,l,c,h,d,u,m,_,y,p,f)=>{[r,a]=pl(c,r,a);let x=o.pxRound,A=G=>x(u(G,h,p,_)),M=G=>x(m(G,d,f,y)),C,b,g;h.ori==0?(C=xl,g=ea,b=Jp):(C=yl,g=ta,b=jp);const w=h.dir*(h.ori==0?1:-1);let F=A(l[w==1?r:a]),L=F,D=[],z=[];for(let G=w==1?r:a;G>=r&&G<=a;G+=w)if(c[G]!=null){let J=l[G],Q=A(J);D.push(L=Q),z.push(M(c[G]))}const V={stroke:i(D,z,C,g,b,x),fill:null,clip:null,band:null,gaps:null,flags:Yr},U=V.stroke;let[W,K]=uu(n,s);if(o.fill!=null||W!=0){let G=V.fill=new Path2D(U),le=o.fillTo(n,s,o.min,o.max,W),J=M(le);g(G,L,J),g(G,F,J)}if(!o.spanGaps){let G=[];G.push(...du(l,c,r,a,w,A,t)),V.gaps=G=o.gaps(n,s,r,a,G),V.clip=vl(G,h.ori,_,y,p,f)}return K!=0&&(V.band=K==2?[us(n,s,r,a,U,-1),us(n,s,r,a,U,1)]:us(n,s,r,a,U,K)),V})}function sv(i){return iv(rv,i)}function rv(i,e,t,n,s,r){const a=i.length;if(a<2)return null;const o=new Path2D;if(t(o,i[0],e[0]),a==2)n(o,i[1],e[1]);else{let l=Array(a),c=Array(a-1),h=Array(a-1),d=Array(a-1);for(let u=0;u<a-1;u++)h[u]=e[u+1]-e[u],d[u]=i[u+1]-i[u],c[u]=h[u]/d[u];l[0]=c[0];for(let u=1;u<a-1;u++)c[u]===0||c[u-1]===0||c[u-1]>0!=c[u]>0?l[u]=0:(l[u]=3*(d[u-1]+d[u])/((2*d[u]+d[u-1])/c[u-1]+(d[u]+2*d[u-1])/c[u]),isFinite(l[u])||(l[u]=0));l[a-1]=c[a-2];for(let u=0;u<a-1;u++)s(o,i[u]+d[u]/3,e[u]+l[u]*d[u]/3,i[u+1]-d[u]/3,e[u+1]-l[u+1]*d[u]/3,i[u+1],e[u+1])}return o}const qc=new Set;function kd(){for(let i of qc)i.syncRect(!0)}Qr&&(Ys(B0,kr,kd),Ys(z0,kr,kd,!0),Ys(Qo,kr,()=>{On.pxRatio=wt}));const av=tm(),ov=Qp();function Bd(i,e,t,n){return(n?[i[0],i[1]].concat(i.slice(2)):[i[0]].concat(i.slice(1))).map((r,a)=>Yc(r,a,e,t))}function lv(i,e){return i.map((t,n)=>n==0?{}:fn({},e,t))}function Yc(i,e,t,n){return fn({},e==0?t:n,i)}function nm(i,e,t){return e==null?$r:[e,t]}const cv=nm;function hv(i,e,t){return e==null?$r:el(e,t,su,!0)}function im(i,e,t,n){return e==null?$r:ml(e,t,i.scales[n].log,!1)}const uv=im;function sm(i,e,t,n){return e==null?$r:iu(e,t,i.scales[n].log,!1)}const dv=sm;function fv(i,e,t,n,s){let r=$n(_d(i),_d(e)),a=e-i,o=Ai(s/n*a,t);do{let l=t[o],c=n*l/a;if(c>=s&&r+(l<5?Ls.get(l):0)<=17)return[l,c]}while(++o<t.length);return[0,0]}function zd(i){let e,t;return i=i.replace(/(\d+)px/,(n,s)=>(e=vn((t=+s)*wt))+"px"),[i,e,t]}function pv(i){i.show&&[i.font,i.labelFont].forEach(e=>{let t=Ot(e[2]*wt,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function On(i,e,t){const n={mode:St(i.mode,1)},s=n.mode;function r(v,E,N,I){let X=E.valToPct(v);return I+N*(E.dir==-1?1-X:X)}function a(v,E,N,I){let X=E.valToPct(v);return I+N*(E.dir==-1?X:1-X)}function o(v,E,N,I){return E.ori==0?r(v,E,N,I):a(v,E,N,I)}n.valToPosH=r,n.valToPosV=a;let l=!1;n.status=0;const c=n.root=hi(S0);if(i.id!=null&&(c.id=i.id),ii(c,i.class),i.title){let v=hi(w0,c);v.textContent=i.title}const h=Ti("canvas"),d=n.ctx=h.getContext("2d"),u=hi(E0,c);Ys("click",u,v=>{v.target===_&&(Ht!=hr||$t!=ur)&&Pn.click(n,v)},!0);const m=n.under=hi(T0,u);u.appendChild(h);const _=n.over=hi(A0,u);i=qr(i);const y=+St(i.pxAlign,1),p=Fd(y);(i.plugins||[]).forEach(v=>{v.opts&&(i=v.opts(n,i)||i)});const f=i.ms||.001,x=n.series=s==1?Bd(i.series||[],Cd,Id,!1):lv(i.series||[null],Nd),A=n.axes=Bd(i.axes||[],Rd,Ld,!0),M=n.scales={},C=n.bands=i.bands||[];C.forEach(v=>{v.fill=gt(v.fill||null),v.dir=St(v.dir,-1)});const b=s==2?x[1].facets[0].scale:x[0].scale,g={axes:ts,series:ut},w=(i.drawOrder||["axes","series"]).map(v=>g[v]);function F(v){const E=v.distr==3?N=>hs(N>0?N:v.clamp(n,N,v.min,v.max,v.key)):v.distr==4?N=>Xl(N,v.asinh):v.distr==100?N=>v.fwd(N):N=>N;return N=>{let I=E(N),{_min:X,_max:Z}=v,oe=Z-X;return(I-X)/oe}}function L(v){let E=M[v];if(E==null){let N=(i.scales||Ca)[v]||Ca;if(N.from!=null){L(N.from);let I=fn({},M[N.from],N,{key:v});I.valToPct=F(I),M[v]=I}else{E=M[v]=fn({},v==b?$p:Z_,N),E.key=v;let I=E.time,X=E.range,Z=Ts(X);if((v!=b||s==2&&!I)&&(Z&&(X[0]==null||X[1]==null)&&(X={min:X[0]==null?pd:{mode:1,hard:X[0],soft:X[0]},max:X[1]==null?pd:{mode:1,hard:X[1],soft:X[1]}},Z=!1),!Z&&_l(X))){let oe=X;X=(fe,ye,Ne)=>ye==null?$r:el(ye,Ne,oe)}E.range=gt(X||(I?cv:v==b?E.distr==3?uv:E.distr==4?dv:nm:E.distr==3?im:E.distr==4?sm:hv)),E.auto=gt(Z?!1:E.auto),E.clamp=gt(E.clamp||K_),E._min=E._max=null,E.valToPct=F(E)}}}L("x"),L("y"),s==1&&x.forEach(v=>{L(v.scale)}),A.forEach(v=>{L(v.scale)});for(let v in i.scales)L(v);const D=M[b],z=D.distr;let V,U;D.ori==0?(ii(c,M0),V=r,U=a):(ii(c,b0),V=a,U=r);const W={};for(let v in M){let E=M[v];(E.min!=null||E.max!=null)&&(W[v]={min:E.min,max:E.max},E.min=E.max=null)}const K=i.tzDate||(v=>new Date(vn(v/f))),G=i.fmtDate||ou,le=f==1?M_(K):E_(K),J=Ed(K,wd(f==1?S_:w_,G)),Q=Ad(K,Td(A_,G)),se=[],de=n.legend=fn({},P_,i.legend),ue=n.cursor=fn({},F_,{drag:{y:s==2}},i.cursor),ee=de.show,me=ue.show,ve=de.markers;de.idxs=se,ve.width=gt(ve.width),ve.dash=gt(ve.dash),ve.stroke=gt(ve.stroke),ve.fill=gt(ve.fill);let Ae,Me,Ve,tt=[],He=[],ct,rt=!1,Qe={};if(de.live){const v=x[1]?x[1].values:null;rt=v!=null,ct=rt?v(n,1,0):{_:0};for(let E in ct)Qe[E]=tu}if(ee)if(Ae=Ti("table",N0,c),Ve=Ti("tbody",null,Ae),de.mount(n,Ae),rt){Me=Ti("thead",null,Ae,Ve);let v=Ti("tr",null,Me);Ti("th",null,v);for(var Xt in ct)Ti("th",td,v).textContent=Xt}else ii(Ae,U0),de.live&&ii(Ae,I0);const kt={show:!0},an={show:!1};function Nt(v,E){if(E==0&&(rt||!de.live||s==2))return $r;let N=[],I=Ti("tr",F0,Ve,Ve.childNodes[E]);ii(I,v.class),v.show||ii(I,qs);let X=Ti("th",null,I);if(ve.show){let fe=hi(O0,X);if(E>0){let ye=ve.width(n,E);ye&&(fe.style.border=ye+"px "+ve.dash(n,E)+" "+ve.stroke(n,E)),fe.style.background=ve.fill(n,E)}}let Z=hi(td,X);v.label instanceof HTMLElement?Z.appendChild(v.label):Z.textContent=v.label,E>0&&(ve.show||(Z.style.color=v.width>0?ve.stroke(n,E):ve.fill(n,E)),vt("click",X,fe=>{if(ue._lock)return;Ke(fe);let ye=x.indexOf(v);if((fe.ctrlKey||fe.metaKey)!=de.isolate){let Ne=x.some((Ie,Fe)=>Fe>0&&Fe!=ye&&Ie.show);x.forEach((Ie,Fe)=>{Fe>0&&Ii(Fe,Ne?Fe==ye?kt:an:kt,!0,un.setSeries)})}else Ii(ye,{show:!v.show},!0,un.setSeries)},!1),Ze&&vt(rd,X,fe=>{ue._lock||(Ke(fe),Ii(x.indexOf(v),fr,!0,un.setSeries))},!1));for(var oe in ct){let fe=Ti("td",k0,I);fe.textContent="--",N.push(fe)}return[I,N]}const wn=new Map;function vt(v,E,N,I=!0){const X=wn.get(E)||{},Z=ue.bind[v](n,E,N,I);Z&&(Ys(v,E,X[v]=Z),wn.set(E,X))}function pn(v,E,N){const I=wn.get(E)||{};for(let X in I)(v==null||X==v)&&(Gc(X,E,I[X]),delete I[X]);v==null&&wn.delete(E)}let Yt=0,on=0,k=0,Ce=0,qe=0,nt=0,be=qe,Ut=nt,ze=k,$e=Ce,P=0,S=0,$=0,he=0;n.bbox={};let ae=!1,_e=!1,xe=!1,te=!1,ie=!1,pe=!1;function O(v,E,N){(N||v!=n.width||E!=n.height)&&re(v,E),at(!1),xe=!0,_e=!0,Nn()}function re(v,E){n.width=Yt=k=v,n.height=on=Ce=E,qe=nt=0,Se(),Ge();let N=n.bbox;P=N.left=Xs(qe*wt,.5),S=N.top=Xs(nt*wt,.5),$=N.width=Xs(k*wt,.5),he=N.height=Xs(Ce*wt,.5)}const ne=3;function we(){let v=!1,E=0;for(;!v;){E++;let N=or(E),I=Ni(E);v=E==ne||N&&I,v||(re(n.width,n.height),_e=!0)}}function ge({width:v,height:E}){O(v,E)}n.setSize=ge;function Se(){let v=!1,E=!1,N=!1,I=!1;A.forEach((X,Z)=>{if(X.show&&X._show){let{side:oe,_size:fe}=X,ye=oe%2,Ne=X.label!=null?X.labelSize:0,Ie=fe+Ne;Ie>0&&(ye?(k-=Ie,oe==3?(qe+=Ie,I=!0):N=!0):(Ce-=Ie,oe==0?(nt+=Ie,v=!0):E=!0))}}),Li[0]=v,Li[1]=N,Li[2]=E,Li[3]=I,k-=xi[1]+xi[3],qe+=xi[3],Ce-=xi[2]+xi[0],nt+=xi[0]}function Ge(){let v=qe+k,E=nt+Ce,N=qe,I=nt;function X(Z,oe){switch(Z){case 1:return v+=oe,v-oe;case 2:return E+=oe,E-oe;case 3:return N-=oe,N+oe;case 0:return I-=oe,I+oe}}A.forEach((Z,oe)=>{if(Z.show&&Z._show){let fe=Z.side;Z._pos=X(fe,Z._size),Z.label!=null&&(Z._lpos=X(fe,Z.labelSize))}})}if(ue.dataIdx==null){let v=ue.hover,E=v.skip=new Set(v.skip??[]);E.add(void 0);let N=v.prox=gt(v.prox),I=v.bias??=0;ue.dataIdx=(X,Z,oe,fe)=>{if(Z==0)return oe;let ye=oe,Ne=N(X,Z,oe,fe)??Ft,Ie=Ne>=0&&Ne<Ft,Fe=D.ori==0?k:Ce,et=ue.left,Mt=e[0],yt=e[Z];if(E.has(yt[oe])){ye=null;let dt=null,Ye=null,We;if(I==0||I==-1)for(We=oe;dt==null&&We-- >0;)E.has(yt[We])||(dt=We);if(I==0||I==1)for(We=oe;Ye==null&&We++<yt.length;)E.has(yt[We])||(Ye=We);if(dt!=null||Ye!=null)if(Ie){let Vt=dt==null?-1/0:V(Mt[dt],D,Fe,0),Jt=Ye==null?1/0:V(Mt[Ye],D,Fe,0),Rn=et-Vt,It=Jt-et;Rn<=It?Rn<=Ne&&(ye=dt):It<=Ne&&(ye=Ye)}else ye=Ye==null?dt:dt==null?Ye:oe-dt<=Ye-oe?dt:Ye}else Ie&&xn(et-V(Mt[oe],D,Fe,0))>Ne&&(ye=null);return ye}}const Ke=v=>{ue.event=v};ue.idxs=se,ue._lock=!1;let ce=ue.points;ce.show=gt(ce.show),ce.size=gt(ce.size),ce.stroke=gt(ce.stroke),ce.width=gt(ce.width),ce.fill=gt(ce.fill);const Oe=n.focus=fn({},i.focus||{alpha:.3},ue.focus),Ze=Oe.prox>=0,Re=Ze&&ce.one;let st=[],zt=[],Bn=[];function ia(v,E){let N=ce.show(n,E);if(N instanceof HTMLElement)return ii(N,D0),ii(N,v.class),ki(N,-10,-10,k,Ce),_.insertBefore(N,st[E]),N}function sr(v,E){if(s==1||E>0){let N=s==1&&M[v.scale].time,I=v.value;v.value=N?yd(I)?Ad(K,Td(I,G)):I||Q:I||$_,v.label=v.label||(N?k_:O_)}if(Re||E>0){v.width=v.width==null?1:v.width,v.paths=v.paths||av||Z0,v.fillTo=gt(v.fillTo||J_),v.pxAlign=+St(v.pxAlign,y),v.pxRound=Fd(v.pxAlign),v.stroke=gt(v.stroke||null),v.fill=gt(v.fill||null),v._stroke=v._fill=v._paths=v._focus=null;let N=q_($n(1,v.width),1),I=v.points=fn({},{size:N,width:$n(1,N*.2),stroke:v.stroke,space:N*2,paths:ov,_stroke:null,_fill:null},v.points);I.show=gt(I.show),I.filter=gt(I.filter),I.fill=gt(I.fill),I.stroke=gt(I.stroke),I.paths=gt(I.paths),I.pxAlign=v.pxAlign}if(ee){let N=Nt(v,E);tt.splice(E,0,N[0]),He.splice(E,0,N[1]),de.values.push(null)}if(me){se.splice(E,0,null);let N=null;Re?E==0&&(N=ia(v,E)):E>0&&(N=ia(v,E)),st.splice(E,0,N),zt.splice(E,0,0),Bn.splice(E,0,0)}An("addSeries",E)}function Cl(v,E){E=E??x.length,v=s==1?Yc(v,E,Cd,Id):Yc(v,E,{},Nd),x.splice(E,0,v),sr(x[E],E)}n.addSeries=Cl;function ja(v){if(x.splice(v,1),ee){de.values.splice(v,1),He.splice(v,1);let E=tt.splice(v,1)[0];pn(null,E.firstChild),E.remove()}me&&(se.splice(v,1),st.splice(v,1)[0].remove(),zt.splice(v,1),Bn.splice(v,1)),An("delSeries",v)}n.delSeries=ja;const Li=[!1,!1,!1,!1];function ji(v,E){if(v._show=v.show,v.show){let N=v.side%2,I=M[v.scale];I==null&&(v.scale=N?x[1].scale:b,I=M[v.scale]);let X=I.time;v.size=gt(v.size),v.space=gt(v.space),v.rotate=gt(v.rotate),Ts(v.incrs)&&v.incrs.forEach(oe=>{!Ls.has(oe)&&Ls.set(oe,Ap(oe))}),v.incrs=gt(v.incrs||(I.distr==2?v_:X?f==1?y_:b_:$s)),v.splits=gt(v.splits||(X&&I.distr==1?le:I.distr==3?Wc:I.distr==4?H_:z_)),v.stroke=gt(v.stroke),v.grid.stroke=gt(v.grid.stroke),v.ticks.stroke=gt(v.ticks.stroke),v.border.stroke=gt(v.border.stroke);let Z=v.values;v.values=Ts(Z)&&!Ts(Z[0])?gt(Z):X?Ts(Z)?Ed(K,wd(Z,G)):yd(Z)?T_(K,Z):Z||J:Z||B_,v.filter=gt(v.filter||(I.distr>=3&&I.log==10?W_:I.distr==3&&I.log==2?X_:Ep)),v.font=zd(v.font),v.labelFont=zd(v.labelFont),v._size=v.size(n,null,E,0),v._space=v._rotate=v._incrs=v._found=v._splits=v._values=null,v._size>0&&(Li[E]=!0,v._el=hi(R0,u))}}function Qi(v,E,N,I){let[X,Z,oe,fe]=N,ye=E%2,Ne=0;return ye==0&&(fe||Z)&&(Ne=E==0&&!X||E==2&&!oe?vn(Rd.size/3):0),ye==1&&(X||oe)&&(Ne=E==1&&!Z||E==3&&!fe?vn(Ld.size/2):0),Ne}const sa=n.padding=(i.padding||[Qi,Qi,Qi,Qi]).map(v=>gt(St(v,Qi))),xi=n._padding=sa.map((v,E)=>v(n,E,Li,0));let Kt,Qt=null,en=null;const Di=s==1?x[0].idxs:null;let Jn=null,ps=!1;function ra(v,E){if(e=v??[],n.data=n._data=e,s==2){Kt=0;for(let N=1;N<x.length;N++)Kt+=e[N][0].length}else{e.length==0&&(n.data=n._data=e=[[]]),Jn=e[0],Kt=Jn.length;let N=e;if(z==2){N=e.slice();let I=N[0]=Array(Kt);for(let X=0;X<Kt;X++)I[X]=X}n._data=e=N}if(at(!0),An("setData"),z==2&&(xe=!0),E!==!1){let N=D;N.auto(n,ps)?aa():_s(b,N.min,N.max),te=te||ue.left>=0,pe=!0,Nn()}}n.setData=ra;function aa(){ps=!0;let v,E;s==1&&(Kt>0?(Qt=Di[0]=0,en=Di[1]=Kt-1,v=e[0][Qt],E=e[0][en],z==2?(v=Qt,E=en):v==E&&(z==3?[v,E]=ml(v,v,D.log,!1):z==4?[v,E]=iu(v,v,D.log,!1):D.time?E=v+vn(86400/f):[v,E]=el(v,E,su,!0))):(Qt=Di[0]=v=null,en=Di[1]=E=null)),_s(b,v,E)}let rr,ms,ar,T,H,j,q,Y,Ee,Pe;function Te(v,E,N,I,X,Z){v??=id,N??=au,I??="butt",X??=id,Z??="round",v!=rr&&(d.strokeStyle=rr=v),X!=ms&&(d.fillStyle=ms=X),E!=ar&&(d.lineWidth=ar=E),Z!=H&&(d.lineJoin=H=Z),I!=j&&(d.lineCap=j=I),N!=T&&d.setLineDash(T=N)}function Le(v,E,N,I){E!=ms&&(d.fillStyle=ms=E),v!=q&&(d.font=q=v),N!=Y&&(d.textAlign=Y=N),I!=Ee&&(d.textBaseline=Ee=I)}function Be(v,E,N,I,X=0){if(I.length>0&&v.auto(n,ps)&&(E==null||E.min==null)){let Z=St(Qt,0),oe=St(en,I.length-1),fe=N.min==null?W0(I,Z,oe,X,v.distr==3):[N.min,N.max];v.min=Ci(v.min,N.min=fe[0]),v.max=$n(v.max,N.max=fe[1])}}const je={min:null,max:null};function ht(){for(let I in M){let X=M[I];W[I]==null&&(X.min==null||W[b]!=null&&X.auto(n,ps))&&(W[I]=je)}for(let I in M){let X=M[I];W[I]==null&&X.from!=null&&W[X.from]!=null&&(W[I]=je)}W[b]!=null&&at(!0);let v={};for(let I in W){let X=W[I];if(X!=null){let Z=v[I]=qr(M[I],Q0);if(X.min!=null)fn(Z,X);else if(I!=b||s==2)if(Kt==0&&Z.from==null){let oe=Z.range(n,null,null,I);Z.min=oe[0],Z.max=oe[1]}else Z.min=Ft,Z.max=-Ft}}if(Kt>0){x.forEach((I,X)=>{if(s==1){let Z=I.scale,oe=W[Z];if(oe==null)return;let fe=v[Z];if(X==0){let ye=fe.range(n,fe.min,fe.max,Z);fe.min=ye[0],fe.max=ye[1],Qt=Ai(fe.min,e[0]),en=Ai(fe.max,e[0]),en-Qt>1&&(e[0][Qt]<fe.min&&Qt++,e[0][en]>fe.max&&en--),I.min=Jn[Qt],I.max=Jn[en]}else I.show&&I.auto&&Be(fe,oe,I,e[X],I.sorted);I.idxs[0]=Qt,I.idxs[1]=en}else if(X>0&&I.show&&I.auto){let[Z,oe]=I.facets,fe=Z.scale,ye=oe.scale,[Ne,Ie]=e[X],Fe=v[fe],et=v[ye];Fe!=null&&Be(Fe,W[fe],Z,Ne,Z.sorted),et!=null&&Be(et,W[ye],oe,Ie,oe.sorted),I.min=oe.min,I.max=oe.max}});for(let I in v){let X=v[I],Z=W[I];if(X.from==null&&(Z==null||Z.min==null)){let oe=X.range(n,X.min==Ft?null:X.min,X.max==-Ft?null:X.max,I);X.min=oe[0],X.max=oe[1]}}}for(let I in v){let X=v[I];if(X.from!=null){let Z=v[X.from];if(Z.min==null)X.min=X.max=null;else{let oe=X.range(n,Z.min,Z.max,I);X.min=oe[0],X.max=oe[1]}}}let E={},N=!1;for(let I in v){let X=v[I],Z=M[I];if(Z.min!=X.min||Z.max!=X.max){Z.min=X.min,Z.max=X.max;let oe=Z.distr;Z._min=oe==3?hs(Z.min):oe==4?Xl(Z.min,Z.asinh):oe==100?Z.fwd(Z.min):Z.min,Z._max=oe==3?hs(Z.max):oe==4?Xl(Z.max,Z.asinh):oe==100?Z.fwd(Z.max):Z.max,E[I]=N=!0}}if(N){x.forEach((I,X)=>{s==2?X>0&&E.y&&(I._paths=null):E[I.scale]&&(I._paths=null)});for(let I in E)xe=!0,An("setScale",I);me&&ue.left>=0&&(te=pe=!0)}for(let I in W)W[I]=null}function ke(v){let E=Vc(Qt-1,0,Kt-1),N=Vc(en+1,0,Kt-1);for(;v[E]==null&&E>0;)E--;for(;v[N]==null&&N<Kt-1;)N++;return[E,N]}function ut(){if(Kt>0){let v=x.some(E=>E._focus)&&Pe!=Oe.alpha;v&&(d.globalAlpha=Pe=Oe.alpha),x.forEach((E,N)=>{if(N>0&&E.show&&(qt(N,!1),qt(N,!0),E._paths==null)){let I=Pe;Pe!=E.alpha&&(d.globalAlpha=Pe=E.alpha);let X=s==2?[0,e[N][0].length-1]:ke(e[N]);E._paths=E.paths(n,N,X[0],X[1]),Pe!=I&&(d.globalAlpha=Pe=I)}}),x.forEach((E,N)=>{if(N>0&&E.show){let I=Pe;Pe!=E.alpha&&(d.globalAlpha=Pe=E.alpha),E._paths!=null&&Rt(N,!1);{let X=E._paths!=null?E._paths.gaps:null,Z=E.points.show(n,N,Qt,en,X),oe=E.points.filter(n,N,Z,X);(Z||oe)&&(E.points._paths=E.points.paths(n,N,Qt,en,oe),Rt(N,!0))}Pe!=I&&(d.globalAlpha=Pe=I),An("drawSeries",N)}}),v&&(d.globalAlpha=Pe=1)}}function qt(v,E){let N=E?x[v].points:x[v];N._stroke=N.stroke(n,v),N._fill=N.fill(n,v)}function Rt(v,E){let N=E?x[v].points:x[v],{stroke:I,fill:X,clip:Z,flags:oe,_stroke:fe=N._stroke,_fill:ye=N._fill,_width:Ne=N.width}=N._paths;Ne=Ot(Ne*wt,3);let Ie=null,Fe=Ne%2/2;E&&ye==null&&(ye=Ne>0?"#fff":fe);let et=N.pxAlign==1&&Fe>0;if(et&&d.translate(Fe,Fe),!E){let Mt=P-Ne/2,yt=S-Ne/2,dt=$+Ne,Ye=he+Ne;Ie=new Path2D,Ie.rect(Mt,yt,dt,Ye)}E?Ue(fe,Ne,N.dash,N.cap,ye,I,X,oe,Z):Ct(v,fe,Ne,N.dash,N.cap,ye,I,X,oe,Ie,Z),et&&d.translate(-Fe,-Fe)}function Ct(v,E,N,I,X,Z,oe,fe,ye,Ne,Ie){let Fe=!1;ye!=0&&C.forEach((et,Mt)=>{if(et.series[0]==v){let yt=x[et.series[1]],dt=e[et.series[1]],Ye=(yt._paths||Ca).band;Ts(Ye)&&(Ye=et.dir==1?Ye[0]:Ye[1]);let We,Vt=null;yt.show&&Ye&&$0(dt,Qt,en)?(Vt=et.fill(n,Mt)||Z,We=yt._paths.clip):Ye=null,Ue(E,N,I,X,Vt,oe,fe,ye,Ne,Ie,We,Ye),Fe=!0}}),Fe||Ue(E,N,I,X,Z,oe,fe,ye,Ne,Ie)}const mn=Yr|$c;function Ue(v,E,N,I,X,Z,oe,fe,ye,Ne,Ie,Fe){Te(v,E,N,I,X),(ye||Ne||Fe)&&(d.save(),ye&&d.clip(ye),Ne&&d.clip(Ne)),Fe?(fe&mn)==mn?(d.clip(Fe),Ie&&d.clip(Ie),mt(X,oe),ln(v,Z,E)):fe&$c?(mt(X,oe),d.clip(Fe),ln(v,Z,E)):fe&Yr&&(d.save(),d.clip(Fe),Ie&&d.clip(Ie),mt(X,oe),d.restore(),ln(v,Z,E)):(mt(X,oe),ln(v,Z,E)),(ye||Ne||Fe)&&d.restore()}function ln(v,E,N){N>0&&(E instanceof Map?E.forEach((I,X)=>{d.strokeStyle=rr=X,d.stroke(I)}):E!=null&&v&&d.stroke(E))}function mt(v,E){E instanceof Map?E.forEach((N,I)=>{d.fillStyle=ms=I,d.fill(N)}):E!=null&&v&&d.fill(E)}function es(v,E,N,I){let X=A[v],Z;if(I<=0)Z=[0,0];else{let oe=X._space=X.space(n,v,E,N,I),fe=X._incrs=X.incrs(n,v,E,N,I,oe);Z=fv(E,N,fe,I,oe)}return X._found=Z}function cn(v,E,N,I,X,Z,oe,fe,ye,Ne){let Ie=oe%2/2;y==1&&d.translate(Ie,Ie),Te(fe,oe,ye,Ne,fe),d.beginPath();let Fe,et,Mt,yt,dt=X+(I==0||I==3?-Z:Z);N==0?(et=X,yt=dt):(Fe=X,Mt=dt);for(let Ye=0;Ye<v.length;Ye++)E[Ye]!=null&&(N==0?Fe=Mt=v[Ye]:et=yt=v[Ye],d.moveTo(Fe,et),d.lineTo(Mt,yt));d.stroke(),y==1&&d.translate(-Ie,-Ie)}function or(v){let E=!0;return A.forEach((N,I)=>{if(!N.show)return;let X=M[N.scale];if(X.min==null){N._show&&(E=!1,N._show=!1,at(!1));return}else N._show||(E=!1,N._show=!0,at(!1));let Z=N.side,oe=Z%2,{min:fe,max:ye}=X,[Ne,Ie]=es(I,fe,ye,oe==0?k:Ce);if(Ie==0)return;let Fe=X.distr==2,et=N._splits=N.splits(n,I,fe,ye,Ne,Ie,Fe),Mt=X.distr==2?et.map(We=>Jn[We]):et,yt=X.distr==2?Jn[et[1]]-Jn[et[0]]:Ne,dt=N._values=N.values(n,N.filter(n,Mt,I,Ie,yt),I,Ie,yt);N._rotate=Z==2?N.rotate(n,dt,I,Ie):0;let Ye=N._size;N._size=ui(N.size(n,dt,I,v)),Ye!=null&&N._size!=Ye&&(E=!1)}),E}function Ni(v){let E=!0;return sa.forEach((N,I)=>{let X=N(n,I,Li,v);X!=xi[I]&&(E=!1),xi[I]=X}),E}function ts(){for(let v=0;v<A.length;v++){let E=A[v];if(!E.show||!E._show)continue;let N=E.side,I=N%2,X,Z,oe=E.stroke(n,v),fe=N==0||N==3?-1:1,[ye,Ne]=E._found;if(E.label!=null){let Gn=E.labelGap*fe,ei=vn((E._lpos+Gn)*wt);Le(E.labelFont[0],oe,"center",N==2?ua:nd),d.save(),I==1?(X=Z=0,d.translate(ei,vn(S+he/2)),d.rotate((N==3?-Go:Go)/2)):(X=vn(P+$/2),Z=ei);let Bs=bp(E.label)?E.label(n,v,ye,Ne):E.label;d.fillText(Bs,X,Z),d.restore()}if(Ne==0)continue;let Ie=M[E.scale],Fe=I==0?$:he,et=I==0?P:S,Mt=E._splits,yt=Ie.distr==2?Mt.map(Gn=>Jn[Gn]):Mt,dt=Ie.distr==2?Jn[Mt[1]]-Jn[Mt[0]]:ye,Ye=E.ticks,We=E.border,Vt=Ye.show?Ye.size:0,Jt=vn(Vt*wt),Rn=vn((E.alignTo==2?E._size-Vt-E.gap:E.gap)*wt),It=E._rotate*-Go/180,jt=p(E._pos*wt),jn=(Jt+Rn)*fe,Hn=jt+jn;Z=I==0?Hn:0,X=I==1?Hn:0;let oi=E.font[0],yi=E.align==1?mr:E.align==2?Gl:It>0?mr:It<0?Gl:I==0?"center":N==3?Gl:mr,Fi=It||I==1?"middle":N==2?ua:nd;Le(oi,oe,yi,Fi);let Qn=E.font[1]*E.lineGap,li=Mt.map(Gn=>p(o(Gn,Ie,Fe,et))),Si=E._values;for(let Gn=0;Gn<Si.length;Gn++){let ei=Si[Gn];if(ei!=null){I==0?X=li[Gn]:Z=li[Gn],ei=""+ei;let Bs=ei.indexOf(`
`)==-1?[ei]:ei.split(/\n/gm);for(let Vn=0;Vn<Bs.length;Vn++){let Qu=Bs[Vn];It?(d.save(),d.translate(X,Z+Vn*Qn),d.rotate(It),d.fillText(Qu,0,0),d.restore()):d.fillText(Qu,X,Z+Vn*Qn)}}}Ye.show&&cn(li,Ye.filter(n,yt,v,Ne,dt),I,N,jt,Jt,Ot(Ye.width*wt,3),Ye.stroke(n,v),Ye.dash,Ye.cap);let Oi=E.grid;Oi.show&&cn(li,Oi.filter(n,yt,v,Ne,dt),I,I==0?2:1,I==0?S:P,I==0?he:$,Ot(Oi.width*wt,3),Oi.stroke(n,v),Oi.dash,Oi.cap),We.show&&cn([jt],[1],I==0?1:0,I==0?1:2,I==1?S:P,I==1?he:$,Ot(We.width*wt,3),We.stroke(n,v),We.dash,We.cap)}An("drawAxes")}function at(v){x.forEach((E,N)=>{N>0&&(E._paths=null,v&&(s==1?(E.min=null,E.max=null):E.facets.forEach(I=>{I.min=null,I.max=null})))})}let Zt=!1,zn=!1,Pt=[];function hn(){zn=!1;for(let v=0;v<Pt.length;v++)An(...Pt[v]);Pt.length=0}function Nn(){Zt||(a_(Uu),Zt=!0)}function Qa(v,E=!1){Zt=!0,zn=E,v(n),Uu(),E&&Pt.length>0&&queueMicrotask(hn)}n.batch=Qa;function Uu(){if(ae&&(ht(),ae=!1),xe&&(we(),xe=!1),_e){if(Wt(m,mr,qe),Wt(m,ua,nt),Wt(m,Ma,k),Wt(m,ba,Ce),Wt(_,mr,qe),Wt(_,ua,nt),Wt(_,Ma,k),Wt(_,ba,Ce),Wt(u,Ma,Yt),Wt(u,ba,on),h.width=vn(Yt*wt),h.height=vn(on*wt),A.forEach(({_el:v,_show:E,_size:N,_pos:I,side:X})=>{if(v!=null)if(E){let Z=X===3||X===0?N:0,oe=X%2==1;Wt(v,oe?"left":"top",I-Z),Wt(v,oe?"width":"height",N),Wt(v,oe?"top":"left",oe?nt:qe),Wt(v,oe?"height":"width",oe?Ce:k),Hc(v,qs)}else ii(v,qs)}),rr=ms=ar=H=j=q=Y=Ee=T=null,Pe=1,ca(!0),qe!=be||nt!=Ut||k!=ze||Ce!=$e){at(!1);let v=k/ze,E=Ce/$e;if(me&&!te&&ue.left>=0){ue.left*=v,ue.top*=E,lr&&ki(lr,vn(ue.left),0,k,Ce),cr&&ki(cr,0,vn(ue.top),k,Ce);for(let N=0;N<st.length;N++){let I=st[N];I!=null&&(zt[N]*=v,Bn[N]*=E,ki(I,ui(zt[N]),ui(Bn[N]),k,Ce))}}if(Gt.show&&!ie&&Gt.left>=0&&Gt.width>0){Gt.left*=v,Gt.width*=v,Gt.top*=E,Gt.height*=E;for(let N in Ul)Wt(dr,N,Gt[N])}be=qe,Ut=nt,ze=k,$e=Ce}An("setSize"),_e=!1}Yt>0&&on>0&&(d.clearRect(0,0,h.width,h.height),An("drawClear"),w.forEach(v=>v()),An("draw")),Gt.show&&ie&&(eo(Gt),ie=!1),me&&te&&(ks(null,!0,!1),te=!1),de.show&&de.live&&pe&&(Nl(),pe=!1),l||(l=!0,n.status=1,An("ready")),ps=!1,Zt=!1}n.redraw=(v,E)=>{xe=E||!1,v!==!1?_s(b,D.min,D.max):Nn()};function Pl(v,E){let N=M[v];if(N.from==null){if(Kt==0){let I=N.range(n,E.min,E.max,v);E.min=I[0],E.max=I[1]}if(E.min>E.max){let I=E.min;E.min=E.max,E.max=I}if(Kt>1&&E.min!=null&&E.max!=null&&E.max-E.min<1e-16)return;v==b&&N.distr==2&&Kt>0&&(E.min=Ai(E.min,e[0]),E.max=Ai(E.max,e[0]),E.min==E.max&&E.max++),W[v]=E,ae=!0,Nn()}}n.setScale=Pl;let Ll,Dl,lr,cr,Fu,Ou,hr,ur,ku,Bu,Ht,$t,gs=!1;const Pn=ue.drag;let En=Pn.x,Tn=Pn.y;me&&(ue.x&&(Ll=hi(P0,_)),ue.y&&(Dl=hi(L0,_)),D.ori==0?(lr=Ll,cr=Dl):(lr=Dl,cr=Ll),Ht=ue.left,$t=ue.top);const Gt=n.select=fn({show:!0,over:!0,left:0,width:0,top:0,height:0},i.select),dr=Gt.show?hi(C0,Gt.over?_:m):null;function eo(v,E){if(Gt.show){for(let N in v)Gt[N]=v[N],N in Ul&&Wt(dr,N,v[N]);E!==!1&&An("setSelect")}}n.setSelect=eo;function Cg(v){if(x[v].show)ee&&Hc(tt[v],qs);else if(ee&&ii(tt[v],qs),me){let N=Re?st[0]:st[v];N!=null&&ki(N,-10,-10,k,Ce)}}function _s(v,E,N){Pl(v,{min:E,max:N})}function Ii(v,E,N,I){E.focus!=null&&Ig(v),E.show!=null&&x.forEach((X,Z)=>{Z>0&&(v==Z||v==null)&&(X.show=E.show,Cg(Z),s==2?(_s(X.facets[0].scale,null,null),_s(X.facets[1].scale,null,null)):_s(X.scale,null,null),Nn())}),N!==!1&&An("setSeries",v,E),I&&ha("setSeries",n,v,E)}n.setSeries=Ii;function Pg(v,E){fn(C[v],E)}function Lg(v,E){v.fill=gt(v.fill||null),v.dir=St(v.dir,-1),E=E??C.length,C.splice(E,0,v)}function Dg(v){v==null?C.length=0:C.splice(v,1)}n.addBand=Lg,n.setBand=Pg,n.delBand=Dg;function Ng(v,E){x[v].alpha=E,me&&st[v]!=null&&(st[v].style.opacity=E),ee&&tt[v]&&(tt[v].style.opacity=E)}let ns,vs,Os;const fr={focus:!0};function Ig(v){if(v!=Os){let E=v==null,N=Oe.alpha!=1;x.forEach((I,X)=>{if(s==1||X>0){let Z=E||X==0||X==v;I._focus=E?null:Z,N&&Ng(X,Z?1:Oe.alpha)}}),Os=v,N&&Nn()}}ee&&Ze&&vt(ad,Ae,v=>{ue._lock||(Ke(v),Os!=null&&Ii(null,fr,!0,un.setSeries))});function Ui(v,E,N){let I=M[E];N&&(v=v/wt-(I.ori==1?nt:qe));let X=k;I.ori==1&&(X=Ce,v=X-v),I.dir==-1&&(v=X-v);let Z=I._min,oe=I._max,fe=v/X,ye=Z+(oe-Z)*fe,Ne=I.distr;return Ne==3?Xr(10,ye):Ne==4?Y0(ye,I.asinh):Ne==100?I.bwd(ye):ye}function Ug(v,E){let N=Ui(v,b,E);return Ai(N,e[0],Qt,en)}n.valToIdx=v=>Ai(v,e[0]),n.posToIdx=Ug,n.posToVal=Ui,n.valToPos=(v,E,N)=>M[E].ori==0?r(v,M[E],N?$:k,N?P:0):a(v,M[E],N?he:Ce,N?S:0),n.setCursor=(v,E,N)=>{Ht=v.left,$t=v.top,ks(null,E,N)};function zu(v,E){Wt(dr,mr,Gt.left=v),Wt(dr,Ma,Gt.width=E)}function Hu(v,E){Wt(dr,ua,Gt.top=v),Wt(dr,ba,Gt.height=E)}let oa=D.ori==0?zu:Hu,la=D.ori==1?zu:Hu;function Fg(){if(ee&&de.live)for(let v=s==2?1:0;v<x.length;v++){if(v==0&&rt)continue;let E=de.values[v],N=0;for(let I in E)He[v][N++].firstChild.nodeValue=E[I]}}function Nl(v,E){if(v!=null&&(v.idxs?v.idxs.forEach((N,I)=>{se[I]=N}):j0(v.idx)||se.fill(v.idx),de.idx=se[0]),ee&&de.live){for(let N=0;N<x.length;N++)(N>0||s==1&&!rt)&&Og(N,se[N]);Fg()}pe=!1,E!==!1&&An("setLegend")}n.setLegend=Nl;function Og(v,E){let N=x[v],I=v==0&&z==2?Jn:e[v],X;rt?X=N.values(n,v,E)??Qe:(X=N.value(n,E==null?null:I[E],v,E),X=X==null?Qe:{_:X}),de.values[v]=X}function ks(v,E,N){ku=Ht,Bu=$t,[Ht,$t]=ue.move(n,Ht,$t),ue.left=Ht,ue.top=$t,me&&(lr&&ki(lr,vn(Ht),0,k,Ce),cr&&ki(cr,0,vn($t),k,Ce));let I,X=Qt>en;ns=Ft,vs=null;let Z=D.ori==0?k:Ce,oe=D.ori==1?k:Ce;if(Ht<0||Kt==0||X){I=ue.idx=null;for(let fe=0;fe<x.length;fe++){let ye=st[fe];ye!=null&&ki(ye,-10,-10,k,Ce)}Ze&&Ii(null,fr,!0,v==null&&un.setSeries),de.live&&(se.fill(I),pe=!0)}else{let fe,ye,Ne;s==1&&(fe=D.ori==0?Ht:$t,ye=Ui(fe,b),I=ue.idx=Ai(ye,e[0],Qt,en),Ne=V(e[0][I],D,Z,0));let Ie=-10,Fe=-10,et=0,Mt=0,yt=!0,dt="",Ye="";for(let We=s==2?1:0;We<x.length;We++){let Vt=x[We],Jt=se[We],Rn=Jt==null?null:s==1?e[We][Jt]:e[We][1][Jt],It=ue.dataIdx(n,We,I,ye),jt=It==null?null:s==1?e[We][It]:e[We][1][It];if(pe=pe||jt!=Rn||It!=Jt,se[We]=It,We>0&&Vt.show){let jn=It==null?-10:It==I?Ne:V(s==1?e[0][It]:e[We][0][It],D,Z,0),Hn=jt==null?-10:U(jt,s==1?M[Vt.scale]:M[Vt.facets[1].scale],oe,0);if(Ze&&jt!=null){let oi=D.ori==1?Ht:$t,yi=xn(Oe.dist(n,We,It,Hn,oi));if(yi<ns){let Fi=Oe.bias;if(Fi!=0){let Qn=Ui(oi,Vt.scale),li=jt>=0?1:-1,Si=Qn>=0?1:-1;Si==li&&(Si==1?Fi==1?jt>=Qn:jt<=Qn:Fi==1?jt<=Qn:jt>=Qn)&&(ns=yi,vs=We)}else ns=yi,vs=We}}if(pe||Re){let oi,yi;D.ori==0?(oi=jn,yi=Hn):(oi=Hn,yi=jn);let Fi,Qn,li,Si,Oi,Gn,ei=!0,Bs=ce.bbox;if(Bs!=null){ei=!1;let Vn=Bs(n,We);li=Vn.left,Si=Vn.top,Fi=Vn.width,Qn=Vn.height}else li=oi,Si=yi,Fi=Qn=ce.size(n,We);if(Gn=ce.fill(n,We),Oi=ce.stroke(n,We),Re)We==vs&&ns<=Oe.prox&&(Ie=li,Fe=Si,et=Fi,Mt=Qn,yt=ei,dt=Gn,Ye=Oi);else{let Vn=st[We];Vn!=null&&(zt[We]=li,Bn[We]=Si,fd(Vn,Fi,Qn,ei),ud(Vn,Gn,Oi),ki(Vn,ui(li),ui(Si),k,Ce))}}}}if(Re){let We=Oe.prox,Vt=Os==null?ns<=We:ns>We||vs!=Os;if(pe||Vt){let Jt=st[0];Jt!=null&&(zt[0]=Ie,Bn[0]=Fe,fd(Jt,et,Mt,yt),ud(Jt,dt,Ye),ki(Jt,ui(Ie),ui(Fe),k,Ce))}}}if(Gt.show&&gs)if(v!=null){let[fe,ye]=un.scales,[Ne,Ie]=un.match,[Fe,et]=v.cursor.sync.scales,Mt=v.cursor.drag;if(En=Mt._x,Tn=Mt._y,En||Tn){let{left:yt,top:dt,width:Ye,height:We}=v.select,Vt=v.scales[Fe].ori,Jt=v.posToVal,Rn,It,jt,jn,Hn,oi=fe!=null&&Ne(fe,Fe),yi=ye!=null&&Ie(ye,et);oi&&En?(Vt==0?(Rn=yt,It=Ye):(Rn=dt,It=We),jt=M[fe],jn=V(Jt(Rn,Fe),jt,Z,0),Hn=V(Jt(Rn+It,Fe),jt,Z,0),oa(Ci(jn,Hn),xn(Hn-jn))):oa(0,Z),yi&&Tn?(Vt==1?(Rn=yt,It=Ye):(Rn=dt,It=We),jt=M[ye],jn=U(Jt(Rn,et),jt,oe,0),Hn=U(Jt(Rn+It,et),jt,oe,0),la(Ci(jn,Hn),xn(Hn-jn))):la(0,oe)}else Fl()}else{let fe=xn(ku-Fu),ye=xn(Bu-Ou);if(D.ori==1){let et=fe;fe=ye,ye=et}En=Pn.x&&fe>=Pn.dist,Tn=Pn.y&&ye>=Pn.dist;let Ne=Pn.uni;Ne!=null?En&&Tn&&(En=fe>=Ne,Tn=ye>=Ne,!En&&!Tn&&(ye>fe?Tn=!0:En=!0)):Pn.x&&Pn.y&&(En||Tn)&&(En=Tn=!0);let Ie,Fe;En&&(D.ori==0?(Ie=hr,Fe=Ht):(Ie=ur,Fe=$t),oa(Ci(Ie,Fe),xn(Fe-Ie)),Tn||la(0,oe)),Tn&&(D.ori==1?(Ie=hr,Fe=Ht):(Ie=ur,Fe=$t),la(Ci(Ie,Fe),xn(Fe-Ie)),En||oa(0,Z)),!En&&!Tn&&(oa(0,0),la(0,0))}if(Pn._x=En,Pn._y=Tn,v==null){if(N){if(ju!=null){let[fe,ye]=un.scales;un.values[0]=fe!=null?Ui(D.ori==0?Ht:$t,fe):null,un.values[1]=ye!=null?Ui(D.ori==1?Ht:$t,ye):null}ha(Vl,n,Ht,$t,k,Ce,I)}if(Ze){let fe=N&&un.setSeries,ye=Oe.prox;Os==null?ns<=ye&&Ii(vs,fr,!0,fe):ns>ye?Ii(null,fr,!0,fe):vs!=Os&&Ii(vs,fr,!0,fe)}}pe&&(de.idx=I,Nl()),E!==!1&&An("setCursor")}let xs=null;Object.defineProperty(n,"rect",{get(){return xs==null&&ca(!1),xs}});function ca(v=!1){v?xs=null:(xs=_.getBoundingClientRect(),An("syncRect",xs))}function Gu(v,E,N,I,X,Z,oe){ue._lock||gs&&v!=null&&v.movementX==0&&v.movementY==0||(Il(v,E,N,I,X,Z,oe,!1,v!=null),v!=null?ks(null,!0,!0):ks(E,!0,!1))}function Il(v,E,N,I,X,Z,oe,fe,ye){if(xs==null&&ca(!1),Ke(v),v!=null)N=v.clientX-xs.left,I=v.clientY-xs.top;else{if(N<0||I<0){Ht=-10,$t=-10;return}let[Ne,Ie]=un.scales,Fe=E.cursor.sync,[et,Mt]=Fe.values,[yt,dt]=Fe.scales,[Ye,We]=un.match,Vt=E.axes[0].side%2==1,Jt=D.ori==0?k:Ce,Rn=D.ori==1?k:Ce,It=Vt?Z:X,jt=Vt?X:Z,jn=Vt?I:N,Hn=Vt?N:I;if(yt!=null?N=Ye(Ne,yt)?o(et,M[Ne],Jt,0):-10:N=Jt*(jn/It),dt!=null?I=We(Ie,dt)?o(Mt,M[Ie],Rn,0):-10:I=Rn*(Hn/jt),D.ori==1){let oi=N;N=I,I=oi}}ye&&(E==null||E.cursor.event.type==Vl)&&((N<=1||N>=k-1)&&(N=Xs(N,k)),(I<=1||I>=Ce-1)&&(I=Xs(I,Ce))),fe?(Fu=N,Ou=I,[hr,ur]=ue.move(n,N,I)):(Ht=N,$t=I)}const Ul={width:0,height:0,left:0,top:0};function Fl(){eo(Ul,!1)}let Vu,Wu,Xu,$u;function qu(v,E,N,I,X,Z,oe){gs=!0,En=Tn=Pn._x=Pn._y=!1,Il(v,E,N,I,X,Z,oe,!0,!1),v!=null&&(vt(Wl,Bc,Yu,!1),ha(sd,n,hr,ur,k,Ce,null));let{left:fe,top:ye,width:Ne,height:Ie}=Gt;Vu=fe,Wu=ye,Xu=Ne,$u=Ie}function Yu(v,E,N,I,X,Z,oe){gs=Pn._x=Pn._y=!1,Il(v,E,N,I,X,Z,oe,!1,!0);let{left:fe,top:ye,width:Ne,height:Ie}=Gt,Fe=Ne>0||Ie>0,et=Vu!=fe||Wu!=ye||Xu!=Ne||$u!=Ie;if(Fe&&et&&eo(Gt),Pn.setScale&&Fe&&et){let Mt=fe,yt=Ne,dt=ye,Ye=Ie;if(D.ori==1&&(Mt=ye,yt=Ie,dt=fe,Ye=Ne),En&&_s(b,Ui(Mt,b),Ui(Mt+yt,b)),Tn)for(let We in M){let Vt=M[We];We!=b&&Vt.from==null&&Vt.min!=Ft&&_s(We,Ui(dt+Ye,We),Ui(dt,We))}Fl()}else ue.lock&&(ue._lock=!ue._lock,ks(E,!0,v!=null));v!=null&&(pn(Wl,Bc),ha(Wl,n,Ht,$t,k,Ce,null))}function kg(v,E,N,I,X,Z,oe){if(ue._lock)return;Ke(v);let fe=gs;if(gs){let ye=!0,Ne=!0,Ie=10,Fe,et;D.ori==0?(Fe=En,et=Tn):(Fe=Tn,et=En),Fe&&et&&(ye=Ht<=Ie||Ht>=k-Ie,Ne=$t<=Ie||$t>=Ce-Ie),Fe&&ye&&(Ht=Ht<hr?0:k),et&&Ne&&($t=$t<ur?0:Ce),ks(null,!0,!0),gs=!1}Ht=-10,$t=-10,se.fill(null),ks(null,!0,!0),fe&&(gs=fe)}function Ku(v,E,N,I,X,Z,oe){ue._lock||(Ke(v),aa(),Fl(),v!=null&&ha(od,n,Ht,$t,k,Ce,null))}function Zu(){A.forEach(pv),O(n.width,n.height,!0)}Ys(Qo,kr,Zu);const pr={};pr.mousedown=qu,pr.mousemove=Gu,pr.mouseup=Yu,pr.dblclick=Ku,pr.setSeries=(v,E,N,I)=>{let X=un.match[2];N=X(n,E,N),N!=-1&&Ii(N,I,!0,!1)},me&&(vt(sd,_,qu),vt(Vl,_,Gu),vt(rd,_,v=>{Ke(v),ca(!1)}),vt(ad,_,kg),vt(od,_,Ku),qc.add(n),n.syncRect=ca);const to=n.hooks=i.hooks||{};function An(v,E,N){zn?Pt.push([v,E,N]):v in to&&to[v].forEach(I=>{I.call(null,n,E,N)})}(i.plugins||[]).forEach(v=>{for(let E in v.hooks)to[E]=(to[E]||[]).concat(v.hooks[E])});const Ju=(v,E,N)=>N,un=fn({key:null,setSeries:!1,filters:{pub:vd,sub:vd},scales:[b,x[1]?x[1].scale:null],match:[xd,xd,Ju],values:[null,null]},ue.sync);un.match.length==2&&un.match.push(Ju),ue.sync=un;const ju=un.key,Ol=qp(ju);function ha(v,E,N,I,X,Z,oe){un.filters.pub(v,E,N,I,X,Z,oe)&&Ol.pub(v,E,N,I,X,Z,oe)}Ol.sub(n);function Bg(v,E,N,I,X,Z,oe){un.filters.sub(v,E,N,I,X,Z,oe)&&pr[v](null,E,N,I,X,Z,oe)}n.pub=Bg;function zg(){Ol.unsub(n),qc.delete(n),wn.clear(),Gc(Qo,kr,Zu),c.remove(),Ae?.remove(),An("destroy")}n.destroy=zg;function kl(){An("init",i,e),ra(e||i.data,!1),W[b]?Pl(b,W[b]):aa(),ie=Gt.show&&(Gt.width>0||Gt.height>0),te=pe=!0,O(i.width,i.height)}return x.forEach(sr),A.forEach(ji),t?t instanceof HTMLElement?(t.appendChild(c),kl()):t(n,kl):kl(),n}On.assign=fn;On.fmtNum=ru;On.rangeNum=el;On.rangeLog=ml;On.rangeAsinh=iu;On.orient=tr;On.pxRatio=wt;On.join=r_;On.fmtDate=ou,On.tzDate=g_;On.sync=qp;{On.addGap=j_,On.clipGaps=vl;let i=On.paths={points:Qp};i.linear=tm,i.stepped=tv,i.bars=nv,i.spline=sv}class Ml{shown=new Map;observer;constructor(){this.observer=typeof IntersectionObserver>"u"?null:new IntersectionObserver(e=>{for(const t of e)this.shown.set(t.target,t.isIntersecting)})}watch(e){this.shown.set(e,!0),this.observer?.observe(e)}visible(e){return this.shown.get(e)??!0}}const mv=1e-6,gv=1e-12,pu=2**-52;function Kc(i,e,t=.05){if(i===null||e===null||!Number.isFinite(i)||!Number.isFinite(e))return[-1,1];i>e&&([i,e]=[e,i]);const n=Math.max(mv*Math.max(Math.abs(i),Math.abs(e)),gv),s=e-i;if(s<n){const r=i/2+e/2;return[r-n/2,r+n/2]}return[i-t*s,e+t*s]}function _v(i,e){return!Number.isFinite(i)||!(e>0)?null:Math.max(Math.abs(i)/e,pu/10)}function vv(i,e){const t=pu/10,n=i!==null&&Number.isFinite(i)&&i>0?Math.min(i,t):t,s=e!==null&&Number.isFinite(e)&&e>0?Math.max(e,1e-12):1e-12;return[10**Math.floor(Math.log10(n)),10**Math.ceil(Math.log10(s)+1e-9)]}const gr=i=>Number.isFinite(i)?Math.abs(i)>=1e4||Math.abs(i)<.001&&i!==0?i.toExponential(2):i.toPrecision(3):"—";function rm(i,e,t,n,s){let[r,a,o,l]=[1/0,-1/0,1/0,-1/0];const c=Math.min(n.length,s.length);for(let d=0;d<c;d++){const[u,m]=[n[d],s[d]??NaN];!Number.isFinite(u)||!Number.isFinite(m)||([r,a,o,l]=[Math.min(r,u),Math.max(a,u),Math.min(o,m),Math.max(l,m)])}const h=i?`${i}: `:"";return r>a?`${h}${R("alt.empty")}`:`${h}${R("alt.summary",{y:t,x:e,yLo:gr(o),yHi:gr(l),xLo:gr(r),xHi:gr(a),xNow:gr(n[c-1]??NaN),yNow:gr(s[c-1]??NaN)})}`}function am(i,e){i.getAttribute("role")!=="img"&&i.setAttribute("role","img"),i.getAttribute("aria-label")!==e&&i.setAttribute("aria-label",e)}function xv(i,e,t,n,s){const r=Math.max(Math.abs(n),1);return{energy:Math.max(Math.abs(i),t*r*s),j3:Math.max(Math.abs(e),t*s*Math.sqrt(r*s))}}const Kl=[{title:"plot.dE",axis:"|ΔE|/E_s",key:"dE",color:"#ffb347",drift:"energy"},{title:"plot.dJ3",axis:"|ΔJ₃|/J_s",key:"dJ3",color:"#7dff8a",drift:"j3"},{title:"plot.z",axis:"z [m]",key:"z",color:"#59c3ff",events:!0},{title:"plot.tension",axis:"T [N]",key:"tension",color:"#ff5d73",events:!0}];function yv(i){if(i===null||!Number.isFinite(i))return"";if(i===0)return"0";const e=Math.abs(i);return e>=.001&&e<1e4?String(+i.toPrecision(4)):i.toExponential(0)}class Sv{constructor(e,t=()=>{}){this.container=e;let n=0;const s={stroke:"#aab",grid:{stroke:"#2a2f3a"},ticks:{stroke:"#2a2f3a"},labelSize:16};for(const r of Kl){const a=document.createElement("div");a.className="plot",a.dataset.plot=r.key,e.appendChild(a),this.els.push(a),this.visibility.watch(a),this.shown.push({h:null,n:-1,t:NaN,ev:null});const o=[()=>t(performance.now()-n)];r.events&&o.push(c=>this.markEvents(c)),r.drift&&o.push(c=>this.markFloor(c));const l={title:R(r.title),width:this.width(),height:160,scales:{x:{time:!1,range:(c,h,d)=>Kc(h,d,0)},y:r.drift?{distr:3,log:10,range:(c,h,d)=>vv(h,d)}:{range:(c,h,d)=>Kc(h,d)}},legend:{show:!0,live:!1},hooks:{drawClear:[()=>{n=performance.now()}],draw:o},cursor:{show:!0,drag:{x:!1,y:!1}},series:[{label:"t [s]"},{label:r.axis,stroke:r.color,width:1.5}],axes:[{...s,label:R("plot.time")},{...s,label:r.axis,size:64,values:(c,h)=>h.map(yv)}]};this.charts.push(new On(l,[[],[]],a))}new ResizeObserver(()=>this.resize()).observe(e)}container;charts=[];els=[];visibility=new Ml;shown=[];events=[];width(){return Math.max(200,this.container.clientWidth-8)}resize(){for(const e of this.charts)e.setSize({width:this.width(),height:160})}markFloor(e){const{ctx:t,bbox:n}=e,s=Math.round(e.valToPos(pu,"y",!0))+.5;s>=n.top&&s<=n.top+n.height&&(t.save(),t.strokeStyle="#8a93a6",t.setLineDash([5,4]),t.beginPath(),t.moveTo(n.left,s),t.lineTo(n.left+n.width,s),t.stroke(),t.fillStyle="#8a93a6",t.font=`${Math.round(11*devicePixelRatio)}px system-ui, sans-serif`,t.textAlign="left",t.textBaseline="bottom",t.fillText(R("plot.floor"),n.left+4,s-3),t.restore())}markEvents(e){const[t,n]=[e.scales.x?.min,e.scales.x?.max];if(t===void 0||n===void 0||t===null||n===null)return;const{ctx:s,bbox:r}=e;s.save(),s.lineWidth=1,s.strokeStyle="#e0e0e0";for(const a of this.events){if(a.t<t||a.t>n)continue;const o=Math.round(e.valToPos(a.t,"x",!0))+.5;s.setLineDash(a.kind==="slack"?[4,3]:[]),s.beginPath(),s.moveTo(o,r.top),s.lineTo(o,r.top+r.height),s.stroke()}s.restore()}scales(){return Kl.map((e,t)=>{const n=this.charts[t]?.scales.y;return{key:e.key,distr:n?.distr??1,min:n?.min??null,max:n?.max??null}})}update(e,t=[],n={energy:1,j3:1}){this.events=t;const s=e.t.length,r=e.t[s-1]??NaN;Kl.forEach((a,o)=>{const l=this.charts[o],c=this.els[o],h=this.shown[o];if(l===void 0||c===void 0||h===void 0||!this.visibility.visible(c)||h.h===e&&h.n===s&&Object.is(h.t,r)&&h.ev===t)return;Object.assign(h,{h:e,n:s,t:r,ev:t});const d=e[a.key],u=a.drift,m=u?d.map(_=>_v(_,n[u])):d;l.setData([e.t,m]),am(l.root,rm(a.axis,R("plot.time"),a.axis,e.t,m))})}}function Ks(i,e=.1){let t=1/0,n=-1/0;for(const a of i)Number.isFinite(a)&&(a<t&&(t=a),a>n&&(n=a));if(t>n)return{lo:-1,hi:1};if(t===n)return{lo:t-Math.max(.5,Math.abs(t)*.1),hi:n+Math.max(.5,Math.abs(t)*.1)};const[s,r]=Kc(t,n,e);return{lo:s,hi:r}}function Mv(i,e,t){const n=Math.max(e===null?0:e-i,.2*t);return{lo:i-.15*n,hi:i+2.2*n}}function ao(i,e=Math.abs(i)){if(i===0)return"0";const t=Math.abs(i),n=Math.min(12,Math.max(3,Math.ceil(Math.log10(t/Math.max(e,1e-300)))+2));return t>=.01&&t<1e4?String(+i.toPrecision(n)):i.toExponential(Math.max(1,n-2))}class Pa{constructor(e,t,n,s,r=150){this.title=t,this.xLabel=n,this.yLabel=s,this.height=r;const a=document.createElement("div");a.className="plot curve";const o=document.createElement("div");o.className="curve-title",o.textContent=t,a.appendChild(o),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("aria-label",t),this.canvas.setAttribute("role","img"),a.appendChild(this.canvas),e.appendChild(a),this.ctx=this.canvas.getContext("2d")}title;xLabel;yLabel;height;canvas;ctx;draw(e,t,n,s,r={}){const a=t[0];am(this.canvas,rm(this.title,this.xLabel,this.yLabel,a?.x??[],a?.y??[]));const o=this.ctx;if(o===null)return;const l=Math.min(window.devicePixelRatio||1,2),c=Math.max(100,e),h=this.height;this.canvas.width!==Math.round(c*l)&&(this.canvas.width=Math.round(c*l),this.canvas.height=Math.round(h*l),this.canvas.style.width=`${c}px`,this.canvas.style.height=`${h}px`),o.setTransform(l,0,0,l,0,0),o.clearRect(0,0,c,h);const d=56,u=h-20,m=6,_=c-8,y=A=>d+(A-n.lo)/(n.hi-n.lo)*(_-d),p=A=>u-(A-s.lo)/(s.hi-s.lo)*(u-m);o.strokeStyle="#2a2f3a",o.strokeRect(d,m,_-d,u-m),o.fillStyle="#aab",o.font="11px system-ui, sans-serif",o.fillText(ao(s.hi,s.hi-s.lo),4,m+10),o.fillText(ao(s.lo,s.hi-s.lo),4,u),o.fillText(this.yLabel,4,(m+u)/2),o.fillText(ao(n.lo,n.hi-n.lo),d,h-4);const f=ao(n.hi,n.hi-n.lo);o.fillText(f,_-o.measureText(f).width,h-4),o.fillText(this.xLabel,(d+_)/2-10,h-4),o.save(),o.beginPath(),o.rect(d,m,_-d,u-m),o.clip(),r.hLine!==void 0&&r.hLine!==null&&this.line(o,d,p(r.hLine),_,p(r.hLine),"#ffb347"),r.vLine!==void 0&&r.vLine!==null&&this.line(o,y(r.vLine),m,y(r.vLine),u,"#888");for(const A of t){o.strokeStyle=A.color,o.lineWidth=1.5,o.beginPath();let M=!1;for(let C=0;C<A.x.length;C++){const b=A.x[C],g=A.y[C];if(!Number.isFinite(b)||!Number.isFinite(g)){M=!1;continue}const w=Math.max(-1e4,Math.min(1e4,p(g)));M?o.lineTo(y(b),w):o.moveTo(y(b),w),M=!0}o.stroke()}r.dot&&(o.fillStyle="#ff8c42",o.beginPath(),o.arc(y(r.dot[0]),p(r.dot[1]),3.5,0,2*Math.PI),o.fill()),o.restore();let x=m+12;o.textAlign="right";for(const A of t)A.label&&(o.fillStyle=A.color,o.fillText(`— ${A.label}`,_-4,x),x+=13);o.textAlign="left"}line(e,t,n,s,r,a){e.strokeStyle=a,e.lineWidth=1,e.setLineDash([4,3]),e.beginPath(),e.moveTo(t,n),e.lineTo(s,r),e.stroke(),e.setLineDash([])}}function bv(i){return Math.atan2(Math.hypot(i[0],i[1]),-i[2])}class wv{constructor(e){this.container=e,this.phase=new Pa(e,R("portrait.phase"),"z [m]","ż [m/s]"),this.potential=new Pa(e,R("portrait.veff"),"θ [rad]","E [J]"),this.em=new Pa(e,R("portrait.em"),"J₃ [kg m²/s]","E [J]");for(const t of[this.phase,this.potential,this.em])this.visibility.watch(t.canvas);this.note=document.createElement("p"),this.note.className="note",this.note.dataset.note="portraits",e.appendChild(this.note)}container;phase;potential;em;note;visibility=new Ml;setModel(e){const t=jh(e)??"";this.note.textContent!==t&&(this.note.textContent=t)}updateEM(e,t){if(!this.visibility.visible(this.em.canvas))return;const n=Math.max(200,this.container.clientWidth-8);if(e===null){this.em.draw(n,[],{lo:-1,hi:1},{lo:-1,hi:1});return}const s=e.top.energy,r=Ks([...e.boundary.j3.filter((o,l)=>(e.boundary.energy[l]??1/0)<2.6*s),t?.j3??0],.05),a={lo:e.bottom.energy-.15*s,hi:Math.max(2.6*s,(t?.energy??0)+.2*s)};this.em.draw(n,[{x:e.boundary.j3,y:e.boundary.energy,color:"#c9a0ff",label:R("portrait.emBoundary")}],r,a,{vLine:0,hLine:e.top.energy,dot:t?[t.j3,t.energy]:null})}update(e,t,n,s,r,a){const o=Math.max(200,this.container.clientWidth-8);if(this.visibility.visible(this.phase.canvas)){const c=t?[t.x[2],t.v[2]]:null,h=Ks(t?[...e.z,t.x[2]]:e.z),d=Ks(t?[...e.zdot,t.v[2]]:e.zdot);this.phase.draw(o,[{x:e.z,y:e.zdot,color:"#59c3ff",label:R("portrait.orbit")}],h,d,{dot:c})}if(!this.visibility.visible(this.potential.canvas))return;if(n===null||n.theta.length===0){this.potential.draw(o,[],{lo:0,hi:Math.PI},{lo:-1,hi:1});return}const l=Mv(n.minimum.v_eff,t?.energy??null,s*Math.max(Math.abs(r),1)*a);this.potential.draw(o,[{x:n.theta,y:n.v_eff,color:"#7dff8a",label:"V_eff(θ)"}],{lo:0,hi:Math.PI},l,{hLine:t?.energy??null,vLine:t?bv(t.x):null})}}async function Zc(i,e){const t=await fetch(i,e),n=await t.json();if(!t.ok){const s=n.detail;throw new Error(typeof s=="string"?s:`${i}: HTTP ${t.status}`)}return n}class om extends Error{}const Ev=1;let Vo=0;const Jc=[];async function oo(i,e,t=()=>!1){Vo>=Ev&&await new Promise(n=>Jc.push(n)),Vo++;try{if(t())throw new om(`${i}: no longer needed`);return await Zc(i,{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(e)})}finally{Vo--,Jc.shift()?.()}}function Tv(i){const e=Date.now()+i;return new Promise(t=>{const n=()=>Vo===0&&Jc.length===0||Date.now()>=e?t():setTimeout(n,20);n()})}const Zl=i=>e=>{e instanceof om||i(e)},lo=i=>i instanceof Error?i.message:String(i);class Av{constructor(e,t,n){this.store=e,this.reduced=t,this.explain=n}store;reduced;explain;veff=null;em=null;veffKey="";veffAt=-1/0;veffJ3=null;emKey="";exactEpoch=-1;reducedEpoch=-1;onFrames(){const e=this.store.status,t=this.store.trajectory[0],n=this.store.latest();if(!(e===null||t===void 0||n===null)){if(this.exactEpoch!==e.epoch&&this.fetchExact(e,t),this.reducedEpoch!==e.epoch&&this.fetchReduced(e,t),!o0(e.model)){[this.veff,this.em,this.veffKey,this.emKey]=[null,null,"",""];return}this.fetchEM(e,t),this.fetchPotential(e,n)}}fetchPotential(e,t){const n=e.params,s=`${e.epoch}:${n.length}:${n.mass}:${n.g}`,r=performance.now(),a=Math.abs(t.j3-(this.veffJ3??NaN))>.001*Math.max(Math.abs(t.j3),1e-9);s===this.veffKey&&!(a&&r-this.veffAt>1e3)||(s!==this.veffKey&&(this.veff=null),[this.veffKey,this.veffAt,this.veffJ3]=[s,r,t.j3],oo("api/effective_potential",{length:n.length,mass:n.mass,g:n.g,j3:t.j3},()=>this.veffKey!==s).then(o=>{this.veffKey===s&&(this.veff=o)},Zl(o=>this.explain(`V_eff: ${lo(o)}`))))}fetchEM(e,t){const n=e.params,s=`${n.length}:${n.mass}:${n.g}`;s!==this.emKey&&(this.emKey=s,this.em=null,n.g!==0&&oo("api/em_map",{length:n.length,mass:n.mass,g:n.g,x:t.x,v:t.v},()=>this.emKey!==s).then(r=>{this.emKey===s&&(this.em=r)},Zl(r=>this.explain(`energy–momentum map: ${lo(r)}`))))}fetchReduced(e,t){if(this.reducedEpoch=e.epoch,e.model!=="ideal"){this.reduced.setNote(jh(e.model)??R("note.reducedIdeal",{model:e.model}));return}this.reduced.setNote(null);const n=e.params,s=()=>this.store.status?.epoch!==e.epoch;oo("api/reduced",{length:n.length,mass:n.mass,g:n.g,x:t.x,v:t.v},s).then(r=>{s()||this.reduced.set(r)},Zl(r=>this.reduced.setNote(`reduced view: ${lo(r)}`)))}fetchExact(e,t){if(this.exactEpoch=e.epoch,e.model!=="ideal")return;const n=e.params;oo("api/exact",{length:n.length,mass:n.mass,g:n.g,x:t.x,v:t.v},()=>this.store.status?.epoch!==e.epoch).then(s=>{this.store.status?.epoch===e.epoch&&this.store.setExact(s)},s=>{this.store.status?.epoch===e.epoch&&this.store.setExact(null,lo(s))})}}const mu="187",Br={ROTATE:0,DOLLY:1,PAN:2},Fr={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},Rv=0,Hd=1,Cv=2,Wo=1,Pv=2,Ea=3,Ds=0,Zn=1,pi=2,zr=0,La=1,Gd=2,Vd=3,Wd=4,Lv=5,Ur=100,Dv=101,Nv=102,Iv=103,Uv=104,Fv=200,Ov=201,kv=202,Bv=203,lm=204,cm=205,zv=206,Hv=207,Gv=208,Vv=209,Wv=210,Xv=211,$v=212,qv=213,Yv=214,jc=0,Qc=1,eh=2,Fa=3,th=4,nh=5,ih=6,sh=7,hm=0,Kv=1,Zv=2,ds=0,um=1,dm=2,fm=3,pm=4,mm=5,gm=6,_m=7,vm=300,Kr=301,Oa=302,Jl=303,jl=304,rh=1e3,ls=1001,ah=1002,Dn=1003,Jv=1004,co=1005,Kn=1006,Ql=1007,Rs=1008,si=1009,xm=1010,ym=1011,ka=1012,gu=1013,Ki=1014,Wi=1015,Zi=1016,_u=1017,vu=1018,Zr=1020,Sm=35902,Mm=35899,bm=1021,wm=1022,Xi=1023,Ns=1026,Cs=1027,Em=1028,xu=1029,js=1030,yu=1031,Su=1033,Xo=33776,$o=33777,qo=33778,Yo=33779,oh=35840,lh=35841,ch=35842,hh=35843,uh=36196,dh=37492,fh=37496,ph=37488,mh=37489,nl=37490,gh=37491,_h=37808,vh=37809,xh=37810,yh=37811,Sh=37812,Mh=37813,bh=37814,wh=37815,Eh=37816,Th=37817,Ah=37818,Rh=37819,Ch=37820,Ph=37821,Lh=36492,Dh=36494,Nh=36495,Ih=36283,Uh=36284,il=36285,Fh=36286,jv=3200,Oh=0,Qv=1,As="",di="srgb",sl="srgb-linear",rl="linear",Lt="srgb",ec=7680,ex=519,tx=512,nx=513,ix=514,Tm=515,sx=516,rx=517,Am=518,Rm=519,Cm=35044,Xd="300 es",Pi=2e3,Ba=2001;function ax(i){for(let e=i.length-1;e>=0;--e)if(i[e]>=65535)return!0;return!1}function al(i){return document.createElementNS("http://www.w3.org/1999/xhtml",i)}function ox(){const i=al("canvas");return i.style.display="block",i}const $d={};function ol(...i){const e="THREE."+i.shift();console.log(e,...i)}function Pm(i){const e=i[0];if(typeof e=="string"&&e.startsWith("TSL:")){const t=i[1];t&&t.isStackTrace?i[0]+=" "+t.getLocation():i[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return i}function Je(...i){i=Pm(i);const e="THREE."+i.shift();{const t=i[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...i)}}function xt(...i){i=Pm(i);const e="THREE."+i.shift();{const t=i[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...i)}}function Ko(...i){const e=i.join(" ");e in $d||($d[e]=!0,Je(...i))}function lx(i,e,t){return new Promise(function(n,s){function r(){switch(i.clientWaitSync(e,i.SYNC_FLUSH_COMMANDS_BIT,0)){case i.WAIT_FAILED:s();break;case i.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:n()}}setTimeout(r,t)})}const cx={[jc]:jc,[eh]:ih,[th]:th,[Fa]:nh,[Qc]:Qc,[ih]:eh,[sh]:sh,[nh]:Fa};class Fs{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});const n=this._listeners;n[e]===void 0&&(n[e]=[]),n[e].indexOf(t)===-1&&n[e].push(t)}hasEventListener(e,t){const n=this._listeners;return n===void 0?!1:n[e]!==void 0&&n[e].indexOf(t)!==-1}removeEventListener(e,t){const n=this._listeners;if(n===void 0)return;const s=n[e];if(s!==void 0){const r=s.indexOf(t);r!==-1&&s.splice(r,1)}}dispatchEvent(e){const t=this._listeners;if(t===void 0)return;const n=t[e.type];if(n!==void 0){e.target=this;const s=n.slice(0);for(let r=0,a=s.length;r<a;r++)s[r].call(this,e);e.target=null}}}const In=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],Da=Math.PI/180,kh=180/Math.PI;function nr(){const i=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,n=Math.random()*4294967295|0;return(In[i&255]+In[i>>8&255]+In[i>>16&255]+In[i>>24&255]+"-"+In[e&255]+In[e>>8&255]+"-"+In[e>>16&15|64]+In[e>>24&255]+"-"+In[t&63|128]+In[t>>8&255]+"-"+In[t>>16&255]+In[t>>24&255]+In[n&255]+In[n>>8&255]+In[n>>16&255]+In[n>>24&255]).toLowerCase()}function pt(i,e,t){return Math.max(e,Math.min(t,i))}function hx(i,e){return(i%e+e)%e}function tc(i,e,t){return(1-t)*i+t*e}function ux(i){return Math.pow(2,Math.floor(Math.log(i)/Math.LN2))}function bl(i){switch(i.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function Lm(i,e){if(e.constructor===Float32Array)return i;const t=bl(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(i/t,-1)}function Dm(i,e){if(e.constructor===Float32Array)return i;const t=bl(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(i*t)}const dx={DEG2RAD:Da};class Xe{static{this.prototype.isVector2=!0}constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){const t=this.x,n=this.y,s=e.elements;return this.x=s[0]*t+s[3]*n+s[6],this.y=s[1]*t+s[4]*n+s[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=pt(this.x,e.x,t.x),this.y=pt(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=pt(this.x,e,t),this.y=pt(this.y,e,t),this}clampLength(e,t){const n=this.length();return this.divideScalar(n||1).multiplyScalar(pt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const n=this.dot(e)/t;return Math.acos(pt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,n=this.y-e.y;return t*t+n*n}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){const n=Math.cos(t),s=Math.sin(t),r=this.x-e.x,a=this.y-e.y;return this.x=r*n-a*s+e.x,this.y=r*s+a*n+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}}class Is{constructor(e=0,t=0,n=0,s=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=n,this._w=s}static slerpFlat(e,t,n,s,r,a,o){let l=n[s+0],c=n[s+1],h=n[s+2],d=n[s+3],u=r[a+0],m=r[a+1],_=r[a+2],y=r[a+3];if(d!==y||l!==u||c!==m||h!==_){let p=l*u+c*m+h*_+d*y;p<0&&(u=-u,m=-m,_=-_,y=-y,p=-p);let f=1-o;if(p<.9995){const x=Math.acos(p),A=Math.sin(x);f=Math.sin(f*x)/A,o=Math.sin(o*x)/A,l=l*f+u*o,c=c*f+m*o,h=h*f+_*o,d=d*f+y*o}else{l=l*f+u*o,c=c*f+m*o,h=h*f+_*o,d=d*f+y*o;const x=1/Math.sqrt(l*l+c*c+h*h+d*d);l*=x,c*=x,h*=x,d*=x}}e[t]=l,e[t+1]=c,e[t+2]=h,e[t+3]=d}static multiplyQuaternionsFlat(e,t,n,s,r,a){const o=n[s],l=n[s+1],c=n[s+2],h=n[s+3],d=r[a],u=r[a+1],m=r[a+2],_=r[a+3];return e[t]=o*_+h*d+l*m-c*u,e[t+1]=l*_+h*u+c*d-o*m,e[t+2]=c*_+h*m+o*u-l*d,e[t+3]=h*_-o*d-l*u-c*m,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,n,s){return this._x=e,this._y=t,this._z=n,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){const n=e._x,s=e._y,r=e._z,a=e._order,o=Math.cos,l=Math.sin,c=o(n/2),h=o(s/2),d=o(r/2),u=l(n/2),m=l(s/2),_=l(r/2);switch(a){case"XYZ":this._x=u*h*d+c*m*_,this._y=c*m*d-u*h*_,this._z=c*h*_+u*m*d,this._w=c*h*d-u*m*_;break;case"YXZ":this._x=u*h*d+c*m*_,this._y=c*m*d-u*h*_,this._z=c*h*_-u*m*d,this._w=c*h*d+u*m*_;break;case"ZXY":this._x=u*h*d-c*m*_,this._y=c*m*d+u*h*_,this._z=c*h*_+u*m*d,this._w=c*h*d-u*m*_;break;case"ZYX":this._x=u*h*d-c*m*_,this._y=c*m*d+u*h*_,this._z=c*h*_-u*m*d,this._w=c*h*d+u*m*_;break;case"YZX":this._x=u*h*d+c*m*_,this._y=c*m*d+u*h*_,this._z=c*h*_-u*m*d,this._w=c*h*d-u*m*_;break;case"XZY":this._x=u*h*d-c*m*_,this._y=c*m*d-u*h*_,this._z=c*h*_+u*m*d,this._w=c*h*d+u*m*_;break;default:Je("Quaternion: .setFromEuler() encountered an unknown order: "+a)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){const n=t/2,s=Math.sin(n);return this._x=e.x*s,this._y=e.y*s,this._z=e.z*s,this._w=Math.cos(n),this._onChangeCallback(),this}setFromRotationMatrix(e){const t=e.elements,n=t[0],s=t[4],r=t[8],a=t[1],o=t[5],l=t[9],c=t[2],h=t[6],d=t[10],u=n+o+d;if(u>0){const m=.5/Math.sqrt(u+1);this._w=.25/m,this._x=(h-l)*m,this._y=(r-c)*m,this._z=(a-s)*m}else if(n>o&&n>d){const m=2*Math.sqrt(1+n-o-d);this._w=(h-l)/m,this._x=.25*m,this._y=(s+a)/m,this._z=(r+c)/m}else if(o>d){const m=2*Math.sqrt(1+o-n-d);this._w=(r-c)/m,this._x=(s+a)/m,this._y=.25*m,this._z=(l+h)/m}else{const m=2*Math.sqrt(1+d-n-o);this._w=(a-s)/m,this._x=(r+c)/m,this._y=(l+h)/m,this._z=.25*m}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let n=e.dot(t)+1;return n<1e-8?(n=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=n):(this._x=0,this._y=-e.z,this._z=e.y,this._w=n)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=n),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(pt(this.dot(e),-1,1)))}rotateTowards(e,t){const n=this.angleTo(e);if(n===0)return this;const s=Math.min(1,t/n);return this.slerp(e,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){const n=e._x,s=e._y,r=e._z,a=e._w,o=t._x,l=t._y,c=t._z,h=t._w;return this._x=n*h+a*o+s*c-r*l,this._y=s*h+a*l+r*o-n*c,this._z=r*h+a*c+n*l-s*o,this._w=a*h-n*o-s*l-r*c,this._onChangeCallback(),this}slerp(e,t){let n=e._x,s=e._y,r=e._z,a=e._w,o=this.dot(e);o<0&&(n=-n,s=-s,r=-r,a=-a,o=-o);let l=1-t;if(o<.9995){const c=Math.acos(o),h=Math.sin(c);l=Math.sin(l*c)/h,t=Math.sin(t*c)/h,this._x=this._x*l+n*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+a*t,this._onChangeCallback()}else this._x=this._x*l+n*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+a*t,this.normalize();return this}slerpQuaternions(e,t,n){return this.copy(e).slerp(t,n)}random(){const e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),n=Math.random(),s=Math.sqrt(1-n),r=Math.sqrt(n);return this.set(s*Math.sin(e),s*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}}class B{static{this.prototype.isVector3=!0}constructor(e=0,t=0,n=0){this.x=e,this.y=t,this.z=n}set(e,t,n){return n===void 0&&(n=this.z),this.x=e,this.y=t,this.z=n,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(qd.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(qd.setFromAxisAngle(e,t))}applyMatrix3(e){const t=this.x,n=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[3]*n+r[6]*s,this.y=r[1]*t+r[4]*n+r[7]*s,this.z=r[2]*t+r[5]*n+r[8]*s,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){const t=this.x,n=this.y,s=this.z,r=e.elements,a=1/(r[3]*t+r[7]*n+r[11]*s+r[15]);return this.x=(r[0]*t+r[4]*n+r[8]*s+r[12])*a,this.y=(r[1]*t+r[5]*n+r[9]*s+r[13])*a,this.z=(r[2]*t+r[6]*n+r[10]*s+r[14])*a,this}applyQuaternion(e){const t=this.x,n=this.y,s=this.z,r=e.x,a=e.y,o=e.z,l=e.w,c=2*(a*s-o*n),h=2*(o*t-r*s),d=2*(r*n-a*t);return this.x=t+l*c+a*d-o*h,this.y=n+l*h+o*c-r*d,this.z=s+l*d+r*h-a*c,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){const t=this.x,n=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[4]*n+r[8]*s,this.y=r[1]*t+r[5]*n+r[9]*s,this.z=r[2]*t+r[6]*n+r[10]*s,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=pt(this.x,e.x,t.x),this.y=pt(this.y,e.y,t.y),this.z=pt(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=pt(this.x,e,t),this.y=pt(this.y,e,t),this.z=pt(this.z,e,t),this}clampLength(e,t){const n=this.length();return this.divideScalar(n||1).multiplyScalar(pt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){const n=e.x,s=e.y,r=e.z,a=t.x,o=t.y,l=t.z;return this.x=s*l-r*o,this.y=r*a-n*l,this.z=n*o-s*a,this}projectOnVector(e){const t=e.lengthSq();if(t===0)return this.set(0,0,0);const n=e.dot(this)/t;return this.copy(e).multiplyScalar(n)}projectOnPlane(e){return nc.copy(this).projectOnVector(e),this.sub(nc)}reflect(e){return this.sub(nc.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const n=this.dot(e)/t;return Math.acos(pt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,n=this.y-e.y,s=this.z-e.z;return t*t+n*n+s*s}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,n){const s=Math.sin(t)*e;return this.x=s*Math.sin(n),this.y=Math.cos(t)*e,this.z=s*Math.cos(n),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,n){return this.x=e*Math.sin(t),this.y=n,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){const t=this.setFromMatrixColumn(e,0).length(),n=this.setFromMatrixColumn(e,1).length(),s=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=n,this.z=s,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){const e=Math.random()*Math.PI*2,t=Math.random()*2-1,n=Math.sqrt(1-t*t);return this.x=n*Math.cos(e),this.y=t,this.z=n*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}}const nc=new B,qd=new Is;class it{static{this.prototype.isMatrix3=!0}constructor(e,t,n,s,r,a,o,l,c){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,n,s,r,a,o,l,c)}set(e,t,n,s,r,a,o,l,c){const h=this.elements;return h[0]=e,h[1]=s,h[2]=o,h[3]=t,h[4]=r,h[5]=l,h[6]=n,h[7]=a,h[8]=c,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){const t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],this}extractBasis(e,t,n){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),n.setFromMatrix3Column(this,2),this}setFromMatrix4(e){const t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const n=e.elements,s=t.elements,r=this.elements,a=n[0],o=n[3],l=n[6],c=n[1],h=n[4],d=n[7],u=n[2],m=n[5],_=n[8],y=s[0],p=s[3],f=s[6],x=s[1],A=s[4],M=s[7],C=s[2],b=s[5],g=s[8];return r[0]=a*y+o*x+l*C,r[3]=a*p+o*A+l*b,r[6]=a*f+o*M+l*g,r[1]=c*y+h*x+d*C,r[4]=c*p+h*A+d*b,r[7]=c*f+h*M+d*g,r[2]=u*y+m*x+_*C,r[5]=u*p+m*A+_*b,r[8]=u*f+m*M+_*g,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){const e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],h=e[8];return t*a*h-t*o*c-n*r*h+n*o*l+s*r*c-s*a*l}invert(){const e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],h=e[8],d=h*a-o*c,u=o*l-h*r,m=c*r-a*l,_=t*d+n*u+s*m;if(_===0)return this.set(0,0,0,0,0,0,0,0,0);const y=1/_;return e[0]=d*y,e[1]=(s*c-h*n)*y,e[2]=(o*n-s*a)*y,e[3]=u*y,e[4]=(h*t-s*l)*y,e[5]=(s*r-o*t)*y,e[6]=m*y,e[7]=(n*l-c*t)*y,e[8]=(a*t-n*r)*y,this}transpose(){let e;const t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){const t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,n,s,r,a,o){const l=Math.cos(r),c=Math.sin(r);return this.set(n*l,n*c,-n*(l*a+c*o)+a+e,-s*c,s*l,-s*(-c*a+l*o)+o+t,0,0,1),this}scale(e,t){return Ko("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(ic.makeScale(e,t)),this}rotate(e){return Ko("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(ic.makeRotation(-e)),this}translate(e,t){return Ko("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(ic.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){const t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,n,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){const t=this.elements,n=e.elements;for(let s=0;s<9;s++)if(t[s]!==n[s])return!1;return!0}fromArray(e,t=0){for(let n=0;n<9;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){const n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e}clone(){return new this.constructor().fromArray(this.elements)}}const ic=new it,Yd=new it().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Kd=new it().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function fx(){const i={enabled:!0,workingColorSpace:sl,spaces:{},convert:function(s,r,a){return this.enabled===!1||r===a||!r||!a||(this.spaces[r].transfer===Lt&&(s.r=fs(s.r),s.g=fs(s.g),s.b=fs(s.b)),this.spaces[r].primaries!==this.spaces[a].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[a].fromXYZ)),this.spaces[a].transfer===Lt&&(s.r=Hr(s.r),s.g=Hr(s.g),s.b=Hr(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===As?rl:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,a){return s.copy(this.spaces[a].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],n=[.3127,.329];return i.define({[sl]:{primaries:e,whitePoint:n,transfer:rl,toXYZ:Yd,fromXYZ:Kd,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:di},outputColorSpaceConfig:{drawingBufferColorSpace:di}},[di]:{primaries:e,whitePoint:n,transfer:Lt,toXYZ:Yd,fromXYZ:Kd,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:di}}}),i}const _t=fx();function fs(i){return i<.04045?i*.0773993808:Math.pow(i*.9478672986+.0521327014,2.4)}function Hr(i){return i<.0031308?i*12.92:1.055*Math.pow(i,.41666)-.055}let _r;class px{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let n;if(e instanceof HTMLCanvasElement)n=e;else{_r===void 0&&(_r=al("canvas")),_r.width=e.width,_r.height=e.height;const s=_r.getContext("2d");e instanceof ImageData?s.putImageData(e,0,0):s.drawImage(e,0,0,e.width,e.height),n=_r}return n.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){const t=al("canvas");t.width=e.width,t.height=e.height;const n=t.getContext("2d");n.drawImage(e,0,0,e.width,e.height);const s=n.getImageData(0,0,e.width,e.height),r=s.data;for(let a=0;a<r.length;a++)r[a]=fs(r[a]/255)*255;return n.putImageData(s,0,0),t}else if(e.data){const t=e.data.slice(0);for(let n=0;n<t.length;n++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[n]=Math.floor(fs(t[n]/255)*255):t[n]=fs(t[n]);return{data:t,width:e.width,height:e.height}}else return Je("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}}let mx=0;class Mu{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:mx++}),this.uuid=nr(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){const t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];const n={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let a=0,o=s.length;a<o;a++)s[a].isDataTexture?r.push(sc(s[a].image)):r.push(sc(s[a]))}else r=sc(s);n.url=r}return t||(e.images[this.uuid]=n),n}}function sc(i){return typeof HTMLImageElement<"u"&&i instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&i instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&i instanceof ImageBitmap?px.getDataURL(i):i.data?{data:Array.from(i.data),width:i.width,height:i.height,type:i.data.constructor.name}:(Je("Texture: Unable to serialize Texture."),{})}let gx=0;const rc=new B;class kn extends Fs{constructor(e=kn.DEFAULT_IMAGE,t=kn.DEFAULT_MAPPING,n=ls,s=ls,r=Kn,a=Rs,o=Xi,l=si,c=kn.DEFAULT_ANISOTROPY,h=As){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:gx++}),this.uuid=nr(),this.name="",this.source=new Mu(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=n,this.wrapT=s,this.magFilter=r,this.minFilter=a,this.anisotropy=c,this.format=o,this.internalFormat=null,this.type=l,this.offset=new Xe(0,0),this.repeat=new Xe(1,1),this.center=new Xe(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new it,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(rc).x}get height(){return this.source.getSize(rc).y}get depth(){return this.source.getSize(rc).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(const t in e){const n=e[t];if(n===void 0){Je(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}const s=this[t];if(s===void 0){Je(`Texture.setValues(): property '${t}' does not exist.`);continue}s&&n&&s.isVector2&&n.isVector2||s&&n&&s.isVector3&&n.isVector3||s&&n&&s.isMatrix3&&n.isMatrix3?s.copy(n):this[t]=n}}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];const n={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(n.userData=this.userData),t||(e.textures[this.uuid]=n),n}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==vm)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case rh:e.x=e.x-Math.floor(e.x);break;case ls:e.x=e.x<0?0:1;break;case ah:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case rh:e.y=e.y-Math.floor(e.y);break;case ls:e.y=e.y<0?0:1;break;case ah:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}}kn.DEFAULT_IMAGE=null;kn.DEFAULT_MAPPING=vm;kn.DEFAULT_ANISOTROPY=1;class nn{static{this.prototype.isVector4=!0}constructor(e=0,t=0,n=0,s=1){this.x=e,this.y=t,this.z=n,this.w=s}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,n,s){return this.x=e,this.y=t,this.z=n,this.w=s,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){const t=this.x,n=this.y,s=this.z,r=this.w,a=e.elements;return this.x=a[0]*t+a[4]*n+a[8]*s+a[12]*r,this.y=a[1]*t+a[5]*n+a[9]*s+a[13]*r,this.z=a[2]*t+a[6]*n+a[10]*s+a[14]*r,this.w=a[3]*t+a[7]*n+a[11]*s+a[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);const t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,n,s,r;const l=e.elements,c=l[0],h=l[4],d=l[8],u=l[1],m=l[5],_=l[9],y=l[2],p=l[6],f=l[10];if(Math.abs(h-u)<.01&&Math.abs(d-y)<.01&&Math.abs(_-p)<.01){if(Math.abs(h+u)<.1&&Math.abs(d+y)<.1&&Math.abs(_+p)<.1&&Math.abs(c+m+f-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;const A=(c+1)/2,M=(m+1)/2,C=(f+1)/2,b=(h+u)/4,g=(d+y)/4,w=(_+p)/4;return A>M&&A>C?A<.01?(n=0,s=.707106781,r=.707106781):(n=Math.sqrt(A),s=b/n,r=g/n):M>C?M<.01?(n=.707106781,s=0,r=.707106781):(s=Math.sqrt(M),n=b/s,r=w/s):C<.01?(n=.707106781,s=.707106781,r=0):(r=Math.sqrt(C),n=g/r,s=w/r),this.set(n,s,r,t),this}let x=Math.sqrt((p-_)*(p-_)+(d-y)*(d-y)+(u-h)*(u-h));return Math.abs(x)<.001&&(x=1),this.x=(p-_)/x,this.y=(d-y)/x,this.z=(u-h)/x,this.w=Math.acos((c+m+f-1)/2),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=pt(this.x,e.x,t.x),this.y=pt(this.y,e.y,t.y),this.z=pt(this.z,e.z,t.z),this.w=pt(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=pt(this.x,e,t),this.y=pt(this.y,e,t),this.z=pt(this.z,e,t),this.w=pt(this.w,e,t),this}clampLength(e,t){const n=this.length();return this.divideScalar(n||1).multiplyScalar(pt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this.w=e.w+(t.w-e.w)*n,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}}class _x extends Fs{constructor(e=1,t=1,n={}){super(),n=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:Kn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},n),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=n.depth,this.scissor=new nn(0,0,e,t),this.scissorTest=!1,this.viewport=new nn(0,0,e,t),this.textures=[];const s=n.count;for(let r=0;r<s;r++)this.textures[r]=new kn({width:e,height:t,depth:n.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(n),this.depthBuffer=n.depthBuffer,this.stencilBuffer=n.stencilBuffer,this.resolveColorBuffer=n.resolveColorBuffer,this.resolveDepthBuffer=n.resolveDepthBuffer,this.resolveStencilBuffer=n.resolveStencilBuffer,this.storeMultisampledColorBuffer=n.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=n.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=n.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=n.depthTexture,this.samples=n.samples,this.multiview=n.multiview,this.useArrayDepthTexture=n.useArrayDepthTexture}_setTextureOptions(e={}){const t={minFilter:Kn,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let n=0;n<this.textures.length;n++)this.textures[n].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,n=1){if(this.width!==e||this.height!==t||this.depth!==n){this.width=e,this.height=t,this.depth=n;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=e,this.textures[s].image.height=t,this.textures[s].image.depth=n,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,n=e.textures.length;t<n;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;const s=Object.assign({},e.textures[t].image);this.textures[t].source=new Mu(s)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){const t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}}class qi extends _x{constructor(e=1,t=1,n={}){super(e,t,n),this.isWebGLRenderTarget=!0}}class Nm extends kn{constructor(e=null,t=1,n=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:n,depth:s},this.magFilter=Dn,this.minFilter=Dn,this.wrapR=ls,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}}class vx extends kn{constructor(e=null,t=1,n=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:n,depth:s},this.magFilter=Dn,this.minFilter=Dn,this.wrapR=ls,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}}class Dt{static{this.prototype.isMatrix4=!0}constructor(e,t,n,s,r,a,o,l,c,h,d,u,m,_,y,p){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,n,s,r,a,o,l,c,h,d,u,m,_,y,p)}set(e,t,n,s,r,a,o,l,c,h,d,u,m,_,y,p){const f=this.elements;return f[0]=e,f[4]=t,f[8]=n,f[12]=s,f[1]=r,f[5]=a,f[9]=o,f[13]=l,f[2]=c,f[6]=h,f[10]=d,f[14]=u,f[3]=m,f[7]=_,f[11]=y,f[15]=p,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new Dt().fromArray(this.elements)}copy(e){const t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],t[9]=n[9],t[10]=n[10],t[11]=n[11],t[12]=n[12],t[13]=n[13],t[14]=n[14],t[15]=n[15],this}copyPosition(e){const t=this.elements,n=e.elements;return t[12]=n[12],t[13]=n[13],t[14]=n[14],this}setFromMatrix3(e){const t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,n){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),n.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),n.setFromMatrixColumn(this,2),this)}makeBasis(e,t,n){return this.set(e.x,t.x,n.x,0,e.y,t.y,n.y,0,e.z,t.z,n.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();const t=this.elements,n=e.elements,s=1/vr.setFromMatrixColumn(e,0).length(),r=1/vr.setFromMatrixColumn(e,1).length(),a=1/vr.setFromMatrixColumn(e,2).length();return t[0]=n[0]*s,t[1]=n[1]*s,t[2]=n[2]*s,t[3]=0,t[4]=n[4]*r,t[5]=n[5]*r,t[6]=n[6]*r,t[7]=0,t[8]=n[8]*a,t[9]=n[9]*a,t[10]=n[10]*a,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){const t=this.elements,n=e.x,s=e.y,r=e.z,a=Math.cos(n),o=Math.sin(n),l=Math.cos(s),c=Math.sin(s),h=Math.cos(r),d=Math.sin(r);if(e.order==="XYZ"){const u=a*h,m=a*d,_=o*h,y=o*d;t[0]=l*h,t[4]=-l*d,t[8]=c,t[1]=m+_*c,t[5]=u-y*c,t[9]=-o*l,t[2]=y-u*c,t[6]=_+m*c,t[10]=a*l}else if(e.order==="YXZ"){const u=l*h,m=l*d,_=c*h,y=c*d;t[0]=u+y*o,t[4]=_*o-m,t[8]=a*c,t[1]=a*d,t[5]=a*h,t[9]=-o,t[2]=m*o-_,t[6]=y+u*o,t[10]=a*l}else if(e.order==="ZXY"){const u=l*h,m=l*d,_=c*h,y=c*d;t[0]=u-y*o,t[4]=-a*d,t[8]=_+m*o,t[1]=m+_*o,t[5]=a*h,t[9]=y-u*o,t[2]=-a*c,t[6]=o,t[10]=a*l}else if(e.order==="ZYX"){const u=a*h,m=a*d,_=o*h,y=o*d;t[0]=l*h,t[4]=_*c-m,t[8]=u*c+y,t[1]=l*d,t[5]=y*c+u,t[9]=m*c-_,t[2]=-c,t[6]=o*l,t[10]=a*l}else if(e.order==="YZX"){const u=a*l,m=a*c,_=o*l,y=o*c;t[0]=l*h,t[4]=y-u*d,t[8]=_*d+m,t[1]=d,t[5]=a*h,t[9]=-o*h,t[2]=-c*h,t[6]=m*d+_,t[10]=u-y*d}else if(e.order==="XZY"){const u=a*l,m=a*c,_=o*l,y=o*c;t[0]=l*h,t[4]=-d,t[8]=c*h,t[1]=u*d+y,t[5]=a*h,t[9]=m*d-_,t[2]=_*d-m,t[6]=o*h,t[10]=y*d+u}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(xx,e,yx)}lookAt(e,t,n){const s=this.elements;return ti.subVectors(e,t),ti.lengthSq()===0&&(ti.z=1),ti.normalize(),ys.crossVectors(n,ti),ys.lengthSq()===0&&(Math.abs(n.z)===1?ti.x+=1e-4:ti.z+=1e-4,ti.normalize(),ys.crossVectors(n,ti)),ys.normalize(),ho.crossVectors(ti,ys),s[0]=ys.x,s[4]=ho.x,s[8]=ti.x,s[1]=ys.y,s[5]=ho.y,s[9]=ti.y,s[2]=ys.z,s[6]=ho.z,s[10]=ti.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const n=e.elements,s=t.elements,r=this.elements,a=n[0],o=n[4],l=n[8],c=n[12],h=n[1],d=n[5],u=n[9],m=n[13],_=n[2],y=n[6],p=n[10],f=n[14],x=n[3],A=n[7],M=n[11],C=n[15],b=s[0],g=s[4],w=s[8],F=s[12],L=s[1],D=s[5],z=s[9],V=s[13],U=s[2],W=s[6],K=s[10],G=s[14],le=s[3],J=s[7],Q=s[11],se=s[15];return r[0]=a*b+o*L+l*U+c*le,r[4]=a*g+o*D+l*W+c*J,r[8]=a*w+o*z+l*K+c*Q,r[12]=a*F+o*V+l*G+c*se,r[1]=h*b+d*L+u*U+m*le,r[5]=h*g+d*D+u*W+m*J,r[9]=h*w+d*z+u*K+m*Q,r[13]=h*F+d*V+u*G+m*se,r[2]=_*b+y*L+p*U+f*le,r[6]=_*g+y*D+p*W+f*J,r[10]=_*w+y*z+p*K+f*Q,r[14]=_*F+y*V+p*G+f*se,r[3]=x*b+A*L+M*U+C*le,r[7]=x*g+A*D+M*W+C*J,r[11]=x*w+A*z+M*K+C*Q,r[15]=x*F+A*V+M*G+C*se,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){const e=this.elements,t=e[0],n=e[4],s=e[8],r=e[12],a=e[1],o=e[5],l=e[9],c=e[13],h=e[2],d=e[6],u=e[10],m=e[14],_=e[3],y=e[7],p=e[11],f=e[15],x=l*m-c*u,A=o*m-c*d,M=o*u-l*d,C=a*m-c*h,b=a*u-l*h,g=a*d-o*h;return t*(y*x-p*A+f*M)-n*(_*x-p*C+f*b)+s*(_*A-y*C+f*g)-r*(_*M-y*b+p*g)}determinantAffine(){const e=this.elements,t=e[0],n=e[4],s=e[8],r=e[1],a=e[5],o=e[9],l=e[2],c=e[6],h=e[10];return t*(a*h-o*c)-n*(r*h-o*l)+s*(r*c-a*l)}transpose(){const e=this.elements;let t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,n){const s=this.elements;return e.isVector3?(s[12]=e.x,s[13]=e.y,s[14]=e.z):(s[12]=e,s[13]=t,s[14]=n),this}invert(){const e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],h=e[8],d=e[9],u=e[10],m=e[11],_=e[12],y=e[13],p=e[14],f=e[15],x=t*o-n*a,A=t*l-s*a,M=t*c-r*a,C=n*l-s*o,b=n*c-r*o,g=s*c-r*l,w=h*y-d*_,F=h*p-u*_,L=h*f-m*_,D=d*p-u*y,z=d*f-m*y,V=u*f-m*p,U=x*V-A*z+M*D+C*L-b*F+g*w;if(U===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);const W=1/U;return e[0]=(o*V-l*z+c*D)*W,e[1]=(s*z-n*V-r*D)*W,e[2]=(y*g-p*b+f*C)*W,e[3]=(u*b-d*g-m*C)*W,e[4]=(l*L-a*V-c*F)*W,e[5]=(t*V-s*L+r*F)*W,e[6]=(p*M-_*g-f*A)*W,e[7]=(h*g-u*M+m*A)*W,e[8]=(a*z-o*L+c*w)*W,e[9]=(n*L-t*z-r*w)*W,e[10]=(_*b-y*M+f*x)*W,e[11]=(d*M-h*b-m*x)*W,e[12]=(o*F-a*D-l*w)*W,e[13]=(t*D-n*F+s*w)*W,e[14]=(y*A-_*C-p*x)*W,e[15]=(h*C-d*A+u*x)*W,this}scale(e){const t=this.elements,n=e.x,s=e.y,r=e.z;return t[0]*=n,t[4]*=s,t[8]*=r,t[1]*=n,t[5]*=s,t[9]*=r,t[2]*=n,t[6]*=s,t[10]*=r,t[3]*=n,t[7]*=s,t[11]*=r,this}getMaxScaleOnAxis(){const e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],n=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],s=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,n,s))}makeTranslation(e,t,n){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,n,0,0,0,1),this}makeRotationX(e){const t=Math.cos(e),n=Math.sin(e);return this.set(1,0,0,0,0,t,-n,0,0,n,t,0,0,0,0,1),this}makeRotationY(e){const t=Math.cos(e),n=Math.sin(e);return this.set(t,0,n,0,0,1,0,0,-n,0,t,0,0,0,0,1),this}makeRotationZ(e){const t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,0,n,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){const n=Math.cos(t),s=Math.sin(t),r=1-n,a=e.x,o=e.y,l=e.z,c=r*a,h=r*o;return this.set(c*a+n,c*o-s*l,c*l+s*o,0,c*o+s*l,h*o+n,h*l-s*a,0,c*l-s*o,h*l+s*a,r*l*l+n,0,0,0,0,1),this}makeScale(e,t,n){return this.set(e,0,0,0,0,t,0,0,0,0,n,0,0,0,0,1),this}makeShear(e,t,n,s,r,a){return this.set(1,n,r,0,e,1,a,0,t,s,1,0,0,0,0,1),this}compose(e,t,n){const s=this.elements,r=t._x,a=t._y,o=t._z,l=t._w,c=r+r,h=a+a,d=o+o,u=r*c,m=r*h,_=r*d,y=a*h,p=a*d,f=o*d,x=l*c,A=l*h,M=l*d,C=n.x,b=n.y,g=n.z;return s[0]=(1-(y+f))*C,s[1]=(m+M)*C,s[2]=(_-A)*C,s[3]=0,s[4]=(m-M)*b,s[5]=(1-(u+f))*b,s[6]=(p+x)*b,s[7]=0,s[8]=(_+A)*g,s[9]=(p-x)*g,s[10]=(1-(u+y))*g,s[11]=0,s[12]=e.x,s[13]=e.y,s[14]=e.z,s[15]=1,this}decompose(e,t,n){const s=this.elements;e.x=s[12],e.y=s[13],e.z=s[14];const r=this.determinantAffine();if(r===0)return n.set(1,1,1),t.identity(),this;let a=vr.set(s[0],s[1],s[2]).length();const o=vr.set(s[4],s[5],s[6]).length(),l=vr.set(s[8],s[9],s[10]).length();r<0&&(a=-a),bi.copy(this);const c=1/a,h=1/o,d=1/l;return bi.elements[0]*=c,bi.elements[1]*=c,bi.elements[2]*=c,bi.elements[4]*=h,bi.elements[5]*=h,bi.elements[6]*=h,bi.elements[8]*=d,bi.elements[9]*=d,bi.elements[10]*=d,t.setFromRotationMatrix(bi),n.x=a,n.y=o,n.z=l,this}makePerspective(e,t,n,s,r,a,o=Pi,l=!1){const c=this.elements,h=2*r/(t-e),d=2*r/(n-s),u=(t+e)/(t-e),m=(n+s)/(n-s);let _,y;if(l)_=r/(a-r),y=a*r/(a-r);else if(o===Pi)_=-(a+r)/(a-r),y=-2*a*r/(a-r);else if(o===Ba)_=-a/(a-r),y=-a*r/(a-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return c[0]=h,c[4]=0,c[8]=u,c[12]=0,c[1]=0,c[5]=d,c[9]=m,c[13]=0,c[2]=0,c[6]=0,c[10]=_,c[14]=y,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(e,t,n,s,r,a,o=Pi,l=!1){const c=this.elements,h=2/(t-e),d=2/(n-s),u=-(t+e)/(t-e),m=-(n+s)/(n-s);let _,y;if(l)_=1/(a-r),y=a/(a-r);else if(o===Pi)_=-2/(a-r),y=-(a+r)/(a-r);else if(o===Ba)_=-1/(a-r),y=-r/(a-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return c[0]=h,c[4]=0,c[8]=0,c[12]=u,c[1]=0,c[5]=d,c[9]=0,c[13]=m,c[2]=0,c[6]=0,c[10]=_,c[14]=y,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(e){const t=this.elements,n=e.elements;for(let s=0;s<16;s++)if(t[s]!==n[s])return!1;return!0}fromArray(e,t=0){for(let n=0;n<16;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){const n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e[t+9]=n[9],e[t+10]=n[10],e[t+11]=n[11],e[t+12]=n[12],e[t+13]=n[13],e[t+14]=n[14],e[t+15]=n[15],e}}const vr=new B,bi=new Dt,xx=new B(0,0,0),yx=new B(1,1,1),ys=new B,ho=new B,ti=new B,Zd=new Dt,Jd=new Is;class Us{constructor(e=0,t=0,n=0,s=Us.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=n,this._order=s}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,n,s=this._order){return this._x=e,this._y=t,this._z=n,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,n=!0){const s=e.elements,r=s[0],a=s[4],o=s[8],l=s[1],c=s[5],h=s[9],d=s[2],u=s[6],m=s[10];switch(t){case"XYZ":this._y=Math.asin(pt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-h,m),this._z=Math.atan2(-a,r)):(this._x=Math.atan2(u,c),this._z=0);break;case"YXZ":this._x=Math.asin(-pt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(o,m),this._z=Math.atan2(l,c)):(this._y=Math.atan2(-d,r),this._z=0);break;case"ZXY":this._x=Math.asin(pt(u,-1,1)),Math.abs(u)<.9999999?(this._y=Math.atan2(-d,m),this._z=Math.atan2(-a,c)):(this._y=0,this._z=Math.atan2(l,r));break;case"ZYX":this._y=Math.asin(-pt(d,-1,1)),Math.abs(d)<.9999999?(this._x=Math.atan2(u,m),this._z=Math.atan2(l,r)):(this._x=0,this._z=Math.atan2(-a,c));break;case"YZX":this._z=Math.asin(pt(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-h,c),this._y=Math.atan2(-d,r)):(this._x=0,this._y=Math.atan2(o,m));break;case"XZY":this._z=Math.asin(-pt(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(u,c),this._y=Math.atan2(o,r)):(this._x=Math.atan2(-h,m),this._y=0);break;default:Je("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,n===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,n){return Zd.makeRotationFromQuaternion(e),this.setFromRotationMatrix(Zd,t,n)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return Jd.setFromEuler(this),this.setFromQuaternion(Jd,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}}Us.DEFAULT_ORDER="XYZ";class bu{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}}let Sx=0;const jd=new B,xr=new Is,is=new Dt,uo=new B,fa=new B,Mx=new B,bx=new Is,Qd=new B(1,0,0),ef=new B(0,1,0),tf=new B(0,0,1),nf={type:"added"},wx={type:"removed"},yr={type:"childadded",child:null},ac={type:"childremoved",child:null};class yn extends Fs{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:Sx++}),this.uuid=nr(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=yn.DEFAULT_UP.clone();const e=new B,t=new Us,n=new Is,s=new B(1,1,1);function r(){n.setFromEuler(t,!1)}function a(){t.setFromQuaternion(n,void 0,!1)}t._onChange(r),n._onChange(a),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:n},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new Dt},normalMatrix:{value:new it}}),this.matrix=new Dt,this.matrixWorld=new Dt,this.matrixAutoUpdate=yn.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=yn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new bu,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return xr.setFromAxisAngle(e,t),this.quaternion.multiply(xr),this}rotateOnWorldAxis(e,t){return xr.setFromAxisAngle(e,t),this.quaternion.premultiply(xr),this}rotateX(e){return this.rotateOnAxis(Qd,e)}rotateY(e){return this.rotateOnAxis(ef,e)}rotateZ(e){return this.rotateOnAxis(tf,e)}translateOnAxis(e,t){return jd.copy(e).applyQuaternion(this.quaternion),this.position.add(jd.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(Qd,e)}translateY(e){return this.translateOnAxis(ef,e)}translateZ(e){return this.translateOnAxis(tf,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(is.copy(this.matrixWorld).invert())}lookAt(e,t,n){e.isVector3?uo.copy(e):uo.set(e,t,n);const s=this.parent;this.updateWorldMatrix(!0,!1),fa.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?is.lookAt(fa,uo,this.up):is.lookAt(uo,fa,this.up),this.quaternion.setFromRotationMatrix(is),s&&(is.extractRotation(s.matrixWorld),xr.setFromRotationMatrix(is),this.quaternion.premultiply(xr.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(xt("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(nf),yr.child=e,this.dispatchEvent(yr),yr.child=null):xt("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let n=0;n<arguments.length;n++)this.remove(arguments[n]);return this}const t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(wx),ac.child=e,this.dispatchEvent(ac),ac.child=null),this}removeFromParent(){const e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),is.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),is.multiply(e.parent.matrixWorld)),e.applyMatrix4(is),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(nf),yr.child=e,this.dispatchEvent(yr),yr.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let n=0,s=this.children.length;n<s;n++){const a=this.children[n].getObjectByProperty(e,t);if(a!==void 0)return a}}getObjectsByProperty(e,t,n=[]){this[e]===t&&n.push(this);const s=this.children;for(let r=0,a=s.length;r<a;r++)s[r].getObjectsByProperty(e,t,n);return n}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(fa,e,Mx),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(fa,bx,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);const t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);const t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);const t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].traverseVisible(e)}traverseAncestors(e){const t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);const e=this.pivot;if(e!==null){const t=e.x,n=e.y,s=e.z,r=this.matrix.elements;r[12]+=t-r[0]*t-r[4]*n-r[8]*s,r[13]+=n-r[1]*t-r[5]*n-r[9]*s,r[14]+=s-r[2]*t-r[6]*n-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);const t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].updateMatrixWorld(e)}updateWorldMatrix(e,t,n=!1){const s=this.parent;if(e===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||n)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,n=!0),t===!0){const r=this.children;for(let a=0,o=r.length;a<o;a++)r[a].updateWorldMatrix(!1,!0,n)}}toJSON(e){const t=e===void 0||typeof e=="string",n={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},n.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});const s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(o=>({...o,boundingBox:o.boundingBox?o.boundingBox.toJSON():void 0,boundingSphere:o.boundingSphere?o.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(o=>({...o})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(e),s.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(o,l){return o[l.uuid]===void 0&&(o[l.uuid]=l.toJSON(e)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(e.geometries,this.geometry);const o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){const l=o.shapes;if(Array.isArray(l))for(let c=0,h=l.length;c<h;c++){const d=l[c];r(e.shapes,d)}else r(e.shapes,l)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){const o=[];for(let l=0,c=this.material.length;l<c;l++)o.push(r(e.materials,this.material[l]));s.material=o}else s.material=r(e.materials,this.material);if(this.children.length>0){s.children=[];for(let o=0;o<this.children.length;o++)s.children.push(this.children[o].toJSON(e).object)}if(this.animations.length>0){s.animations=[];for(let o=0;o<this.animations.length;o++){const l=this.animations[o];s.animations.push(r(e.animations,l))}}if(t){const o=a(e.geometries),l=a(e.materials),c=a(e.textures),h=a(e.images),d=a(e.shapes),u=a(e.skeletons),m=a(e.animations),_=a(e.nodes);o.length>0&&(n.geometries=o),l.length>0&&(n.materials=l),c.length>0&&(n.textures=c),h.length>0&&(n.images=h),d.length>0&&(n.shapes=d),u.length>0&&(n.skeletons=u),m.length>0&&(n.animations=m),_.length>0&&(n.nodes=_)}return n.object=s,n;function a(o){const l=[];for(const c in o){const h=o[c];delete h.metadata,l.push(h)}return l}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let n=0;n<e.children.length;n++){const s=e.children[n];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}}yn.DEFAULT_UP=new B(0,1,0);yn.DEFAULT_MATRIX_AUTO_UPDATE=!0;yn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;class $i extends yn{constructor(){super(),this.isGroup=!0,this.type="Group"}}const Ex={type:"move"};class oc{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new $i,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new $i,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new B,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new B),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new $i,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new B,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new B,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){const t=this._hand;if(t)for(const n of e.hand.values())this._getHandJoint(t,n)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,n){let s=null,r=null,a=null;const o=this._targetRay,l=this._grip,c=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(c&&e.hand){a=!0;for(const y of e.hand.values()){const p=t.getJointPose(y,n),f=this._getHandJoint(c,y);p!==null&&(f.matrix.fromArray(p.transform.matrix),f.matrix.decompose(f.position,f.quaternion,f.scale),f.matrixWorldNeedsUpdate=!0,f.jointRadius=p.radius),f.visible=p!==null}const h=c.joints["index-finger-tip"],d=c.joints["thumb-tip"],u=h.position.distanceTo(d.position),m=.02,_=.005;c.inputState.pinching&&u>m+_?(c.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!c.inputState.pinching&&u<=m-_&&(c.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else l!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,n),r!==null&&(l.matrix.fromArray(r.transform.matrix),l.matrix.decompose(l.position,l.quaternion,l.scale),l.matrixWorldNeedsUpdate=!0,r.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(r.linearVelocity)):l.hasLinearVelocity=!1,r.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(r.angularVelocity)):l.hasAngularVelocity=!1,l.eventsEnabled&&l.dispatchEvent({type:"gripUpdated",data:e,target:this})));o!==null&&(s=t.getPose(e.targetRaySpace,n),s===null&&r!==null&&(s=r),s!==null&&(o.matrix.fromArray(s.transform.matrix),o.matrix.decompose(o.position,o.quaternion,o.scale),o.matrixWorldNeedsUpdate=!0,s.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(s.linearVelocity)):o.hasLinearVelocity=!1,s.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(s.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(Ex)))}return o!==null&&(o.visible=s!==null),l!==null&&(l.visible=r!==null),c!==null&&(c.visible=a!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){const n=new $i;n.matrixAutoUpdate=!1,n.visible=!1,e.joints[t.jointName]=n,e.add(n)}return e.joints[t.jointName]}}const Im={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},Ss={h:0,s:0,l:0},fo={h:0,s:0,l:0};function lc(i,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?i+(e-i)*6*t:t<1/2?e:t<2/3?i+(e-i)*6*(2/3-t):i}class lt{constructor(e,t,n){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,n)}set(e,t,n){if(t===void 0&&n===void 0){const s=e;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(e,t,n);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=di){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,_t.colorSpaceToWorking(this,t),this}setRGB(e,t,n,s=_t.workingColorSpace){return this.r=e,this.g=t,this.b=n,_t.colorSpaceToWorking(this,s),this}setHSL(e,t,n,s=_t.workingColorSpace){if(e=hx(e,1),t=pt(t,0,1),n=pt(n,0,1),t===0)this.r=this.g=this.b=n;else{const r=n<=.5?n*(1+t):n+t-n*t,a=2*n-r;this.r=lc(a,r,e+1/3),this.g=lc(a,r,e),this.b=lc(a,r,e-1/3)}return _t.colorSpaceToWorking(this,s),this}setStyle(e,t=di){function n(r){r!==void 0&&parseFloat(r)<1&&Je("Color: Alpha component of "+e+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(e)){let r;const a=s[1],o=s[2];switch(a){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,t);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:Je("Color: Unknown color model "+e)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(e)){const r=s[1],a=r.length;if(a===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(a===6)return this.setHex(parseInt(r,16),t);Je("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=di){const n=Im[e.toLowerCase()];return n!==void 0?this.setHex(n,t):Je("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=fs(e.r),this.g=fs(e.g),this.b=fs(e.b),this}copyLinearToSRGB(e){return this.r=Hr(e.r),this.g=Hr(e.g),this.b=Hr(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=di){return _t.workingToColorSpace(Un.copy(this),e),Math.round(pt(Un.r*255,0,255))*65536+Math.round(pt(Un.g*255,0,255))*256+Math.round(pt(Un.b*255,0,255))}getHexString(e=di){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=_t.workingColorSpace){_t.workingToColorSpace(Un.copy(this),t);const n=Un.r,s=Un.g,r=Un.b,a=Math.max(n,s,r),o=Math.min(n,s,r);let l,c;const h=(o+a)/2;if(o===a)l=0,c=0;else{const d=a-o;switch(c=h<=.5?d/(a+o):d/(2-a-o),a){case n:l=(s-r)/d+(s<r?6:0);break;case s:l=(r-n)/d+2;break;case r:l=(n-s)/d+4;break}l/=6}return e.h=l,e.s=c,e.l=h,e}getRGB(e,t=_t.workingColorSpace){return _t.workingToColorSpace(Un.copy(this),t),e.r=Un.r,e.g=Un.g,e.b=Un.b,e}getStyle(e=di){_t.workingToColorSpace(Un.copy(this),e);const t=Un.r,n=Un.g,s=Un.b;return e!==di?`color(${e} ${t.toFixed(3)} ${n.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(n*255)},${Math.round(s*255)})`}offsetHSL(e,t,n){return this.getHSL(Ss),this.setHSL(Ss.h+e,Ss.s+t,Ss.l+n)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,n){return this.r=e.r+(t.r-e.r)*n,this.g=e.g+(t.g-e.g)*n,this.b=e.b+(t.b-e.b)*n,this}lerpHSL(e,t){this.getHSL(Ss),e.getHSL(fo);const n=tc(Ss.h,fo.h,t),s=tc(Ss.s,fo.s,t),r=tc(Ss.l,fo.l,t);return this.setHSL(n,s,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){const t=this.r,n=this.g,s=this.b,r=e.elements;return this.r=r[0]*t+r[3]*n+r[6]*s,this.g=r[1]*t+r[4]*n+r[7]*s,this.b=r[2]*t+r[5]*n+r[8]*s,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}}const Un=new lt;lt.NAMES=Im;class Um extends yn{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Us,this.environmentIntensity=1,this.environmentRotation=new Us,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){const t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}}const wi=new B,ss=new B,cc=new B,rs=new B,Sr=new B,Mr=new B,sf=new B,hc=new B,uc=new B,dc=new B,fc=new nn,pc=new nn,mc=new nn;class mi{constructor(e=new B,t=new B,n=new B){this.a=e,this.b=t,this.c=n}static getNormal(e,t,n,s){s.subVectors(n,t),wi.subVectors(e,t),s.cross(wi);const r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(e,t,n,s,r){wi.subVectors(s,t),ss.subVectors(n,t),cc.subVectors(e,t);const a=wi.dot(wi),o=wi.dot(ss),l=wi.dot(cc),c=ss.dot(ss),h=ss.dot(cc),d=a*c-o*o;if(d===0)return r.set(0,0,0),null;const u=1/d,m=(c*l-o*h)*u,_=(a*h-o*l)*u;return r.set(1-m-_,_,m)}static containsPoint(e,t,n,s){return this.getBarycoord(e,t,n,s,rs)===null?!1:rs.x>=0&&rs.y>=0&&rs.x+rs.y<=1}static getInterpolation(e,t,n,s,r,a,o,l){return this.getBarycoord(e,t,n,s,rs)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(r,rs.x),l.addScaledVector(a,rs.y),l.addScaledVector(o,rs.z),l)}static getInterpolatedAttribute(e,t,n,s,r,a){return fc.setScalar(0),pc.setScalar(0),mc.setScalar(0),fc.fromBufferAttribute(e,t),pc.fromBufferAttribute(e,n),mc.fromBufferAttribute(e,s),a.setScalar(0),a.addScaledVector(fc,r.x),a.addScaledVector(pc,r.y),a.addScaledVector(mc,r.z),a}static isFrontFacing(e,t,n,s){return wi.subVectors(n,t),ss.subVectors(e,t),wi.cross(ss).dot(s)<0}set(e,t,n){return this.a.copy(e),this.b.copy(t),this.c.copy(n),this}setFromPointsAndIndices(e,t,n,s){return this.a.copy(e[t]),this.b.copy(e[n]),this.c.copy(e[s]),this}setFromAttributeAndIndices(e,t,n,s){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,n),this.c.fromBufferAttribute(e,s),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return wi.subVectors(this.c,this.b),ss.subVectors(this.a,this.b),wi.cross(ss).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return mi.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return mi.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,n,s,r){return mi.getInterpolation(e,this.a,this.b,this.c,t,n,s,r)}containsPoint(e){return mi.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return mi.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){const n=this.a,s=this.b,r=this.c;let a,o;Sr.subVectors(s,n),Mr.subVectors(r,n),hc.subVectors(e,n);const l=Sr.dot(hc),c=Mr.dot(hc);if(l<=0&&c<=0)return t.copy(n);uc.subVectors(e,s);const h=Sr.dot(uc),d=Mr.dot(uc);if(h>=0&&d<=h)return t.copy(s);const u=l*d-h*c;if(u<=0&&l>=0&&h<=0&&l-h>0)return a=l/(l-h),t.copy(n).addScaledVector(Sr,a);dc.subVectors(e,r);const m=Sr.dot(dc),_=Mr.dot(dc);if(_>=0&&m<=_)return t.copy(r);const y=m*c-l*_;if(y<=0&&c>=0&&_<=0)return o=c/(c-_),t.copy(n).addScaledVector(Mr,o);const p=h*_-m*d;if(p<=0&&d-h>=0&&m-_>=0)return sf.subVectors(r,s),o=(d-h)/(d-h+(m-_)),t.copy(s).addScaledVector(sf,o);const f=1/(p+y+u);return a=y*f,o=u*f,t.copy(n).addScaledVector(Sr,a).addScaledVector(Mr,o)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}}class qa{constructor(e=new B(1/0,1/0,1/0),t=new B(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t+=3)this.expandByPoint(Ei.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,n=e.count;t<n;t++)this.expandByPoint(Ei.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){const n=Ei.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(n),this.max.copy(e).add(n),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);const n=e.geometry;if(n!==void 0){const r=n.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let a=0,o=r.count;a<o;a++)e.isMesh===!0?e.getVertexPosition(a,Ei):Ei.fromBufferAttribute(r,a),Ei.applyMatrix4(e.matrixWorld),this.expandByPoint(Ei);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),po.copy(e.boundingBox)):(n.boundingBox===null&&n.computeBoundingBox(),po.copy(n.boundingBox)),po.applyMatrix4(e.matrixWorld),this.union(po)}const s=e.children;for(let r=0,a=s.length;r<a;r++)this.expandByObject(s[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,Ei),Ei.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,n;return e.normal.x>0?(t=e.normal.x*this.min.x,n=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,n=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,n+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,n+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,n+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,n+=e.normal.z*this.min.z),t<=-e.constant&&n>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(pa),mo.subVectors(this.max,pa),br.subVectors(e.a,pa),wr.subVectors(e.b,pa),Er.subVectors(e.c,pa),Ms.subVectors(wr,br),bs.subVectors(Er,wr),zs.subVectors(br,Er);let t=[0,-Ms.z,Ms.y,0,-bs.z,bs.y,0,-zs.z,zs.y,Ms.z,0,-Ms.x,bs.z,0,-bs.x,zs.z,0,-zs.x,-Ms.y,Ms.x,0,-bs.y,bs.x,0,-zs.y,zs.x,0];return!gc(t,br,wr,Er,mo)||(t=[1,0,0,0,1,0,0,0,1],!gc(t,br,wr,Er,mo))?!1:(go.crossVectors(Ms,bs),t=[go.x,go.y,go.z],gc(t,br,wr,Er,mo))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,Ei).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(Ei).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(as[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),as[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),as[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),as[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),as[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),as[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),as[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),as[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(as),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}}const as=[new B,new B,new B,new B,new B,new B,new B,new B],Ei=new B,po=new qa,br=new B,wr=new B,Er=new B,Ms=new B,bs=new B,zs=new B,pa=new B,mo=new B,go=new B,Hs=new B;function gc(i,e,t,n,s){for(let r=0,a=i.length-3;r<=a;r+=3){Hs.fromArray(i,r);const o=s.x*Math.abs(Hs.x)+s.y*Math.abs(Hs.y)+s.z*Math.abs(Hs.z),l=e.dot(Hs),c=t.dot(Hs),h=n.dot(Hs);if(Math.max(-Math.max(l,c,h),Math.min(l,c,h))>o)return!1}return!0}const dn=new B,_o=new Xe;let Tx=0;class _i extends Fs{constructor(e,t,n=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:Tx++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=n,this.usage=Cm,this.updateRanges=[],this.gpuType=Wi,this.version=0,this._normalizationScale=e!==void 0?bl(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,n){e*=this.itemSize,n*=t.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[e+s]=t.array[n+s];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,n=this.count;t<n;t++)_o.fromBufferAttribute(this,t),_o.applyMatrix3(e),this.setXY(t,_o.x,_o.y);else if(this.itemSize===3)for(let t=0,n=this.count;t<n;t++)dn.fromBufferAttribute(this,t),dn.applyMatrix3(e),this.setXYZ(t,dn.x,dn.y,dn.z);return this}applyMatrix4(e){for(let t=0,n=this.count;t<n;t++)dn.fromBufferAttribute(this,t),dn.applyMatrix4(e),this.setXYZ(t,dn.x,dn.y,dn.z);return this}applyNormalMatrix(e){for(let t=0,n=this.count;t<n;t++)dn.fromBufferAttribute(this,t),dn.applyNormalMatrix(e),this.setXYZ(t,dn.x,dn.y,dn.z);return this}transformDirection(e){for(let t=0,n=this.count;t<n;t++)dn.fromBufferAttribute(this,t),dn.transformDirection(e),this.setXYZ(t,dn.x,dn.y,dn.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let n=this.array[e*this.itemSize+t];return this.normalized&&(n=this._denormalize(n)),n}setComponent(e,t,n){return this.normalized&&(n=this._normalize(n)),this.array[e*this.itemSize+t]=n,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,n){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n)),this.array[e+0]=t,this.array[e+1]=n,this}setXYZ(e,t,n,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=s,this}setXYZW(e,t,n,s,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=s,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){const e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){const t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):Lm(e,this.array)}_normalize(e){const t=this._normalizationScale;return t!==void 0?Math.round(e*t):Dm(e,this.array)}}class Fm extends _i{constructor(e,t,n){super(new Uint16Array(e),t,n)}}class Om extends _i{constructor(e,t,n){super(new Uint32Array(e),t,n)}}class rn extends _i{constructor(e,t,n){super(new Float32Array(e),t,n)}}const Ax=new qa,ma=new B,_c=new B;class Ya{constructor(e=new B,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){const n=this.center;t!==void 0?n.copy(t):Ax.setFromPoints(e).getCenter(n);let s=0;for(let r=0,a=e.length;r<a;r++)s=Math.max(s,n.distanceToSquared(e[r]));return this.radius=Math.sqrt(s),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){const t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){const n=this.center.distanceToSquared(e);return t.copy(e),n>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;ma.subVectors(e,this.center);const t=ma.lengthSq();if(t>this.radius*this.radius){const n=Math.sqrt(t),s=(n-this.radius)*.5;this.center.addScaledVector(ma,s/n),this.radius+=s}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(_c.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(ma.copy(e.center).add(_c)),this.expandByPoint(ma.copy(e.center).sub(_c))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}}let Rx=0;const ci=new Dt,vc=new yn,Tr=new B,ni=new qa,ga=new qa,Cn=new B;class Bt extends Fs{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:Rx++}),this.uuid=nr(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(ax(e)?Om:Fm)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,n=0){this.groups.push({start:e,count:t,materialIndex:n})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){const t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);const n=this.attributes.normal;if(n!==void 0){const r=new it().getNormalMatrix(e);n.applyNormalMatrix(r),n.needsUpdate=!0}const s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(e),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return ci.makeRotationFromQuaternion(e),this.applyMatrix4(ci),this}rotateX(e){return ci.makeRotationX(e),this.applyMatrix4(ci),this}rotateY(e){return ci.makeRotationY(e),this.applyMatrix4(ci),this}rotateZ(e){return ci.makeRotationZ(e),this.applyMatrix4(ci),this}translate(e,t,n){return ci.makeTranslation(e,t,n),this.applyMatrix4(ci),this}scale(e,t,n){return ci.makeScale(e,t,n),this.applyMatrix4(ci),this}lookAt(e){return vc.lookAt(e),vc.updateMatrix(),this.applyMatrix4(vc.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(Tr).negate(),this.translate(Tr.x,Tr.y,Tr.z),this}setFromPoints(e){const t=this.getAttribute("position");if(t===void 0){const n=[];for(let s=0,r=e.length;s<r;s++){const a=e[s];n.push(a.x,a.y,a.z||0)}this.setAttribute("position",new rn(n,3))}else{const n=Math.min(e.length,t.count);for(let s=0;s<n;s++){const r=e[s];t.setXYZ(s,r.x,r.y,r.z||0)}e.length>t.count&&Je("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new qa);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){xt("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new B(-1/0,-1/0,-1/0),new B(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let n=0,s=t.length;n<s;n++){const r=t[n];ni.setFromBufferAttribute(r),this.morphTargetsRelative?(Cn.addVectors(this.boundingBox.min,ni.min),this.boundingBox.expandByPoint(Cn),Cn.addVectors(this.boundingBox.max,ni.max),this.boundingBox.expandByPoint(Cn)):(this.boundingBox.expandByPoint(ni.min),this.boundingBox.expandByPoint(ni.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&xt('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Ya);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){xt("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new B,1/0);return}if(e){const n=this.boundingSphere.center;if(ni.setFromBufferAttribute(e),t)for(let r=0,a=t.length;r<a;r++){const o=t[r];ga.setFromBufferAttribute(o),this.morphTargetsRelative?(Cn.addVectors(ni.min,ga.min),ni.expandByPoint(Cn),Cn.addVectors(ni.max,ga.max),ni.expandByPoint(Cn)):(ni.expandByPoint(ga.min),ni.expandByPoint(ga.max))}ni.getCenter(n);let s=0;for(let r=0,a=e.count;r<a;r++)Cn.fromBufferAttribute(e,r),s=Math.max(s,n.distanceToSquared(Cn));if(t)for(let r=0,a=t.length;r<a;r++){const o=t[r],l=this.morphTargetsRelative;for(let c=0,h=o.count;c<h;c++)Cn.fromBufferAttribute(o,c),l&&(Tr.fromBufferAttribute(e,c),Cn.add(Tr)),s=Math.max(s,n.distanceToSquared(Cn))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&xt('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){const e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){xt("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}const n=t.position,s=t.normal,r=t.uv;let a=this.getAttribute("tangent");(a===void 0||a.count!==n.count)&&(a=new _i(new Float32Array(4*n.count),4),this.setAttribute("tangent",a));const o=[],l=[],c=new Uint8Array(n.count);for(let F=0;F<n.count;F++)o[F]=new B,l[F]=new B;const h=new B,d=new B,u=new B,m=new Xe,_=new Xe,y=new Xe,p=new B,f=new B;function x(F,L,D){c[F]=c[L]=c[D]=1,h.fromBufferAttribute(n,F),d.fromBufferAttribute(n,L),u.fromBufferAttribute(n,D),m.fromBufferAttribute(r,F),_.fromBufferAttribute(r,L),y.fromBufferAttribute(r,D),d.sub(h),u.sub(h),_.sub(m),y.sub(m);const z=1/(_.x*y.y-y.x*_.y);isFinite(z)&&(p.copy(d).multiplyScalar(y.y).addScaledVector(u,-_.y).multiplyScalar(z),f.copy(u).multiplyScalar(_.x).addScaledVector(d,-y.x).multiplyScalar(z),o[F].add(p),o[L].add(p),o[D].add(p),l[F].add(f),l[L].add(f),l[D].add(f))}let A=this.groups;A.length===0&&(A=[{start:0,count:e.count}]);for(let F=0,L=A.length;F<L;++F){const D=A[F],z=D.start,V=D.count;for(let U=z,W=z+V;U<W;U+=3)x(e.getX(U+0),e.getX(U+1),e.getX(U+2))}const M=new B,C=new B,b=new B,g=new B;function w(F){b.fromBufferAttribute(s,F),g.copy(b);const L=o[F];M.copy(L),M.sub(b.multiplyScalar(b.dot(L))).normalize(),C.crossVectors(g,L);const z=C.dot(l[F])<0?-1:1;a.setXYZW(F,M.x,M.y,M.z,z)}for(let F=0,L=n.count;F<L;++F)c[F]&&w(F);this._transformed=!0}computeVertexNormals(){const e=this.index,t=this.getAttribute("position");if(t!==void 0){let n=this.getAttribute("normal");if(n===void 0||n.count!==t.count)n=new _i(new Float32Array(t.count*3),3),this.setAttribute("normal",n);else for(let u=0,m=n.count;u<m;u++)n.setXYZ(u,0,0,0);const s=new B,r=new B,a=new B,o=new B,l=new B,c=new B,h=new B,d=new B;if(e)for(let u=0,m=e.count;u<m;u+=3){const _=e.getX(u+0),y=e.getX(u+1),p=e.getX(u+2);s.fromBufferAttribute(t,_),r.fromBufferAttribute(t,y),a.fromBufferAttribute(t,p),h.subVectors(a,r),d.subVectors(s,r),h.cross(d),o.fromBufferAttribute(n,_),l.fromBufferAttribute(n,y),c.fromBufferAttribute(n,p),o.add(h),l.add(h),c.add(h),n.setXYZ(_,o.x,o.y,o.z),n.setXYZ(y,l.x,l.y,l.z),n.setXYZ(p,c.x,c.y,c.z)}else for(let u=0,m=t.count;u<m;u+=3)s.fromBufferAttribute(t,u+0),r.fromBufferAttribute(t,u+1),a.fromBufferAttribute(t,u+2),h.subVectors(a,r),d.subVectors(s,r),h.cross(d),n.setXYZ(u+0,h.x,h.y,h.z),n.setXYZ(u+1,h.x,h.y,h.z),n.setXYZ(u+2,h.x,h.y,h.z);this.normalizeNormals(),n.needsUpdate=!0}}normalizeNormals(){const e=this.attributes.normal;for(let t=0,n=e.count;t<n;t++)Cn.fromBufferAttribute(e,t),Cn.normalize(),e.setXYZ(t,Cn.x,Cn.y,Cn.z)}toNonIndexed(){function e(o,l){const c=o.array,h=o.itemSize,d=o.normalized,u=new c.constructor(l.length*h);let m=0,_=0;for(let y=0,p=l.length;y<p;y++){o.isInterleavedBufferAttribute?m=l[y]*o.data.stride+o.offset:m=l[y]*h;for(let f=0;f<h;f++)u[_++]=c[m++]}return new _i(u,h,d)}if(this.index===null)return Je("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;const t=new Bt,n=this.index.array,s=this.attributes;for(const o in s){const l=s[o],c=e(l,n);t.setAttribute(o,c)}const r=this.morphAttributes;for(const o in r){const l=[],c=r[o];for(let h=0,d=c.length;h<d;h++){const u=c[h],m=e(u,n);l.push(m)}t.morphAttributes[o]=l}t.morphTargetsRelative=this.morphTargetsRelative;const a=this.groups;for(let o=0,l=a.length;o<l;o++){const c=a[o];t.addGroup(c.start,c.count,c.materialIndex)}return t}toJSON(){const e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){const l=this.parameters;for(const c in l)l[c]!==void 0&&(e[c]=l[c]);return e}e.data={attributes:{}};const t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});const n=this.attributes;for(const l in n){const c=n[l];e.data.attributes[l]=c.toJSON(e.data)}const s={};let r=!1;for(const l in this.morphAttributes){const c=this.morphAttributes[l],h=[];for(let d=0,u=c.length;d<u;d++){const m=c[d];h.push(m.toJSON(e.data))}h.length>0&&(s[l]=h,r=!0)}r&&(e.data.morphAttributes=s,e.data.morphTargetsRelative=this.morphTargetsRelative);const a=this.groups;a.length>0&&(e.data.groups=JSON.parse(JSON.stringify(a)));const o=this.boundingSphere;return o!==null&&(e.data.boundingSphere=o.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;const t={};this.name=e.name;const n=e.index;n!==null&&this.setIndex(n.clone());const s=e.attributes;for(const c in s){const h=s[c];this.setAttribute(c,h.clone(t))}const r=e.morphAttributes;for(const c in r){const h=[],d=r[c];for(let u=0,m=d.length;u<m;u++)h.push(d[u].clone(t));this.morphAttributes[c]=h}this.morphTargetsRelative=e.morphTargetsRelative;const a=e.groups;for(let c=0,h=a.length;c<h;c++){const d=a[c];this.addGroup(d.start,d.count,d.materialIndex)}const o=e.boundingBox;o!==null&&(this.boundingBox=o.clone());const l=e.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}}class Cx{constructor(e,t){this.isInterleavedBuffer=!0,this.array=e,this.stride=t,this.count=e!==void 0?e.length/t:0,this.usage=Cm,this.updateRanges=[],this.version=0,this.uuid=nr()}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.array=new e.array.constructor(e.array),this.count=e.count,this.stride=e.stride,this.usage=e.usage,this}copyAt(e,t,n){e*=this.stride,n*=t.stride;for(let s=0,r=this.stride;s<r;s++)this.array[e+s]=t.array[n+s];return this}set(e,t=0){return this.array.set(e,t),this}clone(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});const t=rf(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=this.array.slice(0).buffer);const n=new this.array.constructor(e.arrayBuffers[t]),s=new this.constructor(n,this.stride);return s.setUsage(this.usage),s}onUpload(e){return this.onUploadCallback=e,this}toJSON(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});const t=rf(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=Array.from(new Uint32Array(this.array.slice(0).buffer)));const n={uuid:this.uuid,buffer:t,type:this.array.constructor.name,stride:this.stride};return n.usage=this.usage,n}}function rf(i){return i.buffer._uuid===void 0&&(i.buffer._uuid=nr()),i.byteOffset===0&&i.byteLength===i.buffer.byteLength?i.buffer._uuid:i.buffer._uuid+":"+i.byteOffset+":"+i.byteLength}const Wn=new B;class ll{constructor(e,t,n,s=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=e,this.itemSize=t,this.offset=n,this.normalized=s,this._normalizationScale=e!==void 0?bl(e.array):void 0}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(e){this.data.needsUpdate=e}applyMatrix4(e){for(let t=0,n=this.data.count;t<n;t++)Wn.fromBufferAttribute(this,t),Wn.applyMatrix4(e),this.setXYZ(t,Wn.x,Wn.y,Wn.z);return this}applyNormalMatrix(e){for(let t=0,n=this.count;t<n;t++)Wn.fromBufferAttribute(this,t),Wn.applyNormalMatrix(e),this.setXYZ(t,Wn.x,Wn.y,Wn.z);return this}transformDirection(e){for(let t=0,n=this.count;t<n;t++)Wn.fromBufferAttribute(this,t),Wn.transformDirection(e),this.setXYZ(t,Wn.x,Wn.y,Wn.z);return this}getComponent(e,t){let n=this.array[e*this.data.stride+this.offset+t];return this.normalized&&(n=this._denormalize(n)),n}setComponent(e,t,n){return this.normalized&&(n=this._normalize(n)),this.data.array[e*this.data.stride+this.offset+t]=n,this}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset]=t,this}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+1]=t,this}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+2]=t,this}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+3]=t,this}getX(e){let t=this.data.array[e*this.data.stride+this.offset];return this.normalized&&(t=this._denormalize(t)),t}getY(e){let t=this.data.array[e*this.data.stride+this.offset+1];return this.normalized&&(t=this._denormalize(t)),t}getZ(e){let t=this.data.array[e*this.data.stride+this.offset+2];return this.normalized&&(t=this._denormalize(t)),t}getW(e){let t=this.data.array[e*this.data.stride+this.offset+3];return this.normalized&&(t=this._denormalize(t)),t}setXY(e,t,n){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n)),this.data.array[e+0]=t,this.data.array[e+1]=n,this}setXYZ(e,t,n,s){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s)),this.data.array[e+0]=t,this.data.array[e+1]=n,this.data.array[e+2]=s,this}setXYZW(e,t,n,s,r){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.data.array[e+0]=t,this.data.array[e+1]=n,this.data.array[e+2]=s,this.data.array[e+3]=r,this}clone(e){if(e===void 0){ol("InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let n=0;n<this.count;n++){const s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return new _i(new this.array.constructor(t),this.itemSize,this.normalized)}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.clone(e)),new ll(e.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(e){if(e===void 0){ol("InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let n=0;n<this.count;n++){const s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:t,normalized:this.normalized}}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.toJSON(e)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}_denormalize(e){const t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):Lm(e,this.data.array)}_normalize(e){const t=this._normalizationScale;return t!==void 0?Math.round(e*t):Dm(e,this.data.array)}}const xc=new B,Px=new B,Lx=new it;class Ri{constructor(e=new B(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,n,s){return this.normal.set(e,t,n),this.constant=s,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,n){const s=xc.subVectors(n,t).cross(Px.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(s,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){const e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,n=!0){const s=e.delta(xc),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;const a=-(e.start.dot(this.normal)+this.constant)/r;return n===!0&&(a<0||a>1)?null:t.copy(e.start).addScaledVector(s,a)}intersectsLine(e){const t=this.distanceToPoint(e.start),n=this.distanceToPoint(e.end);return t<0&&n>0||n<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){const n=t||Lx.getNormalMatrix(e),s=this.coplanarPoint(xc).applyMatrix4(e),r=this.normal.applyMatrix3(n).normalize();return this.constant=-s.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}}let Dx=0;class ir extends Fs{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:Dx++}),this.uuid=nr(),this.name="",this.type="Material",this.blending=La,this.side=Ds,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=lm,this.blendDst=cm,this.blendEquation=Ur,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new lt(0,0,0),this.blendAlpha=0,this.depthFunc=Fa,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=ex,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=ec,this.stencilZFail=ec,this.stencilZPass=ec,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(const t in e){const n=e[t];if(n===void 0){Je(`Material: parameter '${t}' has value of undefined.`);continue}const s=this[t];if(s===void 0){Je(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(n):s&&s.isVector2&&n&&n.isVector2||s&&s.isEuler&&n&&n.isEuler||s&&s.isVector3&&n&&n.isVector3?s.copy(n):this[t]=n}}toJSON(e){const t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});const n={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};n.uuid=this.uuid,n.type=this.type,n.blending=this.blending,n.side=this.side,n.shadowSide=this.shadowSide,n.vertexColors=this.vertexColors,n.opacity=this.opacity,n.transparent=this.transparent,n.blendSrc=this.blendSrc,n.blendDst=this.blendDst,n.blendEquation=this.blendEquation,n.blendSrcAlpha=this.blendSrcAlpha,n.blendDstAlpha=this.blendDstAlpha,n.blendEquationAlpha=this.blendEquationAlpha,n.blendColor=this.blendColor.getHex(),n.blendAlpha=this.blendAlpha,n.depthFunc=this.depthFunc,n.depthTest=this.depthTest,n.depthWrite=this.depthWrite,n.colorWrite=this.colorWrite,n.clipIntersection=this.clipIntersection,n.clipShadows=this.clipShadows,n.stencilWriteMask=this.stencilWriteMask,n.stencilFunc=this.stencilFunc,n.stencilRef=this.stencilRef,n.stencilFuncMask=this.stencilFuncMask,n.stencilFail=this.stencilFail,n.stencilZFail=this.stencilZFail,n.stencilZPass=this.stencilZPass,n.stencilWrite=this.stencilWrite,n.polygonOffset=this.polygonOffset,n.polygonOffsetFactor=this.polygonOffsetFactor,n.polygonOffsetUnits=this.polygonOffsetUnits,n.dithering=this.dithering,n.alphaTest=this.alphaTest,n.alphaHash=this.alphaHash,n.alphaToCoverage=this.alphaToCoverage,n.premultipliedAlpha=this.premultipliedAlpha,n.forceSinglePass=this.forceSinglePass,n.allowOverride=this.allowOverride,n.visible=this.visible,n.toneMapped=this.toneMapped,n.name=this.name,this.color&&this.color.isColor&&(n.color=this.color.getHex()),this.roughness!==void 0&&(n.roughness=this.roughness),this.metalness!==void 0&&(n.metalness=this.metalness),this.sheen!==void 0&&(n.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(n.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(n.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(n.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(n.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(n.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(n.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(n.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(n.shininess=this.shininess),this.clearcoat!==void 0&&(n.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(n.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(n.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(n.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(n.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(n.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(n.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,n.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(n.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(n.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(n.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(n.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(n.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(n.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(n.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(n.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(n.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(n.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(n.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(n.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(n.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(n.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(n.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(n.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(n.lightMap=this.lightMap.toJSON(e).uuid,n.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(n.aoMap=this.aoMap.toJSON(e).uuid,n.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(n.bumpMap=this.bumpMap.toJSON(e).uuid,n.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(n.normalMap=this.normalMap.toJSON(e).uuid,n.normalMapType=this.normalMapType,n.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(n.displacementMap=this.displacementMap.toJSON(e).uuid,n.displacementScale=this.displacementScale,n.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(n.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(n.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(n.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(n.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(n.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(n.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(n.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(n.combine=this.combine)),this.envMapRotation!==void 0&&(n.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(n.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(n.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(n.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(n.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(n.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(n.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(n.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(n.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(n.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(n.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(n.size=this.size),this.sizeAttenuation!==void 0&&(n.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(n.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(n.rotation=this.rotation),this.depthPacking!==void 0&&(n.depthPacking=this.depthPacking),this.linewidth!==void 0&&(n.linewidth=this.linewidth),this.linecap!==void 0&&(n.linecap=this.linecap),this.linejoin!==void 0&&(n.linejoin=this.linejoin),this.dashSize!==void 0&&(n.dashSize=this.dashSize),this.gapSize!==void 0&&(n.gapSize=this.gapSize),this.scale!==void 0&&(n.scale=this.scale),this.wireframe!==void 0&&(n.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(n.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(n.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(n.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(n.flatShading=this.flatShading),this.fog!==void 0&&(n.fog=this.fog),Object.keys(this.userData).length>0&&(n.userData=this.userData);function s(r){const a=[];for(const o in r){const l=r[o];delete l.metadata,a.push(l)}return a}if(t){const r=s(e.textures),a=s(e.images);r.length>0&&(n.textures=r),a.length>0&&(n.images=a)}return n}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new lt().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(n=>new Ri().fromJSON(n))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let n=e.normalScale;Array.isArray(n)===!1&&(n=[n,n]),this.normalScale=new Xe().fromArray(n)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new Xe().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;const t=e.clippingPlanes;let n=null;if(t!==null){const s=t.length;n=new Array(s);for(let r=0;r!==s;++r)n[r]=t[r].clone()}return this.clippingPlanes=n,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}}class km extends ir{constructor(e){super(),this.isSpriteMaterial=!0,this.type="SpriteMaterial",this.color=new lt(16777215),this.map=null,this.alphaMap=null,this.rotation=0,this.sizeAttenuation=!0,this.transparent=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.rotation=e.rotation,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}}let Ar;const _a=new B,Rr=new B,Cr=new B,Pr=new Xe,va=new Xe,Bm=new Dt,vo=new B,xa=new B,xo=new B,af=new Xe,yc=new Xe,of=new Xe;class zm extends yn{constructor(e=new km){if(super(),this.isSprite=!0,this.type="Sprite",Ar===void 0){Ar=new Bt;const t=new Float32Array([-.5,-.5,0,0,0,.5,-.5,0,1,0,.5,.5,0,1,1,-.5,.5,0,0,1]),n=new Cx(t,5);Ar.setIndex([0,1,2,0,2,3]),Ar.setAttribute("position",new ll(n,3,0,!1)),Ar.setAttribute("uv",new ll(n,2,3,!1))}this.geometry=Ar,this.material=e,this.center=new Xe(.5,.5),this.count=1}intersectsFrustum(e){return e.intersectsSprite(this)}raycast(e,t){e.camera===null&&xt('Sprite: "Raycaster.camera" needs to be set in order to raycast against sprites.'),Rr.setFromMatrixScale(this.matrixWorld),Bm.copy(e.camera.matrixWorld),this.modelViewMatrix.multiplyMatrices(e.camera.matrixWorldInverse,this.matrixWorld),Cr.setFromMatrixPosition(this.modelViewMatrix),e.camera.isPerspectiveCamera&&this.material.sizeAttenuation===!1&&Rr.multiplyScalar(-Cr.z);const n=this.material.rotation;let s,r;n!==0&&(r=Math.cos(n),s=Math.sin(n));const a=this.center;yo(vo.set(-.5,-.5,0),Cr,a,Rr,s,r),yo(xa.set(.5,-.5,0),Cr,a,Rr,s,r),yo(xo.set(.5,.5,0),Cr,a,Rr,s,r),af.set(0,0),yc.set(1,0),of.set(1,1);let o=e.ray.intersectTriangle(vo,xa,xo,!1,_a);if(o===null&&(yo(xa.set(-.5,.5,0),Cr,a,Rr,s,r),yc.set(0,1),o=e.ray.intersectTriangle(vo,xo,xa,!1,_a),o===null))return;const l=e.ray.origin.distanceTo(_a);l<e.near||l>e.far||t.push({distance:l,point:_a.clone(),uv:mi.getInterpolation(_a,vo,xa,xo,af,yc,of,new Xe),face:null,object:this})}copy(e,t){return super.copy(e,t),e.center!==void 0&&this.center.copy(e.center),this.material=e.material,this}toJSON(e){const t=super.toJSON(e);return t.object.center=this.center.toArray(),t}}function yo(i,e,t,n,s,r){Pr.subVectors(i,t).addScalar(.5).multiply(n),s!==void 0?(va.x=r*Pr.x-s*Pr.y,va.y=s*Pr.x+r*Pr.y):va.copy(Pr),i.copy(e),i.x+=va.x,i.y+=va.y,i.applyMatrix4(Bm)}const os=new B,Sc=new B,So=new B,Mo=new B;class wl{constructor(e=new B,t=new B(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,os)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);const n=t.dot(this.direction);return n<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,n)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){const t=os.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(os.copy(this.origin).addScaledVector(this.direction,t),os.distanceToSquared(e))}distanceSqToSegment(e,t,n,s){Sc.copy(e).add(t).multiplyScalar(.5),So.copy(t).sub(e).normalize(),Mo.copy(this.origin).sub(Sc);const r=e.distanceTo(t)*.5,a=-this.direction.dot(So),o=Mo.dot(this.direction),l=-Mo.dot(So),c=Mo.lengthSq(),h=Math.abs(1-a*a);let d,u,m,_;if(h>0)if(d=a*l-o,u=a*o-l,_=r*h,d>=0)if(u>=-_)if(u<=_){const y=1/h;d*=y,u*=y,m=d*(d+a*u+2*o)+u*(a*d+u+2*l)+c}else u=r,d=Math.max(0,-(a*u+o)),m=-d*d+u*(u+2*l)+c;else u=-r,d=Math.max(0,-(a*u+o)),m=-d*d+u*(u+2*l)+c;else u<=-_?(d=Math.max(0,-(-a*r+o)),u=d>0?-r:Math.min(Math.max(-r,-l),r),m=-d*d+u*(u+2*l)+c):u<=_?(d=0,u=Math.min(Math.max(-r,-l),r),m=u*(u+2*l)+c):(d=Math.max(0,-(a*r+o)),u=d>0?r:Math.min(Math.max(-r,-l),r),m=-d*d+u*(u+2*l)+c);else u=a>0?-r:r,d=Math.max(0,-(a*u+o)),m=-d*d+u*(u+2*l)+c;return n&&n.copy(this.origin).addScaledVector(this.direction,d),s&&s.copy(Sc).addScaledVector(So,u),m}intersectSphere(e,t){if(e.radius<0)return null;os.subVectors(e.center,this.origin);const n=os.dot(this.direction),s=os.dot(os)-n*n,r=e.radius*e.radius;if(s>r)return null;const a=Math.sqrt(r-s),o=n-a,l=n+a;return l<0?null:o<0?this.at(l,t):this.at(o,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){const t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;const n=-(this.origin.dot(e.normal)+e.constant)/t;return n>=0?n:null}intersectPlane(e,t){const n=this.distanceToPlane(e);return n===null?null:this.at(n,t)}intersectsPlane(e){const t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let n,s,r,a,o,l;const c=1/this.direction.x,h=1/this.direction.y,d=1/this.direction.z,u=this.origin;return c>=0?(n=(e.min.x-u.x)*c,s=(e.max.x-u.x)*c):(n=(e.max.x-u.x)*c,s=(e.min.x-u.x)*c),h>=0?(r=(e.min.y-u.y)*h,a=(e.max.y-u.y)*h):(r=(e.max.y-u.y)*h,a=(e.min.y-u.y)*h),n>a||r>s||((r>n||isNaN(n))&&(n=r),(a<s||isNaN(s))&&(s=a),d>=0?(o=(e.min.z-u.z)*d,l=(e.max.z-u.z)*d):(o=(e.max.z-u.z)*d,l=(e.min.z-u.z)*d),n>l||o>s)||((o>n||n!==n)&&(n=o),(l<s||s!==s)&&(s=l),s<0)?null:this.at(n>=0?n:s,t)}intersectsBox(e){return this.intersectBox(e,os)!==null}intersectTriangle(e,t,n,s,r){const a=this.origin,o=this.direction,l=o.x,c=o.y,h=o.z,d=e.x-a.x,u=e.y-a.y,m=e.z-a.z,_=t.x-a.x,y=t.y-a.y,p=t.z-a.z,f=n.x-a.x,x=n.y-a.y,A=n.z-a.z,M=Math.abs(l),C=Math.abs(c),b=Math.abs(h);let g,w,F,L,D,z,V,U,W,K,G,le;if(M>=C&&M>=b?(F=l,z=d,W=_,le=f,l>=0?(g=c,w=h,L=u,D=m,V=y,U=p,K=x,G=A):(g=h,w=c,L=m,D=u,V=p,U=y,K=A,G=x)):C>=b?(F=c,z=u,W=y,le=x,c>=0?(g=h,w=l,L=m,D=d,V=p,U=_,K=A,G=f):(g=l,w=h,L=d,D=m,V=_,U=p,K=f,G=A)):(F=h,z=m,W=p,le=A,h>=0?(g=l,w=c,L=d,D=u,V=_,U=y,K=f,G=x):(g=c,w=l,L=u,D=d,V=y,U=_,K=x,G=f)),F===0)return null;const J=g/F,Q=w/F,se=1/F,de=L-J*z,ue=D-Q*z,ee=V-J*W,me=U-Q*W,ve=K-J*le,Ae=G-Q*le,Me=ve*me-Ae*ee,Ve=de*Ae-ue*ve,tt=ee*ue-me*de;if(s){if(Me<0||Ve<0||tt<0)return null}else if((Me<0||Ve<0||tt<0)&&(Me>0||Ve>0||tt>0))return null;const He=Me+Ve+tt;if(He===0)return null;const ct=se*(Me*z+Ve*W+tt*le);return(He>0?ct<0:ct>0)?null:this.at(ct/He,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}}class Ps extends ir{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new lt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Us,this.combine=hm,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}}const lf=new Dt,Gs=new wl,bo=new Ya,cf=new B,wo=new B,Eo=new B,To=new B,Mc=new B,Ao=new B,hf=new B,Ro=new B;class sn extends yn{constructor(e=new Bt,t=new Ps){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){const t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){const s=t[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}getVertexPosition(e,t){const n=this.geometry,s=n.attributes.position,r=n.morphAttributes.position,a=n.morphTargetsRelative;t.fromBufferAttribute(s,e);const o=this.morphTargetInfluences;if(r&&o){Ao.set(0,0,0);for(let l=0,c=r.length;l<c;l++){const h=o[l],d=r[l];h!==0&&(Mc.fromBufferAttribute(d,e),a?Ao.addScaledVector(Mc,h):Ao.addScaledVector(Mc.sub(t),h))}t.add(Ao)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){const n=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(n.boundingSphere===null&&n.computeBoundingSphere(),bo.copy(n.boundingSphere),bo.applyMatrix4(r),Gs.copy(e.ray).recast(e.near),!(bo.containsPoint(Gs.origin)===!1&&(Gs.intersectSphere(bo,cf)===null||Gs.origin.distanceToSquared(cf)>(e.far-e.near)**2))&&(lf.copy(r).invert(),Gs.copy(e.ray).applyMatrix4(lf),!(n.boundingBox!==null&&Gs.intersectsBox(n.boundingBox)===!1)&&this._computeIntersections(e,t,Gs)))}_computeIntersections(e,t,n){let s;const r=this.geometry,a=this.material,o=r.index,l=r.attributes.position,c=r.attributes.uv,h=r.attributes.uv1,d=r.attributes.normal,u=r.groups,m=r.drawRange;if(o!==null)if(Array.isArray(a))for(let _=0,y=u.length;_<y;_++){const p=u[_],f=a[p.materialIndex],x=Math.max(p.start,m.start),A=Math.min(o.count,Math.min(p.start+p.count,m.start+m.count));for(let M=x,C=A;M<C;M+=3){const b=o.getX(M),g=o.getX(M+1),w=o.getX(M+2);s=Co(this,f,e,n,c,h,d,b,g,w),s&&(s.faceIndex=Math.floor(M/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{const _=Math.max(0,m.start),y=Math.min(o.count,m.start+m.count);for(let p=_,f=y;p<f;p+=3){const x=o.getX(p),A=o.getX(p+1),M=o.getX(p+2);s=Co(this,a,e,n,c,h,d,x,A,M),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}else if(l!==void 0)if(Array.isArray(a))for(let _=0,y=u.length;_<y;_++){const p=u[_],f=a[p.materialIndex],x=Math.max(p.start,m.start),A=Math.min(l.count,Math.min(p.start+p.count,m.start+m.count));for(let M=x,C=A;M<C;M+=3){const b=M,g=M+1,w=M+2;s=Co(this,f,e,n,c,h,d,b,g,w),s&&(s.faceIndex=Math.floor(M/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{const _=Math.max(0,m.start),y=Math.min(l.count,m.start+m.count);for(let p=_,f=y;p<f;p+=3){const x=p,A=p+1,M=p+2;s=Co(this,a,e,n,c,h,d,x,A,M),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}}}function Nx(i,e,t,n,s,r,a,o){let l;if(e.side===Zn?l=n.intersectTriangle(a,r,s,!0,o):l=n.intersectTriangle(s,r,a,e.side===Ds,o),l===null)return null;Ro.copy(o),Ro.applyMatrix4(i.matrixWorld);const c=t.ray.origin.distanceTo(Ro);return c<t.near||c>t.far?null:{distance:c,point:Ro.clone(),object:i}}function Co(i,e,t,n,s,r,a,o,l,c){i.getVertexPosition(o,wo),i.getVertexPosition(l,Eo),i.getVertexPosition(c,To);const h=Nx(i,e,t,n,wo,Eo,To,hf);if(h){const d=new B;mi.getBarycoord(hf,wo,Eo,To,d),s&&(h.uv=mi.getInterpolatedAttribute(s,o,l,c,d,new Xe)),r&&(h.uv1=mi.getInterpolatedAttribute(r,o,l,c,d,new Xe)),a&&(h.normal=mi.getInterpolatedAttribute(a,o,l,c,d,new B),h.normal.dot(n.direction)>0&&h.normal.multiplyScalar(-1));const u={a:o,b:l,c,normal:new B,materialIndex:0};mi.getNormal(wo,Eo,To,u.normal),h.face=u,h.barycoord=d}return h}class Ix extends kn{constructor(e=null,t=1,n=1,s,r,a,o,l,c=Dn,h=Dn,d,u){super(null,a,o,l,c,h,s,r,d,u),this.isDataTexture=!0,this.image={data:e,width:t,height:n},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}}const Vs=new Ya,Ux=new Xe(.5,.5),Po=new B;class za{constructor(e=new Ri,t=new Ri,n=new Ri,s=new Ri,r=new Ri,a=new Ri){this.planes=[e,t,n,s,r,a]}set(e,t,n,s,r,a){const o=this.planes;return o[0].copy(e),o[1].copy(t),o[2].copy(n),o[3].copy(s),o[4].copy(r),o[5].copy(a),this}copy(e){const t=this.planes;for(let n=0;n<6;n++)t[n].copy(e.planes[n]);return this}setFromProjectionMatrix(e,t=Pi,n=!1){const s=this.planes,r=e.elements,a=r[0],o=r[1],l=r[2],c=r[3],h=r[4],d=r[5],u=r[6],m=r[7],_=r[8],y=r[9],p=r[10],f=r[11],x=r[12],A=r[13],M=r[14],C=r[15];if(s[0].setComponents(c-a,m-h,f-_,C-x).normalize(),s[1].setComponents(c+a,m+h,f+_,C+x).normalize(),s[2].setComponents(c+o,m+d,f+y,C+A).normalize(),s[3].setComponents(c-o,m-d,f-y,C-A).normalize(),n)s[4].setComponents(l,u,p,M).normalize(),s[5].setComponents(c-l,m-u,f-p,C-M).normalize();else if(s[4].setComponents(c-l,m-u,f-p,C-M).normalize(),t===Pi)s[5].setComponents(c+l,m+u,f+p,C+M).normalize();else if(t===Ba)s[5].setComponents(l,u,p,M).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Vs.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{const t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Vs.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Vs)}intersectsSprite(e){Vs.center.set(0,0,0);const t=Ux.distanceTo(e.center);return Vs.radius=.7071067811865476+t,Vs.applyMatrix4(e.matrixWorld),this.intersectsSphere(Vs)}intersectsSphere(e){const t=this.planes,n=e.center,s=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(n)<s)return!1;return!0}intersectsBox(e){const t=this.planes;for(let n=0;n<6;n++){const s=t[n];if(Po.x=s.normal.x>0?e.max.x:e.min.x,Po.y=s.normal.y>0?e.max.y:e.min.y,Po.z=s.normal.z>0?e.max.z:e.min.z,s.distanceToPoint(Po)<0)return!1}return!0}containsPoint(e){const t=this.planes;for(let n=0;n<6;n++)if(t[n].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}}const uf=new Dt;class wu{constructor(){this.coordinateSystem=Pi,this._frustums=[],this._count=0}setFromArrayCamera(e){const t=e.cameras,n=this._frustums;for(let s=0;s<t.length;s++){const r=t[s];uf.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),n[s]===void 0&&(n[s]=new za),n[s].setFromProjectionMatrix(uf,r.coordinateSystem,r.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsObject(e))return!0;return!1}intersectsSprite(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsSprite(e))return!0;return!1}intersectsSphere(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsSphere(e))return!0;return!1}intersectsBox(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsBox(e))return!0;return!1}containsPoint(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;const t=this._frustums,n=e._frustums;for(let s=0;s<e._count;s++)t[s]===void 0&&(t[s]=new za),t[s].copy(n[s]);return this._count=e._count,this}clone(){return new wu().copy(this)}}class vi extends ir{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new lt(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}}const cl=new B,hl=new B,df=new Dt,ya=new wl,Lo=new Ya,bc=new B,ff=new B;class Ji extends yn{constructor(e=new Bt,t=new vi){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,n=[0];for(let s=1,r=t.count;s<r;s++)cl.fromBufferAttribute(t,s-1),hl.fromBufferAttribute(t,s),n[s]=n[s-1],n[s]+=cl.distanceTo(hl);e.setAttribute("lineDistance",new rn(n,1))}else Je("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){const n=this.geometry,s=this.matrixWorld,r=e.params.Line.threshold,a=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),Lo.copy(n.boundingSphere),Lo.applyMatrix4(s),Lo.radius+=r,e.ray.intersectsSphere(Lo)===!1)return;df.copy(s).invert(),ya.copy(e.ray).applyMatrix4(df);const o=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=o*o,c=this.isLineSegments?2:1,h=n.index,u=n.attributes.position;if(h!==null){const m=Math.max(0,a.start),_=Math.min(h.count,a.start+a.count);for(let y=m,p=_-1;y<p;y+=c){const f=h.getX(y),x=h.getX(y+1),A=Do(this,e,ya,l,f,x,y);A&&t.push(A)}if(this.isLineLoop){const y=h.getX(_-1),p=h.getX(m),f=Do(this,e,ya,l,y,p,_-1);f&&t.push(f)}}else{const m=Math.max(0,a.start),_=Math.min(u.count,a.start+a.count);for(let y=m,p=_-1;y<p;y+=c){const f=Do(this,e,ya,l,y,y+1,y);f&&t.push(f)}if(this.isLineLoop){const y=Do(this,e,ya,l,_-1,m,_-1);y&&t.push(y)}}}updateMorphTargets(){const t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){const s=t[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}}function Do(i,e,t,n,s,r,a){const o=i.geometry.attributes.position;if(cl.fromBufferAttribute(o,s),hl.fromBufferAttribute(o,r),t.distanceSqToSegment(cl,hl,bc,ff)>n)return;bc.applyMatrix4(i.matrixWorld);const c=e.ray.origin.distanceTo(bc);if(!(c<e.near||c>e.far))return{distance:c,point:ff.clone().applyMatrix4(i.matrixWorld),index:a,face:null,faceIndex:null,barycoord:null,object:i}}const pf=new B,mf=new B;class El extends Ji{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,n=[];for(let s=0,r=t.count;s<r;s+=2)pf.fromBufferAttribute(t,s),mf.fromBufferAttribute(t,s+1),n[s]=s===0?0:n[s-1],n[s+1]=n[s]+pf.distanceTo(mf);e.setAttribute("lineDistance",new rn(n,1))}else Je("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}}class Fx extends Ji{constructor(e,t){super(e,t),this.isLineLoop=!0,this.type="LineLoop"}}class Hm extends kn{constructor(e=[],t=Kr,n,s,r,a,o,l,c,h){super(e,t,n,s,r,a,o,l,c,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}}class Ox extends kn{constructor(e,t,n,s,r,a,o,l,c){super(e,t,n,s,r,a,o,l,c),this.isCanvasTexture=!0,this.needsUpdate=!0}}class Jr extends kn{constructor(e,t,n=Ki,s,r,a,o=Dn,l=Dn,c,h=Ns,d=1){if(h!==Ns&&h!==Cs)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");const u={width:e,height:t,depth:d};super(u,s,r,a,o,l,h,n,c),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new Mu(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){const t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}}class Gm extends Jr{constructor(e,t=Ki,n=Kr,s,r,a=Dn,o=Dn,l,c=Ns){const h={width:e,height:e,depth:1},d=[h,h,h,h,h,h];super(e,e,t,n,s,r,a,o,l,c),this.image=d,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}}class Vm extends kn{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}}class Ka extends Bt{constructor(e=1,t=1,n=1,s=1,r=1,a=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:n,widthSegments:s,heightSegments:r,depthSegments:a};const o=this;s=Math.floor(s),r=Math.floor(r),a=Math.floor(a);const l=[],c=[],h=[],d=[];let u=0,m=0;_("z","y","x",-1,-1,n,t,e,a,r,0),_("z","y","x",1,-1,n,t,-e,a,r,1),_("x","z","y",1,1,e,n,t,s,a,2),_("x","z","y",1,-1,e,n,-t,s,a,3),_("x","y","z",1,-1,e,t,n,s,r,4),_("x","y","z",-1,-1,e,t,-n,s,r,5),this.setIndex(l),this.setAttribute("position",new rn(c,3)),this.setAttribute("normal",new rn(h,3)),this.setAttribute("uv",new rn(d,2));function _(y,p,f,x,A,M,C,b,g,w,F){const L=M/g,D=C/w,z=M/2,V=C/2,U=b/2,W=g+1,K=w+1;let G=0,le=0;const J=new B;for(let Q=0;Q<K;Q++){const se=Q*D-V;for(let de=0;de<W;de++){const ue=de*L-z;J[y]=ue*x,J[p]=se*A,J[f]=U,c.push(J.x,J.y,J.z),J[y]=0,J[p]=0,J[f]=b>0?1:-1,h.push(J.x,J.y,J.z),d.push(de/g),d.push(1-Q/w),G+=1}}for(let Q=0;Q<w;Q++)for(let se=0;se<g;se++){const de=u+se+W*Q,ue=u+se+W*(Q+1),ee=u+(se+1)+W*(Q+1),me=u+(se+1)+W*Q;l.push(de,ue,me),l.push(ue,ee,me),le+=6}o.addGroup(m,le,F),m+=le,u+=G}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Ka(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}}class Za extends Bt{constructor(e=1,t=1,n=1,s=32,r=1,a=!1,o=0,l=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:e,radiusBottom:t,height:n,radialSegments:s,heightSegments:r,openEnded:a,thetaStart:o,thetaLength:l};const c=this;s=Math.floor(s),r=Math.floor(r);const h=[],d=[],u=[],m=[];let _=0;const y=[],p=n/2;let f=0;x(),a===!1&&(e>0&&A(!0),t>0&&A(!1)),this.setIndex(h),this.setAttribute("position",new rn(d,3)),this.setAttribute("normal",new rn(u,3)),this.setAttribute("uv",new rn(m,2));function x(){const M=new B,C=new B;let b=0;const g=(t-e)/n;for(let w=0;w<=r;w++){const F=[],L=w/r,D=L*(t-e)+e;for(let z=0;z<=s;z++){const V=z/s,U=V*l+o,W=Math.sin(U),K=Math.cos(U);C.x=D*W,C.y=-L*n+p,C.z=D*K,d.push(C.x,C.y,C.z),M.set(W,g,K).normalize(),u.push(M.x,M.y,M.z),m.push(V,1-L),F.push(_++)}y.push(F)}for(let w=0;w<s;w++)for(let F=0;F<r;F++){const L=y[F][w],D=y[F+1][w],z=y[F+1][w+1],V=y[F][w+1];(e>0||F!==0)&&(h.push(L,D,V),b+=3),(t>0||F!==r-1)&&(h.push(D,z,V),b+=3)}c.addGroup(f,b,0),f+=b}function A(M){const C=_,b=new Xe,g=new B;let w=0;const F=M===!0?e:t,L=M===!0?1:-1;for(let z=1;z<=s;z++)d.push(0,p*L,0),u.push(0,L,0),m.push(.5,.5),_++;const D=_;for(let z=0;z<=s;z++){const U=z/s*l+o,W=Math.cos(U),K=Math.sin(U);g.x=F*K,g.y=p*L,g.z=F*W,d.push(g.x,g.y,g.z),u.push(0,L,0),b.x=W*.5+.5,b.y=K*.5*L+.5,m.push(b.x,b.y),_++}for(let z=0;z<s;z++){const V=C+z,U=D+z;M===!0?h.push(U,U+1,V):h.push(U+1,U,V),w+=3}c.addGroup(f,w,M===!0?1:2),f+=w}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Za(e.radiusTop,e.radiusBottom,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}}class Eu extends Za{constructor(e=1,t=1,n=32,s=1,r=!1,a=0,o=Math.PI*2){super(0,e,t,n,s,r,a,o),this.type="ConeGeometry",this.parameters={radius:e,height:t,radialSegments:n,heightSegments:s,openEnded:r,thetaStart:a,thetaLength:o}}static fromJSON(e){return new Eu(e.radius,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}}class Tl extends Bt{constructor(e=1,t=1,n=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:n,heightSegments:s};const r=e/2,a=t/2,o=Math.floor(n),l=Math.floor(s),c=o+1,h=l+1,d=e/o,u=t/l,m=[],_=[],y=[],p=[];for(let f=0;f<h;f++){const x=f*u-a;for(let A=0;A<c;A++){const M=A*d-r;_.push(M,-x,0),y.push(0,0,1),p.push(A/o),p.push(1-f/l)}}for(let f=0;f<l;f++)for(let x=0;x<o;x++){const A=x+c*f,M=x+c*(f+1),C=x+1+c*(f+1),b=x+1+c*f;m.push(A,M,b),m.push(M,C,b)}this.setIndex(m),this.setAttribute("position",new rn(_,3)),this.setAttribute("normal",new rn(y,3)),this.setAttribute("uv",new rn(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Tl(e.width,e.height,e.widthSegments,e.heightSegments)}}class cs extends Bt{constructor(e=1,t=32,n=16,s=0,r=Math.PI*2,a=0,o=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:e,widthSegments:t,heightSegments:n,phiStart:s,phiLength:r,thetaStart:a,thetaLength:o},t=Math.max(3,Math.floor(t)),n=Math.max(2,Math.floor(n));const l=Math.min(a+o,Math.PI);let c=0;const h=[],d=new B,u=new B,m=[],_=[],y=[],p=[];for(let f=0;f<=n;f++){const x=[],A=f/n,M=a+A*o,C=e*Math.cos(M),b=Math.sqrt(e*e-C*C);let g=0;f===0&&a===0?g=.5/t:f===n&&l===Math.PI&&(g=-.5/t);for(let w=0;w<=t;w++){const F=w/t,L=s+F*r;d.x=-b*Math.cos(L),d.y=C,d.z=b*Math.sin(L),_.push(d.x,d.y,d.z),u.copy(d).normalize(),y.push(u.x,u.y,u.z),p.push(F+g,1-A),x.push(c++)}h.push(x)}for(let f=0;f<n;f++)for(let x=0;x<t;x++){const A=h[f][x+1],M=h[f][x],C=h[f+1][x],b=h[f+1][x+1];(f!==0||a>0)&&m.push(A,M,b),(f!==n-1||l<Math.PI)&&m.push(M,C,b)}this.setIndex(m),this.setAttribute("position",new rn(_,3)),this.setAttribute("normal",new rn(y,3)),this.setAttribute("uv",new rn(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new cs(e.radius,e.widthSegments,e.heightSegments,e.phiStart,e.phiLength,e.thetaStart,e.thetaLength)}}function jr(i){const e={};for(const t in i){e[t]={};for(const n in i[t]){const s=i[t][n];if(gf(s))s.isRenderTargetTexture?(Je("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][n]=null):e[t][n]=s.clone();else if(Array.isArray(s))if(gf(s[0])){const r=[];for(let a=0,o=s.length;a<o;a++)r[a]=s[a].clone();e[t][n]=r}else e[t][n]=s.slice();else e[t][n]=s}}return e}function Xn(i){const e={};for(let t=0;t<i.length;t++){const n=jr(i[t]);for(const s in n)e[s]=n[s]}return e}function gf(i){return i&&(i.isColor||i.isMatrix3||i.isMatrix4||i.isVector2||i.isVector3||i.isVector4||i.isTexture||i.isQuaternion)}function kx(i){const e=[];for(let t=0;t<i.length;t++)e.push(i[t].clone());return e}function Wm(i){const e=i.getRenderTarget();return e===null?i.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:_t.workingColorSpace}const Bx={clone:jr,merge:Xn};var zx=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,Hx=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`;class Qs extends ir{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=zx,this.fragmentShader=Hx,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=jr(e.uniforms),this.uniformsGroups=kx(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){const t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(const s in this.uniforms){const a=this.uniforms[s].value;a&&a.isTexture?t.uniforms[s]={type:"t",value:a.toJSON(e).uuid}:a&&a.isColor?t.uniforms[s]={type:"c",value:a.getHex()}:a&&a.isVector2?t.uniforms[s]={type:"v2",value:a.toArray()}:a&&a.isVector3?t.uniforms[s]={type:"v3",value:a.toArray()}:a&&a.isVector4?t.uniforms[s]={type:"v4",value:a.toArray()}:a&&a.isMatrix3?t.uniforms[s]={type:"m3",value:a.toArray()}:a&&a.isMatrix4?t.uniforms[s]={type:"m4",value:a.toArray()}:t.uniforms[s]={value:a}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;const n={};for(const s in this.extensions)this.extensions[s]===!0&&(n[s]=!0);return Object.keys(n).length>0&&(t.extensions=n),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(const n in e.uniforms){const s=e.uniforms[n];switch(this.uniforms[n]={},s.type){case"t":this.uniforms[n].value=t[s.value]||null;break;case"c":this.uniforms[n].value=new lt().setHex(s.value);break;case"v2":this.uniforms[n].value=new Xe().fromArray(s.value);break;case"v3":this.uniforms[n].value=new B().fromArray(s.value);break;case"v4":this.uniforms[n].value=new nn().fromArray(s.value);break;case"m3":this.uniforms[n].value=new it().fromArray(s.value);break;case"m4":this.uniforms[n].value=new Dt().fromArray(s.value);break;default:this.uniforms[n].value=s.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(const n in e.extensions)this.extensions[n]=e.extensions[n];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}}class Gx extends Qs{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}}class Gr extends ir{constructor(e){super(),this.isMeshStandardMaterial=!0,this.type="MeshStandardMaterial",this.defines={STANDARD:""},this.color=new lt(16777215),this.roughness=1,this.metalness=0,this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new lt(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=Oh,this.normalScale=new Xe(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.roughnessMap=null,this.metalnessMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Us,this.envMapIntensity=1,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.defines={STANDARD:""},this.color.copy(e.color),this.roughness=e.roughness,this.metalness=e.metalness,this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.emissive.copy(e.emissive),this.emissiveMap=e.emissiveMap,this.emissiveIntensity=e.emissiveIntensity,this.bumpMap=e.bumpMap,this.bumpScale=e.bumpScale,this.normalMap=e.normalMap,this.normalMapType=e.normalMapType,this.normalScale.copy(e.normalScale),this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.roughnessMap=e.roughnessMap,this.metalnessMap=e.metalnessMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.envMapIntensity=e.envMapIntensity,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.flatShading=e.flatShading,this.fog=e.fog,this}}class Vx extends ir{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=jv,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}}class Wx extends ir{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}}class Xm extends vi{constructor(e){super(),this.isLineDashedMaterial=!0,this.type="LineDashedMaterial",this.scale=1,this.dashSize=3,this.gapSize=1,this.setValues(e)}copy(e){return super.copy(e),this.scale=e.scale,this.dashSize=e.dashSize,this.gapSize=e.gapSize,this}}class $m extends yn{static registerNode(e){this.prototype._lightNode=e}constructor(e,t=1){super(),this.isLight=!0,this.type="Light",this.color=new lt(e),this.intensity=t}copy(e,t){return super.copy(e,t),this.color.copy(e.color),this.intensity=e.intensity,this}toJSON(e){const t=super.toJSON(e);return t.object.color=this.color.getHex(),t.object.intensity=this.intensity,t}}const wc=new Dt,_f=new B,vf=new B;class Xx{constructor(e){this.camera=e,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new Xe(512,512),this.mapType=si,this.map=null,this.mapPass=null,this.matrix=new Dt,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new za,this._frameExtents=new Xe(1,1),this._viewportCount=1,this._viewports=[new nn(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(e){const t=this.camera;_f.setFromMatrixPosition(e.matrixWorld),t.position.copy(_f),vf.setFromMatrixPosition(e.target.matrixWorld),t.lookAt(vf),t.updateMatrixWorld(),this._updateMatrix(t,this.matrix,this._frustum)}_updateMatrix(e,t,n,s){wc.multiplyMatrices(e.projectionMatrix,e.matrixWorldInverse),n.setFromProjectionMatrix(wc,e.coordinateSystem,e.reversedDepth);const r=this._frameExtents,a=s?s.z/r.x:1,o=s?s.w/r.y:1,l=s?s.x/r.x:0,c=s?s.y/r.y:0;e.coordinateSystem===Ba||e.reversedDepth?t.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,1,0,0,0,0,1):t.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,.5,.5,0,0,0,1),t.multiply(wc)}getViewport(e){return this._viewports[e]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(e){return this.camera=e.camera.clone(),this.intensity=e.intensity,this.bias=e.bias,this.radius=e.radius,this.autoUpdate=e.autoUpdate,this.needsUpdate=e.needsUpdate,this.normalBias=e.normalBias,this.blurSamples=e.blurSamples,this.mapSize.copy(e.mapSize),this.mapType=e.mapType,this.biasNode=e.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){const e={};return e.intensity=this.intensity,e.bias=this.bias,e.normalBias=this.normalBias,e.radius=this.radius,e.blurSamples=this.blurSamples,e.mapSize=this.mapSize.toArray(),e.mapType=this.mapType,e.camera=this.camera.toJSON(!1).object,delete e.camera.matrix,e}}const No=new B,Io=new Is,Bi=new B;class qm extends yn{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new Dt,this.projectionMatrix=new Dt,this.projectionMatrixInverse=new Dt,this.coordinateSystem=Pi,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(No,Io,Bi),Bi.x===1&&Bi.y===1&&Bi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(No,Io,Bi.set(1,1,1)).invert()}updateWorldMatrix(e,t,n=!1){super.updateWorldMatrix(e,t,n),this.matrixWorld.decompose(No,Io,Bi),Bi.x===1&&Bi.y===1&&Bi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(No,Io,Bi.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}}const ws=new B,xf=new Xe,yf=new Xe;class Yn extends qm{constructor(e=50,t=1,n=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=n,this.far=s,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){const t=.5*this.getFilmHeight()/e;this.fov=kh*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){const e=Math.tan(Da*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return kh*2*Math.atan(Math.tan(Da*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,n){ws.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(ws.x,ws.y).multiplyScalar(-e/ws.z),ws.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),n.set(ws.x,ws.y).multiplyScalar(-e/ws.z)}getViewSize(e,t){return this.getViewBounds(e,xf,yf),t.subVectors(yf,xf)}setViewOffset(e,t,n,s,r,a){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=this.near;let t=e*Math.tan(Da*.5*this.fov)/this.zoom,n=2*t,s=this.aspect*n,r=-.5*s;const a=this.view;if(this.view!==null&&this.view.enabled){const l=a.fullWidth,c=a.fullHeight;r+=a.offsetX*s/l,t-=a.offsetY*n/c,s*=a.width/l,n*=a.height/c}const o=this.filmOffset;o!==0&&(r+=e*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,t,t-n,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}}class Ym extends qm{constructor(e=-1,t=1,n=1,s=-1,r=.1,a=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=n,this.bottom=s,this.near=r,this.far=a,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,n,s,r,a){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),n=(this.right+this.left)/2,s=(this.top+this.bottom)/2;let r=n-e,a=n+e,o=s+t,l=s-t;if(this.view!==null&&this.view.enabled){const c=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=c*this.view.offsetX,a=r+c*this.view.width,o-=h*this.view.offsetY,l=o-h*this.view.height}this.projectionMatrix.makeOrthographic(r,a,o,l,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}}class $x extends Xx{constructor(){super(new Ym(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}}class qx extends $m{constructor(e,t){super(e,t),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(yn.DEFAULT_UP),this.updateMatrix(),this.target=new yn,this.shadow=new $x}dispose(){super.dispose(),this.shadow.dispose()}copy(e){return super.copy(e),this.target=e.target.clone(),this.shadow=e.shadow.clone(),this}toJSON(e){const t=super.toJSON(e);return t.object.shadow=this.shadow.toJSON(),t.object.target=this.target.uuid,t}}class Yx extends $m{constructor(e,t){super(e,t),this.isAmbientLight=!0,this.type="AmbientLight"}}const Sf=new Dt,Mf=new Dt,Ws=new Dt;class Km{constructor(){this.type="StereoCamera",this.aspect=1,this.eyeSep=.064,this.cameraL=new Yn,this.cameraL.layers.enable(1),this.cameraL.matrixAutoUpdate=!1,this.cameraR=new Yn,this.cameraR.layers.enable(2),this.cameraR.matrixAutoUpdate=!1,this._cache={focus:null,fov:null,aspect:null,near:null,far:null,zoom:null,eyeSep:null}}update(e){const t=this._cache;if(t.focus!==e.focus||t.fov!==e.fov||t.aspect!==e.aspect*this.aspect||t.near!==e.near||t.far!==e.far||t.zoom!==e.zoom||t.eyeSep!==this.eyeSep){t.focus=e.focus,t.fov=e.fov,t.aspect=e.aspect*this.aspect,t.near=e.near,t.far=e.far,t.zoom=e.zoom,t.eyeSep=this.eyeSep,Ws.copy(e.projectionMatrix);const s=t.eyeSep/2,r=s*t.near/t.focus,a=t.near*Math.tan(Da*t.fov*.5)/t.zoom;let o,l;Mf.elements[12]=-s,Sf.elements[12]=s,o=-a*t.aspect+r,l=a*t.aspect+r,Ws.elements[0]=2*t.near/(l-o),Ws.elements[8]=(l+o)/(l-o),this.cameraL.projectionMatrix.copy(Ws),o=-a*t.aspect-r,l=a*t.aspect-r,Ws.elements[0]=2*t.near/(l-o),Ws.elements[8]=(l+o)/(l-o),this.cameraR.projectionMatrix.copy(Ws)}this.cameraL.matrix.copy(e.matrixWorld).multiply(Mf),this.cameraL.matrixWorldNeedsUpdate=!0,this.cameraR.matrix.copy(e.matrixWorld).multiply(Sf),this.cameraR.matrixWorldNeedsUpdate=!0}}const Lr=-90,Dr=1;class Bh extends yn{constructor(e,t,n){super(),this.type="CubeCamera",this.renderTarget=n,this.coordinateSystem=null,this.activeMipmapLevel=0;const s=new Yn(Lr,Dr,e,t);s.layers=this.layers,this.add(s);const r=new Yn(Lr,Dr,e,t);r.layers=this.layers,this.add(r);const a=new Yn(Lr,Dr,e,t);a.layers=this.layers,this.add(a);const o=new Yn(Lr,Dr,e,t);o.layers=this.layers,this.add(o);const l=new Yn(Lr,Dr,e,t);l.layers=this.layers,this.add(l);const c=new Yn(Lr,Dr,e,t);c.layers=this.layers,this.add(c)}updateCoordinateSystem(){const e=this.coordinateSystem,t=this.children.concat(),[n,s,r,a,o,l]=t;for(const c of t)this.remove(c);if(e===Pi)n.up.set(0,1,0),n.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),a.up.set(0,0,1),a.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(e===Ba)n.up.set(0,-1,0),n.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),a.up.set(0,0,-1),a.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(const c of t)this.add(c),c.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();const{renderTarget:n,activeMipmapLevel:s}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());const[r,a,o,l,c,h]=this.children,d=e.getRenderTarget(),u=e.getActiveCubeFace(),m=e.getActiveMipmapLevel(),_=e.xr.enabled;e.xr.enabled=!1;const y=n.texture.mipmapsAutoUpdate;n.texture.mipmapsAutoUpdate=!1;let p=!1;e.isWebGLRenderer===!0?p=e.state.buffers.depth.getReversed():p=e.reversedDepthBuffer,e.setRenderTarget(n,0,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,r),e.setRenderTarget(n,1,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(n,2,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(n,3,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),e.setRenderTarget(n,4,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),n.texture.mipmapsAutoUpdate=y,e.setRenderTarget(n,5,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,h),e.setRenderTarget(d,u,m),e.xr.enabled=_,n.texture.needsPMREMUpdate=!0}}class Kx extends Yn{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}}const bf=new Dt;class Zm{constructor(e,t,n=0,s=1/0){this.ray=new wl(e,t),this.near=n,this.far=s,this.camera=null,this.layers=new bu,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(e,t){this.ray.set(e,t)}setFromCamera(e,t){t.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(e.x,e.y,.5).unproject(t).sub(this.ray.origin).normalize(),this.camera=t):t.isOrthographicCamera?(this.ray.origin.set(e.x,e.y,t.projectionMatrix.elements[14]).unproject(t),this.ray.direction.set(0,0,-1).transformDirection(t.matrixWorld),this.camera=t):xt("Raycaster: Unsupported camera type: "+t.type)}setFromXRController(e){return bf.identity().extractRotation(e.matrixWorld),this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4(bf),this}intersectObject(e,t=!0,n=[]){return zh(e,this,n,t),n.sort(wf),n}intersectObjects(e,t=!0,n=[]){for(let s=0,r=e.length;s<r;s++)zh(e[s],this,n,t);return n.sort(wf),n}}function wf(i,e){return i.distance-e.distance}function zh(i,e,t,n){let s=!0;if(i.layers.test(e.layers)&&i.raycast(e,t)===!1&&(s=!1),s===!0&&n===!0){const r=i.children;for(let a=0,o=r.length;a<o;a++)zh(r[a],e,t,!0)}}class Hh{constructor(e=1,t=0,n=0){this.radius=e,this.phi=t,this.theta=n}set(e,t,n){return this.radius=e,this.phi=t,this.theta=n,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=pt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,n){return this.radius=Math.sqrt(e*e+t*t+n*n),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,n),this.phi=Math.acos(pt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}}const Ef=new B;let Uo,Ec;class Zx extends yn{constructor(e=new B(0,0,1),t=new B(0,0,0),n=1,s=16776960,r=n*.2,a=r*.2){super(),this.type="ArrowHelper",Uo===void 0&&(Uo=new Bt,Uo.setAttribute("position",new rn([0,0,0,0,1,0],3)),Ec=new Eu(.5,1,5,1),Ec.translate(0,-.5,0)),this.position.copy(t),this.line=new Ji(Uo,new vi({color:s,toneMapped:!1})),this.line.matrixAutoUpdate=!1,this.add(this.line),this.cone=new sn(Ec,new Ps({color:s,toneMapped:!1})),this.cone.matrixAutoUpdate=!1,this.add(this.cone),this.setDirection(e),this.setLength(n,r,a)}setDirection(e){if(e.y>.99999)this.quaternion.set(0,0,0,1);else if(e.y<-.99999)this.quaternion.set(1,0,0,0);else{Ef.set(e.z,0,-e.x).normalize();const t=Math.acos(e.y);this.quaternion.setFromAxisAngle(Ef,t)}}setLength(e,t=e*.2,n=t*.2){this.line.scale.set(1,Math.max(1e-4,e-t),1),this.line.updateMatrix(),this.cone.scale.set(n,t,n),this.cone.position.y=e,this.cone.updateMatrix()}setColor(e){this.line.material.color.set(e),this.cone.material.color.set(e)}copy(e){return super.copy(e,!1),this.line.copy(e.line),this.cone.copy(e.cone),this}dispose(){super.dispose(),this.line.geometry.dispose(),this.line.material.dispose(),this.cone.geometry.dispose(),this.cone.material.dispose()}}class Jm extends El{constructor(e=1){const t=[0,0,0,e,0,0,0,0,0,0,e,0,0,0,0,0,0,e],n=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new Bt;s.setAttribute("position",new rn(t,3)),s.setAttribute("color",new rn(n,3));const r=new vi({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(e,t,n){const s=new lt,r=this.geometry.attributes.color.array;return s.set(e),s.toArray(r,0),s.toArray(r,3),s.set(t),s.toArray(r,6),s.toArray(r,9),s.set(n),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}}let Jx=class extends Fs{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function Tf(i,e,t,n){const s=jx(n);switch(t){case bm:return i*e;case Em:return i*e/s.components*s.byteLength;case xu:return i*e/s.components*s.byteLength;case js:return i*e*2/s.components*s.byteLength;case yu:return i*e*2/s.components*s.byteLength;case wm:return i*e*3/s.components*s.byteLength;case Xi:return i*e*4/s.components*s.byteLength;case Su:return i*e*4/s.components*s.byteLength;case Xo:case $o:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case qo:case Yo:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case lh:case hh:return Math.max(i,16)*Math.max(e,8)/4;case oh:case ch:return Math.max(i,8)*Math.max(e,8)/2;case uh:case dh:case ph:case mh:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case fh:case nl:case gh:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case _h:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case vh:return Math.floor((i+4)/5)*Math.floor((e+3)/4)*16;case xh:return Math.floor((i+4)/5)*Math.floor((e+4)/5)*16;case yh:return Math.floor((i+5)/6)*Math.floor((e+4)/5)*16;case Sh:return Math.floor((i+5)/6)*Math.floor((e+5)/6)*16;case Mh:return Math.floor((i+7)/8)*Math.floor((e+4)/5)*16;case bh:return Math.floor((i+7)/8)*Math.floor((e+5)/6)*16;case wh:return Math.floor((i+7)/8)*Math.floor((e+7)/8)*16;case Eh:return Math.floor((i+9)/10)*Math.floor((e+4)/5)*16;case Th:return Math.floor((i+9)/10)*Math.floor((e+5)/6)*16;case Ah:return Math.floor((i+9)/10)*Math.floor((e+7)/8)*16;case Rh:return Math.floor((i+9)/10)*Math.floor((e+9)/10)*16;case Ch:return Math.floor((i+11)/12)*Math.floor((e+9)/10)*16;case Ph:return Math.floor((i+11)/12)*Math.floor((e+11)/12)*16;case Lh:case Dh:case Nh:return Math.ceil(i/4)*Math.ceil(e/4)*16;case Ih:case Uh:return Math.ceil(i/4)*Math.ceil(e/4)*8;case il:case Fh:return Math.ceil(i/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function jx(i){switch(i){case si:case xm:return{byteLength:1,components:1};case ka:case ym:case Zi:return{byteLength:2,components:1};case _u:case vu:return{byteLength:2,components:4};case Ki:case gu:case Wi:return{byteLength:4,components:1};case Sm:case Mm:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${i}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:mu}}));typeof window<"u"&&(window.__THREE__?Je("WARNING: Multiple instances of Three.js being imported."):window.__THREE__=mu);function jm(){let i=null,e=!1,t=null,n=null;function s(r,a){n=i.requestAnimationFrame(s),t(r,a)}return{start:function(){e!==!0&&t!==null&&i!==null&&(n=i.requestAnimationFrame(s),e=!0)},stop:function(){i!==null&&i.cancelAnimationFrame(n),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){i=r}}}function Qx(i){const e=new WeakMap;function t(o,l){const c=o.array,h=o.usage,d=c.byteLength,u=i.createBuffer();i.bindBuffer(l,u),i.bufferData(l,c,h),o.onUploadCallback();let m;if(c instanceof Float32Array)m=i.FLOAT;else if(typeof Float16Array<"u"&&c instanceof Float16Array)m=i.HALF_FLOAT;else if(c instanceof Uint16Array)o.isFloat16BufferAttribute?m=i.HALF_FLOAT:m=i.UNSIGNED_SHORT;else if(c instanceof Int16Array)m=i.SHORT;else if(c instanceof Uint32Array)m=i.UNSIGNED_INT;else if(c instanceof Int32Array)m=i.INT;else if(c instanceof Int8Array)m=i.BYTE;else if(c instanceof Uint8Array)m=i.UNSIGNED_BYTE;else if(c instanceof Uint8ClampedArray)m=i.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+c);return{buffer:u,type:m,bytesPerElement:c.BYTES_PER_ELEMENT,version:o.version,size:d}}function n(o,l,c){const h=l.array,d=l.updateRanges;if(i.bindBuffer(c,o),d.length===0)i.bufferSubData(c,0,h);else{d.sort((m,_)=>m.start-_.start);let u=0;for(let m=1;m<d.length;m++){const _=d[u],y=d[m];y.start<=_.start+_.count+1?_.count=Math.max(_.count,y.start+y.count-_.start):(++u,d[u]=y)}d.length=u+1;for(let m=0,_=d.length;m<_;m++){const y=d[m];i.bufferSubData(c,y.start*h.BYTES_PER_ELEMENT,h,y.start,y.count)}l.clearUpdateRanges()}l.onUploadCallback()}function s(o){return o.isInterleavedBufferAttribute&&(o=o.data),e.get(o)}function r(o){o.isInterleavedBufferAttribute&&(o=o.data);const l=e.get(o);l&&(i.deleteBuffer(l.buffer),e.delete(o))}function a(o,l){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){const h=e.get(o);(!h||h.version<o.version)&&e.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}const c=e.get(o);if(c===void 0)e.set(o,t(o,l));else if(c.version<o.version){if(c.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");n(c.buffer,o,l),c.version=o.version}}return{get:s,remove:r,update:a}}var ey=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,ty=`#ifdef USE_ALPHAHASH
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
#endif`,ny=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,iy=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,sy=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,ry=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,ay=`#ifdef USE_AOMAP
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
#endif`,oy=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,ly=`#ifdef USE_BATCHING
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
#endif`,cy=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,hy=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,uy=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,dy=`float G_BlinnPhong_Implicit( ) {
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
} // validated`,fy=`#ifdef USE_IRIDESCENCE
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
#endif`,py=`#ifdef USE_BUMPMAP
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
#endif`,my=`#if NUM_CLIPPING_PLANES > 0
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
#endif`,gy=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,_y=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,vy=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,xy=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,yy=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,Sy=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,My=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
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
#endif`,by=`#define PI 3.141592653589793
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
} // validated`,wy=`vec3 transformedNormal = objectNormal;
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
#endif`,Ey=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,Ty=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,Ay=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,Ry=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,Cy="gl_FragColor = linearToOutputTexel( gl_FragColor );",Py=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,Ly=`#ifdef USE_ENVMAP
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
#endif`,Dy=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,Ny=`#ifdef USE_ENVMAP
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
#endif`,Iy=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,Uy=`#ifdef USE_ENVMAP
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
#endif`,Fy=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,Oy=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,ky=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,By=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,zy=`#ifdef USE_GRADIENTMAP
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
}`,Hy=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,Gy=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,Vy=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,Wy=`uniform bool receiveShadow;
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
#include <lightprobes_pars_fragment>`,Xy=`#ifdef USE_ENVMAP
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
#endif`,$y=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,qy=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,Yy=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,Ky=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,Zy=`PhysicalMaterial material;
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
#endif`,Jy=`uniform sampler2D dfgLUT;
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
}`,jy=`
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
#endif`,Qy=`#if defined( RE_IndirectDiffuse )
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
#endif`,eS=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,tS=`#if NUM_LIGHT_PROBE_GRIDS > 0
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
#endif`,nS=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,iS=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,sS=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,rS=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,aS=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,oS=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,lS=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
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
#endif`,cS=`#if defined( USE_POINTS_UV )
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
#endif`,hS=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,uS=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,dS=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,fS=`#if defined( USE_MORPHCOLORS )
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
#endif`,pS=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,mS=`#ifdef USE_MORPHTARGETS
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
#endif`,gS=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,_S=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
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
vec3 nonPerturbedNormal = normal;`,vS=`#ifdef USE_NORMALMAP_OBJECTSPACE
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
#endif`,xS=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,yS=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,SS=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,MS=`#ifdef USE_NORMALMAP
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
#endif`,bS=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,wS=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,ES=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,TS=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,AS=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,RS=`vec3 packNormalToRGB( const in vec3 normal ) {
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
}`,CS=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,PS=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,LS=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,DS=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,NS=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,IS=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,US=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,FS=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,OS=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
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
#endif`,kS=`float getShadowMask() {
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
}`,BS=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,zS=`#ifdef USE_SKINNING
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
#endif`,HS=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,GS=`#ifdef USE_SKINNING
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
#endif`,VS=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,WS=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,XS=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,$S=`#ifndef saturate
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
vec3 CustomToneMapping( vec3 color ) { return color; }`,qS=`#ifdef USE_TRANSMISSION
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
#endif`,YS=`#ifdef USE_TRANSMISSION
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
#endif`,KS=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,ZS=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,JS=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,jS=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`;const QS=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,eM=`uniform sampler2D t2D;
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
}`,tM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,nM=`uniform float backgroundBlurriness;
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
}`,iM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,sM=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,rM=`#include <common>
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
}`,aM=`#if DEPTH_PACKING == 3200
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
}`,oM=`#define DISTANCE
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
}`,lM=`#define DISTANCE
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
}`,cM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,hM=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,uM=`uniform float scale;
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
}`,dM=`uniform vec3 diffuse;
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
}`,fM=`#include <common>
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
}`,pM=`uniform vec3 diffuse;
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
}`,mM=`#define LAMBERT
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
}`,gM=`#define LAMBERT
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
}`,_M=`#define MATCAP
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
}`,vM=`#define MATCAP
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
}`,xM=`#define NORMAL
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
}`,yM=`#define NORMAL
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
}`,SM=`#define PHONG
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
}`,MM=`#define PHONG
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
}`,bM=`#define STANDARD
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
}`,wM=`#define STANDARD
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
}`,EM=`#define TOON
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
}`,TM=`#define TOON
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
}`,AM=`uniform float size;
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
}`,RM=`uniform vec3 diffuse;
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
}`,CM=`#include <common>
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
}`,PM=`uniform vec3 color;
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
}`,LM=`uniform float rotation;
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
}`,DM=`uniform vec3 diffuse;
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
}`,ot={alphahash_fragment:ey,alphahash_pars_fragment:ty,alphamap_fragment:ny,alphamap_pars_fragment:iy,alphatest_fragment:sy,alphatest_pars_fragment:ry,aomap_fragment:ay,aomap_pars_fragment:oy,batching_pars_vertex:ly,batching_vertex:cy,begin_vertex:hy,beginnormal_vertex:uy,bsdfs:dy,iridescence_fragment:fy,bumpmap_pars_fragment:py,clipping_planes_fragment:my,clipping_planes_pars_fragment:gy,clipping_planes_pars_vertex:_y,clipping_planes_vertex:vy,color_fragment:xy,color_pars_fragment:yy,color_pars_vertex:Sy,color_vertex:My,common:by,defaultnormal_vertex:wy,displacementmap_pars_vertex:Ey,displacementmap_vertex:Ty,emissivemap_fragment:Ay,emissivemap_pars_fragment:Ry,colorspace_fragment:Cy,colorspace_pars_fragment:Py,envmap_fragment:Ly,envmap_common_pars_fragment:Dy,envmap_pars_fragment:Ny,envmap_pars_vertex:Iy,envmap_physical_pars_fragment:Xy,envmap_vertex:Uy,fog_vertex:Fy,fog_pars_vertex:Oy,fog_fragment:ky,fog_pars_fragment:By,gradientmap_pars_fragment:zy,lightmap_pars_fragment:Hy,lights_lambert_fragment:Gy,lights_lambert_pars_fragment:Vy,lights_pars_begin:Wy,lights_toon_fragment:$y,lights_toon_pars_fragment:qy,lights_phong_fragment:Yy,lights_phong_pars_fragment:Ky,lights_physical_fragment:Zy,lights_physical_pars_fragment:Jy,lights_fragment_begin:jy,lights_fragment_maps:Qy,lights_fragment_end:eS,lightprobes_pars_fragment:tS,logdepthbuf_fragment:nS,logdepthbuf_pars_fragment:iS,logdepthbuf_pars_vertex:sS,logdepthbuf_vertex:rS,map_fragment:aS,map_pars_fragment:oS,map_particle_fragment:lS,map_particle_pars_fragment:cS,metalnessmap_fragment:hS,metalnessmap_pars_fragment:uS,morphinstance_vertex:dS,morphcolor_vertex:fS,morphnormal_vertex:pS,morphtarget_pars_vertex:mS,morphtarget_vertex:gS,normal_fragment_begin:_S,normal_fragment_maps:vS,normal_pars_fragment:xS,normal_pars_vertex:yS,normal_vertex:SS,normalmap_pars_fragment:MS,clearcoat_normal_fragment_begin:bS,clearcoat_normal_fragment_maps:wS,clearcoat_pars_fragment:ES,iridescence_pars_fragment:TS,opaque_fragment:AS,packing:RS,premultiplied_alpha_fragment:CS,project_vertex:PS,dithering_fragment:LS,dithering_pars_fragment:DS,roughnessmap_fragment:NS,roughnessmap_pars_fragment:IS,shadowmap_pars_fragment:US,shadowmap_pars_vertex:FS,shadowmap_vertex:OS,shadowmask_pars_fragment:kS,skinbase_vertex:BS,skinning_pars_vertex:zS,skinning_vertex:HS,skinnormal_vertex:GS,specularmap_fragment:VS,specularmap_pars_fragment:WS,tonemapping_fragment:XS,tonemapping_pars_fragment:$S,transmission_fragment:qS,transmission_pars_fragment:YS,uv_pars_fragment:KS,uv_pars_vertex:ZS,uv_vertex:JS,worldpos_vertex:jS,background_vert:QS,background_frag:eM,backgroundCube_vert:tM,backgroundCube_frag:nM,cube_vert:iM,cube_frag:sM,depth_vert:rM,depth_frag:aM,distance_vert:oM,distance_frag:lM,equirect_vert:cM,equirect_frag:hM,linedashed_vert:uM,linedashed_frag:dM,meshbasic_vert:fM,meshbasic_frag:pM,meshlambert_vert:mM,meshlambert_frag:gM,meshmatcap_vert:_M,meshmatcap_frag:vM,meshnormal_vert:xM,meshnormal_frag:yM,meshphong_vert:SM,meshphong_frag:MM,meshphysical_vert:bM,meshphysical_frag:wM,meshtoon_vert:EM,meshtoon_frag:TM,points_vert:AM,points_frag:RM,shadow_vert:CM,shadow_frag:PM,sprite_vert:LM,sprite_frag:DM},De={common:{diffuse:{value:new lt(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new it},alphaMap:{value:null},alphaMapTransform:{value:new it},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new it}},envmap:{envMap:{value:null},envMapRotation:{value:new it},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new it}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new it}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new it},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new it},normalScale:{value:new Xe(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new it},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new it}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new it}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new it}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new lt(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new lt(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new it},alphaTest:{value:0},uvTransform:{value:new it}},sprite:{diffuse:{value:new lt(16777215)},opacity:{value:1},center:{value:new Xe(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new it},alphaMap:{value:null},alphaMapTransform:{value:new it},alphaTest:{value:0}}},Vi={basic:{uniforms:Xn([De.common,De.specularmap,De.envmap,De.aomap,De.lightmap,De.fog]),vertexShader:ot.meshbasic_vert,fragmentShader:ot.meshbasic_frag},lambert:{uniforms:Xn([De.common,De.specularmap,De.envmap,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.fog,De.lights,{emissive:{value:new lt(0)},envMapIntensity:{value:1}}]),vertexShader:ot.meshlambert_vert,fragmentShader:ot.meshlambert_frag},phong:{uniforms:Xn([De.common,De.specularmap,De.envmap,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.fog,De.lights,{emissive:{value:new lt(0)},specular:{value:new lt(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:ot.meshphong_vert,fragmentShader:ot.meshphong_frag},standard:{uniforms:Xn([De.common,De.envmap,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.roughnessmap,De.metalnessmap,De.fog,De.lights,{emissive:{value:new lt(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:ot.meshphysical_vert,fragmentShader:ot.meshphysical_frag},toon:{uniforms:Xn([De.common,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.gradientmap,De.fog,De.lights,{emissive:{value:new lt(0)}}]),vertexShader:ot.meshtoon_vert,fragmentShader:ot.meshtoon_frag},matcap:{uniforms:Xn([De.common,De.bumpmap,De.normalmap,De.displacementmap,De.fog,{matcap:{value:null}}]),vertexShader:ot.meshmatcap_vert,fragmentShader:ot.meshmatcap_frag},points:{uniforms:Xn([De.points,De.fog]),vertexShader:ot.points_vert,fragmentShader:ot.points_frag},dashed:{uniforms:Xn([De.common,De.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:ot.linedashed_vert,fragmentShader:ot.linedashed_frag},depth:{uniforms:Xn([De.common,De.displacementmap]),vertexShader:ot.depth_vert,fragmentShader:ot.depth_frag},normal:{uniforms:Xn([De.common,De.bumpmap,De.normalmap,De.displacementmap,{opacity:{value:1}}]),vertexShader:ot.meshnormal_vert,fragmentShader:ot.meshnormal_frag},sprite:{uniforms:Xn([De.sprite,De.fog]),vertexShader:ot.sprite_vert,fragmentShader:ot.sprite_frag},background:{uniforms:{uvTransform:{value:new it},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:ot.background_vert,fragmentShader:ot.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new it}},vertexShader:ot.backgroundCube_vert,fragmentShader:ot.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:ot.cube_vert,fragmentShader:ot.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:ot.equirect_vert,fragmentShader:ot.equirect_frag},distance:{uniforms:Xn([De.common,De.displacementmap,{referencePosition:{value:new B},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:ot.distance_vert,fragmentShader:ot.distance_frag},shadow:{uniforms:Xn([De.lights,De.fog,{color:{value:new lt(0)},opacity:{value:1}}]),vertexShader:ot.shadow_vert,fragmentShader:ot.shadow_frag}};Vi.physical={uniforms:Xn([Vi.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new it},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new it},clearcoatNormalScale:{value:new Xe(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new it},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new it},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new it},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new it},sheen:{value:0},sheenColor:{value:new lt(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new it},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new it},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new it},transmissionSamplerSize:{value:new Xe},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new it},attenuationDistance:{value:0},attenuationColor:{value:new lt(0)},specularColor:{value:new lt(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new it},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new it},anisotropyVector:{value:new Xe},anisotropyMap:{value:null},anisotropyMapTransform:{value:new it}}]),vertexShader:ot.meshphysical_vert,fragmentShader:ot.meshphysical_frag};const Fo={r:0,b:0,g:0},NM=new Dt,Qm=new it;Qm.set(-1,0,0,0,1,0,0,0,1);function IM(i,e,t,n,s,r){const a=new lt(0);let o=s===!0?0:1,l,c,h=null,d=0,u=null;function m(x){let A=x.isScene===!0?x.background:null;if(A&&A.isTexture){const M=x.backgroundBlurriness>0;A=e.get(A,M)}return A}function _(x){let A=!1;const M=m(x);M===null?p(a,o):M&&M.isColor&&(p(M,1),A=!0);const C=i.xr.getEnvironmentBlendMode();C==="additive"?t.buffers.color.setClear(0,0,0,1,r):C==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,r),(i.autoClear||A)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),i.clear(i.autoClearColor,i.autoClearDepth,i.autoClearStencil))}function y(x,A){const M=m(A);M&&M.isCubeTexture?(c===void 0&&(c=new sn(new Ka(1,1,1),new Qs({name:"BackgroundCubeMaterial",uniforms:jr(Vi.backgroundCube.uniforms),vertexShader:Vi.backgroundCube.vertexShader,fragmentShader:Vi.backgroundCube.fragmentShader,side:Zn,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),c.geometry.deleteAttribute("uv"),c.onBeforeRender=function(C,b,g){this.matrixWorld.copyPosition(g.matrixWorld)},Object.defineProperty(c.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),n.update(c)),c.material.uniforms.envMap.value=M,c.material.uniforms.backgroundBlurriness.value=A.backgroundBlurriness,c.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,c.material.uniforms.backgroundRotation.value.setFromMatrix4(NM.makeRotationFromEuler(A.backgroundRotation)).transpose(),M.isRenderTargetTexture===!1&&c.material.uniforms.backgroundRotation.value.premultiply(Qm),c.material.toneMapped=_t.getTransfer(M.colorSpace)!==Lt,(h!==M||d!==M.version||u!==i.toneMapping)&&(c.material.needsUpdate=!0,h=M,d=M.version,u=i.toneMapping),c.layers.enableAll(),x.unshift(c,c.geometry,c.material,0,0,null)):M&&M.isTexture&&(l===void 0&&(l=new sn(new Tl(2,2),new Qs({name:"BackgroundMaterial",uniforms:jr(Vi.background.uniforms),vertexShader:Vi.background.vertexShader,fragmentShader:Vi.background.fragmentShader,side:Ds,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),n.update(l)),l.material.uniforms.t2D.value=M,l.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,l.material.toneMapped=_t.getTransfer(M.colorSpace)!==Lt,M.matrixAutoUpdate===!0&&M.updateMatrix(),l.material.uniforms.uvTransform.value.copy(M.matrix),(h!==M||d!==M.version||u!==i.toneMapping)&&(l.material.needsUpdate=!0,h=M,d=M.version,u=i.toneMapping),l.layers.enableAll(),x.unshift(l,l.geometry,l.material,0,0,null))}function p(x,A){x.getRGB(Fo,Wm(i)),t.buffers.color.setClear(Fo.r,Fo.g,Fo.b,A,r)}function f(){c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0),l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0)}return{getClearColor:function(){return a},setClearColor:function(x,A=1){a.set(x),o=A,p(a,o)},getClearAlpha:function(){return o},setClearAlpha:function(x){o=x,p(a,o)},render:_,addToRenderList:y,dispose:f}}function UM(i,e){const t=i.getParameter(i.MAX_VERTEX_ATTRIBS),n={},s=u(null);let r=s,a=!1;function o(D,z,V,U,W){let K=!1;const G=d(D,U,V,z);r!==G&&(r=G,c(r.object)),K=m(D,U,V,W),K&&_(D,U,V,W),W!==null&&e.update(W,i.ELEMENT_ARRAY_BUFFER),(K||a)&&(a=!1,M(D,z,V,U),W!==null&&i.bindBuffer(i.ELEMENT_ARRAY_BUFFER,e.get(W).buffer))}function l(){return i.createVertexArray()}function c(D){return i.bindVertexArray(D)}function h(D){return i.deleteVertexArray(D)}function d(D,z,V,U){const W=U.wireframe===!0;let K=n[z.id];K===void 0&&(K={},n[z.id]=K);const G=D.isInstancedMesh===!0?D.id:0;let le=K[G];le===void 0&&(le={},K[G]=le);let J=le[V.id];J===void 0&&(J={},le[V.id]=J);let Q=J[W];return Q===void 0&&(Q=u(l()),J[W]=Q),Q}function u(D){const z=[],V=[],U=[];for(let W=0;W<t;W++)z[W]=0,V[W]=0,U[W]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:z,enabledAttributes:V,attributeDivisors:U,object:D,attributes:{},index:null}}function m(D,z,V,U){const W=r.attributes,K=z.attributes;let G=0;const le=V.getAttributes();for(const J in le)if(le[J].location>=0){const se=W[J];let de=K[J];if(de===void 0&&(J==="instanceMatrix"&&D.instanceMatrix&&(de=D.instanceMatrix),J==="instanceColor"&&D.instanceColor&&(de=D.instanceColor)),se===void 0||se.attribute!==de||de&&se.data!==de.data)return!0;G++}return r.attributesNum!==G||r.index!==U}function _(D,z,V,U){const W={},K=z.attributes;let G=0;const le=V.getAttributes();for(const J in le)if(le[J].location>=0){let se=K[J];se===void 0&&(J==="instanceMatrix"&&D.instanceMatrix&&(se=D.instanceMatrix),J==="instanceColor"&&D.instanceColor&&(se=D.instanceColor));const de={};de.attribute=se,se&&se.data&&(de.data=se.data),W[J]=de,G++}r.attributes=W,r.attributesNum=G,r.index=U}function y(){const D=r.newAttributes;for(let z=0,V=D.length;z<V;z++)D[z]=0}function p(D){f(D,0)}function f(D,z){const V=r.newAttributes,U=r.enabledAttributes,W=r.attributeDivisors;V[D]=1,U[D]===0&&(i.enableVertexAttribArray(D),U[D]=1),W[D]!==z&&(i.vertexAttribDivisor(D,z),W[D]=z)}function x(){const D=r.newAttributes,z=r.enabledAttributes;for(let V=0,U=z.length;V<U;V++)z[V]!==D[V]&&(i.disableVertexAttribArray(V),z[V]=0)}function A(D,z,V,U,W,K,G){G===!0?i.vertexAttribIPointer(D,z,V,W,K):i.vertexAttribPointer(D,z,V,U,W,K)}function M(D,z,V,U){y();const W=U.attributes,K=V.getAttributes(),G=z.defaultAttributeValues;for(const le in K){const J=K[le];if(J.location>=0){let Q=W[le];if(Q===void 0&&(le==="instanceMatrix"&&D.instanceMatrix&&(Q=D.instanceMatrix),le==="instanceColor"&&D.instanceColor&&(Q=D.instanceColor)),Q!==void 0){const se=Q.normalized,de=Q.itemSize,ue=e.get(Q);if(ue===void 0)continue;const ee=ue.buffer,me=ue.type,ve=ue.bytesPerElement,Ae=me===i.INT||me===i.UNSIGNED_INT||Q.gpuType===gu;if(Q.isInterleavedBufferAttribute){const Me=Q.data,Ve=Me.isInterleavedBuffer===!0?Me.stride:Me.itemSize,tt=Q.offset;if(Me.isInstancedInterleavedBuffer||Me.isInstancedBufferAttribute){for(let He=0;He<J.locationSize;He++)f(J.location+He,Me.meshPerAttribute);D.isInstancedMesh!==!0&&U._maxInstanceCount===void 0&&(U._maxInstanceCount=Me.meshPerAttribute*Me.count)}else for(let He=0;He<J.locationSize;He++)p(J.location+He);i.bindBuffer(i.ARRAY_BUFFER,ee);for(let He=0;He<J.locationSize;He++)A(J.location+He,de/J.locationSize,me,se,Ve*ve,(tt+de/J.locationSize*He)*ve,Ae)}else{if(Q.isInstancedBufferAttribute){for(let Me=0;Me<J.locationSize;Me++)f(J.location+Me,Q.meshPerAttribute);D.isInstancedMesh!==!0&&U._maxInstanceCount===void 0&&(U._maxInstanceCount=Q.meshPerAttribute*Q.count)}else for(let Me=0;Me<J.locationSize;Me++)p(J.location+Me);i.bindBuffer(i.ARRAY_BUFFER,ee);for(let Me=0;Me<J.locationSize;Me++)A(J.location+Me,de/J.locationSize,me,se,de*ve,de/J.locationSize*Me*ve,Ae)}}else if(G!==void 0){const se=G[le];if(se!==void 0)switch(se.length){case 2:i.vertexAttrib2fv(J.location,se);break;case 3:i.vertexAttrib3fv(J.location,se);break;case 4:i.vertexAttrib4fv(J.location,se);break;default:i.vertexAttrib1fv(J.location,se)}}}}x()}function C(){F();for(const D in n){const z=n[D];for(const V in z){const U=z[V];for(const W in U){const K=U[W];for(const G in K)h(K[G].object),delete K[G];delete U[W]}}delete n[D]}}function b(D){if(n[D.id]===void 0)return;const z=n[D.id];for(const V in z){const U=z[V];for(const W in U){const K=U[W];for(const G in K)h(K[G].object),delete K[G];delete U[W]}}delete n[D.id]}function g(D){for(const z in n){const V=n[z];for(const U in V){const W=V[U];if(W[D.id]===void 0)continue;const K=W[D.id];for(const G in K)h(K[G].object),delete K[G];delete W[D.id]}}}function w(D){for(const z in n){const V=n[z],U=D.isInstancedMesh===!0?D.id:0,W=V[U];if(W!==void 0){for(const K in W){const G=W[K];for(const le in G)h(G[le].object),delete G[le];delete W[K]}delete V[U],Object.keys(V).length===0&&delete n[z]}}}function F(){L(),a=!0,r!==s&&(r=s,c(r.object))}function L(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:o,reset:F,resetDefaultState:L,dispose:C,releaseStatesOfGeometry:b,releaseStatesOfObject:w,releaseStatesOfProgram:g,initAttributes:y,enableAttribute:p,disableUnusedAttributes:x}}function FM(i,e,t){let n;function s(l){n=l}function r(l,c){i.drawArrays(n,l,c),t.update(c,n,1)}function a(l,c,h){h!==0&&(i.drawArraysInstanced(n,l,c,h),t.update(c,n,h))}function o(l,c,h){if(h===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(n,l,0,c,0,h);let u=0;for(let m=0;m<h;m++)u+=c[m];t.update(u,n,1)}this.setMode=s,this.render=r,this.renderInstances=a,this.renderMultiDraw=o}function OM(i,e,t,n){let s;function r(){if(s!==void 0)return s;if(e.has("EXT_texture_filter_anisotropic")===!0){const g=e.get("EXT_texture_filter_anisotropic");s=i.getParameter(g.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function a(g){return!(g!==Xi&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(g){const w=g===Zi&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(g!==si&&g!==Wi&&!w&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_TYPE))}function l(g){if(g==="highp"){if(i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.HIGH_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.HIGH_FLOAT).precision>0)return"highp";g="mediump"}return g==="mediump"&&i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.MEDIUM_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let c=t.precision!==void 0?t.precision:"highp";const h=l(c);h!==c&&(Je("WebGLRenderer:",c,"not supported, using",h,"instead."),c=h);const d=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),u=t.logarithmicDepthBuffer===!0&&d===!1;t.reversedDepthBuffer===!0&&d===!1&&Je("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&d===!0&&Je("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");const m=i.getParameter(i.MAX_TEXTURE_IMAGE_UNITS),_=i.getParameter(i.MAX_VERTEX_TEXTURE_IMAGE_UNITS),y=i.getParameter(i.MAX_TEXTURE_SIZE),p=i.getParameter(i.MAX_CUBE_MAP_TEXTURE_SIZE),f=i.getParameter(i.MAX_VERTEX_ATTRIBS),x=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),A=i.getParameter(i.MAX_VARYING_VECTORS),M=i.getParameter(i.MAX_FRAGMENT_UNIFORM_VECTORS),C=i.getParameter(i.MAX_SAMPLES),b=i.getParameter(i.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:l,textureFormatReadable:a,textureTypeReadable:o,precision:c,logarithmicDepthBuffer:u,reversedDepthBuffer:d,maxTextures:m,maxVertexTextures:_,maxTextureSize:y,maxCubemapSize:p,maxAttributes:f,maxVertexUniforms:x,maxVaryings:A,maxFragmentUniforms:M,maxSamples:C,samples:b}}function kM(i){const e=this;let t=null,n=0,s=!1,r=!1;const a=new Ri,o=new it,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(d,u){const m=d.length!==0||u||n!==0||s;return s=u,n=d.length,m},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(d,u){t=h(d,u,0)},this.setState=function(d,u,m){const _=d.clippingPlanes,y=d.clipIntersection,p=d.clipShadows,f=i.get(d);if(!s||_===null||_.length===0||r&&!p)r?h(null):c();else{const x=r?0:n,A=x*4;let M=f.clippingState||null;l.value=M,M=h(_,u,A,m);for(let C=0;C!==A;++C)M[C]=t[C];f.clippingState=M,this.numIntersection=y?this.numPlanes:0,this.numPlanes+=x}};function c(){l.value!==t&&(l.value=t,l.needsUpdate=n>0),e.numPlanes=n,e.numIntersection=0}function h(d,u,m,_){const y=d!==null?d.length:0;let p=null;if(y!==0){if(p=l.value,_!==!0||p===null){const f=m+y*4,x=u.matrixWorldInverse;o.getNormalMatrix(x),(p===null||p.length<f)&&(p=new Float32Array(f));for(let A=0,M=m;A!==y;++A,M+=4)a.copy(d[A]).applyMatrix4(x,o),a.normal.toArray(p,M),p[M+3]=a.constant}l.value=p,l.needsUpdate=!0}return e.numPlanes=y,e.numIntersection=0,p}}class Tu extends qi{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;const n={width:e,height:e,depth:1},s=[n,n,n,n,n,n];this.texture=new Hm(s),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;const n={uniforms:{tEquirect:{value:null}},vertexShader:`

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
			`},s=new Ka(5,5,5),r=new Qs({name:"CubemapFromEquirect",uniforms:jr(n.uniforms),vertexShader:n.vertexShader,fragmentShader:n.fragmentShader,side:Zn,blending:zr});r.uniforms.tEquirect.value=t;const a=new sn(s,r),o=t.minFilter;return t.minFilter===Rs&&(t.minFilter=Kn),new Bh(1,10,this).update(e,a),t.minFilter=o,a.geometry.dispose(),a.material.dispose(),this}clear(e,t=!0,n=!0,s=!0){const r=e.getRenderTarget();for(let a=0;a<6;a++)e.setRenderTarget(this,a),e.clear(t,n,s);e.setRenderTarget(r)}}const Af=256,BM=3,zM=20,eg=256,tg=16,HM=3,GM=new B,VM=new lt;class ul{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new Bh(1,10,null),this._boxMesh=new sn(new Ka(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,n=.1,s=100,r={}){const{size:a=256,position:o=GM}=r,l=this._renderer;this._setSize(a);const c=this._allocateTarget(),h=this._getSourceTarget(!0);t>0&&(h.texture.mipmapsAutoUpdate=!1);const d=l.autoClear,u=l.autoClearColor,m=l.autoClearDepth,_=l.autoClearStencil,y=e.background;l.autoClear=!0,l.autoClearColor=!0,l.autoClearDepth=!0,l.autoClearStencil=!0,y===null&&(e.background=l.getClearColor(VM));const p=new Bh(n,s,h);return p.position.copy(o),p.update(l,e),l.autoClear=d,l.autoClearColor=u,l.autoClearDepth=m,l.autoClearStencil=_,e.background=y,t>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(c,t)),this._applyPMREM(c),c}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=Pf(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Cf(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(Af,ux(e))}_fromTexture(e,t){e.mapping===Kr||e.mapping===Oa?this._setSize(e.image.length===0?Af:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);const n=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(n),n}_allocateTarget(){const e=this._cubeSize,t=Rf(e,!1,!1),n=Math.log2(e)-BM;for(let s=0;s<=n;s++)t.texture.mipmaps.push({width:e>>s,height:e>>s});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){const t=this._cubeSize,n=this._sourceTarget;return(n===null||n.width!==t||e&&n.depthBuffer===!1)&&(n!==null&&n.dispose(),this._sourceTarget=Rf(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,n){const s=this._boxMesh,r=this._cubeCamera;s.material=n,r.renderTarget=e,r.activeMipmapLevel=t;const a=e.width>>t;e.viewport.set(0,0,a,a),r.update(this._renderer,s),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===Kr||e.mapping===Oa?(this._cubemapMaterial===null&&(this._cubemapMaterial=Pf()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Cf()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=WM(),this._integrationMaterial=XM());const t=this._cubeSize,n=e.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;const r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(t/tg);for(let a=0;a<=n;a++){const o=ul.lodToRoughness(a,n);if(a>n-HM)r.roughness.value=o,this._renderCube(e,a,this._integrationMaterial);else{const l=o>0?Math.log2(t)+.5*Math.log2(6/(eg*Math.pow(o,4)))+.5:0;s.roughness.value=o,s.lodBias.value=l,this._renderCube(e,a,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=$M());const n=this._blurMaterial,s=n.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(e,0,n),s.envMap.value=e.texture,this._renderCube(r,0,n)}}function Rf(i,e,t){return new Tu(i,{minFilter:Rs,generateMipmaps:e,type:Zi,colorSpace:sl,depthBuffer:t})}function Ja(i,e,t){return new Qs({name:i,uniforms:e,vertexShader:ot.cube_vert,fragmentShader:t,side:Zn,blending:zr,depthTest:!1,depthWrite:!1})}function WM(){return Ja("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${eg}u

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
	`)}function XM(){return Ja("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:tg}},`

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
	`)}function $M(){return Ja("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${zM}
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
	`)}function Cf(){return Ja("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

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
	`)}function Pf(){return Ja("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function qM(i){let e=new WeakMap,t=new WeakMap,n=null;function s(u,m=!1){return u==null?null:m?a(u):r(u)}function r(u){if(u&&u.isTexture){const m=u.mapping;if(m===Jl||m===jl)if(e.has(u)){const _=e.get(u).texture;return o(_,u.mapping)}else{const _=u.image;if(_&&_.height>0){const y=new Tu(_.height);return y.fromEquirectangularTexture(i,u),e.set(u,y),u.addEventListener("dispose",c),o(y.texture,u.mapping)}else return null}}return u}function a(u){if(u&&u.isTexture&&u.isPMREMTexture!==!0){const m=u.mapping,_=m===Jl||m===jl,y=m===Kr||m===Oa;if(_||y){let p=t.get(u);const f=p!==void 0?p.texture.pmremVersion:0;if(u.isRenderTargetTexture&&u.pmremVersion!==f)return n===null&&(n=new ul(i)),p=_?n.fromEquirectangular(u,p):n.fromCubemap(u,p),p.texture.pmremVersion=u.pmremVersion,t.set(u,p),p.texture;if(p!==void 0)return p.texture;{const x=u.image;return _&&x&&x.height>0||y&&x&&l(x)?(n===null&&(n=new ul(i)),p=_?n.fromEquirectangular(u):n.fromCubemap(u),p.texture.pmremVersion=u.pmremVersion,t.set(u,p),u.addEventListener("dispose",h),p.texture):null}}}return u}function o(u,m){return m===Jl?u.mapping=Kr:m===jl&&(u.mapping=Oa),u}function l(u){let m=0;const _=6;for(let y=0;y<_;y++)u[y]!==void 0&&m++;return m===_}function c(u){const m=u.target;m.removeEventListener("dispose",c);const _=e.get(m);_!==void 0&&(e.delete(m),_.dispose())}function h(u){const m=u.target;m.removeEventListener("dispose",h);const _=t.get(m);_!==void 0&&(t.delete(m),_.dispose())}function d(){e=new WeakMap,t=new WeakMap,n!==null&&(n.dispose(),n=null)}return{get:s,dispose:d}}function YM(i){const e={};function t(n){if(e[n]!==void 0)return e[n];const s=i.getExtension(n);return e[n]=s,s}return{has:function(n){return t(n)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(n){const s=t(n);return s===null&&Ko("WebGLRenderer: "+n+" extension not supported."),s}}}function KM(i,e,t,n){const s={},r=new WeakMap,a=new FinalizationRegistry(_=>delete s[_]);function o(_){l(_.target)}function l(_){_.index!==null&&e.remove(_.index);for(const p in _.attributes)e.remove(_.attributes[p]);_.removeEventListener("dispose",o),delete s[_.id],a.unregister(_);const y=r.get(_);y&&(e.remove(y),r.delete(_)),n.releaseStatesOfGeometry(_),_.isInstancedBufferGeometry===!0&&delete _._maxInstanceCount,t.memory.geometries--}function c(_,y){return s[y.id]!==void 0||(y.addEventListener("dispose",o),s[y.id]=new WeakRef(y),a.register(y,y.id,y),t.memory.geometries++),y}function h(_){const y=_.attributes;for(const p in y)e.update(y[p],i.ARRAY_BUFFER)}function d(_){const y=_.index,p=_.attributes.position;let f=0;if(p===void 0)return;const x=y!==null?y.array.length:p.array.length/3-1,A=p.count>=65535?Om:Fm,M=new A(Math.ceil(x/3)*6,1),C=M.array;if(y!==null){const g=y.array;f=y.version;for(let w=0,F=0;w<x;w+=3){const L=g[w+0],D=g[w+1],z=g[w+2];C[F++]=L,C[F++]=D,C[F++]=D,C[F++]=z,C[F++]=z,C[F++]=L}}else{f=p.version;for(let g=0,w=0;g<x;g+=3){const F=g+0,L=g+1,D=g+2;C[w++]=F,C[w++]=L,C[w++]=L,C[w++]=D,C[w++]=D,C[w++]=F}}M.version=f;const b=r.get(_);b&&e.remove(b),r.set(_,M)}function u(_){const y=r.get(_);if(y){const p=_.index;p!==null&&y.version<p.version&&d(_)}else d(_);return r.get(_)}function m(){for(const _ in s){const y=s[_].deref();y!==void 0&&l(y)}}return{get:c,update:h,getWireframeAttribute:u,dispose:m}}function ZM(i,e,t){let n;function s(d){n=d}let r,a;function o(d){r=d.type,a=d.bytesPerElement}function l(d,u){i.drawElements(n,u,r,d*a),t.update(u,n,1)}function c(d,u,m){m!==0&&(i.drawElementsInstanced(n,u,r,d*a,m),t.update(u,n,m))}function h(d,u,m){if(m===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(n,u,0,r,d,0,m);let y=0;for(let p=0;p<m;p++)y+=u[p];t.update(y,n,1)}this.setMode=s,this.setIndex=o,this.render=l,this.renderInstances=c,this.renderMultiDraw=h}function JM(i){const e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function n(r,a,o){switch(t.calls++,a){case i.TRIANGLES:t.triangles+=o*(r/3);break;case i.LINES:t.lines+=o*(r/2);break;case i.LINE_STRIP:t.lines+=o*(r-1);break;case i.LINE_LOOP:t.lines+=o*r;break;case i.POINTS:t.points+=o*r;break;default:xt("WebGLInfo: Unknown draw mode:",a);break}}function s(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:s,update:n}}function jM(i,e,t){const n=new WeakMap,s=new nn;function r(a,o,l){const c=a.morphTargetInfluences,h=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,d=h!==void 0?h.length:0;let u=n.get(o);if(u===void 0||u.count!==d){let L=function(){w.dispose(),n.delete(o),o.removeEventListener("dispose",L)};var m=L;u!==void 0&&u.texture.dispose();const _=o.morphAttributes.position!==void 0,y=o.morphAttributes.normal!==void 0,p=o.morphAttributes.color!==void 0,f=o.morphAttributes.position||[],x=o.morphAttributes.normal||[],A=o.morphAttributes.color||[];let M=0;_===!0&&(M=1),y===!0&&(M=2),p===!0&&(M=3);let C=o.attributes.position.count*M,b=1;C>e.maxTextureSize&&(b=Math.ceil(C/e.maxTextureSize),C=e.maxTextureSize);const g=new Float32Array(C*b*4*d),w=new Nm(g,C,b,d);w.type=Wi,w.needsUpdate=!0;const F=M*4;for(let D=0;D<d;D++){const z=f[D],V=x[D],U=A[D],W=C*b*4*D;for(let K=0;K<z.count;K++){const G=K*F;_===!0&&(s.fromBufferAttribute(z,K),g[W+G+0]=s.x,g[W+G+1]=s.y,g[W+G+2]=s.z,g[W+G+3]=0),y===!0&&(s.fromBufferAttribute(V,K),g[W+G+4]=s.x,g[W+G+5]=s.y,g[W+G+6]=s.z,g[W+G+7]=0),p===!0&&(s.fromBufferAttribute(U,K),g[W+G+8]=s.x,g[W+G+9]=s.y,g[W+G+10]=s.z,g[W+G+11]=U.itemSize===4?s.w:1)}}u={count:d,texture:w,size:new Xe(C,b)},n.set(o,u),o.addEventListener("dispose",L)}if(a.isInstancedMesh===!0&&a.morphTexture!==null)l.getUniforms().setValue(i,"morphTexture",a.morphTexture,t);else{let _=0;for(let p=0;p<c.length;p++)_+=c[p];const y=o.morphTargetsRelative?1:1-_;l.getUniforms().setValue(i,"morphTargetBaseInfluence",y),l.getUniforms().setValue(i,"morphTargetInfluences",c)}l.getUniforms().setValue(i,"morphTargetsTexture",u.texture,t),l.getUniforms().setValue(i,"morphTargetsTextureSize",u.size)}return{update:r}}function QM(i,e,t,n,s){let r=new WeakMap;function a(c){const h=s.render.frame,d=c.geometry,u=e.get(c,d);if(r.get(u)!==h&&(e.update(u),r.set(u,h)),c.isInstancedMesh&&(c.hasEventListener("dispose",l)===!1&&c.addEventListener("dispose",l),r.get(c)!==h&&(t.update(c.instanceMatrix,i.ARRAY_BUFFER),c.instanceColor!==null&&t.update(c.instanceColor,i.ARRAY_BUFFER),r.set(c,h))),c.isSkinnedMesh){const m=c.skeleton;r.get(m)!==h&&(m.update(),r.set(m,h))}return u}function o(){r=new WeakMap}function l(c){const h=c.target;h.removeEventListener("dispose",l),n.releaseStatesOfObject(h),t.remove(h.instanceMatrix),h.instanceColor!==null&&t.remove(h.instanceColor)}return{update:a,dispose:o}}const eb={[um]:"LINEAR_TONE_MAPPING",[dm]:"REINHARD_TONE_MAPPING",[fm]:"CINEON_TONE_MAPPING",[pm]:"ACES_FILMIC_TONE_MAPPING",[gm]:"AGX_TONE_MAPPING",[_m]:"NEUTRAL_TONE_MAPPING",[mm]:"CUSTOM_TONE_MAPPING"};function tb(i,e,t,n,s,r){const a=new qi(e,t,{type:i,depthBuffer:s,stencilBuffer:r,samples:n?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1});let o=null,l=null,c=null;const h=new Bt;h.setAttribute("position",new rn([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new rn([0,2,0,0,2,0],2));const d=new Gx({uniforms:{tDiffuse:{value:null}},vertexShader:`
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
			}`,depthTest:!1,depthWrite:!1}),u=new sn(h,d),m=new Ym(-1,1,1,-1,0,1);let _=null,y=null,p=!1,f,x=null,A=[],M=!1;this.setSize=function(C,b){a.setSize(C,b),o!==null&&o.setSize(C,b),l!==null&&l.setSize(C,b);for(let g=0;g<A.length;g++){const w=A[g];w.setSize&&w.setSize(C,b)}},this.setEffects=function(C){A=C,M=A.length>0&&A[0].isRenderPass===!0;const b=a.width,g=a.height;A.length>0&&o===null&&(o=new qi(b,g,{type:Zi,depthBuffer:!1,stencilBuffer:!1}),l=new qi(b,g,{type:Zi,depthBuffer:!1,stencilBuffer:!1}));const w=s===!0&&A.some(F=>F.needsDepthTexture===!0);w!==(a.depthTexture!==null)&&(w===!0&&c===null&&(c=new Jr(b,g),r===!0&&(c.format=Cs,c.type=Zr)),a.dispose(),a.depthTexture=w?c:null,a.resolveDepthBuffer=w,a.storeMultisampledDepthBuffer=w);for(let F=0;F<A.length;F++){const L=A[F];L.setSize&&L.setSize(b,g),w&&L.needsDepthTexture===!0&&L.setDepthTexture&&L.setDepthTexture(c)}},this.begin=function(C,b){if(p||C.toneMapping===ds&&A.length===0)return!1;if(x=b,b!==null){const g=b.width,w=b.height;(a.width!==g||a.height!==w)&&this.setSize(g,w)}return M===!1&&C.setRenderTarget(a),f=C.toneMapping,C.toneMapping=ds,!0},this.hasRenderPass=function(){return M},this.end=function(C,b){C.toneMapping=f,p=!0;let g=a,w=o;for(let F=0;F<A.length;F++){const L=A[F];L.enabled!==!1&&(L.render(C,w,g,b),L.needsSwap!==!1&&(g=w,w=w===o?l:o))}if(_!==C.outputColorSpace||y!==C.toneMapping){_=C.outputColorSpace,y=C.toneMapping,d.defines={},_t.getTransfer(_)===Lt&&(d.defines.SRGB_TRANSFER="");const F=eb[y];F&&(d.defines[F]=""),d.needsUpdate=!0}d.uniforms.tDiffuse.value=g.texture,C.setRenderTarget(x),C.render(u,m),x=null,p=!1},this.isCompositing=function(){return p},this.dispose=function(){a.dispose(),o!==null&&o.dispose(),l!==null&&l.dispose(),h.dispose(),d.dispose()}}const ng=new kn,ig=new Jr(1,1),sg=new Gm(1),rg=new Nm,ag=new vx,og=new Hm,Lf=[],Df=[],Nf=new Float32Array(16),If=new Float32Array(9),Uf=new Float32Array(4);function na(i,e,t){const n=i[0];if(n<=0||n>0)return i;const s=e*t;let r=Lf[s];if(r===void 0&&(r=new Float32Array(s),Lf[s]=r),e!==0){n.toArray(r,0);for(let a=1,o=0;a!==e;++a)o+=t,i[a].toArray(r,o)}return r}function Sn(i,e){if(i.length!==e.length)return!1;for(let t=0,n=i.length;t<n;t++)if(i[t]!==e[t])return!1;return!0}function Mn(i,e){for(let t=0,n=e.length;t<n;t++)i[t]=e[t]}function Al(i,e){let t=Df[e];t===void 0&&(t=new Int32Array(e),Df[e]=t);for(let n=0;n!==e;++n)t[n]=i.allocateTextureUnit();return t}function nb(i,e){const t=this.cache;t[0]!==e&&(i.uniform1f(this.addr,e),t[0]=e)}function ib(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Sn(t,e))return;i.uniform2fv(this.addr,e),Mn(t,e)}}function sb(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(i.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(Sn(t,e))return;i.uniform3fv(this.addr,e),Mn(t,e)}}function rb(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Sn(t,e))return;i.uniform4fv(this.addr,e),Mn(t,e)}}function ab(i,e){const t=this.cache,n=e.elements;if(n===void 0){if(Sn(t,e))return;i.uniformMatrix2fv(this.addr,!1,e),Mn(t,e)}else{if(Sn(t,n))return;Uf.set(n),i.uniformMatrix2fv(this.addr,!1,Uf),Mn(t,n)}}function ob(i,e){const t=this.cache,n=e.elements;if(n===void 0){if(Sn(t,e))return;i.uniformMatrix3fv(this.addr,!1,e),Mn(t,e)}else{if(Sn(t,n))return;If.set(n),i.uniformMatrix3fv(this.addr,!1,If),Mn(t,n)}}function lb(i,e){const t=this.cache,n=e.elements;if(n===void 0){if(Sn(t,e))return;i.uniformMatrix4fv(this.addr,!1,e),Mn(t,e)}else{if(Sn(t,n))return;Nf.set(n),i.uniformMatrix4fv(this.addr,!1,Nf),Mn(t,n)}}function cb(i,e){const t=this.cache;t[0]!==e&&(i.uniform1i(this.addr,e),t[0]=e)}function hb(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Sn(t,e))return;i.uniform2iv(this.addr,e),Mn(t,e)}}function ub(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(Sn(t,e))return;i.uniform3iv(this.addr,e),Mn(t,e)}}function db(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Sn(t,e))return;i.uniform4iv(this.addr,e),Mn(t,e)}}function fb(i,e){const t=this.cache;t[0]!==e&&(i.uniform1ui(this.addr,e),t[0]=e)}function pb(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Sn(t,e))return;i.uniform2uiv(this.addr,e),Mn(t,e)}}function mb(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(Sn(t,e))return;i.uniform3uiv(this.addr,e),Mn(t,e)}}function gb(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Sn(t,e))return;i.uniform4uiv(this.addr,e),Mn(t,e)}}function Rl(i){return i.version===0&&(i.compareFunction=Rm,i.needsUpdate=!0),i}function _b(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_2D_SHADOW?r=Rl(ig):r=ng,t.setTexture2D(e||r,s)}function vb(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),t.setTexture3D(e||ag,s)}function xb(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_CUBE_SHADOW?r=Rl(sg):r=og,t.setTextureCube(e||r,s)}function yb(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),t.setTexture2DArray(e||rg,s)}function Sb(i){switch(i){case 5126:return nb;case 35664:return ib;case 35665:return sb;case 35666:return rb;case 35674:return ab;case 35675:return ob;case 35676:return lb;case 5124:case 35670:return cb;case 35667:case 35671:return hb;case 35668:case 35672:return ub;case 35669:case 35673:return db;case 5125:return fb;case 36294:return pb;case 36295:return mb;case 36296:return gb;case 35678:case 36198:case 36298:case 36306:case 35682:return _b;case 35679:case 36299:case 36307:return vb;case 35680:case 36300:case 36308:case 36293:return xb;case 36289:case 36303:case 36311:case 36292:return yb}}function Mb(i,e){i.uniform1fv(this.addr,e)}function bb(i,e){const t=na(e,this.size,2);i.uniform2fv(this.addr,t)}function wb(i,e){const t=na(e,this.size,3);i.uniform3fv(this.addr,t)}function Eb(i,e){const t=na(e,this.size,4);i.uniform4fv(this.addr,t)}function Tb(i,e){const t=na(e,this.size,4);i.uniformMatrix2fv(this.addr,!1,t)}function Ab(i,e){const t=na(e,this.size,9);i.uniformMatrix3fv(this.addr,!1,t)}function Rb(i,e){const t=na(e,this.size,16);i.uniformMatrix4fv(this.addr,!1,t)}function Cb(i,e){i.uniform1iv(this.addr,e)}function Pb(i,e){i.uniform2iv(this.addr,e)}function Lb(i,e){i.uniform3iv(this.addr,e)}function Db(i,e){i.uniform4iv(this.addr,e)}function Nb(i,e){i.uniform1uiv(this.addr,e)}function Ib(i,e){i.uniform2uiv(this.addr,e)}function Ub(i,e){i.uniform3uiv(this.addr,e)}function Fb(i,e){i.uniform4uiv(this.addr,e)}function Ob(i,e,t){const n=this.cache,s=e.length,r=Al(t,s);Sn(n,r)||(i.uniform1iv(this.addr,r),Mn(n,r));let a;this.type===i.SAMPLER_2D_SHADOW?a=Rl(ig):a=ng;for(let o=0;o!==s;++o)t.setTexture2D(e[o]||a,r[o])}function kb(i,e,t){const n=this.cache,s=e.length,r=Al(t,s);Sn(n,r)||(i.uniform1iv(this.addr,r),Mn(n,r));for(let a=0;a!==s;++a)t.setTexture3D(e[a]||ag,r[a])}function Bb(i,e,t){const n=this.cache,s=e.length,r=Al(t,s);Sn(n,r)||(i.uniform1iv(this.addr,r),Mn(n,r));let a;this.type===i.SAMPLER_CUBE_SHADOW?a=Rl(sg):a=og;for(let o=0;o!==s;++o)t.setTextureCube(e[o]||a,r[o])}function zb(i,e,t){const n=this.cache,s=e.length,r=Al(t,s);Sn(n,r)||(i.uniform1iv(this.addr,r),Mn(n,r));for(let a=0;a!==s;++a)t.setTexture2DArray(e[a]||rg,r[a])}function Hb(i){switch(i){case 5126:return Mb;case 35664:return bb;case 35665:return wb;case 35666:return Eb;case 35674:return Tb;case 35675:return Ab;case 35676:return Rb;case 5124:case 35670:return Cb;case 35667:case 35671:return Pb;case 35668:case 35672:return Lb;case 35669:case 35673:return Db;case 5125:return Nb;case 36294:return Ib;case 36295:return Ub;case 36296:return Fb;case 35678:case 36198:case 36298:case 36306:case 35682:return Ob;case 35679:case 36299:case 36307:return kb;case 35680:case 36300:case 36308:case 36293:return Bb;case 36289:case 36303:case 36311:case 36292:return zb}}class Gb{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.setValue=Sb(t.type)}}class Vb{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=Hb(t.type)}}class Wb{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,n){const s=this.seq;for(let r=0,a=s.length;r!==a;++r){const o=s[r];o.setValue(e,t[o.id],n)}}}const Tc=/(\w+)(\])?(\[|\.)?/g;function Ff(i,e){i.seq.push(e),i.map[e.id]=e}function Xb(i,e,t){const n=i.name,s=n.length;for(Tc.lastIndex=0;;){const r=Tc.exec(n),a=Tc.lastIndex;let o=r[1];const l=r[2]==="]",c=r[3];if(l&&(o=o|0),c===void 0||c==="["&&a+2===s){Ff(t,c===void 0?new Gb(o,i,e):new Vb(o,i,e));break}else{let d=t.map[o];d===void 0&&(d=new Wb(o),Ff(t,d)),t=d}}}class Zo{constructor(e,t){this.seq=[],this.map={};const n=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let a=0;a<n;++a){const o=e.getActiveUniform(t,a),l=e.getUniformLocation(t,o.name);Xb(o,l,this)}const s=[],r=[];for(const a of this.seq)a.type===e.SAMPLER_2D_SHADOW||a.type===e.SAMPLER_CUBE_SHADOW||a.type===e.SAMPLER_2D_ARRAY_SHADOW?s.push(a):r.push(a);s.length>0&&(this.seq=s.concat(r))}setValue(e,t,n,s){const r=this.map[t];r!==void 0&&r.setValue(e,n,s)}setOptional(e,t,n){const s=t[n];s!==void 0&&this.setValue(e,n,s)}static upload(e,t,n,s){for(let r=0,a=t.length;r!==a;++r){const o=t[r],l=n[o.id];l.needsUpdate!==!1&&o.setValue(e,l.value,s)}}static seqWithValue(e,t){const n=[];for(let s=0,r=e.length;s!==r;++s){const a=e[s];a.id in t&&n.push(a)}return n}}function Of(i,e,t){const n=i.createShader(e);return i.shaderSource(n,t),i.compileShader(n),n}const $b=37297;let qb=0;function Yb(i,e){const t=i.split(`
`),n=[],s=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let a=s;a<r;a++){const o=a+1;n.push(`${o===e?">":" "} ${o}: ${t[a]}`)}return n.join(`
`)}const kf=new it;function Kb(i){_t._getMatrix(kf,_t.workingColorSpace,i);const e=`mat3( ${kf.elements.map(t=>t.toFixed(4))} )`;switch(_t.getTransfer(i)){case rl:return[e,"LinearTransferOETF"];case Lt:return[e,"sRGBTransferOETF"];default:return Je("WebGLProgram: Unsupported color space: ",i),[e,"LinearTransferOETF"]}}function Bf(i,e,t){const n=i.getShaderParameter(e,i.COMPILE_STATUS),r=(i.getShaderInfoLog(e)||"").trim();if(n&&r==="")return"";const a=/ERROR: 0:(\d+)/.exec(r);if(a){const o=parseInt(a[1]);return t.toUpperCase()+`

`+r+`

`+Yb(i.getShaderSource(e),o)}else return r}function Zb(i,e){const t=Kb(e);return[`vec4 ${i}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}const Jb={[um]:"Linear",[dm]:"Reinhard",[fm]:"Cineon",[pm]:"ACESFilmic",[gm]:"AgX",[_m]:"Neutral",[mm]:"Custom"};function jb(i,e){const t=Jb[e];return t===void 0?(Je("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+i+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+i+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}const Oo=new B;function Qb(){_t.getLuminanceCoefficients(Oo);const i=Oo.x.toFixed(4),e=Oo.y.toFixed(4),t=Oo.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${i}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function ew(i){return[i.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",i.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(Ta).join(`
`)}function tw(i){const e=[];for(const t in i){const n=i[t];n!==!1&&e.push("#define "+t+" "+n)}return e.join(`
`)}function nw(i,e){const t={},n=i.getProgramParameter(e,i.ACTIVE_ATTRIBUTES);for(let s=0;s<n;s++){const r=i.getActiveAttrib(e,s),a=r.name;let o=1;r.type===i.FLOAT_MAT2&&(o=2),r.type===i.FLOAT_MAT3&&(o=3),r.type===i.FLOAT_MAT4&&(o=4),t[a]={type:r.type,location:i.getAttribLocation(e,a),locationSize:o}}return t}function Ta(i){return i!==""}function zf(i,e){const t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return i.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function Hf(i,e){return i.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}const iw=/^[ \t]*#include +<([\w\d./]+)>/gm;function Gh(i){return i.replace(iw,sw)}function sw(i,e){const t=ot[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return Gh(t)}const rw=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function Gf(i){return i.replace(rw,aw)}function aw(i,e,t,n){let s="";for(let r=parseInt(e);r<parseInt(t);r++)s+=n.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function Vf(i){let e=`precision ${i.precision} float;
	precision ${i.precision} int;
	precision ${i.precision} sampler2D;
	precision ${i.precision} samplerCube;
	precision ${i.precision} sampler3D;
	precision ${i.precision} sampler2DArray;
	precision ${i.precision} sampler2DShadow;
	precision ${i.precision} samplerCubeShadow;
	precision ${i.precision} sampler2DArrayShadow;
	precision ${i.precision} isampler2D;
	precision ${i.precision} isampler3D;
	precision ${i.precision} isamplerCube;
	precision ${i.precision} isampler2DArray;
	precision ${i.precision} usampler2D;
	precision ${i.precision} usampler3D;
	precision ${i.precision} usamplerCube;
	precision ${i.precision} usampler2DArray;
	`;return i.precision==="highp"?e+=`
#define HIGH_PRECISION`:i.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:i.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}const ow={[Wo]:"SHADOWMAP_TYPE_PCF",[Ea]:"SHADOWMAP_TYPE_VSM"};function lw(i){return ow[i.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}const cw={[Oa]:"ENVMAP_MODE_REFRACTION"};function hw(i){return i.envMap===!1?"ENVMAP_MODE_REFLECTION":cw[i.envMapMode]||"ENVMAP_MODE_REFLECTION"}const uw={[hm]:"ENVMAP_BLENDING_MULTIPLY",[Kv]:"ENVMAP_BLENDING_MIX",[Zv]:"ENVMAP_BLENDING_ADD"};function dw(i){return i.envMap===!1?"ENVMAP_BLENDING_NONE":uw[i.combine]||"ENVMAP_BLENDING_NONE"}function fw(i,e,t,n){const s=i.getContext(),r=t.defines;let a=t.vertexShader,o=t.fragmentShader;const l=lw(t),c=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=hw(t),d=dw(t),u=ew(t),m=tw(r),_=s.createProgram();let y,p,f=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(y=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Ta).join(`
`),y.length>0&&(y+=`
`),p=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Ta).join(`
`),p.length>0&&(p+=`
`)):(y=[Vf(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+h:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(Ta).join(`
`),p=[Vf(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+c:"",t.envMap?"#define "+h:"",t.envMap?"#define "+d:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==ds?"#define TONE_MAPPING":"",t.toneMapping!==ds?ot.tonemapping_pars_fragment:"",t.toneMapping!==ds?jb("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",ot.colorspace_pars_fragment,Zb("linearToOutputTexel",t.outputColorSpace),Qb(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(Ta).join(`
`)),a=Gh(a),a=zf(a,t),a=Hf(a,t),o=Gh(o),o=zf(o,t),o=Hf(o,t),a=Gf(a),o=Gf(o),t.isRawShaderMaterial!==!0&&(f=`#version 300 es
`,y=[u,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+y,p=["#define varying in",t.glslVersion===Xd?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===Xd?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+p);const x=f+y+a,A=f+p+o,M=Of(s,s.VERTEX_SHADER,x),C=Of(s,s.FRAGMENT_SHADER,A);s.attachShader(_,M),s.attachShader(_,C),t.index0AttributeName!==void 0?s.bindAttribLocation(_,0,t.index0AttributeName):t.hasPositionAttribute===!0&&s.bindAttribLocation(_,0,"position"),s.linkProgram(_);function b(L){if(i.debug.checkShaderErrors){const D=s.getProgramInfoLog(_)||"",z=s.getShaderInfoLog(M)||"",V=s.getShaderInfoLog(C)||"",U=D.trim(),W=z.trim(),K=V.trim();let G=!0,le=!0;if(s.getProgramParameter(_,s.LINK_STATUS)===!1)if(G=!1,typeof i.debug.onShaderError=="function")i.debug.onShaderError(s,_,M,C);else{const J=Bf(s,M,"vertex"),Q=Bf(s,C,"fragment");xt("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(_,s.VALIDATE_STATUS)+`

Material Name: `+L.name+`
Material Type: `+L.type+`

Program Info Log: `+U+`
`+J+`
`+Q)}else U!==""?Je("WebGLProgram: Program Info Log:",U):(W===""||K==="")&&(le=!1);le&&(L.diagnostics={runnable:G,programLog:U,vertexShader:{log:W,prefix:y},fragmentShader:{log:K,prefix:p}})}s.deleteShader(M),s.deleteShader(C),g=new Zo(s,_),w=nw(s,_)}let g;this.getUniforms=function(){return g===void 0&&b(this),g};let w;this.getAttributes=function(){return w===void 0&&b(this),w};let F=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return F===!1&&(F=s.getProgramParameter(_,$b)),F},this.destroy=function(){n.releaseStatesOfProgram(this),s.deleteProgram(_),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=qb++,this.cacheKey=e,this.usedTimes=1,this.program=_,this.vertexShader=M,this.fragmentShader=C,this}let pw=0;class mw{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,n){const s=this._getShaderCacheForMaterial(e);return s.has(t)===!1&&(s.add(t),t.usedTimes++),s.has(n)===!1&&(s.add(n),n.usedTimes++),this}remove(e){const t=this.materialCache.get(e);for(const n of t)n.usedTimes--,n.usedTimes===0&&this.shaderCache.delete(n.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){const t=this.materialCache;let n=t.get(e);return n===void 0&&(n=new Set,t.set(e,n)),n}_getShaderStage(e){const t=this.shaderCache;let n=t.get(e);return n===void 0&&(n=new gw(e),t.set(e,n)),n}}class gw{constructor(e){this.id=pw++,this.code=e,this.usedTimes=0}}function _w(i){return i===js||i===nl||i===il}function vw(i,e,t,n,s,r){const a=new bu,o=new mw,l=new Set,c=[],h=new Map,d=n.logarithmicDepthBuffer,u={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function m(g){return l.add(g),g===0?"uv":`uv${g}`}function _(g,w,F,L,D,z){const V=L.fog,U=D.geometry,W=g.isMeshStandardMaterial||g.isMeshLambertMaterial||g.isMeshPhongMaterial?L.environment:null,K=g.isMeshStandardMaterial||g.isMeshLambertMaterial&&!g.envMap||g.isMeshPhongMaterial&&!g.envMap,G=e.get(g.envMap||W,K),le=u[g.type];let J=n.precision;g.precision!==null&&(J=n.getMaxPrecision(g.precision),J!==g.precision&&Je("WebGLProgram.getParameters:",g.precision,"not supported, using",J,"instead."));const Q=U.morphAttributes.position||U.morphAttributes.normal||U.morphAttributes.color,se=Q!==void 0?Q.length:0;let de=0;U.morphAttributes.position!==void 0&&(de=1),U.morphAttributes.normal!==void 0&&(de=2),U.morphAttributes.color!==void 0&&(de=3);let ue,ee,me,ve;if(le){const Re=Vi[le];ue=Re.vertexShader,ee=Re.fragmentShader}else{ue=g.vertexShader,ee=g.fragmentShader;const Re=o.getVertexShaderStage(g),st=o.getFragmentShaderStage(g);o.update(g,Re,st),me=Re.id,ve=st.id}const Ae=i.getRenderTarget(),Me=i.state.buffers.depth.getReversed(),Ve=D.isInstancedMesh===!0,tt=D.isBatchedMesh===!0,He=!!g.map,ct=!!g.matcap,rt=!!G,Qe=rt&&G.isPMREMTexture===!0,Xt=!!g.aoMap,kt=!!g.lightMap,an=!!g.bumpMap&&g.wireframe===!1,Nt=!!g.normalMap,wn=!!g.displacementMap,vt=!!g.emissiveMap,pn=!!g.metalnessMap,Yt=!!g.roughnessMap,on=g.anisotropy>0,k=g.clearcoat>0,Ce=g.diffuseRoughness>0,qe=g.dispersion>0,nt=g.retroreflectivity>0,be=g.iridescence>0,Ut=g.sheen>0,ze=g.transmission>0,$e=on&&!!g.anisotropyMap,P=k&&!!g.clearcoatMap,S=k&&!!g.clearcoatNormalMap,$=k&&!!g.clearcoatRoughnessMap,he=Ce&&!!g.diffuseRoughnessMap,ae=be&&!!g.iridescenceMap,_e=be&&!!g.iridescenceThicknessMap,xe=Ut&&!!g.sheenColorMap,te=Ut&&!!g.sheenRoughnessMap,ie=!!g.specularMap,pe=!!g.specularColorMap,O=!!g.specularIntensityMap,re=ze&&!!g.transmissionMap,ne=ze&&!!g.thicknessMap,we=!!g.gradientMap,ge=!!g.alphaMap,Se=g.alphaTest>0,Ge=!!g.alphaHash,Ke=!!g.extensions;let ce=ds;g.toneMapped&&(Ae===null||Ae.isXRRenderTarget===!0)&&(ce=i.toneMapping);const Oe=Qe?G.isCompressedCubeTexture?G.image[0].mipmaps:G.mipmaps:null,Ze={shaderID:le,shaderType:g.type,shaderName:g.name,vertexShader:ue,fragmentShader:ee,defines:g.defines,customVertexShaderID:me,customFragmentShaderID:ve,isRawShaderMaterial:g.isRawShaderMaterial===!0,glslVersion:g.glslVersion,precision:J,batching:tt,batchingColor:tt&&D._colorsTexture!==null,instancing:Ve,instancingColor:Ve&&D.instanceColor!==null,instancingMorph:Ve&&D.morphTexture!==null,outputColorSpace:Ae===null?i.outputColorSpace:Ae.isXRRenderTarget===!0?Ae.texture.colorSpace:_t.workingColorSpace,alphaToCoverage:!!g.alphaToCoverage,map:He,matcap:ct,envMap:rt,envMapMode:rt&&G.mapping,envMapPMREM:Qe,envMapMaxLod:Qe?Oe.length-1:null,envMapSize:Qe?Oe[0].width:null,aoMap:Xt,lightMap:kt,bumpMap:an,normalMap:Nt,displacementMap:wn,emissiveMap:vt,normalMapObjectSpace:Nt&&g.normalMapType===Qv,normalMapTangentSpace:Nt&&g.normalMapType===Oh,packedNormalMap:Nt&&g.normalMapType===Oh&&_w(g.normalMap.format),metalnessMap:pn,roughnessMap:Yt,anisotropy:on,anisotropyMap:$e,clearcoat:k,clearcoatMap:P,clearcoatNormalMap:S,clearcoatRoughnessMap:$,diffuseRoughness:Ce,diffuseRoughnessMap:he,dispersion:qe,retroreflection:nt,iridescence:be,iridescenceMap:ae,iridescenceThicknessMap:_e,sheen:Ut,sheenColorMap:xe,sheenRoughnessMap:te,specularMap:ie,specularColorMap:pe,specularIntensityMap:O,transmission:ze,transmissionMap:re,thicknessMap:ne,gradientMap:we,opaque:g.transparent===!1&&g.blending===La&&g.alphaToCoverage===!1,alphaMap:ge,alphaTest:Se,alphaHash:Ge,combine:g.combine,mapUv:He&&m(g.map.channel),aoMapUv:Xt&&m(g.aoMap.channel),lightMapUv:kt&&m(g.lightMap.channel),bumpMapUv:an&&m(g.bumpMap.channel),normalMapUv:Nt&&m(g.normalMap.channel),displacementMapUv:wn&&m(g.displacementMap.channel),emissiveMapUv:vt&&m(g.emissiveMap.channel),metalnessMapUv:pn&&m(g.metalnessMap.channel),roughnessMapUv:Yt&&m(g.roughnessMap.channel),anisotropyMapUv:$e&&m(g.anisotropyMap.channel),clearcoatMapUv:P&&m(g.clearcoatMap.channel),clearcoatNormalMapUv:S&&m(g.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:$&&m(g.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:he&&m(g.diffuseRoughnessMap.channel),iridescenceMapUv:ae&&m(g.iridescenceMap.channel),iridescenceThicknessMapUv:_e&&m(g.iridescenceThicknessMap.channel),sheenColorMapUv:xe&&m(g.sheenColorMap.channel),sheenRoughnessMapUv:te&&m(g.sheenRoughnessMap.channel),specularMapUv:ie&&m(g.specularMap.channel),specularColorMapUv:pe&&m(g.specularColorMap.channel),specularIntensityMapUv:O&&m(g.specularIntensityMap.channel),transmissionMapUv:re&&m(g.transmissionMap.channel),thicknessMapUv:ne&&m(g.thicknessMap.channel),alphaMapUv:ge&&m(g.alphaMap.channel),vertexTangents:!!U.attributes.tangent&&(Nt||on),vertexNormals:!!U.attributes.normal,vertexColors:g.vertexColors,vertexAlphas:g.vertexColors===!0&&!!U.attributes.color&&U.attributes.color.itemSize===4,pointsUvs:D.isPoints===!0&&!!U.attributes.uv&&(He||ge),fog:!!V,useFog:g.fog===!0,fogExp2:!!V&&V.isFogExp2,flatShading:g.wireframe===!1&&(g.flatShading===!0||U.attributes.normal===void 0&&Nt===!1&&(g.isMeshLambertMaterial||g.isMeshPhongMaterial||g.isMeshStandardMaterial||g.isMeshPhysicalMaterial)),sizeAttenuation:g.sizeAttenuation===!0,logarithmicDepthBuffer:d,reversedDepthBuffer:Me,skinning:D.isSkinnedMesh===!0,hasPositionAttribute:U.attributes.position!==void 0,morphTargets:U.morphAttributes.position!==void 0,morphNormals:U.morphAttributes.normal!==void 0,morphColors:U.morphAttributes.color!==void 0,morphTargetsCount:se,morphTextureStride:de,numSunLights:w.sun.length,numDirLights:w.directional.length,numPointLights:w.point.length,numSpotLights:w.spot.length,numSpotLightMaps:w.spotLightMap.length,numRectAreaLights:w.rectArea.length,numHemiLights:w.hemi.length,numSunLightShadows:w.sunShadowMap.length,numDirLightShadows:w.directionalShadowMap.length,numPointLightShadows:w.pointShadowMap.length,numSpotLightShadows:w.spotShadowMap.length,numSpotLightShadowsWithMaps:w.numSpotLightShadowsWithMaps,numLightProbes:w.numLightProbes,numLightProbeGrids:z.filter(Re=>Re.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:g.dithering,shadowMapEnabled:i.shadowMap.enabled&&F.length>0,shadowMapType:i.shadowMap.type,toneMapping:ce,decodeVideoTexture:He&&g.map.isVideoTexture===!0&&_t.getTransfer(g.map.colorSpace)===Lt,decodeVideoTextureEmissive:vt&&g.emissiveMap.isVideoTexture===!0&&_t.getTransfer(g.emissiveMap.colorSpace)===Lt,premultipliedAlpha:g.premultipliedAlpha,doubleSided:g.side===pi,flipSided:g.side===Zn,useDepthPacking:g.depthPacking>=0,depthPacking:g.depthPacking||0,index0AttributeName:g.index0AttributeName,extensionClipCullDistance:Ke&&g.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Ke&&g.extensions.multiDraw===!0||tt)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:g.customProgramCacheKey()};return Ze.vertexUv1s=l.has(1),Ze.vertexUv2s=l.has(2),Ze.vertexUv3s=l.has(3),l.clear(),Ze}function y(g){const w=[];if(g.shaderID?w.push(g.shaderID):(w.push(g.customVertexShaderID),w.push(g.customFragmentShaderID)),g.defines!==void 0)for(const F in g.defines)w.push(F),w.push(g.defines[F]);return g.isRawShaderMaterial===!1&&(p(w,g),f(w,g),w.push(i.outputColorSpace)),w.push(g.customProgramCacheKey),w.join()}function p(g,w){g.push(w.precision),g.push(w.outputColorSpace),g.push(w.envMapMode),g.push(w.envMapPMREM),g.push(w.envMapMaxLod),g.push(w.envMapSize),g.push(w.mapUv),g.push(w.alphaMapUv),g.push(w.lightMapUv),g.push(w.aoMapUv),g.push(w.bumpMapUv),g.push(w.normalMapUv),g.push(w.displacementMapUv),g.push(w.emissiveMapUv),g.push(w.metalnessMapUv),g.push(w.roughnessMapUv),g.push(w.anisotropyMapUv),g.push(w.clearcoatMapUv),g.push(w.clearcoatNormalMapUv),g.push(w.clearcoatRoughnessMapUv),g.push(w.diffuseRoughnessMapUv),g.push(w.iridescenceMapUv),g.push(w.iridescenceThicknessMapUv),g.push(w.sheenColorMapUv),g.push(w.sheenRoughnessMapUv),g.push(w.specularMapUv),g.push(w.specularColorMapUv),g.push(w.specularIntensityMapUv),g.push(w.transmissionMapUv),g.push(w.thicknessMapUv),g.push(w.combine),g.push(w.fogExp2),g.push(w.sizeAttenuation),g.push(w.morphTargetsCount),g.push(w.numSunLights),g.push(w.numDirLights),g.push(w.numPointLights),g.push(w.numSpotLights),g.push(w.numSpotLightMaps),g.push(w.numHemiLights),g.push(w.numRectAreaLights),g.push(w.numSunLightShadows),g.push(w.numDirLightShadows),g.push(w.numPointLightShadows),g.push(w.numSpotLightShadows),g.push(w.numSpotLightShadowsWithMaps),g.push(w.numLightProbes),g.push(w.numLightProbeGrids),g.push(w.shadowMapType),g.push(w.toneMapping),g.push(w.numClippingPlanes),g.push(w.numClipIntersection),g.push(w.depthPacking)}function f(g,w){a.disableAll(),w.instancing&&a.enable(0),w.instancingColor&&a.enable(1),w.instancingMorph&&a.enable(2),w.matcap&&a.enable(3),w.envMap&&a.enable(4),w.normalMapObjectSpace&&a.enable(5),w.normalMapTangentSpace&&a.enable(6),w.clearcoat&&a.enable(7),w.iridescence&&a.enable(8),w.alphaTest&&a.enable(9),w.vertexColors&&a.enable(10),w.vertexAlphas&&a.enable(11),w.vertexUv1s&&a.enable(12),w.vertexUv2s&&a.enable(13),w.vertexUv3s&&a.enable(14),w.vertexTangents&&a.enable(15),w.anisotropy&&a.enable(16),w.alphaHash&&a.enable(17),w.batching&&a.enable(18),w.dispersion&&a.enable(19),w.retroreflection&&a.enable(24),w.diffuseRoughness&&a.enable(25),w.batchingColor&&a.enable(20),w.gradientMap&&a.enable(21),w.packedNormalMap&&a.enable(22),w.vertexNormals&&a.enable(23),g.push(a.mask),a.disableAll(),w.fog&&a.enable(0),w.useFog&&a.enable(1),w.flatShading&&a.enable(2),w.logarithmicDepthBuffer&&a.enable(3),w.reversedDepthBuffer&&a.enable(4),w.skinning&&a.enable(5),w.morphTargets&&a.enable(6),w.morphNormals&&a.enable(7),w.morphColors&&a.enable(8),w.premultipliedAlpha&&a.enable(9),w.shadowMapEnabled&&a.enable(10),w.doubleSided&&a.enable(11),w.flipSided&&a.enable(12),w.useDepthPacking&&a.enable(13),w.dithering&&a.enable(14),w.transmission&&a.enable(15),w.sheen&&a.enable(16),w.opaque&&a.enable(17),w.pointsUvs&&a.enable(18),w.decodeVideoTexture&&a.enable(19),w.decodeVideoTextureEmissive&&a.enable(20),w.alphaToCoverage&&a.enable(21),w.numLightProbeGrids>0&&a.enable(22),w.hasPositionAttribute&&a.enable(23),g.push(a.mask)}function x(g){const w=u[g.type];let F;if(w){const L=Vi[w];F=Bx.clone(L.uniforms)}else F=g.uniforms;return F}function A(g,w){let F=h.get(w);return F!==void 0?++F.usedTimes:(F=new fw(i,w,g,s),c.push(F),h.set(w,F)),F}function M(g){if(--g.usedTimes===0){const w=c.indexOf(g);c[w]=c[c.length-1],c.pop(),h.delete(g.cacheKey),g.destroy()}}function C(g){o.remove(g)}function b(){o.dispose()}return{getParameters:_,getProgramCacheKey:y,getUniforms:x,acquireProgram:A,releaseProgram:M,releaseShaderCache:C,programs:c,dispose:b}}function xw(){let i=new WeakMap;function e(a){return i.has(a)}function t(a){let o=i.get(a);return o===void 0&&(o={},i.set(a,o)),o}function n(a){i.delete(a)}function s(a,o,l){i.get(a)[o]=l}function r(){i=new WeakMap}return{has:e,get:t,remove:n,update:s,dispose:r}}function yw(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.material.id!==e.material.id?i.material.id-e.material.id:i.materialVariant!==e.materialVariant?i.materialVariant-e.materialVariant:i.z!==e.z?i.z-e.z:i.id-e.id}function Wf(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.z!==e.z?e.z-i.z:i.id-e.id}function Xf(){const i=[];let e=0;const t=[],n=[],s=[];function r(){e=0,t.length=0,n.length=0,s.length=0}function a(u){let m=0;return u.isInstancedMesh&&(m+=2),u.isSkinnedMesh&&(m+=1),m}function o(u,m,_,y,p,f){let x=i[e];return x===void 0?(x={id:u.id,object:u,geometry:m,material:_,materialVariant:a(u),groupOrder:y,renderOrder:u.renderOrder,z:p,group:f},i[e]=x):(x.id=u.id,x.object=u,x.geometry=m,x.material=_,x.materialVariant=a(u),x.groupOrder=y,x.renderOrder=u.renderOrder,x.z=p,x.group=f),e++,x}function l(u,m,_,y,p,f,x){x.reversedDepth===!0&&(p=-p);const A=o(u,m,_,y,p,f);_.transmission>0?n.push(A):_.transparent===!0?s.push(A):t.push(A)}function c(u,m,_,y,p,f){const x=o(u,m,_,y,p,f);_.transmission>0?n.unshift(x):_.transparent===!0?s.unshift(x):t.unshift(x)}function h(u,m){t.length>1&&t.sort(u||yw),n.length>1&&n.sort(m||Wf),s.length>1&&s.sort(m||Wf)}function d(){for(let u=e,m=i.length;u<m;u++){const _=i[u];if(_.id===null)break;_.id=null,_.object=null,_.geometry=null,_.material=null,_.group=null}}return{opaque:t,transmissive:n,transparent:s,init:r,push:l,unshift:c,finish:d,sort:h}}function Sw(){let i=new WeakMap;function e(n,s){const r=i.get(n);let a;return r===void 0?(a=new Xf,i.set(n,[a])):s>=r.length?(a=new Xf,r.push(a)):a=r[s],a}function t(){i=new WeakMap}return{get:e,dispose:t}}function Mw(){const i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new B,color:new lt};break;case"SpotLight":t={position:new B,direction:new B,color:new lt,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new B,color:new lt,distance:0,decay:0};break;case"HemisphereLight":t={direction:new B,skyColor:new lt,groundColor:new lt};break;case"RectAreaLight":t={color:new lt,position:new B,halfWidth:new B,halfHeight:new B};break}return i[e.id]=t,t}}}function bw(){const i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Xe};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Xe};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Xe,shadowCameraNear:1,shadowCameraFar:1e3};break}return i[e.id]=t,t}}}let ww=0;function Ew(i,e){return(e.castShadow?2:0)-(i.castShadow?2:0)+(e.map?1:0)-(i.map?1:0)}function Tw(i){const e=new Mw,t=bw(),n={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let c=0;c<9;c++)n.probe.push(new B);const s=new B,r=new Dt,a=new Dt;function o(c){let h=0,d=0,u=0;for(let z=0;z<9;z++)n.probe[z].set(0,0,0);let m=0,_=0,y=0,p=0,f=0,x=0,A=0,M=0,C=0,b=0,g=0,w=0,F=0,L=0;c.sort(Ew);for(let z=0,V=c.length;z<V;z++){const U=c[z],W=U.color,K=U.intensity,G=U.distance;let le=null;if(U.shadow&&U.shadow.map&&(U.shadow.map.texture.format===js?le=U.shadow.map.texture:le=U.shadow.map.depthTexture||U.shadow.map.texture),U.isAmbientLight)h+=W.r*K,d+=W.g*K,u+=W.b*K;else if(U.isLightProbe){for(let J=0;J<9;J++)n.probe[J].addScaledVector(U.sh.coefficients[J],K);L++}else if(U.isSunLight){const J=e.get(U);if(J.color.copy(U.color).multiplyScalar(U.intensity),U.castShadow){const Q=U.shadow,se=t.get(U);se.shadowIntensity=Q.intensity,se.shadowBias=Q.bias,se.shadowNormalBias=Q.normalBias,se.shadowRadius=Q.radius,se.shadowMapSize.copy(Q.mapSize).multiply(Q.getFrameExtents()),n.sunShadow[_]=se,n.sunShadowMap[_]=le;const de=Q.getViewportCount();for(let ue=0;ue<de;ue++)n.sunShadowMatrix[y+ue]=Q.getMatrix(ue),n.sunShadowCascade[y+ue]=Q._cascadeData[ue];y+=de,_++}n.sun[m]=J,m++}else if(U.isDirectionalLight){const J=e.get(U);if(J.color.copy(U.color).multiplyScalar(U.intensity),U.castShadow){const Q=U.shadow,se=t.get(U);se.shadowIntensity=Q.intensity,se.shadowBias=Q.bias,se.shadowNormalBias=Q.normalBias,se.shadowRadius=Q.radius,se.shadowMapSize=Q.mapSize,n.directionalShadow[p]=se,n.directionalShadowMap[p]=le,n.directionalShadowMatrix[p]=U.shadow.matrix,C++}n.directional[p]=J,p++}else if(U.isSpotLight){const J=e.get(U);J.position.setFromMatrixPosition(U.matrixWorld),J.color.copy(W).multiplyScalar(K),J.distance=G,J.coneCos=Math.cos(U.angle),J.penumbraCos=Math.cos(U.angle*(1-U.penumbra)),J.decay=U.decay,n.spot[x]=J;const Q=U.shadow;if(U.map&&(n.spotLightMap[w]=U.map,w++,Q.updateMatrices(U),U.castShadow&&F++),n.spotLightMatrix[x]=Q.matrix,U.castShadow){const se=t.get(U);se.shadowIntensity=Q.intensity,se.shadowBias=Q.bias,se.shadowNormalBias=Q.normalBias,se.shadowRadius=Q.radius,se.shadowMapSize=Q.mapSize,n.spotShadow[x]=se,n.spotShadowMap[x]=le,g++}x++}else if(U.isRectAreaLight){const J=e.get(U);J.color.copy(W).multiplyScalar(K),J.halfWidth.set(U.width*.5,0,0),J.halfHeight.set(0,U.height*.5,0),n.rectArea[A]=J,A++}else if(U.isPointLight){const J=e.get(U);if(J.color.copy(U.color).multiplyScalar(U.intensity),J.distance=U.distance,J.decay=U.decay,U.castShadow){const Q=U.shadow,se=t.get(U);se.shadowIntensity=Q.intensity,se.shadowBias=Q.bias,se.shadowNormalBias=Q.normalBias,se.shadowRadius=Q.radius,se.shadowMapSize=Q.mapSize,se.shadowCameraNear=Q.camera.near,se.shadowCameraFar=Q.camera.far,n.pointShadow[f]=se,n.pointShadowMap[f]=le,n.pointShadowMatrix[f]=U.shadow.matrix,b++}n.point[f]=J,f++}else if(U.isHemisphereLight){const J=e.get(U);J.skyColor.copy(U.color).multiplyScalar(K),J.groundColor.copy(U.groundColor).multiplyScalar(K),n.hemi[M]=J,M++}}A>0&&(i.has("OES_texture_float_linear")===!0?(n.rectAreaLTC1=De.LTC_FLOAT_1,n.rectAreaLTC2=De.LTC_FLOAT_2):(n.rectAreaLTC1=De.LTC_HALF_1,n.rectAreaLTC2=De.LTC_HALF_2)),n.ambient[0]=h,n.ambient[1]=d,n.ambient[2]=u;const D=n.hash;(D.sunLength!==m||D.directionalLength!==p||D.pointLength!==f||D.spotLength!==x||D.rectAreaLength!==A||D.hemiLength!==M||D.numSunShadows!==_||D.numDirectionalShadows!==C||D.numPointShadows!==b||D.numSpotShadows!==g||D.numSpotMaps!==w||D.numLightProbes!==L)&&(n.sun.length=m,n.directional.length=p,n.spot.length=x,n.rectArea.length=A,n.point.length=f,n.hemi.length=M,n.sunShadow.length=_,n.sunShadowMap.length=_,n.sunShadowMatrix.length=y,n.sunShadowCascade.length=y,n.directionalShadow.length=C,n.directionalShadowMap.length=C,n.directionalShadowMatrix.length=C,n.pointShadow.length=b,n.pointShadowMap.length=b,n.pointShadowMatrix.length=b,n.spotShadow.length=g,n.spotShadowMap.length=g,n.spotLightMatrix.length=g+w-F,n.spotLightMap.length=w,n.numSpotLightShadowsWithMaps=F,n.numLightProbes=L,D.sunLength=m,D.directionalLength=p,D.pointLength=f,D.spotLength=x,D.rectAreaLength=A,D.hemiLength=M,D.numSunShadows=_,D.numDirectionalShadows=C,D.numPointShadows=b,D.numSpotShadows=g,D.numSpotMaps=w,D.numLightProbes=L,n.version=ww++)}function l(c,h){let d=0,u=0,m=0,_=0,y=0,p=0;const f=h.matrixWorldInverse;for(let x=0,A=c.length;x<A;x++){const M=c[x];if(M.isSunLight){const C=n.sun[d];C.direction.setFromMatrixPosition(M.matrixWorld),C.direction.transformDirection(f),d++}else if(M.isDirectionalLight){const C=n.directional[u];C.direction.setFromMatrixPosition(M.matrixWorld),s.setFromMatrixPosition(M.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(f),u++}else if(M.isSpotLight){const C=n.spot[_];C.position.setFromMatrixPosition(M.matrixWorld),C.position.applyMatrix4(f),C.direction.setFromMatrixPosition(M.matrixWorld),s.setFromMatrixPosition(M.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(f),_++}else if(M.isRectAreaLight){const C=n.rectArea[y];C.position.setFromMatrixPosition(M.matrixWorld),C.position.applyMatrix4(f),a.identity(),r.copy(M.matrixWorld),r.premultiply(f),a.extractRotation(r),C.halfWidth.set(M.width*.5,0,0),C.halfHeight.set(0,M.height*.5,0),C.halfWidth.applyMatrix4(a),C.halfHeight.applyMatrix4(a),y++}else if(M.isPointLight){const C=n.point[m];C.position.setFromMatrixPosition(M.matrixWorld),C.position.applyMatrix4(f),m++}else if(M.isHemisphereLight){const C=n.hemi[p];C.direction.setFromMatrixPosition(M.matrixWorld),C.direction.transformDirection(f),p++}}}return{setup:o,setupView:l,state:n}}function $f(i){const e=new Tw(i),t=[],n=[],s=[];function r(d){h.camera=d,t.length=0,n.length=0,s.length=0}function a(d){d.isLightProbeGrid?s.push(d):t.push(d)}function o(d){n.push(d)}function l(){e.setup(t),s.sort((d,u)=>d.priority-u.priority||d.id-u.id)}function c(d){e.setupView(t,d)}const h={lightsArray:t,shadowsArray:n,lightProbeGridArray:s,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:h,setupLights:l,setupLightsView:c,pushLight:a,pushShadow:o}}function Aw(i){let e=new WeakMap;function t(s,r=0){const a=e.get(s);let o;return a===void 0?(o=new $f(i),e.set(s,[o])):r>=a.length?(o=new $f(i),a.push(o)):o=a[r],o}function n(){e=new WeakMap}return{get:t,dispose:n}}const Rw=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,Cw=`uniform sampler2D shadow_pass;
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
}`,Pw=[new B(1,0,0),new B(-1,0,0),new B(0,1,0),new B(0,-1,0),new B(0,0,1),new B(0,0,-1)],Lw=[new B(0,-1,0),new B(0,-1,0),new B(0,0,1),new B(0,0,-1),new B(0,-1,0),new B(0,-1,0)],qf=new Dt,Sa=new B,Ac=new B;function Dw(i,e,t){let n=new za;const s=new Xe,r=new Xe,a=new nn,o=new Vx,l=new Wx,c={},h=t.maxTextureSize,d={[Ds]:Zn,[Zn]:Ds,[pi]:pi},u=new Qs({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new Xe},radius:{value:4}},vertexShader:Rw,fragmentShader:Cw}),m=u.clone();m.defines.HORIZONTAL_PASS=1;const _=new Bt;_.setAttribute("position",new _i(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));const y=new sn(_,u),p=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Wo;let f=this.type;this.render=function(b,g,w){if(p.enabled===!1||p.autoUpdate===!1&&p.needsUpdate===!1||b.length===0)return;this.type===Pv&&(Je("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=Wo);const F=i.getRenderTarget(),L=i.getActiveCubeFace(),D=i.getActiveMipmapLevel(),z=i.state;z.setBlending(zr),z.buffers.depth.getReversed()===!0?z.buffers.color.setClear(0,0,0,0):z.buffers.color.setClear(1,1,1,1),z.buffers.depth.setTest(!0),z.setScissorTest(!1);const V=f!==this.type;V&&g.traverse(function(U){U.material&&(Array.isArray(U.material)?U.material.forEach(W=>W.needsUpdate=!0):U.material.needsUpdate=!0)});for(let U=0,W=b.length;U<W;U++){const K=b[U],G=K.shadow;if(G===void 0){Je("WebGLShadowMap:",K,"has no shadow.");continue}if(G.autoUpdate===!1&&G.needsUpdate===!1)continue;s.copy(G.mapSize);const le=G.getFrameExtents();s.multiply(le),r.copy(G.mapSize),(s.x>h||s.y>h)&&(s.x>h&&(r.x=Math.floor(h/le.x),s.x=r.x*le.x,G.mapSize.x=r.x),s.y>h&&(r.y=Math.floor(h/le.y),s.y=r.y*le.y,G.mapSize.y=r.y));const J=i.state.buffers.depth.getReversed();if(G.camera._reversedDepth=J,G.map===null||V===!0){if(G.map!==null&&(G.map.depthTexture!==null&&(G.map.depthTexture.dispose(),G.map.depthTexture=null),G.map.dispose()),this.type===Ea){if(K.isPointLight){Je("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}G.map=new qi(s.x,s.y,{format:js,type:Zi,minFilter:Kn,magFilter:Kn,generateMipmaps:!1}),G.map.texture.name=K.name+".shadowMap",G.map.depthTexture=new Jr(s.x,s.y,Wi),G.map.depthTexture.name=K.name+".shadowMapDepth",G.map.depthTexture.format=Ns,G.map.depthTexture.compareFunction=null,G.map.depthTexture.minFilter=Dn,G.map.depthTexture.magFilter=Dn}else K.isPointLight?(G.map=new Tu(s.x),G.map.depthTexture=new Gm(s.x,Ki)):(G.map=new qi(s.x,s.y),G.map.depthTexture=new Jr(s.x,s.y,Ki)),G.map.depthTexture.name=K.name+".shadowMap",G.map.depthTexture.format=Ns,this.type===Wo?(G.map.depthTexture.compareFunction=J?Am:Tm,G.map.depthTexture.minFilter=Kn,G.map.depthTexture.magFilter=Kn):(G.map.depthTexture.compareFunction=null,G.map.depthTexture.minFilter=Dn,G.map.depthTexture.magFilter=Dn);G.camera.updateProjectionMatrix()}G.map.isWebGLCubeRenderTarget!==!0&&(G.map.width!==s.x||G.map.height!==s.y)&&G.map.setSize(s.x,s.y);const Q=G.map.isWebGLCubeRenderTarget?6:G.getViewportCount();K.isPointLight!==!0&&G.updateMatrices(K,w);const se=(G.camera.layers.mask&4294967294)!==0?G.camera.layers:w.layers;for(let de=0;de<Q;de++){const ue=G.getCamera(de);if(K.isPointLight){const ee=G.camera,me=G.matrix,ve=K.distance||ee.far;ve!==ee.far&&(ee.far=ve,ee.updateProjectionMatrix()),Sa.setFromMatrixPosition(K.matrixWorld),ee.position.copy(Sa),Ac.copy(ee.position),Ac.add(Pw[de]),ee.up.copy(Lw[de]),ee.lookAt(Ac),ee.updateMatrixWorld(),me.makeTranslation(-Sa.x,-Sa.y,-Sa.z),qf.multiplyMatrices(ee.projectionMatrix,ee.matrixWorldInverse),G._frustum.setFromProjectionMatrix(qf,ee.coordinateSystem,ee.reversedDepth)}if(G.map.isWebGLCubeRenderTarget)i.setRenderTarget(G.map,de),i.clear();else{de===0&&(i.setRenderTarget(G.map),i.clear());const ee=G.getViewport(de);a.set(r.x*ee.x,r.y*ee.y,r.x*ee.z,r.y*ee.w),z.viewport(a)}n=G.getFrustum(de),M(g,w,ue,K,se,this.type)}G.isPointLightShadow!==!0&&this.type===Ea&&x(G,w),G.needsUpdate=!1}f=this.type,p.needsUpdate=!1,i.setRenderTarget(F,L,D)};function x(b,g){const w=e.update(y);u.defines.VSM_SAMPLES!==b.blurSamples&&(u.defines.VSM_SAMPLES=b.blurSamples,m.defines.VSM_SAMPLES=b.blurSamples,u.needsUpdate=!0,m.needsUpdate=!0),b.mapPass===null?b.mapPass=new qi(s.x,s.y,{format:js,type:Zi}):(b.mapPass.width!==b.map.width||b.mapPass.height!==b.map.height)&&b.mapPass.setSize(b.map.width,b.map.height),u.uniforms.shadow_pass.value=b.map.depthTexture,u.uniforms.resolution.value.set(b.map.width,b.map.height),u.uniforms.radius.value=b.radius,i.setRenderTarget(b.mapPass),i.clear(),i.renderBufferDirect(g,null,w,u,y,null),m.uniforms.shadow_pass.value=b.mapPass.texture,m.uniforms.resolution.value.set(b.map.width,b.map.height),m.uniforms.radius.value=b.radius,i.setRenderTarget(b.map),i.clear(),i.renderBufferDirect(g,null,w,m,y,null)}function A(b,g,w,F){let L=null;const D=w.isPointLight===!0?b.customDistanceMaterial:b.customDepthMaterial;if(D!==void 0)L=D;else if(L=w.isPointLight===!0?l:o,i.localClippingEnabled&&g.clipShadows===!0&&Array.isArray(g.clippingPlanes)&&g.clippingPlanes.length!==0||g.displacementMap&&g.displacementScale!==0||g.alphaMap&&g.alphaTest>0||g.map&&g.alphaTest>0||g.alphaToCoverage===!0){const z=L.uuid,V=g.uuid;let U=c[z];U===void 0&&(U={},c[z]=U);let W=U[V];W===void 0&&(W=L.clone(),U[V]=W,g.addEventListener("dispose",C)),L=W}if(L.visible=g.visible,L.wireframe=g.wireframe,F===Ea?L.side=g.shadowSide!==null?g.shadowSide:g.side:L.side=g.shadowSide!==null?g.shadowSide:d[g.side],L.alphaMap=g.alphaMap,L.alphaTest=g.alphaToCoverage===!0?.5:g.alphaTest,L.map=g.map,L.clipShadows=g.clipShadows,L.clippingPlanes=g.clippingPlanes,L.clipIntersection=g.clipIntersection,L.displacementMap=g.displacementMap,L.displacementScale=g.displacementScale,L.displacementBias=g.displacementBias,L.wireframeLinewidth=g.wireframeLinewidth,L.linewidth=g.linewidth,w.isPointLight===!0&&L.isMeshDistanceMaterial===!0){const z=i.properties.get(L);z.light=w}return L}function M(b,g,w,F,L,D){if(b.visible===!1)return;if(b.layers.test(L)&&(b.isMesh||b.isLine||b.isPoints)&&(b.castShadow||b.receiveShadow&&D===Ea)&&(!b.frustumCulled||b.intersectsFrustum(n))){b.modelViewMatrix.multiplyMatrices(w.matrixWorldInverse,b.matrixWorld);const U=e.update(b),W=b.material;if(Array.isArray(W)){const K=U.groups;for(let G=0,le=K.length;G<le;G++){const J=K[G],Q=W[J.materialIndex];if(Q&&Q.visible){const se=A(b,Q,F,D);b.onBeforeShadow(i,b,g,w,U,se,J),i.renderBufferDirect(w,null,U,se,b,J),b.onAfterShadow(i,b,g,w,U,se,J)}}}else if(W.visible){const K=A(b,W,F,D);b.onBeforeShadow(i,b,g,w,U,K,null),i.renderBufferDirect(w,null,U,K,b,null),b.onAfterShadow(i,b,g,w,U,K,null)}}const V=b.children;for(let U=0,W=V.length;U<W;U++)M(V[U],g,w,F,L,D)}function C(b){b.target.removeEventListener("dispose",C);for(const w in c){const F=c[w],L=b.target.uuid;L in F&&(F[L].dispose(),delete F[L])}}}function Nw(i,e){function t(){let O=!1;const re=new nn;let ne=null;const we=new nn(0,0,0,0);return{setMask:function(ge){ne!==ge&&!O&&(i.colorMask(ge,ge,ge,ge),ne=ge)},setLocked:function(ge){O=ge},setClear:function(ge,Se,Ge,Ke,ce){ce===!0&&(ge*=Ke,Se*=Ke,Ge*=Ke),re.set(ge,Se,Ge,Ke),we.equals(re)===!1&&(i.clearColor(ge,Se,Ge,Ke),we.copy(re))},reset:function(){O=!1,ne=null,we.set(-1,0,0,0)}}}function n(){let O=!1,re=!1,ne=null,we=null,ge=null;return{setReversed:function(Se){if(re!==Se){const Ge=e.get("EXT_clip_control");Se?Ge.clipControlEXT(Ge.LOWER_LEFT_EXT,Ge.ZERO_TO_ONE_EXT):Ge.clipControlEXT(Ge.LOWER_LEFT_EXT,Ge.NEGATIVE_ONE_TO_ONE_EXT),re=Se;const Ke=ge;ge=null,this.setClear(Ke)}},getReversed:function(){return re},setTest:function(Se){Se?Me(i.DEPTH_TEST):Ve(i.DEPTH_TEST)},setMask:function(Se){ne!==Se&&!O&&(i.depthMask(Se),ne=Se)},setFunc:function(Se){if(re&&(Se=cx[Se]),we!==Se){switch(Se){case jc:i.depthFunc(i.NEVER);break;case Qc:i.depthFunc(i.ALWAYS);break;case eh:i.depthFunc(i.LESS);break;case Fa:i.depthFunc(i.LEQUAL);break;case th:i.depthFunc(i.EQUAL);break;case nh:i.depthFunc(i.GEQUAL);break;case ih:i.depthFunc(i.GREATER);break;case sh:i.depthFunc(i.NOTEQUAL);break;default:i.depthFunc(i.LEQUAL)}we=Se}},setLocked:function(Se){O=Se},setClear:function(Se){ge!==Se&&(ge=Se,re&&(Se=1-Se),i.clearDepth(Se))},reset:function(){O=!1,ne=null,we=null,ge=null,re=!1}}}function s(){let O=!1,re=null,ne=null,we=null,ge=null,Se=null,Ge=null,Ke=null,ce=null;return{setTest:function(Oe){O||(Oe?Me(i.STENCIL_TEST):Ve(i.STENCIL_TEST))},setMask:function(Oe){re!==Oe&&!O&&(i.stencilMask(Oe),re=Oe)},setFunc:function(Oe,Ze,Re){(ne!==Oe||we!==Ze||ge!==Re)&&(i.stencilFunc(Oe,Ze,Re),ne=Oe,we=Ze,ge=Re)},setOp:function(Oe,Ze,Re){(Se!==Oe||Ge!==Ze||Ke!==Re)&&(i.stencilOp(Oe,Ze,Re),Se=Oe,Ge=Ze,Ke=Re)},setLocked:function(Oe){O=Oe},setClear:function(Oe){ce!==Oe&&(i.clearStencil(Oe),ce=Oe)},reset:function(){O=!1,re=null,ne=null,we=null,ge=null,Se=null,Ge=null,Ke=null,ce=null}}}const r=new t,a=new n,o=new s;let l={};const c=new WeakMap;let h={},d={},u={},m=new WeakMap,_=[],y=null,p=!1,f=null,x=null,A=null,M=null,C=null,b=null,g=null,w=new lt(0,0,0),F=0,L=!1,D=null,z=null,V=null,U=null,W=null;const K=i.getParameter(i.MAX_COMBINED_TEXTURE_IMAGE_UNITS);let G=!1,le=0;const J=i.getParameter(i.VERSION);J.indexOf("WebGL")!==-1?(le=parseFloat(/^WebGL (\d)/.exec(J)[1]),G=le>=1):J.indexOf("OpenGL ES")!==-1&&(le=parseFloat(/^OpenGL ES (\d)/.exec(J)[1]),G=le>=2);let Q=null,se={};const de=i.getParameter(i.SCISSOR_BOX),ue=i.getParameter(i.VIEWPORT),ee=new nn().fromArray(de),me=new nn().fromArray(ue);function ve(O,re,ne,we){const ge=new Uint8Array(4),Se=i.createTexture();i.bindTexture(O,Se),i.texParameteri(O,i.TEXTURE_MIN_FILTER,i.NEAREST),i.texParameteri(O,i.TEXTURE_MAG_FILTER,i.NEAREST);for(let Ge=0;Ge<ne;Ge++)O===i.TEXTURE_3D||O===i.TEXTURE_2D_ARRAY?i.texImage3D(re,0,i.RGBA,1,1,we,0,i.RGBA,i.UNSIGNED_BYTE,ge):i.texImage2D(re+Ge,0,i.RGBA,1,1,0,i.RGBA,i.UNSIGNED_BYTE,ge);return Se}const Ae={};Ae[i.TEXTURE_2D]=ve(i.TEXTURE_2D,i.TEXTURE_2D,1),Ae[i.TEXTURE_CUBE_MAP]=ve(i.TEXTURE_CUBE_MAP,i.TEXTURE_CUBE_MAP_POSITIVE_X,6),Ae[i.TEXTURE_2D_ARRAY]=ve(i.TEXTURE_2D_ARRAY,i.TEXTURE_2D_ARRAY,1,1),Ae[i.TEXTURE_3D]=ve(i.TEXTURE_3D,i.TEXTURE_3D,1,1),r.setClear(0,0,0,1),a.setClear(1),o.setClear(0),Me(i.DEPTH_TEST),a.setFunc(Fa),an(!1),Nt(Hd),Me(i.CULL_FACE),Xt(zr);function Me(O){h[O]!==!0&&(i.enable(O),h[O]=!0)}function Ve(O){h[O]!==!1&&(i.disable(O),h[O]=!1)}function tt(O,re){return u[O]!==re?(i.bindFramebuffer(O,re),u[O]=re,O===i.DRAW_FRAMEBUFFER&&(u[i.FRAMEBUFFER]=re),O===i.FRAMEBUFFER&&(u[i.DRAW_FRAMEBUFFER]=re),!0):!1}function He(O,re){let ne=_,we=!1;if(O){ne=m.get(re),ne===void 0&&(ne=[],m.set(re,ne));const ge=O.textures;if(ne.length!==ge.length||ne[0]!==i.COLOR_ATTACHMENT0){for(let Se=0,Ge=ge.length;Se<Ge;Se++)ne[Se]=i.COLOR_ATTACHMENT0+Se;ne.length=ge.length,we=!0}}else ne[0]!==i.BACK&&(ne[0]=i.BACK,we=!0);we&&i.drawBuffers(ne)}function ct(O){return y!==O?(i.useProgram(O),y=O,!0):!1}const rt={[Ur]:i.FUNC_ADD,[Dv]:i.FUNC_SUBTRACT,[Nv]:i.FUNC_REVERSE_SUBTRACT};rt[Iv]=i.MIN,rt[Uv]=i.MAX;const Qe={[Fv]:i.ZERO,[Ov]:i.ONE,[kv]:i.SRC_COLOR,[lm]:i.SRC_ALPHA,[Wv]:i.SRC_ALPHA_SATURATE,[Gv]:i.DST_COLOR,[zv]:i.DST_ALPHA,[Bv]:i.ONE_MINUS_SRC_COLOR,[cm]:i.ONE_MINUS_SRC_ALPHA,[Vv]:i.ONE_MINUS_DST_COLOR,[Hv]:i.ONE_MINUS_DST_ALPHA,[Xv]:i.CONSTANT_COLOR,[$v]:i.ONE_MINUS_CONSTANT_COLOR,[qv]:i.CONSTANT_ALPHA,[Yv]:i.ONE_MINUS_CONSTANT_ALPHA};function Xt(O,re,ne,we,ge,Se,Ge,Ke,ce,Oe){if(O===zr){p===!0&&(Ve(i.BLEND),p=!1);return}if(p===!1&&(Me(i.BLEND),p=!0),O!==Lv){if(O!==f||Oe!==L){if((x!==Ur||C!==Ur)&&(i.blendEquation(i.FUNC_ADD),x=Ur,C=Ur),Oe)switch(O){case La:i.blendFuncSeparate(i.ONE,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Gd:i.blendFunc(i.ONE,i.ONE);break;case Vd:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case Wd:i.blendFuncSeparate(i.DST_COLOR,i.ONE_MINUS_SRC_ALPHA,i.ZERO,i.ONE);break;default:xt("WebGLState: Invalid blending: ",O);break}else switch(O){case La:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Gd:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE,i.ONE,i.ONE);break;case Vd:xt("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case Wd:xt("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:xt("WebGLState: Invalid blending: ",O);break}A=null,M=null,b=null,g=null,w.set(0,0,0),F=0,f=O,L=Oe}return}ge=ge||re,Se=Se||ne,Ge=Ge||we,(re!==x||ge!==C)&&(i.blendEquationSeparate(rt[re],rt[ge]),x=re,C=ge),(ne!==A||we!==M||Se!==b||Ge!==g)&&(i.blendFuncSeparate(Qe[ne],Qe[we],Qe[Se],Qe[Ge]),A=ne,M=we,b=Se,g=Ge),(Ke.equals(w)===!1||ce!==F)&&(i.blendColor(Ke.r,Ke.g,Ke.b,ce),w.copy(Ke),F=ce),f=O,L=!1}function kt(O,re){O.side===pi?Ve(i.CULL_FACE):Me(i.CULL_FACE);let ne=O.side===Zn;re&&(ne=!ne),an(ne),O.blending===La&&O.transparent===!1?Xt(zr):Xt(O.blending,O.blendEquation,O.blendSrc,O.blendDst,O.blendEquationAlpha,O.blendSrcAlpha,O.blendDstAlpha,O.blendColor,O.blendAlpha,O.premultipliedAlpha),a.setFunc(O.depthFunc),a.setTest(O.depthTest),a.setMask(O.depthWrite),r.setMask(O.colorWrite);const we=O.stencilWrite;o.setTest(we),we&&(o.setMask(O.stencilWriteMask),o.setFunc(O.stencilFunc,O.stencilRef,O.stencilFuncMask),o.setOp(O.stencilFail,O.stencilZFail,O.stencilZPass)),vt(O.polygonOffset,O.polygonOffsetFactor,O.polygonOffsetUnits),O.alphaToCoverage===!0?Me(i.SAMPLE_ALPHA_TO_COVERAGE):Ve(i.SAMPLE_ALPHA_TO_COVERAGE)}function an(O){D!==O&&(O?i.frontFace(i.CW):i.frontFace(i.CCW),D=O)}function Nt(O){O!==Rv?(Me(i.CULL_FACE),O!==z&&(O===Hd?i.cullFace(i.BACK):O===Cv?i.cullFace(i.FRONT):i.cullFace(i.FRONT_AND_BACK))):Ve(i.CULL_FACE),z=O}function wn(O){O!==V&&(G&&i.lineWidth(O),V=O)}function vt(O,re,ne){O?(Me(i.POLYGON_OFFSET_FILL),(U!==re||W!==ne)&&(U=re,W=ne,a.getReversed()&&(re=-re,ne=-ne),i.polygonOffset(re,ne))):Ve(i.POLYGON_OFFSET_FILL)}function pn(O){O?Me(i.SCISSOR_TEST):Ve(i.SCISSOR_TEST)}function Yt(O){O===void 0&&(O=i.TEXTURE0+K-1),Q!==O&&(i.activeTexture(O),Q=O)}function on(O,re,ne){ne===void 0&&(Q===null?ne=i.TEXTURE0+K-1:ne=Q);let we=se[ne];we===void 0&&(we={type:void 0,texture:void 0},se[ne]=we),(we.type!==O||we.texture!==re)&&(Q!==ne&&(i.activeTexture(ne),Q=ne),i.bindTexture(O,re||Ae[O]),we.type=O,we.texture=re)}function k(){const O=se[Q];O!==void 0&&O.type!==void 0&&(i.bindTexture(O.type,null),O.type=void 0,O.texture=void 0)}function Ce(){try{i.compressedTexImage2D(...arguments)}catch(O){xt("WebGLState:",O)}}function qe(){try{i.compressedTexImage3D(...arguments)}catch(O){xt("WebGLState:",O)}}function nt(){try{i.texSubImage2D(...arguments)}catch(O){xt("WebGLState:",O)}}function be(){try{i.texSubImage3D(...arguments)}catch(O){xt("WebGLState:",O)}}function Ut(){try{i.compressedTexSubImage2D(...arguments)}catch(O){xt("WebGLState:",O)}}function ze(){try{i.compressedTexSubImage3D(...arguments)}catch(O){xt("WebGLState:",O)}}function $e(){try{i.texStorage2D(...arguments)}catch(O){xt("WebGLState:",O)}}function P(){try{i.texStorage3D(...arguments)}catch(O){xt("WebGLState:",O)}}function S(){try{i.texImage2D(...arguments)}catch(O){xt("WebGLState:",O)}}function $(){try{i.texImage3D(...arguments)}catch(O){xt("WebGLState:",O)}}function he(O){return d[O]!==void 0?d[O]:i.getParameter(O)}function ae(O,re){d[O]!==re&&(i.pixelStorei(O,re),d[O]=re)}function _e(O){ee.equals(O)===!1&&(i.scissor(O.x,O.y,O.z,O.w),ee.copy(O))}function xe(O){me.equals(O)===!1&&(i.viewport(O.x,O.y,O.z,O.w),me.copy(O))}function te(O,re){let ne=c.get(re);ne===void 0&&(ne=new WeakMap,c.set(re,ne));let we=ne.get(O);we===void 0&&(we=i.getUniformBlockIndex(re,O.name),i.uniformBlockBinding(re,we,we),ne.set(O,we))}function ie(O,re,ne){const ge=c.get(re).get(O);l[ge]!==ne&&(i.bindBufferBase(i.UNIFORM_BUFFER,ge,ne),l[ge]=ne)}function pe(){i.disable(i.BLEND),i.disable(i.CULL_FACE),i.disable(i.DEPTH_TEST),i.disable(i.POLYGON_OFFSET_FILL),i.disable(i.SCISSOR_TEST),i.disable(i.STENCIL_TEST),i.disable(i.SAMPLE_ALPHA_TO_COVERAGE),i.blendEquation(i.FUNC_ADD),i.blendFunc(i.ONE,i.ZERO),i.blendFuncSeparate(i.ONE,i.ZERO,i.ONE,i.ZERO),i.blendColor(0,0,0,0),i.colorMask(!0,!0,!0,!0),i.clearColor(0,0,0,0),i.depthMask(!0),i.depthFunc(i.LESS),a.setReversed(!1),i.clearDepth(1),i.stencilMask(4294967295),i.stencilFunc(i.ALWAYS,0,4294967295),i.stencilOp(i.KEEP,i.KEEP,i.KEEP),i.clearStencil(0),i.cullFace(i.BACK),i.frontFace(i.CCW),i.polygonOffset(0,0),i.activeTexture(i.TEXTURE0),i.bindFramebuffer(i.FRAMEBUFFER,null),i.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),i.bindFramebuffer(i.READ_FRAMEBUFFER,null),i.useProgram(null),i.lineWidth(1),i.scissor(0,0,i.canvas.width,i.canvas.height),i.viewport(0,0,i.canvas.width,i.canvas.height),i.pixelStorei(i.PACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,!1),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,i.BROWSER_DEFAULT_WEBGL),i.pixelStorei(i.PACK_ROW_LENGTH,0),i.pixelStorei(i.PACK_SKIP_PIXELS,0),i.pixelStorei(i.PACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_ROW_LENGTH,0),i.pixelStorei(i.UNPACK_IMAGE_HEIGHT,0),i.pixelStorei(i.UNPACK_SKIP_PIXELS,0),i.pixelStorei(i.UNPACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_SKIP_IMAGES,0),h={},d={},Q=null,se={},u={},l={},m=new WeakMap,_=[],y=null,p=!1,f=null,x=null,A=null,M=null,C=null,b=null,g=null,w=new lt(0,0,0),F=0,L=!1,D=null,z=null,V=null,U=null,W=null,ee.set(0,0,i.canvas.width,i.canvas.height),me.set(0,0,i.canvas.width,i.canvas.height),r.reset(),a.reset(),o.reset()}return{buffers:{color:r,depth:a,stencil:o},enable:Me,disable:Ve,bindFramebuffer:tt,drawBuffers:He,useProgram:ct,setBlending:Xt,setMaterial:kt,setFlipSided:an,setCullFace:Nt,setLineWidth:wn,setPolygonOffset:vt,setScissorTest:pn,activeTexture:Yt,bindTexture:on,unbindTexture:k,compressedTexImage2D:Ce,compressedTexImage3D:qe,texImage2D:S,texImage3D:$,pixelStorei:ae,getParameter:he,updateUBOMapping:te,uniformBlockBinding:ie,texStorage2D:$e,texStorage3D:P,texSubImage2D:nt,texSubImage3D:be,compressedTexSubImage2D:Ut,compressedTexSubImage3D:ze,scissor:_e,viewport:xe,reset:pe}}function Iw(i,e,t,n,s,r,a){const o=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),c=new Xe,h=new WeakMap,d=new Set;let u;const m=new WeakMap,_=new Set,y=new FinalizationRegistry(P=>_.delete(P));let p=!1;try{p=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function f(P,S){return p?new OffscreenCanvas(P,S):al("canvas")}function x(P,S,$){let he=1;const ae=$e(P);if((ae.width>$||ae.height>$)&&(he=$/Math.max(ae.width,ae.height)),he<1)if(typeof HTMLImageElement<"u"&&P instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&P instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&P instanceof ImageBitmap||typeof VideoFrame<"u"&&P instanceof VideoFrame){const _e=Math.floor(he*ae.width),xe=Math.floor(he*ae.height);u===void 0&&(u=f(_e,xe));const te=S?f(_e,xe):u;return te.width=_e,te.height=xe,te.getContext("2d").drawImage(P,0,0,_e,xe),Je("WebGLRenderer: Texture has been resized from ("+ae.width+"x"+ae.height+") to ("+_e+"x"+xe+")."),te}else return"data"in P&&Je("WebGLRenderer: Image in DataTexture is too big ("+ae.width+"x"+ae.height+")."),P;return P}function A(P){return P.generateMipmaps}function M(P){i.generateMipmap(P)}function C(P){return P.isWebGLCubeRenderTarget?i.TEXTURE_CUBE_MAP:P.isWebGL3DRenderTarget?i.TEXTURE_3D:P.isWebGLArrayRenderTarget||P.isCompressedArrayTexture?i.TEXTURE_2D_ARRAY:i.TEXTURE_2D}function b(P,S,$,he,ae,_e=!1){if(P!==null){if(i[P]!==void 0)return i[P];Je("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+P+"'")}let xe;he&&(xe=e.get("EXT_texture_norm16"),xe||Je("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let te=S;if(S===i.RED&&($===i.FLOAT&&(te=i.R32F),$===i.HALF_FLOAT&&(te=i.R16F),$===i.UNSIGNED_BYTE&&(te=i.R8),$===i.UNSIGNED_SHORT&&xe&&(te=xe.R16_EXT),$===i.SHORT&&xe&&(te=xe.R16_SNORM_EXT)),S===i.RED_INTEGER&&($===i.UNSIGNED_BYTE&&(te=i.R8UI),$===i.UNSIGNED_SHORT&&(te=i.R16UI),$===i.UNSIGNED_INT&&(te=i.R32UI),$===i.BYTE&&(te=i.R8I),$===i.SHORT&&(te=i.R16I),$===i.INT&&(te=i.R32I)),S===i.RG&&($===i.FLOAT&&(te=i.RG32F),$===i.HALF_FLOAT&&(te=i.RG16F),$===i.UNSIGNED_BYTE&&(te=i.RG8),$===i.UNSIGNED_SHORT&&xe&&(te=xe.RG16_EXT),$===i.SHORT&&xe&&(te=xe.RG16_SNORM_EXT)),S===i.RG_INTEGER&&($===i.UNSIGNED_BYTE&&(te=i.RG8UI),$===i.UNSIGNED_SHORT&&(te=i.RG16UI),$===i.UNSIGNED_INT&&(te=i.RG32UI),$===i.BYTE&&(te=i.RG8I),$===i.SHORT&&(te=i.RG16I),$===i.INT&&(te=i.RG32I)),S===i.RGB_INTEGER&&($===i.UNSIGNED_BYTE&&(te=i.RGB8UI),$===i.UNSIGNED_SHORT&&(te=i.RGB16UI),$===i.UNSIGNED_INT&&(te=i.RGB32UI),$===i.BYTE&&(te=i.RGB8I),$===i.SHORT&&(te=i.RGB16I),$===i.INT&&(te=i.RGB32I)),S===i.RGBA_INTEGER&&($===i.UNSIGNED_BYTE&&(te=i.RGBA8UI),$===i.UNSIGNED_SHORT&&(te=i.RGBA16UI),$===i.UNSIGNED_INT&&(te=i.RGBA32UI),$===i.BYTE&&(te=i.RGBA8I),$===i.SHORT&&(te=i.RGBA16I),$===i.INT&&(te=i.RGBA32I)),S===i.RGB&&($===i.UNSIGNED_SHORT&&xe&&(te=xe.RGB16_EXT),$===i.SHORT&&xe&&(te=xe.RGB16_SNORM_EXT),$===i.UNSIGNED_INT_5_9_9_9_REV&&(te=i.RGB9_E5),$===i.UNSIGNED_INT_10F_11F_11F_REV&&(te=i.R11F_G11F_B10F)),S===i.RGBA){const ie=_e?rl:_t.getTransfer(ae);$===i.FLOAT&&(te=i.RGBA32F),$===i.HALF_FLOAT&&(te=i.RGBA16F),$===i.UNSIGNED_BYTE&&(te=ie===Lt?i.SRGB8_ALPHA8:i.RGBA8),$===i.UNSIGNED_SHORT&&xe&&(te=xe.RGBA16_EXT),$===i.SHORT&&xe&&(te=xe.RGBA16_SNORM_EXT),$===i.UNSIGNED_SHORT_4_4_4_4&&(te=i.RGBA4),$===i.UNSIGNED_SHORT_5_5_5_1&&(te=i.RGB5_A1)}return(te===i.R16F||te===i.R32F||te===i.RG16F||te===i.RG32F||te===i.RGBA16F||te===i.RGBA32F)&&e.get("EXT_color_buffer_float"),te}function g(P,S){let $;return P?S===null||S===Ki||S===Zr?$=i.DEPTH24_STENCIL8:S===Wi?$=i.DEPTH32F_STENCIL8:S===ka&&($=i.DEPTH24_STENCIL8,Je("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):S===null||S===Ki||S===Zr?$=i.DEPTH_COMPONENT24:S===Wi?$=i.DEPTH_COMPONENT32F:S===ka&&($=i.DEPTH_COMPONENT16),$}function w(P,S){return A(P)===!0||P.isFramebufferTexture&&P.minFilter!==Dn&&P.minFilter!==Kn?Math.log2(Math.max(S.width,S.height))+1:P.mipmaps.length>0?P.mipmaps.length:P.isCompressedTexture&&Array.isArray(P.image)?S.mipmaps.length:1}function F(P){const S=new WeakRef(P);n.get(P).__ref=S,_.add(S),y.register(P,S,S)}function L(P){const S=n.get(P).__ref;S!==void 0&&(_.delete(S),y.unregister(S))}function D(P){V(P.target)}function z(P){U(P.target)}function V(P){P.removeEventListener("dispose",D),L(P),K(P),P.isVideoTexture&&h.delete(P),P.isHTMLTexture&&d.delete(P)}function U(P){P.removeEventListener("dispose",z),L(P),le(P)}function W(){for(const P of _){const S=P.deref();S!==void 0&&(S.isRenderTarget===!0?U(S):V(S))}_.clear(),d.clear()}function K(P){const S=n.get(P);if(S.__webglInit===void 0)return;const $=P.source,he=m.get($);if(he){const ae=he[S.__cacheKey];ae.usedTimes--,ae.usedTimes===0&&G(P),Object.keys(he).length===0&&m.delete($)}n.remove(P)}function G(P){const S=n.get(P);i.deleteTexture(S.__webglTexture);const $=P.source,he=m.get($);delete he[S.__cacheKey],a.memory.textures--}function le(P){const S=n.get(P);S.__depthDisposeCallback&&S.__depthDisposeCallback();const $=P.depthTexture;if($&&$.renderTarget===P&&V($),P.isWebGLCubeRenderTarget)for(let ae=0;ae<6;ae++){if(Array.isArray(S.__webglFramebuffer[ae]))for(let _e=0;_e<S.__webglFramebuffer[ae].length;_e++)i.deleteFramebuffer(S.__webglFramebuffer[ae][_e]);else i.deleteFramebuffer(S.__webglFramebuffer[ae]);S.__webglDepthbuffer&&i.deleteRenderbuffer(S.__webglDepthbuffer[ae])}else{if(Array.isArray(S.__webglFramebuffer))for(let ae=0;ae<S.__webglFramebuffer.length;ae++)i.deleteFramebuffer(S.__webglFramebuffer[ae]);else i.deleteFramebuffer(S.__webglFramebuffer);if(S.__webglDepthbuffer&&i.deleteRenderbuffer(S.__webglDepthbuffer),S.__webglMultisampledFramebuffer&&i.deleteFramebuffer(S.__webglMultisampledFramebuffer),S.__webglColorRenderbuffer)for(let ae=0;ae<S.__webglColorRenderbuffer.length;ae++)S.__webglColorRenderbuffer[ae]&&i.deleteRenderbuffer(S.__webglColorRenderbuffer[ae]);S.__webglDepthRenderbuffer&&i.deleteRenderbuffer(S.__webglDepthRenderbuffer)}const he=P.textures;for(let ae=0,_e=he.length;ae<_e;ae++){const xe=n.get(he[ae]);xe.__webglTexture&&(i.deleteTexture(xe.__webglTexture),a.memory.textures--),n.remove(he[ae])}n.remove(P)}let J=0;function Q(){J=0}function se(){return J}function de(P){J=P}function ue(){const P=J;return P>=s.maxTextures&&Je("WebGLTextures: Trying to use "+(P+1)+" texture units while this GPU supports only "+s.maxTextures),J+=1,P}function ee(P){const S=[];return S.push(P.wrapS),S.push(P.wrapT),S.push(P.wrapR||0),S.push(P.magFilter),S.push(P.minFilter),S.push(P.anisotropy),S.push(P.internalFormat),S.push(P.format),S.push(P.type),S.push(P.generateMipmaps),S.push(P.mipmapsAutoUpdate),S.push(P.premultiplyAlpha),S.push(P.flipY),S.push(P.unpackAlignment),S.push(P.colorSpace),S.join()}function me(P,S){const $=n.get(P);if(P.isVideoTexture&&Ut(P),P.isRenderTargetTexture===!1&&P.isExternalTexture!==!0&&P.version>0&&$.__version!==P.version){const he=P.image;if(he===null)Je("WebGLRenderer: Texture marked for update but no image data found.");else if(he.complete===!1)Je("WebGLRenderer: Texture marked for update but image is incomplete");else{kt($,P,S);return}}else P.isExternalTexture&&($.__webglTexture=P.sourceTexture?P.sourceTexture:null);t.bindTexture(i.TEXTURE_2D,$.__webglTexture,i.TEXTURE0+S)}function ve(P,S){const $=n.get(P);if(P.isRenderTargetTexture===!1&&P.version>0&&$.__version!==P.version){kt($,P,S);return}else P.isExternalTexture&&($.__webglTexture=P.sourceTexture?P.sourceTexture:null);t.bindTexture(i.TEXTURE_2D_ARRAY,$.__webglTexture,i.TEXTURE0+S)}function Ae(P,S){const $=n.get(P);if(P.isRenderTargetTexture===!1&&P.version>0&&$.__version!==P.version){kt($,P,S);return}t.bindTexture(i.TEXTURE_3D,$.__webglTexture,i.TEXTURE0+S)}function Me(P,S){const $=n.get(P);if(P.version>0&&$.__version!==P.version){an($,P,S);return}t.bindTexture(i.TEXTURE_CUBE_MAP,$.__webglTexture,i.TEXTURE0+S)}const Ve={[rh]:i.REPEAT,[ls]:i.CLAMP_TO_EDGE,[ah]:i.MIRRORED_REPEAT},tt={[Dn]:i.NEAREST,[Jv]:i.NEAREST_MIPMAP_NEAREST,[co]:i.NEAREST_MIPMAP_LINEAR,[Kn]:i.LINEAR,[Ql]:i.LINEAR_MIPMAP_NEAREST,[Rs]:i.LINEAR_MIPMAP_LINEAR},He={[tx]:i.NEVER,[Rm]:i.ALWAYS,[nx]:i.LESS,[Tm]:i.LEQUAL,[ix]:i.EQUAL,[Am]:i.GEQUAL,[sx]:i.GREATER,[rx]:i.NOTEQUAL};function ct(P,S){if(S.type===Wi&&e.has("OES_texture_float_linear")===!1&&(S.magFilter===Kn||S.magFilter===Ql||S.magFilter===co||S.magFilter===Rs||S.minFilter===Kn||S.minFilter===Ql||S.minFilter===co||S.minFilter===Rs)&&Je("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),i.texParameteri(P,i.TEXTURE_WRAP_S,Ve[S.wrapS]),i.texParameteri(P,i.TEXTURE_WRAP_T,Ve[S.wrapT]),(P===i.TEXTURE_3D||P===i.TEXTURE_2D_ARRAY)&&i.texParameteri(P,i.TEXTURE_WRAP_R,Ve[S.wrapR]),i.texParameteri(P,i.TEXTURE_MAG_FILTER,tt[S.magFilter]),i.texParameteri(P,i.TEXTURE_MIN_FILTER,tt[S.minFilter]),S.compareFunction&&(i.texParameteri(P,i.TEXTURE_COMPARE_MODE,i.COMPARE_REF_TO_TEXTURE),i.texParameteri(P,i.TEXTURE_COMPARE_FUNC,He[S.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(S.magFilter===Dn||S.minFilter!==co&&S.minFilter!==Rs||S.type===Wi&&e.has("OES_texture_float_linear")===!1)return;if(S.anisotropy>1||n.get(S).__currentAnisotropy){const $=e.get("EXT_texture_filter_anisotropic");i.texParameterf(P,$.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(S.anisotropy,s.getMaxAnisotropy())),n.get(S).__currentAnisotropy=S.anisotropy}}}function rt(P,S){let $=!1;P.__webglInit===void 0&&(P.__webglInit=!0,S.addEventListener("dispose",D),F(S));const he=S.source;let ae=m.get(he);ae===void 0&&(ae={},m.set(he,ae));const _e=ee(S);if(_e!==P.__cacheKey){ae[_e]===void 0&&(ae[_e]={texture:i.createTexture(),usedTimes:0},a.memory.textures++,$=!0),ae[_e].usedTimes++;const xe=ae[P.__cacheKey];xe!==void 0&&(ae[P.__cacheKey].usedTimes--,xe.usedTimes===0&&G(S)),P.__cacheKey=_e,P.__webglTexture=ae[_e].texture}return $}function Qe(P,S,$){return Math.floor(Math.floor(P/$)/S)}function Xt(P,S,$,he){const _e=P.updateRanges;if(_e.length===0)t.texSubImage2D(i.TEXTURE_2D,0,0,0,S.width,S.height,$,he,S.data);else{_e.sort((O,re)=>O.start-re.start);let xe=0;for(let O=1;O<_e.length;O++){const re=_e[xe],ne=_e[O],we=re.start+re.count,ge=Qe(ne.start,S.width,4),Se=Qe(re.start,S.width,4);ne.start<=we+1&&ge===Se&&Qe(ne.start+ne.count-1,S.width,4)===ge?re.count=Math.max(re.count,ne.start+ne.count-re.start):(++xe,_e[xe]=ne)}_e.length=xe+1;const te=t.getParameter(i.UNPACK_ROW_LENGTH),ie=t.getParameter(i.UNPACK_SKIP_PIXELS),pe=t.getParameter(i.UNPACK_SKIP_ROWS);t.pixelStorei(i.UNPACK_ROW_LENGTH,S.width);for(let O=0,re=_e.length;O<re;O++){const ne=_e[O],we=Math.floor(ne.start/4),ge=Math.ceil(ne.count/4),Se=we%S.width,Ge=Math.floor(we/S.width),Ke=ge,ce=1;t.pixelStorei(i.UNPACK_SKIP_PIXELS,Se),t.pixelStorei(i.UNPACK_SKIP_ROWS,Ge),t.texSubImage2D(i.TEXTURE_2D,0,Se,Ge,Ke,ce,$,he,S.data)}P.clearUpdateRanges(),t.pixelStorei(i.UNPACK_ROW_LENGTH,te),t.pixelStorei(i.UNPACK_SKIP_PIXELS,ie),t.pixelStorei(i.UNPACK_SKIP_ROWS,pe)}}function kt(P,S,$){let he=i.TEXTURE_2D;(S.isDataArrayTexture||S.isCompressedArrayTexture)&&(he=i.TEXTURE_2D_ARRAY),S.isData3DTexture&&(he=i.TEXTURE_3D);const ae=rt(P,S),_e=S.source;t.bindTexture(he,P.__webglTexture,i.TEXTURE0+$);const xe=n.get(_e);if(_e.version!==xe.__version||ae===!0){if(t.activeTexture(i.TEXTURE0+$),(typeof ImageBitmap<"u"&&S.image instanceof ImageBitmap)===!1){const ce=_t.getPrimaries(_t.workingColorSpace),Oe=S.colorSpace===As?null:_t.getPrimaries(S.colorSpace),Ze=S.colorSpace===As||ce===Oe?i.NONE:i.BROWSER_DEFAULT_WEBGL;t.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,S.flipY),t.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),t.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,Ze)}t.pixelStorei(i.UNPACK_ALIGNMENT,S.unpackAlignment);let ie=x(S.image,!1,s.maxTextureSize);ie=ze(S,ie);const pe=r.convert(S.format,S.colorSpace),O=r.convert(S.type);let re=b(S.internalFormat,pe,O,S.normalized,S.colorSpace,S.isVideoTexture);ct(he,S);let ne;const we=S.mipmaps,ge=S.isVideoTexture!==!0,Se=xe.__version===void 0||ae===!0,Ge=_e.dataReady,Ke=w(S,ie);if(S.isDepthTexture)re=g(S.format===Cs,S.type),Se&&(ge?t.texStorage2D(i.TEXTURE_2D,1,re,ie.width,ie.height):t.texImage2D(i.TEXTURE_2D,0,re,ie.width,ie.height,0,pe,O,null));else if(S.isDataTexture)if(we.length>0){ge&&Se&&t.texStorage2D(i.TEXTURE_2D,Ke,re,we[0].width,we[0].height);for(let ce=0,Oe=we.length;ce<Oe;ce++)ne=we[ce],ge?Ge&&t.texSubImage2D(i.TEXTURE_2D,ce,0,0,ne.width,ne.height,pe,O,ne.data):t.texImage2D(i.TEXTURE_2D,ce,re,ne.width,ne.height,0,pe,O,ne.data);S.generateMipmaps=!1}else ge?(Se&&t.texStorage2D(i.TEXTURE_2D,Ke,re,ie.width,ie.height),Ge&&Xt(S,ie,pe,O)):t.texImage2D(i.TEXTURE_2D,0,re,ie.width,ie.height,0,pe,O,ie.data);else if(S.isCompressedTexture)if(S.isCompressedArrayTexture){ge&&Se&&t.texStorage3D(i.TEXTURE_2D_ARRAY,Ke,re,we[0].width,we[0].height,ie.depth);for(let ce=0,Oe=we.length;ce<Oe;ce++)if(ne=we[ce],S.format!==Xi)if(pe!==null)if(ge){if(Ge)if(S.layerUpdates.size>0){const Ze=Tf(ne.width,ne.height,S.format,S.type);for(const Re of S.layerUpdates){const st=ne.data.subarray(Re*Ze/ne.data.BYTES_PER_ELEMENT,(Re+1)*Ze/ne.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ce,0,0,Re,ne.width,ne.height,1,pe,st)}}else t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ce,0,0,0,ne.width,ne.height,ie.depth,pe,ne.data)}else t.compressedTexImage3D(i.TEXTURE_2D_ARRAY,ce,re,ne.width,ne.height,ie.depth,0,ne.data,0,0);else Je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else ge?Ge&&t.texSubImage3D(i.TEXTURE_2D_ARRAY,ce,0,0,0,ne.width,ne.height,ie.depth,pe,O,ne.data):t.texImage3D(i.TEXTURE_2D_ARRAY,ce,re,ne.width,ne.height,ie.depth,0,pe,O,ne.data);S.layerUpdates.size>0&&S.clearLayerUpdates()}else{ge&&Se&&t.texStorage2D(i.TEXTURE_2D,Ke,re,we[0].width,we[0].height);for(let ce=0,Oe=we.length;ce<Oe;ce++)ne=we[ce],S.format!==Xi?pe!==null?ge?Ge&&t.compressedTexSubImage2D(i.TEXTURE_2D,ce,0,0,ne.width,ne.height,pe,ne.data):t.compressedTexImage2D(i.TEXTURE_2D,ce,re,ne.width,ne.height,0,ne.data):Je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):ge?Ge&&t.texSubImage2D(i.TEXTURE_2D,ce,0,0,ne.width,ne.height,pe,O,ne.data):t.texImage2D(i.TEXTURE_2D,ce,re,ne.width,ne.height,0,pe,O,ne.data)}else if(S.isDataArrayTexture)if(ge){if(Se&&t.texStorage3D(i.TEXTURE_2D_ARRAY,Ke,re,ie.width,ie.height,ie.depth),Ge)if(S.layerUpdates.size>0){const ce=Tf(ie.width,ie.height,S.format,S.type);for(const Oe of S.layerUpdates){const Ze=ie.data.subarray(Oe*ce/ie.data.BYTES_PER_ELEMENT,(Oe+1)*ce/ie.data.BYTES_PER_ELEMENT);t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,Oe,ie.width,ie.height,1,pe,O,Ze)}S.clearLayerUpdates()}else t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,0,ie.width,ie.height,ie.depth,pe,O,ie.data)}else t.texImage3D(i.TEXTURE_2D_ARRAY,0,re,ie.width,ie.height,ie.depth,0,pe,O,ie.data);else if(S.isData3DTexture)ge?(Se&&t.texStorage3D(i.TEXTURE_3D,Ke,re,ie.width,ie.height,ie.depth),Ge&&t.texSubImage3D(i.TEXTURE_3D,0,0,0,0,ie.width,ie.height,ie.depth,pe,O,ie.data)):t.texImage3D(i.TEXTURE_3D,0,re,ie.width,ie.height,ie.depth,0,pe,O,ie.data);else if(S.isFramebufferTexture){if(Se)if(ge)t.texStorage2D(i.TEXTURE_2D,Ke,re,ie.width,ie.height);else{let ce=ie.width,Oe=ie.height;for(let Ze=0;Ze<Ke;Ze++)t.texImage2D(i.TEXTURE_2D,Ze,re,ce,Oe,0,pe,O,null),ce>>=1,Oe>>=1}}else if(S.isHTMLTexture){if("texElementImage2D"in i){const ce=i.canvas;if(ce.hasAttribute("layoutsubtree")||ce.setAttribute("layoutsubtree","true"),ie.parentNode!==ce){ce.appendChild(ie),d.add(S),ce.onpaint=Oe=>{const Ze=Oe.changedElements;for(const Re of d)Ze.includes(Re.image)&&(Re.needsUpdate=!0)},ce.requestPaint();return}if(i.texElementImage2D.length===3)i.texElementImage2D(i.TEXTURE_2D,i.RGBA8,ie);else{const Ze=i.RGBA,Re=i.RGBA,st=i.UNSIGNED_BYTE;i.texElementImage2D(i.TEXTURE_2D,0,Ze,Re,st,ie)}i.texParameteri(i.TEXTURE_2D,i.TEXTURE_MIN_FILTER,i.LINEAR),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_S,i.CLAMP_TO_EDGE),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_T,i.CLAMP_TO_EDGE)}}else if(we.length>0){if(ge&&Se){const ce=$e(we[0]);t.texStorage2D(i.TEXTURE_2D,Ke,re,ce.width,ce.height)}for(let ce=0,Oe=we.length;ce<Oe;ce++)ne=we[ce],ge?Ge&&t.texSubImage2D(i.TEXTURE_2D,ce,0,0,pe,O,ne):t.texImage2D(i.TEXTURE_2D,ce,re,pe,O,ne);S.generateMipmaps=!1}else if(ge){if(Se){const ce=$e(ie);t.texStorage2D(i.TEXTURE_2D,Ke,re,ce.width,ce.height)}Ge&&t.texSubImage2D(i.TEXTURE_2D,0,0,0,pe,O,ie)}else t.texImage2D(i.TEXTURE_2D,0,re,pe,O,ie);A(S)&&S.mipmapsAutoUpdate===!0&&M(he),xe.__version=_e.version,S.onUpdate&&S.onUpdate(S)}P.__version=S.version}function an(P,S,$){if(S.image.length!==6)return;const he=rt(P,S),ae=S.source;t.bindTexture(i.TEXTURE_CUBE_MAP,P.__webglTexture,i.TEXTURE0+$);const _e=n.get(ae);if(ae.version!==_e.__version||he===!0){t.activeTexture(i.TEXTURE0+$);const xe=_t.getPrimaries(_t.workingColorSpace),te=S.colorSpace===As?null:_t.getPrimaries(S.colorSpace),ie=S.colorSpace===As||xe===te?i.NONE:i.BROWSER_DEFAULT_WEBGL;t.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,S.flipY),t.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),t.pixelStorei(i.UNPACK_ALIGNMENT,S.unpackAlignment),t.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,ie);const pe=S.isCompressedTexture||S.image[0].isCompressedTexture,O=S.image[0]&&S.image[0].isDataTexture,re=[];for(let Re=0;Re<6;Re++)!pe&&!O?re[Re]=x(S.image[Re],!0,s.maxCubemapSize):re[Re]=O?S.image[Re].image:S.image[Re],re[Re]=ze(S,re[Re]);const ne=re[0],we=r.convert(S.format,S.colorSpace),ge=r.convert(S.type);let Se=b(S.internalFormat,we,ge,S.normalized,S.colorSpace);const Ge=S.isVideoTexture!==!0,Ke=_e.__version===void 0||he===!0,ce=ae.dataReady;let Oe=w(S,ne);ct(i.TEXTURE_CUBE_MAP,S);let Ze;if(S.isDepthTexture){if(Se=g(S.format===Cs,S.type),Ke)if(Ge)t.texStorage2D(i.TEXTURE_CUBE_MAP,1,Se,ne.width,ne.height);else for(let Re=0;Re<6;Re++)t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,Se,ne.width,ne.height,0,we,ge,null)}else if(pe){Ge&&Ke&&t.texStorage2D(i.TEXTURE_CUBE_MAP,Oe,Se,ne.width,ne.height);for(let Re=0;Re<6;Re++){Ze=re[Re].mipmaps;for(let st=0;st<Ze.length;st++){const zt=Ze[st];S.format!==Xi?we!==null?Ge?ce&&t.compressedTexSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st,0,0,zt.width,zt.height,we,zt.data):t.compressedTexImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st,Se,zt.width,zt.height,0,zt.data):Je("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Ge?ce&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st,0,0,zt.width,zt.height,we,ge,zt.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st,Se,zt.width,zt.height,0,we,ge,zt.data)}}}else{if(Ze=S.mipmaps,Ge&&Ke){Ze.length>0&&Oe++;const Re=$e(re[0]);t.texStorage2D(i.TEXTURE_CUBE_MAP,Oe,Se,Re.width,Re.height)}for(let Re=0;Re<6;Re++)if(O){Ge?ce&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,0,0,re[Re].width,re[Re].height,we,ge,re[Re].data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,Se,re[Re].width,re[Re].height,0,we,ge,re[Re].data);for(let st=0;st<Ze.length;st++){const Bn=Ze[st].image[Re].image;Ge?ce&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st+1,0,0,Bn.width,Bn.height,we,ge,Bn.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st+1,Se,Bn.width,Bn.height,0,we,ge,Bn.data)}}else{Ge?ce&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,0,0,we,ge,re[Re]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,Se,we,ge,re[Re]);for(let st=0;st<Ze.length;st++){const zt=Ze[st];Ge?ce&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st+1,0,0,we,ge,zt.image[Re]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,st+1,Se,we,ge,zt.image[Re])}}}A(S)&&S.mipmapsAutoUpdate===!0&&M(i.TEXTURE_CUBE_MAP),_e.__version=ae.version,S.onUpdate&&S.onUpdate(S)}P.__version=S.version}function Nt(P,S,$,he,ae,_e){const xe=r.convert($.format,$.colorSpace),te=r.convert($.type),ie=b($.internalFormat,xe,te,$.normalized,$.colorSpace),pe=n.get(S),O=n.get($);if(O.__renderTarget=S,!pe.__hasExternalTextures){const re=Math.max(1,S.width>>_e),ne=Math.max(1,S.height>>_e);ae===i.TEXTURE_3D||ae===i.TEXTURE_2D_ARRAY?t.texImage3D(ae,_e,ie,re,ne,S.depth,0,xe,te,null):t.texImage2D(ae,_e,ie,re,ne,0,xe,te,null)}t.bindFramebuffer(i.FRAMEBUFFER,P),be(S)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,he,ae,O.__webglTexture,0,nt(S)):(ae===i.TEXTURE_2D||ae>=i.TEXTURE_CUBE_MAP_POSITIVE_X&&ae<=i.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&i.framebufferTexture2D(i.FRAMEBUFFER,he,ae,O.__webglTexture,_e),t.bindFramebuffer(i.FRAMEBUFFER,null)}function wn(P,S,$){if(i.bindRenderbuffer(i.RENDERBUFFER,P),S.depthBuffer){const he=S.depthTexture,ae=he&&he.isDepthTexture?he.type:null,_e=g(S.stencilBuffer,ae),xe=S.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;be(S)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,nt(S),_e,S.width,S.height):$?i.renderbufferStorageMultisample(i.RENDERBUFFER,nt(S),_e,S.width,S.height):i.renderbufferStorage(i.RENDERBUFFER,_e,S.width,S.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,xe,i.RENDERBUFFER,P)}else{const he=S.textures;for(let ae=0;ae<he.length;ae++){const _e=he[ae],xe=r.convert(_e.format,_e.colorSpace),te=r.convert(_e.type),ie=b(_e.internalFormat,xe,te,_e.normalized,_e.colorSpace);be(S)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,nt(S),ie,S.width,S.height):$?i.renderbufferStorageMultisample(i.RENDERBUFFER,nt(S),ie,S.width,S.height):i.renderbufferStorage(i.RENDERBUFFER,ie,S.width,S.height)}}i.bindRenderbuffer(i.RENDERBUFFER,null)}function vt(P,S,$){const he=S.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(i.FRAMEBUFFER,P),!(S.depthTexture&&S.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");const ae=n.get(S.depthTexture);ae.__renderTarget=S;const _e=he?S.depthTexture.image[0]:S.depthTexture.image;(!ae.__webglTexture||_e.width!==S.width||_e.height!==S.height)&&(_e.width=S.width,_e.height=S.height,S.depthTexture.needsUpdate=!0),he?Me(S.depthTexture,0):me(S.depthTexture,0);const xe=ae.__webglTexture,te=nt(S),ie=he?i.TEXTURE_CUBE_MAP_POSITIVE_X+$:i.TEXTURE_2D,pe=S.depthTexture.format===Cs?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;if(S.depthTexture.format===Ns)be(S)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,pe,ie,xe,0,te):i.framebufferTexture2D(i.FRAMEBUFFER,pe,ie,xe,0);else if(S.depthTexture.format===Cs)be(S)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,pe,ie,xe,0,te):i.framebufferTexture2D(i.FRAMEBUFFER,pe,ie,xe,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function pn(P){const S=n.get(P),$=P.isWebGLCubeRenderTarget===!0;if(S.__boundDepthTexture!==P.depthTexture){const he=P.depthTexture;if(S.__depthDisposeCallback&&S.__depthDisposeCallback(),he){const ae=()=>{delete S.__boundDepthTexture,delete S.__depthDisposeCallback,he.removeEventListener("dispose",ae)};he.addEventListener("dispose",ae),S.__depthDisposeCallback=ae}S.__boundDepthTexture=he}if(P.depthTexture&&!S.__autoAllocateDepthBuffer)if($)for(let he=0;he<6;he++)vt(S.__webglFramebuffer[he],P,he);else P.texture.mipmaps.length>0?vt(S.__webglFramebuffer[0],P,0):vt(S.__webglFramebuffer,P,0);else if($){S.__webglDepthbuffer=[];for(let he=0;he<6;he++)if(t.bindFramebuffer(i.FRAMEBUFFER,S.__webglFramebuffer[he]),S.__webglDepthbuffer[he]===void 0)S.__webglDepthbuffer[he]=i.createRenderbuffer(),wn(S.__webglDepthbuffer[he],P,!1);else{const ae=P.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,_e=S.__webglDepthbuffer[he];i.bindRenderbuffer(i.RENDERBUFFER,_e),i.framebufferRenderbuffer(i.FRAMEBUFFER,ae,i.RENDERBUFFER,_e)}}else if(P.texture.mipmaps.length>0?t.bindFramebuffer(i.FRAMEBUFFER,S.__webglFramebuffer[0]):t.bindFramebuffer(i.FRAMEBUFFER,S.__webglFramebuffer),S.__webglDepthbuffer===void 0)S.__webglDepthbuffer=i.createRenderbuffer(),wn(S.__webglDepthbuffer,P,!1);else{const ae=P.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,_e=S.__webglDepthbuffer;i.bindRenderbuffer(i.RENDERBUFFER,_e),i.framebufferRenderbuffer(i.FRAMEBUFFER,ae,i.RENDERBUFFER,_e)}t.bindFramebuffer(i.FRAMEBUFFER,null)}function Yt(P,S,$){const he=n.get(P);S!==void 0&&Nt(he.__webglFramebuffer,P,P.texture,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,0),$!==void 0&&pn(P)}function on(P){const S=P.texture,$=n.get(P),he=n.get(S);P.addEventListener("dispose",z),F(P);const ae=P.textures,_e=P.isWebGLCubeRenderTarget===!0,xe=ae.length>1;if(xe||(he.__webglTexture===void 0&&(he.__webglTexture=i.createTexture()),he.__version=S.version,a.memory.textures++),_e){$.__webglFramebuffer=[];for(let te=0;te<6;te++)if(S.mipmaps.length>0){$.__webglFramebuffer[te]=[];for(let ie=0;ie<S.mipmaps.length;ie++)$.__webglFramebuffer[te][ie]=i.createFramebuffer()}else $.__webglFramebuffer[te]=i.createFramebuffer()}else{if(S.mipmaps.length>0){$.__webglFramebuffer=[];for(let te=0;te<S.mipmaps.length;te++)$.__webglFramebuffer[te]=i.createFramebuffer()}else $.__webglFramebuffer=i.createFramebuffer();if(xe)for(let te=0,ie=ae.length;te<ie;te++){const pe=n.get(ae[te]);pe.__webglTexture===void 0&&(pe.__webglTexture=i.createTexture(),a.memory.textures++)}if(P.samples>0&&be(P)===!1){$.__webglMultisampledFramebuffer=i.createFramebuffer(),$.__webglColorRenderbuffer=[],t.bindFramebuffer(i.FRAMEBUFFER,$.__webglMultisampledFramebuffer);for(let te=0;te<ae.length;te++){const ie=ae[te];$.__webglColorRenderbuffer[te]=i.createRenderbuffer(),i.bindRenderbuffer(i.RENDERBUFFER,$.__webglColorRenderbuffer[te]);const pe=r.convert(ie.format,ie.colorSpace),O=r.convert(ie.type),re=b(ie.internalFormat,pe,O,ie.normalized,ie.colorSpace,P.isXRRenderTarget===!0),ne=nt(P);i.renderbufferStorageMultisample(i.RENDERBUFFER,ne,re,P.width,P.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+te,i.RENDERBUFFER,$.__webglColorRenderbuffer[te])}i.bindRenderbuffer(i.RENDERBUFFER,null),P.depthBuffer&&($.__webglDepthRenderbuffer=i.createRenderbuffer(),wn($.__webglDepthRenderbuffer,P,!0)),t.bindFramebuffer(i.FRAMEBUFFER,null)}}if(_e){t.bindTexture(i.TEXTURE_CUBE_MAP,he.__webglTexture),ct(i.TEXTURE_CUBE_MAP,S);for(let te=0;te<6;te++)if(S.mipmaps.length>0)for(let ie=0;ie<S.mipmaps.length;ie++)Nt($.__webglFramebuffer[te][ie],P,S,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+te,ie);else Nt($.__webglFramebuffer[te],P,S,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+te,0);A(S)?M(i.TEXTURE_CUBE_MAP):S.mipmaps.length>0&&i.texParameteri(i.TEXTURE_CUBE_MAP,i.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),t.unbindTexture()}else if(xe){for(let te=0,ie=ae.length;te<ie;te++){const pe=ae[te],O=n.get(pe);let re=i.TEXTURE_2D;(P.isWebGL3DRenderTarget||P.isWebGLArrayRenderTarget)&&(re=P.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),t.bindTexture(re,O.__webglTexture),ct(re,pe),Nt($.__webglFramebuffer,P,pe,i.COLOR_ATTACHMENT0+te,re,0),A(pe)&&M(re)}t.unbindTexture()}else{let te=i.TEXTURE_2D;if((P.isWebGL3DRenderTarget||P.isWebGLArrayRenderTarget)&&(te=P.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),t.bindTexture(te,he.__webglTexture),ct(te,S),S.mipmaps.length>0)for(let ie=0;ie<S.mipmaps.length;ie++)Nt($.__webglFramebuffer[ie],P,S,i.COLOR_ATTACHMENT0,te,ie);else Nt($.__webglFramebuffer,P,S,i.COLOR_ATTACHMENT0,te,0);A(S)?M(te):S.mipmaps.length>0&&i.texParameteri(te,i.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),t.unbindTexture()}P.depthBuffer&&pn(P)}function k(P){const S=P.textures;for(let $=0,he=S.length;$<he;$++){const ae=S[$];if(A(ae)&&ae.mipmapsAutoUpdate===!0){const _e=C(P),xe=n.get(ae).__webglTexture;t.bindTexture(_e,xe),M(_e),t.unbindTexture()}}}const Ce=[];function qe(P){if(P.samples>0){if(be(P)===!1){const S=P.textures,$=P.width,he=P.height;let ae=i.COLOR_BUFFER_BIT;const _e=P.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,xe=n.get(P),te=S.length>1;if(te)for(let pe=0;pe<S.length;pe++)t.bindFramebuffer(i.FRAMEBUFFER,xe.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+pe,i.RENDERBUFFER,null),t.bindFramebuffer(i.FRAMEBUFFER,xe.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+pe,i.TEXTURE_2D,null,0);t.bindFramebuffer(i.READ_FRAMEBUFFER,xe.__webglMultisampledFramebuffer),P.texture.mipmaps.length>0?t.bindFramebuffer(i.DRAW_FRAMEBUFFER,xe.__webglFramebuffer[0]):t.bindFramebuffer(i.DRAW_FRAMEBUFFER,xe.__webglFramebuffer);for(let pe=0;pe<S.length;pe++){if(P.resolveDepthBuffer&&(P.depthBuffer&&(ae|=i.DEPTH_BUFFER_BIT),P.stencilBuffer&&P.resolveStencilBuffer&&(ae|=i.STENCIL_BUFFER_BIT)),te){i.framebufferRenderbuffer(i.READ_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.RENDERBUFFER,xe.__webglColorRenderbuffer[pe]);const O=n.get(S[pe]).__webglTexture;i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,O,0)}i.blitFramebuffer(0,0,$,he,0,0,$,he,ae,i.NEAREST),l===!0&&(Ce.length=0,Ce.push(i.COLOR_ATTACHMENT0+pe),P.depthBuffer&&P.storeMultisampledDepthBuffer===!1&&Ce.push(_e),i.invalidateFramebuffer(i.READ_FRAMEBUFFER,Ce))}if(t.bindFramebuffer(i.READ_FRAMEBUFFER,null),t.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),te)for(let pe=0;pe<S.length;pe++){t.bindFramebuffer(i.FRAMEBUFFER,xe.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+pe,i.RENDERBUFFER,xe.__webglColorRenderbuffer[pe]);const O=n.get(S[pe]).__webglTexture;t.bindFramebuffer(i.FRAMEBUFFER,xe.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+pe,i.TEXTURE_2D,O,0)}t.bindFramebuffer(i.DRAW_FRAMEBUFFER,xe.__webglMultisampledFramebuffer)}else if(P.depthBuffer&&P.storeMultisampledDepthBuffer===!1&&l){const S=P.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,[S])}}}function nt(P){return Math.min(s.maxSamples,P.samples)}function be(P){const S=n.get(P);return P.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&S.__useRenderToTexture!==!1}function Ut(P){const S=a.render.frame;h.get(P)!==S&&(h.set(P,S),P.update())}function ze(P,S){const $=P.colorSpace,he=P.format,ae=P.type;return P.isCompressedTexture===!0||P.isVideoTexture===!0||$!==sl&&$!==As&&(_t.getTransfer($)===Lt?(he!==Xi||ae!==si)&&Je("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):xt("WebGLTextures: Unsupported texture color space:",$)),S}function $e(P){return typeof HTMLImageElement<"u"&&P instanceof HTMLImageElement?(c.width=P.naturalWidth||P.width,c.height=P.naturalHeight||P.height):typeof VideoFrame<"u"&&P instanceof VideoFrame?(c.width=P.displayWidth,c.height=P.displayHeight):(c.width=P.width,c.height=P.height),c}this.allocateTextureUnit=ue,this.resetTextureUnits=Q,this.getTextureUnits=se,this.setTextureUnits=de,this.setTexture2D=me,this.setTexture2DArray=ve,this.setTexture3D=Ae,this.setTextureCube=Me,this.rebindTextures=Yt,this.setupRenderTarget=on,this.updateRenderTargetMipmap=k,this.updateMultisampleRenderTarget=qe,this.setupDepthRenderbuffer=pn,this.setupFrameBufferTexture=Nt,this.useMultisampledRTT=be,this.dispose=W}function Uw(i,e){function t(n,s=As){let r;const a=_t.getTransfer(s);if(n===si)return i.UNSIGNED_BYTE;if(n===_u)return i.UNSIGNED_SHORT_4_4_4_4;if(n===vu)return i.UNSIGNED_SHORT_5_5_5_1;if(n===Sm)return i.UNSIGNED_INT_5_9_9_9_REV;if(n===Mm)return i.UNSIGNED_INT_10F_11F_11F_REV;if(n===xm)return i.BYTE;if(n===ym)return i.SHORT;if(n===ka)return i.UNSIGNED_SHORT;if(n===gu)return i.INT;if(n===Ki)return i.UNSIGNED_INT;if(n===Wi)return i.FLOAT;if(n===Zi)return i.HALF_FLOAT;if(n===bm)return i.ALPHA;if(n===wm)return i.RGB;if(n===Xi)return i.RGBA;if(n===Ns)return i.DEPTH_COMPONENT;if(n===Cs)return i.DEPTH_STENCIL;if(n===Em)return i.RED;if(n===xu)return i.RED_INTEGER;if(n===js)return i.RG;if(n===yu)return i.RG_INTEGER;if(n===Su)return i.RGBA_INTEGER;if(n===Xo||n===$o||n===qo||n===Yo)if(a===Lt)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(n===Xo)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(n===$o)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(n===qo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(n===Yo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(n===Xo)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(n===$o)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(n===qo)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(n===Yo)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(n===oh||n===lh||n===ch||n===hh)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(n===oh)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(n===lh)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(n===ch)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(n===hh)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(n===uh||n===dh||n===fh||n===ph||n===mh||n===nl||n===gh)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(n===uh||n===dh)return a===Lt?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(n===fh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(n===ph)return r.COMPRESSED_R11_EAC;if(n===mh)return r.COMPRESSED_SIGNED_R11_EAC;if(n===nl)return r.COMPRESSED_RG11_EAC;if(n===gh)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(n===_h||n===vh||n===xh||n===yh||n===Sh||n===Mh||n===bh||n===wh||n===Eh||n===Th||n===Ah||n===Rh||n===Ch||n===Ph)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(n===_h)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(n===vh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(n===xh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(n===yh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(n===Sh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(n===Mh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(n===bh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(n===wh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(n===Eh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(n===Th)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(n===Ah)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(n===Rh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(n===Ch)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(n===Ph)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(n===Lh||n===Dh||n===Nh)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(n===Lh)return a===Lt?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(n===Dh)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(n===Nh)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(n===Ih||n===Uh||n===il||n===Fh)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(n===Ih)return r.COMPRESSED_RED_RGTC1_EXT;if(n===Uh)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(n===il)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(n===Fh)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return n===Zr?i.UNSIGNED_INT_24_8:i[n]!==void 0?i[n]:null}return{convert:t}}const Fw=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,Ow=`
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

}`;class kw{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){const n=new Vm(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=n}}getMesh(e){if(this.texture!==null&&this.mesh===null){const t=e.cameras[0].viewport,n=new Qs({vertexShader:Fw,fragmentShader:Ow,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new sn(new Tl(20,20),n)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}}class Bw extends Fs{constructor(e,t){super();const n=this;let s=null,r=1,a=null,o="local-floor",l=1,c=null,h=null,d=null,u=null,m=null,_=null;const y=typeof XRWebGLBinding<"u",p=new kw,f={},x=t.getContextAttributes();let A=null,M=null;const C=[],b=[],g=new Xe;let w=null,F=null;const L=new Yn;L.viewport=new nn;const D=new Yn;D.viewport=new nn;const z=[L,D],V=new Kx;let U=null,W=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(ee){let me=C[ee];return me===void 0&&(me=new oc,C[ee]=me),me.getTargetRaySpace()},this.getControllerGrip=function(ee){let me=C[ee];return me===void 0&&(me=new oc,C[ee]=me),me.getGripSpace()},this.getHand=function(ee){let me=C[ee];return me===void 0&&(me=new oc,C[ee]=me),me.getHandSpace()};function K(ee){const me=b.indexOf(ee.inputSource);if(me===-1)return;const ve=C[me];ve!==void 0&&(ve.update(ee.inputSource,ee.frame,c||a),ve.dispatchEvent({type:ee.type,data:ee.inputSource}))}function G(){s.removeEventListener("select",K),s.removeEventListener("selectstart",K),s.removeEventListener("selectend",K),s.removeEventListener("squeeze",K),s.removeEventListener("squeezestart",K),s.removeEventListener("squeezeend",K),s.removeEventListener("end",G),s.removeEventListener("inputsourceschange",le);for(let ee=0;ee<C.length;ee++){const me=b[ee];me!==null&&(b[ee]=null,C[ee].disconnect(me))}U=null,W=null,p.reset();for(const ee in f)delete f[ee];if(e.setRenderTarget(A),m=null,u=null,d=null,s=null,M=null,ue.stop(),n.isPresenting=!1,e.setPixelRatio(w),e.setSize(g.width,g.height,!1),F!==null){const ee=F.camera;ee.fov=F.fov,ee.zoom=F.zoom,ee.updateProjectionMatrix(),F=null}n.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(ee){r=ee,n.isPresenting===!0&&Je("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(ee){o=ee,n.isPresenting===!0&&Je("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return c||a},this.setReferenceSpace=function(ee){c=ee},this.getBaseLayer=function(){return u!==null?u:m},this.getBinding=function(){return d===null&&y&&(d=new XRWebGLBinding(s,t)),d},this.getFrame=function(){return _},this.getSession=function(){return s},this.setSession=async function(ee){if(s=ee,s!==null){if(A=e.getRenderTarget(),s.addEventListener("select",K),s.addEventListener("selectstart",K),s.addEventListener("selectend",K),s.addEventListener("squeeze",K),s.addEventListener("squeezestart",K),s.addEventListener("squeezeend",K),s.addEventListener("end",G),s.addEventListener("inputsourceschange",le),x.xrCompatible!==!0&&await t.makeXRCompatible(),w=e.getPixelRatio(),e.getSize(g),y&&"createProjectionLayer"in XRWebGLBinding.prototype){let ve=null,Ae=null,Me=null;x.depth&&(Me=x.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,ve=x.stencil?Cs:Ns,Ae=x.stencil?Zr:Ki);const Ve={colorFormat:t.RGBA8,depthFormat:Me,scaleFactor:r};d=this.getBinding(),u=d.createProjectionLayer(Ve),s.updateRenderState({layers:[u]}),e.setPixelRatio(1),e.setSize(u.textureWidth,u.textureHeight,!1),M=new qi(u.textureWidth,u.textureHeight,{format:Xi,type:si,depthTexture:new Jr(u.textureWidth,u.textureHeight,Ae,void 0,void 0,void 0,void 0,void 0,void 0,ve),stencilBuffer:x.stencil,colorSpace:e.outputColorSpace,samples:x.antialias?4:0,resolveDepthBuffer:u.ignoreDepthValues===!1,resolveStencilBuffer:u.ignoreDepthValues===!1,storeMultisampledDepthBuffer:u.ignoreDepthValues===!1,storeMultisampledStencilBuffer:u.ignoreDepthValues===!1})}else{const ve={antialias:x.antialias,alpha:!0,depth:x.depth,stencil:x.stencil,framebufferScaleFactor:r};m=new XRWebGLLayer(s,t,ve),s.updateRenderState({baseLayer:m}),e.setPixelRatio(1),e.setSize(m.framebufferWidth,m.framebufferHeight,!1),M=new qi(m.framebufferWidth,m.framebufferHeight,{format:Xi,type:si,colorSpace:e.outputColorSpace,stencilBuffer:x.stencil,resolveDepthBuffer:m.ignoreDepthValues===!1,resolveStencilBuffer:m.ignoreDepthValues===!1,storeMultisampledDepthBuffer:m.ignoreDepthValues===!1,storeMultisampledStencilBuffer:m.ignoreDepthValues===!1})}M.isXRRenderTarget=!0,this.setFoveation(l),c=null,a=await s.requestReferenceSpace(o),ue.setContext(s),ue.start(),n.isPresenting=!0,n.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return p.getDepthTexture()};function le(ee){for(let me=0;me<ee.removed.length;me++){const ve=ee.removed[me],Ae=b.indexOf(ve);Ae>=0&&(b[Ae]=null,C[Ae].disconnect(ve))}for(let me=0;me<ee.added.length;me++){const ve=ee.added[me];let Ae=b.indexOf(ve);if(Ae===-1){for(let Ve=0;Ve<C.length;Ve++)if(Ve>=b.length){b.push(ve),Ae=Ve;break}else if(b[Ve]===null){b[Ve]=ve,Ae=Ve;break}if(Ae===-1)break}const Me=C[Ae];Me&&Me.connect(ve)}}function J(ee,me){me===null?ee.matrixWorld.copy(ee.matrix):ee.matrixWorld.multiplyMatrices(me.matrixWorld,ee.matrix),ee.matrixWorldInverse.copy(ee.matrixWorld).invert()}this.updateCamera=function(ee){if(s===null)return;let me=ee.near,ve=ee.far;p.texture!==null&&(p.depthNear>0&&(me=p.depthNear),p.depthFar>0&&(ve=p.depthFar)),V.near=D.near=L.near=me,V.far=D.far=L.far=ve,(U!==V.near||W!==V.far)&&(s.updateRenderState({depthNear:V.near,depthFar:V.far}),U=V.near,W=V.far),V.layers.mask=ee.layers.mask|6,L.layers.mask=V.layers.mask&-5,D.layers.mask=V.layers.mask&-3;const Ae=ee.parent,Me=V.cameras;J(V,Ae);for(let Ve=0;Ve<Me.length;Ve++)J(Me[Ve],Ae);V.projectionMatrix.copy(L.projectionMatrix),V.projectionMatrixInverse.copy(L.projectionMatrixInverse),F===null&&ee.isPerspectiveCamera&&(F={camera:ee,fov:ee.fov,zoom:ee.zoom}),Q(ee,V,Ae)};function Q(ee,me,ve){ve===null?ee.matrix.copy(me.matrixWorld):(ee.matrix.copy(ve.matrixWorld),ee.matrix.invert(),ee.matrix.multiply(me.matrixWorld)),ee.matrix.decompose(ee.position,ee.quaternion,ee.scale),ee.updateMatrixWorld(!0),ee.projectionMatrix.copy(me.projectionMatrix),ee.projectionMatrixInverse.copy(me.projectionMatrixInverse),ee.isPerspectiveCamera&&(ee.fov=kh*2*Math.atan(1/ee.projectionMatrix.elements[5]),ee.zoom=1)}this.getCamera=function(){return V},this.getFoveation=function(){if(!(u===null&&m===null))return l},this.setFoveation=function(ee){l=ee,u!==null&&(u.fixedFoveation=ee),m!==null&&m.fixedFoveation!==void 0&&(m.fixedFoveation=ee)},this.hasDepthSensing=function(){return p.texture!==null},this.getDepthSensingMesh=function(){return p.getMesh(V)},this.getCameraTexture=function(ee){return f[ee]};let se=null;function de(ee,me){if(h=me.getViewerPose(c||a),_=me,h!==null){const ve=h.views;m!==null&&(e.setRenderTargetFramebuffer(M,m.framebuffer),e.setRenderTarget(M));let Ae=!1;ve.length!==V.cameras.length&&(V.cameras.length=0,Ae=!0);for(let He=0;He<ve.length;He++){const ct=ve[He];let rt=null;if(m!==null)rt=m.getViewport(ct);else{const Xt=d.getViewSubImage(u,ct);rt=Xt.viewport,He===0&&(e.setRenderTargetTextures(M,Xt.colorTexture,Xt.depthStencilTexture),e.setRenderTarget(M))}let Qe=z[He];Qe===void 0&&(Qe=new Yn,Qe.layers.enable(He),Qe.viewport=new nn,z[He]=Qe),Qe.matrix.fromArray(ct.transform.matrix),Qe.matrix.decompose(Qe.position,Qe.quaternion,Qe.scale),Qe.projectionMatrix.fromArray(ct.projectionMatrix),Qe.projectionMatrixInverse.copy(Qe.projectionMatrix).invert(),Qe.viewport.set(rt.x,rt.y,rt.width,rt.height),He===0&&(V.matrix.copy(Qe.matrix),V.matrix.decompose(V.position,V.quaternion,V.scale)),Ae===!0&&V.cameras.push(Qe)}const Me=s.enabledFeatures;if(Me&&Me.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&y){d=n.getBinding();const He=d.getDepthInformation(ve[0]);He&&He.isValid&&He.texture&&p.init(He,s.renderState)}if(Me&&Me.includes("camera-access")&&y){e.state.unbindTexture(),d=n.getBinding();for(let He=0;He<ve.length;He++){const ct=ve[He].camera;if(ct){let rt=f[ct];rt||(rt=new Vm,f[ct]=rt);const Qe=d.getCameraImage(ct);rt.sourceTexture=Qe}}}}for(let ve=0;ve<C.length;ve++){const Ae=b[ve],Me=C[ve];Ae!==null&&Me!==void 0&&Me.update(Ae,me,c||a)}se&&se(ee,me),me.detectedPlanes&&n.dispatchEvent({type:"planesdetected",data:me}),_=null}const ue=new jm;ue.setAnimationLoop(de),this.setAnimationLoop=function(ee){se=ee},this.dispose=function(){}}}const zw=new Dt,lg=new it;lg.set(-1,0,0,0,1,0,0,0,1);function Hw(i,e){function t(p,f){p.matrixAutoUpdate===!0&&p.updateMatrix(),f.value.copy(p.matrix)}function n(p,f){f.color.getRGB(p.fogColor.value,Wm(i)),f.isFog?(p.fogNear.value=f.near,p.fogFar.value=f.far):f.isFogExp2&&(p.fogDensity.value=f.density)}function s(p,f,x,A,M){f.isNodeMaterial?f.uniformsNeedUpdate=!1:f.isMeshBasicMaterial?r(p,f):f.isMeshLambertMaterial?(r(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshToonMaterial?(r(p,f),d(p,f)):f.isMeshPhongMaterial?(r(p,f),h(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshStandardMaterial?(r(p,f),u(p,f),f.isMeshPhysicalMaterial&&m(p,f,M)):f.isMeshMatcapMaterial?(r(p,f),_(p,f)):f.isMeshDepthMaterial?r(p,f):f.isMeshDistanceMaterial?(r(p,f),y(p,f)):f.isMeshNormalMaterial?r(p,f):f.isLineBasicMaterial?(a(p,f),f.isLineDashedMaterial&&o(p,f)):f.isPointsMaterial?l(p,f,x,A):f.isSpriteMaterial?c(p,f):f.isShadowMaterial?(p.color.value.copy(f.color),p.opacity.value=f.opacity):f.isShaderMaterial&&(f.uniformsNeedUpdate=!1)}function r(p,f){p.opacity.value=f.opacity,f.color&&p.diffuse.value.copy(f.color),f.emissive&&p.emissive.value.copy(f.emissive).multiplyScalar(f.emissiveIntensity),f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.bumpMap&&(p.bumpMap.value=f.bumpMap,t(f.bumpMap,p.bumpMapTransform),p.bumpScale.value=f.bumpScale,f.side===Zn&&(p.bumpScale.value*=-1)),f.normalMap&&(p.normalMap.value=f.normalMap,t(f.normalMap,p.normalMapTransform),p.normalScale.value.copy(f.normalScale),f.side===Zn&&p.normalScale.value.negate()),f.displacementMap&&(p.displacementMap.value=f.displacementMap,t(f.displacementMap,p.displacementMapTransform),p.displacementScale.value=f.displacementScale,p.displacementBias.value=f.displacementBias),f.emissiveMap&&(p.emissiveMap.value=f.emissiveMap,t(f.emissiveMap,p.emissiveMapTransform)),f.specularMap&&(p.specularMap.value=f.specularMap,t(f.specularMap,p.specularMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest);const x=e.get(f),A=x.envMap,M=x.envMapRotation;A&&(p.envMap.value=A,p.envMapRotation.value.setFromMatrix4(zw.makeRotationFromEuler(M)).transpose(),A.isCubeTexture&&A.isRenderTargetTexture===!1&&p.envMapRotation.value.premultiply(lg),p.reflectivity.value=f.reflectivity,p.ior.value=f.ior,p.refractionRatio.value=f.refractionRatio),f.lightMap&&(p.lightMap.value=f.lightMap,p.lightMapIntensity.value=f.lightMapIntensity,t(f.lightMap,p.lightMapTransform)),f.aoMap&&(p.aoMap.value=f.aoMap,p.aoMapIntensity.value=f.aoMapIntensity,t(f.aoMap,p.aoMapTransform))}function a(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform))}function o(p,f){p.dashSize.value=f.dashSize,p.totalSize.value=f.dashSize+f.gapSize,p.scale.value=f.scale}function l(p,f,x,A){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.size.value=f.size*x,p.scale.value=A*.5,f.map&&(p.map.value=f.map,t(f.map,p.uvTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function c(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.rotation.value=f.rotation,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function h(p,f){p.specular.value.copy(f.specular),p.shininess.value=Math.max(f.shininess,1e-4)}function d(p,f){f.gradientMap&&(p.gradientMap.value=f.gradientMap)}function u(p,f){p.metalness.value=f.metalness,f.metalnessMap&&(p.metalnessMap.value=f.metalnessMap,t(f.metalnessMap,p.metalnessMapTransform)),p.roughness.value=f.roughness,f.roughnessMap&&(p.roughnessMap.value=f.roughnessMap,t(f.roughnessMap,p.roughnessMapTransform)),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)}function m(p,f,x){p.ior.value=f.ior,f.diffuseRoughness>0&&(p.diffuseRoughness.value=f.diffuseRoughness,f.diffuseRoughnessMap&&(p.diffuseRoughnessMap.value=f.diffuseRoughnessMap,t(f.diffuseRoughnessMap,p.diffuseRoughnessMapTransform))),f.sheen>0&&(p.sheenColor.value.copy(f.sheenColor).multiplyScalar(f.sheen),p.sheenRoughness.value=f.sheenRoughness,f.sheenColorMap&&(p.sheenColorMap.value=f.sheenColorMap,t(f.sheenColorMap,p.sheenColorMapTransform)),f.sheenRoughnessMap&&(p.sheenRoughnessMap.value=f.sheenRoughnessMap,t(f.sheenRoughnessMap,p.sheenRoughnessMapTransform))),f.clearcoat>0&&(p.clearcoat.value=f.clearcoat,p.clearcoatRoughness.value=f.clearcoatRoughness,f.clearcoatMap&&(p.clearcoatMap.value=f.clearcoatMap,t(f.clearcoatMap,p.clearcoatMapTransform)),f.clearcoatRoughnessMap&&(p.clearcoatRoughnessMap.value=f.clearcoatRoughnessMap,t(f.clearcoatRoughnessMap,p.clearcoatRoughnessMapTransform)),f.clearcoatNormalMap&&(p.clearcoatNormalMap.value=f.clearcoatNormalMap,t(f.clearcoatNormalMap,p.clearcoatNormalMapTransform),p.clearcoatNormalScale.value.copy(f.clearcoatNormalScale),f.side===Zn&&p.clearcoatNormalScale.value.negate())),f.dispersion>0&&(p.dispersion.value=f.dispersion),f.retroreflectivity>0&&(p.retroreflectivity.value=f.retroreflectivity),f.iridescence>0&&(p.iridescence.value=f.iridescence,p.iridescenceIOR.value=f.iridescenceIOR,p.iridescenceThicknessMinimum.value=f.iridescenceThicknessMinimum,p.iridescenceThicknessMaximum.value=f.iridescenceThicknessMaximum,f.iridescenceMap&&(p.iridescenceMap.value=f.iridescenceMap,t(f.iridescenceMap,p.iridescenceMapTransform)),f.iridescenceThicknessMap&&(p.iridescenceThicknessMap.value=f.iridescenceThicknessMap,t(f.iridescenceThicknessMap,p.iridescenceThicknessMapTransform))),f.transmission>0&&(p.transmission.value=f.transmission,p.transmissionSamplerMap.value=x.texture,p.transmissionSamplerSize.value.set(x.width,x.height),f.transmissionMap&&(p.transmissionMap.value=f.transmissionMap,t(f.transmissionMap,p.transmissionMapTransform)),p.thickness.value=f.thickness,f.thicknessMap&&(p.thicknessMap.value=f.thicknessMap,t(f.thicknessMap,p.thicknessMapTransform)),p.attenuationDistance.value=f.attenuationDistance,p.attenuationColor.value.copy(f.attenuationColor)),f.anisotropy>0&&(p.anisotropyVector.value.set(f.anisotropy*Math.cos(f.anisotropyRotation),f.anisotropy*Math.sin(f.anisotropyRotation)),f.anisotropyMap&&(p.anisotropyMap.value=f.anisotropyMap,t(f.anisotropyMap,p.anisotropyMapTransform))),p.specularIntensity.value=f.specularIntensity,p.specularColor.value.copy(f.specularColor),f.specularColorMap&&(p.specularColorMap.value=f.specularColorMap,t(f.specularColorMap,p.specularColorMapTransform)),f.specularIntensityMap&&(p.specularIntensityMap.value=f.specularIntensityMap,t(f.specularIntensityMap,p.specularIntensityMapTransform))}function _(p,f){f.matcap&&(p.matcap.value=f.matcap)}function y(p,f){const x=e.get(f).light;p.referencePosition.value.setFromMatrixPosition(x.matrixWorld),p.nearDistance.value=x.shadow.camera.near,p.farDistance.value=x.shadow.camera.far}return{refreshFogUniforms:n,refreshMaterialUniforms:s}}function Gw(i,e,t,n){let s={},r={};function a(x,A){const M=A.program;n.uniformBlockBinding(x,M,s[x.id])}function o(x,A){let M=s[x.id];M===void 0&&(_(x),M=l(x),s[x.id]=M,x.addEventListener("dispose",p));const C=A.program;n.updateUBOMapping(x,C);const b=e.render.frame;r[x.id]!==b&&(c(x),r[x.id]=b)}function l(x){const A=i.createBuffer(),M=x.__size,C=x.usage;return i.bindBuffer(i.UNIFORM_BUFFER,A),i.bufferData(i.UNIFORM_BUFFER,M,C),i.bindBuffer(i.UNIFORM_BUFFER,null),A}function c(x){const A=s[x.id],M=x.uniforms,C=x.__cache;i.bindBuffer(i.UNIFORM_BUFFER,A);for(let b=0,g=M.length;b<g;b++){const w=M[b];if(Array.isArray(w))for(let F=0,L=w.length;F<L;F++)h(w[F],b,F,C);else h(w,b,0,C)}i.bindBuffer(i.UNIFORM_BUFFER,null)}function h(x,A,M,C){if(u(x,A,M,C)===!0){const b=x.__offset,g=x.value;if(Array.isArray(g)){let w=0;for(let F=0;F<g.length;F++){const L=g[F],D=y(L,!0);d(L,x.__data,w),w+=D.storage/Float32Array.BYTES_PER_ELEMENT}}else d(g,x.__data,0);i.bufferSubData(i.UNIFORM_BUFFER,b,x.__data)}}function d(x,A,M){typeof x=="number"||typeof x=="boolean"?A[M]=x:x.isMatrix3?(A[M]=x.elements[0],A[M+1]=x.elements[1],A[M+2]=x.elements[2],A[M+3]=0,A[M+4]=x.elements[3],A[M+5]=x.elements[4],A[M+6]=x.elements[5],A[M+7]=0,A[M+8]=x.elements[6],A[M+9]=x.elements[7],A[M+10]=x.elements[8],A[M+11]=0):ArrayBuffer.isView(x)?A.set(x.subarray(0,A.length-M),M):x.toArray(A,M)}function u(x,A,M,C){const b=x.value,g=A+"_"+M;if(Array.isArray(b)){C[g]===void 0&&(C[g]=[]);const w=C[g];let F=!1;for(let L=0;L<b.length;L++)m(b[L],w,L)===!0&&(F=!0);return F}return m(b,C,g)}function m(x,A,M){if(A[M]===void 0)return typeof x=="number"||typeof x=="boolean"?A[M]=x:ArrayBuffer.isView(x)?A[M]=x.slice():A[M]=x.clone(),!0;{const C=A[M];if(typeof x=="number"||typeof x=="boolean"){if(C!==x)return A[M]=x,!0}else{if(ArrayBuffer.isView(x))return!0;if(C.equals(x)===!1)return C.copy(x),!0}}return!1}function _(x){const A=x.uniforms;let M=0;const C=16;for(let g=0,w=A.length;g<w;g++){const F=Array.isArray(A[g])?A[g]:[A[g]];for(let L=0,D=F.length;L<D;L++){const z=F[L],V=Array.isArray(z.value)?z.value:[z.value],U=Array.isArray(A[g])||Array.isArray(z.value);let W=M;for(let G=0,le=V.length;G<le;G++){const J=V[G],Q=y(J,U),se=M%C,de=se%Q.boundary,ue=se+de;M+=de,ue!==0&&C-ue<Q.storage&&(M+=C-ue),G===0&&(W=M),M+=Q.storage}const K=z.type==="int"?Int32Array:z.type==="uint"?Uint32Array:Float32Array;z.__data=new K((M-W)/Float32Array.BYTES_PER_ELEMENT),z.__offset=W}}const b=M%C;return b>0&&(M+=C-b),x.__size=M,x.__cache={},this}function y(x,A){const M={boundary:0,storage:0};return typeof x=="number"||typeof x=="boolean"?(M.boundary=4,M.storage=4):x.isVector2?(M.boundary=8,M.storage=8):x.isVector3||x.isColor?(M.boundary=16,M.storage=12):x.isVector4?(M.boundary=16,M.storage=16):x.isMatrix3?(M.boundary=16,M.storage=48):x.isMatrix4?(M.boundary=16,M.storage=64):x.isTexture?Je("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(x)?(M.boundary=16,M.storage=x.byteLength):Je("WebGLRenderer: Unsupported uniform value type.",x),A===!0&&(M.boundary=16,M.storage=Math.ceil(M.storage/16)*16),M}function p(x){const A=x.target;A.removeEventListener("dispose",p),i.deleteBuffer(s[A.id]),delete s[A.id],delete r[A.id]}function f(){for(const x in s)i.deleteBuffer(s[x]);s={},r={}}return{bind:a,update:o,dispose:f}}const Vw=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]);let zi=null;function Ww(){return zi===null&&(zi=new Ix(Vw,16,16,js,Zi),zi.name="DFG_LUT",zi.minFilter=Kn,zi.magFilter=Kn,zi.wrapS=ls,zi.wrapT=ls,zi.generateMipmaps=!1,zi.needsUpdate=!0),zi}class cg{constructor(e={}){const{canvas:t=ox(),context:n=null,depth:s=!0,stencil:r=!1,alpha:a=!1,antialias:o=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:c=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:d=!1,reversedDepthBuffer:u=!1,outputBufferType:m=si}=e;this.isWebGLRenderer=!0;let _;if(n!==null){if(typeof WebGLRenderingContext<"u"&&n instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");_=n.getContextAttributes().alpha}else _=a;const y=m,p=new Set([Su,yu,xu]),f=new Set([si,Ki,ka,Zr,_u,vu]),x=new Uint32Array(4),A=new Int32Array(4),M={textures:[],min:[],max:[],resolution:[]};let C=null,b=null;const g=[],w=[];let F=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=ds,this.toneMappingExposure=1,this.transmissionResolutionScale=1;const L=this;let D=!1,z=null,V=null,U=null,W=null;this._outputColorSpace=di;let K=0,G=0,le=null,J=-1,Q=null;const se=new nn,de=new nn;let ue=null;const ee=new lt(0);let me=0,ve=t.width,Ae=t.height,Me=1,Ve=null,tt=null;const He=new nn(0,0,ve,Ae),ct=new nn(0,0,ve,Ae);let rt=!1;const Qe=new za,Xt=new wu;let kt=!1,an=!1;const Nt=new Dt,wn=new B,vt=new nn,pn={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0};let Yt=!1;function on(){return le===null?Me:1}let k=n;function Ce(T,H){return t.getContext(T,H)}let qe,nt,be,Ut,ze,$e,P,S,$,he,ae,_e,xe,te,ie,pe,O,re,ne,we,ge,Se,Ge;try{const T={alpha:!0,depth:s,stencil:r,antialias:o,premultipliedAlpha:l,preserveDrawingBuffer:c,powerPreference:h,failIfMajorPerformanceCaveat:d};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${mu}`),t.addEventListener("webglcontextlost",Oe,!1),t.addEventListener("webglcontextrestored",Ze,!1),t.addEventListener("webglcontextcreationerror",Re,!1),k===null){const H="webgl2";if(k=Ce(H,T),k===null)throw Ce(H)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}Ke()}catch(T){throw t.removeEventListener("webglcontextlost",Oe,!1),t.removeEventListener("webglcontextrestored",Ze,!1),t.removeEventListener("webglcontextcreationerror",Re,!1),xt("WebGLRenderer: "+T.message),T}function Ke(){qe=new YM(k),qe.init(),ge=new Uw(k,qe),nt=new OM(k,qe,e,ge),be=new Nw(k,qe),nt.reversedDepthBuffer&&u&&be.buffers.depth.setReversed(!0),V=k.createFramebuffer(),U=k.createFramebuffer(),W=k.createFramebuffer(),Ut=new JM(k),ze=new xw,$e=new Iw(k,qe,be,ze,nt,ge,Ut),P=new qM(L),S=new Qx(k),Se=new UM(k,S),$=new KM(k,S,Ut,Se),he=new QM(k,$,S,Se,Ut),re=new jM(k,nt,$e),ie=new kM(ze),ae=new vw(L,P,qe,nt,Se,ie),_e=new Hw(L,ze),xe=new Sw,te=new Aw(qe),O=new IM(L,P,be,he,_,l),pe=new Dw(L,he,nt),Ge=new Gw(k,Ut,nt,be),ne=new FM(k,qe,Ut),we=new ZM(k,qe,Ut),Ut.programs=ae.programs,L.capabilities=nt,L.extensions=qe,L.properties=ze,L.renderLists=xe,L.shadowMap=pe,L.state=be,L.info=Ut}y!==si&&(F=new tb(y,t.width,t.height,o,s,r));const ce=new Bw(L,k);this.xr=ce,this.getContext=function(){return k},this.getContextAttributes=function(){return k.getContextAttributes()},this.forceContextLoss=function(){const T=qe.get("WEBGL_lose_context");T&&T.loseContext()},this.forceContextRestore=function(){const T=qe.get("WEBGL_lose_context");T&&T.restoreContext()},this.getPixelRatio=function(){return Me},this.setPixelRatio=function(T){T!==void 0&&(Me=T,this.setSize(ve,Ae,!1))},this.getSize=function(T){return T.set(ve,Ae)},this.setSize=function(T,H,j=!0){if(ce.isPresenting){Je("WebGLRenderer: Can't change size while VR device is presenting.");return}ve=T,Ae=H,t.width=Math.floor(T*Me),t.height=Math.floor(H*Me),j===!0&&(t.style.width=T+"px",t.style.height=H+"px"),F!==null&&F.setSize(t.width,t.height),this.setViewport(0,0,T,H)},this.getDrawingBufferSize=function(T){return T.set(ve*Me,Ae*Me).floor()},this.setDrawingBufferSize=function(T,H,j){ve=T,Ae=H,Me=j,t.width=Math.floor(T*j),t.height=Math.floor(H*j),this.setViewport(0,0,T,H)},this.setEffects=function(T){if(y===si){xt("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(T){for(let H=0;H<T.length;H++)if(T[H].isOutputPass===!0){Je("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}F.setEffects(T||[])},this.getCurrentViewport=function(T){return T.copy(se)},this.getViewport=function(T){return T.copy(He)},this.setViewport=function(T,H,j,q){T.isVector4?He.set(T.x,T.y,T.z,T.w):He.set(T,H,j,q),be.viewport(se.copy(He).multiplyScalar(on()).round())},this.getScissor=function(T){return T.copy(ct)},this.setScissor=function(T,H,j,q){T.isVector4?ct.set(T.x,T.y,T.z,T.w):ct.set(T,H,j,q),be.scissor(de.copy(ct).multiplyScalar(on()).round())},this.getScissorTest=function(){return rt},this.setScissorTest=function(T){be.setScissorTest(rt=T)},this.setOpaqueSort=function(T){Ve=T},this.setTransparentSort=function(T){tt=T},this.getClearColor=function(T){return T.copy(O.getClearColor())},this.setClearColor=function(){O.setClearColor(...arguments)},this.getClearAlpha=function(){return O.getClearAlpha()},this.setClearAlpha=function(){O.setClearAlpha(...arguments)},this.clear=function(T=!0,H=!0,j=!0){let q=0;if(T){let Y=!1;if(le!==null){const Ee=le.texture.format;Y=p.has(Ee)}if(Y){const Ee=le.texture.type,Pe=f.has(Ee),Te=O.getClearColor(),Le=O.getClearAlpha(),Be=Te.r,je=Te.g,ht=Te.b;Pe?(x[0]=Be,x[1]=je,x[2]=ht,x[3]=Le,k.clearBufferuiv(k.COLOR,0,x)):(A[0]=Be,A[1]=je,A[2]=ht,A[3]=Le,k.clearBufferiv(k.COLOR,0,A))}else q|=k.COLOR_BUFFER_BIT}H&&(q|=k.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),j&&(q|=k.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),q!==0&&k.clear(q)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(T){T.setRenderer(this),z=T},this.dispose=function(){t.removeEventListener("webglcontextlost",Oe,!1),t.removeEventListener("webglcontextrestored",Ze,!1),t.removeEventListener("webglcontextcreationerror",Re,!1),O.dispose(),xe.dispose(),te.dispose(),$e.dispose(),ze.dispose(),P.dispose(),he.dispose(),$.dispose(),Se.dispose(),Ge.dispose(),ae.dispose(),ce.dispose(),ce.removeEventListener("sessionstart",ja),ce.removeEventListener("sessionend",Li),ji.stop()};function Oe(T){T.preventDefault(),ol("WebGLRenderer: Context Lost."),D=!0}function Ze(){ol("WebGLRenderer: Context Restored."),D=!1;const T=Ut.autoReset,H=pe.enabled,j=pe.autoUpdate,q=pe.needsUpdate,Y=pe.type;Ke(),Ut.autoReset=T,pe.enabled=H,pe.autoUpdate=j,pe.needsUpdate=q,pe.type=Y}function Re(T){xt("WebGLRenderer: A WebGL context could not be created. Reason: ",T.statusMessage)}function st(T){const H=T.target;H.removeEventListener("dispose",st),zt(H)}function zt(T){Bn(T),ze.remove(T)}function Bn(T){const H=ze.get(T).programs;H!==void 0&&(H.forEach(function(j){ae.releaseProgram(j)}),T.isShaderMaterial&&ae.releaseShaderCache(T))}this.renderBufferDirect=function(T,H,j,q,Y,Ee){H===null&&(H=pn);const Pe=Y.isMesh&&Y.matrixWorld.determinantAffine()<0,Te=aa(T,H,j,q,Y);be.setMaterial(q,Pe);let Le=j.index,Be=1;if(q.wireframe===!0){if(Le=$.getWireframeAttribute(j),Le===void 0)return;Be=2}const je=j.drawRange,ht=j.attributes.position;let ke=je.start*Be,ut=(je.start+je.count)*Be;Ee!==null&&(ke=Math.max(ke,Ee.start*Be),ut=Math.min(ut,(Ee.start+Ee.count)*Be)),Le!==null?(ke=Math.max(ke,0),ut=Math.min(ut,Le.count)):ht!=null&&(ke=Math.max(ke,0),ut=Math.min(ut,ht.count));const qt=ut-ke;if(qt<0||qt===1/0)return;Se.setup(Y,q,Te,j,Le);let Rt,Ct=ne;if(Le!==null&&(Rt=S.get(Le),Ct=we,Ct.setIndex(Rt)),Y.isMesh)q.wireframe===!0?(be.setLineWidth(q.wireframeLinewidth*on()),Ct.setMode(k.LINES)):Ct.setMode(k.TRIANGLES);else if(Y.isLine){let mn=q.linewidth;mn===void 0&&(mn=1),be.setLineWidth(mn*on()),Y.isLineSegments?Ct.setMode(k.LINES):Y.isLineLoop?Ct.setMode(k.LINE_LOOP):Ct.setMode(k.LINE_STRIP)}else Y.isPoints?Ct.setMode(k.POINTS):Y.isSprite&&Ct.setMode(k.TRIANGLES);if(Y.isBatchedMesh)if(qe.get("WEBGL_multi_draw"))Ct.renderMultiDraw(Y._multiDrawStarts,Y._multiDrawCounts,Y._multiDrawCount);else{const mn=Y._multiDrawStarts,Ue=Y._multiDrawCounts,ln=Y._multiDrawCount,mt=Le?S.get(Le).bytesPerElement:1,es=ze.get(q).currentProgram.getUniforms();for(let cn=0;cn<ln;cn++)es.setValue(k,"_gl_DrawID",cn),Ct.render(mn[cn]/mt,Ue[cn])}else if(Y.isInstancedMesh)Ct.renderInstances(ke,qt,Y.count);else if(j.isInstancedBufferGeometry){const mn=j._maxInstanceCount!==void 0?j._maxInstanceCount:1/0,Ue=Math.min(j.instanceCount,mn);Ct.renderInstances(ke,qt,Ue)}else Ct.render(ke,qt)};function ia(T,H,j,q){z!==null&&T.isNodeMaterial&&z.setObject(q,T),kt===!0&&ie.setState(T,j,!1),T.transparent===!0&&T.side===pi&&T.forceSinglePass===!1?(T.side=Zn,T.needsUpdate=!0,Di(T,H,q),T.side=Ds,T.needsUpdate=!0,Di(T,H,q),T.side=pi):Di(T,H,q)}this.compile=function(T,H,j=null){j===null&&(j=T),z!==null&&z.renderStart(T,H,j),b=te.get(j),b.init(H),w.push(b),j.traverseVisible(function(Y){Y.isLight&&Y.layers.test(H.layers)&&(b.pushLight(Y),Y.castShadow&&b.pushShadow(Y))}),T!==j&&T.traverseVisible(function(Y){Y.isLight&&Y.layers.test(H.layers)&&(b.pushLight(Y),Y.castShadow&&b.pushShadow(Y))}),b.setupLights(),z!==null&&z.updateLights(b.state.lightsArray),an=this.localClippingEnabled,kt=ie.init(this.clippingPlanes,an),kt===!0&&ie.setGlobalState(this.clippingPlanes,H),z!==null&&pe.render(b.state.shadowsArray,j,H);const q=new Set;return T.traverse(function(Y){if(!(Y.isMesh||Y.isPoints||Y.isLine||Y.isSprite))return;const Ee=Y.material;if(Ee)if(Array.isArray(Ee))for(let Pe=0;Pe<Ee.length;Pe++){const Te=Ee[Pe];ia(Te,j,H,Y),q.add(Te)}else ia(Ee,j,H,Y),q.add(Ee)}),b=w.pop(),z!==null&&z.renderEnd(),q},this.compileAsync=function(T,H,j=null){const q=this.compile(T,H,j);return new Promise(Y=>{function Ee(){if(q.forEach(function(Pe){const Le=ze.get(Pe).currentProgram;(Le===void 0||Le.isReady())&&q.delete(Pe)}),q.size===0){Y(T);return}setTimeout(Ee,10)}qe.get("KHR_parallel_shader_compile")!==null?Ee():setTimeout(Ee,10)})};let sr=null;function Cl(T){sr&&sr(T)}function ja(){ji.stop()}function Li(){ji.start()}const ji=new jm;ji.setAnimationLoop(Cl),typeof self<"u"&&ji.setContext(self),this.setAnimationLoop=function(T){sr=T,ce.setAnimationLoop(T),T===null?ji.stop():ji.start()},ce.addEventListener("sessionstart",ja),ce.addEventListener("sessionend",Li),this.render=function(T,H){if(H!==void 0&&H.isCamera!==!0){xt("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(D===!0)return;z!==null&&z.renderStart(T,H);const j=ce.enabled===!0&&ce.isPresenting===!0,q=F!==null&&(le===null||j)&&F.begin(L,le);if(T.matrixWorldAutoUpdate===!0&&T.updateMatrixWorld(),H.parent===null&&H.matrixWorldAutoUpdate===!0&&H.updateMatrixWorld(),ce.enabled===!0&&ce.isPresenting===!0&&(F===null||F.isCompositing()===!1)&&(ce.cameraAutoUpdate===!0&&ce.updateCamera(H),H=ce.getCamera()),T.isScene===!0&&T.onBeforeRender(L,T,H,le),b=te.get(T,w.length),b.init(H),b.state.textureUnits=$e.getTextureUnits(),w.push(b),Nt.multiplyMatrices(H.projectionMatrix,H.matrixWorldInverse),H.isArrayCamera?Xt.setFromArrayCamera(H):Qe.setFromProjectionMatrix(Nt,Pi,H.reversedDepth),an=this.localClippingEnabled,kt=ie.init(this.clippingPlanes,an),C=xe.get(T,g.length),C.init(),g.push(C),this.info.render.frame++,ce.enabled===!0&&ce.isPresenting===!0){const Pe=L.xr.getDepthSensingMesh();Pe!==null&&Qi(Pe,H,-1/0,L.sortObjects)}Qi(T,H,0,L.sortObjects),C.finish(),z!==null&&z.updateLights(b.state.lightsArray),L.sortObjects===!0&&C.sort(Ve,tt),Yt=ce.enabled===!1||ce.isPresenting===!1||ce.hasDepthSensing()===!1,Yt&&O.addToRenderList(C,T),this.info.autoReset===!0&&this.info.reset(),kt===!0&&ie.beginShadows();const Y=b.state.shadowsArray;if(pe.render(Y,T,H),kt===!0&&ie.endShadows(),(q&&F.hasRenderPass())===!1){const Pe=C.opaque,Te=C.transmissive;if(b.setupLights(),H.isArrayCamera){const Le=H.cameras;if(Te.length>0)for(let Be=0,je=Le.length;Be<je;Be++){const ht=Le[Be];xi(Pe,Te,T,ht)}Yt&&O.render(T);for(let Be=0,je=Le.length;Be<je;Be++){const ht=Le[Be];sa(C,T,ht,ht.viewport)}}else Te.length>0&&xi(Pe,Te,T,H),Yt&&O.render(T),sa(C,T,H)}le!==null&&G===0&&($e.updateMultisampleRenderTarget(le),$e.updateRenderTargetMipmap(le)),q&&F.end(L),T.isScene===!0&&T.onAfterRender(L,T,H),Se.resetDefaultState(),J=-1,Q=null,w.pop(),w.length>0?(b=w[w.length-1],$e.setTextureUnits(b.state.textureUnits),kt===!0&&ie.setGlobalState(L.clippingPlanes,b.state.camera)):b=null,g.pop(),g.length>0?C=g[g.length-1]:C=null,z!==null&&z.renderEnd()};function Qi(T,H,j,q){if(T.visible===!1)return;if(T.layers.test(H.layers)){if(T.isGroup)j=T.renderOrder;else if(T.isLOD)T.autoUpdate===!0&&T.update(H);else if(T.isLight)b.pushLight(T),T.castShadow&&b.pushShadow(T);else if(T.isSprite){const Pe=H.isArrayCamera?Xt:Qe;if(!T.frustumCulled||T.intersectsFrustum(Pe)){q&&vt.setFromMatrixPosition(T.matrixWorld).applyMatrix4(Nt);const Te=he.update(T),Le=T.material;Le.visible&&C.push(T,Te,Le,j,vt.z,null,H)}}else if(T.isMesh||T.isLine||T.isPoints){const Pe=H.isArrayCamera?Xt:Qe;if(!T.frustumCulled||T.intersectsFrustum(Pe)){const Te=he.update(T),Le=T.material;if(q&&(T.boundingSphere!==void 0?(T.boundingSphere===null&&T.computeBoundingSphere(),vt.copy(T.boundingSphere.center)):(Te.boundingSphere===null&&Te.computeBoundingSphere(),vt.copy(Te.boundingSphere.center)),vt.applyMatrix4(T.matrixWorld).applyMatrix4(Nt)),Array.isArray(Le)){const Be=Te.groups;for(let je=0,ht=Be.length;je<ht;je++){const ke=Be[je],ut=Le[ke.materialIndex];ut&&ut.visible&&C.push(T,Te,ut,j,vt.z,ke,H)}}else Le.visible&&C.push(T,Te,Le,j,vt.z,null,H)}}}const Ee=T.children;for(let Pe=0,Te=Ee.length;Pe<Te;Pe++)Qi(Ee[Pe],H,j,q)}function sa(T,H,j,q){const{opaque:Y,transmissive:Ee,transparent:Pe}=T;b.setupLightsView(j),kt===!0&&ie.setGlobalState(L.clippingPlanes,j),q&&be.viewport(se.copy(q)),Y.length>0&&Kt(Y,H,j),Ee.length>0&&Kt(Ee,H,j),Pe.length>0&&Kt(Pe,H,j),be.buffers.depth.setTest(!0),be.buffers.depth.setMask(!0),be.buffers.color.setMask(!0),be.setPolygonOffset(!1)}function xi(T,H,j,q){if((j.isScene===!0?j.overrideMaterial:null)!==null)return;if(b.state.transmissionRenderTarget[q.id]===void 0){const ke=qe.has("EXT_color_buffer_half_float")||qe.has("EXT_color_buffer_float");b.state.transmissionRenderTarget[q.id]=new qi(1,1,{generateMipmaps:!0,type:ke?Zi:si,minFilter:Rs,samples:Math.max(4,nt.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:_t.workingColorSpace})}const Ee=b.state.transmissionRenderTarget[q.id],Pe=q.viewport||se;Ee.setSize(Pe.z*L.transmissionResolutionScale,Pe.w*L.transmissionResolutionScale);const Te=L.getRenderTarget(),Le=L.getActiveCubeFace(),Be=L.getActiveMipmapLevel();L.setRenderTarget(Ee),L.getClearColor(ee),me=L.getClearAlpha(),me<1&&L.setClearColor(16777215,.5),L.clear(),Yt&&O.render(j);const je=L.toneMapping;L.toneMapping=ds;const ht=q.viewport;if(q.viewport!==void 0&&(q.viewport=void 0),b.setupLightsView(q),kt===!0&&ie.setGlobalState(L.clippingPlanes,q),Kt(T,j,q),$e.updateMultisampleRenderTarget(Ee),$e.updateRenderTargetMipmap(Ee),qe.has("WEBGL_multisampled_render_to_texture")===!1){let ke=!1;for(let ut=0,qt=H.length;ut<qt;ut++){const Rt=H[ut],{object:Ct,geometry:mn,material:Ue,group:ln}=Rt;if(Ue.side===pi&&Ct.layers.test(q.layers)){const mt=Ue.side;Ue.side=Zn,Ue.needsUpdate=!0,Qt(Ct,j,q,mn,Ue,ln),Ue.side=mt,Ue.needsUpdate=!0,ke=!0}}ke===!0&&($e.updateMultisampleRenderTarget(Ee),$e.updateRenderTargetMipmap(Ee))}L.setRenderTarget(Te,Le,Be),L.setClearColor(ee,me),ht!==void 0&&(q.viewport=ht),L.toneMapping=je}function Kt(T,H,j){const q=H.isScene===!0?H.overrideMaterial:null;for(let Y=0,Ee=T.length;Y<Ee;Y++){const Pe=T[Y],{object:Te,geometry:Le,group:Be}=Pe;let je=Pe.material;je.allowOverride===!0&&q!==null&&(je=q),Te.layers.test(j.layers)&&Qt(Te,H,j,Le,je,Be)}}function Qt(T,H,j,q,Y,Ee){z!==null&&Y.isNodeMaterial&&z.setObject(T,Y),T.onBeforeRender(L,H,j,q,Y,Ee),T.modelViewMatrix.multiplyMatrices(j.matrixWorldInverse,T.matrixWorld),T.normalMatrix.getNormalMatrix(T.modelViewMatrix),Y.onBeforeRender(L,H,j,q,T,Ee),Y.transparent===!0&&Y.side===pi&&Y.forceSinglePass===!1?(Y.side=Zn,Y.needsUpdate=!0,L.renderBufferDirect(j,H,q,Y,T,Ee),Y.side=Ds,Y.needsUpdate=!0,L.renderBufferDirect(j,H,q,Y,T,Ee),Y.side=pi):L.renderBufferDirect(j,H,q,Y,T,Ee),T.onAfterRender(L,H,j,q,Y,Ee)}function en(T){let H=0;for(const j of T)j.texture!==null&&H++;return H}function Di(T,H,j){H.isScene!==!0&&(H=pn);const q=ze.get(T),Y=b.state.lights,Ee=b.state.shadowsArray,Pe=Y.state.version,Te=ae.getParameters(T,Y.state,Ee,H,j,b.state.lightProbeGridArray),Le=ae.getProgramCacheKey(Te);let Be=q.programs;q.environment=T.isMeshStandardMaterial||T.isMeshLambertMaterial||T.isMeshPhongMaterial?H.environment:null,q.fog=H.fog;const je=T.isMeshStandardMaterial||T.isMeshLambertMaterial&&!T.envMap||T.isMeshPhongMaterial&&!T.envMap;q.envMap=P.get(T.envMap||q.environment,je),q.envMapRotation=q.environment!==null&&T.envMap===null?H.environmentRotation:T.envMapRotation,Be===void 0&&(T.addEventListener("dispose",st),Be=new Map,q.programs=Be,q.programVariants=new Map);let ht=Be.get(Le);if(ht!==void 0){if(q.currentProgram===ht&&q.lightsStateVersion===Pe)return ra(T,Te),ht}else Te.uniforms=ae.getUniforms(T),z!==null&&T.isNodeMaterial&&z.build(T,j,Te),T.onBeforeCompile(Te,L),ht=ae.acquireProgram(Te,Le),Be.set(Le,ht),q.uniforms=Te.uniforms;const ke=q.uniforms;return(!T.isShaderMaterial&&!T.isRawShaderMaterial||T.clipping===!0)&&(ke.clippingPlanes=ie.uniform),ra(T,Te),q.needsLights=ms(T),q.lightsStateVersion=Pe,q.needsLights&&(ke.ambientLightColor.value=Y.state.ambient,ke.lightProbe.value=Y.state.probe,ke.sunLights.value=Y.state.sun,ke.sunLightShadows.value=Y.state.sunShadow,ke.directionalLights.value=Y.state.directional,ke.directionalLightShadows.value=Y.state.directionalShadow,ke.spotLights.value=Y.state.spot,ke.spotLightShadows.value=Y.state.spotShadow,ke.rectAreaLights.value=Y.state.rectArea,ke.ltc_1.value=Y.state.rectAreaLTC1,ke.ltc_2.value=Y.state.rectAreaLTC2,ke.pointLights.value=Y.state.point,ke.pointLightShadows.value=Y.state.pointShadow,ke.hemisphereLights.value=Y.state.hemi,ke.sunShadowMatrix.value=Y.state.sunShadowMatrix,ke.sunShadowCascade.value=Y.state.sunShadowCascade,ke.directionalShadowMatrix.value=Y.state.directionalShadowMatrix,ke.spotLightMatrix.value=Y.state.spotLightMatrix,ke.spotLightMap.value=Y.state.spotLightMap,ke.pointShadowMatrix.value=Y.state.pointShadowMatrix),q.numLightProbeGrids=en(b.state.lightProbeGridArray),q.currentProgram=ht,q.uniformsList=null,ht}function Jn(T,H,j,q,Y){const Ee=ze.get(T),Pe=Ee.currentProgram.id+","+q+","+Y;let Te=Ee.programVariants.get(Pe);return Te===void 0?(Te=Di(T,H,j),Ee.programVariants.set(Pe,Te)):(Ee.currentProgram=Te,Ee.uniformsList=null,Ee.outputColorSpace=q,Ee.toneMapping=Y),Te}function ps(T){if(T.uniformsList===null){const H=T.currentProgram.getUniforms();T.uniformsList=Zo.seqWithValue(H.seq,T.uniforms)}return T.uniformsList}function ra(T,H){const j=ze.get(T);j.outputColorSpace=H.outputColorSpace,j.batching=H.batching,j.batchingColor=H.batchingColor,j.instancing=H.instancing,j.instancingColor=H.instancingColor,j.instancingMorph=H.instancingMorph,j.skinning=H.skinning,j.morphTargets=H.morphTargets,j.morphNormals=H.morphNormals,j.morphColors=H.morphColors,j.morphTargetsCount=H.morphTargetsCount,j.numClippingPlanes=H.numClippingPlanes,j.numIntersection=H.numClipIntersection,j.vertexAlphas=H.vertexAlphas,j.vertexTangents=H.vertexTangents,j.toneMapping=H.toneMapping}function aa(T,H,j,q,Y){H.isScene!==!0&&(H=pn),$e.resetTextureUnits();const Ee=H.fog,Pe=q.isMeshStandardMaterial||q.isMeshLambertMaterial||q.isMeshPhongMaterial?H.environment:null,Te=le===null?L.outputColorSpace:le.isXRRenderTarget===!0?le.texture.colorSpace:_t.workingColorSpace,Le=q.isMeshStandardMaterial||q.isMeshLambertMaterial&&!q.envMap||q.isMeshPhongMaterial&&!q.envMap,Be=P.get(q.envMap||Pe,Le),je=q.vertexColors===!0&&!!j.attributes.color&&j.attributes.color.itemSize===4,ht=!!j.attributes.tangent&&(!!q.normalMap||q.anisotropy>0),ke=!!j.morphAttributes.position,ut=!!j.morphAttributes.normal,qt=!!j.morphAttributes.color;let Rt=ds;q.toneMapped&&(le===null||le.isXRRenderTarget===!0)&&(Rt=L.toneMapping);const Ct=j.morphAttributes.position||j.morphAttributes.normal||j.morphAttributes.color,mn=Ct!==void 0?Ct.length:0,Ue=ze.get(q),ln=b.state.lights;if(kt===!0&&(an===!0||T!==Q)){const Pt=T===Q&&q.id===J;ie.setState(q,T,Pt)}let mt=!1,es=!1;q.version===Ue.__version?Ue.needsLights&&Ue.lightsStateVersion!==ln.state.version||Y.isBatchedMesh&&Ue.batching===!1||!Y.isBatchedMesh&&Ue.batching===!0||Y.isBatchedMesh&&Ue.batchingColor===!0&&Y._colorsTexture===null||Y.isBatchedMesh&&Ue.batchingColor===!1&&Y._colorsTexture!==null||Y.isInstancedMesh&&Ue.instancing===!1||!Y.isInstancedMesh&&Ue.instancing===!0||Y.isSkinnedMesh&&Ue.skinning===!1||!Y.isSkinnedMesh&&Ue.skinning===!0||Y.isInstancedMesh&&Ue.instancingColor===!0&&Y.instanceColor===null||Y.isInstancedMesh&&Ue.instancingColor===!1&&Y.instanceColor!==null||Y.isInstancedMesh&&Ue.instancingMorph===!0&&Y.morphTexture===null||Y.isInstancedMesh&&Ue.instancingMorph===!1&&Y.morphTexture!==null||Ue.envMap!==Be||q.fog===!0&&Ue.fog!==Ee||Ue.numClippingPlanes!==void 0&&(Ue.numClippingPlanes!==ie.numPlanes||Ue.numIntersection!==ie.numIntersection)||Ue.vertexAlphas!==je||Ue.vertexTangents!==ht||Ue.morphTargets!==ke||Ue.morphNormals!==ut||Ue.morphColors!==qt||Ue.morphTargetsCount!==mn||Ue.numLightProbeGrids!==en(b.state.lightProbeGridArray)?mt=!0:(Ue.outputColorSpace!==Te||Ue.toneMapping!==Rt)&&(es=!0):(mt=!0,Ue.__version=q.version);let cn=Ue.currentProgram;(mt===!0||es===!0)&&(cn=es===!0?Jn(q,H,Y,Te,Rt):Di(q,H,Y),z&&q.isNodeMaterial&&z.onUpdateProgram(q,cn,Ue));let or=!1,Ni=!1,ts=!1;const at=cn.getUniforms(),Zt=Ue.uniforms;if(be.useProgram(cn.program)&&(or=!0,Ni=!0,ts=!0),q.id!==J&&(J=q.id,Ni=!0),or||Q!==T){be.buffers.depth.getReversed()&&T.reversedDepth!==!0&&(T._reversedDepth=!0,T.updateProjectionMatrix()),at.setValue(k,"projectionMatrix",T.projectionMatrix),at.setValue(k,"viewMatrix",T.matrixWorldInverse);const hn=at.map.cameraPosition;hn!==void 0&&hn.setValue(k,wn.setFromMatrixPosition(T.matrixWorld)),nt.logarithmicDepthBuffer&&at.setValue(k,"logDepthBufFC",2/(Math.log(T.far+1)/Math.LN2)),(q.isMeshPhongMaterial||q.isMeshToonMaterial||q.isMeshLambertMaterial||q.isMeshBasicMaterial||q.isMeshStandardMaterial||q.isShaderMaterial)&&at.setValue(k,"isOrthographic",T.isOrthographicCamera===!0),Q!==T&&(Q=T,Ni=!0,ts=!0)}if(Ue.needsLights&&(ln.state.sunShadowMap.length>0&&at.setValue(k,"sunShadowMap",ln.state.sunShadowMap,$e),ln.state.directionalShadowMap.length>0&&at.setValue(k,"directionalShadowMap",ln.state.directionalShadowMap,$e),ln.state.spotShadowMap.length>0&&at.setValue(k,"spotShadowMap",ln.state.spotShadowMap,$e),ln.state.pointShadowMap.length>0&&at.setValue(k,"pointShadowMap",ln.state.pointShadowMap,$e)),Y.isSkinnedMesh){at.setOptional(k,Y,"bindMatrix"),at.setOptional(k,Y,"bindMatrixInverse");const Pt=Y.skeleton;Pt&&(Pt.boneTexture===null&&Pt.computeBoneTexture(),at.setValue(k,"boneTexture",Pt.boneTexture,$e))}Y.isBatchedMesh&&(at.setOptional(k,Y,"batchingTexture"),at.setValue(k,"batchingTexture",Y._matricesTexture,$e),at.setOptional(k,Y,"batchingIdTexture"),at.setValue(k,"batchingIdTexture",Y._indirectTexture,$e),at.setOptional(k,Y,"batchingColorTexture"),Y._colorsTexture!==null&&at.setValue(k,"batchingColorTexture",Y._colorsTexture,$e));const zn=j.morphAttributes;if((zn.position!==void 0||zn.normal!==void 0||zn.color!==void 0)&&re.update(Y,j,cn),(Ni||Ue.receiveShadow!==Y.receiveShadow)&&(Ue.receiveShadow=Y.receiveShadow,at.setValue(k,"receiveShadow",Y.receiveShadow)),(q.isMeshStandardMaterial||q.isMeshLambertMaterial||q.isMeshPhongMaterial)&&q.envMap===null&&H.environment!==null&&(Zt.envMapIntensity.value=H.environmentIntensity),Zt.dfgLUT!==void 0&&(Zt.dfgLUT.value=Ww()),Ni){if(at.setValue(k,"toneMappingExposure",L.toneMappingExposure),Ue.needsLights&&rr(Zt,ts),Ee&&q.fog===!0&&_e.refreshFogUniforms(Zt,Ee),_e.refreshMaterialUniforms(Zt,q,Me,Ae,b.state.transmissionRenderTarget[T.id]),Ue.needsLights&&Ue.numLightProbeGrids>0){const Pt=M;let hn=0;for(const Nn of b.state.lightProbeGridArray)Nn.texture!==null&&(Pt.textures[hn]=Nn.texture,Pt.min[hn]=Nn.boundingBox.min,Pt.max[hn]=Nn.boundingBox.max,Pt.resolution[hn]=Nn.resolution,hn++);for(const Nn in Pt)Pt[Nn].length=hn;Zt.probesSH.value=Pt.textures,Zt.probesMin.value=Pt.min,Zt.probesMax.value=Pt.max,Zt.probesResolution.value=Pt.resolution}Zo.upload(k,ps(Ue),Zt,$e)}if(q.isShaderMaterial&&q.uniformsNeedUpdate===!0&&(Zo.upload(k,ps(Ue),Zt,$e),q.uniformsNeedUpdate=!1),q.isSpriteMaterial&&at.setValue(k,"center",Y.center),at.setValue(k,"modelViewMatrix",Y.modelViewMatrix),at.setValue(k,"normalMatrix",Y.normalMatrix),at.setValue(k,"modelMatrix",Y.matrixWorld),q.uniformsGroups!==void 0){const Pt=q.uniformsGroups;for(let hn=0,Nn=Pt.length;hn<Nn;hn++){const Qa=Pt[hn];Ge.update(Qa,cn),Ge.bind(Qa,cn)}}return cn}function rr(T,H){T.ambientLightColor.needsUpdate=H,T.lightProbe.needsUpdate=H,T.sunLights.needsUpdate=H,T.sunLightShadows.needsUpdate=H,T.directionalLights.needsUpdate=H,T.directionalLightShadows.needsUpdate=H,T.pointLights.needsUpdate=H,T.pointLightShadows.needsUpdate=H,T.spotLights.needsUpdate=H,T.spotLightShadows.needsUpdate=H,T.rectAreaLights.needsUpdate=H,T.hemisphereLights.needsUpdate=H}function ms(T){return T.isMeshLambertMaterial||T.isMeshToonMaterial||T.isMeshPhongMaterial||T.isMeshStandardMaterial||T.isShadowMaterial||T.isShaderMaterial&&T.lights===!0}this.getActiveCubeFace=function(){return K},this.getActiveMipmapLevel=function(){return G},this.getRenderTarget=function(){return le},this.setRenderTargetTextures=function(T,H,j){const q=ze.get(T);q.__autoAllocateDepthBuffer=T.resolveDepthBuffer===!1,q.__autoAllocateDepthBuffer===!1&&(q.__useRenderToTexture=!1),ze.get(T.texture).__webglTexture=H,ze.get(T.depthTexture).__webglTexture=q.__autoAllocateDepthBuffer?void 0:j,q.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(T,H){const j=ze.get(T);j.__webglFramebuffer=H,j.__useDefaultFramebuffer=H===void 0},this.setRenderTarget=function(T,H=0,j=0){le=T,K=H,G=j;let q=null,Y=!1,Ee=!1;if(T){const Te=ze.get(T);if(Te.__useDefaultFramebuffer!==void 0){be.bindFramebuffer(k.FRAMEBUFFER,Te.__webglFramebuffer),se.copy(T.viewport),de.copy(T.scissor),ue=T.scissorTest,be.viewport(se),be.scissor(de),be.setScissorTest(ue),J=-1;return}else if(Te.__webglFramebuffer===void 0)$e.setupRenderTarget(T);else if(Te.__hasExternalTextures)$e.rebindTextures(T,ze.get(T.texture).__webglTexture,ze.get(T.depthTexture).__webglTexture);else if(T.depthBuffer){const je=T.depthTexture;if(Te.__boundDepthTexture!==je){if(je!==null&&ze.has(je)&&(T.width!==je.image.width||T.height!==je.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");$e.setupDepthRenderbuffer(T)}}const Le=T.texture;(Le.isData3DTexture||Le.isDataArrayTexture||Le.isCompressedArrayTexture)&&(Ee=!0);const Be=ze.get(T).__webglFramebuffer;T.isWebGLCubeRenderTarget?(Array.isArray(Be[H])?q=Be[H][j]:q=Be[H],Y=!0):T.samples>0&&$e.useMultisampledRTT(T)===!1?q=ze.get(T).__webglMultisampledFramebuffer:Array.isArray(Be)?q=Be[j]:q=Be,se.copy(T.viewport),de.copy(T.scissor),ue=T.scissorTest}else se.copy(He).multiplyScalar(Me).floor(),de.copy(ct).multiplyScalar(Me).floor(),ue=rt;if(j!==0&&(q=V),be.bindFramebuffer(k.FRAMEBUFFER,q)&&be.drawBuffers(T,q),be.viewport(se),be.scissor(de),be.setScissorTest(ue),Y){const Te=ze.get(T.texture);k.framebufferTexture2D(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_CUBE_MAP_POSITIVE_X+H,Te.__webglTexture,j)}else if(Ee){const Te=H;for(let Le=0;Le<T.textures.length;Le++){const Be=ze.get(T.textures[Le]);k.framebufferTextureLayer(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0+Le,Be.__webglTexture,j,Te)}}else if(T!==null&&j!==0){const Te=ze.get(T.texture);k.framebufferTexture2D(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,Te.__webglTexture,j)}J=-1};function ar(T){const H=ze.get(T);return(H.__readFormat!==T.format||H.__readType!==T.type)&&(H.__readFormat=T.format,H.__readType=T.type,H.__formatReadable=nt.textureFormatReadable(T.format),H.__typeReadable=nt.textureTypeReadable(T.type)),H}this.readRenderTargetPixels=function(T,H,j,q,Y,Ee,Pe,Te=0){if(!(T&&T.isWebGLRenderTarget)){xt("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Le=ze.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Pe!==void 0&&(Le=Le[Pe],Array.isArray(Le)&&(Le=Le[0])),Le){be.bindFramebuffer(k.FRAMEBUFFER,Le);try{const Be=T.textures[Te],je=Be.format,ht=Be.type;T.textures.length>1&&k.readBuffer(k.COLOR_ATTACHMENT0+Te);const ke=ar(Be);if(ke.__formatReadable===!1){xt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(ke.__typeReadable===!1){xt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}H>=0&&H<=T.width-q&&j>=0&&j<=T.height-Y&&k.readPixels(H,j,q,Y,ge.convert(je),ge.convert(ht),Ee)}finally{const Be=le!==null?ze.get(le).__webglFramebuffer:null;be.bindFramebuffer(k.FRAMEBUFFER,Be)}}},this.readRenderTargetPixelsAsync=async function(T,H,j,q,Y,Ee,Pe,Te=0){if(!(T&&T.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Le=ze.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Pe!==void 0&&(Le=Le[Pe],Array.isArray(Le)&&(Le=Le[0])),Le)if(H>=0&&H<=T.width-q&&j>=0&&j<=T.height-Y){be.bindFramebuffer(k.FRAMEBUFFER,Le);const Be=T.textures[Te],je=Be.format,ht=Be.type;T.textures.length>1&&k.readBuffer(k.COLOR_ATTACHMENT0+Te);const ke=ar(Be);if(ke.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(ke.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");const ut=k.createBuffer();k.bindBuffer(k.PIXEL_PACK_BUFFER,ut),k.bufferData(k.PIXEL_PACK_BUFFER,Ee.byteLength,k.STREAM_READ),k.readPixels(H,j,q,Y,ge.convert(je),ge.convert(ht),0),k.bindBuffer(k.PIXEL_PACK_BUFFER,null);const qt=le!==null?ze.get(le).__webglFramebuffer:null;be.bindFramebuffer(k.FRAMEBUFFER,qt);const Rt=k.fenceSync(k.SYNC_GPU_COMMANDS_COMPLETE,0);return k.flush(),await lx(k,Rt,4),k.bindBuffer(k.PIXEL_PACK_BUFFER,ut),k.getBufferSubData(k.PIXEL_PACK_BUFFER,0,Ee),k.bindBuffer(k.PIXEL_PACK_BUFFER,null),k.deleteBuffer(ut),k.deleteSync(Rt),Ee}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(T,H=null,j=0){const q=Math.pow(2,-j),Y=Math.floor(T.image.width*q),Ee=Math.floor(T.image.height*q),Pe=H!==null?H.x:0,Te=H!==null?H.y:0;$e.setTexture2D(T,0),k.copyTexSubImage2D(k.TEXTURE_2D,j,0,0,Pe,Te,Y,Ee),be.unbindTexture()},this.copyTextureToTexture=function(T,H,j=null,q=null,Y=0,Ee=0){let Pe,Te,Le,Be,je,ht,ke,ut,qt;const Rt=T.isCompressedTexture?T.mipmaps[Ee]:T.image;if(j!==null)Pe=j.max.x-j.min.x,Te=j.max.y-j.min.y,Le=j.isBox3?j.max.z-j.min.z:1,Be=j.min.x,je=j.min.y,ht=j.isBox3?j.min.z:0;else{const at=Math.pow(2,-Y);Pe=Math.floor(Rt.width*at),Te=Math.floor(Rt.height*at),T.isDataArrayTexture?Le=Rt.depth:T.isData3DTexture?Le=Math.floor(Rt.depth*at):Le=1,Be=0,je=0,ht=0}q!==null?(ke=q.x,ut=q.y,qt=q.z):(ke=0,ut=0,qt=0);const Ct=ge.convert(H.format),mn=ge.convert(H.type);let Ue;H.isData3DTexture?($e.setTexture3D(H,0),Ue=k.TEXTURE_3D):H.isDataArrayTexture||H.isCompressedArrayTexture?($e.setTexture2DArray(H,0),Ue=k.TEXTURE_2D_ARRAY):($e.setTexture2D(H,0),Ue=k.TEXTURE_2D),be.activeTexture(k.TEXTURE0),be.pixelStorei(k.UNPACK_FLIP_Y_WEBGL,H.flipY),be.pixelStorei(k.UNPACK_PREMULTIPLY_ALPHA_WEBGL,H.premultiplyAlpha),be.pixelStorei(k.UNPACK_ALIGNMENT,H.unpackAlignment);const ln=be.getParameter(k.UNPACK_ROW_LENGTH),mt=be.getParameter(k.UNPACK_IMAGE_HEIGHT),es=be.getParameter(k.UNPACK_SKIP_PIXELS),cn=be.getParameter(k.UNPACK_SKIP_ROWS),or=be.getParameter(k.UNPACK_SKIP_IMAGES);be.pixelStorei(k.UNPACK_ROW_LENGTH,Rt.width),be.pixelStorei(k.UNPACK_IMAGE_HEIGHT,Rt.height),be.pixelStorei(k.UNPACK_SKIP_PIXELS,Be),be.pixelStorei(k.UNPACK_SKIP_ROWS,je),be.pixelStorei(k.UNPACK_SKIP_IMAGES,ht);const Ni=T.isDataArrayTexture||T.isData3DTexture,ts=H.isDataArrayTexture||H.isData3DTexture;if(T.isDepthTexture){const at=ze.get(T),Zt=ze.get(H),zn=ze.get(at.__renderTarget),Pt=ze.get(Zt.__renderTarget);be.bindFramebuffer(k.READ_FRAMEBUFFER,zn.__webglFramebuffer),be.bindFramebuffer(k.DRAW_FRAMEBUFFER,Pt.__webglFramebuffer);for(let hn=0;hn<Le;hn++)Ni&&(k.framebufferTextureLayer(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,ze.get(T).__webglTexture,Y,ht+hn),k.framebufferTextureLayer(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,ze.get(H).__webglTexture,Ee,qt+hn)),k.blitFramebuffer(Be,je,Be+Pe,je+Te,ke,ut,ke+Pe,ut+Te,k.DEPTH_BUFFER_BIT,k.NEAREST);be.bindFramebuffer(k.READ_FRAMEBUFFER,null),be.bindFramebuffer(k.DRAW_FRAMEBUFFER,null)}else if(Y!==0||T.isRenderTargetTexture||ze.has(T)){const at=ze.get(T),Zt=ze.get(H);be.bindFramebuffer(k.READ_FRAMEBUFFER,U),be.bindFramebuffer(k.DRAW_FRAMEBUFFER,W);for(let zn=0;zn<Le;zn++)Ni?k.framebufferTextureLayer(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,at.__webglTexture,Y,ht+zn):k.framebufferTexture2D(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,at.__webglTexture,Y),ts?k.framebufferTextureLayer(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,Zt.__webglTexture,Ee,qt+zn):k.framebufferTexture2D(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,Zt.__webglTexture,Ee),Y!==0?k.blitFramebuffer(Be,je,Be+Pe,je+Te,ke,ut,ke+Pe,ut+Te,k.COLOR_BUFFER_BIT,k.NEAREST):ts?k.copyTexSubImage3D(Ue,Ee,ke,ut,qt+zn,Be,je,Pe,Te):k.copyTexSubImage2D(Ue,Ee,ke,ut,Be,je,Pe,Te);be.bindFramebuffer(k.READ_FRAMEBUFFER,null),be.bindFramebuffer(k.DRAW_FRAMEBUFFER,null)}else ts?T.isDataTexture||T.isData3DTexture?k.texSubImage3D(Ue,Ee,ke,ut,qt,Pe,Te,Le,Ct,mn,Rt.data):H.isCompressedArrayTexture?k.compressedTexSubImage3D(Ue,Ee,ke,ut,qt,Pe,Te,Le,Ct,Rt.data):k.texSubImage3D(Ue,Ee,ke,ut,qt,Pe,Te,Le,Ct,mn,Rt):T.isDataTexture?k.texSubImage2D(k.TEXTURE_2D,Ee,ke,ut,Pe,Te,Ct,mn,Rt.data):T.isCompressedTexture?k.compressedTexSubImage2D(k.TEXTURE_2D,Ee,ke,ut,Rt.width,Rt.height,Ct,Rt.data):k.texSubImage2D(k.TEXTURE_2D,Ee,ke,ut,Pe,Te,Ct,mn,Rt);be.pixelStorei(k.UNPACK_ROW_LENGTH,ln),be.pixelStorei(k.UNPACK_IMAGE_HEIGHT,mt),be.pixelStorei(k.UNPACK_SKIP_PIXELS,es),be.pixelStorei(k.UNPACK_SKIP_ROWS,cn),be.pixelStorei(k.UNPACK_SKIP_IMAGES,or),Ee===0&&H.generateMipmaps===!0&&H.mipmapsAutoUpdate===!0&&k.generateMipmap(Ue),be.unbindTexture()},this.initRenderTarget=function(T){ze.get(T).__webglFramebuffer===void 0&&$e.setupRenderTarget(T)},this.initTexture=function(T){T.isCubeTexture?$e.setTextureCube(T,0):T.isData3DTexture?$e.setTexture3D(T,0):T.isDataArrayTexture||T.isCompressedArrayTexture?$e.setTexture2DArray(T,0):$e.setTexture2D(T,0),be.unbindTexture()},this.resetState=function(){K=0,G=0,le=null,be.reset(),Se.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Pi}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;const t=this.getContext();t.drawingBufferColorSpace=_t._getDrawingBufferColorSpace(e),t.unpackColorSpace=_t._getUnpackColorSpace()}}const Yf={type:"change"},Au={type:"start"},hg={type:"end"},ko=new wl,Kf=new Ri,Xw=Math.cos(70*dx.DEG2RAD),_n=new B,qn=2*Math.PI,Et={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},Rc=1e-6;class ug extends Jx{constructor(e,t=null){super(e,t),this.state=Et.NONE,this.target=new B,this.cursor=new B,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:Br.ROTATE,MIDDLE:Br.DOLLY,RIGHT:Br.PAN},this.touches={ONE:Fr.ROTATE,TWO:Fr.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new B,this._lastQuaternion=new Is,this._lastTargetPosition=new B,this._quat=new Is().setFromUnitVectors(e.up,new B(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new Hh,this._sphericalDelta=new Hh,this._scale=1,this._panOffset=new B,this._rotateStart=new Xe,this._rotateEnd=new Xe,this._rotateDelta=new Xe,this._panStart=new Xe,this._panEnd=new Xe,this._panDelta=new Xe,this._dollyStart=new Xe,this._dollyEnd=new Xe,this._dollyDelta=new Xe,this._dollyDirection=new B,this._mouse=new Xe,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=qw.bind(this),this._onPointerDown=$w.bind(this),this._onPointerUp=Yw.bind(this),this._onContextMenu=tE.bind(this),this._onMouseWheel=Jw.bind(this),this._onKeyDown=jw.bind(this),this._onTouchStart=Qw.bind(this),this._onTouchMove=eE.bind(this),this._onMouseDown=Kw.bind(this),this._onMouseMove=Zw.bind(this),this._interceptControlDown=nE.bind(this),this._interceptControlUp=iE.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Et.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(Yf),this.update(),this.state=Et.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){const t=this.object.position;_n.copy(t).sub(this.target),_n.applyQuaternion(this._quat),this._spherical.setFromVector3(_n),this.autoRotate&&this.state===Et.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let n=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(n)&&isFinite(s)&&(n<-Math.PI?n+=qn:n>Math.PI&&(n-=qn),s<-Math.PI?s+=qn:s>Math.PI&&(s-=qn),n<=s?this._spherical.theta=Math.max(n,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(n+s)/2?Math.max(n,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{const a=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=a!=this._spherical.radius}if(_n.setFromSpherical(this._spherical),_n.applyQuaternion(this._quatInverse),t.copy(this.target).add(_n),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let a=null;if(this.object.isPerspectiveCamera){const o=_n.length();a=this._clampDistance(o*this._scale);const l=o-a;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),r=!!l}else if(this.object.isOrthographicCamera){const o=new B(this._mouse.x,this._mouse.y,0);o.unproject(this.object);const l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=l!==this.object.zoom;const c=new B(this._mouse.x,this._mouse.y,0);c.unproject(this.object),this.object.position.sub(c).add(o),this.object.updateMatrixWorld(),a=_n.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;a!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(a).add(this.object.position):(ko.origin.copy(this.object.position),ko.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(ko.direction))<Xw?this.object.lookAt(this.target):(Kf.setFromNormalAndCoplanarPoint(this.object.up,this.target),ko.intersectPlane(Kf,this.target))))}else if(this.object.isOrthographicCamera){const a=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),a!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>Rc||8*(1-this._lastQuaternion.dot(this.object.quaternion))>Rc||this._lastTargetPosition.distanceToSquared(this.target)>Rc?(this.dispatchEvent(Yf),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?qn/60*this.autoRotateSpeed*e:qn/60/60*this.autoRotateSpeed}_getZoomScale(e){const t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){_n.setFromMatrixColumn(t,0),_n.multiplyScalar(-e),this._panOffset.add(_n)}_panUp(e,t){this.screenSpacePanning===!0?_n.setFromMatrixColumn(t,1):(_n.setFromMatrixColumn(t,0),_n.crossVectors(this.object.up,_n)),_n.multiplyScalar(e),this._panOffset.add(_n)}_pan(e,t){const n=this.domElement;if(this.object.isPerspectiveCamera){const s=this.object.position;_n.copy(s).sub(this.target);let r=_n.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/n.clientHeight,this.object.matrix),this._panUp(2*t*r/n.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/n.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/n.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;const n=this.domElement.getBoundingClientRect(),s=e-n.left,r=t-n.top,a=n.width,o=n.height;this._mouse.x=s/a*2-1,this._mouse.y=-(r/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(qn*this._rotateDelta.x/t.clientHeight),this._rotateUp(qn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(qn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-qn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(qn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-qn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._rotateStart.set(n,s)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panStart.set(n,s)}}_handleTouchStartDolly(e){const t=this._getSecondPointerPosition(e),n=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(n*n+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{const n=this._getSecondPointerPosition(e),s=.5*(e.pageX+n.x),r=.5*(e.pageY+n.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(qn*this._rotateDelta.x/t.clientHeight),this._rotateUp(qn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panEnd.set(n,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){const t=this._getSecondPointerPosition(e),n=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(n*n+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);const a=(e.pageX+t.x)*.5,o=(e.pageY+t.y)*.5;this._updateZoomParameters(a,o)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new Xe,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){const t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){const t=e.deltaMode,n={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:n.deltaY*=16;break;case 2:n.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(n.deltaY*=10),n}}function $w(i){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(i.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(i)&&(this._addPointer(i),i.pointerType==="touch"?this._onTouchStart(i):this._onMouseDown(i),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function qw(i){this.enabled!==!1&&(i.pointerType==="touch"?this._onTouchMove(i):this._onMouseMove(i))}function Yw(i){switch(this._removePointer(i),this._pointers.length){case 0:this.domElement.releasePointerCapture(i.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(hg),this.state=Et.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:const e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function Kw(i){let e;switch(i.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case Br.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(i),this.state=Et.DOLLY;break;case Br.ROTATE:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Et.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Et.ROTATE}break;case Br.PAN:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Et.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Et.PAN}break;default:this.state=Et.NONE}this.state!==Et.NONE&&this.dispatchEvent(Au)}function Zw(i){switch(this.state){case Et.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(i);break;case Et.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(i);break;case Et.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(i);break}}function Jw(i){this.enabled===!1||this.enableZoom===!1||this.state!==Et.NONE||(i.preventDefault(),this.dispatchEvent(Au),this._handleMouseWheel(this._customWheelEvent(i)),this.dispatchEvent(hg))}function jw(i){this.enabled!==!1&&this._handleKeyDown(i)}function Qw(i){switch(this._trackPointer(i),this._pointers.length){case 1:switch(this.touches.ONE){case Fr.ROTATE:if(this.enableRotate===!1){this.state=Et.NONE;break}this._handleTouchStartRotate(i),this.state=Et.TOUCH_ROTATE;break;case Fr.PAN:if(this.enablePan===!1){this.state=Et.NONE;break}this._handleTouchStartPan(i),this.state=Et.TOUCH_PAN;break;default:this.state=Et.NONE}break;case 2:switch(this.touches.TWO){case Fr.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(i),this.state=Et.TOUCH_DOLLY_PAN;break;case Fr.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(i),this.state=Et.TOUCH_DOLLY_ROTATE;break;default:this.state=Et.NONE}break;default:this.state=Et.NONE}this.state!==Et.NONE&&this.dispatchEvent(Au)}function eE(i){switch(this._trackPointer(i),this.state){case Et.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(i),this.update();break;case Et.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(i),this.update();break;case Et.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(i),this.update();break;case Et.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(i),this.update();break;default:this.state=Et.NONE}}function tE(i){this.enabled!==!1&&i.preventDefault()}function nE(i){i.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function iE(i){i.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function sE(i,e){const t=e*e;return[i.x[2]/e,i.v[2]/e,(i.v[0]**2+i.v[1]**2+i.v[2]**2)/t]}function rE(i){const e=Math.max(...i.surface.sigma2.map(Math.abs),1e-9),t=Math.max(...i.orbit.sigma3,i.point[2],1e-9);return{s2:e,s3top:1.6*t+1e-9}}class Ru{constructor(e,t){this.container=e;const n=document.createElement("div");n.className="curve-title",n.textContent=R("data.reduced"),e.appendChild(n),this.renderer=new cg({antialias:t.antialias,preserveDrawingBuffer:!0}),this.renderer.localClippingEnabled=!0,this.renderer.setPixelRatio(t.pixelRatio),this.renderer.domElement.className="reduced-canvas",e.appendChild(this.renderer.domElement),this.note=document.createElement("p"),this.note.className="note",e.appendChild(this.note),this.scene.background=new lt(1448482),this.camera.up.set(0,0,1),this.camera.position.set(3.2,-3.6,2.2),this.controls=new ug(this.camera,this.renderer.domElement),this.point=new sn(new cs(.05,16,12),new Ps({color:16747586,depthTest:!1,transparent:!0})),this.point.renderOrder=3,this.point.visible=!1,this.scene.add(this.group,this.point,new Jm(1.2)),this.resize(),new ResizeObserver(()=>this.resize()).observe(e),new IntersectionObserver(s=>{this.visible=s.some(r=>r.isIntersecting)}).observe(this.renderer.domElement),this.controls.addEventListener("change",()=>{this.dirty=!0})}container;renderer;camera=new Yn(35,1,.01,100);controls;scene=new Um;group=new $i;point;scales=null;note;visible=!1;lastDrawn=-1/0;dirty=!0;resize(){const e=Math.max(200,this.container.clientWidth-8),t=220;this.renderer.setSize(e,t,!1),this.renderer.domElement.style.width=`${e}px`,this.renderer.domElement.style.height=`${t}px`,this.camera.aspect=e/t,this.camera.updateProjectionMatrix()}setNote(e){this.note.textContent=e??"",e!==null&&this.set(null)}set(e){for(const b of[...this.group.children]){this.group.remove(b);const g=b;g.geometry?.dispose(),g.material?.dispose()}if(this.scales=e===null?null:rE(e),this.dirty=!0,e===null||this.scales===null)return;const{s2:t,s3top:n}=this.scales,s=(b,g,w)=>new B(b,g/t,2*w/n-1),r=[new Ri(new B(0,0,-1),1)],{sigma1:a,sigma2:o,sigma3:l}=e.surface,c=[];a.forEach((b,g)=>o.forEach((w,F)=>c.push(...s(b,w,l[g]?.[F]??NaN).toArray())));const h=[],d=o.length;for(let b=0;b+1<a.length;b++)for(let g=0;g+1<d;g++){const w=b*d+g;h.push(w,w+d,w+1,w+1,w+d,w+d+1)}const u=new Bt;u.setAttribute("position",new rn(c,3)),u.setIndex(h);const m={color:9417727,transparent:!0,opacity:.25,side:pi,clippingPlanes:r};this.group.add(new sn(u,new Ps({...m,depthWrite:!1}))),this.group.add(new sn(u.clone(),new Ps({...m,wireframe:!0,opacity:.25})));const{h:_,gamma:y}=e.plane,p=(b,g)=>s(b,g,2*(_-y*b)),f=new Bt().setFromPoints([p(-1,-t),p(1,-t),p(1,t),p(-1,t)]);f.setIndex([0,1,2,0,2,3]);const x=new Ps({color:16757575,transparent:!0,opacity:.22,side:pi,depthWrite:!1,clippingPlanes:[...r,new Ri(new B(0,0,1),1)]});this.group.add(new sn(f,x));const A=e.orbit,M=new Bt().setFromPoints(A.sigma1.map((b,g)=>s(b,A.sigma2[g]??NaN,A.sigma3[g]??NaN))),C=new Ji(M,new vi({color:5882879,depthTest:!1,transparent:!0}));C.renderOrder=2,this.group.add(C),this.point.visible=!0}update(e,t){if(this.scales!==null&&e!==null){const[s,r,a]=sE(e,t);this.point.position.set(s,r/this.scales.s2,2*a/this.scales.s3top-1)}this.point.visible=this.scales!==null&&e!==null;const n=performance.now();!this.visible||!this.dirty&&n-this.lastDrawn<Ru.MIN_INTERVAL||(this.lastDrawn=n,this.dirty=!1,this.controls.update(),this.renderer.render(this.scene,this.camera))}static MIN_INTERVAL=250}class aE{constructor(e){const t=new Km;t.aspect=.5;const n=new Xe;this.setEyeSeparation=function(s){t.eyeSep=s},this.setSize=function(s,r){e.setSize(s,r)},this.render=function(s,r){s.matrixWorldAutoUpdate===!0&&s.updateMatrixWorld(),r.parent===null&&r.matrixWorldAutoUpdate===!0&&r.updateMatrixWorld(),t.update(r);const a=e.autoClear;e.getSize(n),e.autoClear=!1,e.clear(),e.setScissorTest(!0),e.setScissor(0,0,n.width/2,n.height),e.setViewport(0,0,n.width/2,n.height),e.render(s,t.cameraL),e.setScissor(n.width/2,0,n.width/2,n.height),e.setViewport(n.width/2,0,n.width/2,n.height),e.render(s,t.cameraR),e.setScissorTest(!1),e.autoClear=a}}}const Bo=(i,e)=>i[0]*e[0]+i[1]*e[1]+i[2]*e[2],Cc=(i,e)=>[i[0]+e[0],i[1]+e[1],i[2]+e[2]],Pc=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]],Gi=(i,e)=>[i[0]*e,i[1]*e,i[2]*e];function oE(i,e){return 4*Math.sqrt(Math.max(Math.abs(e),1)*Math.max(i,0))}function lE(i,e,t,n,s){const r=Math.hypot(...t),a=Math.hypot(...i.direction);if(!(r>0)||!(a>0)||!(n>0)||!Number.isFinite(r)||!Number.isFinite(a)||![...e,...i.origin].every(Number.isFinite))return null;const o=Gi(t,1/r),l=Gi(i.direction,1/a),c=Cc(e,t),h=Pc(c,i.origin),d=Bo(o,l),u=Math.abs(d)>1e-9?Bo(o,h)/d:-1,m=u>0?Cc(i.origin,Gi(l,u)):Cc(i.origin,Gi(l,Math.max(Bo(h,l),0)));let _=Pc(m,c);_=Pc(_,Gi(o,Bo(_,o)));let y=Gi(_,1/n);const p=Math.hypot(...y);if(!Number.isFinite(p))return null;const f=Math.max(s,0);return p>f?(y=p>0?Gi(y,f/p):[0,0,0],{v:y,speed:f,capped:!0}):{v:y,speed:p,capped:!1}}function cE(i,e,t,n){const s=Gi(e,t),r=Math.hypot(...s);if(r>=n)return s;if(r>1e-12*n)return Gi(s,n/r);const a=[-i[1],i[0],0],o=Math.hypot(...a);return o>1e-12*Math.hypot(...i)&&o>0?Gi(a,n/o):[n,0,0]}function hE(i,e,t){const n=i.intersectSphere(new Ya(e,t),new B);if(n!==null)return n.sub(e);const s=i.closestPointToPoint(e,new B).sub(e),r=s.length();return r>0?s.multiplyScalar(t/r):new B(0,0,-t)}class uE{constructor(e,t,n,s,r,a){this.canvas=e,this.camera=t,this.controls=n,this.bob=s,this.onDrag=r,this.sphere=a,e.addEventListener("pointerdown",o=>this.down(o),{capture:!0}),e.addEventListener("pointermove",o=>this.move(o)),e.addEventListener("pointerup",o=>this.up(o)),e.addEventListener("pointercancel",o=>this.up(o))}canvas;camera;controls;bob;onDrag;sphere;dragging=!1;raycaster=new Zm;get active(){return this.dragging}ray(e){const t=this.canvas.getBoundingClientRect(),n=new Xe((e.clientX-t.left)/t.width*2-1,-((e.clientY-t.top)/t.height)*2+1);return this.raycaster.setFromCamera(n,this.camera),this.raycaster.ray}position(e){const{pivot:t,length:n}=this.sphere(),s=hE(this.ray(e),t,n);return[s.x,s.y,s.z]}down(e){e.button!==0||!this.bob.visible||(this.ray(e),this.raycaster.intersectObject(this.bob,!1).length!==0&&(this.dragging=!0,this.controls.enabled=!1,this.canvas.setPointerCapture?.(e.pointerId),e.stopImmediatePropagation(),this.onDrag(this.position(e),"start")))}move(e){this.dragging&&this.onDrag(this.position(e),"move")}up(e){this.dragging&&(this.dragging=!1,this.controls.enabled=!0,this.onDrag(this.position(e),"end"))}}class dE{constructor(e,t,n,s,r,a,o,l){this.canvas=e,this.camera=t,this.controls=n,this.handle=s,this.occluder=r,this.grabRadius=a,this.pullBasis=o,this.onPull=l,e.addEventListener("pointerdown",c=>this.down(c),{capture:!0}),e.addEventListener("pointermove",c=>this.move(c)),e.addEventListener("pointerup",c=>this.up(c)),e.addEventListener("pointercancel",c=>this.up(c))}canvas;camera;controls;handle;occluder;grabRadius;pullBasis;onPull;basis=null;moved=!1;raycaster=new Zm;tmp=new B;get active(){return this.basis!==null}ray(e){const t=this.canvas.getBoundingClientRect(),n=new Xe((e.clientX-t.left)/t.width*2-1,-((e.clientY-t.top)/t.height)*2+1);return this.raycaster.setFromCamera(n,this.camera),this.raycaster.ray}pulled(e){if(this.basis===null)return null;const t=this.ray(e),{pivot:n,x:s,arrowScale:r,vmax:a}=this.basis;return lE({origin:[t.origin.x,t.origin.y,t.origin.z],direction:[t.direction.x,t.direction.y,t.direction.z]},n,s,r,a)}down(e){if(e.button!==0||!this.handle.visible)return;const t=this.ray(e),n=this.handle.getWorldPosition(this.tmp),s=this.grabRadius();if(t.distanceToPoint(n)>s)return;const r=this.raycaster.intersectObject(this.occluder,!1)[0];if(r!==void 0&&r.distance<n.sub(t.origin).dot(t.direction)-s)return;const a=this.pullBasis();a!==null&&(this.basis=a,this.moved=!1,this.controls.enabled=!1,this.canvas.setPointerCapture?.(e.pointerId),e.stopImmediatePropagation(),this.onPull(a.x,null,"start"))}move(e){this.basis!==null&&(this.moved=!0,this.onPull(this.basis.x,this.pulled(e),"move"))}up(e){if(this.basis===null)return;const t=this.moved?this.pulled(e):null,n=this.basis.x;this.basis=null,this.controls.enabled=!0,this.onPull(n,t,"end")}}const Zf=(i,e)=>[i[1]*e[2]-i[2]*e[1],i[2]*e[0]-i[0]*e[2],i[0]*e[1]-i[1]*e[0]],Aa=(i,e)=>[i[0]*e,i[1]*e,i[2]*e],fE=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]];function pE(i){const e=[i?.gravity_x??0,i?.gravity_y??0,i?.gravity_z??-1],t=Math.hypot(...e);return t>0?Aa(e,1/t):[0,0,-1]}function mE(i,e,t,n,s){const r=Math.hypot(...i.x),a=Aa(i.v,e),o=Aa(i.a,e),l=fE(i.x,s);return{velocity:i.v,momentum:a,gravity:Aa(n,e*t),tension:r>0?Aa(i.x,-i.tension/r):[0,0,0],net:o,angularMomentum:Zf(l,a),torque:Zf(l,o)}}function Vh(i,e,t){const n=Math.max(Math.abs(t),1),s=.5*i/(e*n),r=Math.sqrt(n/i);return{velocity:.25,momentum:.25,gravity:s,tension:s,net:s,angularMomentum:.5*i/(e*i*i*r),torque:s/i}}const dg=15127459;function gE(i){const e=i/20,t=10**Math.floor(Math.log10(e)),n=e/t;return(n<1.5?1:n<3.5?2:5)*t}class Lc{sprite;canvas=document.createElement("canvas");texture;text="";constructor(e,t){this.canvas.width=256,this.canvas.height=64,this.texture=new Ox(this.canvas),this.sprite=new zm(new km({map:this.texture,depthTest:!1,transparent:!0})),this.sprite.scale.set(4*t,t,1),this.set(e)}set(e){if(e===this.text)return;this.text=e;const t=this.canvas.getContext("2d");t!==null&&(t.clearRect(0,0,256,64),t.font="bold 44px system-ui, sans-serif",t.fillStyle=`#${dg.toString(16)}`,t.textAlign="center",t.textBaseline="middle",t.fillText(e,128,32),this.texture.needsUpdate=!0)}}function Jf(i){const e=new Bt().setFromPoints(i);return new El(e,new vi({color:dg}))}class _E{ruler=new $i;protractor=new $i;dial=new $i;thetaLabel=new Lc("",.1);built=-1;pivot=new B;moved={ruler:[0,0],protractor:[0,0]};constructor(){this.ruler.visible=!1,this.protractor.visible=!1,this.protractor.add(this.dial,this.thetaLabel.sprite)}build(e){if(e===this.built)return;this.built=e;for(const l of[this.ruler,this.dial])for(const c of[...l.children])l.remove(c),(c instanceof sn||c instanceof El||c instanceof zm)&&(c.geometry.dispose(),c.material.dispose());const t=gE(2*e),n=1.1*e,s=[new B(n,0,-e),new B(n,0,e)],r=Math.floor(e/t+1e-9);for(let l=-r;l<=r;l++){const c=l*t,h=l%5===0;if(s.push(new B(n,0,c),new B(n-(h?.08:.04)*e,0,c)),h){const d=new Lc(`${+c.toPrecision(6)} m`,.07*e);d.sprite.position.set(n+.16*e,0,c),this.ruler.add(d.sprite)}}this.ruler.add(Jf(s));const a=.4*e,o=[];for(let l=0;l<360;l+=2){const c=l*Math.PI/180,h=(l+2)*Math.PI/180;o.push(new B(a*Math.sin(c),0,-a*Math.cos(c)),new B(a*Math.sin(h),0,-a*Math.cos(h)))}for(let l=0;l<360;l+=10){const c=l*Math.PI/180,h=l%30===0?.85:.92;if(o.push(new B(a*Math.sin(c),0,-a*Math.cos(c)),new B(h*a*Math.sin(c),0,-h*a*Math.cos(c))),l%30===0&&l<=180){const d=new Lc(`${l}°`,.06*e);d.sprite.position.set(1.2*a*Math.sin(c),0,-1.2*a*Math.cos(c)),this.dial.add(d.sprite)}}o.push(new B(0,0,-a),new B(0,0,a)),this.dial.add(Jf(o))}face(e){const t=this.ruler.position;this.ruler.rotation.set(0,0,Math.atan2(e.x-t.x,-(e.y-t.y))),this.placeRuler()}placeRuler(){const e=this.ruler.rotation.z,[t,n]=this.moved.ruler,s=this.built>0?this.built:1;this.ruler.position.set(this.pivot.x+t*s*Math.cos(e),this.pivot.y+t*s*Math.sin(e),this.pivot.z+n*s)}update(e,t,n,s,r,a,o={ruler:[0,0],protractor:[0,0]}){if(this.ruler.visible=s,this.protractor.visible=r,!s&&!r)return;this.build(n),this.moved=o,this.pivot.copy(e),this.ruler.position.copy(e),this.face(a);const l=Math.atan2(t[1],t[0]),[c,h]=o.protractor,d=Number.isFinite(l)?Math.cos(l):1,u=Number.isFinite(l)?Math.sin(l):0;this.protractor.position.set(e.x+c*n*d,e.y+c*n*u,e.z+h*n);const m=Math.atan2(Math.hypot(t[0],t[1]),-t[2]);this.dial.rotation.set(0,0,Number.isFinite(l)?l:0);const _=.72*n,y=m/2;this.thetaLabel.sprite.position.set(_*Math.sin(y)*Math.cos(l),_*Math.sin(y)*Math.sin(l),-_*Math.cos(y)),this.thetaLabel.sprite.scale.set(.4*n,.1*n,1),this.thetaLabel.set(`θ = ${(m*180/Math.PI).toFixed(1)}°`)}}class vE{constructor(e){this.renderer=e,this.stereo.aspect=1}renderer;stereo=new Km;render(e,t,n,s,r){const a=this.renderer,o=a.getContext();t.focus=s,t.updateMatrixWorld(),this.stereo.eyeSep=n,this.stereo.update(t);const l=a.autoClear,c=e.background;a.autoClear=!1,e.background=null,a.setClearColor(r,1),a.clear();try{o.colorMask(!0,!1,!1,!0),a.render(e,this.stereo.cameraL),a.clearDepth(),o.colorMask(!1,!0,!0,!0),a.render(e,this.stereo.cameraR)}finally{o.colorMask(!0,!0,!0,!0),e.background=c,a.autoClear=l}}}function xE(i,e,t,n=.9){const s=e*Math.PI/360,r=Math.atan(Math.tan(s)*Math.max(t,.001)),a=Math.min(s,r);return i/Math.sin(a*n)}function yE(i,e){const t=[],s=a=>{for(let o=0;o<96;o++)t.push(a(2*Math.PI*o/96),a(2*Math.PI*(o+1)/96))};for(let a=0;a<6;a++){const o=a*Math.PI/6;s(l=>new B(Math.sin(l)*Math.cos(o),Math.sin(l)*Math.sin(o),Math.cos(l)))}for(const a of[-.75,-.5,-.25,.25,.5,.75]){const o=Math.sqrt(1-a*a);s(l=>new B(o*Math.cos(l),o*Math.sin(l),a))}const r=new El(new Bt().setFromPoints(t),new vi({color:i,transparent:!0,opacity:e}));return r.visible=!1,r}function SE(i,e,t,n){const s=t.position.clone().sub(i).normalize(),r=new B().crossVectors(s,new B(0,0,1));r.lengthSq()<1e-12&&r.set(1,0,0),r.normalize();const a=new B().crossVectors(s,r).normalize(),o=t.position.distanceTo(i),l=e*Math.sqrt(Math.max(0,1-e*e/(o*o))),c=i.clone().addScaledVector(s,e*e/o),h=n.getBoundingClientRect(),d={left:1/0,right:-1/0,top:1/0,bottom:-1/0};for(let u=0;u<64;u++){const m=2*Math.PI*u/64,_=c.clone().addScaledVector(r,l*Math.cos(m)).addScaledVector(a,l*Math.sin(m)).project(t),y=h.left+(_.x+1)/2*h.width,p=h.top+(1-_.y)/2*h.height;d.left=Math.min(d.left,y),d.right=Math.max(d.right,y),d.top=Math.min(d.top,p),d.bottom=Math.max(d.bottom,p)}return d}const tn=180/Math.PI;function Ha(i){return{theta:Math.atan2(Math.hypot(i[0],i[1]),-i[2]),phi:Math.atan2(i[1],i[0])}}function ME(i){let e=i%(2*Math.PI);return e<=-Math.PI&&(e+=2*Math.PI),e>Math.PI&&(e-=2*Math.PI),e}class bE{constructor(e=8){this.maxLaps=e}maxLaps;acc=0;since=null;laps=[];get running(){return this.since!==null}reading(e){return this.acc+(this.since===null?0:Math.max(0,e-this.since))}start(e){this.since===null&&(this.since=e)}stop(e){this.since!==null&&(this.acc=this.reading(e),this.since=null)}lap(e){this.laps.push(this.reading(e)),this.laps.length>this.maxLaps&&this.laps.shift()}reset(){[this.acc,this.since,this.laps]=[0,null,[]]}}const zo={kind:null,period:null,advance:null,precession:null,lowPerPeriod:1,intervals:0,amplitude:null,thetaMin:null,thetaMax:null,from:null,to:null};class wE{constructor(e=1e-7,t=10,n=.02){this.minRise=e,this.keep=t,this.planarRatio=n}minRise;keep;planarRatio;prev=null;phi=0;lows=[];lowCount=0;zLow=1/0;zHigh=-1/0;rMax=0;thMax=0;thMin=1/0;reset(){this.prev=null,this.phi=0,this.lows=[],this.lowCount=0,this.zLow=1/0,this.zHigh=-1/0,this.rMax=0,this.thMax=0,this.thMin=1/0}push(e){const t=this.prev;if(t!==null&&e.t<=t.t)return;const n=Math.atan2(e.x[1],e.x[0]),s=Math.hypot(e.x[0],e.x[1]),r=Math.atan2(s,-e.x[2]);if(t===null){this.phi=n,this.prev=e,this.zLow=this.zHigh=e.x[2],[this.rMax,this.thMax,this.thMin]=[s,r,r];return}const a=this.phi;this.phi=a+ME(n-Math.atan2(t.x[1],t.x[0])),this.zLow=Math.min(this.zLow,e.x[2]),this.zHigh=Math.max(this.zHigh,e.x[2]);const[o,l]=[t.v[2],e.v[2]];if(o<0&&l>=0){const c=o===l?0:-o/(l-o),h=t.t+c*(e.t-t.t),d=a+c*(this.phi-a);if(this.lows.length===0||this.zHigh-this.zLow>this.minRise){const u=(M,C)=>M+c*(C-M),m=u(t.x[0],e.x[0]),_=u(t.x[1],e.x[1]),y=u(t.v[0],e.v[0]),p=u(t.v[1],e.v[1]),f=Math.hypot(y,p)||1,x=Math.hypot(m,_),A=Math.max(this.rMax,x);this.lows.push({t:h,phi:d,dir:[y/f,p/f],through:A>0&&x<=this.planarRatio*A,thetaMax:this.thMax,thetaMin:Math.min(this.thMin,r)}),this.lows.length>2*this.keep+1&&this.lows.shift(),this.lowCount++}this.zLow=this.zHigh=e.x[2],[this.rMax,this.thMax,this.thMin]=[s,r,r],this.prev=e;return}this.rMax=Math.max(this.rMax,s),this.thMax=Math.max(this.thMax,r),this.thMin=Math.min(this.thMin,r),this.prev=e}reading(){const e=this.lows,t=e[e.length-1];if(t===void 0||e.length<2)return{...zo};const n={thetaMin:Math.min(t.thetaMin,this.thMin),thetaMax:Math.max(t.thetaMax,this.thMax)};if(t.through){const l=[];let c=0;for(let p=e.length-1;p>=0&&l.length<=this.keep;p--){const f=e[p];if(!f.through)break;f.dir[0]*t.dir[0]+f.dir[1]*t.dir[1]>0&&l.push(f),c=p}const h=l.length-1,d=l[h],u=e[e.length-2],m=u.dir[0]*t.dir[0]+u.dir[1]*t.dir[1]>0?1:2,_=e.slice(Math.max(c,e.indexOf(d))+1),y=_.length>0?Math.sqrt(_.reduce((p,f)=>p+f.thetaMax**2,0)/_.length):t.thetaMax;return{...zo,kind:"swing",period:h<1?null:(t.t-d.t)/h,lowPerPeriod:m,intervals:Math.max(h,0),amplitude:y,...n,from:h<1?null:d.t,to:t.t}}let s=e.length-1;for(;s>0&&e.length-1-s<this.keep&&!e[s-1].through;)s--;const r=e[s],a=e.length-1-s;if(a<1)return{...zo,kind:"orbit",...n};const o=(t.phi-r.phi)/a;return{...zo,kind:"orbit",period:(t.t-r.t)/a,advance:o,precession:Math.sign(o)*(2*Math.abs(o)-2*Math.PI),intervals:a,...n,from:r.t,to:t.t}}}function EE(i){let[e,t]=[1,Math.sqrt(1-i)];for(let n=0;n<40&&Math.abs(e-t)>1e-16*e;n++)[e,t]=[(e+t)/2,Math.sqrt(e*t)];return Math.PI/(2*e)}function TE(i,e,t,n){if(!(e>0)||!(i>0)||!(n>=0)||n>=Math.PI)return null;const s=e/i,r=Math.sqrt(s-t**2/4);return r>0?4*EE(Math.sin(n/2)**2)/r:null}function fg(i,e,t,n,s){const r=.5*e*(i.v[0]**2+i.v[1]**2+i.v[2]**2),a=i.energy-r+e*Math.abs(t)*n,o=-s;return{kinetic:r,potential:a,lost:o,total:r+a+o}}function AE(i,e){return .5*(i.power+e.power)*(e.t-i.t)}function RE(i,e,t=null){const n=i.kind===null?e?.kind==="planar":i.kind==="swing",s=e===null||e.period_z_infinite||e.period_z===null?null:e.period_z;let r=s;n&&s!==null&&e?.kind!=="planar"&&(r=i.lowPerPeriod*s),e===null&&(r=t);const a=e?.azimuth_advance??null,o=l=>l===null?null:Math.sign(l)*(2*Math.abs(l)-2*Math.PI);return{swing:n,period:[i.period,r],advance:[n?null:i.advance,n?null:a],precession:[n?null:i.precession,n?null:o(a)]}}const jf=512,Zs=4e3,CE=4e3,PE=2e5,LE=3,DE=["t [s]","x1 [m]","x2 [m]","x3 [m]","v1 [m/s]","v2 [m/s]","v3 [m/s]","energy [J]","j3 [kg m^2/s]","tension [N]","power [W]","a1 [m/s^2]","a2 [m/s^2]","a3 [m/s^2]","pivot1 [m]","pivot2 [m]","pivot3 [m]","taut [1]","error_x [m]"];function Qf(){return{t:[],dE:[],dJ3:[],z:[],zdot:[],tension:[],frames:[]}}function Hi(i,e,t){return i+(e-i)*t}function NE(i,e,t){const n=(o,l)=>[Hi(o[0],l[0],t),Hi(o[1],l[1],t),Hi(o[2],l[2],t)],s=n(i.x,e.x),r=Hi(Math.hypot(...i.x),Math.hypot(...e.x),t),a=Math.hypot(...s);if(a>0)for(let o=0;o<3;o++)s[o]=s[o]*(r/a);return{t:Hi(i.t,e.t,t),x:s,v:n(i.v,e.v),energy:Hi(i.energy,e.energy,t),j3:Hi(i.j3,e.j3,t),tension:Hi(i.tension,e.tension,t),power:Hi(i.power,e.power,t),a:n(i.a,e.a),pivot:n(i.pivot,e.pivot),taut:i.taut&&e.taut,errorX:i.errorX<0||e.errorX<0?-1:Hi(i.errorX,e.errorX,t)}}function IE(i,e,t){return i===null||e.epoch!==i.epoch||t!==null&&e.t<t}function ep(i,e,t){let n=0,s=i.length;for(;n<s;){const r=n+s>>1,a=i[r].t;(t?a<e:a<=e)?n=r+1:s=r}return n}class Cu{status=null;frames=[];trail=[];history=Qf();trajectory=[];trajectoryTruncated=!1;reference=null;tensionExtremes=null;playT=null;exact=null;exactError=null;errors=[];events=[];connected=!1;tickHz=60;work=0;periodTimer=new wE;historyStride=1;historyCount=0;disconnected=!1;listeners=new Set;subscribe(e){return this.listeners.add(e),()=>this.listeners.delete(e)}emit(){for(const e of this.listeners)e()}onStatus(e){const t=this.disconnected||IE(this.status,e,this.latest()?.t??null);this.disconnected=!1,this.status=e,t&&this.clear(),this.emit()}clear(){this.frames=[],this.trail=[],this.history=Qf(),this.trajectory=[],this.trajectoryTruncated=!1,this.reference=null,this.tensionExtremes=null,this.playT=null,this.exact=null,this.exactError=null,this.events=[],this.work=0,this.periodTimer.reset(),this.historyStride=1,this.historyCount=0}onError(e){this.errors.push(e),this.errors.length>20&&this.errors.shift(),this.emit()}onEvent(e){const t=this.events;this.events=u0(t,e,this.status?.epoch??null),this.events!==t&&(this.work-=e.energy_lost,this.emit())}setConnected(e){this.connected=e,e||(this.disconnected=!0),this.emit()}setExact(e,t=null){this.exact=e,this.exactError=t,this.emit()}onFrames(e){for(const t of e){const n=this.frames[this.frames.length-1];if(n!==void 0&&t.t<n.t)continue;n!==void 0&&t.t===n.t?this.frames.pop():n!==void 0&&(this.work+=AE(n,t)),this.frames.push(t),this.periodTimer.push(t),this.reference===null&&(this.reference={energy:t.energy,j3:t.j3});const s=this.tensionExtremes;s===null?this.tensionExtremes={min:t.tension,tMin:t.t,max:t.tension,tMax:t.t}:(t.tension<s.min&&([s.min,s.tMin]=[t.tension,t.t]),t.tension>s.max&&([s.max,s.tMax]=[t.tension,t.t])),this.pushTrail(t),this.pushHistory(t),this.trajectory.length<PE?this.trajectory.push(t):this.trajectoryTruncated=!0,this.playT===null&&(this.playT=t.t)}this.frames.length>jf&&this.frames.splice(0,this.frames.length-jf)}pushTrail(e){const t=this.trail[this.trail.length-1];t!==void 0&&t.t===e.t&&this.trail.pop(),this.trail.push(e),this.trail.length>Zs&&this.trail.splice(0,this.trail.length-Zs)}pushHistory(e){const t=this.reference;if(t===null)return;const n=this.history;if(!(n.t.length>0&&e.t<=n.t[n.t.length-1])&&this.historyCount++%this.historyStride===0&&(n.t.push(e.t),n.dE.push(e.energy-t.energy),n.dJ3.push(e.j3-t.j3),n.z.push(e.x[2]),n.zdot.push(e.v[2]),n.tension.push(e.tension),n.frames.push(e),n.t.length>CE)){const s=r=>r.filter((a,o)=>o%2===0);this.history={t:s(n.t),dE:s(n.dE),dJ3:s(n.dJ3),z:s(n.z),zdot:s(n.zdot),tension:s(n.tension),frames:s(n.frames)},this.historyStride*=2,this.historyCount=1}}latest(){return this.frames[this.frames.length-1]??null}advancePlayhead(e){const t=this.latest(),n=this.frames[0];if(t==null||n===void 0)return this.playT=null;const s=this.status;if(s===null||s.paused||this.playT===null)return this.playT=t.t,this.playT;const r=LE*s.time_scale/this.tickHz;let a=this.playT+Math.max(0,e)*s.time_scale;return a=Math.min(a,t.t),a=Math.max(a,t.t-r,n.t),this.playT=a,a}displayed(){const e=this.playT,t=this.frames;if(e===null||t.length===0)return null;const n=t[t.length-1];if(e>=n.t)return n;let s=0,r=t.length-1;if(e<=t[0].t)return t[0];for(;r-s>1;){const c=s+r>>1;t[c].t<=e?s=c:r=c}const a=t[s],o=t[r],l=o.t-a.t;return NE(a,o,l>0?(e-a.t)/l:1)}trailRange(e){const t=this.playT;if(t===null)return{start:0,end:0};const n=ep(this.trail,t,!1),s=ep(this.trail,t-e,!0);return{start:Math.min(s,n),end:n}}trailWindow(e){const{start:t,end:n}=this.trailRange(e);return this.trail.slice(t,n)}toCSV(){const e=this.status,t={source:"pendulab lab",scenario:e?.scenario??null,params:e?.params??null,model:e?.model??null,model_params:e?.model_params??null,method:e?.method??null,dt:e?.dt??null,truncated:this.trajectoryTruncated},n=DE.join(","),s=this.trajectory.map(r=>[r.t,...r.x,...r.v,r.energy,r.j3,r.tension,r.power,...r.a,...r.pivot,r.taut?1:0,r.errorX].map(a=>String(a)).join(","));return[`# ${JSON.stringify(t)}`,n,...s].join(`
`)+`
`}}const UE=13170016,FE=[16743129,7328767],OE=new B(0,1,0);class tp{group=new $i;bob;rod;pivotMark;trail;positions=new Float32Array(3*(Zs+1));tmpX=new B;tmpPivot=new B;tmpDir=new B;length=1;offset=new B;constructor(e=UE){this.bob=new sn(new cs(1,24,16),new Gr({color:e,roughness:.4})),this.rod=new sn(new Za(1,1,1,8),new Gr({color:e,metalness:.3,roughness:.5}));const t=new Bt;t.setAttribute("position",new _i(this.positions,3)),t.setDrawRange(0,0),this.trail=new Ji(t,new vi({color:e,transparent:!0,opacity:.6})),this.trail.frustumCulled=!1,this.pivotMark=new sn(new cs(1,12,8),new Gr({color:e})),this.pivotMark.visible=!1,this.group.add(this.bob,this.rod,this.trail,this.pivotMark),this.group.visible=!1}setLength(e,t=e){this.length=t,this.bob.scale.setScalar(.045*t)}setOffset(e){e===null?this.offset.set(0,0,0):this.offset.fromArray(e),this.pivotMark.visible=e!==null,this.pivotMark.position.copy(this.offset),this.pivotMark.scale.setScalar(.03*this.length)}update(e,t){if(this.group.visible=e!==null,e===null)return;const n=this.tmpX.fromArray(e.x),s=this.tmpPivot.fromArray(e.pivot).add(this.offset);this.bob.position.copy(n).add(s);const r=n.length();r>0&&(this.rod.position.copy(n).multiplyScalar(.5).add(s),this.rod.quaternion.setFromUnitVectors(OE,this.tmpDir.copy(n).divideScalar(r)),this.rod.scale.set(.005*this.length,r,.005*this.length));const a=Math.max(0,Math.min(t.end-t.start,Zs)),o=this.positions;for(let h=0;h<a;h++){const d=t.frames[t.end-a+h];o[3*h]=d.x[0]+d.pivot[0]+this.offset.x,o[3*h+1]=d.x[1]+d.pivot[1]+this.offset.y,o[3*h+2]=d.x[2]+d.pivot[2]+this.offset.z}const l=this.trail.geometry;l.setDrawRange(0,a);const c=l.getAttribute("position");c.clearUpdateRanges(),c.addUpdateRange(0,3*Math.max(a,1)),c.needsUpdate=!0}}const kE=16766720,BE=4e3;function zE(i,e=[0,0,0]){const t=i.filter(s=>s.every(Number.isFinite)).slice(0,BE),n=new Float32Array(3*t.length);return t.forEach((s,r)=>{n[3*r]=s[0]+e[0],n[3*r+1]=s[1]+e[1],n[3*r+2]=s[2]+e[2]}),n}function HE(i,e){const t=e>1?i/(e-1):0,n=Math.max(t/3,1e-4);return{dash:n,gap:Math.max(2*n,1e-4)}}class GE{line;material=new Xm({color:kE,dashSize:.01,gapSize:.02});constructor(){this.line=new Ji(new Bt,this.material),this.line.frustumCulled=!1,this.line.visible=!1,this.line.name="measured-path"}set(e){this.line.geometry.dispose();const t=new Bt,n=zE(e??[]);t.setAttribute("position",new _i(n,3)),this.line.geometry=t;const s=n.length/3;if(this.line.visible=s>1,s<2)return;this.line.computeLineDistances();const r=t.getAttribute("lineDistance"),{dash:a,gap:o}=HE(r.getX(s-1),s);this.material.dashSize=a,this.material.gapSize=o}get points(){return this.line.visible?this.line.geometry.getAttribute("position").count:0}}const pg=["off","anaglyph","side by side"],Pu={trail:!0,trailSeconds:10,sphere:!0,axes:!0,velocity:!0,momentum:!1,gravity:!1,tension:!1,net:!1,angularMomentum:!1,torque:!1,originX:0,originY:0,originZ:0,stereo:"off",ruler:!1,protractor:!1,rulerShift:0,rulerLift:0,protractorShift:0,protractorLift:0,present:!1,simple:!1},Lu={velocity:14711807,momentum:10194175,gravity:16757575,tension:16735603,net:16777215,angularMomentum:5102016,torque:16769357},VE=["angularMomentum","torque"];function WE(i){const e=new Zx(new B(1,0,0),new B,1,i);return e.visible=!1,e}class XE{arrows=Object.fromEntries(Object.entries(Lu).map(([e,t])=>[e,WE(t)]));tmpVec=new B;tmpOrigin=new B;objects(){return Object.values(this.arrows)}hide(){for(const e of Object.values(this.arrows))e.visible=!1}update(e,t,n,s,r,a,o,l){const c=Object.keys(this.arrows);if(!c.some(_=>t[_])){for(const _ of c)this.arrows[_].visible=!1;return}const h=[t.originX,t.originY,t.originZ],d=mE(e,n,s,r,h),u=Vh(l,n,s),m=this.tmpOrigin.fromArray(h).add(a);for(const _ of c){const y=VE.includes(_)?m:o,p=this.tmpVec.fromArray(d[_]).multiplyScalar(u[_]);$E(this.arrows[_],t[_],y,p,l)}}}function $E(i,e,t,n,s){const r=n.length();if(i.visible=e&&r>1e-6*s,!i.visible)return;i.position.copy(t),i.setDirection(n.divideScalar(r));const a=Math.min(.25*r,.08*s);i.setLength(r,a,.5*a)}const qE=/swiftshader|llvmpipe|softpipe|software|basic render driver|lavapipe/i;function YE(i){return i!==null&&qE.test(i)}function KE(i,e){return 1-(1-i)**e}function ZE(i,e){const t=YE(i),n=Number.isFinite(e)&&e>0?e:1;return{renderer:i,software:t,antialias:!t,pixelRatio:Math.min(n,t?1:2),reachLayers:t?1:2}}function JE(){const i=document.createElement("canvas"),e=i.getContext("webgl2")??i.getContext("webgl");if(e===null)return null;let t=e.getParameter(e.RENDERER);if(typeof t!="string"||t===""||/^webkit webgl$/i.test(t)){const n=e.getExtension("WEBGL_debug_renderer_info");n!==null&&(t=e.getParameter(n.UNMASKED_RENDERER_WEBGL))}return e.getExtension("WEBGL_lose_context")?.loseContext(),typeof t=="string"&&t!==""&&!/^webkit webgl$/i.test(t)?t:null}const mg=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]],Ga=i=>Math.hypot(i[0],i[1],i[2]),Va=(i,e)=>[i[0]*e,i[1]*e,i[2]*e],Wh=(i,e)=>[i[1]*e[2]-i[2]*e[1],i[2]*e[0]-i[0]*e[2],i[0]*e[1]-i[1]*e[0]];function gg(i,e){const t=e[0]*i[0]+e[1]*i[1]+e[2]*i[2];let n=mg(e,Va(i,t));return Ga(n)<1e-9&&(n=Math.abs(i[0])<.9?Wh(i,[1,0,0]):Wh(i,[0,1,0])),Va(n,1/Ga(n))}function jE(i,e,t,n){const s=Ga(i);if(!(s>0))return[[0,0,0],[...i]];const r=Va(i,1/s),a=gg(r,[0,0,1]),o=Wh(r,a),l=[];for(let c=0;c<=n;c++){const h=c/n,d=t*Math.min(1,h/.05,(1-h)/.05),u=2*Math.PI*e*h,[m,_]=[Math.cos(u)*d,Math.sin(u)*d];l.push([i[0]*h+a[0]*m+o[0]*_,i[1]*h+a[1]*m+o[1]*_,i[2]*h+a[2]*m+o[2]*_])}return l}function QE(i){let e=0;for(let t=1;t<i.length;t++)e+=Ga(mg(i[t],i[t-1]));return e}function np(i,e,t){const n=[];for(let s=0;s<=t;s++){const r=s/t,[a,o]=[2*r*(1-r),r*r];n.push([e[0]*a+i[0]*o,e[1]*a+i[1]*o,e[2]*a+i[2]*o])}return n}function eT(i,e,t,n=[0,0,-1]){const s=Ga(i),r=Va(i,.5);if(!(s>0)||s>=e)return np(i,r,t);const a=gg(Va(i,1/s),n),o=h=>np(i,[r[0]+a[0]*h,r[1]+a[1]*h,r[2]+a[2]*h],t);let[l,c]=[0,e];for(let h=0;h<40&&c-l>1e-4*e;h++){const d=.5*(l+c);QE(o(d))<e?l=d:c=d}return o(.5*(l+c))}const ip=400,sp=48;class tT{group=new $i;coil;slack;constructor(){this.coil=new Ji(new Bt().setFromPoints(Array.from({length:ip+1},()=>new B)),new vi({color:14211288})),this.slack=new Ji(new Bt().setFromPoints(Array.from({length:sp+1},()=>new B)),new Xm({color:15918793,dashSize:.04,gapSize:.03}));for(const e of[this.coil,this.slack])e.frustumCulled=!1,e.visible=!1;this.group.add(this.coil,this.slack)}update(e,t,n,s,r){if(this.coil.visible=e==="coil",this.slack.visible=e==="slack string",this.group.position.set(...n),e==="coil"&&this.fill(this.coil,jE(t,14,.035*s,ip)),e==="slack string"){this.fill(this.slack,eT(t,s,sp,r));const a=this.slack.material;a.dashSize=.04*s,a.gapSize=.03*s,this.slack.computeLineDistances()}}fill(e,t){const n=e.geometry.getAttribute("position");t.forEach((s,r)=>n.setXYZ(r,s[0],s[1],s[2])),n.needsUpdate=!0}}const rp=.06,nT=new B(0,1,0),iT=.025,sT=.06,rT=.085;class aT{sphere;equator;reachLines=yE(9417727,.18);rod;bob;pivot;axes;boom;handle;tether=new tT;tmpX=new B;tmpDir=new B;tmpHandle=new B;bobAt=new B;model="ideal";length=1;constructor(e){this.sphere=new sn(new cs(1,48,32),new Ps({color:9417727,transparent:!0,opacity:e.reachLayers===1?KE(rp,2):rp,depthWrite:!1,side:e.reachLayers===2?pi:Ds}));const t=new Bt().setFromPoints(Array.from({length:128},(n,s)=>{const r=2*Math.PI*s/128;return new B(Math.cos(r),Math.sin(r),0)}));this.equator=new Fx(t,new vi({color:9417727,transparent:!0,opacity:.25})),this.pivot=new sn(new cs(.02,16,12),new Gr({color:13421772})),this.rod=new sn(new Za(1,1,1,12),new Gr({color:14211288,metalness:.6,roughness:.3})),this.bob=new sn(new cs(1,32,24),new Gr({color:16747586,roughness:.35})),this.axes=new Jm(1.3),this.handle=new sn(new cs(1,16,12),new Ps({color:15911167})),this.handle.name="velocity handle",this.handle.visible=!1,this.boom=new Ji(new Bt().setFromPoints([new B,new B]),new vi({color:10134712})),this.boom.visible=!1,this.boom.frustumCulled=!1}objects(){return[this.sphere,this.equator,this.reachLines,this.pivot,this.rod,this.bob,this.axes,this.tether.group,this.handle,this.boom]}setLength(e){this.length=e,this.sphere.scale.setScalar(e),this.equator.scale.setScalar(e),this.reachLines.scale.setScalar(e),this.pivot.scale.setScalar(e),this.bob.scale.setScalar(.05*e),this.handle.scale.setScalar(iT*e),this.axes.scale.setScalar(e)}show(e,t,n,s){this.sphere.visible=t.sphere&&!n,this.reachLines.visible=t.sphere&&n,this.equator.visible=t.sphere,this.axes.visible=t.axes;const r=e!==null,a=Oc(this.model,e?.taut??!0);this.rod.visible=r&&(a==="rod"||a==="taut string"),this.bob.visible=r,this.handle.visible=r&&t.velocity,e===null&&this.tether.update("rod",[0,0,0],[0,0,0],this.length,s)}place(e,t,n,s,r){const a=Oc(this.model,e.taut??!0),o=Math.hypot(t.x,t.y);if(this.boom.visible=o>1e-9*this.length,this.boom.visible){const u=this.boom.geometry.getAttribute("position");u.setXYZ(0,0,0,t.z),u.setXYZ(1,t.x,t.y,t.z),u.needsUpdate=!0}for(const u of[this.sphere,this.equator,this.reachLines,this.pivot])u.position.copy(t);const l=this.tmpX.fromArray(e.x),c=l.length(),h=this.bobAt.copy(l).add(t);if(this.bob.position.copy(h),c>0){this.rod.position.copy(l).multiplyScalar(.5).add(t),this.rod.quaternion.setFromUnitVectors(nT,this.tmpDir.copy(l).divideScalar(c));const u=a==="taut string"?.003:.008;this.rod.scale.set(u*this.length,c,u*this.length)}const d=n<0?[-s[0],-s[1],-s[2]]:s;if(this.tether.update(a,e.x,e.pivot,this.length,d),this.handle.visible){const u=cE(e.x,e.v,r,rT*this.length);this.handle.position.copy(this.tmpHandle.fromArray(u).add(h))}return h}}class oT{constructor(e,t,n){this.inputs=t,this.invalidate=n,this.camera.up.set(0,0,1),this.controls=new ug(this.camera,e),this.controls.enableDamping=!0}inputs;invalidate;camera=new Yn(40,1,.01,1e3);controls;length=1;extent=1;reach=1;follow=!1;followAt=null;topView=!1;tmp=new B;setLength(e){const t=Math.abs(e-this.length)>1e-12*e;this.length=e,t&&(this.extent=this.reach=e,this.reset())}setModel(e){this.follow=e==="slewing",this.followAt=null,this.extent=this.reach=this.length,this.reset()}setTopView(e){this.topView=e,this.reset()}reset(){const e=this.inputs.row(),t=e[e.length-1]??null,n=t===null?0:.5*Math.hypot(...t.offset),s=t===null?this.extent:n+Math.max(this.extent,...e.map(c=>c.length)),r=1.1*s,a=this.inputs.halfWidth()?this.camera.aspect/2:this.camera.aspect,o=xE(r,this.camera.fov,a),l=this.follow&&this.followAt!==null?this.followAt.clone():new B;t!==null&&l.add(new B(...t.offset).multiplyScalar(.5)),this.topView?this.camera.position.set(0,-1e-4*o,o).add(l):this.camera.position.set(3.3,-3.9,1.5).normalize().multiplyScalar(o).add(l),this.controls.target.copy(l),this.camera.near=.01*this.length,this.camera.far=100*s,this.camera.updateProjectionMatrix(),this.controls.update(),this.invalidate()}setAspect(e){this.camera.aspect=e,this.camera.updateProjectionMatrix(),this.reset()}track(e,t){this.followPivot(e),this.reach=Math.max(this.reach,Math.hypot(...t)),this.fit(this.reach+(this.follow?0:e.length()))}fit(e){Math.abs(e-this.extent)<=.2*this.extent||(this.extent=e,this.reset())}followPivot(e){if(!this.follow)return;if(this.followAt===null){this.followAt=e.clone(),this.reset();return}const t=this.tmp.copy(e).sub(this.followAt);t.lengthSq()!==0&&(this.camera.position.add(t),this.controls.target.add(t),this.followAt.copy(e))}orbitBy(e,t,n=1){const s=this.camera.position.clone().sub(this.controls.target),r=new Hh().setFromCartesianCoords(s.x,s.z,-s.y);r.theta+=e,r.phi=Math.min(Math.max(r.phi-t,.05),Math.PI-.05),r.radius*=n;const a=new B().setFromSpherical(r);this.camera.position.set(a.x,-a.z,a.y).add(this.controls.target),this.camera.lookAt(this.controls.target),this.controls.update(),this.invalidate()}}const lT={frames:[],start:0,end:0},cT=new lt(5882879);class hT{constructor(e){this.background=e;const t=new Bt;t.setAttribute("position",new _i(this.positions,3)),t.setAttribute("color",new _i(this.colors,3)),t.setDrawRange(0,0),this.line=new Ji(t,new vi({vertexColors:!0})),this.line.frustumCulled=!1}background;line;positions=new Float32Array(3*(Zs+1));colors=new Float32Array(3*(Zs+1));colored=-1;hide(){this.line.geometry.setDrawRange(0,0)}update(e,t){const n=Math.min(e.end-e.start,Zs),s=this.line.geometry;if(n<=0){s.setDrawRange(0,0);return}const r=e.end-n,a=this.positions,o=n+1;for(let c=0;c<o;c++){const h=c<n?e.frames[r+c]:t;a[3*c]=h.x[0]+h.pivot[0],a[3*c+1]=h.x[1]+h.pivot[1],a[3*c+2]=h.x[2]+h.pivot[2]}s.setDrawRange(0,o);const l=s.getAttribute("position");l.clearUpdateRanges(),l.addUpdateRange(0,3*o),l.needsUpdate=!0,o!==this.colored&&this.fade(o)}fade(e){this.colored=e;const t=this.colors,n=new lt;for(let r=0;r<e;r++)n.copy(this.background).lerp(cT,(r+1)/e),t[3*r]=n.r,t[3*r+1]=n.g,t[3*r+2]=n.b;const s=this.line.geometry.getAttribute("color");s.clearUpdateRanges(),s.addUpdateRange(0,3*e),s.needsUpdate=!0}}const Dc=new lt(1119259);class uT{constructor(e,t){this.container=e,this.renderer=new cg({antialias:t.antialias}),this.renderer.setPixelRatio(t.pixelRatio),this.renderer.domElement.id="scene-canvas",e.appendChild(this.renderer.domElement),this.scene.background=Dc,this.rig=new oT(this.renderer.domElement,{row:()=>this.twinLayout===null?[]:[this.twinLayout,...this.extraLayouts],halfWidth:()=>this.stereo==="side by side"},()=>this.invalid=!0),this.camera=this.rig.camera,this.controls=this.rig.controls,this.scene.add(new Yx(16777215,.6));const n=new qx(16777215,1.6);n.position.set(2,-3,4),this.scene.add(n),this.body=new aT(t),this.scene.add(...this.body.objects(),this.trail.line,this.twin.group,...this.extras.map(s=>s.group),this.measured.line,this.instruments.ruler,this.instruments.protractor,...this.arrows.objects()),this.setLength(1),this.resetCamera(),new ResizeObserver(()=>this.resize()).observe(e),this.resize()}container;renderer;camera;controls;scene=new Um;rig;body;trail=new hT(Dc);arrows=new XE;length=1;stereo="off";anaglyph=null;sideBySide=null;instruments=new _E;twin=new tp;extras=FE.map(e=>new tp(e));extraLayouts=[];extrasKey="";twinLayoutKey="";twinLayout=null;measured=new GE;drag=null;pull=null;drawn=null;velocityScale=Vh(1,1,9.81).velocity;gNow=9.81;pivotNow=new B;invalid=!0;setLength(e){e>0&&(this.length=e,this.body.setLength(e),this.twin.setLength(this.twinLayout?.length??e,Math.max(this.twinLayout?.length??0,e)),this.extras.forEach((t,n)=>t.setLength(this.extraLayouts[n]?.length??e,Math.max(this.extraLayouts[n]?.length??0,e))),this.rig.setLength(e),this.invalid=!0)}resetCamera(){this.rig.reset()}setModel(e){e!==this.body.model&&(this.invalid=!0,this.body.model=e,this.rig.setModel(e))}setTopView(e){this.rig.setTopView(e)}enableDrag(e,t){const n=this.renderer.domElement;this.pull=new dE(n,this.camera,this.controls,this.body.handle,this.body.bob,()=>sT*this.length,()=>this.pullBasis(),t),this.drag=new uE(n,this.camera,this.controls,this.body.bob,e,()=>({pivot:this.pivotNow,length:this.length}))}pullBasis(){const e=this.drawn;return e===null?null:{pivot:[...e.pivot],x:[...e.x],arrowScale:this.velocityScale,vmax:oE(this.length,this.gNow)}}setStereo(e){this.stereo=e,e==="anaglyph"&&this.anaglyph===null&&(this.anaglyph=new vE(this.renderer)),e==="side by side"&&this.sideBySide===null&&(this.sideBySide=new aE(this.renderer)),this.resize(),this.resetCamera()}resize(){const e=Math.max(1,this.container.clientWidth),t=Math.max(1,this.container.clientHeight);this.renderer.setSize(e,t,!1),this.stereo==="side by side"&&this.sideBySide?.setSize(e,t),this.renderer.domElement.style.width="",this.renderer.domElement.style.height="",this.rig.setAspect(e/t),this.invalid=!0}update(e,t,n,s,r,a){if(this.body.show(e,n,this.stereo==="anaglyph",a),this.drawn=e,this.gNow=r,this.velocityScale=Vh(this.length,s,r).velocity,e===null){this.trail.hide(),this.arrows.hide();return}const o=this.pivotNow.fromArray(e.pivot);this.rig.track(o,e.x),this.instruments.update(o,e.x,this.length,n.ruler,n.protractor,this.camera.position,{ruler:[n.rulerShift,n.rulerLift],protractor:[n.protractorShift,n.protractorLift]});const l=this.body.place(e,o,r,a,this.velocityScale);this.trail.update(n.trail?t:lT,e),this.arrows.update(e,n,s,r,a,o,l,this.length)}orbitBy(e,t,n=1){this.rig.orbitBy(e,t,n)}onScreen(e){if(!e.visible)return null;const t=e.position.clone().project(this.camera),n=this.renderer.domElement.getBoundingClientRect();return{x:n.left+(t.x+1)/2*n.width,y:n.top+(1-t.y)/2*n.height}}bobOnScreen(){return this.onScreen(this.body.bob)}handleOnScreen(){return this.onScreen(this.body.handle)}setTwinLayout(e){const t=e===null?"":`${e.offset.join(",")}|${e.length}`;t!==this.twinLayoutKey&&(this.twinLayoutKey=t,this.twinLayout=e,this.twin.setLength(e?.length??this.length,Math.max(e?.length??0,this.length)),this.twin.setOffset(e?.offset??null),this.resetCamera())}setExtras(e){const t=e.map(n=>`${n.offset.join(",")}|${n.length}`).join(";");t!==this.extrasKey&&(this.extrasKey=t,this.extraLayouts=e,this.extras.forEach((n,s)=>{const r=e[s];if(r===void 0)return n.update(null,{frames:[],start:0,end:0});n.setLength(r.length,Math.max(r.length,this.length)),n.setOffset(r.offset)}),this.resetCamera())}updateExtras(e){this.extras.forEach((t,n)=>t.update(e[n]?.frame??null,e[n]?.trail??{frames:[],start:0,end:0})),this.invalid=!0}extrasOnScreen(){return this.extras.filter(e=>e.group.visible).flatMap(e=>this.onScreen(e.bob)??[])}updateTwin(e,t){this.twin.update(e,t),this.invalid=!0}setMeasured(e){this.measured.set(e),this.invalid=!0}measuredPoints(){return this.measured.points}sphereOnScreen(){return SE(this.body.sphere.position,this.body.sphere.scale.x,this.camera,this.renderer.domElement)}instrumentsOnScreen(){return{ruler:this.onScreen(this.instruments.ruler),protractor:this.onScreen(this.instruments.protractor)}}twinOnScreen(){return this.twin.group.visible?this.onScreen(this.twin.bob):null}draw(e){const t=this.controls.update();return t&&this.instruments.ruler.visible&&this.instruments.face(this.camera.position),!e&&!t&&!this.invalid?!1:(this.invalid=!1,this.render(),!0)}render(){const e=this.camera.position.distanceTo(this.controls.target);this.stereo==="anaglyph"&&this.anaglyph!==null?this.anaglyph.render(this.scene,this.camera,e/30,e,Dc):this.stereo==="side by side"&&this.sideBySide!==null?(this.camera.focus=e,this.sideBySide.setEyeSeparation(e/30),this.sideBySide.render(this.scene,this.camera)):this.renderer.render(this.scene,this.camera)}screenshot(){return this.render(),this.renderer.domElement.toDataURL("image/png")}}class dT{constructor(e){this.intervalMs=e}intervalMs;last=-1/0;due(e){return e-this.last<this.intervalMs?!1:(this.last=e,!0)}reset(){this.last=-1/0}}class fT{last=null;changed(e){const t=this.last;return t!==null&&t.length===e.length&&e.every((n,s)=>Object.is(n,t[s]))?!1:(this.last=[...e],!0)}}class pT{sums=new Map;add(e,t){const n=this.sums.get(e);n===void 0?this.sums.set(e,{ms:t,count:1}):(n.ms+=t,n.count++)}take(){const e={};for(const[t,n]of this.sums)e[t]={ms:n.ms/n.count,count:n.count};return this.sums.clear(),e}}const mT={kinetic:"#7dff8a",potential:"#59c3ff",lost:"#ff5d73",total:"#e8e8e8"};class gT{canvas;ctx;scale=1;shown=null;constructor(e){const t=document.createElement("h3");t.textContent=R("energy.title"),e.appendChild(t),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("role","img"),this.canvas.setAttribute("aria-label",R("energy.title")),e.appendChild(this.canvas),this.ctx=this.canvas.getContext("2d")}rescale(){this.scale=1}draw(e,t){this.shown=e;const n=this.ctx;if(n===null)return;const s=Math.min(window.devicePixelRatio||1,2),r=Math.max(200,(this.canvas.parentElement?.clientWidth??300)-4),a=130;if(this.canvas.width!==Math.round(r*s)&&(this.canvas.width=Math.round(r*s),this.canvas.height=Math.round(a*s),this.canvas.style.width=`${r}px`,this.canvas.style.height=`${a}px`),n.setTransform(s,0,0,s,0,0),n.clearRect(0,0,r,a),e===null)return;const o=[["kinetic",R("energy.kinetic"),e.kinetic],["potential",R("energy.potential"),e.potential]];t&&o.push(["lost",R("energy.lost"),e.lost]),o.push(["total",R("energy.total"),e.total]);const l=Math.max(...o.map(([,,m])=>Math.abs(m)),1e-12);this.scale=l>this.scale?l:Math.max(l,.995*this.scale);const c=14,h=a-30,d=h,u=r/o.length;n.font="11px system-ui, sans-serif",n.textAlign="center",o.forEach(([m,_,y],p)=>{const f=u*p+u*.2,x=u*.6,A=Math.abs(y)/this.scale*(h-c);n.fillStyle=mT[m],y>=0?n.fillRect(f,d-A,x,A):(n.globalAlpha=.5,n.fillRect(f,d-A,x,A),n.globalAlpha=1),n.fillStyle="#dde3ee",n.fillText(_,f+x/2,a-16),n.fillText(`${y.toPrecision(4)} J`,f+x/2,a-3)}),n.strokeStyle="#555",n.beginPath(),n.moveTo(0,d+.5),n.lineTo(r,d+.5),n.stroke()}}const ap=(i,e)=>.5*e.mass*(i.v[0]**2+i.v[1]**2+i.v[2]**2),dl=[{name:"t",label:"var.t",unit:"s",get:i=>i.t},{name:"theta",label:"var.theta",unit:"°",get:i=>Ha(i.x).theta*tn},{name:"phi",label:"var.phi",unit:"°",get:i=>Ha(i.x).phi*tn},{name:"x",label:"var.x",unit:"m",get:i=>i.x[0]},{name:"y",label:"var.y",unit:"m",get:i=>i.x[1]},{name:"z",label:"var.z",unit:"m",get:i=>i.x[2]},{name:"zdot",label:"var.zdot",unit:"m/s",get:i=>i.v[2]},{name:"speed",label:"var.speed",unit:"m/s",get:i=>Math.hypot(...i.v)},{name:"energy",label:"var.energy",unit:"J",get:i=>i.energy},{name:"kinetic",label:"var.kinetic",unit:"J",get:ap},{name:"potential",label:"var.potential",unit:"J",get:(i,e)=>i.energy-ap(i,e)},{name:"j3",label:"var.j3",unit:"kg m²/s",get:i=>i.j3},{name:"tension",label:"var.tension",unit:"N",get:i=>i.tension},{name:"power",label:"var.power",unit:"W",get:i=>i.power},{name:"radius",label:"var.radius",unit:"m",get:i=>Math.hypot(...i.x)}];function Na(i){return dl.find(e=>e.name===i)??dl[0]}function op(i,e,t,n){const[s,r]=[Na(e),Na(t)];return{x:i.map(a=>s.get(a,n)),y:i.map(a=>r.get(a,n))}}class _T{constructor(e){this.container=e;const t=document.createElement("div");t.className="tools chosen",t.dataset.tool="chosen";const n=document.createElement("h3");n.textContent=R("chosen.title"),t.appendChild(n);for(const s of["y","x"]){const r=document.createElement("label");r.append(`${R(s==="x"?"chosen.xAxis":"chosen.yAxis")} `);const a=document.createElement("select");a.dataset.input=`chosen-${s}`;for(const o of dl){const l=document.createElement("option");l.value=o.name,l.textContent=`${R(o.label)} [${o.unit}]`,a.appendChild(l)}a.value=this.choice[s],this.selects[s]=a,a.addEventListener("change",()=>{this.choice[s]=a.value,this.labels()}),r.appendChild(a),t.append(r," ")}e.appendChild(t),this.plot=new Pa(e,"","","",170),this.plot.canvas.dataset.plot="chosen",this.visibility.watch(this.plot.canvas),this.labels()}container;plot;visibility=new Ml;choice={x:"t",y:"theta"};selects={};choose(e,t){return[e,t].every(n=>dl.some(s=>s.name===n))?(this.choice.x=e,this.choice.y=t,this.selects.x&&(this.selects.x.value=e),this.selects.y&&(this.selects.y.value=t),this.labels(),!0):!1}labels(){const[e,t]=[Na(this.choice.x),Na(this.choice.y)];this.plot.xLabel=`${R(e.label)} [${e.unit}]`,this.plot.yLabel=`${R(t.label)} [${t.unit}]`}update(e,t,n=null){if(!this.visibility.visible(this.plot.canvas))return;const r=[{...op(e,this.choice.x,this.choice.y,t),color:"#59c3ff",label:R(n?"twin.first":Na(this.choice.y).label)}];n!==null&&r.push({...op(n,this.choice.x,this.choice.y,t),color:"#c8f560",label:R("twin.second")});const a=r.flatMap(l=>l.x),o=r.flatMap(l=>l.y);this.plot.draw(this.container.clientWidth-8,r,Ks(a,.02),Ks(o))}}const Jo=2;function _g(i,e){const t=1.1*(i+e),n=Math.hypot(3.9,3.3);return[t*3.9/n,t*3.3/n,0]}function vT(i,e){const t=Math.hypot(...i),n=Math.atan2(Math.hypot(i[0],i[1]),-i[2])+e,s=Math.atan2(i[1],i[0]);return[t*Math.sin(n)*Math.cos(s),t*Math.sin(n)*Math.sin(s),-t*Math.cos(n)]}function vg(i,e){const t=[];i.scenario&&t.push({type:"load_scenario",name:i.scenario});const n=e.mode==="damped",s=e.mode==="own",r=n&&i.model==="ideal"?"damped":i.model,a={...i.model_params};if(n&&(a.damping=e.damping),t.push({type:"set_model",model:r,params:a}),t.push({type:"set_params",length:s?e.length:i.params.length,mass:s?e.mass:i.params.mass,g:i.params.g}),t.push({type:"set_method",method:e.mode==="method"?e.method:i.method,dt:i.dt}),s)t.push({type:"set_state",theta:e.theta,phi:0,theta_dot:0,phi_dot:0});else{const o=e.mode==="epsilon"?vT(i.start.x,e.epsilon):i.start.x;t.push({type:"set_state",x:o,v:i.start.v,project:!0})}return t.push({type:"set_time_scale",time_scale:i.time_scale}),t.push({type:"reset"}),t.push({type:i.paused?"pause":"resume"}),t}function xT(i,e){const t=i.length;if(t===0)return null;const n=i[0],s=i[t-1];if(e<n.t||e>s.t)return null;let r=0,a=t-1;for(;a-r>1;){const p=r+a>>1;i[p].t<=e?r=p:a=p}const o=i[r],l=i[a],c=l.t-o.t;if(!(c>0))return[o.x[0]+o.pivot[0],o.x[1]+o.pivot[1],o.x[2]+o.pivot[2]];const h=(e-o.t)/c,[d,u,m,_]=[2*h**3-3*h**2+1,h**3-2*h**2+h,-2*h**3+3*h**2,h**3-h**2],y=p=>d*o.x[p]+u*c*o.v[p]+m*l.x[p]+_*c*l.v[p]+(1-h)*o.pivot[p]+h*l.pivot[p];return[y(0),y(1),y(2)]}function lp(i,e){const t=[],n=[];for(const s of i){const r=xT(e,s.t);r!==null&&(t.push(s.t),n.push(Math.hypot(s.x[0]+s.pivot[0]-r[0],s.x[1]+s.pivot[1]-r[1],s.x[2]+s.pivot[2]-r[2])))}return{t,d:n}}function yT(i){const e=[];let t=[0,0,0];for(let n=1;n<i.length;n++){const s=_g(i[n-1],i[n]);t=[t[0]+s[0],t[1]+s[1],t[2]+s[2]],e.push(t)}return e}function Vr(i,e,t,n,s){const r=document.createElement("label");r.append(`${e} `);const a=document.createElement("input");return a.type="number",a.step=s,a.value=n,a.dataset.input=t,a.style.width="4.5em",r.appendChild(a),i.appendChild(r),a}class ST{constructor(e,t,n){this.socket=t,this.explain=n,this.list=document.createElement("div"),this.list.dataset.output="extras",this.add=document.createElement("button"),this.add.type="button",this.add.dataset.action="extra-add",this.add.textContent=R("extras.add"),this.add.addEventListener("click",()=>this.addRow());const s=document.createElement("section");s.className="tools",s.dataset.tool="extras";const r=document.createElement("h3");r.textContent=R("extras.title");const a=document.createElement("p");a.textContent=R("extras.hint"),s.append(r,a,this.list,this.add),e.appendChild(s)}socket;explain;extras=[];list;add;show(){this.add.hidden=this.extras.length>=Jo,this.extras.forEach((e,t)=>{const n=e.row.querySelector("button");n!==null&&(n.hidden=t!==this.extras.length-1)})}values(){return this.extras.map(e=>({length:Number(e.inputs.length.value),mass:Number(e.inputs.mass.value),theta:Number(e.inputs.theta.value)/tn}))}setRows(e){for(;this.extras.length>0;)this.removeLast();for(const t of e.slice(0,Jo)){const n=this.addRow();if(n===null)return;n.inputs.length.value=String(t.length),n.inputs.mass.value=String(t.mass),n.inputs.theta.value=String(Number((t.theta*tn).toPrecision(12)))}}addRow(){if(this.extras.length>=Jo)return null;const e=this.extras.length+3,t=document.createElement("p");t.dataset.extra=String(e),t.append(`${R("extras.pendulum",{n:e})}: `);const n={length:Vr(t,"l [m]",`extra-length-${e}`,"0.75","0.05"),mass:Vr(t,"m [kg]",`extra-mass-${e}`,"1","0.1"),theta:Vr(t,"θ₀ [°]",`extra-theta-${e}`,"10","1")},s=document.createElement("button");s.type="button",s.dataset.action=`extra-remove-${e}`,s.textContent="✕",s.title=R("extras.remove",{n:e}),s.setAttribute("aria-label",s.title),s.addEventListener("click",()=>this.removeLast()),t.appendChild(s),this.list.appendChild(t);const r={store:new Cu,row:t,inputs:n,conn:null,pending:[]};return this.extras.push(r),this.show(),r}removeLast(){const e=this.extras.pop();e!==void 0&&(e.conn?.close(),e.row.remove(),this.show())}start(e){const t=[];for(const n of this.extras){const s={mode:"own",epsilon:0,method:e.method,damping:0,length:Number(n.inputs.length.value),mass:Number(n.inputs.mass.value),theta:Number(n.inputs.theta.value)/tn};if(!(s.length>0&&s.mass>0&&s.theta>=0&&s.theta<=Math.PI))return this.explain(R("twin.badOwn")),!1;t.push(s)}return this.extras.forEach((n,s)=>{n.pending=vg(e,t[s]),n.conn===null?n.conn=this.connect(n):this.flush(n)}),!0}connect(e){return new Jh(this.socket,{onOpen:()=>this.flush(e),onClose:()=>e.store.setConnected(!1),onFrames:t=>e.store.onFrames(t),onNotice:t=>{t.type==="status"?e.store.onStatus(t):t.type==="event"?e.store.onEvent(t):this.explain(`${R("extras.pendulum",{n:e.row.dataset.extra??""})}: ${t.message}`)},onProtocolError:t=>this.explain(t)})}flush(e){if(!(e.conn===null||!e.conn.isOpen)){for(const t of e.pending)e.conn.send(t);e.pending=[]}}running(){return this.extras.filter(e=>e.conn!==null&&e.store.status!==null).map(e=>e.store)}stop(){for(const e of this.extras)e.conn?.close(),e.conn=null,e.store.clear(),e.store.status=null}mirror(e){if(!(e.type!=="pause"&&e.type!=="resume"&&e.type!=="reset"&&e.type!=="step"))for(const t of this.extras)t.conn?.send(e)}}function cp(i,e,t){if(e===null||i.frames.length===0)return null;const n=i.frames;i.playT=Math.min(Math.max(e,n[0].t),n[n.length-1].t);const{start:s,end:r}=i.trailRange(t);return{frame:i.displayed(),trail:{frames:i.trail,start:s,end:r}}}class MT{constructor(e,t,n,s,r){this.first=t,this.socket=s,this.actions=r;const a=document.createElement("section");a.className="tools",a.dataset.tool="twin";const o=document.createElement("h3");o.textContent=R("twin.title"),a.appendChild(o);const l=document.createElement("label");l.append(`${R("twin.mode")} `);const c=document.createElement("select");c.dataset.input="twin-mode";const h=[["off",R("twin.off")],["own",R("twin.own")],["epsilon",R("twin.epsilon")],["method",R("twin.method")],["damped",R("twin.damped")]];for(const[g,w]of h){const F=document.createElement("option");F.value=g,F.textContent=w,c.appendChild(F)}l.appendChild(c);const d=document.createElement("label");d.append("ε [°] ");const u=document.createElement("input");u.type="number",u.step="0.01",u.value="0.01",u.dataset.input="twin-epsilon",u.style.width="5em",d.appendChild(u);const m=document.createElement("label");m.append(`${R("twin.methodPick")} `);const _=document.createElement("select");_.dataset.input="twin-method";for(const g of n){const w=document.createElement("option");w.value=g.name,w.textContent=jo(g.name,g.order),_.appendChild(w)}_.value=n.some(g=>g.name==="rk4")?"rk4":n[0]?.name??"",m.appendChild(_);const y=document.createElement("label");y.append(`${R("twin.damping")} `);const p=document.createElement("input");p.type="number",p.step="0.1",p.min="0",p.value="0.5",p.dataset.input="twin-damping",p.style.width="5em",y.appendChild(p);const f=document.createElement("span"),x=Vr(f,R("twin.length"),"twin-length","0.5","0.05"),A=Vr(f,R("twin.mass"),"twin-mass","1","0.1"),M=Vr(f,R("twin.theta"),"twin-theta","10","1"),C=document.createElement("button");C.type="button",C.dataset.action="twin-start",C.textContent=R("twin.start");const b=()=>{d.hidden=c.value!=="epsilon",m.hidden=c.value!=="method",y.hidden=c.value!=="damped",f.hidden=c.value!=="own",C.hidden=c.value==="off"};c.addEventListener("change",()=>{b(),c.value==="off"&&this.stop()}),C.addEventListener("click",()=>{if(this.options.mode=c.value,this.options.epsilon=Number(u.value)/tn,this.options.method=_.value,this.options.damping=Number(p.value),this.options.length=Number(x.value),this.options.mass=Number(A.value),this.options.theta=Number(M.value)/tn,!Number.isFinite(this.options.epsilon)||!(this.options.damping>=0)){r.explain(R("twin.bad"));return}const g=this.options;if(g.mode==="own"&&!(g.length>0&&g.mass>0&&g.theta>=0&&g.theta<=Math.PI)){r.explain(R("twin.badOwn"));return}this.start()}),b(),this.setInputs=g=>{c.value=g.mode,u.value=String(g.epsilon*tn),_.value=g.method,p.value=String(g.damping),x.value=String(g.length),A.value=String(g.mass),M.value=String(g.theta*tn),b()},this.periods=document.createElement("table"),this.periods.dataset.readout="twin-periods",this.periods.hidden=!0,a.append(l," ",d,m,y,f," ",C,this.periods),e.appendChild(a),this.plot=new Pa(e,R("twin.separation"),"t [s]","|r₁ − r₂| [m]",140),this.plot.canvas.dataset.plot="separation",this.plot.canvas.parentElement?.setAttribute("hidden",""),this.visibility.watch(this.plot.canvas)}first;socket;actions;store=new Cu;options={mode:"off",epsilon:.01/tn,method:"rk4",damping:.5,length:.5,mass:1,theta:10/tn};periods;setInputs;conn=null;pending=[];plot;visibility=new Ml;extras=null;get on(){return this.conn!==null}layout(){const[e,t]=[this.first.status,this.store.status];return this.conn===null||this.options.mode!=="own"||e===null||t===null?null:{offset:_g(e.params.length,t.params.length),length:t.params.length}}extraLayouts(){const e=this.first.status,t=this.store.status,n=this.extras?.running()??[];if(this.layout()===null||e===null||t===null||n.length===0)return[];const s=n.map(a=>a.status.params.length),r=yT([e.params.length,t.params.length,...s]);return s.map((a,o)=>({offset:r[o+1],length:a}))}drawnExtras(e,t){return this.conn===null||this.options.mode!=="own"?[]:(this.extras?.running()??[]).map(n=>cp(n,e,t)??{frame:null,trail:{frames:[],start:0,end:0}})}restore(e){Object.assign(this.options,e),this.setInputs(e),this.extras?.setRows(e.extras??[]),e.mode!=="off"&&this.start()}start(){const e=this.first.status;if(e===null)return this.actions.explain(R("msg.notConnected"));this.pending=vg(e,this.options),this.options.mode==="own"&&this.extras!==null?(this.extras.start(e),this.options.extras=this.extras.values()):(this.extras?.stop(),delete this.options.extras),this.conn===null?this.conn=new Jh(this.socket,{onOpen:()=>this.flush(),onClose:()=>this.store.setConnected(!1),onFrames:t=>this.store.onFrames(t),onNotice:t=>{t.type==="status"?this.store.onStatus(t):t.type==="event"?this.store.onEvent(t):this.actions.explain(`${R("twin.second")}: ${t.message}`)},onProtocolError:t=>this.actions.explain(`${R("twin.second")}: ${t}`)}):this.flush(),this.actions.send({type:"reset"}),this.plot.canvas.parentElement?.removeAttribute("hidden"),this.periods.hidden=!1}flush(){if(!(this.conn===null||!this.conn.isOpen)){for(const e of this.pending)this.conn.send(e);this.pending=[]}}stop(){this.extras?.stop(),this.conn?.close(),this.conn=null,this.store.clear(),this.store.status=null,this.plot.canvas.parentElement?.setAttribute("hidden",""),this.periods.hidden=!0}mirror(e){this.conn!==null&&(this.extras?.mirror(e),(e.type==="pause"||e.type==="resume"||e.type==="reset"||e.type==="step")&&this.conn.send(e))}drawn(e,t){return this.conn===null?null:cp(this.store,e,t)}update(e){if(this.conn!==null&&this.fillPeriods(),this.conn===null||!this.visibility.visible(this.plot.canvas))return;const t=lp(this.first.history.frames,this.store.trajectory);this.plot.draw(e,[{x:t.t,y:t.d,color:"#c8f560",label:R("twin.separation")}],Ks(t.t,.02),Ks([0,...t.d]))}fillPeriods(){const e=(n,s)=>{const r=s.status,a=s.periodTimer.reading(),o=r===null?null:Math.atan2(Math.hypot(r.start.x[0],r.start.x[1]),-r.start.x[2])*tn;return[n,r===null?"—":r.params.length.toPrecision(3),r===null?"—":r.params.mass.toPrecision(3),o===null?"—":o.toFixed(1),a.period===null?"—":`${a.period.toFixed(4)} (${a.intervals})`]},t=[["",R("twin.colLength"),R("twin.colMass"),R("twin.colTheta"),R("twin.colPeriod")],e(R("twin.first"),this.first),e(R("twin.second"),this.store),...(this.extras?.running()??[]).map((n,s)=>e(R("extras.pendulum",{n:s+3}),n))];for(;this.periods.rows.length>t.length;)this.periods.deleteRow(-1);t.forEach((n,s)=>{const r=this.periods.rows[s]??this.periods.insertRow();for(;r.cells.length<n.length;)r.insertCell();n.forEach((a,o)=>{const l=r.cells[o];l&&l.textContent!==a&&(l.textContent=a)})})}separationNow(){return lp(this.first.history.frames,this.store.trajectory)}}const bT=[["gloss.period","gloss.periodText"],["gloss.amplitude","gloss.amplitudeText"],["gloss.lowest","gloss.lowestText"],["gloss.friction","gloss.frictionText"],["gloss.gravity","gloss.gravityText"],["gloss.energy","gloss.energyText"],["gloss.spin","gloss.spinText"],["gloss.precession","gloss.precessionText"],["gloss.method","gloss.methodText"],["gloss.drift","gloss.driftText"]];class wT{constructor(e){const t=document.createElement("section");t.className="tools glossary",t.dataset.tool="glossary";const n=document.createElement("h3");n.textContent=R("gloss.title"),t.appendChild(n);for(const[a,o]of bT){const l=document.createElement("details"),c=document.createElement("summary");c.textContent=R(a);const h=document.createElement("p");h.textContent=R(o),l.append(c,h),t.appendChild(l)}const s=document.createElement("label"),r=document.createElement("input");r.type="checkbox",r.dataset.input="advanced",r.checked=Ho(),r.addEventListener("change",()=>p0(r.checked)),s.append(r,` ${R("gloss.advanced")}`),t.appendChild(s),e.appendChild(t)}}function ET(i,e){if(e)return null;switch(i){case" ":case"Spacebar":return"run";case"r":case"R":return"reset";case"s":case"S":return"step";case"?":return"help";case"Escape":return"close";default:return null}}function TT(i){switch(i){case"ArrowUp":case"ArrowRight":return 1;case"ArrowDown":case"ArrowLeft":return-1;case"PageUp":return 10;case"PageDown":return-10;case"Home":return-1/0;case"End":return 1/0;default:return null}}function hp(i,e=""){return typeof HTMLElement>"u"||!(i instanceof HTMLElement)?!1:e===" "&&(i instanceof HTMLButtonElement||i instanceof HTMLInputElement&&["checkbox","radio","button"].includes(i.type))||i.isContentEditable||i instanceof HTMLSelectElement||i instanceof HTMLTextAreaElement?!0:i instanceof HTMLInputElement?!["checkbox","radio","button"].includes(i.type):i.getAttribute("role")==="slider"}function xg(i){for(const e of i.controllersRecursive()){const t=e.$slider;t!==void 0&&(t.setAttribute("aria-valuenow",String(e.getValue())),t.dataset.keys!=="1"&&(t.dataset.keys="1",t.tabIndex=0,t.setAttribute("role","slider"),t.setAttribute("aria-label",e.$name.textContent??""),e._min!==void 0&&t.setAttribute("aria-valuemin",String(e._min)),e._max!==void 0&&t.setAttribute("aria-valuemax",String(e._max)),t.addEventListener("keydown",n=>{const s=TT(n.key);if(s===null)return;n.preventDefault(),n.stopPropagation();const[r,a,o]=[e._min??-1/0,e._max??1/0,e._step??.01],l=Number(e.getValue()),c=s===1/0?a:s===-1/0?r:Math.min(a,Math.max(r,l+s*o));Number.isFinite(c)&&e.setValue(+c.toPrecision(12)),t.setAttribute("aria-valuenow",String(e.getValue()))})))}}function AT(i,e){const t=5*Math.PI/180;if(e&&i==="ArrowLeft")return{bob:-1};if(e&&i==="ArrowRight")return{bob:1};switch(i){case"ArrowLeft":return{orbit:[-t,0],zoom:1};case"ArrowRight":return{orbit:[t,0],zoom:1};case"ArrowUp":return{orbit:[0,t],zoom:1};case"ArrowDown":return{orbit:[0,-t],zoom:1};case"+":case"=":return{orbit:[0,0],zoom:1/1.1};case"-":return{orbit:[0,0],zoom:1.1};default:return null}}function Tt(i){const e=document.getElementById(i);if(e===null)throw new Error(`#${i} missing from index.html`);return e}function yg(i,e){const t=document.createElement("a");t.href=e,t.download=i,document.body.appendChild(t),t.click(),t.remove()}function Du(i,e){const t=URL.createObjectURL(e);yg(i,t),setTimeout(()=>URL.revokeObjectURL(t),1e4)}function RT(){const i=t0(new URLSearchParams(window.location.search).get("lang"),window.localStorage?.getItem("pendulab.lang")??null,navigator.languages??[navigator.language]);n0(i),document.documentElement.lang=i,f0(),document.title=R("page.title"),Tt("page-title").textContent=R("page.title"),Tt("units").textContent=R("page.units"),Tt("scene").setAttribute("aria-label",R("page.scene")),Tt("panel").setAttribute("aria-label",R("page.panel")),Tt("panel-title").textContent=R("page.panel");const e={tools:"page.tools",energy:"page.energy",data:"page.data",plots:"page.plots",portraits:"page.portraits",reduced:"page.reduced"};for(const[t,n]of Object.entries(e))Tt(t).setAttribute("aria-label",R(n))}class CT{constructor(e){this.el=e}el;timer=null;explain=(e,t=!1)=>{this.el.textContent=e,this.el.classList.toggle("info",t),this.el.classList.add("shown"),this.timer!==null&&clearTimeout(this.timer),this.timer=setTimeout(()=>this.el.classList.remove("shown"),6e3)};clearNews(){this.el.classList.contains("info")&&this.el.classList.remove("shown")}}const Ia=180/Math.PI;function PT(i,e){const t={};for(const[n,s]of Object.entries(i))n in e&&e[n]!==s&&(t[n]=s);return t}function Sg(i){const e=t=>Fn(Number((t*Ia).toPrecision(12)));return i.mode==="own"?[`own:${Fn(i.length)}:${Fn(i.mass)}:${e(i.theta)}`,...(i.extras??[]).map(t=>`${Fn(t.length)}:${Fn(t.mass)}:${e(t.theta)}`)].join(","):i.mode==="epsilon"?`eps:${e(i.epsilon)}`:i.mode==="method"?`method:${i.method}`:i.mode==="damped"?`damped:${Fn(i.damping)}`:null}function Fn(i){return Object.is(i,-0)?"-0":String(i)}function LT(i){const e=new URLSearchParams;i.scenario!==void 0&&e.set("s",i.scenario),i.model!==void 0&&e.set("model",i.model),i.modelParams!==void 0&&Object.keys(i.modelParams).length>0&&e.set("mp",Object.entries(i.modelParams).map(([n,s])=>`${n}:${Fn(s)}`).join(",")),i.length!==void 0&&e.set("l",Fn(i.length)),i.mass!==void 0&&e.set("m",Fn(i.mass)),i.g!==void 0&&e.set("g",Fn(i.g)),i.method!==void 0&&e.set("method",i.method),i.dt!==void 0&&e.set("dt",Fn(i.dt)),i.timeScale!==void 0&&e.set("ts",Fn(i.timeScale)),i.x!==void 0&&e.set("x",i.x.map(Fn).join(",")),i.v!==void 0&&e.set("v",i.v.map(Fn).join(",")),i.paused===!0&&e.set("paused","1"),i.at!==void 0&&i.at>0&&e.set("at",Fn(i.at)),i.view!==void 0&&Object.keys(i.view).length>0&&e.set("view",Object.entries(i.view).map(([n,s])=>typeof s=="boolean"?s?n:`-${n}`:`${n}:${typeof s=="number"?Fn(s):s}`).join(",")),i.plot!==void 0&&e.set("plot",i.plot.join(","));const t=i.twin===void 0?null:Sg(i.twin);return t!==null&&e.set("twin",t),i.lang!==void 0&&e.set("lang",i.lang),e.toString()}const Mg=/^[A-Za-z0-9_.-]{1,100}$/;function Or(i){if(!/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(i.trim()))return null;const e=Number(i);return Number.isFinite(e)?e:null}function DT(i){const e=new URLSearchParams(i.startsWith("?")?i.slice(1):i),t={},n=[],s=new Set(["s","model","mp","l","m","g","method","dt","ts","x","v","paused","lang","at","view","plot","twin"]);for(const F of e.keys())s.has(F)||n.push(`unknown URL key ${F}`);const r=F=>{const L=e.get(F);if(L!==null){if(!Mg.test(L)){n.push(`${F} = ${JSON.stringify(L)} is not a name`);return}return L}},a=F=>{const L=e.get(F);if(L===null)return;const D=Or(L);return D===null&&n.push(`${F} = ${JSON.stringify(L)} is not a finite number`),D??void 0},o=F=>{const L=e.get(F);if(L===null)return;const D=L.split(",").map(Or);if(D.length!==3||D.some(z=>z===null)){n.push(`${F} = ${JSON.stringify(L)} is not three finite numbers`);return}return D},l=r("s");l!==void 0&&(t.scenario=l);const c=r("model");c!==void 0&&(t.model=c);const h=e.get("mp");if(h!==null){const F={};for(const L of h.split(",")){const[D,z,...V]=L.split(":"),U=z===void 0?null:Or(z);if(D===void 0||!/^[A-Za-z_][A-Za-z0-9_]{0,40}$/.test(D)||U===null||V.length>0){n.push(`mp: ${JSON.stringify(L)} is not name:number`);continue}F[D]=U}Object.keys(F).length>0&&(t.modelParams=F)}const d=a("l");d!==void 0&&(t.length=d);const u=a("m");u!==void 0&&(t.mass=u);const m=a("g");m!==void 0&&(t.g=m);const _=r("method");_!==void 0&&(t.method=_);const y=a("dt");y!==void 0&&(t.dt=y);const p=a("ts");p!==void 0&&(t.timeScale=p);const f=o("x"),x=o("v");f===void 0!=(x===void 0)&&n.length===0?n.push("the start needs both x and v"):f!==void 0&&x!==void 0&&(t.x=f,t.v=x);const A=e.get("paused");A!==null&&(t.paused=A==="1"||A==="true");const M=e.get("lang");M!==null&&/^[a-z]{2}$/.test(M)&&(t.lang=M);const C=a("at");C!==void 0&&(C>=0&&C<=1e6?t.at=C:n.push(`at = ${C} is not a time 0 … 1e6 s`));const b=e.get("view");if(b!==null){const F={};for(const L of b.split(",").filter(Boolean)){const D=/^(-?)([A-Za-z]{1,30})(?::([A-Za-z0-9 .+-]{1,30}))?$/.exec(L);if(D===null){n.push(`view: ${JSON.stringify(L)} is not a view option`);continue}const[,z,V,U]=D;U===void 0?F[V]=z!=="-":F[V]=Or(U)??U}t.view=F}const g=e.get("plot");if(g!==null){const F=g.split(",");F.length===2&&F.every(L=>/^[a-z0-9_]{1,20}$/i.test(L))?t.plot=[F[0],F[1]]:n.push(`plot = ${JSON.stringify(g)} is not two variable names`)}const w=e.get("twin");if(w!==null){const F=IT(w);F===null?n.push(`twin = ${JSON.stringify(w)} is not own:l:m:θ₀, eps:ε, method:name or damped:c`):t.twin=F}return{value:t,problems:n}}function NT(i){const e=i.map(Or);if(e.length!==3||e.some(r=>r===null))return null;const[t,n,s]=e;return t>0&&n>0&&s>=0&&s<=180?{length:t,mass:n,theta:s/Ia}:null}function IT(i){const e={mode:"off",epsilon:.01/Ia,method:"rk4",damping:.5,length:.5,mass:1,theta:10/Ia},[t="",...n]=i.split(","),[s,...r]=t.split(":"),a=r.map(Or);if(s==="own"){const o=[r,...n.map(h=>h.split(":"))].map(NT);if(o.length>1+Jo||o.some(h=>h===null))return null;const[l,...c]=o;return{...e,mode:"own",...l,...c.length>0?{extras:c}:{}}}return n.length>0?null:s==="eps"&&a.length===1&&a[0]!==null?{...e,mode:"epsilon",epsilon:a[0]/Ia}:s==="damped"&&a.length===1&&(a[0]??-1)>=0?{...e,mode:"damped",damping:a[0]}:s==="method"&&r.length===1&&Mg.test(r[0])?{...e,mode:"method",method:r[0]}:null}function up(i){const e={model:i.model,length:i.params.length,mass:i.params.mass,g:i.params.g,method:i.method,dt:i.dt,timeScale:i.time_scale,x:i.start.x,v:i.start.v};return i.scenario!==null&&(e.scenario=i.scenario),Object.keys(i.model_params).length>0&&(e.modelParams={...i.model_params}),i.paused&&(e.paused=!0),i.paused&&!i.adaptive&&i.t>i.t0&&(e.at=i.t-i.t0),e}function Xh(i){const e=[];i.scenario!==void 0&&e.push({type:"load_scenario",name:i.scenario}),i.model!==void 0&&e.push({type:"set_model",model:i.model,params:{...i.modelParams}});const t={type:"set_params"};i.length!==void 0&&(t.length=i.length),i.mass!==void 0&&(t.mass=i.mass),i.g!==void 0&&(t.g=i.g),Object.keys(t).length>1&&e.push(t);const n={type:"set_method"};if(i.method!==void 0&&(n.method=i.method),i.dt!==void 0&&(n.dt=i.dt),Object.keys(n).length>1&&e.push(n),i.timeScale!==void 0&&e.push({type:"set_time_scale",time_scale:i.timeScale}),i.x!==void 0&&i.v!==void 0&&e.push({type:"set_state",x:i.x,v:i.v}),e.length>0&&e.push({type:"reset"}),i.paused===!0&&e.push({type:"pause"}),i.paused===!0&&i.at!==void 0&&i.at>0&&i.dt!==void 0&&i.dt>0){let s=Math.round(i.at/i.dt);for(s>1e7&&(s=0);s>0;){const r=Math.min(s,1e5);e.push({type:"step",n:r}),s-=r}}return e}function UT(i){const e=[R("link.scenario")];i.paused===!0&&e.push(i.at!==void 0&&i.at>0?R("link.pausedAt",{t:i.at.toFixed(3)}):R("link.paused"));const t=Object.entries(i.view??{}).map(([s,r])=>typeof r=="boolean"?r?s:`−${s}`:`${s} ${r}`);t.length>0&&e.push(R("link.view",{list:t.join(", ")})),i.plot!==void 0&&e.push(R("link.plot",{x:i.plot[0],y:i.plot[1]}));const n=i.twin===void 0?null:Sg(i.twin);return n!==null&&e.push(R("link.twin",{what:n})),i.lang!==void 0&&e.push(R("link.lang",{lang:i.lang})),e.join("; ")}function FT(i,e){const t=[];for(const[n,s]of Object.entries(e)){const r=Pu[n];r!==void 0&&typeof r==typeof s&&(n!=="stereo"||pg.includes(s))?i[n]=s:t.push(`view: ${n} = ${String(s)} is not a view option`)}return t}class OT{constructor(e,t,n){this.store=e,this.view=t;const s=DT(window.location.search);this.value=s.value,s.problems.push(...FT(t,s.value.view??{})),s.problems.length>0&&n(`link: ${s.problems.join("; ")}`),this.startup=Xh(s.value),s.value.twin!==void 0&&(this.replay=this.startup.filter(r=>r.type==="step"),this.startup=this.startup.filter(r=>r.type!=="step")),this.twinToRestore=s.value.twin??null}store;view;value;startup;replay=[];twinToRestore;chosen=null;twin=null;attach(e,t){this.chosen=e,this.twin=t,this.value.plot&&e.choose(...this.value.plot)}takeStartup(){const e=this.startup;return this.startup=[],e}restoreShown(){this.store.status!==null&&(this.startup=Xh(up(this.store.status)))}lab(){const e=this.store.status,t=e===null?{}:up(e);t.view=PT(this.view,Pu);const n=this.chosen?.choice;return n!==void 0&&(n.x!=="t"||n.y!=="theta")&&(t.plot=[n.x,n.y]),this.twin?.on&&this.twin.options.mode!=="off"&&(t.twin={...this.twin.options}),t.lang=fl(),t}write(){if(this.startup.length>0||this.store.status===null)return;const e=`?${LT(this.lab())}`;e!==window.location.search&&window.history.replaceState(null,"",e)}}class kT{constructor(e,t){this.store=e,this.explain=t}store;explain;conn=null;twin=null;send=e=>{this.conn===null||!this.conn.send(e)?this.explain(R("msg.notConnected")):this.twin?.mirror(e)};run=()=>this.send({type:this.store.status?.paused===!1?"pause":"resume"});reset=()=>this.send({type:"reset"});step=()=>this.send({type:"step",n:1});sent(){return this.conn?.sent??0}}const BT=i=>`#${i.toString(16).padStart(6,"0")}`,zT={velocity:"vec.velocity",momentum:"vec.momentum",gravity:"vec.gravity",tension:"vec.tension",net:"vec.net",angularMomentum:"vec.angularMomentum",torque:"vec.torque"};class HT{constructor(e){this.el=e,e.setAttribute("aria-label",R("help.title"));const t=document.createElement("div");t.className="help-box";const n=document.createElement("h2");n.textContent=R("help.title");const s=document.createElement("table"),r=[[R("key.space"),"help.space"],["R","help.r"],["S","help.s"],["← → ↑ ↓","help.arrows"],[R("key.page"),"help.page"],["← → ↑ ↓ / + −","help.camera"],[`${R("key.shift")} + ← →`,"help.bobKeys"],["D","help.describe"],["Tab","help.tab"],["?","help.help"],["Esc","help.esc"]];for(const[h,d]of r){const u=s.insertRow(),m=u.insertCell(),_=document.createElement("kbd");_.textContent=h,m.appendChild(_),u.insertCell().textContent=R(d)}const a=document.createElement("h3");a.textContent=R("help.colours");const o=document.createElement("ul");o.className="colour-key";const l=[["#ff8c42",R("help.bob")],["#59c3ff",R("help.trail")],["#c8f560",R("help.twin")],...Object.entries(zT).map(([h,d])=>[BT(Lu[h]),R(d)]),["#e6d3a3",R("help.ruler")]];for(const[h,d]of l){const u=document.createElement("li"),m=document.createElement("span");m.className="swatch",m.style.background=h,u.append(m,` ${d}`),o.appendChild(u)}const c=document.createElement("button");c.type="button",c.dataset.action="help-close",c.textContent=R("help.close"),c.addEventListener("click",()=>this.toggle(!1)),t.append(n,s,a,o,c),e.appendChild(t),e.addEventListener("click",h=>h.target===e&&this.toggle(!1)),e.addEventListener("keydown",h=>{if(h.key!=="Tab")return;const d=[...e.querySelectorAll('button, [href], input, select, [tabindex]:not([tabindex="-1"])')],u=d[0],m=d[d.length-1];u===void 0||m===void 0||(h.shiftKey&&document.activeElement===u?(h.preventDefault(),m.focus()):!h.shiftKey&&document.activeElement===m&&(h.preventDefault(),u.focus()))}),document.addEventListener("focusin",h=>{this.open&&h.target instanceof Node&&!e.contains(h.target)&&this.el.querySelector("button")?.focus()})}el;returnFocus=null;get open(){return!this.el.hidden}toggle(e=!this.open){e!==this.open&&(e?(this.returnFocus=document.activeElement instanceof HTMLElement?document.activeElement:null,this.el.hidden=!1,this.el.querySelector("button")?.focus()):(this.el.hidden=!0,this.returnFocus?.focus()))}}const dp="(max-width: 700px), (max-aspect-ratio: 3/4)";function Es(i,e,t,n=!1){const s=document.createElement("button");return s.type="button",s.dataset.action=i,s.textContent=e,s.title=t,s.setAttribute("aria-label",t),n&&s.classList.add("when-open"),s}class GT{constructor(e,t,n){this.panel=t,e.setAttribute("aria-label",R("toolbar.label")),this.toggle=Es("panel","",R("toolbar.collapse")),this.toggle.setAttribute("aria-controls","panel-body"),this.toggle.addEventListener("click",()=>{this.setCollapsed(!t.classList.contains("collapsed")),n.collapsed(t.classList.contains("collapsed"))}),this.runButton=Es("run",R("toolbar.pauseShort"),R("toolbar.pause")),this.runButton.addEventListener("click",()=>n.run());const s=Es("reset",R("toolbar.resetShort"),R("toolbar.reset"));s.addEventListener("click",()=>n.reset());const r=Es("step",R("toolbar.stepShort"),R("toolbar.step"));r.addEventListener("click",()=>n.step()),this.recordButton=Es("record",R("toolbar.recordShort"),R("toolbar.record")),this.recordButton.setAttribute("aria-pressed","false"),this.recordButton.addEventListener("click",()=>n.record());const a=Es("help","?",R("toolbar.help"));a.addEventListener("click",()=>n.help()),this.presentButton=Es("present","A⁺",R("toolbar.present"),!0),this.presentButton.setAttribute("aria-pressed","false"),this.presentButton.addEventListener("click",()=>n.present(this.presentButton.getAttribute("aria-pressed")!=="true")),this.simpleButton=Es("simple",R("toolbar.simpleShort"),R("toolbar.simple"),!0),this.simpleButton.setAttribute("aria-pressed","false"),this.simpleButton.addEventListener("click",()=>n.simple(this.simpleButton.getAttribute("aria-pressed")!=="true"));const o=document.createElement("select");o.dataset.input="language",o.classList.add("when-open"),o.setAttribute("aria-label",R("toolbar.language"));for(const[l,c]of Object.entries(Xa)){const h=document.createElement("option");h.value=l,h.textContent=c.name,o.appendChild(h)}o.value=fl(),o.addEventListener("change",()=>n.language(o.value)),e.append(this.toggle,this.runButton,s,r,this.recordButton,a,this.simpleButton,this.presentButton,o),this.setCollapsed(!1),window.matchMedia(dp).addEventListener("change",()=>this.setCollapsed(t.classList.contains("collapsed")))}panel;runButton;recordButton;toggle;presentButton;simpleButton;showPresenting(e){this.presentButton.setAttribute("aria-pressed",String(e))}showSimple(e){this.simpleButton.setAttribute("aria-pressed",String(e))}setCollapsed(e){this.panel.classList.toggle("collapsed",e),this.toggle.setAttribute("aria-expanded",String(!e));const t=window.matchMedia(dp).matches;this.toggle.textContent=t?e?"▴":"▾":e?"◂":"▸",this.toggle.title=R(e?"toolbar.expand":"toolbar.collapse"),this.toggle.setAttribute("aria-label",this.toggle.title)}showRunning(e){const t=R(e?"toolbar.startShort":"toolbar.pauseShort");this.runButton.textContent!==t&&(this.runButton.textContent=t,this.runButton.title=R(e?"toolbar.start":"toolbar.pause"),this.runButton.setAttribute("aria-label",this.runButton.title))}showRecording(e){this.recordButton.setAttribute("aria-pressed",String(e)),this.recordButton.textContent=R(e?"toolbar.recordStopShort":"toolbar.recordShort"),this.recordButton.title=R(e?"toolbar.recordStop":"toolbar.record")}}const VT=300,WT=25e5;function XT(i){for(const e of["video/webm;codecs=vp9","video/webm;codecs=vp8","video/webm"])if(i(e))return e;return null}class $T{constructor(e,t){this.canvas=e,this.done=t}canvas;done;recorder=null;chunks=[];timer=null;get recording(){return this.recorder!==null}start(){if(this.recorder!==null)return null;if(typeof MediaRecorder>"u"||typeof this.canvas.captureStream!="function")return"no MediaRecorder";const e=XT(s=>MediaRecorder.isTypeSupported(s));if(e===null)return"no WebM";const t=this.canvas.captureStream(30),n=new MediaRecorder(t,{mimeType:e,videoBitsPerSecond:WT});return this.chunks=[],n.ondataavailable=s=>{s.data.size>0&&this.chunks.push(s.data)},n.onstop=()=>{for(const s of t.getTracks())s.stop();this.done(new Blob(this.chunks,{type:"video/webm"})),this.chunks=[]},n.start(1e3),this.recorder=n,this.timer=setTimeout(()=>this.stop(),VT*1e3),null}stop(){this.timer!==null&&clearTimeout(this.timer),this.timer=null;const e=this.recorder;this.recorder=null,e!==null&&e.state!=="inactive"&&e.stop()}}function qT(i,e){window.localStorage?.setItem("pendulab.lang",e);const t=Fc(()=>i.store.status?.commands,()=>i.session.sent(),2e3);Promise.all([t,Tv(2e3)]).then(()=>{const n=new URLSearchParams(window.location.search);n.set("lang",e),window.location.search=n.toString()})}function YT(i){const{store:e,scene:t,view:n,session:s,explain:r}=i;let a=null;const o=new $T(t.renderer.domElement,h=>{h.slice(0,4).arrayBuffer().then(d=>{a={size:h.size,head:[...new Uint8Array(d)].map(u=>u.toString(16).padStart(2,"0")).join("")}}),Du(`pendulab-${e.status?.scenario??"lab"}.webm`,h),r(R("msg.recorded",{mb:(h.size/1e6).toFixed(1)}),!0)}),l=new HT(Tt("help")),c=new GT(Tt("toolbar"),Tt("panel"),{run:s.run,reset:s.reset,step:s.step,record:()=>{if(o.recording)o.stop();else{const h=o.start();r(h!==null?R("msg.noRecording",{why:h}):R("msg.recording"),h===null)}c.showRecording(o.recording)},help:()=>l.toggle(),language:h=>qT(i,h),collapsed:()=>{},present:h=>{n.present=h,document.body.classList.toggle("present",h),c.showPresenting(h)},simple:h=>{n.simple=h,document.body.classList.toggle("simple",h),c.showSimple(h)}});return document.body.classList.toggle("present",n.present),c.showPresenting(n.present),document.body.classList.toggle("simple",n.simple),c.showSimple(n.simple),{toolbar:c,help:l,lastVideo:()=>a}}function bg(i,e,t=1e-6){if(i===null)return R("describe.none");const n=Ha(i.x).theta*tn,s=Math.hypot(...i.v),r=i.v[2],a=s<t?R("describe.rest"):Math.abs(r)<.001*s?R("describe.turning"):r>0?R("describe.rising"):R("describe.falling");let o=R("describe.text",{theta:n.toFixed(0),dir:a,v:s.toFixed(2)});if(e!==null){const l=Math.abs(e.kinetic)+Math.abs(e.potential)+Math.abs(e.lost);if(l>0){const c=h=>Math.round(100*h/l);o+=R("describe.energy",{k:c(e.kinetic),u:c(e.potential)}),Math.abs(e.lost)>.005*l&&(o+=R("describe.lost",{p:c(e.lost)}))}}return o}function KT(i){const{scene:e,store:t,session:n,explain:s}=i,r=e.renderer.domElement;r.tabIndex=0,r.setAttribute("aria-label",`${R("page.scene")}. ${R("help.camera")}; ${R("key.shift")} + ← →: ${R("help.bobKeys")}`),r.addEventListener("keydown",a=>{const o=AT(a.key,a.shiftKey);if(o===null||a.ctrlKey||a.metaKey||a.altKey)return;if(a.preventDefault(),"orbit"in o){e.orbitBy(o.orbit[0],o.orbit[1],o.zoom);return}const l=t.status;if(l===null)return;l.paused||n.send({type:"pause"});const c=Ha(l.start.x),h=Math.min(Math.max(c.theta+o.bob/tn,0),Math.PI);n.send({type:"set_state",theta:h,phi:c.phi,theta_dot:0,phi_dot:0}),s(R("describe.text",{theta:(h*tn).toFixed(0),dir:R("describe.rest"),v:"0.00"}),!0)})}function ZT(i,e){const{store:t}=i,n=t.latest(),s=t.status?.params,r=n?fg(n,s?.mass??1,s?.g??9.81,s?.length??1,t.work):null;e.describe(bg(t.displayed(),r),performance.now(),!0)}function JT(i,e,t){KT(i);const{session:n}=i;document.addEventListener("keydown",s=>{const r=!s.ctrlKey&&!s.metaKey&&!s.altKey;if((s.key==="d"||s.key==="D")&&r&&!hp(s.target,s.key)&&!e.open){ZT(i,t);return}const a=ET(s.key,!r);if(a!==null){if(a==="close"){e.open&&e.toggle(!1);return}hp(s.target,s.key)||e.open&&a!=="help"||(s.preventDefault(),a==="run"?n.run():a==="reset"?n.reset():a==="step"?n.step():e.toggle())}})}const $h=[["gravity.earth",9.81],["gravity.moon",1.62],["gravity.mars",3.71],["gravity.jupiter",24.79],["gravity.zero",0],["gravity.negative",-9.81]];function jT(i,e){return i===null?null:"damping"in(i.model_params??{})?{type:"set_params",params:{damping:e}}:i.model==="ideal"&&e>0?{type:"set_model",model:"damped",params:{damping:e}}:null}function QT(i,e,t){for(const[n,s]of[["θ₀",i],["φ₀",e],["φ̇₀",t]])if(!Number.isFinite(s))return R("start.notNumber",{name:n});return i<0||i>180?R("start.thetaRange",{value:i}):{type:"set_state",theta:i/tn,phi:e/tn,theta_dot:0,phi_dot:t/tn}}function eA(i){let e=Math.round((2+18*i)*100)/100;for(const[,t]of $h)Math.abs(e-t)<.3&&(e=Math.round((e+.6)*100)/100);return e}function tA(i){return Math.min(1760,440*2**(Math.max(0,i)/2))}function bt(i,e={},t=""){const n=document.createElement(i);for(const[s,r]of Object.entries(e))n.setAttribute(s,r);return t&&(n.textContent=t),n}function Nr(i,e,t){const n=bt("section",{class:"tools","data-tool":t});return n.appendChild(bt("h3",{},e)),i.appendChild(n),n}function Nc(i,e,t,n){const s=bt("label");s.append(`${i} `);const r=bt("input",{type:"number",step:n,name:e,"data-input":e});return r.value=String(t),r.style.width="5.5em",s.appendChild(r),[s,r]}class nA{constructor(e,t,n){this.store=t;const s=()=>this.now=t.playT??this.now,r=Nr(e,R("tools.start"),"start"),[a,o]=Nc("θ₀ [°]","theta0",30,"1"),[l,c]=Nc("φ₀ [°]","phi0",0,"1"),[h,d]=Nc("φ̇₀ [°/s]","phidot0",0,"10");o.title=R("tools.thetaHelp"),c.title=R("tools.phiHelp"),d.title=R("tools.phiDotHelp");const u=bt("button",{type:"button","data-action":"set-start"},R("tools.setStart")),m=()=>{const L=QT(Number(o.value),Number(c.value),Number(d.value));typeof L=="string"?n.explain(L):n.send(L)};u.addEventListener("click",m);for(const L of[o,c,d])L.addEventListener("keydown",D=>D.key==="Enter"&&m());r.append(a,l,h,u);const _=Nr(e,R("tools.world"),"world"),y=bt("label");y.append(`${R("tools.gravity")} `),this.gravity=bt("select",{"data-input":"gravity-preset"}),this.gravity.appendChild(bt("option",{value:""},R("gravity.custom")));for(const[L,D]of $h)this.gravity.appendChild(bt("option",{value:String(D)},`${R(L)} (${D} m/s²)`));this.gravity.appendChild(bt("option",{value:"mystery"},R("tools.mystery")));const p=bt("button",{type:"button","data-action":"reveal-g",hidden:""},R("tools.reveal"));this.reveal=p,this.gravity.addEventListener("change",()=>{this.gravity.value==="mystery"?(this.mysteryG=eA(Math.random()),document.body.classList.add("mystery"),p.hidden=!1,n.send({type:"set_params",g:this.mysteryG}),n.explain(R("tools.mysteryOn"),!0)):this.gravity.value!==""&&n.send({type:"set_params",g:Number(this.gravity.value)})}),p.addEventListener("click",()=>{n.explain(R("tools.revealed",{g:this.mysteryG??"?"}),!0),this.endMystery()}),y.append(this.gravity," ",p);const f=bt("label");f.append(`${R("tools.friction")} `),this.friction=bt("input",{type:"range",min:"0",max:"2",step:"0.01","data-input":"friction"}),this.friction.value="0",this.friction.title=R("tools.frictionHelp"),this.frictionValue=bt("output"),this.friction.addEventListener("input",()=>{this.frictionValue.textContent=`${Number(this.friction.value).toFixed(2)} 1/s`}),this.friction.addEventListener("change",()=>{const L=jT(t.status,Number(this.friction.value));L!==null?n.send(L):Number(this.friction.value)>0&&n.explain(R("tools.noFriction",{model:t.status?.model??"?"}))}),f.append(this.friction," ",this.frictionValue),_.append(y,f);const x=Nr(e,R("tools.now"),"angles");this.angleText=bt("div",{class:"big","data-readout":"angles","aria-live":"off"}),this.description=bt("p",{class:"describe","data-readout":"describe","aria-live":"off","aria-atomic":"true"});const A=bt("label");this.describeLive=bt("input",{type:"checkbox","data-input":"describe"}),A.append(this.describeLive,` ${R("describe.toggle")}`);const M=bt("label");this.sound=bt("input",{type:"checkbox","data-input":"sound"}),M.append(this.sound,` ${R("tools.sound")}`),x.append(this.angleText,this.description,A,M);const C=Nr(e,R("tools.stopwatch"),"stopwatch");this.watchText=bt("div",{class:"big","data-readout":"stopwatch"},"0.000 s"),this.watchButton=bt("button",{type:"button","data-action":"stopwatch"},R("tools.swStart"));const b=bt("button",{type:"button","data-action":"lap"},R("tools.swLap")),g=bt("button",{type:"button","data-action":"stopwatch-reset"},R("tools.swReset"));this.lapList=bt("ol",{class:"laps"}),this.watchButton.addEventListener("click",()=>{this.stopwatch.running?this.stopwatch.stop(s()):this.stopwatch.start(s()),this.watchButton.textContent=this.stopwatch.running?R("tools.swStop"):R("tools.swStart")}),b.addEventListener("click",()=>this.stopwatch.lap(s())),g.addEventListener("click",()=>{this.stopwatch.reset(),this.watchButton.textContent=R("tools.swStart")}),C.append(this.watchText,this.watchButton," ",b," ",g,this.lapList);const w=Nr(e,R("tools.period"),"period");w.title=R("tools.periodHelp"),this.periodTable=bt("table",{"data-readout":"period"}),w.appendChild(this.periodTable);const F=Nr(e,R("tools.overlays"),"overlays");for(const L of["ruler","protractor"]){const D=bt("label"),z=bt("input",{type:"checkbox","data-input":L});z.addEventListener("change",()=>n.overlay(L,z.checked)),this.overlayBoxes[L]=z;const V=bt("span",{class:"move-pad",role:"group","aria-label":R("tools.moveGroup",{what:R(L==="ruler"?"tools.ruler":"tools.protractor")})}),U=[["◀","tools.moveLeft",[-.05,0]],["▶","tools.moveRight",[.05,0]],["▲","tools.moveUp",[0,.05]],["▼","tools.moveDown",[0,-.05]],["⟲","tools.moveBack",null]];for(const[W,K,G]of U){const le=bt("button",{type:"button","data-action":`move-${L}`,"aria-label":R(K),title:R(K)},W);le.addEventListener("click",()=>n.move(L,G)),V.appendChild(le)}D.append(z,` ${R(L==="ruler"?"tools.ruler":"tools.protractor")}`),F.append(D,V)}}store;stopwatch=new bE;angleText;watchText;lapList;watchButton;periodTable;friction;frictionValue;gravity;now=0;mysteryG=null;reveal;description;describeLive;describedAt=-1/0;sound;audio=null;heard=0;tones=0;listen(e){const t=this.store.periodTimer.lowCount;if(t<this.heard&&(this.heard=t),t===this.heard||(this.heard=t,!this.sound.checked||typeof AudioContext>"u"))return;this.audio??=new AudioContext;const n=this.audio,s=n.createOscillator(),r=n.createGain();s.frequency.value=tA(e),r.gain.setValueAtTime(.15,n.currentTime),r.gain.exponentialRampToValueAtTime(.001,n.currentTime+.12),s.connect(r).connect(n.destination),s.start(),s.stop(n.currentTime+.12),this.tones++}spokenUntil=-1/0;endMystery(){this.mysteryG=null,document.body.classList.remove("mystery"),this.reveal.hidden=!0}describe(e,t,n=!1){const s=this.describeLive.checked;n&&(this.spokenUntil=t+3e3),this.description.setAttribute("aria-live",s||t<this.spokenUntil?"polite":"off"),!(!n&&s&&t-this.describedAt<5e3)&&(!n&&!s&&t-this.describedAt<1e3||(this.describedAt=t,this.description.textContent!==e?this.description.textContent=e:n&&(this.description.textContent="",requestAnimationFrame(()=>this.description.textContent=e))))}overlayBoxes={};showOverlay(e,t){const n=this.overlayBoxes[e];n&&(n.checked=t)}sync(e){const t=$h.find(([,s])=>s===e.params.g);this.mysteryG!==null&&e.params.g!==this.mysteryG&&this.endMystery(),document.activeElement!==this.gravity&&(this.gravity.value=this.mysteryG!==null?"mystery":t?String(t[1]):"");const n=e.model_params?.damping;document.activeElement!==this.friction&&(this.friction.value=String(n??0),this.friction.disabled=n===void 0&&e.model!=="ideal",this.frictionValue.textContent=`${(n??0).toFixed(2)} 1/s`)}update(e,t,n=0){t!==null&&(this.now=t),this.listen(n);const s=e===null?null:Ha(e),r=s===null?"—":`θ = ${(s.theta*tn).toFixed(1)}°   φ = ${(s.phi*tn).toFixed(1)}°`;this.angleText.textContent!==r&&(this.angleText.textContent=r);const a=`${this.stopwatch.reading(this.now).toFixed(3)} s`;this.watchText.textContent!==a&&(this.watchText.textContent=a);const o=this.stopwatch.laps.map(l=>`${l.toFixed(3)} s`).join("|");this.lapList.dataset.shown!==o&&(this.lapList.dataset.shown=o,this.lapList.replaceChildren(...this.stopwatch.laps.map(l=>bt("li",{},`${l.toFixed(3)} s`)))),this.fillPeriod()}fillPeriod(){const e=this.store.periodTimer.reading(),t=e.kind==="swing"&&e.amplitude!==null?iA(this.store.status,e.amplitude):null,n=RE(e,this.store.exact,t),s=([d,u])=>d===null||u===null||u===0?"":`${((d-u)/u*100).toFixed(2)} %`,r=d=>d===null?"—":(d*tn).toFixed(2),a=e.kind===null?R("tools.kindNone"):e.kind==="orbit"?R("tools.kindOrbit"):e.lowPerPeriod===1?R("tools.kindOver"):R("tools.kindSwing"),o=this.store.exact!==null?R("tools.exact"):R("tools.theory"),l=[["head","",R("tools.measured"),o,R("tools.difference")],["kind",R("tools.motion"),a,"",""]];n.swing?(l.push(["period",R("tools.periodSwing"),ft(n.period[0],5),ft(n.period[1],5),s(n.period)]),l.push(["amplitude",R("tools.amplitude"),r(e.amplitude),"",""])):(l.push(["period",R("tools.periodZ"),ft(n.period[0],5),ft(n.period[1],5),s(n.period)]),l.push(["advance",R("tools.advance"),r(n.advance[0]),r(n.advance[1]),s(n.advance)]),l.push(["precession",R("tools.precession"),r(n.precession[0]),r(n.precession[1]),""]),l.push(["band",R("tools.band"),e.thetaMin===null?"—":`${r(e.thetaMin)} … ${r(e.thetaMax)}`,"",""]));const c=this.periodTable;for(;c.rows.length>l.length;)c.deleteRow(-1);l.forEach(([d,...u],m)=>{const _=c.rows[m]??c.insertRow();for(_.dataset.row=d;_.cells.length<4;)_.insertCell();u.forEach((y,p)=>{const f=_.cells[p];f&&f.textContent!==y&&(f.textContent=y)})});const h=e.intervals===0?R("tools.periodWait"):R(n.swing?"tools.periodCount":"tools.periodCountZ",{n:e.intervals});c.caption?.textContent!==h&&(c.createCaption().textContent=h),c.dataset.period=e.period===null?"":String(e.period),c.dataset.kind=e.kind??""}}function iA(i,e){if(i===null)return null;const t=i.model_params??{},n=s=>(t[s]??0)===0;return i.model==="damped"&&!(n("drag")&&n("forcing_amplitude")&&n("gravity_x")&&n("gravity_y"))||i.model!=="ideal"&&i.model!=="damped"?null:TE(i.params.length,i.params.g,t.damping??0,e)}const qh=2*2**20,sA=["damped","ideal","rotating","slewing","vibrating"];function rA(i,e,t,n,s){if(t>qh)return`${i}: ${(t/2**20).toFixed(1)} MiB; the lab fits files of at most ${qh/2**20} MiB (use pendulab fit for larger ones)`;if(e.trim()==="")return`${i}: the file is empty`;const r={csv:e,name:i,model:n},a=s.split(/[\s,]+/).filter(o=>o!=="");return a.length>0&&(r.fit=a),r}const wg=i=>typeof i=="number"&&Number.isFinite(i),aA=i=>Array.isArray(i)&&i.length===3&&i.every(wg);function oA(i){if(typeof i!="object"||i===null)return"the fit answer is not an object";const e=i;if(typeof e.report!="string"||typeof e.scenario_toml!="string")return"the fit answer has no report";const t=e.measured;if(t!=null){const n=t,s=n.t,r=n.x;if(!Array.isArray(s)||!Array.isArray(r)||s.length!==r.length||!s.every(wg)||!r.every(aA))return"the fit answer has a malformed measured path"}return{report:e.report,warnings:Array.isArray(e.warnings)?e.warnings.filter(n=>typeof n=="string"):[],params:e.params??{},converged:e.converged===!0,scenario_toml:e.scenario_toml,lab:e.lab??null,measured:t??null}}function lA(i){const e={model:i.model,modelParams:{...i.model_params},length:i.params.length,mass:i.params.mass,g:i.params.g,method:i.method,dt:i.dt,x:i.start.x,v:i.start.v};return Xh(e)}function cA(i){return Object.entries(i).map(([e,t])=>{const n=t.determined&&t.stderr!==null?` ± ${t.stderr.toPrecision(2)}`:" (not determined by these data)",s=t.unit&&t.unit!=="1"?` ${t.unit}`:"";return`${e} = ${t.value.toPrecision(6)}${n}${s}`})}function Ln(i,e={},t=""){const n=document.createElement(i);for(const[s,r]of Object.entries(e))n.setAttribute(s,r);return t&&(n.textContent=t),n}function hA(i){return Object.entries(i).map(([e,t])=>{const[n]=gp(e,e,""),s=t.determined&&t.stderr!==null?` ± ${t.stderr.toPrecision(2)}`:` ${R("fit.notDetermined")}`,r=t.unit&&t.unit!=="1"?` ${t.unit}`:"";return`${n} = ${t.value.toPrecision(6)}${s}${r}`})}class uA{constructor(e,t){this.actions=t;const n=Ln("section",{class:"tools","data-tool":"fit"});n.appendChild(Ln("h3",{},R("fit.title")));const s=Ln("label");s.append(`${R("fit.load")} `),this.input=Ln("input",{type:"file",accept:".csv,.txt,.tsv,text/csv,text/plain","data-input":"fit-file"}),s.appendChild(this.input),s.title=R("fit.help");const r=Ln("label");r.append(`${R("fit.model")} `),this.model=Ln("select",{"data-input":"fit-model"});for(const o of sA)this.model.appendChild(Ln("option",{value:o},Wr(o,o)));r.appendChild(this.model);const a=Ln("label");a.append(`${R("fit.params")} `),this.names=Ln("input",{type:"text","data-input":"fit-params",placeholder:R("fit.paramsDefault")}),this.names.style.width="12em",a.appendChild(this.names),a.title=R("fit.paramsHelp"),this.clear=Ln("button",{type:"button","data-action":"fit-clear"},R("fit.clear")),this.clear.disabled=!0,this.clear.addEventListener("click",()=>this.reset()),this.report=Ln("pre",{class:"fit-report","data-output":"fit-report","aria-live":"polite"}),this.report.hidden=!0,this.warnings=Ln("ul",{class:"fit-warnings","data-output":"fit-warnings"}),this.warnings.hidden=!0;for(const o of[s,r,a,this.clear]){const l=Ln("p");l.appendChild(o),n.appendChild(l)}this.full.append(Ln("summary",{},R("fit.fullReport")),this.fullText),this.full.hidden=!0,n.append(this.warnings,this.report,this.full),e.appendChild(n),this.input.addEventListener("change",()=>{const o=this.input.files?.[0];o!==void 0&&this.send(o)})}actions;input;model;names;clear;report;warnings;full=Ln("details",{class:"fit-full","data-output":"fit-full"});fullText=Ln("pre",{class:"fit-report"});busy=!1;reset(){this.report.hidden=!0,this.report.textContent="",this.warnings.hidden=!0,this.warnings.replaceChildren(),this.full.hidden=!0,this.clear.disabled=!0,this.input.value="",this.actions.cleared()}async send(e){if(this.busy)return;const t=e.size>qh?"":await e.text(),n=rA(e.name,t,e.size,this.model.value,this.names.value);if(typeof n=="string")return this.actions.explain(n);this.busy=!0,this.input.disabled=!0,this.report.hidden=!1,this.report.textContent=R("fit.running",{name:e.name});try{const s=await fetch("api/fit",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(n)}),r=await s.json().catch(()=>({detail:`HTTP ${s.status}`}));if(!s.ok){const u=r.detail;throw new Error(typeof u=="string"?u:`HTTP ${s.status}`)}const a=oA(r);if(typeof a=="string")throw new Error(a);const o=fl()==="en",l=R(a.converged?"fit.converged":"fit.notConverged"),h=[...o?[a.report,"",...cA(a.params)]:[R("fit.summary",{model:Wr(this.model.value,this.model.value),state:l}),"",...hA(a.params)],...a.warnings.map(u=>`⚠ ${u}`)];this.fullText.textContent=a.report,this.full.hidden=o,a.measured===null&&h.push(R("fit.noPath")),this.report.textContent=h.join(`
`);const d=[...a.warnings,...a.report.split(`
`).filter(u=>/warning|does not fit|misfit/i.test(u))].map(u=>u.replace(/^\s*warning:\s*/i,"").trim());this.warnings.replaceChildren(...[...new Set(d)].map(u=>Ln("li",{},`⚠ ${u}`))),this.warnings.hidden=d.length===0,this.clear.disabled=!1,this.actions.loaded(a,e.name)}catch(s){const r=s instanceof Error?s.message:String(s);this.report.textContent=`${e.name}: ${r}`,this.actions.explain(R("fit.failed",{why:r}))}finally{this.busy=!1,this.input.disabled=!1}}}function dA(i){const{store:e,scene:t,view:n,session:s,explain:r}=i,a=new nA(Tt("tools"),e,{send:s.send,explain:r,overlay:(o,l)=>{n[o]=l},move:(o,l)=>{const[c,h]=o==="ruler"?["rulerShift","rulerLift"]:["protractorShift","protractorLift"],d=u=>Math.round(u*1e3)/1e3;n[c]=l===null?0:d(n[c]+l[0]),n[h]=l===null?0:d(n[h]+l[1]),n[o]=!0,a.showOverlay(o,!0)}});return new uA(Tt("tools"),{loaded:(o,l)=>{if(t.setMeasured(o.measured?.x??null),o.lab!==null)for(const c of lA(o.lab))s.send(c);r(R("fit.loaded",{name:l}),!0)},cleared:()=>t.setMeasured(null),explain:r}),a.showOverlay("ruler",n.ruler),a.showOverlay("protractor",n.protractor),a}class Yi{constructor(e,t,n,s,r="div"){this.parent=e,this.object=t,this.property=n,this._disabled=!1,this._hidden=!1,this.initialValue=this.getValue(),this.domElement=document.createElement(r),this.domElement.classList.add("lil-controller"),this.domElement.classList.add(s),this.$name=document.createElement("div"),this.$name.classList.add("lil-name"),Yi.nextNameID=Yi.nextNameID||0,this.$name.id=`lil-gui-name-${++Yi.nextNameID}`,this.$widget=document.createElement("div"),this.$widget.classList.add("lil-widget"),this.$disable=this.$widget,this.domElement.appendChild(this.$name),this.domElement.appendChild(this.$widget),this.domElement.addEventListener("keydown",a=>a.stopPropagation()),this.domElement.addEventListener("keyup",a=>a.stopPropagation()),this.parent.children.push(this),this.parent.controllers.push(this),this.parent.$children.appendChild(this.domElement),this._listenCallback=this._listenCallback.bind(this),this.name(n)}name(e){return this._name=e,this.$name.textContent=e,this}onChange(e){return this._onChange=e,this}_callOnChange(){this.parent._callOnChange(this),this._onChange!==void 0&&this._onChange.call(this,this.getValue()),this._changed=!0}onFinishChange(e){return this._onFinishChange=e,this}_callOnFinishChange(){this._changed&&(this.parent._callOnFinishChange(this),this._onFinishChange!==void 0&&this._onFinishChange.call(this,this.getValue())),this._changed=!1}reset(){return this.setValue(this.initialValue),this._callOnFinishChange(),this}enable(e=!0){return this.disable(!e)}disable(e=!0){return e===this._disabled?this:(this._disabled=e,this.domElement.classList.toggle("lil-disabled",e),this.$disable.toggleAttribute("disabled",e),this)}show(e=!0){return this._hidden=!e,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}options(e){const t=this.parent.add(this.object,this.property,e);return t.name(this._name),this.destroy(),t}min(e){return this}max(e){return this}step(e){return this}decimals(e){return this}listen(e=!0){return this._listening=e,this._listenCallbackID!==void 0&&(cancelAnimationFrame(this._listenCallbackID),this._listenCallbackID=void 0),this._listening&&this._listenCallback(),this}_listenCallback(){this._listenCallbackID=requestAnimationFrame(this._listenCallback);const e=this.save();e!==this._listenPrevValue&&this.updateDisplay(),this._listenPrevValue=e}getValue(){return this.object[this.property]}setValue(e){return this.getValue()!==e&&(this.object[this.property]=e,this._callOnChange(),this.updateDisplay()),this}updateDisplay(){return this}load(e){return this.setValue(e),this._callOnFinishChange(),this}save(){return this.getValue()}destroy(){this.listen(!1),this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.controllers.splice(this.parent.controllers.indexOf(this),1),this.parent.$children.removeChild(this.domElement)}}class fA extends Yi{constructor(e,t,n){super(e,t,n,"lil-boolean","label"),this.$input=document.createElement("input"),this.$input.setAttribute("type","checkbox"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$widget.appendChild(this.$input),this.$input.addEventListener("change",()=>{this.setValue(this.$input.checked),this._callOnFinishChange()}),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.checked=this.getValue(),this}}function Yh(i){let e,t;return(e=i.match(/(#|0x)?([a-f0-9]{6})/i))?t=e[2]:(e=i.match(/rgb\(\s*(\d*)\s*,\s*(\d*)\s*,\s*(\d*)\s*\)/))?t=parseInt(e[1]).toString(16).padStart(2,0)+parseInt(e[2]).toString(16).padStart(2,0)+parseInt(e[3]).toString(16).padStart(2,0):(e=i.match(/^#?([a-f0-9])([a-f0-9])([a-f0-9])$/i))&&(t=e[1]+e[1]+e[2]+e[2]+e[3]+e[3]),t?"#"+t:!1}const pA={isPrimitive:!0,match:i=>typeof i=="string",fromHexString:Yh,toHexString:Yh},Wa={isPrimitive:!0,match:i=>typeof i=="number",fromHexString:i=>parseInt(i.substring(1),16),toHexString:i=>"#"+i.toString(16).padStart(6,0)},mA={isPrimitive:!1,match:i=>Array.isArray(i)||ArrayBuffer.isView(i),fromHexString(i,e,t=1){const n=Wa.fromHexString(i);e[0]=(n>>16&255)/255*t,e[1]=(n>>8&255)/255*t,e[2]=(n&255)/255*t},toHexString([i,e,t],n=1){n=255/n;const s=i*n<<16^e*n<<8^t*n<<0;return Wa.toHexString(s)}},gA={isPrimitive:!1,match:i=>Object(i)===i,fromHexString(i,e,t=1){const n=Wa.fromHexString(i);e.r=(n>>16&255)/255*t,e.g=(n>>8&255)/255*t,e.b=(n&255)/255*t},toHexString({r:i,g:e,b:t},n=1){n=255/n;const s=i*n<<16^e*n<<8^t*n<<0;return Wa.toHexString(s)}},_A=[pA,Wa,mA,gA];function vA(i){return _A.find(e=>e.match(i))}class xA extends Yi{constructor(e,t,n,s){super(e,t,n,"lil-color"),this.$input=document.createElement("input"),this.$input.setAttribute("type","color"),this.$input.setAttribute("tabindex",-1),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$text=document.createElement("input"),this.$text.setAttribute("type","text"),this.$text.setAttribute("spellcheck","false"),this.$text.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$display.appendChild(this.$input),this.$widget.appendChild(this.$display),this.$widget.appendChild(this.$text),this._format=vA(this.initialValue),this._rgbScale=s,this._initialValueHexString=this.save(),this._textFocused=!1,this.$input.addEventListener("input",()=>{this._setValueFromHexString(this.$input.value)}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$text.addEventListener("input",()=>{const r=Yh(this.$text.value);r&&this._setValueFromHexString(r)}),this.$text.addEventListener("focus",()=>{this._textFocused=!0,this.$text.select()}),this.$text.addEventListener("blur",()=>{this._textFocused=!1,this.updateDisplay(),this._callOnFinishChange()}),this.$disable=this.$text,this.updateDisplay()}reset(){return this._setValueFromHexString(this._initialValueHexString),this}_setValueFromHexString(e){if(this._format.isPrimitive){const t=this._format.fromHexString(e);this.setValue(t)}else this._format.fromHexString(e,this.getValue(),this._rgbScale),this._callOnChange(),this.updateDisplay()}save(){return this._format.toHexString(this.getValue(),this._rgbScale)}load(e){return this._setValueFromHexString(e),this._callOnFinishChange(),this}updateDisplay(){return this.$input.value=this._format.toHexString(this.getValue(),this._rgbScale),this._textFocused||(this.$text.value=this.$input.value.substring(1)),this.$display.style.backgroundColor=this.$input.value,this}}class Ic extends Yi{constructor(e,t,n){super(e,t,n,"lil-function"),this.$button=document.createElement("button"),this.$button.appendChild(this.$name),this.$widget.appendChild(this.$button),this.$button.addEventListener("click",s=>{s.preventDefault(),this.getValue().call(this.object),this._callOnChange()}),this.$button.addEventListener("touchstart",()=>{},{passive:!0}),this.$disable=this.$button}}class yA extends Yi{constructor(e,t,n,s,r,a){super(e,t,n,"lil-number"),this._initInput(),this.min(s),this.max(r);const o=a!==void 0;this.step(o?a:this._getImplicitStep(),o),this.updateDisplay()}decimals(e){return this._decimals=e,this.updateDisplay(),this}min(e){return this._min=e,this._onUpdateMinMax(),this}max(e){return this._max=e,this._onUpdateMinMax(),this}step(e,t=!0){return this._step=e,this._stepExplicit=t,this}updateDisplay(){const e=this.getValue();if(this._hasSlider){let t=(e-this._min)/(this._max-this._min);t=Math.max(0,Math.min(t,1)),this.$fill.style.width=t*100+"%"}return this._inputFocused||(this.$input.value=this._decimals===void 0?e:e.toFixed(this._decimals)),this}_initInput(){this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("aria-labelledby",this.$name.id),window.matchMedia("(pointer: coarse)").matches&&(this.$input.setAttribute("type","number"),this.$input.setAttribute("step","any")),this.$widget.appendChild(this.$input),this.$disable=this.$input;const t=()=>{let x=parseFloat(this.$input.value);isNaN(x)||(this._stepExplicit&&(x=this._snap(x)),this.setValue(this._clamp(x)))},n=x=>{const A=parseFloat(this.$input.value);isNaN(A)||(this._snapClampSetValue(A+x),this.$input.value=this.getValue())},s=x=>{x.key==="Enter"&&this.$input.blur(),x.code==="ArrowUp"&&(x.preventDefault(),n(this._step*this._arrowKeyMultiplier(x))),x.code==="ArrowDown"&&(x.preventDefault(),n(this._step*this._arrowKeyMultiplier(x)*-1))},r=x=>{this._inputFocused&&(x.preventDefault(),n(this._step*this._normalizeMouseWheel(x)))};let a=!1,o,l,c,h,d;const u=5,m=x=>{o=x.clientX,l=c=x.clientY,a=!0,h=this.getValue(),d=0,window.addEventListener("mousemove",_),window.addEventListener("mouseup",y)},_=x=>{if(a){const A=x.clientX-o,M=x.clientY-l;Math.abs(M)>u?(x.preventDefault(),this.$input.blur(),a=!1,this._setDraggingStyle(!0,"vertical")):Math.abs(A)>u&&y()}if(!a){const A=x.clientY-c;d-=A*this._step*this._arrowKeyMultiplier(x),h+d>this._max?d=this._max-h:h+d<this._min&&(d=this._min-h),this._snapClampSetValue(h+d)}c=x.clientY},y=()=>{this._setDraggingStyle(!1,"vertical"),this._callOnFinishChange(),window.removeEventListener("mousemove",_),window.removeEventListener("mouseup",y)},p=()=>{this._inputFocused=!0},f=()=>{this._inputFocused=!1,this.updateDisplay(),this._callOnFinishChange()};this.$input.addEventListener("input",t),this.$input.addEventListener("keydown",s),this.$input.addEventListener("wheel",r,{passive:!1}),this.$input.addEventListener("mousedown",m),this.$input.addEventListener("focus",p),this.$input.addEventListener("blur",f)}_initSlider(){this._hasSlider=!0,this.$slider=document.createElement("div"),this.$slider.classList.add("lil-slider"),this.$fill=document.createElement("div"),this.$fill.classList.add("lil-fill"),this.$slider.appendChild(this.$fill),this.$widget.insertBefore(this.$slider,this.$input),this.domElement.classList.add("lil-has-slider");const e=(f,x,A,M,C)=>(f-x)/(A-x)*(C-M)+M,t=f=>{const x=this.$slider.getBoundingClientRect();let A=e(f,x.left,x.right,this._min,this._max);this._snapClampSetValue(A)},n=f=>{this._setDraggingStyle(!0),t(f.clientX),window.addEventListener("mousemove",s),window.addEventListener("mouseup",r)},s=f=>{t(f.clientX)},r=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("mousemove",s),window.removeEventListener("mouseup",r)};let a=!1,o,l;const c=f=>{f.preventDefault(),this._setDraggingStyle(!0),t(f.touches[0].clientX),a=!1},h=f=>{f.touches.length>1||(this._hasScrollBar?(o=f.touches[0].clientX,l=f.touches[0].clientY,a=!0):c(f),window.addEventListener("touchmove",d,{passive:!1}),window.addEventListener("touchend",u))},d=f=>{if(a){const x=f.touches[0].clientX-o,A=f.touches[0].clientY-l;Math.abs(x)>Math.abs(A)?c(f):(window.removeEventListener("touchmove",d),window.removeEventListener("touchend",u))}else f.preventDefault(),t(f.touches[0].clientX)},u=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("touchmove",d),window.removeEventListener("touchend",u)},m=this._callOnFinishChange.bind(this),_=400;let y;const p=f=>{if(Math.abs(f.deltaX)<Math.abs(f.deltaY)&&this._hasScrollBar)return;f.preventDefault();const A=this._normalizeMouseWheel(f)*this._step;this._snapClampSetValue(this.getValue()+A),this.$input.value=this.getValue(),clearTimeout(y),y=setTimeout(m,_)};this.$slider.addEventListener("mousedown",n),this.$slider.addEventListener("touchstart",h,{passive:!1}),this.$slider.addEventListener("wheel",p,{passive:!1})}_setDraggingStyle(e,t="horizontal"){this.$slider&&this.$slider.classList.toggle("lil-active",e),document.body.classList.toggle("lil-dragging",e),document.body.classList.toggle(`lil-${t}`,e)}_getImplicitStep(){return this._hasMin&&this._hasMax?(this._max-this._min)/1e3:.1}_onUpdateMinMax(){!this._hasSlider&&this._hasMin&&this._hasMax&&(this._stepExplicit||this.step(this._getImplicitStep(),!1),this._initSlider(),this.updateDisplay())}_normalizeMouseWheel(e){let{deltaX:t,deltaY:n}=e;return Math.floor(e.deltaY)!==e.deltaY&&e.wheelDelta&&(t=0,n=-e.wheelDelta/120,n*=this._stepExplicit?1:10),t+-n}_arrowKeyMultiplier(e){let t=this._stepExplicit?1:10;return e.shiftKey?t*=10:e.altKey&&(t/=10),t}_snap(e){let t=0;return this._hasMin?t=this._min:this._hasMax&&(t=this._max),e-=t,e=Math.round(e/this._step)*this._step,e+=t,e=parseFloat(e.toPrecision(15)),e}_clamp(e){return e<this._min&&(e=this._min),e>this._max&&(e=this._max),e}_snapClampSetValue(e){this.setValue(this._clamp(this._snap(e)))}get _hasScrollBar(){const e=this.parent.root.$children;return e.scrollHeight>e.clientHeight}get _hasMin(){return this._min!==void 0}get _hasMax(){return this._max!==void 0}}class SA extends Yi{constructor(e,t,n,s){super(e,t,n,"lil-option"),this.$select=document.createElement("select"),this.$select.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$select.addEventListener("change",()=>{this.setValue(this._values[this.$select.selectedIndex]),this._callOnFinishChange()}),this.$select.addEventListener("focus",()=>{this.$display.classList.add("lil-focus")}),this.$select.addEventListener("blur",()=>{this.$display.classList.remove("lil-focus")}),this.$widget.appendChild(this.$select),this.$widget.appendChild(this.$display),this.$disable=this.$select,this.options(s)}options(e){return this._values=Array.isArray(e)?e:Object.values(e),this._names=Array.isArray(e)?e:Object.keys(e),this.$select.replaceChildren(),this._names.forEach(t=>{const n=document.createElement("option");n.textContent=t,this.$select.appendChild(n)}),this.updateDisplay(),this}updateDisplay(){const e=this.getValue(),t=this._values.indexOf(e);return this.$select.selectedIndex=t,this.$display.textContent=t===-1?e:this._names[t],this}}class MA extends Yi{constructor(e,t,n){super(e,t,n,"lil-string"),this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("spellcheck","false"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$input.addEventListener("input",()=>{this.setValue(this.$input.value)}),this.$input.addEventListener("keydown",s=>{s.code==="Enter"&&this.$input.blur()}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$widget.appendChild(this.$input),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.value=this.getValue(),this}}var bA=`.lil-gui {
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
}`;function wA(i){const e=document.createElement("style");e.innerHTML=i;const t=document.querySelector("head link[rel=stylesheet], head style");t?document.head.insertBefore(e,t):document.head.appendChild(e)}let fp=!1;class Nu{constructor({parent:e,autoPlace:t=e===void 0,container:n,width:s,title:r="Controls",closeFolders:a=!1,injectStyles:o=!0,touchStyles:l=!0}={}){if(this.parent=e,this.root=e?e.root:this,this.children=[],this.controllers=[],this.folders=[],this._closed=!1,this._hidden=!1,this.domElement=document.createElement("div"),this.domElement.classList.add("lil-gui"),this.$title=document.createElement("button"),this.$title.classList.add("lil-title"),this.$title.setAttribute("aria-expanded",!0),this.$title.addEventListener("click",()=>this.openAnimated(this._closed)),this.$title.addEventListener("touchstart",()=>{},{passive:!0}),this.$children=document.createElement("div"),this.$children.classList.add("lil-children"),this.domElement.appendChild(this.$title),this.domElement.appendChild(this.$children),this.title(r),this.parent){this.parent.children.push(this),this.parent.folders.push(this),this.parent.$children.appendChild(this.domElement);return}this.domElement.classList.add("lil-root"),l&&this.domElement.classList.add("lil-allow-touch-styles"),!fp&&o&&(wA(bA),fp=!0),n?n.appendChild(this.domElement):t&&(this.domElement.classList.add("lil-auto-place","autoPlace"),document.body.appendChild(this.domElement)),s&&this.domElement.style.setProperty("--width",s+"px"),this._closeFolders=a}add(e,t,n,s,r){if(Object(n)===n)return new SA(this,e,t,n);const a=e[t];switch(typeof a){case"number":return new yA(this,e,t,n,s,r);case"boolean":return new fA(this,e,t);case"string":return new MA(this,e,t);case"function":return new Ic(this,e,t)}console.error(`gui.add failed
	property:`,t,`
	object:`,e,`
	value:`,a)}addColor(e,t,n=1){return new xA(this,e,t,n)}addFolder(e){const t=new Nu({parent:this,title:e});return this.root._closeFolders&&t.close(),t}load(e,t=!0){return e.controllers&&this.controllers.forEach(n=>{n instanceof Ic||n._name in e.controllers&&n.load(e.controllers[n._name])}),t&&e.folders&&this.folders.forEach(n=>{n._title in e.folders&&n.load(e.folders[n._title])}),this}save(e=!0){const t={controllers:{},folders:{}};return this.controllers.forEach(n=>{if(!(n instanceof Ic)){if(n._name in t.controllers)throw new Error(`Cannot save GUI with duplicate property "${n._name}"`);t.controllers[n._name]=n.save()}}),e&&this.folders.forEach(n=>{if(n._title in t.folders)throw new Error(`Cannot save GUI with duplicate folder "${n._title}"`);t.folders[n._title]=n.save()}),t}open(e=!0){return this._setClosed(!e),this.$title.setAttribute("aria-expanded",!this._closed),this.domElement.classList.toggle("lil-closed",this._closed),this}close(){return this.open(!1)}_setClosed(e){this._closed!==e&&(this._closed=e,this._callOnOpenClose(this))}show(e=!0){return this._hidden=!e,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}openAnimated(e=!0){return this._setClosed(!e),this.$title.setAttribute("aria-expanded",!this._closed),requestAnimationFrame(()=>{const t=this.$children.clientHeight;this.$children.style.height=t+"px",this.domElement.classList.add("lil-transition");const n=r=>{r.target===this.$children&&(this.$children.style.height="",this.domElement.classList.remove("lil-transition"),this.$children.removeEventListener("transitionend",n))};this.$children.addEventListener("transitionend",n);const s=e?this.$children.scrollHeight:0;this.domElement.classList.toggle("lil-closed",!e),requestAnimationFrame(()=>{this.$children.style.height=s+"px"})}),this}title(e){return this._title=e,this.$title.textContent=e,this}reset(e=!0){return(e?this.controllersRecursive():this.controllers).forEach(n=>n.reset()),this}onChange(e){return this._onChange=e,this}_callOnChange(e){this.parent&&this.parent._callOnChange(e),this._onChange!==void 0&&this._onChange.call(this,{object:e.object,property:e.property,value:e.getValue(),controller:e})}onFinishChange(e){return this._onFinishChange=e,this}_callOnFinishChange(e){this.parent&&this.parent._callOnFinishChange(e),this._onFinishChange!==void 0&&this._onFinishChange.call(this,{object:e.object,property:e.property,value:e.getValue(),controller:e})}onOpenClose(e){return this._onOpenClose=e,this}_callOnOpenClose(e){this.parent&&this.parent._callOnOpenClose(e),this._onOpenClose!==void 0&&this._onOpenClose.call(this,e)}destroy(){this.parent&&(this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.folders.splice(this.parent.folders.indexOf(this),1)),this.domElement.parentElement&&this.domElement.parentElement.removeChild(this.domElement),Array.from(this.children).forEach(e=>e.destroy())}controllersRecursive(){let e=Array.from(this.controllers);return this.folders.forEach(t=>{e=e.concat(t.controllersRecursive())}),e}foldersRecursive(){let e=Array.from(this.folders);return this.folders.forEach(t=>{e=e.concat(t.foldersRecursive())}),e}}function Eg(i){return i==="1"?"":i.replace("^2","²").replace("^3","³")}function Tg(i){return gp(i.name,i.label??i.name,i.description)}function EA(i){const e=Eg(i.unit),[t]=Tg(i);return e?`${t} [${e}]`:t}function Kh(i){const e=Eg(i.unit),t=e?` ${e}`:"";return i.min!==null&&i.max!==null?`${i.min} … ${i.max}${t}`:i.min!==null?`≥ ${i.min}${t}`:i.max!==null?`≤ ${i.max}${t}`:"any finite number"}function TA(i,e){return Number.isFinite(e)&&(i.min===null||e>=i.min)&&(i.max===null||e<=i.max)?null:R("msg.notAllowed",{name:i.name,value:e,allowed:i.allowed??Kh(i),range:Kh(i)})}function Ag(i,e,t,n,s){typeof e[t.name]!="number"&&(e[t.name]=t.default);const r=i.add(e,t.name,t.ui_min,t.ui_max).name(EA(t)).onChange(l=>{const c=TA(t,l);c!==null?s(c):n(l)}),[,a]=Tg(t);r.domElement.title=R("gui.paramHelp",{help:a,name:t.name,unit:t.unit,range:Kh(t),default:t.default}),r.domElement.dataset.param=t.name,r.step(t.step,!1);const o=r;return typeof o._clamp=="function"&&(o._clamp=l=>l),r}function Iu(i,e){let t=-1/0,n=null,s=null;return(...r)=>{s=r;const a=t+e-performance.now();a<=0&&n===null?(t=performance.now(),i(...r),s=null):n===null&&(n=setTimeout(()=>{n=null,t=performance.now(),s!==null&&i(...s),s=null},Math.max(0,a)))}}const AA={damped:{damping:.3}};function RA(i){const e=AA[i];return e?{type:"set_model",model:i,params:{...e}}:{type:"set_model",model:i}}function CA(i){const e={};for(const t of i)e[t.label?`${Wr(t.name,t.label)} (${t.name})`:t.name]=t.name;return e}class PA{constructor(e,t,n){this.parent=e,this.schema=t,this.actions=n,this.picker=e.add(this.state,"model",CA(t.models)).name(R("gui.model")).onChange(s=>n.send(RA(s))),this.picker.domElement.dataset.control="model",this.picker.domElement.title=[R("gui.modelsHelp"),...t.models.map(s=>`${Wr(s.name,s.label??s.name)} (${s.name}): ${s0(s.name,s.summary)}`)].join(`
`),this.sendParam=Iu((s,r)=>{n.send({type:"set_params",params:{[s]:r}})},50)}parent;schema;actions;state={model:"ideal"};picker;paramsFolder=null;paramControls=[];values={};shown=null;sendParam;spec(e){return this.schema.models.find(t=>t.name===e)}rebuild(e){this.paramsFolder?.destroy(),this.paramsFolder=null,this.paramControls=[],this.values={},this.shown=e;const t=this.spec(e);if(t===void 0||t.params.length===0)return;const n=this.parent.addFolder(R("gui.modelParams",{model:Wr(e,t.label??e)}));for(const s of t.params){this.values[s.name]=s.default;const r=Ag(n,this.values,s,a=>this.sendParam(s.name,a),this.actions.explain);this.paramControls.push(r)}this.paramsFolder=n}sync(e){const t=e.model??"ideal";this.state.model=t,this.picker.updateDisplay(),this.shown!==t&&this.rebuild(t);for(const[n,s]of Object.entries(e.model_params??{}))this.values[n]=s;for(const n of this.paramControls)n.domElement.contains(document.activeElement)||n.updateDisplay()}}const LA={velocity:["vec.velocity","vec.velocityHelp"],momentum:["vec.momentum","vec.momentumHelp"],gravity:["vec.gravity","vec.gravityHelp"],tension:["vec.tension","vec.tensionHelp"],net:["vec.net","vec.netHelp"],angularMomentum:["vec.angularMomentum","vec.angularMomentumHelp"],torque:["vec.torque","vec.torqueHelp"]};function DA(i,e,t,n){const s=i.addFolder(R("gui.view"));s.add(e,"trail").name(R("gui.trail")).onChange(t),s.add(e,"trailSeconds",1,120,1).name(R("gui.trailSeconds")).onChange(t),s.add(e,"sphere").name(R("gui.sphere")).onChange(t),s.add(e,"axes").name(R("gui.axes")).onChange(t);const r={topView:!1};s.add(r,"topView").name(R("gui.topView")).onChange(h=>{n(h),t()});const a={off:"stereo.off",anaglyph:"stereo.anaglyph","side by side":"stereo.sideBySide"},o=Object.fromEntries(pg.map(h=>[a[h]?R(a[h]):h,h])),l=s.add(e,"stereo",o).name(R("gui.stereo")).onChange(t);l.domElement.title=R("gui.stereoHelp"),l.domElement.dataset.control="stereo",s.close();const c=i.addFolder(R("gui.vectors"));for(const[h,[d,u]]of Object.entries(LA)){const m=c.add(e,h).name(R(d)).onChange(t);m.domElement.title=R(u),m.domElement.dataset.vector=h,m.$name.style.borderLeft=`10px solid #${Lu[h].toString(16).padStart(6,"0")}`,m.$name.style.paddingLeft="4px"}for(const h of["X","Y","Z"]){const d=`origin${h}`;c.add(e,d,-5,5,.01).name(R("gui.origin",{axis:h.toLowerCase()})).onChange(t).domElement.title=R("gui.originHelp")}return c.close(),s}function pp(i,e,t){const n=i.addFolder(e);return n.domElement.dataset.folder=t,n}class NA{constructor(e,t,n,s,r){this.view=s,this.gui=new Nu({container:e,title:R("gui.title"),width:270});const a={};this.model=a;const o=pp(this.gui,R("gui.pendulum"),"pendulum"),l=Iu((b,g)=>{r.send({type:"set_params",[b]:g})},50);for(const b of t.model.params){const g=w=>l(b.name,w);this.synced.push(Ag(o,a,b,g,r.explain))}this.modelControls=new PA(o,t,r);const c=this.gui.addFolder(R("gui.integrator")).close(),h={};for(const b of t.methods)h[jo(b.name,b.order)]=b.name;a.method=t.methods.find(b=>b.default)?.name??t.methods[0]?.name??"rattle";const d=c.add(a,"method",h).name(R("gui.method")).onChange(b=>r.send({type:"set_method",method:b}));d.domElement.title=t.methods.map(b=>`${jo(b.name,b.order)} — ${b.name}${fl()==="en"?`: ${b.summary}`:""}`).join(`
`),this.synced.push(d);const u=t.controls.dt;a.dt=u.default??.001;const m=c.add(a,"dt").name("dt [s]").decimals(6).onFinishChange(b=>{if(!(b>=u.min&&b<=u.max)){r.explain(R("gui.dtRange",{min:u.min,max:u.max}));return}r.send({type:"set_method",dt:b})});m.domElement.title=R("gui.dtHelp",{min:u.min,max:u.max}),this.synced.push(m);const _=pp(this.gui,R("gui.run"),"run"),y=t.controls.time_scale;a.time_scale=y.default??1;const p=_.add(a,"time_scale").name(R("gui.timeScale")).decimals(3).onFinishChange(b=>{if(!(b>=y.min&&b<=y.max)){r.explain(R("gui.tsRange",{min:y.min,max:y.max}));return}r.send({type:"set_time_scale",time_scale:b})});p.domElement.title=R("gui.tsHelp",{min:y.min,max:y.max}),this.synced.push(p),a.paused=!1,a.run=()=>r.send({type:a.paused===!0?"resume":"pause"}),this.runButton=_.add(a,"run").name(R("toolbar.pause")),a.stepN=1;const f=t.controls.step_n;_.add(a,"stepN",f.min,Math.min(f.max,1e3),1).name(R("gui.stepN")),a.step=()=>r.send({type:"step",n:Math.round(Number(a.stepN))}),_.add(a,"step").name(R("toolbar.step")),a.reset=()=>r.send({type:"reset"}),_.add(a,"reset").name(R("toolbar.reset"));const x={};for(const b of n)b.error===void 0&&(x[ed(b.name,b.title)]=b.name);a.scenario="";const A=_.add(a,"scenario",x).name(R("gui.scenario")).onChange(b=>r.send({type:"load_scenario",name:b}));A.domElement.title=n.filter(b=>b.error===void 0).map(b=>`${b.name}: ${ed(b.name,b.title)}`).join(`
`),this.synced.push(A),DA(this.gui,s,()=>r.viewChanged(this.view,this.topView),b=>{this.topView=b});const M=this.gui.addFolder(R("gui.export")).close();a.csv=()=>r.downloadCSV(),M.add(a,"csv").name(R("gui.csv")),a.toml=()=>r.downloadTOML();const C=M.add(a,"toml").name(R("gui.toml"));C.domElement.dataset.control="toml",C.domElement.title=R("gui.tomlHelp"),a.png=()=>r.screenshot(),M.add(a,"png").name(R("gui.png")),a.link=()=>r.copyLink(),M.add(a,"link").name(R("gui.link"))}view;gui;model;synced=[];runButton;modelControls;topView=!1;sync(e){const t=this.model;t.length=e.params.length,t.mass=e.params.mass,t.g=e.params.g,t.method=e.method,t.dt=e.dt,t.time_scale=e.time_scale,t.paused=e.paused,t.scenario=e.scenario??"";for(const n of this.synced)n.domElement.contains(document.activeElement)||n.updateDisplay();this.runButton.name(e.paused?R("toolbar.start"):R("toolbar.pause")),this.modelControls.sync(e)}}function IA(i){const e={model:i.model,length:i.params.length,mass:i.params.mass,g:i.params.g,params:{...i.model_params},x:i.start.x,v:i.start.v,method:i.method,dt:i.dt,t0:i.t0,t_end:Math.max(i.t0+100,Math.ceil(i.t))},t=i.title??i.scenario;return t&&(e.title=`${t} (from the lab)`),e}function UA(i){const e=i.store.status;if(e===null)return i.explain(R("msg.notConnected"));fetch("api/scenario.toml",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(IA(e))}).then(async t=>{if(!t.ok)throw new Error((await t.json()).detail??`HTTP ${t.status}`);Du(`pendulab-${e.scenario??"lab"}.toml`,await t.blob())}).catch(t=>i.explain(`scenario download: ${t instanceof Error?t.message:String(t)}`))}function FA(i,e){e.write();const t=window.location.href,n=UT(e.lab()),s=()=>i.explain(`${t} — ${n}`,!0),r=navigator.clipboard?.writeText(t);r===void 0?s():r.then(()=>i.explain(R("msg.linkCopied",{what:n}),!0),s)}function OA(i,e,t,n){const{store:s,scene:r,view:a,session:o,explain:l}=i,c=h=>`pendulab-${s.status?.scenario??"lab"}.${h}`;return new NA(Tt("gui"),e,t,a,{send:o.send,explain:l,downloadCSV:()=>Du(c("csv"),new Blob([s.toCSV()],{type:"text/csv"})),downloadTOML:()=>UA(i),screenshot:()=>yg(c("png"),r.screenshot()),copyLink:()=>FA(i,n),viewChanged:(h,d)=>{r.setTopView(d),r.setStereo(h.stereo)}})}function gi(i){mp.has(i)||(mp.add(i),performance.mark(`pendulab:${i}`))}const mp=new Set;function kA(i,e,t,n,s){const{store:r,scene:a}=i,o=r.status;r.onStatus(s),o!==null&&(o.scenario!==s.scenario||o.model!==s.model)&&t.clearNews(),(o===null||o.epoch!==s.epoch)&&e.energy.rescale(),e.controls.sync(s),xg(e.controls.gui),e.tools.sync(s),e.toolbar.showRunning(s.paused),a.setLength(s.params.length),a.setModel(s.model),e.portraits.setModel(s.model),n.write()}function BA(i,e){const t=e.twinToRestore,n=i.session.twin;t===null||n===null||(e.twinToRestore=null,Fc(()=>i.store.status?.commands,()=>i.session.sent(),5e3).then(()=>(n.restore(t),Fc(()=>n.store.status?.paused?1:void 0,()=>1,5e3))).then(()=>{for(const s of e.replay)i.session.send(s);e.replay=[]}))}function zA(i,e,t,n,s){if(s.type==="error"){i.store.onError(s);const r=r0(s);i.explain(s.command?`${s.command}: ${r}`:r);return}if(s.type==="event"){i.store.onEvent(s),i.explain(c0(s),!0);return}gi("first status"),kA(i,e,t,n,s);for(const r of n.takeStartup())i.session.send(r);BA(i,n)}class HA{real=null;held=[];call(e){this.real!==null?e(this.real):this.held.push(e)}onOpen(){this.call(e=>e.onOpen())}onClose(){this.call(e=>e.onClose())}onFrames(e){this.call(t=>t.onFrames(e))}onNotice(e){this.call(t=>t.onNotice(e))}onProtocolError(e){this.call(t=>t.onProtocolError(e))}attach(e){this.real=e;for(const t of this.held.splice(0))t(e)}}function GA(){const i=new HA;return gi("socket opening"),{conn:new Jh(Uc(window.location),i),held:i}}function VA(i,e,t,n,s,r,a){const{store:o}=i;e.attach({onOpen:()=>{gi("socket open"),o.setConnected(!0),Tt("conn").textContent=R("conn.connected"),Tt("offline").hidden=!0},onClose:()=>{o.setConnected(!1),Tt("conn").textContent=R("conn.retrying"),Tt("offline").textContent=R("conn.gone"),Tt("offline").hidden=!1,s.restoreShown()},onFrames:l=>{gi("first frames");const c=performance.now();o.onFrames(l),r.onFrames(),a.add("frames received",performance.now()-c)},onNotice:l=>zA(i,t,n,s,l),onProtocolError:l=>i.explain(`protocol: ${l}`)})}function WA(i){const{store:e,scene:t,session:n,explain:s}=i,r=Iu((o,l)=>{n.send({type:"set_state",x:o,v:l,project:!0})},50),a=()=>{e.status?.paused===!1&&n.send({type:"pause"})};t.enableDrag((o,l)=>{l==="start"&&a(),r(o,[0,0,0]),l==="end"&&s(R("msg.dragged"),!0)},(o,l,c)=>{if(c==="start"){a(),s(R("msg.pull"),!0);return}if(l===null)return;r(o,l.v);const h=l.capped?R("msg.capped"):"",d={v:l.speed.toFixed(2),cap:h};s(R(c==="end"?"msg.velocitySet":"msg.velocity",d),!0)})}function Rg(i){const e=i.store.status?.params;return{mass:e?.mass??1,g:e?.g??9.81,length:e?.length??1}}function XA(i,e,t){const{store:n,scene:s,view:r,session:a}=i,o=performance.now(),l=n.displayed(),{mass:c,g:h}=Rg(i),d=pE(n.status?.model_params),{start:u,end:m}=n.trailRange(r.trailSeconds),_=a.twin,y=_?.drawn(n.playT,r.trailSeconds)??null;s.setTwinLayout(_?.layout()??null),s.setExtras(_?.extraLayouts()??[]);const p=_?.drawnExtras(n.playT,r.trailSeconds)??[],f=[l,n.trail,u,m,c,h,...d,...Object.values(r),y?.frame??null,y?.trail.end??0,...p.map(C=>C.frame)],x=e.changed(f);x&&(s.update(l,{frames:n.trail,start:u,end:m},r,c,h,d),s.updateTwin(y?.frame??null,y?.trail??{frames:[],start:0,end:0}),s.updateExtras(p));const A=performance.now();t.add("scene update",A-o);const M=s.draw(x);return M&&t.add("scene render (submit)",performance.now()-A),M}function $A(i,e,t,n,s){const{store:r,session:a}=i,o=r.displayed(),{mass:l,g:c,length:h}=Rg(i),d=a.twin;let u=performance.now();const m=r.reference;e.plots.update(r.history,r.events,xv(m?.energy??0,m?.j3??0,l,c,h)),e.chosen.update(r.history.frames,{mass:l,g:c,length:h},d?.on?d.store.history.frames:null),d?.update(Tt("plots").clientWidth-8),e.tools.update(o?.x??null,o?.t??null,o?Math.hypot(...o.v):0),t.write();const _=r.latest(),y=_?fg(_,l,c,h,r.work):null;e.energy.draw(y,r.status?.model!=="ideal"),e.tools.describe(bg(o,y),s);let p=performance.now();n.add("plots setData",p-u),e.portraits.update(r.history,o,e.analyses.veff,l,c,h),e.portraits.updateEM(e.analyses.em,o),u=performance.now(),n.add("portraits",u-p),e.reduced.update(o,h),p=performance.now(),n.add("reduced view",p-u),e.data.update(o,r),n.add("data panel",performance.now()-p)}function qA(i,e,t,n){let s=0,r=performance.now();const a=new dT(100),o=new fT,l=c=>{gi("loop"),i.store.advancePlayhead((c-r)/1e3),r=c,XA(i,o,n)&&(s++,gi("first render"),i.store.frames.length>0&&gi("first frame drawn")),a.due(c)&&($A(i,e,t,n,c),gi("panels drawn")),requestAnimationFrame(l)};return requestAnimationFrame(l),()=>s}function YA(i){i.software&&(Tt("render").textContent=` · ${R("page.software")}`,Tt("render").title=R("page.softwareHelp",{renderer:i.renderer??""}));const e=new uT(Tt("scene"),i);return e.renderer.domElement.setAttribute("role","img"),e.renderer.domElement.setAttribute("aria-label",R("page.scene")),e}function KA(i,e,t,n,s,r){const{store:a,scene:o,session:l}=i;return{...r,store:a,send:l.send,screenshot:()=>o.screenshot(),bobOnScreen:()=>o.bobOnScreen(),handleOnScreen:()=>o.handleOnScreen(),quality:()=>t,frameCosts:()=>n.take(),twinOnScreen:()=>o.twinOnScreen(),extras:()=>l.twin?.extras?.running()??[],extrasOnScreen:()=>o.extrasOnScreen(),instrumentsOnScreen:()=>o.instrumentsOnScreen(),tones:()=>e.tools.tones,sphereOnScreen:()=>o.sphereOnScreen(),separation:()=>l.twin?.separationNow()??{t:[],d:[]},energy:()=>e.energy.shown,plotScales:()=>e.plots.scales(),measuredPoints:()=>o.measuredPoints(),engine:()=>s}}async function ZA(){gi("start");const i=await qg(),e=GA();RT();const t=new Cu,n=new CT(Tt("message")),s=n.explain,[r,a]=await Promise.all([Zc("api/schema"),Zc("api/scenarios")]);t.tickHz=r.tick_hz,gi("schema");const o=ZE(JE(),window.devicePixelRatio),l=YA(o);gi("scene");const c=new pT,h=new _T(Tt("plots")),d=new Sv(Tt("plots"),V=>c.add("plots drawn (uPlot)",V)),u=new wv(Tt("portraits")),m=new Ru(Tt("reduced"),o),_=new x0(Tt("data")),y={...Pu},p=new OT(t,y,s),f=new kT(t,s);f.conn=e.conn;const x={store:t,scene:l,view:y,session:f,explain:s},{toolbar:A,help:M,lastVideo:C}=YT(x),b=dA(x);JT(x,M,b);const g=new gT(Tt("energy")),w=OA(x,r,a,p);l.setStereo(y.stereo);const F=new Av(t,m,s),L=new MT(Tt("tools"),t,r.methods,Uc(window.location),{send:f.send,explain:s});f.twin=L,L.extras=new ST(Tt("tools"),Uc(window.location),s),p.attach(h,L),new wT(Tt("tools")),xg(w.gui),gi("panels"),VA(x,e.held,{controls:w,tools:b,toolbar:A,portraits:u,energy:g},n,p,F,c),WA(x);const D={plots:d,chosen:h,portraits:u,reduced:m,data:_,energy:g,tools:b,analyses:F};let z=()=>0;window.pendulab=KA(x,D,o,c,i,{drawn:()=>z(),lastVideo:C,twin:L.store}),z=qA(x,D,p,c)}ZA().catch(i=>{const e=document.getElementById("offline");e&&(e.textContent=`${R("conn.noStart")} ${i instanceof Error?i.message:String(i)}`,e.hidden=!1),console.error(i)});
