(function(){const e=document.createElement("link").relList;if(e&&e.supports&&e.supports("modulepreload"))return;for(const s of document.querySelectorAll('link[rel="modulepreload"]'))n(s);new MutationObserver(s=>{for(const r of s)if(r.type==="childList")for(const a of r.addedNodes)a.tagName==="LINK"&&a.rel==="modulepreload"&&n(a)}).observe(document,{childList:!0,subtree:!0});function t(s){const r={};return s.integrity&&(r.integrity=s.integrity),s.referrerPolicy&&(r.referrerPolicy=s.referrerPolicy),s.crossOrigin==="use-credentials"?r.credentials="include":s.crossOrigin==="anonymous"?r.credentials="omit":r.credentials="same-origin",r}function n(s){if(s.ep)return;s.ep=!0;const r=t(s);fetch(s.href,r)}})();const yg=["t","x1","x2","x3","v1","v2","v3","energy","j3","tension","power","a1","a2","a3","pivot1","pivot2","pivot3","taut","error_x"],Mg={fields:yg},Hh=Mg.fields,bg=Hh.length,Ja=8*bg;function gn(i){const e=Hh.indexOf(i);if(e<0)throw new Error(`frame.json lacks the field ${i}`);return e}const yi={t:gn("t"),x:[gn("x1"),gn("x2"),gn("x3")],v:[gn("v1"),gn("v2"),gn("v3")],energy:gn("energy"),j3:gn("j3"),tension:gn("tension"),power:gn("power"),a:[gn("a1"),gn("a2"),gn("a3")],pivot:[gn("pivot1"),gn("pivot2"),gn("pivot3")],taut:gn("taut"),errorX:gn("error_x")};class fi extends Error{}function wg(i){if(i.byteLength===0||i.byteLength%Ja!==0)throw new fi(`a frame message has a multiple of ${Ja} bytes, got ${i.byteLength}`);const e=new DataView(i),t=i.byteLength/Ja,n=[];for(let s=0;s<t;s++){const r=s*Ja,a=l=>e.getFloat64(r+8*l,!0),o=l=>[a(l[0]),a(l[1]),a(l[2])];n.push({t:a(yi.t),x:o(yi.x),v:o(yi.v),energy:a(yi.energy),j3:a(yi.j3),tension:a(yi.tension),power:a(yi.power),a:o(yi.a),pivot:o(yi.pivot),taut:a(yi.taut)!==0,errorX:a(yi.errorX)})}return n}function Hu(i){return typeof i=="object"&&i!==null&&!Array.isArray(i)}function Eg(i){let e;try{e=JSON.parse(i)}catch(t){throw new fi(`notice is not JSON: ${String(t)}`)}if(!Hu(e))throw new fi("notice is not a JSON object");if(e.type==="error"&&typeof e.message=="string"){const t=typeof e.command=="string"?e.command:null;return{type:"error",message:e.message,command:t}}if(e.type==="status"){const t=e.params;if(!Hu(t)||typeof e.epoch!="number"||typeof e.method!="string")throw new fi("status notice lacks epoch, method or params");const n=e.frame_fields;if(Array.isArray(n)&&n.join(",")!==Hh.join(","))throw new fi(`server frame layout ${n.join(",")} differs from the page's`);return e}if(e.type==="event")return Tg(e);throw new fi(`unknown notice type ${JSON.stringify(e.type)}`)}function Nl(i){return typeof i=="number"&&Number.isFinite(i)}function Tg(i){const{kind:e,t,energy_lost:n,x:s,epoch:r}=i,a=i.skipped??0;if(e!=="slack"&&e!=="taut")throw new fi(`event notice: kind ${JSON.stringify(e)} is not "slack" or "taut"`);if(!Nl(t))throw new fi("event notice: t is not a finite number");if(!Nl(n)||n<0)throw new fi("event notice: energy_lost is not a finite number ≥ 0");if(!Array.isArray(s)||s.length!==3||!s.every(Nl))throw new fi("event notice: x is not 3 finite numbers");if(!Number.isInteger(r)||!Number.isInteger(a)||a<0)throw new fi("event notice: epoch or skipped is not an integer");return{type:"event",kind:e,t,energy_lost:n,x:[s[0],s[1],s[2]],epoch:r,skipped:a}}function Gu(i){const e=i.protocol==="https:"?"wss:":"ws:",t=i.pathname.endsWith("/")?i.pathname:i.pathname.replace(/[^/]*$/,"");return`${e}//${i.host}${t}ws`}function Il(i,e,t,n=20){const s=Date.now()+t;return new Promise(r=>{const a=()=>{(i()??-1)>=e()?r(!0):Date.now()>=s?r(!1):setTimeout(a,n)};a()})}class sp{constructor(e,t){this.url=e,this.handlers=t,this.open()}url;handlers;sent=0;ws=null;retryMs=500;closedByUs=!1;open(){const e=new WebSocket(this.url);e.binaryType="arraybuffer",e.onopen=()=>{this.retryMs=500,this.sent=0,this.handlers.onOpen()},e.onmessage=t=>{try{t.data instanceof ArrayBuffer?this.handlers.onFrames(wg(t.data)):typeof t.data=="string"&&this.handlers.onNotice(Eg(t.data))}catch(n){if(n instanceof fi)this.handlers.onProtocolError(n.message);else throw n}},e.onclose=()=>{this.ws=null,this.handlers.onClose(),this.closedByUs||(setTimeout(()=>this.open(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))},this.ws=e}get isOpen(){return this.ws!==null&&this.ws.readyState===WebSocket.OPEN}send(e){return!this.isOpen||this.ws===null?!1:(this.ws.send(JSON.stringify(e)),this.sent++,!0)}close(){this.closedByUs=!0,this.ws?.close()}}const ol={"page.title":"Pendulab lab — the spherical pendulum","page.units":"SI units, z up","page.scene":"3-D view of the pendulum (drag to orbit, scroll to zoom)","page.panel":"controls and measurements","page.software":"software WebGL: no antialiasing","conn.connected":"connected","conn.retrying":"disconnected: retrying…","conn.gone":"The lab’s server is not answering: the pendulum has stopped. Is pendulab serve still running? Trying to reconnect …","conn.noStart":"The lab could not start:","toolbar.label":"run controls","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Reset","toolbar.stepShort":"Step","toolbar.recordShort":"● Record","toolbar.recordStopShort":"■ Stop","toolbar.start":"start (Space)","toolbar.pause":"pause (Space)","toolbar.reset":"reset to the start (R)","toolbar.step":"one step (S)","toolbar.record":"record a video (WebM)","toolbar.recordStop":"stop recording and download the video","toolbar.help":"keyboard shortcuts and colour key (?)","toolbar.language":"language","toolbar.collapse":"hide the panel","toolbar.expand":"show the panel","gui.title":"Pendulab lab","gui.pendulum":"Pendulum","gui.model":"model","gui.modelParams":"{model}: parameters","gui.paramHelp":"{help} — key {name} [{unit}]; allowed: {range}; default {default}","gui.integrator":"Integrator","gui.method":"method","gui.order":"order {n}","gui.symplectic":"symplectic","gui.adaptive":"adaptive","method.rk4":"Runge–Kutta, 4th order (classic; drifts off the sphere)","method.dop853":"Adaptive, very accurate (Dormand–Prince, 8th order)","method.rattle":"Symplectic (RATTLE, 2nd order; the default)","method.rattle4":"Symplectic (RATTLE, 4th order)","method.rattle6":"Symplectic (RATTLE, 6th order)","method.rattle8":"Symplectic (RATTLE, 8th order)","method.rkmk4":"Rotation steps on the sphere (Munthe-Kaas, 4th order)","method.rk4_angles":"Runge–Kutta 4 in angles (breaks down at the poles)","method.other":"{name} (order {n})","kind.generic":"goes round and round in a rosette","kind.conical":"circles at one height (conical pendulum)","kind.planar":"swings to and fro in a plane","kind.planar_rotating":"swings over the top in a plane","kind.separatrix":"creeps towards the top for ever","kind.rest":"at rest","kind.great_circle":"goes round a great circle (no gravity)","data.energy":"energy E","data.energyChange":"energy change E − E₀","data.spin":"angular momentum about the vertical J₃","data.spinChange":"its change J₃ − J₃(0)","data.height":"height z","data.turning":"lowest and highest height z₁, z₂","gui.dtRange":"dt must be between {min} and {max} s","gui.dtHelp":"step size of fixed-step methods; {min} … {max} s (dop853 chooses its own)","gui.run":"Run","gui.timeScale":"time scale [×]","gui.tsRange":"the time scale must be between {min} and {max}","gui.tsHelp":"simulated seconds per second (slow motion below 1); {min} … {max}","gui.stepN":"steps per step","gui.scenario":"scenario","gui.view":"View","gui.trail":"trail","gui.trailSeconds":"trail [s]","gui.sphere":"sphere of reach","gui.axes":"axes","gui.topView":"top view","gui.stereo":"stereo","gui.stereoHelp":"anaglyph: red–cyan glasses; side by side: a stereo viewer","stereo.off":"off","stereo.anaglyph":"anaglyph","stereo.sideBySide":"side by side","gui.vectors":"Vectors","gui.origin":"origin {axis} [m]","gui.originHelp":"origin of L and τ relative to the pivot (0: the pivot)","gui.export":"Share and export","gui.csv":"download trajectory (CSV)","gui.toml":"download scenario (TOML)","gui.tomlHelp":"the scenario as it stands (model, parameters, start, method) as a file for `pendulab run`","gui.png":"screenshot (PNG)","gui.link":"copy link to this lab (what it carries: on copying)","vec.velocity":"velocity v","vec.velocityHelp":"v [m/s], drawn as 0.25 s of travel","vec.momentum":"momentum m v","vec.momentumHelp":"m v [kg m/s], 0.25 m per kg m/s","vec.gravity":"gravity m g","vec.gravityHelp":"the weight m g d [N] (d: the gravity direction); forces: m·max(|g|, 1) N ↔ 0.5 l","vec.tension":"rod force (tension)","vec.tensionHelp":"the rod force −T x/|x| [N], T from the server","vec.net":"net force m a","vec.netHelp":"m a [N]: a = ẍ computed by the server’s core (relative to the pivot)","vec.angularMomentum":"angular momentum L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] about the origin o, drawn from o","vec.torque":"torque τ","vec.torqueHelp":"τ = (x − o) × m a [N m] about the origin o, drawn from o; dL/dt = τ","data.now":"Now (from the server)","data.exact":"Exact solution of this orbit","data.tension":"tension","data.tensionMin":"tension min","data.tensionMax":"tension max","data.method":"method","data.state":"state","data.paused":"paused","data.running":"running","data.lagging":" (lagging: slower than asked)","data.model":"model","data.kind":"kind of motion","data.periodZ":"z-period T_z","data.swingPeriod":"swing period T","data.advance":"azimuthal advance Δφ per T_z","data.rotation":"rotation number W = Δφ/2π","data.reduced":"reduced view (σ₁, σ₂, σ₃): J₃ surface ∩ energy plane","portrait.phase":"phase portrait: vertical speed ż against height z","portrait.veff":"effective potential V_eff(θ); energy E dashed, θ now dotted","portrait.em":"energy–momentum map: E against J₃ (dot: now)","portrait.orbit":"orbit","portrait.emBoundary":"boundary (conical orbits)","note.spring":"the swinging spring leaves the sphere (its length varies): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.string":"the string goes slack (free flight inside the sphere): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.exactIdeal":"the exact solution exists for the ideal pendulum only; this is the {model} model","note.reducedIdeal":"the reduced view is the ideal pendulum’s; this is the {model} model","event.slack":"the string went slack (tension 0: free flight)","event.taut":"the string snapped taut, lost {lost} J","event.skippedOne":" ({n} earlier event of this moment not shown)","event.skippedMany":" ({n} earlier events of this moment not shown)","event.slackRow":"went slack","event.tautRow":"snapped taut","event.tautValue":"t = {t} s, lost {lost}","data.power":"power P = dE/dt","data.springForce":"spring force k(|r| − l₀)","data.springLength":"spring length |r|","data.stretch":"stretch |r| − l₀","data.string":"string","data.slackZero":"slack (0)","data.slack":"slack: free flight, |x| = {r} m","data.taut":"taut","data.events":"events","data.noEvents":"none yet (slack, snaps)","data.z3":"z₃ (outside)","data.dynamic":"Δφ dynamic","data.geometric":"Δφ geometric","data.error":"position error |Δx|","data.errorRel":"position error / l","data.errorHow":"error obtained by","data.errorPaused":"estimate paused (the server’s work budget is used up; it catches up when there is time)","data.errorNone":"no estimate","data.howExact":"the true error: against the exact solution (since t = {since} s)","data.howRichardson":"estimate: Richardson against a companion at dt/2 = {dt} s, order p = {p} (since t = {since} s)","data.howCompanion":"estimate: a companion run at rtol = {rtol} (since t = {since} s)","page.softwareHelp":"{renderer}: drawn without multisampling for the frame rate","tools.start":"Start angle","tools.thetaHelp":"θ₀: the angle from the downward vertical, in degrees (0 … 180)","tools.phiHelp":"φ₀: the azimuth around the vertical, in degrees","tools.phiDotHelp":"φ̇₀: how fast the bob starts going round, in degrees per second (0: a planar swing)","tools.setStart":"set start","tools.world":"Gravity and friction","tools.gravity":"gravity","tools.friction":"friction","tools.frictionHelp":"linear damping c [1/s]: the force −m c v; on the ideal pendulum it switches to the damped model","tools.noFriction":"the {model} model has no friction parameter","tools.now":"Angles now","tools.stopwatch":"Stopwatch (simulated time)","tools.swStart":"start","tools.swStop":"stop","tools.swLap":"lap","tools.swReset":"reset","tools.period":"Period timer","tools.periodHelp":"measured from the motion: the lowest points of the bob; a swing’s period ends when the bob passes the bottom again the same way. Compared with the exact value (ideal pendulum) or the theory (small-swing formula with friction)","tools.periodCount":"mean over {n} periods","tools.periodCountZ":"mean over {n} lowest-to-lowest times","tools.periodWait":"waiting for the bob to pass its lowest point twice","tools.motion":"motion","tools.kindNone":"—","tools.kindSwing":"swings to and fro","tools.kindOver":"swings over the top","tools.kindOrbit":"goes round (never through the bottom)","tools.periodSwing":"period T [s]","tools.periodZ":"lowest point to lowest point [s]","tools.advance":"turn between lowest points [°]","tools.precession":"pattern turns per round [°]","tools.amplitude":"amplitude (largest angle) [°]","tools.band":"angle from the vertical [°]","tools.theory":"theory","tools.measured":"measured","tools.exact":"exact","tools.difference":"difference","tools.overlays":"Ruler and protractor","tools.ruler":"ruler (metres)","tools.protractor":"protractor (θ in degrees)","describe.none":"no motion yet","describe.text":"angle {theta}° from the vertical, {dir}, speed {v} m/s","describe.rest":"at rest","describe.turning":"at a turning point","describe.rising":"rising","describe.falling":"falling towards the bottom","describe.energy":"; energy {k} % kinetic, {u} % potential","describe.lost":", {p} % lost to friction","describe.toggle":"describe the motion every 5 s (screen readers; D: now)","tools.mystery":"mystery planet (find g from the period)","tools.reveal":"reveal g","tools.mysteryOn":"a mystery planet: time the swings and work out g = 4π² l / T²","tools.revealed":"the mystery planet’s g is {g} m/s²","start.notNumber":"{name} must be a number","start.thetaRange":"θ₀ = {value}° is not allowed: 0 … 180°","gravity.custom":"custom","gravity.earth":"Earth","gravity.moon":"Moon","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"zero","gravity.negative":"negative (upwards)","energy.title":"Energy","energy.kinetic":"kinetic","energy.potential":"potential","energy.lost":"lost","energy.total":"total","plot.dE":"energy drift |ΔE|/E_s (log)","plot.dJ3":"J₃ drift |ΔJ₃|/J_s (log)","plot.z":"height z(t)","plot.tension":"rod tension T(t)","plot.time":"time t [s]","plot.floor":"float64 roundoff 2.2e-16","chosen.title":"Plot any variables","chosen.xAxis":"across","chosen.yAxis":"up","var.t":"time t","var.theta":"angle θ","var.phi":"azimuth φ","var.x":"x","var.y":"y","var.z":"height z","var.zdot":"vertical speed ż","var.speed":"speed |v|","var.energy":"energy E","var.kinetic":"kinetic energy K","var.potential":"potential energy U","var.j3":"angular momentum J₃","var.tension":"tension T","var.power":"power P","var.radius":"distance |x|","twin.title":"Two pendulums","twin.mode":"second pendulum","twin.off":"off","twin.epsilon":"start differs by ε","twin.method":"another integrator","twin.damped":"damped beside this one","twin.own":"its own length, mass and start (side by side)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"the second pendulum needs a length > 0, a mass > 0 and a start angle 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"period T [s] (periods)","twin.methodPick":"integrator","twin.damping":"damping [1/s]","twin.start":"start both","twin.bad":"ε must be a number and the damping ≥ 0","twin.first":"pendulum 1","twin.second":"pendulum 2","twin.separation":"separation of the bobs |r₁ − r₂| [m]","help.title":"Keyboard shortcuts and colour key","help.space":"start / pause","help.r":"reset to the start","help.s":"one step (paused)","help.arrows":"on a focused slider: one step down / up","help.page":"on a focused slider: ten steps","help.camera":"on the 3-D view: turn the camera / zoom","help.bobKeys":"on the 3-D view: move the bob’s start by 1° (pauses)","help.describe":"describe the motion now (screen readers)","help.tab":"move between controls","help.help":"this overlay","help.esc":"close this overlay","help.colours":"Colours","help.close":"close","help.bob":"bob","help.trail":"trail","help.twin":"second pendulum","help.ruler":"ruler and protractor","msg.notConnected":"not connected to the server","link.scenario":"the scenario (model, parameters, method, start)","link.paused":"paused","link.pausedAt":"paused at {t} s","link.view":"view: {list}","link.plot":"plot {y} against {x}","link.twin":"second pendulum {what}","link.lang":"language {lang}","msg.linkCopied":"link copied; it carries {what}","msg.dragged":"start set by dragging (at rest there): press start to release it","msg.pull":"pull the arrow to set the start velocity","msg.capped":" (capped: the most the arrow sets, 4√(g l))","msg.velocitySet":"start velocity set: |v| = {v} m/s{cap}; press start to run from it","msg.velocity":"start velocity |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} is not allowed: {allowed} ({range})","msg.recording":"recording the view…","msg.recorded":"video saved ({mb} MB, WebM)","msg.noRecording":"this browser cannot record the view ({why})","fit.title":"Measured data","fit.load":"Load measured data…","fit.help":"a CSV file of measurements in SI units (columns t, x, y, z or x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): the server fits the pendulum to it, loads the fitted motion and draws the measured path dotted beside it","fit.model":"model","fit.params":"fit","fit.paramsDefault":"what the data determine","fit.paramsHelp":"the parameters to fit, comma separated (e.g. length,g,damping,pivot); empty: what the data can determine","fit.clear":"clear measured path","fit.running":"fitting {name} …","fit.noPath":"(frame-free data: no measured path to draw)","fit.failed":"fit: {why}","fit.loaded":"fitted {name}: the fitted motion is loaded, the measured path dotted in gold"},Ag={"page.title":"Pendulab-Labor — das Kugelpendel","page.units":"SI-Einheiten, z nach oben","page.scene":"3-D-Ansicht des Pendels (ziehen zum Drehen, scrollen zum Zoomen)","page.panel":"Steuerung und Messungen","page.software":"Software-WebGL: ohne Kantenglättung","conn.connected":"verbunden","conn.retrying":"getrennt: neuer Versuch…","conn.gone":"Der Server des Labors antwortet nicht: das Pendel steht. Läuft pendulab serve noch? Neuer Verbindungsversuch …","conn.noStart":"Das Labor konnte nicht starten:","toolbar.label":"Ablauf","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Zurück","toolbar.stepShort":"Schritt","toolbar.recordShort":"● Aufnahme","toolbar.recordStopShort":"■ Stopp","toolbar.start":"Start (Leertaste)","toolbar.pause":"Pause (Leertaste)","toolbar.reset":"zurück zum Start (R)","toolbar.step":"ein Schritt (S)","toolbar.record":"Video aufnehmen (WebM)","toolbar.recordStop":"Aufnahme beenden und Video speichern","toolbar.help":"Tastenkürzel und Farben (?)","toolbar.language":"Sprache","toolbar.collapse":"Leiste ausblenden","toolbar.expand":"Leiste einblenden","gui.title":"Pendulab-Labor","gui.pendulum":"Pendel","gui.model":"Modell","gui.modelParams":"{model}: Parameter","gui.paramHelp":"{help} — Schlüssel {name} [{unit}]; erlaubt: {range}; Vorgabe {default}","gui.integrator":"Integrator","gui.method":"Verfahren","gui.order":"Ordnung {n}","gui.symplectic":"symplektisch","gui.adaptive":"adaptiv","method.rk4":"Runge–Kutta, 4. Ordnung (klassisch; verlässt die Kugel)","method.dop853":"Adaptiv, sehr genau (Dormand–Prince, 8. Ordnung)","method.rattle":"Symplektisch (RATTLE, 2. Ordnung; Voreinstellung)","method.rattle4":"Symplektisch (RATTLE, 4. Ordnung)","method.rattle6":"Symplektisch (RATTLE, 6. Ordnung)","method.rattle8":"Symplektisch (RATTLE, 8. Ordnung)","method.rkmk4":"Drehschritte auf der Kugel (Munthe-Kaas, 4. Ordnung)","method.rk4_angles":"Runge–Kutta 4 in Winkeln (versagt an den Polen)","method.other":"{name} ({n}. Ordnung)","kind.generic":"kreist in einer Rosette","kind.conical":"kreist in einer Höhe (Kegelpendel)","kind.planar":"schwingt in einer Ebene hin und her","kind.planar_rotating":"schwingt in einer Ebene über den höchsten Punkt","kind.separatrix":"kriecht für immer auf den höchsten Punkt zu","kind.rest":"in Ruhe","kind.great_circle":"läuft auf einem Großkreis (ohne Schwerkraft)","data.energy":"Energie E","data.energyChange":"Energieänderung E − E₀","data.spin":"Drehimpuls um die Senkrechte J₃","data.spinChange":"seine Änderung J₃ − J₃(0)","data.height":"Höhe z","data.turning":"tiefste und höchste Höhe z₁, z₂","gui.dtRange":"dt muss zwischen {min} und {max} s liegen","gui.dtHelp":"Schrittweite der Verfahren mit festem Schritt; {min} … {max} s (dop853 wählt selbst)","gui.run":"Ablauf","gui.timeScale":"Zeitfaktor [×]","gui.tsRange":"der Zeitfaktor muss zwischen {min} und {max} liegen","gui.tsHelp":"simulierte Sekunden pro Sekunde (Zeitlupe unter 1); {min} … {max}","gui.stepN":"Schritte pro Schritt","gui.scenario":"Szenario","gui.view":"Ansicht","gui.trail":"Spur","gui.trailSeconds":"Spur [s]","gui.sphere":"Kugel der Reichweite","gui.axes":"Achsen","gui.topView":"Draufsicht","gui.stereo":"Stereo","gui.stereoHelp":"Anaglyphe: Rot-Cyan-Brille; nebeneinander: ein Stereobetrachter","stereo.off":"aus","stereo.anaglyph":"Anaglyphe (Rot–Cyan)","stereo.sideBySide":"nebeneinander","gui.vectors":"Vektoren","gui.origin":"Ursprung {axis} [m]","gui.originHelp":"Ursprung von L und τ relativ zum Aufhängepunkt (0: der Aufhängepunkt)","gui.export":"Teilen und exportieren","gui.csv":"Bahn herunterladen (CSV)","gui.toml":"Szenario herunterladen (TOML)","gui.tomlHelp":"das Szenario, wie es ist (Modell, Parameter, Start, Verfahren), als Datei für `pendulab run`","gui.png":"Bildschirmfoto (PNG)","gui.link":"Link zu diesem Labor kopieren (was er enthält: beim Kopieren)","vec.velocity":"Geschwindigkeit v","vec.velocityHelp":"v [m/s], gezeichnet als Weg in 0,25 s","vec.momentum":"Impuls m v","vec.momentumHelp":"m v [kg m/s], 0,25 m pro kg m/s","vec.gravity":"Gewichtskraft m g","vec.gravityHelp":"die Gewichtskraft m g d [N] (d: Richtung der Schwerkraft); Kräfte: m·max(|g|, 1) N ↔ 0,5 l","vec.tension":"Stangenkraft (Zugkraft)","vec.tensionHelp":"die Stangenkraft −T x/|x| [N], T vom Server","vec.net":"Gesamtkraft m a","vec.netHelp":"m a [N]: a = ẍ vom Kern des Servers berechnet (relativ zum Aufhängepunkt)","vec.angularMomentum":"Drehimpuls L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] um den Ursprung o, von o aus gezeichnet","vec.torque":"Drehmoment τ","vec.torqueHelp":"τ = (x − o) × m a [N m] um den Ursprung o, von o aus gezeichnet; dL/dt = τ","data.now":"Jetzt (vom Server)","data.exact":"Exakte Lösung dieser Bahn","data.tension":"Zugkraft","data.tensionMin":"Zugkraft min","data.tensionMax":"Zugkraft max","data.method":"Verfahren","data.state":"Zustand","data.paused":"angehalten","data.running":"läuft","data.lagging":" (hinkt nach: langsamer als verlangt)","data.model":"Modell","data.kind":"Art der Bewegung","data.periodZ":"z-Periode T_z","data.swingPeriod":"Schwingungsdauer T","data.advance":"Azimutvorschub Δφ pro T_z","data.rotation":"Umlaufzahl W = Δφ/2π","data.reduced":"reduzierte Ansicht (σ₁, σ₂, σ₃): J₃-Fläche ∩ Energieebene","portrait.phase":"Phasenporträt: Vertikalgeschwindigkeit ż gegen Höhe z","portrait.veff":"effektives Potential V_eff(θ); Energie E gestrichelt, θ jetzt gepunktet","portrait.em":"Energie-Impuls-Abbildung: E gegen J₃ (Punkt: jetzt)","portrait.orbit":"Bahn","portrait.emBoundary":"Rand (konische Bahnen)","note.spring":"die Schwingfeder verlässt die Kugel (ihre Länge ändert sich): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.string":"die Schnur wird schlaff (freier Flug in der Kugel): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.exactIdeal":"die exakte Lösung gibt es nur für das ideale Pendel; dies ist das Modell {model}","note.reducedIdeal":"die reduzierte Ansicht ist die des idealen Pendels; dies ist das Modell {model}","event.slack":"die Schnur wurde schlaff (Zugkraft 0: freier Flug)","event.taut":"die Schnur straffte sich ruckartig, verlor {lost} J","event.skippedOne":" ({n} früheres Ereignis dieses Moments nicht gezeigt)","event.skippedMany":" ({n} frühere Ereignisse dieses Moments nicht gezeigt)","event.slackRow":"schlaff geworden","event.tautRow":"gestrafft","event.tautValue":"t = {t} s, verlor {lost}","data.power":"Leistung P = dE/dt","data.springForce":"Federkraft k(|r| − l₀)","data.springLength":"Federlänge |r|","data.stretch":"Dehnung |r| − l₀","data.string":"Schnur","data.slackZero":"schlaff (0)","data.slack":"schlaff: freier Flug, |x| = {r} m","data.taut":"straff","data.events":"Ereignisse","data.noEvents":"noch keine (schlaff, Straffen)","data.z3":"z₃ (außerhalb)","data.dynamic":"Δφ dynamisch","data.geometric":"Δφ geometrisch","data.error":"Lagefehler |Δx|","data.errorRel":"Lagefehler / l","data.errorHow":"Fehler ermittelt durch","data.errorPaused":"Schätzung pausiert (das Rechenbudget des Servers ist aufgebraucht; sie holt auf, sobald Zeit ist)","data.errorNone":"keine Schätzung","data.howExact":"den wahren Fehler: gegen die exakte Lösung (seit t = {since} s)","data.howRichardson":"Schätzung: Richardson gegen einen Begleitlauf mit dt/2 = {dt} s, Ordnung p = {p} (seit t = {since} s)","data.howCompanion":"Schätzung: einen Begleitlauf mit rtol = {rtol} (seit t = {since} s)","page.softwareHelp":"{renderer}: ohne Multisampling gezeichnet, für die Bildrate","tools.start":"Startwinkel","tools.thetaHelp":"θ₀: der Winkel zur Senkrechten nach unten, in Grad (0 … 180)","tools.phiHelp":"φ₀: der Winkel um die Senkrechte, in Grad","tools.phiDotHelp":"φ̇₀: wie schnell die Kugel zu kreisen beginnt, in Grad pro Sekunde (0: ebene Schwingung)","tools.setStart":"Start setzen","tools.world":"Schwerkraft und Reibung","tools.gravity":"Schwerkraft","tools.friction":"Reibung","tools.frictionHelp":"lineare Dämpfung c [1/s]: die Kraft −m c v; beim idealen Pendel wird auf das gedämpfte Modell gewechselt","tools.noFriction":"das Modell {model} hat keinen Reibungsparameter","tools.now":"Winkel jetzt","tools.stopwatch":"Stoppuhr (simulierte Zeit)","tools.swStart":"Start","tools.swStop":"Stopp","tools.swLap":"Runde","tools.swReset":"Null","tools.period":"Periodenmessung","tools.periodHelp":"aus der Bewegung gemessen: den tiefsten Punkten der Kugel; eine Periode der Schwingung endet, wenn die Kugel den tiefsten Punkt wieder in derselben Richtung durchläuft. Verglichen mit dem exakten Wert (ideales Pendel) oder der Theorie (Formel für kleine Ausschläge mit Reibung)","tools.periodCount":"Mittel über {n} Perioden","tools.periodCountZ":"Mittel über {n} Zeiten von tiefstem zu tiefstem Punkt","tools.periodWait":"wartet, bis die Kugel zweimal den tiefsten Punkt durchlaufen hat","tools.motion":"Bewegung","tools.kindNone":"—","tools.kindSwing":"schwingt hin und her","tools.kindOver":"schwingt über den höchsten Punkt","tools.kindOrbit":"kreist (nie durch den tiefsten Punkt)","tools.periodSwing":"Periode T [s]","tools.periodZ":"tiefster bis tiefster Punkt [s]","tools.advance":"Drehung zwischen tiefsten Punkten [°]","tools.precession":"Bahn dreht sich pro Umlauf um [°]","tools.amplitude":"Amplitude (größter Winkel) [°]","tools.band":"Winkel zur Senkrechten [°]","tools.theory":"Theorie","tools.measured":"gemessen","tools.exact":"exakt","tools.difference":"Abweichung","tools.overlays":"Lineal und Winkelmesser","tools.ruler":"Lineal (Meter)","tools.protractor":"Winkelmesser (θ in Grad)","describe.none":"noch keine Bewegung","describe.text":"Winkel {theta}° zur Senkrechten, {dir}, Geschwindigkeit {v} m/s","describe.rest":"in Ruhe","describe.turning":"am Umkehrpunkt","describe.rising":"steigt","describe.falling":"fällt zum tiefsten Punkt","describe.energy":"; Energie {k} % kinetisch, {u} % potentiell","describe.lost":", {p} % durch Reibung verloren","describe.toggle":"Bewegung alle 5 s beschreiben (Bildschirmleser; D: jetzt)","tools.mystery":"geheimer Planet (g aus der Periode bestimmen)","tools.reveal":"g zeigen","tools.mysteryOn":"ein geheimer Planet: Schwingungen stoppen und g = 4π² l / T² ausrechnen","tools.revealed":"g des geheimen Planeten ist {g} m/s²","start.notNumber":"{name} muss eine Zahl sein","start.thetaRange":"θ₀ = {value}° ist nicht erlaubt: 0 … 180°","gravity.custom":"eigene","gravity.earth":"Erde","gravity.moon":"Mond","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"null","gravity.negative":"negativ (nach oben)","energy.title":"Energie","energy.kinetic":"kinetisch","energy.potential":"potentiell","energy.lost":"verloren","energy.total":"gesamt","plot.dE":"Energiedrift |ΔE|/E_s (log)","plot.dJ3":"J₃-Drift |ΔJ₃|/J_s (log)","plot.z":"Höhe z(t)","plot.tension":"Stangenkraft T(t)","plot.time":"Zeit t [s]","plot.floor":"float64-Rundung 2,2e-16","chosen.title":"Beliebige Größen zeichnen","chosen.xAxis":"waagerecht","chosen.yAxis":"senkrecht","var.t":"Zeit t","var.theta":"Winkel θ","var.phi":"Azimut φ","var.x":"x","var.y":"y","var.z":"Höhe z","var.zdot":"Vertikalgeschwindigkeit ż","var.speed":"Geschwindigkeit |v|","var.energy":"Energie E","var.kinetic":"kinetische Energie K","var.potential":"potentielle Energie U","var.j3":"Drehimpuls J₃","var.tension":"Zugkraft T","var.power":"Leistung P","var.radius":"Abstand |x|","twin.title":"Zwei Pendel","twin.mode":"zweites Pendel","twin.off":"aus","twin.epsilon":"Start um ε verschieden","twin.method":"anderer Integrator","twin.damped":"gedämpft daneben","twin.own":"eigene Länge, Masse und Start (nebeneinander)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"das zweite Pendel braucht eine Länge > 0, eine Masse > 0 und einen Startwinkel 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"Periode T [s] (Perioden)","twin.methodPick":"Integrator","twin.damping":"Dämpfung [1/s]","twin.start":"beide starten","twin.bad":"ε muss eine Zahl sein und die Dämpfung ≥ 0","twin.first":"Pendel 1","twin.second":"Pendel 2","twin.separation":"Abstand der Kugeln |r₁ − r₂| [m]","help.title":"Tastenkürzel und Farben","help.space":"Start / Pause","help.r":"zurück zum Start","help.s":"ein Schritt (angehalten)","help.arrows":"auf einem Schieberegler: einen Schritt runter / hoch","help.page":"auf einem Schieberegler: zehn Schritte","help.camera":"in der 3-D-Ansicht: Kamera drehen / zoomen","help.bobKeys":"in der 3-D-Ansicht: Start der Kugel um 1° verschieben (hält an)","help.describe":"die Bewegung jetzt beschreiben (Bildschirmleser)","help.tab":"zwischen Bedienelementen wechseln","help.help":"diese Übersicht","help.esc":"diese Übersicht schließen","help.colours":"Farben","help.close":"schließen","help.bob":"Kugel","help.trail":"Spur","help.twin":"zweites Pendel","help.ruler":"Lineal und Winkelmesser","msg.notConnected":"keine Verbindung zum Server","link.scenario":"das Szenario (Modell, Parameter, Verfahren, Start)","link.paused":"angehalten","link.pausedAt":"angehalten bei {t} s","link.view":"Ansicht: {list}","link.plot":"Diagramm {y} gegen {x}","link.twin":"zweites Pendel {what}","link.lang":"Sprache {lang}","msg.linkCopied":"Link kopiert; er enthält {what}","msg.dragged":"Start durch Ziehen gesetzt (dort in Ruhe): Start drücken, um loszulassen","msg.pull":"den Pfeil ziehen, um die Startgeschwindigkeit zu setzen","msg.capped":" (begrenzt: höchstens 4√(g l))","msg.velocitySet":"Startgeschwindigkeit gesetzt: |v| = {v} m/s{cap}; Start drücken","msg.velocity":"Startgeschwindigkeit |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} ist nicht erlaubt: {allowed} ({range})","msg.recording":"die Ansicht wird aufgenommen…","msg.recorded":"Video gespeichert ({mb} MB, WebM)","msg.noRecording":"dieser Browser kann die Ansicht nicht aufnehmen ({why})","fit.title":"Messdaten","fit.load":"Messdaten laden…","fit.help":"eine CSV-Datei mit Messwerten in SI-Einheiten (Spalten t, x, y, z oder x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): der Server passt das Pendel an, lädt die angepasste Bewegung und zeichnet die gemessene Bahn gepunktet daneben","fit.model":"Modell","fit.params":"anpassen","fit.paramsDefault":"was die Daten bestimmen","fit.paramsHelp":"die anzupassenden Parameter, durch Kommas getrennt (z. B. length,g,damping,pivot); leer: was die Daten bestimmen können","fit.clear":"gemessene Bahn löschen","fit.running":"{name} wird angepasst …","fit.noPath":"(Daten ohne Bezugssystem: keine Bahn zu zeichnen)","fit.failed":"Anpassung: {why}","fit.loaded":"{name} angepasst: die angepasste Bewegung ist geladen, die gemessene Bahn golden gepunktet"},Rg={length:["Länge l","Länge der Stange vom Aufhängepunkt zur Kugel"],mass:["Masse m","Masse der Kugel"],g:["Schwerebeschleunigung g","Stärke der Schwerkraft (jedes Vorzeichen; 0 erlaubt)"],damping:["Reibung (lineare Dämpfung) c","Reibungskraft −m c v, proportional zur Geschwindigkeit"],drag:["Luftwiderstand c_q","Kraft −m c_q |v| v, quadratisch in der Geschwindigkeit"],forcing_amplitude:["Antrieb: Stärke A","periodische Kraft pro Masse A cos(ω t + ψ) in Richtung e"],forcing_omega:["Antrieb: Kreisfrequenz ω","wie schnell der Antrieb schwingt"],forcing_phase:["Antrieb: Phase ψ","Phase des Antriebs bei t = 0"],forcing_x:["Antriebsrichtung e: x","x-Komponente der Antriebsrichtung (wird normiert)"],forcing_y:["Antriebsrichtung e: y","y-Komponente der Antriebsrichtung"],forcing_z:["Antriebsrichtung e: z","z-Komponente der Antriebsrichtung"],gravity_x:["Schwerkraftrichtung d: x","x-Komponente der Richtung der Schwerkraft (wird normiert)"],gravity_y:["Schwerkraftrichtung d: y","y-Komponente der Richtung der Schwerkraft"],gravity_z:["Schwerkraftrichtung d: z","z-Komponente der Richtung der Schwerkraft"],frame_rate:["Drehrate des Bezugssystems |Ω|","wie schnell sich das Bezugssystem dreht (Erde: 7,292e-5)"],latitude:["geografische Breite λ","Breite des Ortes (Foucault-Pendel)"],radius:["Auslegerradius R","Abstand des Aufhängepunkts von der Drehachse des Krans"],rate:["Drehrate des Krans ω","wie schnell sich der Ausleger dreht"],height:["Höhe des Aufhängepunkts h","Höhe des Auslegers"],amplitude:["Rüttelamplitude A","Amplitude der senkrechten Schwingung des Aufhängepunkts"],frequency:["Rüttelfrequenz ν","Kreisfrequenz der Schwingung des Aufhängepunkts"],stiffness:["Federkonstante k","Steifigkeit der Feder; die Länge l ist die entspannte Länge"],restitution:["Stoßzahl e","wie elastisch die Schnur beim Straffen zurückfedert (0 … 1)"]},Cg={ideal:"Ideales Pendel",damped:"Gedämpft und angetrieben",rotating:"Auf der drehenden Erde (Foucault)",slewing:"Drehkran",vibrating:"Gerüttelter Aufhängepunkt (Kapitza)",sampled_pivot:"Aufhängepunkt auf vorgegebener Bahn",spring:"Schwingfeder",string:"Pendel an einer Schnur"},Pg={"page.title":"Laboratoire Pendulab — le pendule sphérique","page.units":"unités SI, z vers le haut","page.scene":"vue 3D du pendule (glisser pour tourner, molette pour zoomer)","page.panel":"commandes et mesures","page.software":"WebGL logiciel : sans anticrénelage","conn.connected":"connecté","conn.retrying":"déconnecté : nouvel essai…","conn.gone":"Le serveur du laboratoire ne répond pas : le pendule est arrêté. pendulab serve tourne-t-il encore ? Nouvel essai de connexion …","conn.noStart":"Le laboratoire n’a pas pu démarrer :","toolbar.label":"commandes de marche","toolbar.startShort":"▶ Démarrer","toolbar.pauseShort":"Pause","toolbar.resetShort":"Revenir","toolbar.stepShort":"Pas","toolbar.recordShort":"● Filmer","toolbar.recordStopShort":"■ Arrêter","toolbar.start":"démarrer (Espace)","toolbar.pause":"pause (Espace)","toolbar.reset":"revenir au départ (R)","toolbar.step":"un pas (S)","toolbar.record":"filmer la vue (WebM)","toolbar.recordStop":"arrêter de filmer et télécharger la vidéo","toolbar.help":"raccourcis clavier et légende des couleurs (?)","toolbar.language":"langue","toolbar.collapse":"masquer le panneau","toolbar.expand":"afficher le panneau","gui.title":"Laboratoire Pendulab","gui.pendulum":"Pendule","gui.model":"modèle","gui.modelParams":"{model} : paramètres","gui.paramHelp":"{help} — clé {name} [{unit}] ; permis : {range} ; par défaut {default}","gui.integrator":"Méthode de calcul","gui.method":"méthode","gui.order":"ordre {n}","gui.symplectic":"symplectique","gui.adaptive":"adaptative","method.rk4":"Runge–Kutta, ordre 4 (classique ; quitte la sphère)","method.dop853":"Adaptative, très précise (Dormand–Prince, ordre 8)","method.rattle":"Symplectique (RATTLE, ordre 2 ; par défaut)","method.rattle4":"Symplectique (RATTLE, ordre 4)","method.rattle6":"Symplectique (RATTLE, ordre 6)","method.rattle8":"Symplectique (RATTLE, ordre 8)","method.rkmk4":"Pas de rotation sur la sphère (Munthe-Kaas, ordre 4)","method.rk4_angles":"Runge–Kutta 4 en angles (échoue aux pôles)","method.other":"{name} (ordre {n})","kind.generic":"tourne en rosace","kind.conical":"tourne à hauteur constante (pendule conique)","kind.planar":"oscille dans un plan","kind.planar_rotating":"fait des tours complets dans un plan","kind.separatrix":"monte vers le sommet sans jamais l’atteindre","kind.rest":"au repos","kind.great_circle":"parcourt un grand cercle (sans pesanteur)","data.energy":"énergie E","data.energyChange":"variation de l’énergie E − E₀","data.spin":"moment cinétique autour de la verticale J₃","data.spinChange":"sa variation J₃ − J₃(0)","data.height":"hauteur z","data.turning":"hauteurs la plus basse et la plus haute z₁, z₂","gui.dtRange":"dt doit être entre {min} et {max} s","gui.dtHelp":"pas de temps des méthodes à pas fixe ; {min} … {max} s (dop853 choisit le sien)","gui.run":"Marche","gui.timeScale":"échelle de temps [×]","gui.tsRange":"l’échelle de temps doit être entre {min} et {max}","gui.tsHelp":"secondes simulées par seconde (ralenti en dessous de 1) ; {min} … {max}","gui.stepN":"pas par clic","gui.scenario":"scénario","gui.view":"Vue","gui.trail":"trace","gui.trailSeconds":"trace [s]","gui.sphere":"sphère atteignable","gui.axes":"axes","gui.topView":"vue de dessus","gui.stereo":"stéréo","gui.stereoHelp":"anaglyphe : lunettes rouge–cyan ; côte à côte : visionneuse stéréo","stereo.off":"non","stereo.anaglyph":"anaglyphe (rouge–cyan)","stereo.sideBySide":"côte à côte","gui.vectors":"Vecteurs","gui.origin":"origine {axis} [m]","gui.originHelp":"origine de L et τ par rapport au point de suspension (0 : le point de suspension)","gui.export":"Partager et exporter","gui.csv":"télécharger la trajectoire (CSV)","gui.toml":"télécharger le scénario (TOML)","gui.tomlHelp":"le scénario tel qu’il est (modèle, paramètres, départ, méthode) en fichier pour `pendulab run`","gui.png":"capture d’écran (PNG)","gui.link":"copier le lien vers ce laboratoire (son contenu : à la copie)","vec.velocity":"vitesse v","vec.velocityHelp":"v [m/s], dessinée comme 0,25 s de trajet","vec.momentum":"quantité de mouvement m v","vec.momentumHelp":"m v [kg m/s], 0,25 m par kg m/s","vec.gravity":"poids m g","vec.gravityHelp":"le poids m g d [N] (d : direction de la pesanteur) ; forces : m·max(|g|, 1) N ↔ 0,5 l","vec.tension":"force de la tige (tension)","vec.tensionHelp":"la force de la tige −T x/|x| [N], T venant du serveur","vec.net":"force résultante m a","vec.netHelp":"m a [N] : a = ẍ calculée par le cœur du serveur (par rapport au point de suspension)","vec.angularMomentum":"moment cinétique L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] par rapport à l’origine o, dessiné depuis o","vec.torque":"moment de force τ","vec.torqueHelp":"τ = (x − o) × m a [N m] par rapport à l’origine o, dessiné depuis o ; dL/dt = τ","data.now":"Maintenant (du serveur)","data.exact":"Solution exacte de cette orbite","data.tension":"tension","data.tensionMin":"tension min","data.tensionMax":"tension max","data.method":"méthode","data.state":"état","data.paused":"en pause","data.running":"en marche","data.lagging":" (en retard : plus lent que demandé)","data.model":"modèle","data.kind":"type de mouvement","data.periodZ":"du point le plus bas au suivant T_z","data.swingPeriod":"période d’oscillation T","data.advance":"rotation entre deux points les plus bas Δφ","data.rotation":"nombre de rotation W = Δφ/2π","data.reduced":"vue réduite (σ₁, σ₂, σ₃) : surface J₃ ∩ plan d’énergie","portrait.phase":"portrait de phase : vitesse verticale ż selon la hauteur z","portrait.veff":"potentiel effectif V_eff(θ) ; énergie E en tirets, θ actuel en pointillés","portrait.em":"carte énergie–moment : E selon J₃ (point : maintenant)","portrait.orbit":"orbite","portrait.emBoundary":"bord (orbites coniques)","note.spring":"le ressort quitte la sphère (sa longueur varie) : V_eff, la carte énergie–moment, la vue réduite et la solution exacte sont celles du pendule à tige et ne sont pas affichées","note.string":"le fil se détend (vol libre dans la sphère) : V_eff, la carte énergie–moment, la vue réduite et la solution exacte sont celles du pendule à tige et ne sont pas affichées","note.exactIdeal":"la solution exacte n’existe que pour le pendule idéal ; ceci est le modèle {model}","note.reducedIdeal":"la vue réduite est celle du pendule idéal ; ceci est le modèle {model}","event.slack":"le fil s’est détendu (tension 0 : vol libre)","event.taut":"le fil s’est tendu d’un coup, {lost} J perdus","event.skippedOne":" ({n} événement antérieur de cet instant non affiché)","event.skippedMany":" ({n} événements antérieurs de cet instant non affichés)","event.slackRow":"détendu","event.tautRow":"tendu d’un coup","event.tautValue":"t = {t} s, perdu {lost}","data.power":"puissance P = dE/dt","data.springForce":"force du ressort k(|r| − l₀)","data.springLength":"longueur du ressort |r|","data.stretch":"allongement |r| − l₀","data.string":"fil","data.slackZero":"détendu (0)","data.slack":"détendu : vol libre, |x| = {r} m","data.taut":"tendu","data.events":"événements","data.noEvents":"aucun pour l’instant (détentes, à-coups)","data.z3":"z₃ (hors de la sphère)","data.dynamic":"Δφ dynamique","data.geometric":"Δφ géométrique","data.error":"erreur de position |Δx|","data.errorRel":"erreur de position / l","data.errorHow":"erreur obtenue par","data.errorPaused":"estimation en pause (le budget de calcul du serveur est épuisé ; elle rattrape quand il y a du temps)","data.errorNone":"pas d’estimation","data.howExact":"l’erreur vraie : comparée à la solution exacte (depuis t = {since} s)","data.howRichardson":"estimation : Richardson avec un calcul compagnon à dt/2 = {dt} s, ordre p = {p} (depuis t = {since} s)","data.howCompanion":"estimation : un calcul compagnon à rtol = {rtol} (depuis t = {since} s)","page.softwareHelp":"{renderer} : dessiné sans multiéchantillonnage pour la fluidité","tools.start":"Angle de départ","tools.thetaHelp":"θ₀ : l’angle avec la verticale vers le bas, en degrés (0 … 180)","tools.phiHelp":"φ₀ : l’azimut autour de la verticale, en degrés","tools.phiDotHelp":"φ̇₀ : à quelle vitesse la masse commence à tourner, en degrés par seconde (0 : une oscillation plane)","tools.setStart":"fixer le départ","tools.world":"Pesanteur et frottement","tools.gravity":"pesanteur","tools.friction":"frottement","tools.frictionHelp":"amortissement linéaire c [1/s] : la force −m c v ; sur le pendule idéal, passe au modèle amorti","tools.noFriction":"le modèle {model} n’a pas de paramètre de frottement","tools.now":"Angles maintenant","tools.stopwatch":"Chronomètre (temps simulé)","tools.swStart":"démarrer","tools.swStop":"arrêter","tools.swLap":"tour","tools.swReset":"remettre à zéro","tools.period":"Mesure de la période","tools.periodHelp":"mesurée sur le mouvement : les points les plus bas de la masse ; une période d’oscillation se termine quand la masse repasse en bas dans le même sens. Comparée à la valeur exacte (pendule idéal) ou à la théorie (formule des petites oscillations avec frottement)","tools.periodCount":"moyenne sur {n} périodes","tools.periodCountZ":"moyenne sur {n} passages d’un point le plus bas au suivant","tools.periodWait":"attend que la masse passe deux fois par son point le plus bas","tools.motion":"mouvement","tools.kindNone":"—","tools.kindSwing":"oscille d’avant en arrière","tools.kindOver":"fait des tours complets","tools.kindOrbit":"tourne (ne passe jamais par le bas)","tools.periodSwing":"période T [s]","tools.periodZ":"d’un point le plus bas au suivant [s]","tools.advance":"rotation entre deux points les plus bas [°]","tools.precession":"la figure tourne par tour de [°]","tools.amplitude":"amplitude (plus grand angle) [°]","tools.band":"angle avec la verticale [°]","tools.theory":"théorie","tools.measured":"mesuré","tools.exact":"exact","tools.difference":"écart","tools.overlays":"Règle et rapporteur","tools.ruler":"règle (mètres)","tools.protractor":"rapporteur (θ en degrés)","describe.none":"pas encore de mouvement","describe.text":"angle de {theta}° avec la verticale, {dir}, vitesse {v} m/s","describe.rest":"au repos","describe.turning":"à un point de rebroussement","describe.rising":"monte","describe.falling":"descend vers le bas","describe.energy":" ; énergie {k} % cinétique, {u} % potentielle","describe.lost":", {p} % perdue par frottement","describe.toggle":"décrire le mouvement toutes les 5 s (lecteurs d’écran ; D : maintenant)","tools.mystery":"planète mystère (trouver g avec la période)","tools.reveal":"révéler g","tools.mysteryOn":"une planète mystère : chronométrer les oscillations et calculer g = 4π² l / T²","tools.revealed":"g de la planète mystère vaut {g} m/s²","start.notNumber":"{name} doit être un nombre","start.thetaRange":"θ₀ = {value}° n’est pas permis : 0 … 180°","gravity.custom":"autre","gravity.earth":"Terre","gravity.moon":"Lune","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"nulle","gravity.negative":"négative (vers le haut)","energy.title":"Énergie","energy.kinetic":"cinétique","energy.potential":"potentielle","energy.lost":"perdue","energy.total":"totale","plot.dE":"dérive de l’énergie |ΔE|/E_s (log)","plot.dJ3":"dérive de J₃ |ΔJ₃|/J_s (log)","plot.z":"hauteur z(t)","plot.tension":"tension de la tige T(t)","plot.time":"temps t [s]","plot.floor":"arrondi float64 2,2e-16","chosen.title":"Tracer des grandeurs au choix","chosen.xAxis":"en abscisse","chosen.yAxis":"en ordonnée","var.t":"temps t","var.theta":"angle θ","var.phi":"azimut φ","var.x":"x","var.y":"y","var.z":"hauteur z","var.zdot":"vitesse verticale ż","var.speed":"vitesse |v|","var.energy":"énergie E","var.kinetic":"énergie cinétique K","var.potential":"énergie potentielle U","var.j3":"moment cinétique J₃","var.tension":"tension T","var.power":"puissance P","var.radius":"distance |x|","twin.title":"Deux pendules","twin.mode":"second pendule","twin.off":"aucun","twin.epsilon":"départ différent de ε","twin.method":"une autre méthode de calcul","twin.damped":"amorti à côté de celui-ci","twin.own":"sa propre longueur, masse et départ (côte à côte)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"le second pendule demande une longueur > 0, une masse > 0 et un angle de départ 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"période T [s] (périodes)","twin.methodPick":"méthode","twin.damping":"amortissement [1/s]","twin.start":"démarrer les deux","twin.bad":"ε doit être un nombre et l’amortissement ≥ 0","twin.first":"pendule 1","twin.second":"pendule 2","twin.separation":"distance entre les masses |r₁ − r₂| [m]","help.title":"Raccourcis clavier et légende des couleurs","help.space":"démarrer / pause","help.r":"revenir au départ","help.s":"un pas (en pause)","help.arrows":"sur un curseur sélectionné : un pas vers le bas / le haut","help.page":"sur un curseur sélectionné : dix pas","help.camera":"dans la vue 3D : tourner la caméra / zoomer","help.bobKeys":"dans la vue 3D : déplacer le départ de la masse de 1° (met en pause)","help.describe":"décrire le mouvement maintenant (lecteurs d’écran)","help.tab":"passer d’une commande à l’autre","help.help":"cette fenêtre","help.esc":"fermer cette fenêtre","help.colours":"Couleurs","help.close":"fermer","help.bob":"masse","help.trail":"trace","help.twin":"second pendule","help.ruler":"règle et rapporteur","msg.notConnected":"pas de connexion au serveur","link.scenario":"le scénario (modèle, paramètres, méthode, départ)","link.paused":"en pause","link.pausedAt":"en pause à {t} s","link.view":"vue : {list}","link.plot":"graphique {y} selon {x}","link.twin":"second pendule {what}","link.lang":"langue {lang}","msg.linkCopied":"lien copié ; il contient {what}","msg.dragged":"départ fixé en glissant (au repos à cet endroit) : appuyer sur démarrer pour le lâcher","msg.pull":"tirer la flèche pour fixer la vitesse de départ","msg.capped":" (limitée : le maximum de la flèche, 4√(g l))","msg.velocitySet":"vitesse de départ fixée : |v| = {v} m/s{cap} ; appuyer sur démarrer pour partir de là","msg.velocity":"vitesse de départ |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} n’est pas permis : {allowed} ({range})","msg.recording":"la vue est filmée…","msg.recorded":"vidéo enregistrée ({mb} Mo, WebM)","msg.noRecording":"ce navigateur ne peut pas filmer la vue ({why})","fit.title":"Données mesurées","fit.load":"Charger des mesures…","fit.help":"un fichier CSV de mesures en unités SI (colonnes t, x, y, z ou x, z ; theta, phi ; angle ; specific_force ; angular_speed — docs/fit.md) : le serveur y ajuste le pendule, charge le mouvement ajusté et dessine le chemin mesuré en pointillés à côté","fit.model":"modèle","fit.params":"ajuster","fit.paramsDefault":"ce que les données déterminent","fit.paramsHelp":"les paramètres à ajuster, séparés par des virgules (p. ex. length,g,damping,pivot) ; vide : ce que les données peuvent déterminer","fit.clear":"effacer le chemin mesuré","fit.running":"ajustement de {name} …","fit.noPath":"(données sans repère : pas de chemin mesuré à dessiner)","fit.failed":"ajustement : {why}","fit.loaded":"{name} ajusté : le mouvement ajusté est chargé, le chemin mesuré en pointillés dorés"},Lg={length:["longueur l","longueur de la tige du point de suspension à la masse"],mass:["masse m","masse de la boule"],g:["pesanteur g","intensité de la pesanteur (tout signe ; 0 permis)"],damping:["frottement (amortissement linéaire) c","force de frottement −m c v, proportionnelle à la vitesse"],drag:["résistance de l’air c_q","force −m c_q |v| v, quadratique en vitesse"],forcing_amplitude:["forçage : intensité A","force périodique par masse A cos(ω t + ψ) dans la direction e"],forcing_omega:["forçage : pulsation ω","à quelle vitesse le forçage oscille"],forcing_phase:["forçage : phase ψ","phase du forçage à t = 0"],forcing_x:["direction du forçage e : x","composante x de la direction du forçage (normalisée)"],forcing_y:["direction du forçage e : y","composante y de la direction du forçage"],forcing_z:["direction du forçage e : z","composante z de la direction du forçage"],gravity_x:["direction de la pesanteur d : x","composante x de la direction de la pesanteur (normalisée)"],gravity_y:["direction de la pesanteur d : y","composante y de la direction de la pesanteur"],gravity_z:["direction de la pesanteur d : z","composante z de la direction de la pesanteur"],frame_rate:["vitesse de rotation du référentiel |Ω|","à quelle vitesse tourne le référentiel (Terre : 7,292e-5)"],latitude:["latitude λ","latitude du lieu (pendule de Foucault)"],radius:["rayon de la flèche R","distance du point de suspension à l’axe de rotation de la grue"],rate:["vitesse de rotation de la grue ω","à quelle vitesse tourne la flèche"],height:["hauteur du point de suspension h","hauteur de la flèche"],amplitude:["amplitude de vibration A","amplitude de l’oscillation verticale du point de suspension"],frequency:["fréquence de vibration ν","pulsation de l’oscillation du point de suspension"],stiffness:["raideur du ressort k","raideur du ressort ; la longueur l est la longueur au repos"],restitution:["coefficient de restitution e","élasticité du fil quand il se tend d’un coup (0 … 1)"]},Dg={ideal:"Pendule idéal",damped:"Amorti et forcé",rotating:"Sur la Terre qui tourne (Foucault)",slewing:"Grue pivotante",vibrating:"Point de suspension vibrant (Kapitza)",sampled_pivot:"Point de suspension sur un chemin donné",spring:"Ressort oscillant",string:"Pendule à fil"},za={en:{name:"English",words:ol,params:{},models:{}},de:{name:"Deutsch",words:Ag,params:Rg,models:Cg},fr:{name:"Français",words:Pg,params:Lg,models:Dg}};let Ha="en";function Ul(i){return typeof i=="string"&&Object.hasOwn(za,i)}function Ng(i,e,t){if(Ul(i))return i;if(Ul(e))return e;for(const n of t){const s=n.toLowerCase().split("-")[0];if(Ul(s))return s}return"en"}function Ig(i){Ha=i}function rp(){return Ha}function L(i,e={}){return(za[Ha].words[i]??ol[i]).replace(/\{(\w+)\}/g,(s,r)=>r in e?String(e[r]):s)}function Ug(i,e,t){return za[Ha].params[i]??[e,t]}function Gh(i,e){return za[Ha].models[i]??e}function $o(i,e){const t=`method.${i}`;return Object.hasOwn(ol,t)?L(t):L("method.other",{name:i,n:e})}function Fg(i){const e=`kind.${i}`;return Object.hasOwn(ol,e)?L(e):i}const Og=["spring","string"];function kg(i){return!Og.includes(i??"ideal")}function Vh(i){return i==="spring"?L("note.spring"):i==="string"?L("note.string"):null}function ap(i,e){return i==="spring"?"coil":i==="string"?e?"taut string":"slack string":"rod"}function pt(i,e=6){if(i==null||Number.isNaN(i))return"—";if(!Number.isFinite(i))return i>0?"∞":"−∞";if(i===0)return"0";const t=Math.abs(i);return t>=.001&&t<1e6?i.toPrecision(e):i.toExponential(e-1)}const Bg=5;function zg(i){const e=i.kind==="slack"?L("event.slack"):L("event.taut",{lost:pt(i.energy_lost,3)}),t=i.skipped>0?L(i.skipped>1?"event.skippedMany":"event.skippedOne",{n:i.skipped}):"";return`t = ${i.t.toFixed(3)} s: ${e}${t}`}function Hg(i){return i.kind==="slack"?[L("event.slackRow"),`t = ${pt(i.t,6)} s`,""]:[L("event.tautRow"),L("event.tautValue",{t:pt(i.t,6),lost:pt(i.energy_lost,4)}),"J"]}function Gg(i,e,t,n=Bg){if(t===null||e.epoch!==t)return i;const s=[...i,e];return s.length>n?s.slice(s.length-n):s}function Vg(i,e){const t=e.reference,n=e.status,s=e.tensionExtremes,r=[["t",pt(i?.t,7),"s"],[L("data.energy"),pt(i?.energy,10),"J"],[L("data.energyChange"),i&&t?pt(i.energy-t.energy,3):"—","J"],[L("data.spin"),pt(i?.j3,10),"kg m²/s"],[L("data.spinChange"),i&&t?pt(i.j3-t.j3,3):"—","kg m²/s"],[L("data.tension"),pt(i?.tension,6),"N"],[L("data.tensionMin"),s?`${pt(s.min,6)} (t = ${pt(s.tMin,4)} s)`:"—","N"],[L("data.tensionMax"),s?`${pt(s.max,6)} (t = ${pt(s.tMax,4)} s)`:"—","N"],[L("data.height"),pt(i?.x[2],6),"m"],[L("data.method"),n?`${$o(n.method,0)}${n.adaptive?"":`, dt = ${n.dt} s`}`:"—",""],[L("data.state"),n?`${n.paused?L("data.paused"):L("data.running")}${n.lagging?L("data.lagging"):""}`:"—",""],...Wg(i,n)];n&&n.model!=="ideal"&&(r.splice(1,0,[L("data.model"),Gh(n.model,n.model),""]),r.splice(4,0,[L("data.power"),pt(i?.power,6),"W"]));const a=r.findIndex(l=>l[0]===L("data.tension")),o=ap(n?.model,i?.taut??!0);if(o==="coil"&&n){const l=i?Math.hypot(...i.x):null;r[a]=[L("data.springForce"),pt(i?.tension,6),"N"],r.splice(a+1,0,[L("data.springLength"),pt(l,6),"m"],[L("data.stretch"),l===null?"—":pt(l-n.params.length,4),"m"])}else o==="slack string"?(r[a]=[L("data.tension"),L("data.slackZero"),"N"],r.splice(a+1,0,[L("data.string"),L("data.slack",{r:pt(i?Math.hypot(...i.x):null,5)}),""])):o==="taut string"&&r.splice(a+1,0,[L("data.string"),L("data.taut"),""]);if(n?.model==="string"){const l=[...e.events].reverse().map(Hg);r.push(...l.length>0?l:[[L("data.events"),L("data.noEvents"),""]])}return r}function Wg(i,e){const t=e?.error_estimate;if(!e||!t)return[];if(t.how===null)return[[L("data.errorHow"),t.note??L("data.errorNone"),""]];const n=pt(t.since,6),s=t.how==="exact"?L("data.howExact",{since:n}):t.how==="richardson"?L("data.howRichardson",{dt:pt(t.reference.dt,3),p:t.order??"?",since:n}):L("data.howCompanion",{rtol:pt(t.reference.rtol,3),since:n}),r=i?.errorX,a=r!==void 0&&r>=0;return[[L("data.error"),a?pt(r,3):r===void 0?"—":L("data.errorPaused"),a?"m":""],[L("data.errorRel"),a?pt(r/e.params.length,3):"—",""],[L("data.errorHow"),s,""]]}function Xg(i){const e=i.status,t=Vh(e?.model);return t!==null?t:e&&e.model!=="ideal"?L("note.exactIdeal",{model:e.model}):i.exactError??i.exact?.phases_note??""}function $g(i){if(i===null)return[];const e=i.turning_heights,t=[[L("data.kind"),Fg(i.kind),""],[L("data.turning"),`${pt(e[0])}, ${pt(e[1])}`,"m"]];return e.length>2&&t.push([L("data.z3"),pt(e[2]),"m"]),t.push([i.kind==="planar"?L("data.swingPeriod"):L("data.periodZ"),i.period_z_infinite?"∞":pt(i.period_z),"s"]),i.azimuth_advance!==null&&t.push([L("data.advance"),pt(i.azimuth_advance),"rad"]),i.rotation_number!==null&&t.push([L("data.rotation"),pt(i.rotation_number),""]),i.phases!==null&&(t.push([L("data.dynamic"),pt(i.phases.dynamic),"rad"]),t.push([L("data.geometric"),pt(i.phases.geometric),"rad"])),t}class qg{live;exactTable;note;constructor(e){const t=n=>{const s=document.createElement("h3");s.textContent=n,e.appendChild(s)};t(L("data.now")),this.live=document.createElement("table"),e.appendChild(this.live),t(L("data.exact")),this.exactTable=document.createElement("table"),e.appendChild(this.exactTable),this.note=document.createElement("p"),this.note.className="note",e.appendChild(this.note)}fill(e,t){for(;e.rows.length>t.length;)e.deleteRow(-1);t.forEach(([n,s,r],a)=>{const o=e.rows[a]??e.insertRow();for(;o.cells.length<3;)o.insertCell();const[l,c,h]=[o.cells[0],o.cells[1],o.cells[2]];l&&l.textContent!==n&&(l.textContent=n),c&&c.textContent!==s&&(c.textContent=s),h&&h.textContent!==r&&(h.textContent=r)})}update(e,t){this.fill(this.live,Vg(e,t)),this.fill(this.exactTable,$g(t.exact));const n=Xg(t);this.note.textContent!==n&&(this.note.textContent=n)}}class $i{constructor(e,t,n,s,r="div"){this.parent=e,this.object=t,this.property=n,this._disabled=!1,this._hidden=!1,this.initialValue=this.getValue(),this.domElement=document.createElement(r),this.domElement.classList.add("lil-controller"),this.domElement.classList.add(s),this.$name=document.createElement("div"),this.$name.classList.add("lil-name"),$i.nextNameID=$i.nextNameID||0,this.$name.id=`lil-gui-name-${++$i.nextNameID}`,this.$widget=document.createElement("div"),this.$widget.classList.add("lil-widget"),this.$disable=this.$widget,this.domElement.appendChild(this.$name),this.domElement.appendChild(this.$widget),this.domElement.addEventListener("keydown",a=>a.stopPropagation()),this.domElement.addEventListener("keyup",a=>a.stopPropagation()),this.parent.children.push(this),this.parent.controllers.push(this),this.parent.$children.appendChild(this.domElement),this._listenCallback=this._listenCallback.bind(this),this.name(n)}name(e){return this._name=e,this.$name.textContent=e,this}onChange(e){return this._onChange=e,this}_callOnChange(){this.parent._callOnChange(this),this._onChange!==void 0&&this._onChange.call(this,this.getValue()),this._changed=!0}onFinishChange(e){return this._onFinishChange=e,this}_callOnFinishChange(){this._changed&&(this.parent._callOnFinishChange(this),this._onFinishChange!==void 0&&this._onFinishChange.call(this,this.getValue())),this._changed=!1}reset(){return this.setValue(this.initialValue),this._callOnFinishChange(),this}enable(e=!0){return this.disable(!e)}disable(e=!0){return e===this._disabled?this:(this._disabled=e,this.domElement.classList.toggle("lil-disabled",e),this.$disable.toggleAttribute("disabled",e),this)}show(e=!0){return this._hidden=!e,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}options(e){const t=this.parent.add(this.object,this.property,e);return t.name(this._name),this.destroy(),t}min(e){return this}max(e){return this}step(e){return this}decimals(e){return this}listen(e=!0){return this._listening=e,this._listenCallbackID!==void 0&&(cancelAnimationFrame(this._listenCallbackID),this._listenCallbackID=void 0),this._listening&&this._listenCallback(),this}_listenCallback(){this._listenCallbackID=requestAnimationFrame(this._listenCallback);const e=this.save();e!==this._listenPrevValue&&this.updateDisplay(),this._listenPrevValue=e}getValue(){return this.object[this.property]}setValue(e){return this.getValue()!==e&&(this.object[this.property]=e,this._callOnChange(),this.updateDisplay()),this}updateDisplay(){return this}load(e){return this.setValue(e),this._callOnFinishChange(),this}save(){return this.getValue()}destroy(){this.listen(!1),this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.controllers.splice(this.parent.controllers.indexOf(this),1),this.parent.$children.removeChild(this.domElement)}}class Yg extends $i{constructor(e,t,n){super(e,t,n,"lil-boolean","label"),this.$input=document.createElement("input"),this.$input.setAttribute("type","checkbox"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$widget.appendChild(this.$input),this.$input.addEventListener("change",()=>{this.setValue(this.$input.checked),this._callOnFinishChange()}),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.checked=this.getValue(),this}}function Dc(i){let e,t;return(e=i.match(/(#|0x)?([a-f0-9]{6})/i))?t=e[2]:(e=i.match(/rgb\(\s*(\d*)\s*,\s*(\d*)\s*,\s*(\d*)\s*\)/))?t=parseInt(e[1]).toString(16).padStart(2,0)+parseInt(e[2]).toString(16).padStart(2,0)+parseInt(e[3]).toString(16).padStart(2,0):(e=i.match(/^#?([a-f0-9])([a-f0-9])([a-f0-9])$/i))&&(t=e[1]+e[1]+e[2]+e[2]+e[3]+e[3]),t?"#"+t:!1}const Kg={isPrimitive:!0,match:i=>typeof i=="string",fromHexString:Dc,toHexString:Dc},Pa={isPrimitive:!0,match:i=>typeof i=="number",fromHexString:i=>parseInt(i.substring(1),16),toHexString:i=>"#"+i.toString(16).padStart(6,0)},Zg={isPrimitive:!1,match:i=>Array.isArray(i)||ArrayBuffer.isView(i),fromHexString(i,e,t=1){const n=Pa.fromHexString(i);e[0]=(n>>16&255)/255*t,e[1]=(n>>8&255)/255*t,e[2]=(n&255)/255*t},toHexString([i,e,t],n=1){n=255/n;const s=i*n<<16^e*n<<8^t*n<<0;return Pa.toHexString(s)}},Jg={isPrimitive:!1,match:i=>Object(i)===i,fromHexString(i,e,t=1){const n=Pa.fromHexString(i);e.r=(n>>16&255)/255*t,e.g=(n>>8&255)/255*t,e.b=(n&255)/255*t},toHexString({r:i,g:e,b:t},n=1){n=255/n;const s=i*n<<16^e*n<<8^t*n<<0;return Pa.toHexString(s)}},jg=[Kg,Pa,Zg,Jg];function Qg(i){return jg.find(e=>e.match(i))}class e0 extends $i{constructor(e,t,n,s){super(e,t,n,"lil-color"),this.$input=document.createElement("input"),this.$input.setAttribute("type","color"),this.$input.setAttribute("tabindex",-1),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$text=document.createElement("input"),this.$text.setAttribute("type","text"),this.$text.setAttribute("spellcheck","false"),this.$text.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$display.appendChild(this.$input),this.$widget.appendChild(this.$display),this.$widget.appendChild(this.$text),this._format=Qg(this.initialValue),this._rgbScale=s,this._initialValueHexString=this.save(),this._textFocused=!1,this.$input.addEventListener("input",()=>{this._setValueFromHexString(this.$input.value)}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$text.addEventListener("input",()=>{const r=Dc(this.$text.value);r&&this._setValueFromHexString(r)}),this.$text.addEventListener("focus",()=>{this._textFocused=!0,this.$text.select()}),this.$text.addEventListener("blur",()=>{this._textFocused=!1,this.updateDisplay(),this._callOnFinishChange()}),this.$disable=this.$text,this.updateDisplay()}reset(){return this._setValueFromHexString(this._initialValueHexString),this}_setValueFromHexString(e){if(this._format.isPrimitive){const t=this._format.fromHexString(e);this.setValue(t)}else this._format.fromHexString(e,this.getValue(),this._rgbScale),this._callOnChange(),this.updateDisplay()}save(){return this._format.toHexString(this.getValue(),this._rgbScale)}load(e){return this._setValueFromHexString(e),this._callOnFinishChange(),this}updateDisplay(){return this.$input.value=this._format.toHexString(this.getValue(),this._rgbScale),this._textFocused||(this.$text.value=this.$input.value.substring(1)),this.$display.style.backgroundColor=this.$input.value,this}}class Fl extends $i{constructor(e,t,n){super(e,t,n,"lil-function"),this.$button=document.createElement("button"),this.$button.appendChild(this.$name),this.$widget.appendChild(this.$button),this.$button.addEventListener("click",s=>{s.preventDefault(),this.getValue().call(this.object),this._callOnChange()}),this.$button.addEventListener("touchstart",()=>{},{passive:!0}),this.$disable=this.$button}}class t0 extends $i{constructor(e,t,n,s,r,a){super(e,t,n,"lil-number"),this._initInput(),this.min(s),this.max(r);const o=a!==void 0;this.step(o?a:this._getImplicitStep(),o),this.updateDisplay()}decimals(e){return this._decimals=e,this.updateDisplay(),this}min(e){return this._min=e,this._onUpdateMinMax(),this}max(e){return this._max=e,this._onUpdateMinMax(),this}step(e,t=!0){return this._step=e,this._stepExplicit=t,this}updateDisplay(){const e=this.getValue();if(this._hasSlider){let t=(e-this._min)/(this._max-this._min);t=Math.max(0,Math.min(t,1)),this.$fill.style.width=t*100+"%"}return this._inputFocused||(this.$input.value=this._decimals===void 0?e:e.toFixed(this._decimals)),this}_initInput(){this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("aria-labelledby",this.$name.id),window.matchMedia("(pointer: coarse)").matches&&(this.$input.setAttribute("type","number"),this.$input.setAttribute("step","any")),this.$widget.appendChild(this.$input),this.$disable=this.$input;const t=()=>{let x=parseFloat(this.$input.value);isNaN(x)||(this._stepExplicit&&(x=this._snap(x)),this.setValue(this._clamp(x)))},n=x=>{const R=parseFloat(this.$input.value);isNaN(R)||(this._snapClampSetValue(R+x),this.$input.value=this.getValue())},s=x=>{x.key==="Enter"&&this.$input.blur(),x.code==="ArrowUp"&&(x.preventDefault(),n(this._step*this._arrowKeyMultiplier(x))),x.code==="ArrowDown"&&(x.preventDefault(),n(this._step*this._arrowKeyMultiplier(x)*-1))},r=x=>{this._inputFocused&&(x.preventDefault(),n(this._step*this._normalizeMouseWheel(x)))};let a=!1,o,l,c,h,u;const d=5,m=x=>{o=x.clientX,l=c=x.clientY,a=!0,h=this.getValue(),u=0,window.addEventListener("mousemove",_),window.addEventListener("mouseup",S)},_=x=>{if(a){const R=x.clientX-o,y=x.clientY-l;Math.abs(y)>d?(x.preventDefault(),this.$input.blur(),a=!1,this._setDraggingStyle(!0,"vertical")):Math.abs(R)>d&&S()}if(!a){const R=x.clientY-c;u-=R*this._step*this._arrowKeyMultiplier(x),h+u>this._max?u=this._max-h:h+u<this._min&&(u=this._min-h),this._snapClampSetValue(h+u)}c=x.clientY},S=()=>{this._setDraggingStyle(!1,"vertical"),this._callOnFinishChange(),window.removeEventListener("mousemove",_),window.removeEventListener("mouseup",S)},p=()=>{this._inputFocused=!0},f=()=>{this._inputFocused=!1,this.updateDisplay(),this._callOnFinishChange()};this.$input.addEventListener("input",t),this.$input.addEventListener("keydown",s),this.$input.addEventListener("wheel",r,{passive:!1}),this.$input.addEventListener("mousedown",m),this.$input.addEventListener("focus",p),this.$input.addEventListener("blur",f)}_initSlider(){this._hasSlider=!0,this.$slider=document.createElement("div"),this.$slider.classList.add("lil-slider"),this.$fill=document.createElement("div"),this.$fill.classList.add("lil-fill"),this.$slider.appendChild(this.$fill),this.$widget.insertBefore(this.$slider,this.$input),this.domElement.classList.add("lil-has-slider");const e=(f,x,R,y,A)=>(f-x)/(R-x)*(A-y)+y,t=f=>{const x=this.$slider.getBoundingClientRect();let R=e(f,x.left,x.right,this._min,this._max);this._snapClampSetValue(R)},n=f=>{this._setDraggingStyle(!0),t(f.clientX),window.addEventListener("mousemove",s),window.addEventListener("mouseup",r)},s=f=>{t(f.clientX)},r=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("mousemove",s),window.removeEventListener("mouseup",r)};let a=!1,o,l;const c=f=>{f.preventDefault(),this._setDraggingStyle(!0),t(f.touches[0].clientX),a=!1},h=f=>{f.touches.length>1||(this._hasScrollBar?(o=f.touches[0].clientX,l=f.touches[0].clientY,a=!0):c(f),window.addEventListener("touchmove",u,{passive:!1}),window.addEventListener("touchend",d))},u=f=>{if(a){const x=f.touches[0].clientX-o,R=f.touches[0].clientY-l;Math.abs(x)>Math.abs(R)?c(f):(window.removeEventListener("touchmove",u),window.removeEventListener("touchend",d))}else f.preventDefault(),t(f.touches[0].clientX)},d=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("touchmove",u),window.removeEventListener("touchend",d)},m=this._callOnFinishChange.bind(this),_=400;let S;const p=f=>{if(Math.abs(f.deltaX)<Math.abs(f.deltaY)&&this._hasScrollBar)return;f.preventDefault();const R=this._normalizeMouseWheel(f)*this._step;this._snapClampSetValue(this.getValue()+R),this.$input.value=this.getValue(),clearTimeout(S),S=setTimeout(m,_)};this.$slider.addEventListener("mousedown",n),this.$slider.addEventListener("touchstart",h,{passive:!1}),this.$slider.addEventListener("wheel",p,{passive:!1})}_setDraggingStyle(e,t="horizontal"){this.$slider&&this.$slider.classList.toggle("lil-active",e),document.body.classList.toggle("lil-dragging",e),document.body.classList.toggle(`lil-${t}`,e)}_getImplicitStep(){return this._hasMin&&this._hasMax?(this._max-this._min)/1e3:.1}_onUpdateMinMax(){!this._hasSlider&&this._hasMin&&this._hasMax&&(this._stepExplicit||this.step(this._getImplicitStep(),!1),this._initSlider(),this.updateDisplay())}_normalizeMouseWheel(e){let{deltaX:t,deltaY:n}=e;return Math.floor(e.deltaY)!==e.deltaY&&e.wheelDelta&&(t=0,n=-e.wheelDelta/120,n*=this._stepExplicit?1:10),t+-n}_arrowKeyMultiplier(e){let t=this._stepExplicit?1:10;return e.shiftKey?t*=10:e.altKey&&(t/=10),t}_snap(e){let t=0;return this._hasMin?t=this._min:this._hasMax&&(t=this._max),e-=t,e=Math.round(e/this._step)*this._step,e+=t,e=parseFloat(e.toPrecision(15)),e}_clamp(e){return e<this._min&&(e=this._min),e>this._max&&(e=this._max),e}_snapClampSetValue(e){this.setValue(this._clamp(this._snap(e)))}get _hasScrollBar(){const e=this.parent.root.$children;return e.scrollHeight>e.clientHeight}get _hasMin(){return this._min!==void 0}get _hasMax(){return this._max!==void 0}}class n0 extends $i{constructor(e,t,n,s){super(e,t,n,"lil-option"),this.$select=document.createElement("select"),this.$select.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$select.addEventListener("change",()=>{this.setValue(this._values[this.$select.selectedIndex]),this._callOnFinishChange()}),this.$select.addEventListener("focus",()=>{this.$display.classList.add("lil-focus")}),this.$select.addEventListener("blur",()=>{this.$display.classList.remove("lil-focus")}),this.$widget.appendChild(this.$select),this.$widget.appendChild(this.$display),this.$disable=this.$select,this.options(s)}options(e){return this._values=Array.isArray(e)?e:Object.values(e),this._names=Array.isArray(e)?e:Object.keys(e),this.$select.replaceChildren(),this._names.forEach(t=>{const n=document.createElement("option");n.textContent=t,this.$select.appendChild(n)}),this.updateDisplay(),this}updateDisplay(){const e=this.getValue(),t=this._values.indexOf(e);return this.$select.selectedIndex=t,this.$display.textContent=t===-1?e:this._names[t],this}}class i0 extends $i{constructor(e,t,n){super(e,t,n,"lil-string"),this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("spellcheck","false"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$input.addEventListener("input",()=>{this.setValue(this.$input.value)}),this.$input.addEventListener("keydown",s=>{s.code==="Enter"&&this.$input.blur()}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$widget.appendChild(this.$input),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.value=this.getValue(),this}}var s0=`.lil-gui {
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
}`;function r0(i){const e=document.createElement("style");e.innerHTML=i;const t=document.querySelector("head link[rel=stylesheet], head style");t?document.head.insertBefore(e,t):document.head.appendChild(e)}let Vu=!1;class Wh{constructor({parent:e,autoPlace:t=e===void 0,container:n,width:s,title:r="Controls",closeFolders:a=!1,injectStyles:o=!0,touchStyles:l=!0}={}){if(this.parent=e,this.root=e?e.root:this,this.children=[],this.controllers=[],this.folders=[],this._closed=!1,this._hidden=!1,this.domElement=document.createElement("div"),this.domElement.classList.add("lil-gui"),this.$title=document.createElement("button"),this.$title.classList.add("lil-title"),this.$title.setAttribute("aria-expanded",!0),this.$title.addEventListener("click",()=>this.openAnimated(this._closed)),this.$title.addEventListener("touchstart",()=>{},{passive:!0}),this.$children=document.createElement("div"),this.$children.classList.add("lil-children"),this.domElement.appendChild(this.$title),this.domElement.appendChild(this.$children),this.title(r),this.parent){this.parent.children.push(this),this.parent.folders.push(this),this.parent.$children.appendChild(this.domElement);return}this.domElement.classList.add("lil-root"),l&&this.domElement.classList.add("lil-allow-touch-styles"),!Vu&&o&&(r0(s0),Vu=!0),n?n.appendChild(this.domElement):t&&(this.domElement.classList.add("lil-auto-place","autoPlace"),document.body.appendChild(this.domElement)),s&&this.domElement.style.setProperty("--width",s+"px"),this._closeFolders=a}add(e,t,n,s,r){if(Object(n)===n)return new n0(this,e,t,n);const a=e[t];switch(typeof a){case"number":return new t0(this,e,t,n,s,r);case"boolean":return new Yg(this,e,t);case"string":return new i0(this,e,t);case"function":return new Fl(this,e,t)}console.error(`gui.add failed
	property:`,t,`
	object:`,e,`
	value:`,a)}addColor(e,t,n=1){return new e0(this,e,t,n)}addFolder(e){const t=new Wh({parent:this,title:e});return this.root._closeFolders&&t.close(),t}load(e,t=!0){return e.controllers&&this.controllers.forEach(n=>{n instanceof Fl||n._name in e.controllers&&n.load(e.controllers[n._name])}),t&&e.folders&&this.folders.forEach(n=>{n._title in e.folders&&n.load(e.folders[n._title])}),this}save(e=!0){const t={controllers:{},folders:{}};return this.controllers.forEach(n=>{if(!(n instanceof Fl)){if(n._name in t.controllers)throw new Error(`Cannot save GUI with duplicate property "${n._name}"`);t.controllers[n._name]=n.save()}}),e&&this.folders.forEach(n=>{if(n._title in t.folders)throw new Error(`Cannot save GUI with duplicate folder "${n._title}"`);t.folders[n._title]=n.save()}),t}open(e=!0){return this._setClosed(!e),this.$title.setAttribute("aria-expanded",!this._closed),this.domElement.classList.toggle("lil-closed",this._closed),this}close(){return this.open(!1)}_setClosed(e){this._closed!==e&&(this._closed=e,this._callOnOpenClose(this))}show(e=!0){return this._hidden=!e,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}openAnimated(e=!0){return this._setClosed(!e),this.$title.setAttribute("aria-expanded",!this._closed),requestAnimationFrame(()=>{const t=this.$children.clientHeight;this.$children.style.height=t+"px",this.domElement.classList.add("lil-transition");const n=r=>{r.target===this.$children&&(this.$children.style.height="",this.domElement.classList.remove("lil-transition"),this.$children.removeEventListener("transitionend",n))};this.$children.addEventListener("transitionend",n);const s=e?this.$children.scrollHeight:0;this.domElement.classList.toggle("lil-closed",!e),requestAnimationFrame(()=>{this.$children.style.height=s+"px"})}),this}title(e){return this._title=e,this.$title.textContent=e,this}reset(e=!0){return(e?this.controllersRecursive():this.controllers).forEach(n=>n.reset()),this}onChange(e){return this._onChange=e,this}_callOnChange(e){this.parent&&this.parent._callOnChange(e),this._onChange!==void 0&&this._onChange.call(this,{object:e.object,property:e.property,value:e.getValue(),controller:e})}onFinishChange(e){return this._onFinishChange=e,this}_callOnFinishChange(e){this.parent&&this.parent._callOnFinishChange(e),this._onFinishChange!==void 0&&this._onFinishChange.call(this,{object:e.object,property:e.property,value:e.getValue(),controller:e})}onOpenClose(e){return this._onOpenClose=e,this}_callOnOpenClose(e){this.parent&&this.parent._callOnOpenClose(e),this._onOpenClose!==void 0&&this._onOpenClose.call(this,e)}destroy(){this.parent&&(this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.folders.splice(this.parent.folders.indexOf(this),1)),this.domElement.parentElement&&this.domElement.parentElement.removeChild(this.domElement),Array.from(this.children).forEach(e=>e.destroy())}controllersRecursive(){let e=Array.from(this.controllers);return this.folders.forEach(t=>{e=e.concat(t.controllersRecursive())}),e}foldersRecursive(){let e=Array.from(this.folders);return this.folders.forEach(t=>{e=e.concat(t.foldersRecursive())}),e}}function op(i){return i==="1"?"":i.replace("^2","²").replace("^3","³")}function lp(i){return Ug(i.name,i.label??i.name,i.description)}function a0(i){const e=op(i.unit),[t]=lp(i);return e?`${t} [${e}]`:t}function Nc(i){const e=op(i.unit),t=e?` ${e}`:"";return i.min!==null&&i.max!==null?`${i.min} … ${i.max}${t}`:i.min!==null?`≥ ${i.min}${t}`:i.max!==null?`≤ ${i.max}${t}`:"any finite number"}function o0(i,e){return Number.isFinite(e)&&(i.min===null||e>=i.min)&&(i.max===null||e<=i.max)?null:L("msg.notAllowed",{name:i.name,value:e,allowed:i.allowed??Nc(i),range:Nc(i)})}function cp(i,e,t,n,s){typeof e[t.name]!="number"&&(e[t.name]=t.default);const r=i.add(e,t.name,t.ui_min,t.ui_max).name(a0(t)).onChange(l=>{const c=o0(t,l);c!==null?s(c):n(l)}),[,a]=lp(t);r.domElement.title=L("gui.paramHelp",{help:a,name:t.name,unit:t.unit,range:Nc(t),default:t.default}),r.domElement.dataset.param=t.name,r.step(t.step,!1);const o=r;return typeof o._clamp=="function"&&(o._clamp=l=>l),r}function Xh(i,e){let t=-1/0,n=null,s=null;return(...r)=>{s=r;const a=t+e-performance.now();a<=0&&n===null?(t=performance.now(),i(...r),s=null):n===null&&(n=setTimeout(()=>{n=null,t=performance.now(),s!==null&&i(...s),s=null},Math.max(0,a)))}}const l0={damped:{damping:.3}};function c0(i){const e=l0[i];return e?{type:"set_model",model:i,params:{...e}}:{type:"set_model",model:i}}function h0(i){const e={};for(const t of i)e[t.label?`${Gh(t.name,t.label)} (${t.name})`:t.name]=t.name;return e}class u0{constructor(e,t,n){this.parent=e,this.schema=t,this.actions=n,this.picker=e.add(this.state,"model",h0(t.models)).name(L("gui.model")).onChange(s=>n.send(c0(s))),this.picker.domElement.dataset.control="model",this.picker.domElement.title=t.models.map(s=>`${s.name}: ${s.summary}`).join(`
`),this.sendParam=Xh((s,r)=>{n.send({type:"set_params",params:{[s]:r}})},50)}parent;schema;actions;state={model:"ideal"};picker;paramsFolder=null;paramControls=[];values={};shown=null;sendParam;spec(e){return this.schema.models.find(t=>t.name===e)}rebuild(e){this.paramsFolder?.destroy(),this.paramsFolder=null,this.paramControls=[],this.values={},this.shown=e;const t=this.spec(e);if(t===void 0||t.params.length===0)return;const n=this.parent.addFolder(L("gui.modelParams",{model:Gh(e,t.label??e)}));for(const s of t.params){this.values[s.name]=s.default;const r=cp(n,this.values,s,a=>this.sendParam(s.name,a),this.actions.explain);this.paramControls.push(r)}this.paramsFolder=n}sync(e){const t=e.model??"ideal";this.state.model=t,this.picker.updateDisplay(),this.shown!==t&&this.rebuild(t);for(const[n,s]of Object.entries(e.model_params??{}))this.values[n]=s;for(const n of this.paramControls)n.domElement.contains(document.activeElement)||n.updateDisplay()}}const $h="187",Ir={ROTATE:0,DOLLY:1,PAN:2},Nr={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},d0=0,Wu=1,f0=2,ko=1,p0=2,ga=3,Cs=0,Kn=1,pi=2,Ur=0,wa=1,Xu=2,$u=3,qu=4,m0=5,Lr=100,g0=101,_0=102,v0=103,x0=104,S0=200,y0=201,M0=202,b0=203,hp=204,up=205,w0=206,E0=207,T0=208,A0=209,R0=210,C0=211,P0=212,L0=213,D0=214,Ic=0,Uc=1,Fc=2,La=3,Oc=4,kc=5,Bc=6,zc=7,dp=0,N0=1,I0=2,cs=0,fp=1,pp=2,mp=3,gp=4,_p=5,vp=6,xp=7,Sp=300,Br=301,Da=302,Ol=303,kl=304,Hc=1e3,os=1001,Gc=1002,Ln=1003,U0=1004,ja=1005,Yn=1006,Bl=1007,Ts=1008,ii=1009,yp=1010,Mp=1011,Na=1012,qh=1013,Yi=1014,Vi=1015,Ki=1016,Yh=1017,Kh=1018,zr=1020,bp=35902,wp=35899,Ep=1021,Tp=1022,Wi=1023,Ps=1026,As=1027,Ap=1028,Zh=1029,Ks=1030,Jh=1031,jh=1033,Bo=33776,zo=33777,Ho=33778,Go=33779,Vc=35840,Wc=35841,Xc=35842,$c=35843,qc=36196,Yc=37492,Kc=37496,Zc=37488,Jc=37489,qo=37490,jc=37491,Qc=37808,eh=37809,th=37810,nh=37811,ih=37812,sh=37813,rh=37814,ah=37815,oh=37816,lh=37817,ch=37818,hh=37819,uh=37820,dh=37821,fh=36492,ph=36494,mh=36495,gh=36283,_h=36284,Yo=36285,vh=36286,F0=3200,xh=0,O0=1,Es="",ui="srgb",Ko="srgb-linear",Zo="linear",Dt="srgb",zl=7680,k0=519,B0=512,z0=513,H0=514,Rp=515,G0=516,V0=517,Cp=518,Pp=519,Lp=35044,Yu="300 es",Ci=2e3,Ia=2001;function W0(i){for(let e=i.length-1;e>=0;--e)if(i[e]>=65535)return!0;return!1}function Jo(i){return document.createElementNS("http://www.w3.org/1999/xhtml",i)}function X0(){const i=Jo("canvas");return i.style.display="block",i}const Ku={};function jo(...i){const e="THREE."+i.shift();console.log(e,...i)}function Dp(i){const e=i[0];if(typeof e=="string"&&e.startsWith("TSL:")){const t=i[1];t&&t.isStackTrace?i[0]+=" "+t.getLocation():i[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return i}function tt(...i){i=Dp(i);const e="THREE."+i.shift();{const t=i[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...i)}}function St(...i){i=Dp(i);const e="THREE."+i.shift();{const t=i[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...i)}}function Vo(...i){const e=i.join(" ");e in Ku||(Ku[e]=!0,tt(...i))}function $0(i,e,t){return new Promise(function(n,s){function r(){switch(i.clientWaitSync(e,i.SYNC_FLUSH_COMMANDS_BIT,0)){case i.WAIT_FAILED:s();break;case i.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:n()}}setTimeout(r,t)})}const q0={[Ic]:Ic,[Fc]:Bc,[Oc]:Oc,[La]:kc,[Uc]:Uc,[Bc]:Fc,[zc]:zc,[kc]:La};class Is{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});const n=this._listeners;n[e]===void 0&&(n[e]=[]),n[e].indexOf(t)===-1&&n[e].push(t)}hasEventListener(e,t){const n=this._listeners;return n===void 0?!1:n[e]!==void 0&&n[e].indexOf(t)!==-1}removeEventListener(e,t){const n=this._listeners;if(n===void 0)return;const s=n[e];if(s!==void 0){const r=s.indexOf(t);r!==-1&&s.splice(r,1)}}dispatchEvent(e){const t=this._listeners;if(t===void 0)return;const n=t[e.type];if(n!==void 0){e.target=this;const s=n.slice(0);for(let r=0,a=s.length;r<a;r++)s[r].call(this,e);e.target=null}}}const Nn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],Ea=Math.PI/180,Sh=180/Math.PI;function js(){const i=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,n=Math.random()*4294967295|0;return(Nn[i&255]+Nn[i>>8&255]+Nn[i>>16&255]+Nn[i>>24&255]+"-"+Nn[e&255]+Nn[e>>8&255]+"-"+Nn[e>>16&15|64]+Nn[e>>24&255]+"-"+Nn[t&63|128]+Nn[t>>8&255]+"-"+Nn[t>>16&255]+Nn[t>>24&255]+Nn[n&255]+Nn[n>>8&255]+Nn[n>>16&255]+Nn[n>>24&255]).toLowerCase()}function mt(i,e,t){return Math.max(e,Math.min(t,i))}function Y0(i,e){return(i%e+e)%e}function Hl(i,e,t){return(1-t)*i+t*e}function K0(i){return Math.pow(2,Math.floor(Math.log(i)/Math.LN2))}function ll(i){switch(i.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function Np(i,e){if(e.constructor===Float32Array)return i;const t=ll(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(i/t,-1)}function Ip(i,e){if(e.constructor===Float32Array)return i;const t=ll(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(i*t)}const Z0={DEG2RAD:Ea};class Ye{static{this.prototype.isVector2=!0}constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){const t=this.x,n=this.y,s=e.elements;return this.x=s[0]*t+s[3]*n+s[6],this.y=s[1]*t+s[4]*n+s[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=mt(this.x,e.x,t.x),this.y=mt(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=mt(this.x,e,t),this.y=mt(this.y,e,t),this}clampLength(e,t){const n=this.length();return this.divideScalar(n||1).multiplyScalar(mt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const n=this.dot(e)/t;return Math.acos(mt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,n=this.y-e.y;return t*t+n*n}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){const n=Math.cos(t),s=Math.sin(t),r=this.x-e.x,a=this.y-e.y;return this.x=r*n-a*s+e.x,this.y=r*s+a*n+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}}class Ls{constructor(e=0,t=0,n=0,s=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=n,this._w=s}static slerpFlat(e,t,n,s,r,a,o){let l=n[s+0],c=n[s+1],h=n[s+2],u=n[s+3],d=r[a+0],m=r[a+1],_=r[a+2],S=r[a+3];if(u!==S||l!==d||c!==m||h!==_){let p=l*d+c*m+h*_+u*S;p<0&&(d=-d,m=-m,_=-_,S=-S,p=-p);let f=1-o;if(p<.9995){const x=Math.acos(p),R=Math.sin(x);f=Math.sin(f*x)/R,o=Math.sin(o*x)/R,l=l*f+d*o,c=c*f+m*o,h=h*f+_*o,u=u*f+S*o}else{l=l*f+d*o,c=c*f+m*o,h=h*f+_*o,u=u*f+S*o;const x=1/Math.sqrt(l*l+c*c+h*h+u*u);l*=x,c*=x,h*=x,u*=x}}e[t]=l,e[t+1]=c,e[t+2]=h,e[t+3]=u}static multiplyQuaternionsFlat(e,t,n,s,r,a){const o=n[s],l=n[s+1],c=n[s+2],h=n[s+3],u=r[a],d=r[a+1],m=r[a+2],_=r[a+3];return e[t]=o*_+h*u+l*m-c*d,e[t+1]=l*_+h*d+c*u-o*m,e[t+2]=c*_+h*m+o*d-l*u,e[t+3]=h*_-o*u-l*d-c*m,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,n,s){return this._x=e,this._y=t,this._z=n,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){const n=e._x,s=e._y,r=e._z,a=e._order,o=Math.cos,l=Math.sin,c=o(n/2),h=o(s/2),u=o(r/2),d=l(n/2),m=l(s/2),_=l(r/2);switch(a){case"XYZ":this._x=d*h*u+c*m*_,this._y=c*m*u-d*h*_,this._z=c*h*_+d*m*u,this._w=c*h*u-d*m*_;break;case"YXZ":this._x=d*h*u+c*m*_,this._y=c*m*u-d*h*_,this._z=c*h*_-d*m*u,this._w=c*h*u+d*m*_;break;case"ZXY":this._x=d*h*u-c*m*_,this._y=c*m*u+d*h*_,this._z=c*h*_+d*m*u,this._w=c*h*u-d*m*_;break;case"ZYX":this._x=d*h*u-c*m*_,this._y=c*m*u+d*h*_,this._z=c*h*_-d*m*u,this._w=c*h*u+d*m*_;break;case"YZX":this._x=d*h*u+c*m*_,this._y=c*m*u+d*h*_,this._z=c*h*_-d*m*u,this._w=c*h*u-d*m*_;break;case"XZY":this._x=d*h*u-c*m*_,this._y=c*m*u-d*h*_,this._z=c*h*_+d*m*u,this._w=c*h*u+d*m*_;break;default:tt("Quaternion: .setFromEuler() encountered an unknown order: "+a)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){const n=t/2,s=Math.sin(n);return this._x=e.x*s,this._y=e.y*s,this._z=e.z*s,this._w=Math.cos(n),this._onChangeCallback(),this}setFromRotationMatrix(e){const t=e.elements,n=t[0],s=t[4],r=t[8],a=t[1],o=t[5],l=t[9],c=t[2],h=t[6],u=t[10],d=n+o+u;if(d>0){const m=.5/Math.sqrt(d+1);this._w=.25/m,this._x=(h-l)*m,this._y=(r-c)*m,this._z=(a-s)*m}else if(n>o&&n>u){const m=2*Math.sqrt(1+n-o-u);this._w=(h-l)/m,this._x=.25*m,this._y=(s+a)/m,this._z=(r+c)/m}else if(o>u){const m=2*Math.sqrt(1+o-n-u);this._w=(r-c)/m,this._x=(s+a)/m,this._y=.25*m,this._z=(l+h)/m}else{const m=2*Math.sqrt(1+u-n-o);this._w=(a-s)/m,this._x=(r+c)/m,this._y=(l+h)/m,this._z=.25*m}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let n=e.dot(t)+1;return n<1e-8?(n=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=n):(this._x=0,this._y=-e.z,this._z=e.y,this._w=n)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=n),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(mt(this.dot(e),-1,1)))}rotateTowards(e,t){const n=this.angleTo(e);if(n===0)return this;const s=Math.min(1,t/n);return this.slerp(e,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){const n=e._x,s=e._y,r=e._z,a=e._w,o=t._x,l=t._y,c=t._z,h=t._w;return this._x=n*h+a*o+s*c-r*l,this._y=s*h+a*l+r*o-n*c,this._z=r*h+a*c+n*l-s*o,this._w=a*h-n*o-s*l-r*c,this._onChangeCallback(),this}slerp(e,t){let n=e._x,s=e._y,r=e._z,a=e._w,o=this.dot(e);o<0&&(n=-n,s=-s,r=-r,a=-a,o=-o);let l=1-t;if(o<.9995){const c=Math.acos(o),h=Math.sin(c);l=Math.sin(l*c)/h,t=Math.sin(t*c)/h,this._x=this._x*l+n*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+a*t,this._onChangeCallback()}else this._x=this._x*l+n*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+a*t,this.normalize();return this}slerpQuaternions(e,t,n){return this.copy(e).slerp(t,n)}random(){const e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),n=Math.random(),s=Math.sqrt(1-n),r=Math.sqrt(n);return this.set(s*Math.sin(e),s*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}}class z{static{this.prototype.isVector3=!0}constructor(e=0,t=0,n=0){this.x=e,this.y=t,this.z=n}set(e,t,n){return n===void 0&&(n=this.z),this.x=e,this.y=t,this.z=n,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(Zu.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(Zu.setFromAxisAngle(e,t))}applyMatrix3(e){const t=this.x,n=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[3]*n+r[6]*s,this.y=r[1]*t+r[4]*n+r[7]*s,this.z=r[2]*t+r[5]*n+r[8]*s,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){const t=this.x,n=this.y,s=this.z,r=e.elements,a=1/(r[3]*t+r[7]*n+r[11]*s+r[15]);return this.x=(r[0]*t+r[4]*n+r[8]*s+r[12])*a,this.y=(r[1]*t+r[5]*n+r[9]*s+r[13])*a,this.z=(r[2]*t+r[6]*n+r[10]*s+r[14])*a,this}applyQuaternion(e){const t=this.x,n=this.y,s=this.z,r=e.x,a=e.y,o=e.z,l=e.w,c=2*(a*s-o*n),h=2*(o*t-r*s),u=2*(r*n-a*t);return this.x=t+l*c+a*u-o*h,this.y=n+l*h+o*c-r*u,this.z=s+l*u+r*h-a*c,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){const t=this.x,n=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[4]*n+r[8]*s,this.y=r[1]*t+r[5]*n+r[9]*s,this.z=r[2]*t+r[6]*n+r[10]*s,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=mt(this.x,e.x,t.x),this.y=mt(this.y,e.y,t.y),this.z=mt(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=mt(this.x,e,t),this.y=mt(this.y,e,t),this.z=mt(this.z,e,t),this}clampLength(e,t){const n=this.length();return this.divideScalar(n||1).multiplyScalar(mt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){const n=e.x,s=e.y,r=e.z,a=t.x,o=t.y,l=t.z;return this.x=s*l-r*o,this.y=r*a-n*l,this.z=n*o-s*a,this}projectOnVector(e){const t=e.lengthSq();if(t===0)return this.set(0,0,0);const n=e.dot(this)/t;return this.copy(e).multiplyScalar(n)}projectOnPlane(e){return Gl.copy(this).projectOnVector(e),this.sub(Gl)}reflect(e){return this.sub(Gl.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const n=this.dot(e)/t;return Math.acos(mt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,n=this.y-e.y,s=this.z-e.z;return t*t+n*n+s*s}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,n){const s=Math.sin(t)*e;return this.x=s*Math.sin(n),this.y=Math.cos(t)*e,this.z=s*Math.cos(n),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,n){return this.x=e*Math.sin(t),this.y=n,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){const t=this.setFromMatrixColumn(e,0).length(),n=this.setFromMatrixColumn(e,1).length(),s=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=n,this.z=s,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){const e=Math.random()*Math.PI*2,t=Math.random()*2-1,n=Math.sqrt(1-t*t);return this.x=n*Math.cos(e),this.y=t,this.z=n*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}}const Gl=new z,Zu=new Ls;class rt{static{this.prototype.isMatrix3=!0}constructor(e,t,n,s,r,a,o,l,c){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,n,s,r,a,o,l,c)}set(e,t,n,s,r,a,o,l,c){const h=this.elements;return h[0]=e,h[1]=s,h[2]=o,h[3]=t,h[4]=r,h[5]=l,h[6]=n,h[7]=a,h[8]=c,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){const t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],this}extractBasis(e,t,n){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),n.setFromMatrix3Column(this,2),this}setFromMatrix4(e){const t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const n=e.elements,s=t.elements,r=this.elements,a=n[0],o=n[3],l=n[6],c=n[1],h=n[4],u=n[7],d=n[2],m=n[5],_=n[8],S=s[0],p=s[3],f=s[6],x=s[1],R=s[4],y=s[7],A=s[2],w=s[5],g=s[8];return r[0]=a*S+o*x+l*A,r[3]=a*p+o*R+l*w,r[6]=a*f+o*y+l*g,r[1]=c*S+h*x+u*A,r[4]=c*p+h*R+u*w,r[7]=c*f+h*y+u*g,r[2]=d*S+m*x+_*A,r[5]=d*p+m*R+_*w,r[8]=d*f+m*y+_*g,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){const e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],h=e[8];return t*a*h-t*o*c-n*r*h+n*o*l+s*r*c-s*a*l}invert(){const e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],h=e[8],u=h*a-o*c,d=o*l-h*r,m=c*r-a*l,_=t*u+n*d+s*m;if(_===0)return this.set(0,0,0,0,0,0,0,0,0);const S=1/_;return e[0]=u*S,e[1]=(s*c-h*n)*S,e[2]=(o*n-s*a)*S,e[3]=d*S,e[4]=(h*t-s*l)*S,e[5]=(s*r-o*t)*S,e[6]=m*S,e[7]=(n*l-c*t)*S,e[8]=(a*t-n*r)*S,this}transpose(){let e;const t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){const t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,n,s,r,a,o){const l=Math.cos(r),c=Math.sin(r);return this.set(n*l,n*c,-n*(l*a+c*o)+a+e,-s*c,s*l,-s*(-c*a+l*o)+o+t,0,0,1),this}scale(e,t){return Vo("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(Vl.makeScale(e,t)),this}rotate(e){return Vo("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(Vl.makeRotation(-e)),this}translate(e,t){return Vo("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(Vl.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){const t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,n,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){const t=this.elements,n=e.elements;for(let s=0;s<9;s++)if(t[s]!==n[s])return!1;return!0}fromArray(e,t=0){for(let n=0;n<9;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){const n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e}clone(){return new this.constructor().fromArray(this.elements)}}const Vl=new rt,Ju=new rt().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),ju=new rt().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function J0(){const i={enabled:!0,workingColorSpace:Ko,spaces:{},convert:function(s,r,a){return this.enabled===!1||r===a||!r||!a||(this.spaces[r].transfer===Dt&&(s.r=hs(s.r),s.g=hs(s.g),s.b=hs(s.b)),this.spaces[r].primaries!==this.spaces[a].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[a].fromXYZ)),this.spaces[a].transfer===Dt&&(s.r=Fr(s.r),s.g=Fr(s.g),s.b=Fr(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===Es?Zo:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,a){return s.copy(this.spaces[a].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],n=[.3127,.329];return i.define({[Ko]:{primaries:e,whitePoint:n,transfer:Zo,toXYZ:Ju,fromXYZ:ju,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:ui},outputColorSpaceConfig:{drawingBufferColorSpace:ui}},[ui]:{primaries:e,whitePoint:n,transfer:Dt,toXYZ:Ju,fromXYZ:ju,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:ui}}}),i}const vt=J0();function hs(i){return i<.04045?i*.0773993808:Math.pow(i*.9478672986+.0521327014,2.4)}function Fr(i){return i<.0031308?i*12.92:1.055*Math.pow(i,.41666)-.055}let dr;class j0{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let n;if(e instanceof HTMLCanvasElement)n=e;else{dr===void 0&&(dr=Jo("canvas")),dr.width=e.width,dr.height=e.height;const s=dr.getContext("2d");e instanceof ImageData?s.putImageData(e,0,0):s.drawImage(e,0,0,e.width,e.height),n=dr}return n.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){const t=Jo("canvas");t.width=e.width,t.height=e.height;const n=t.getContext("2d");n.drawImage(e,0,0,e.width,e.height);const s=n.getImageData(0,0,e.width,e.height),r=s.data;for(let a=0;a<r.length;a++)r[a]=hs(r[a]/255)*255;return n.putImageData(s,0,0),t}else if(e.data){const t=e.data.slice(0);for(let n=0;n<t.length;n++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[n]=Math.floor(hs(t[n]/255)*255):t[n]=hs(t[n]);return{data:t,width:e.width,height:e.height}}else return tt("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}}let Q0=0;class Qh{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:Q0++}),this.uuid=js(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){const t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];const n={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let a=0,o=s.length;a<o;a++)s[a].isDataTexture?r.push(Wl(s[a].image)):r.push(Wl(s[a]))}else r=Wl(s);n.url=r}return t||(e.images[this.uuid]=n),n}}function Wl(i){return typeof HTMLImageElement<"u"&&i instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&i instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&i instanceof ImageBitmap?j0.getDataURL(i):i.data?{data:Array.from(i.data),width:i.width,height:i.height,type:i.data.constructor.name}:(tt("Texture: Unable to serialize Texture."),{})}let e_=0;const Xl=new z;class Un extends Is{constructor(e=Un.DEFAULT_IMAGE,t=Un.DEFAULT_MAPPING,n=os,s=os,r=Yn,a=Ts,o=Wi,l=ii,c=Un.DEFAULT_ANISOTROPY,h=Es){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:e_++}),this.uuid=js(),this.name="",this.source=new Qh(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=n,this.wrapT=s,this.magFilter=r,this.minFilter=a,this.anisotropy=c,this.format=o,this.internalFormat=null,this.type=l,this.offset=new Ye(0,0),this.repeat=new Ye(1,1),this.center=new Ye(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new rt,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(Xl).x}get height(){return this.source.getSize(Xl).y}get depth(){return this.source.getSize(Xl).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(const t in e){const n=e[t];if(n===void 0){tt(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}const s=this[t];if(s===void 0){tt(`Texture.setValues(): property '${t}' does not exist.`);continue}s&&n&&s.isVector2&&n.isVector2||s&&n&&s.isVector3&&n.isVector3||s&&n&&s.isMatrix3&&n.isMatrix3?s.copy(n):this[t]=n}}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];const n={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(n.userData=this.userData),t||(e.textures[this.uuid]=n),n}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==Sp)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case Hc:e.x=e.x-Math.floor(e.x);break;case os:e.x=e.x<0?0:1;break;case Gc:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case Hc:e.y=e.y-Math.floor(e.y);break;case os:e.y=e.y<0?0:1;break;case Gc:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}}Un.DEFAULT_IMAGE=null;Un.DEFAULT_MAPPING=Sp;Un.DEFAULT_ANISOTROPY=1;class an{static{this.prototype.isVector4=!0}constructor(e=0,t=0,n=0,s=1){this.x=e,this.y=t,this.z=n,this.w=s}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,n,s){return this.x=e,this.y=t,this.z=n,this.w=s,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){const t=this.x,n=this.y,s=this.z,r=this.w,a=e.elements;return this.x=a[0]*t+a[4]*n+a[8]*s+a[12]*r,this.y=a[1]*t+a[5]*n+a[9]*s+a[13]*r,this.z=a[2]*t+a[6]*n+a[10]*s+a[14]*r,this.w=a[3]*t+a[7]*n+a[11]*s+a[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);const t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,n,s,r;const l=e.elements,c=l[0],h=l[4],u=l[8],d=l[1],m=l[5],_=l[9],S=l[2],p=l[6],f=l[10];if(Math.abs(h-d)<.01&&Math.abs(u-S)<.01&&Math.abs(_-p)<.01){if(Math.abs(h+d)<.1&&Math.abs(u+S)<.1&&Math.abs(_+p)<.1&&Math.abs(c+m+f-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;const R=(c+1)/2,y=(m+1)/2,A=(f+1)/2,w=(h+d)/4,g=(u+S)/4,b=(_+p)/4;return R>y&&R>A?R<.01?(n=0,s=.707106781,r=.707106781):(n=Math.sqrt(R),s=w/n,r=g/n):y>A?y<.01?(n=.707106781,s=0,r=.707106781):(s=Math.sqrt(y),n=w/s,r=b/s):A<.01?(n=.707106781,s=.707106781,r=0):(r=Math.sqrt(A),n=g/r,s=b/r),this.set(n,s,r,t),this}let x=Math.sqrt((p-_)*(p-_)+(u-S)*(u-S)+(d-h)*(d-h));return Math.abs(x)<.001&&(x=1),this.x=(p-_)/x,this.y=(u-S)/x,this.z=(d-h)/x,this.w=Math.acos((c+m+f-1)/2),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=mt(this.x,e.x,t.x),this.y=mt(this.y,e.y,t.y),this.z=mt(this.z,e.z,t.z),this.w=mt(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=mt(this.x,e,t),this.y=mt(this.y,e,t),this.z=mt(this.z,e,t),this.w=mt(this.w,e,t),this}clampLength(e,t){const n=this.length();return this.divideScalar(n||1).multiplyScalar(mt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this.w=e.w+(t.w-e.w)*n,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}}class t_ extends Is{constructor(e=1,t=1,n={}){super(),n=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:Yn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},n),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=n.depth,this.scissor=new an(0,0,e,t),this.scissorTest=!1,this.viewport=new an(0,0,e,t),this.textures=[];const s=n.count;for(let r=0;r<s;r++)this.textures[r]=new Un({width:e,height:t,depth:n.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(n),this.depthBuffer=n.depthBuffer,this.stencilBuffer=n.stencilBuffer,this.resolveColorBuffer=n.resolveColorBuffer,this.resolveDepthBuffer=n.resolveDepthBuffer,this.resolveStencilBuffer=n.resolveStencilBuffer,this.storeMultisampledColorBuffer=n.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=n.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=n.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=n.depthTexture,this.samples=n.samples,this.multiview=n.multiview,this.useArrayDepthTexture=n.useArrayDepthTexture}_setTextureOptions(e={}){const t={minFilter:Yn,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let n=0;n<this.textures.length;n++)this.textures[n].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,n=1){if(this.width!==e||this.height!==t||this.depth!==n){this.width=e,this.height=t,this.depth=n;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=e,this.textures[s].image.height=t,this.textures[s].image.depth=n,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,n=e.textures.length;t<n;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;const s=Object.assign({},e.textures[t].image);this.textures[t].source=new Qh(s)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){const t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}}class qi extends t_{constructor(e=1,t=1,n={}){super(e,t,n),this.isWebGLRenderTarget=!0}}class Up extends Un{constructor(e=null,t=1,n=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:n,depth:s},this.magFilter=Ln,this.minFilter=Ln,this.wrapR=os,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}}class n_ extends Un{constructor(e=null,t=1,n=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:n,depth:s},this.magFilter=Ln,this.minFilter=Ln,this.wrapR=os,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}}class Nt{static{this.prototype.isMatrix4=!0}constructor(e,t,n,s,r,a,o,l,c,h,u,d,m,_,S,p){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,n,s,r,a,o,l,c,h,u,d,m,_,S,p)}set(e,t,n,s,r,a,o,l,c,h,u,d,m,_,S,p){const f=this.elements;return f[0]=e,f[4]=t,f[8]=n,f[12]=s,f[1]=r,f[5]=a,f[9]=o,f[13]=l,f[2]=c,f[6]=h,f[10]=u,f[14]=d,f[3]=m,f[7]=_,f[11]=S,f[15]=p,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new Nt().fromArray(this.elements)}copy(e){const t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],t[9]=n[9],t[10]=n[10],t[11]=n[11],t[12]=n[12],t[13]=n[13],t[14]=n[14],t[15]=n[15],this}copyPosition(e){const t=this.elements,n=e.elements;return t[12]=n[12],t[13]=n[13],t[14]=n[14],this}setFromMatrix3(e){const t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,n){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),n.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),n.setFromMatrixColumn(this,2),this)}makeBasis(e,t,n){return this.set(e.x,t.x,n.x,0,e.y,t.y,n.y,0,e.z,t.z,n.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();const t=this.elements,n=e.elements,s=1/fr.setFromMatrixColumn(e,0).length(),r=1/fr.setFromMatrixColumn(e,1).length(),a=1/fr.setFromMatrixColumn(e,2).length();return t[0]=n[0]*s,t[1]=n[1]*s,t[2]=n[2]*s,t[3]=0,t[4]=n[4]*r,t[5]=n[5]*r,t[6]=n[6]*r,t[7]=0,t[8]=n[8]*a,t[9]=n[9]*a,t[10]=n[10]*a,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){const t=this.elements,n=e.x,s=e.y,r=e.z,a=Math.cos(n),o=Math.sin(n),l=Math.cos(s),c=Math.sin(s),h=Math.cos(r),u=Math.sin(r);if(e.order==="XYZ"){const d=a*h,m=a*u,_=o*h,S=o*u;t[0]=l*h,t[4]=-l*u,t[8]=c,t[1]=m+_*c,t[5]=d-S*c,t[9]=-o*l,t[2]=S-d*c,t[6]=_+m*c,t[10]=a*l}else if(e.order==="YXZ"){const d=l*h,m=l*u,_=c*h,S=c*u;t[0]=d+S*o,t[4]=_*o-m,t[8]=a*c,t[1]=a*u,t[5]=a*h,t[9]=-o,t[2]=m*o-_,t[6]=S+d*o,t[10]=a*l}else if(e.order==="ZXY"){const d=l*h,m=l*u,_=c*h,S=c*u;t[0]=d-S*o,t[4]=-a*u,t[8]=_+m*o,t[1]=m+_*o,t[5]=a*h,t[9]=S-d*o,t[2]=-a*c,t[6]=o,t[10]=a*l}else if(e.order==="ZYX"){const d=a*h,m=a*u,_=o*h,S=o*u;t[0]=l*h,t[4]=_*c-m,t[8]=d*c+S,t[1]=l*u,t[5]=S*c+d,t[9]=m*c-_,t[2]=-c,t[6]=o*l,t[10]=a*l}else if(e.order==="YZX"){const d=a*l,m=a*c,_=o*l,S=o*c;t[0]=l*h,t[4]=S-d*u,t[8]=_*u+m,t[1]=u,t[5]=a*h,t[9]=-o*h,t[2]=-c*h,t[6]=m*u+_,t[10]=d-S*u}else if(e.order==="XZY"){const d=a*l,m=a*c,_=o*l,S=o*c;t[0]=l*h,t[4]=-u,t[8]=c*h,t[1]=d*u+S,t[5]=a*h,t[9]=m*u-_,t[2]=_*u-m,t[6]=o*h,t[10]=S*u+d}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(i_,e,s_)}lookAt(e,t,n){const s=this.elements;return ei.subVectors(e,t),ei.lengthSq()===0&&(ei.z=1),ei.normalize(),xs.crossVectors(n,ei),xs.lengthSq()===0&&(Math.abs(n.z)===1?ei.x+=1e-4:ei.z+=1e-4,ei.normalize(),xs.crossVectors(n,ei)),xs.normalize(),Qa.crossVectors(ei,xs),s[0]=xs.x,s[4]=Qa.x,s[8]=ei.x,s[1]=xs.y,s[5]=Qa.y,s[9]=ei.y,s[2]=xs.z,s[6]=Qa.z,s[10]=ei.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const n=e.elements,s=t.elements,r=this.elements,a=n[0],o=n[4],l=n[8],c=n[12],h=n[1],u=n[5],d=n[9],m=n[13],_=n[2],S=n[6],p=n[10],f=n[14],x=n[3],R=n[7],y=n[11],A=n[15],w=s[0],g=s[4],b=s[8],I=s[12],N=s[1],P=s[5],B=s[9],V=s[13],U=s[2],W=s[6],Z=s[10],H=s[14],he=s[3],J=s[7],ee=s[11],se=s[15];return r[0]=a*w+o*N+l*U+c*he,r[4]=a*g+o*P+l*W+c*J,r[8]=a*b+o*B+l*Z+c*ee,r[12]=a*I+o*V+l*H+c*se,r[1]=h*w+u*N+d*U+m*he,r[5]=h*g+u*P+d*W+m*J,r[9]=h*b+u*B+d*Z+m*ee,r[13]=h*I+u*V+d*H+m*se,r[2]=_*w+S*N+p*U+f*he,r[6]=_*g+S*P+p*W+f*J,r[10]=_*b+S*B+p*Z+f*ee,r[14]=_*I+S*V+p*H+f*se,r[3]=x*w+R*N+y*U+A*he,r[7]=x*g+R*P+y*W+A*J,r[11]=x*b+R*B+y*Z+A*ee,r[15]=x*I+R*V+y*H+A*se,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){const e=this.elements,t=e[0],n=e[4],s=e[8],r=e[12],a=e[1],o=e[5],l=e[9],c=e[13],h=e[2],u=e[6],d=e[10],m=e[14],_=e[3],S=e[7],p=e[11],f=e[15],x=l*m-c*d,R=o*m-c*u,y=o*d-l*u,A=a*m-c*h,w=a*d-l*h,g=a*u-o*h;return t*(S*x-p*R+f*y)-n*(_*x-p*A+f*w)+s*(_*R-S*A+f*g)-r*(_*y-S*w+p*g)}determinantAffine(){const e=this.elements,t=e[0],n=e[4],s=e[8],r=e[1],a=e[5],o=e[9],l=e[2],c=e[6],h=e[10];return t*(a*h-o*c)-n*(r*h-o*l)+s*(r*c-a*l)}transpose(){const e=this.elements;let t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,n){const s=this.elements;return e.isVector3?(s[12]=e.x,s[13]=e.y,s[14]=e.z):(s[12]=e,s[13]=t,s[14]=n),this}invert(){const e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],h=e[8],u=e[9],d=e[10],m=e[11],_=e[12],S=e[13],p=e[14],f=e[15],x=t*o-n*a,R=t*l-s*a,y=t*c-r*a,A=n*l-s*o,w=n*c-r*o,g=s*c-r*l,b=h*S-u*_,I=h*p-d*_,N=h*f-m*_,P=u*p-d*S,B=u*f-m*S,V=d*f-m*p,U=x*V-R*B+y*P+A*N-w*I+g*b;if(U===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);const W=1/U;return e[0]=(o*V-l*B+c*P)*W,e[1]=(s*B-n*V-r*P)*W,e[2]=(S*g-p*w+f*A)*W,e[3]=(d*w-u*g-m*A)*W,e[4]=(l*N-a*V-c*I)*W,e[5]=(t*V-s*N+r*I)*W,e[6]=(p*y-_*g-f*R)*W,e[7]=(h*g-d*y+m*R)*W,e[8]=(a*B-o*N+c*b)*W,e[9]=(n*N-t*B-r*b)*W,e[10]=(_*w-S*y+f*x)*W,e[11]=(u*y-h*w-m*x)*W,e[12]=(o*I-a*P-l*b)*W,e[13]=(t*P-n*I+s*b)*W,e[14]=(S*R-_*A-p*x)*W,e[15]=(h*A-u*R+d*x)*W,this}scale(e){const t=this.elements,n=e.x,s=e.y,r=e.z;return t[0]*=n,t[4]*=s,t[8]*=r,t[1]*=n,t[5]*=s,t[9]*=r,t[2]*=n,t[6]*=s,t[10]*=r,t[3]*=n,t[7]*=s,t[11]*=r,this}getMaxScaleOnAxis(){const e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],n=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],s=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,n,s))}makeTranslation(e,t,n){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,n,0,0,0,1),this}makeRotationX(e){const t=Math.cos(e),n=Math.sin(e);return this.set(1,0,0,0,0,t,-n,0,0,n,t,0,0,0,0,1),this}makeRotationY(e){const t=Math.cos(e),n=Math.sin(e);return this.set(t,0,n,0,0,1,0,0,-n,0,t,0,0,0,0,1),this}makeRotationZ(e){const t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,0,n,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){const n=Math.cos(t),s=Math.sin(t),r=1-n,a=e.x,o=e.y,l=e.z,c=r*a,h=r*o;return this.set(c*a+n,c*o-s*l,c*l+s*o,0,c*o+s*l,h*o+n,h*l-s*a,0,c*l-s*o,h*l+s*a,r*l*l+n,0,0,0,0,1),this}makeScale(e,t,n){return this.set(e,0,0,0,0,t,0,0,0,0,n,0,0,0,0,1),this}makeShear(e,t,n,s,r,a){return this.set(1,n,r,0,e,1,a,0,t,s,1,0,0,0,0,1),this}compose(e,t,n){const s=this.elements,r=t._x,a=t._y,o=t._z,l=t._w,c=r+r,h=a+a,u=o+o,d=r*c,m=r*h,_=r*u,S=a*h,p=a*u,f=o*u,x=l*c,R=l*h,y=l*u,A=n.x,w=n.y,g=n.z;return s[0]=(1-(S+f))*A,s[1]=(m+y)*A,s[2]=(_-R)*A,s[3]=0,s[4]=(m-y)*w,s[5]=(1-(d+f))*w,s[6]=(p+x)*w,s[7]=0,s[8]=(_+R)*g,s[9]=(p-x)*g,s[10]=(1-(d+S))*g,s[11]=0,s[12]=e.x,s[13]=e.y,s[14]=e.z,s[15]=1,this}decompose(e,t,n){const s=this.elements;e.x=s[12],e.y=s[13],e.z=s[14];const r=this.determinantAffine();if(r===0)return n.set(1,1,1),t.identity(),this;let a=fr.set(s[0],s[1],s[2]).length();const o=fr.set(s[4],s[5],s[6]).length(),l=fr.set(s[8],s[9],s[10]).length();r<0&&(a=-a),Mi.copy(this);const c=1/a,h=1/o,u=1/l;return Mi.elements[0]*=c,Mi.elements[1]*=c,Mi.elements[2]*=c,Mi.elements[4]*=h,Mi.elements[5]*=h,Mi.elements[6]*=h,Mi.elements[8]*=u,Mi.elements[9]*=u,Mi.elements[10]*=u,t.setFromRotationMatrix(Mi),n.x=a,n.y=o,n.z=l,this}makePerspective(e,t,n,s,r,a,o=Ci,l=!1){const c=this.elements,h=2*r/(t-e),u=2*r/(n-s),d=(t+e)/(t-e),m=(n+s)/(n-s);let _,S;if(l)_=r/(a-r),S=a*r/(a-r);else if(o===Ci)_=-(a+r)/(a-r),S=-2*a*r/(a-r);else if(o===Ia)_=-a/(a-r),S=-a*r/(a-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return c[0]=h,c[4]=0,c[8]=d,c[12]=0,c[1]=0,c[5]=u,c[9]=m,c[13]=0,c[2]=0,c[6]=0,c[10]=_,c[14]=S,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(e,t,n,s,r,a,o=Ci,l=!1){const c=this.elements,h=2/(t-e),u=2/(n-s),d=-(t+e)/(t-e),m=-(n+s)/(n-s);let _,S;if(l)_=1/(a-r),S=a/(a-r);else if(o===Ci)_=-2/(a-r),S=-(a+r)/(a-r);else if(o===Ia)_=-1/(a-r),S=-r/(a-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return c[0]=h,c[4]=0,c[8]=0,c[12]=d,c[1]=0,c[5]=u,c[9]=0,c[13]=m,c[2]=0,c[6]=0,c[10]=_,c[14]=S,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(e){const t=this.elements,n=e.elements;for(let s=0;s<16;s++)if(t[s]!==n[s])return!1;return!0}fromArray(e,t=0){for(let n=0;n<16;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){const n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e[t+9]=n[9],e[t+10]=n[10],e[t+11]=n[11],e[t+12]=n[12],e[t+13]=n[13],e[t+14]=n[14],e[t+15]=n[15],e}}const fr=new z,Mi=new Nt,i_=new z(0,0,0),s_=new z(1,1,1),xs=new z,Qa=new z,ei=new z,Qu=new Nt,ed=new Ls;class Ds{constructor(e=0,t=0,n=0,s=Ds.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=n,this._order=s}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,n,s=this._order){return this._x=e,this._y=t,this._z=n,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,n=!0){const s=e.elements,r=s[0],a=s[4],o=s[8],l=s[1],c=s[5],h=s[9],u=s[2],d=s[6],m=s[10];switch(t){case"XYZ":this._y=Math.asin(mt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-h,m),this._z=Math.atan2(-a,r)):(this._x=Math.atan2(d,c),this._z=0);break;case"YXZ":this._x=Math.asin(-mt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(o,m),this._z=Math.atan2(l,c)):(this._y=Math.atan2(-u,r),this._z=0);break;case"ZXY":this._x=Math.asin(mt(d,-1,1)),Math.abs(d)<.9999999?(this._y=Math.atan2(-u,m),this._z=Math.atan2(-a,c)):(this._y=0,this._z=Math.atan2(l,r));break;case"ZYX":this._y=Math.asin(-mt(u,-1,1)),Math.abs(u)<.9999999?(this._x=Math.atan2(d,m),this._z=Math.atan2(l,r)):(this._x=0,this._z=Math.atan2(-a,c));break;case"YZX":this._z=Math.asin(mt(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-h,c),this._y=Math.atan2(-u,r)):(this._x=0,this._y=Math.atan2(o,m));break;case"XZY":this._z=Math.asin(-mt(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(d,c),this._y=Math.atan2(o,r)):(this._x=Math.atan2(-h,m),this._y=0);break;default:tt("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,n===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,n){return Qu.makeRotationFromQuaternion(e),this.setFromRotationMatrix(Qu,t,n)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return ed.setFromEuler(this),this.setFromQuaternion(ed,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}}Ds.DEFAULT_ORDER="XYZ";class eu{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}}let r_=0;const td=new z,pr=new Ls,ns=new Nt,eo=new z,ra=new z,a_=new z,o_=new Ls,nd=new z(1,0,0),id=new z(0,1,0),sd=new z(0,0,1),rd={type:"added"},l_={type:"removed"},mr={type:"childadded",child:null},$l={type:"childremoved",child:null};class Sn extends Is{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:r_++}),this.uuid=js(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=Sn.DEFAULT_UP.clone();const e=new z,t=new Ds,n=new Ls,s=new z(1,1,1);function r(){n.setFromEuler(t,!1)}function a(){t.setFromQuaternion(n,void 0,!1)}t._onChange(r),n._onChange(a),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:n},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new Nt},normalMatrix:{value:new rt}}),this.matrix=new Nt,this.matrixWorld=new Nt,this.matrixAutoUpdate=Sn.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=Sn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new eu,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return pr.setFromAxisAngle(e,t),this.quaternion.multiply(pr),this}rotateOnWorldAxis(e,t){return pr.setFromAxisAngle(e,t),this.quaternion.premultiply(pr),this}rotateX(e){return this.rotateOnAxis(nd,e)}rotateY(e){return this.rotateOnAxis(id,e)}rotateZ(e){return this.rotateOnAxis(sd,e)}translateOnAxis(e,t){return td.copy(e).applyQuaternion(this.quaternion),this.position.add(td.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(nd,e)}translateY(e){return this.translateOnAxis(id,e)}translateZ(e){return this.translateOnAxis(sd,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(ns.copy(this.matrixWorld).invert())}lookAt(e,t,n){e.isVector3?eo.copy(e):eo.set(e,t,n);const s=this.parent;this.updateWorldMatrix(!0,!1),ra.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?ns.lookAt(ra,eo,this.up):ns.lookAt(eo,ra,this.up),this.quaternion.setFromRotationMatrix(ns),s&&(ns.extractRotation(s.matrixWorld),pr.setFromRotationMatrix(ns),this.quaternion.premultiply(pr.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(St("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(rd),mr.child=e,this.dispatchEvent(mr),mr.child=null):St("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let n=0;n<arguments.length;n++)this.remove(arguments[n]);return this}const t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(l_),$l.child=e,this.dispatchEvent($l),$l.child=null),this}removeFromParent(){const e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),ns.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),ns.multiply(e.parent.matrixWorld)),e.applyMatrix4(ns),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(rd),mr.child=e,this.dispatchEvent(mr),mr.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let n=0,s=this.children.length;n<s;n++){const a=this.children[n].getObjectByProperty(e,t);if(a!==void 0)return a}}getObjectsByProperty(e,t,n=[]){this[e]===t&&n.push(this);const s=this.children;for(let r=0,a=s.length;r<a;r++)s[r].getObjectsByProperty(e,t,n);return n}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ra,e,a_),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ra,o_,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);const t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);const t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);const t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].traverseVisible(e)}traverseAncestors(e){const t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);const e=this.pivot;if(e!==null){const t=e.x,n=e.y,s=e.z,r=this.matrix.elements;r[12]+=t-r[0]*t-r[4]*n-r[8]*s,r[13]+=n-r[1]*t-r[5]*n-r[9]*s,r[14]+=s-r[2]*t-r[6]*n-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);const t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].updateMatrixWorld(e)}updateWorldMatrix(e,t,n=!1){const s=this.parent;if(e===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||n)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,n=!0),t===!0){const r=this.children;for(let a=0,o=r.length;a<o;a++)r[a].updateWorldMatrix(!1,!0,n)}}toJSON(e){const t=e===void 0||typeof e=="string",n={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},n.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});const s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(o=>({...o,boundingBox:o.boundingBox?o.boundingBox.toJSON():void 0,boundingSphere:o.boundingSphere?o.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(o=>({...o})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(e),s.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(o,l){return o[l.uuid]===void 0&&(o[l.uuid]=l.toJSON(e)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(e.geometries,this.geometry);const o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){const l=o.shapes;if(Array.isArray(l))for(let c=0,h=l.length;c<h;c++){const u=l[c];r(e.shapes,u)}else r(e.shapes,l)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){const o=[];for(let l=0,c=this.material.length;l<c;l++)o.push(r(e.materials,this.material[l]));s.material=o}else s.material=r(e.materials,this.material);if(this.children.length>0){s.children=[];for(let o=0;o<this.children.length;o++)s.children.push(this.children[o].toJSON(e).object)}if(this.animations.length>0){s.animations=[];for(let o=0;o<this.animations.length;o++){const l=this.animations[o];s.animations.push(r(e.animations,l))}}if(t){const o=a(e.geometries),l=a(e.materials),c=a(e.textures),h=a(e.images),u=a(e.shapes),d=a(e.skeletons),m=a(e.animations),_=a(e.nodes);o.length>0&&(n.geometries=o),l.length>0&&(n.materials=l),c.length>0&&(n.textures=c),h.length>0&&(n.images=h),u.length>0&&(n.shapes=u),d.length>0&&(n.skeletons=d),m.length>0&&(n.animations=m),_.length>0&&(n.nodes=_)}return n.object=s,n;function a(o){const l=[];for(const c in o){const h=o[c];delete h.metadata,l.push(h)}return l}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let n=0;n<e.children.length;n++){const s=e.children[n];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}}Sn.DEFAULT_UP=new z(0,1,0);Sn.DEFAULT_MATRIX_AUTO_UPDATE=!0;Sn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;class Xi extends Sn{constructor(){super(),this.isGroup=!0,this.type="Group"}}const c_={type:"move"};class ql{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Xi,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Xi,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new z,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new z),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Xi,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new z,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new z,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){const t=this._hand;if(t)for(const n of e.hand.values())this._getHandJoint(t,n)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,n){let s=null,r=null,a=null;const o=this._targetRay,l=this._grip,c=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(c&&e.hand){a=!0;for(const S of e.hand.values()){const p=t.getJointPose(S,n),f=this._getHandJoint(c,S);p!==null&&(f.matrix.fromArray(p.transform.matrix),f.matrix.decompose(f.position,f.quaternion,f.scale),f.matrixWorldNeedsUpdate=!0,f.jointRadius=p.radius),f.visible=p!==null}const h=c.joints["index-finger-tip"],u=c.joints["thumb-tip"],d=h.position.distanceTo(u.position),m=.02,_=.005;c.inputState.pinching&&d>m+_?(c.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!c.inputState.pinching&&d<=m-_&&(c.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else l!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,n),r!==null&&(l.matrix.fromArray(r.transform.matrix),l.matrix.decompose(l.position,l.quaternion,l.scale),l.matrixWorldNeedsUpdate=!0,r.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(r.linearVelocity)):l.hasLinearVelocity=!1,r.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(r.angularVelocity)):l.hasAngularVelocity=!1,l.eventsEnabled&&l.dispatchEvent({type:"gripUpdated",data:e,target:this})));o!==null&&(s=t.getPose(e.targetRaySpace,n),s===null&&r!==null&&(s=r),s!==null&&(o.matrix.fromArray(s.transform.matrix),o.matrix.decompose(o.position,o.quaternion,o.scale),o.matrixWorldNeedsUpdate=!0,s.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(s.linearVelocity)):o.hasLinearVelocity=!1,s.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(s.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(c_)))}return o!==null&&(o.visible=s!==null),l!==null&&(l.visible=r!==null),c!==null&&(c.visible=a!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){const n=new Xi;n.matrixAutoUpdate=!1,n.visible=!1,e.joints[t.jointName]=n,e.add(n)}return e.joints[t.jointName]}}const Fp={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},Ss={h:0,s:0,l:0},to={h:0,s:0,l:0};function Yl(i,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?i+(e-i)*6*t:t<1/2?e:t<2/3?i+(e-i)*6*(2/3-t):i}class ct{constructor(e,t,n){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,n)}set(e,t,n){if(t===void 0&&n===void 0){const s=e;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(e,t,n);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=ui){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,vt.colorSpaceToWorking(this,t),this}setRGB(e,t,n,s=vt.workingColorSpace){return this.r=e,this.g=t,this.b=n,vt.colorSpaceToWorking(this,s),this}setHSL(e,t,n,s=vt.workingColorSpace){if(e=Y0(e,1),t=mt(t,0,1),n=mt(n,0,1),t===0)this.r=this.g=this.b=n;else{const r=n<=.5?n*(1+t):n+t-n*t,a=2*n-r;this.r=Yl(a,r,e+1/3),this.g=Yl(a,r,e),this.b=Yl(a,r,e-1/3)}return vt.colorSpaceToWorking(this,s),this}setStyle(e,t=ui){function n(r){r!==void 0&&parseFloat(r)<1&&tt("Color: Alpha component of "+e+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(e)){let r;const a=s[1],o=s[2];switch(a){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,t);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:tt("Color: Unknown color model "+e)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(e)){const r=s[1],a=r.length;if(a===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(a===6)return this.setHex(parseInt(r,16),t);tt("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=ui){const n=Fp[e.toLowerCase()];return n!==void 0?this.setHex(n,t):tt("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=hs(e.r),this.g=hs(e.g),this.b=hs(e.b),this}copyLinearToSRGB(e){return this.r=Fr(e.r),this.g=Fr(e.g),this.b=Fr(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=ui){return vt.workingToColorSpace(In.copy(this),e),Math.round(mt(In.r*255,0,255))*65536+Math.round(mt(In.g*255,0,255))*256+Math.round(mt(In.b*255,0,255))}getHexString(e=ui){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=vt.workingColorSpace){vt.workingToColorSpace(In.copy(this),t);const n=In.r,s=In.g,r=In.b,a=Math.max(n,s,r),o=Math.min(n,s,r);let l,c;const h=(o+a)/2;if(o===a)l=0,c=0;else{const u=a-o;switch(c=h<=.5?u/(a+o):u/(2-a-o),a){case n:l=(s-r)/u+(s<r?6:0);break;case s:l=(r-n)/u+2;break;case r:l=(n-s)/u+4;break}l/=6}return e.h=l,e.s=c,e.l=h,e}getRGB(e,t=vt.workingColorSpace){return vt.workingToColorSpace(In.copy(this),t),e.r=In.r,e.g=In.g,e.b=In.b,e}getStyle(e=ui){vt.workingToColorSpace(In.copy(this),e);const t=In.r,n=In.g,s=In.b;return e!==ui?`color(${e} ${t.toFixed(3)} ${n.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(n*255)},${Math.round(s*255)})`}offsetHSL(e,t,n){return this.getHSL(Ss),this.setHSL(Ss.h+e,Ss.s+t,Ss.l+n)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,n){return this.r=e.r+(t.r-e.r)*n,this.g=e.g+(t.g-e.g)*n,this.b=e.b+(t.b-e.b)*n,this}lerpHSL(e,t){this.getHSL(Ss),e.getHSL(to);const n=Hl(Ss.h,to.h,t),s=Hl(Ss.s,to.s,t),r=Hl(Ss.l,to.l,t);return this.setHSL(n,s,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){const t=this.r,n=this.g,s=this.b,r=e.elements;return this.r=r[0]*t+r[3]*n+r[6]*s,this.g=r[1]*t+r[4]*n+r[7]*s,this.b=r[2]*t+r[5]*n+r[8]*s,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}}const In=new ct;ct.NAMES=Fp;class Op extends Sn{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Ds,this.environmentIntensity=1,this.environmentRotation=new Ds,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){const t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}}const bi=new z,is=new z,Kl=new z,ss=new z,gr=new z,_r=new z,ad=new z,Zl=new z,Jl=new z,jl=new z,Ql=new an,ec=new an,tc=new an;class mi{constructor(e=new z,t=new z,n=new z){this.a=e,this.b=t,this.c=n}static getNormal(e,t,n,s){s.subVectors(n,t),bi.subVectors(e,t),s.cross(bi);const r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(e,t,n,s,r){bi.subVectors(s,t),is.subVectors(n,t),Kl.subVectors(e,t);const a=bi.dot(bi),o=bi.dot(is),l=bi.dot(Kl),c=is.dot(is),h=is.dot(Kl),u=a*c-o*o;if(u===0)return r.set(0,0,0),null;const d=1/u,m=(c*l-o*h)*d,_=(a*h-o*l)*d;return r.set(1-m-_,_,m)}static containsPoint(e,t,n,s){return this.getBarycoord(e,t,n,s,ss)===null?!1:ss.x>=0&&ss.y>=0&&ss.x+ss.y<=1}static getInterpolation(e,t,n,s,r,a,o,l){return this.getBarycoord(e,t,n,s,ss)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(r,ss.x),l.addScaledVector(a,ss.y),l.addScaledVector(o,ss.z),l)}static getInterpolatedAttribute(e,t,n,s,r,a){return Ql.setScalar(0),ec.setScalar(0),tc.setScalar(0),Ql.fromBufferAttribute(e,t),ec.fromBufferAttribute(e,n),tc.fromBufferAttribute(e,s),a.setScalar(0),a.addScaledVector(Ql,r.x),a.addScaledVector(ec,r.y),a.addScaledVector(tc,r.z),a}static isFrontFacing(e,t,n,s){return bi.subVectors(n,t),is.subVectors(e,t),bi.cross(is).dot(s)<0}set(e,t,n){return this.a.copy(e),this.b.copy(t),this.c.copy(n),this}setFromPointsAndIndices(e,t,n,s){return this.a.copy(e[t]),this.b.copy(e[n]),this.c.copy(e[s]),this}setFromAttributeAndIndices(e,t,n,s){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,n),this.c.fromBufferAttribute(e,s),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return bi.subVectors(this.c,this.b),is.subVectors(this.a,this.b),bi.cross(is).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return mi.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return mi.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,n,s,r){return mi.getInterpolation(e,this.a,this.b,this.c,t,n,s,r)}containsPoint(e){return mi.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return mi.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){const n=this.a,s=this.b,r=this.c;let a,o;gr.subVectors(s,n),_r.subVectors(r,n),Zl.subVectors(e,n);const l=gr.dot(Zl),c=_r.dot(Zl);if(l<=0&&c<=0)return t.copy(n);Jl.subVectors(e,s);const h=gr.dot(Jl),u=_r.dot(Jl);if(h>=0&&u<=h)return t.copy(s);const d=l*u-h*c;if(d<=0&&l>=0&&h<=0&&l-h>0)return a=l/(l-h),t.copy(n).addScaledVector(gr,a);jl.subVectors(e,r);const m=gr.dot(jl),_=_r.dot(jl);if(_>=0&&m<=_)return t.copy(r);const S=m*c-l*_;if(S<=0&&c>=0&&_<=0)return o=c/(c-_),t.copy(n).addScaledVector(_r,o);const p=h*_-m*u;if(p<=0&&u-h>=0&&m-_>=0)return ad.subVectors(r,s),o=(u-h)/(u-h+(m-_)),t.copy(s).addScaledVector(ad,o);const f=1/(p+S+d);return a=S*f,o=d*f,t.copy(n).addScaledVector(gr,a).addScaledVector(_r,o)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}}class Ga{constructor(e=new z(1/0,1/0,1/0),t=new z(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t+=3)this.expandByPoint(wi.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,n=e.count;t<n;t++)this.expandByPoint(wi.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){const n=wi.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(n),this.max.copy(e).add(n),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);const n=e.geometry;if(n!==void 0){const r=n.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let a=0,o=r.count;a<o;a++)e.isMesh===!0?e.getVertexPosition(a,wi):wi.fromBufferAttribute(r,a),wi.applyMatrix4(e.matrixWorld),this.expandByPoint(wi);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),no.copy(e.boundingBox)):(n.boundingBox===null&&n.computeBoundingBox(),no.copy(n.boundingBox)),no.applyMatrix4(e.matrixWorld),this.union(no)}const s=e.children;for(let r=0,a=s.length;r<a;r++)this.expandByObject(s[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,wi),wi.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,n;return e.normal.x>0?(t=e.normal.x*this.min.x,n=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,n=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,n+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,n+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,n+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,n+=e.normal.z*this.min.z),t<=-e.constant&&n>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(aa),io.subVectors(this.max,aa),vr.subVectors(e.a,aa),xr.subVectors(e.b,aa),Sr.subVectors(e.c,aa),ys.subVectors(xr,vr),Ms.subVectors(Sr,xr),ks.subVectors(vr,Sr);let t=[0,-ys.z,ys.y,0,-Ms.z,Ms.y,0,-ks.z,ks.y,ys.z,0,-ys.x,Ms.z,0,-Ms.x,ks.z,0,-ks.x,-ys.y,ys.x,0,-Ms.y,Ms.x,0,-ks.y,ks.x,0];return!nc(t,vr,xr,Sr,io)||(t=[1,0,0,0,1,0,0,0,1],!nc(t,vr,xr,Sr,io))?!1:(so.crossVectors(ys,Ms),t=[so.x,so.y,so.z],nc(t,vr,xr,Sr,io))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,wi).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(wi).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(rs[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),rs[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),rs[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),rs[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),rs[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),rs[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),rs[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),rs[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(rs),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}}const rs=[new z,new z,new z,new z,new z,new z,new z,new z],wi=new z,no=new Ga,vr=new z,xr=new z,Sr=new z,ys=new z,Ms=new z,ks=new z,aa=new z,io=new z,so=new z,Bs=new z;function nc(i,e,t,n,s){for(let r=0,a=i.length-3;r<=a;r+=3){Bs.fromArray(i,r);const o=s.x*Math.abs(Bs.x)+s.y*Math.abs(Bs.y)+s.z*Math.abs(Bs.z),l=e.dot(Bs),c=t.dot(Bs),h=n.dot(Bs);if(Math.max(-Math.max(l,c,h),Math.min(l,c,h))>o)return!1}return!0}const fn=new z,ro=new Ye;let h_=0;class gi extends Is{constructor(e,t,n=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:h_++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=n,this.usage=Lp,this.updateRanges=[],this.gpuType=Vi,this.version=0,this._normalizationScale=e!==void 0?ll(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,n){e*=this.itemSize,n*=t.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[e+s]=t.array[n+s];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,n=this.count;t<n;t++)ro.fromBufferAttribute(this,t),ro.applyMatrix3(e),this.setXY(t,ro.x,ro.y);else if(this.itemSize===3)for(let t=0,n=this.count;t<n;t++)fn.fromBufferAttribute(this,t),fn.applyMatrix3(e),this.setXYZ(t,fn.x,fn.y,fn.z);return this}applyMatrix4(e){for(let t=0,n=this.count;t<n;t++)fn.fromBufferAttribute(this,t),fn.applyMatrix4(e),this.setXYZ(t,fn.x,fn.y,fn.z);return this}applyNormalMatrix(e){for(let t=0,n=this.count;t<n;t++)fn.fromBufferAttribute(this,t),fn.applyNormalMatrix(e),this.setXYZ(t,fn.x,fn.y,fn.z);return this}transformDirection(e){for(let t=0,n=this.count;t<n;t++)fn.fromBufferAttribute(this,t),fn.transformDirection(e),this.setXYZ(t,fn.x,fn.y,fn.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let n=this.array[e*this.itemSize+t];return this.normalized&&(n=this._denormalize(n)),n}setComponent(e,t,n){return this.normalized&&(n=this._normalize(n)),this.array[e*this.itemSize+t]=n,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,n){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n)),this.array[e+0]=t,this.array[e+1]=n,this}setXYZ(e,t,n,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=s,this}setXYZW(e,t,n,s,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=s,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){const e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){const t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):Np(e,this.array)}_normalize(e){const t=this._normalizationScale;return t!==void 0?Math.round(e*t):Ip(e,this.array)}}class kp extends gi{constructor(e,t,n){super(new Uint16Array(e),t,n)}}class Bp extends gi{constructor(e,t,n){super(new Uint32Array(e),t,n)}}class ln extends gi{constructor(e,t,n){super(new Float32Array(e),t,n)}}const u_=new Ga,oa=new z,ic=new z;class Va{constructor(e=new z,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){const n=this.center;t!==void 0?n.copy(t):u_.setFromPoints(e).getCenter(n);let s=0;for(let r=0,a=e.length;r<a;r++)s=Math.max(s,n.distanceToSquared(e[r]));return this.radius=Math.sqrt(s),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){const t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){const n=this.center.distanceToSquared(e);return t.copy(e),n>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;oa.subVectors(e,this.center);const t=oa.lengthSq();if(t>this.radius*this.radius){const n=Math.sqrt(t),s=(n-this.radius)*.5;this.center.addScaledVector(oa,s/n),this.radius+=s}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(ic.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(oa.copy(e.center).add(ic)),this.expandByPoint(oa.copy(e.center).sub(ic))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}}let d_=0;const li=new Nt,sc=new Sn,yr=new z,ti=new Ga,la=new Ga,Rn=new z;class Gt extends Is{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:d_++}),this.uuid=js(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(W0(e)?Bp:kp)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,n=0){this.groups.push({start:e,count:t,materialIndex:n})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){const t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);const n=this.attributes.normal;if(n!==void 0){const r=new rt().getNormalMatrix(e);n.applyNormalMatrix(r),n.needsUpdate=!0}const s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(e),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return li.makeRotationFromQuaternion(e),this.applyMatrix4(li),this}rotateX(e){return li.makeRotationX(e),this.applyMatrix4(li),this}rotateY(e){return li.makeRotationY(e),this.applyMatrix4(li),this}rotateZ(e){return li.makeRotationZ(e),this.applyMatrix4(li),this}translate(e,t,n){return li.makeTranslation(e,t,n),this.applyMatrix4(li),this}scale(e,t,n){return li.makeScale(e,t,n),this.applyMatrix4(li),this}lookAt(e){return sc.lookAt(e),sc.updateMatrix(),this.applyMatrix4(sc.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(yr).negate(),this.translate(yr.x,yr.y,yr.z),this}setFromPoints(e){const t=this.getAttribute("position");if(t===void 0){const n=[];for(let s=0,r=e.length;s<r;s++){const a=e[s];n.push(a.x,a.y,a.z||0)}this.setAttribute("position",new ln(n,3))}else{const n=Math.min(e.length,t.count);for(let s=0;s<n;s++){const r=e[s];t.setXYZ(s,r.x,r.y,r.z||0)}e.length>t.count&&tt("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Ga);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){St("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new z(-1/0,-1/0,-1/0),new z(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let n=0,s=t.length;n<s;n++){const r=t[n];ti.setFromBufferAttribute(r),this.morphTargetsRelative?(Rn.addVectors(this.boundingBox.min,ti.min),this.boundingBox.expandByPoint(Rn),Rn.addVectors(this.boundingBox.max,ti.max),this.boundingBox.expandByPoint(Rn)):(this.boundingBox.expandByPoint(ti.min),this.boundingBox.expandByPoint(ti.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&St('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Va);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){St("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new z,1/0);return}if(e){const n=this.boundingSphere.center;if(ti.setFromBufferAttribute(e),t)for(let r=0,a=t.length;r<a;r++){const o=t[r];la.setFromBufferAttribute(o),this.morphTargetsRelative?(Rn.addVectors(ti.min,la.min),ti.expandByPoint(Rn),Rn.addVectors(ti.max,la.max),ti.expandByPoint(Rn)):(ti.expandByPoint(la.min),ti.expandByPoint(la.max))}ti.getCenter(n);let s=0;for(let r=0,a=e.count;r<a;r++)Rn.fromBufferAttribute(e,r),s=Math.max(s,n.distanceToSquared(Rn));if(t)for(let r=0,a=t.length;r<a;r++){const o=t[r],l=this.morphTargetsRelative;for(let c=0,h=o.count;c<h;c++)Rn.fromBufferAttribute(o,c),l&&(yr.fromBufferAttribute(e,c),Rn.add(yr)),s=Math.max(s,n.distanceToSquared(Rn))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&St('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){const e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){St("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}const n=t.position,s=t.normal,r=t.uv;let a=this.getAttribute("tangent");(a===void 0||a.count!==n.count)&&(a=new gi(new Float32Array(4*n.count),4),this.setAttribute("tangent",a));const o=[],l=[],c=new Uint8Array(n.count);for(let I=0;I<n.count;I++)o[I]=new z,l[I]=new z;const h=new z,u=new z,d=new z,m=new Ye,_=new Ye,S=new Ye,p=new z,f=new z;function x(I,N,P){c[I]=c[N]=c[P]=1,h.fromBufferAttribute(n,I),u.fromBufferAttribute(n,N),d.fromBufferAttribute(n,P),m.fromBufferAttribute(r,I),_.fromBufferAttribute(r,N),S.fromBufferAttribute(r,P),u.sub(h),d.sub(h),_.sub(m),S.sub(m);const B=1/(_.x*S.y-S.x*_.y);isFinite(B)&&(p.copy(u).multiplyScalar(S.y).addScaledVector(d,-_.y).multiplyScalar(B),f.copy(d).multiplyScalar(_.x).addScaledVector(u,-S.x).multiplyScalar(B),o[I].add(p),o[N].add(p),o[P].add(p),l[I].add(f),l[N].add(f),l[P].add(f))}let R=this.groups;R.length===0&&(R=[{start:0,count:e.count}]);for(let I=0,N=R.length;I<N;++I){const P=R[I],B=P.start,V=P.count;for(let U=B,W=B+V;U<W;U+=3)x(e.getX(U+0),e.getX(U+1),e.getX(U+2))}const y=new z,A=new z,w=new z,g=new z;function b(I){w.fromBufferAttribute(s,I),g.copy(w);const N=o[I];y.copy(N),y.sub(w.multiplyScalar(w.dot(N))).normalize(),A.crossVectors(g,N);const B=A.dot(l[I])<0?-1:1;a.setXYZW(I,y.x,y.y,y.z,B)}for(let I=0,N=n.count;I<N;++I)c[I]&&b(I);this._transformed=!0}computeVertexNormals(){const e=this.index,t=this.getAttribute("position");if(t!==void 0){let n=this.getAttribute("normal");if(n===void 0||n.count!==t.count)n=new gi(new Float32Array(t.count*3),3),this.setAttribute("normal",n);else for(let d=0,m=n.count;d<m;d++)n.setXYZ(d,0,0,0);const s=new z,r=new z,a=new z,o=new z,l=new z,c=new z,h=new z,u=new z;if(e)for(let d=0,m=e.count;d<m;d+=3){const _=e.getX(d+0),S=e.getX(d+1),p=e.getX(d+2);s.fromBufferAttribute(t,_),r.fromBufferAttribute(t,S),a.fromBufferAttribute(t,p),h.subVectors(a,r),u.subVectors(s,r),h.cross(u),o.fromBufferAttribute(n,_),l.fromBufferAttribute(n,S),c.fromBufferAttribute(n,p),o.add(h),l.add(h),c.add(h),n.setXYZ(_,o.x,o.y,o.z),n.setXYZ(S,l.x,l.y,l.z),n.setXYZ(p,c.x,c.y,c.z)}else for(let d=0,m=t.count;d<m;d+=3)s.fromBufferAttribute(t,d+0),r.fromBufferAttribute(t,d+1),a.fromBufferAttribute(t,d+2),h.subVectors(a,r),u.subVectors(s,r),h.cross(u),n.setXYZ(d+0,h.x,h.y,h.z),n.setXYZ(d+1,h.x,h.y,h.z),n.setXYZ(d+2,h.x,h.y,h.z);this.normalizeNormals(),n.needsUpdate=!0}}normalizeNormals(){const e=this.attributes.normal;for(let t=0,n=e.count;t<n;t++)Rn.fromBufferAttribute(e,t),Rn.normalize(),e.setXYZ(t,Rn.x,Rn.y,Rn.z)}toNonIndexed(){function e(o,l){const c=o.array,h=o.itemSize,u=o.normalized,d=new c.constructor(l.length*h);let m=0,_=0;for(let S=0,p=l.length;S<p;S++){o.isInterleavedBufferAttribute?m=l[S]*o.data.stride+o.offset:m=l[S]*h;for(let f=0;f<h;f++)d[_++]=c[m++]}return new gi(d,h,u)}if(this.index===null)return tt("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;const t=new Gt,n=this.index.array,s=this.attributes;for(const o in s){const l=s[o],c=e(l,n);t.setAttribute(o,c)}const r=this.morphAttributes;for(const o in r){const l=[],c=r[o];for(let h=0,u=c.length;h<u;h++){const d=c[h],m=e(d,n);l.push(m)}t.morphAttributes[o]=l}t.morphTargetsRelative=this.morphTargetsRelative;const a=this.groups;for(let o=0,l=a.length;o<l;o++){const c=a[o];t.addGroup(c.start,c.count,c.materialIndex)}return t}toJSON(){const e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){const l=this.parameters;for(const c in l)l[c]!==void 0&&(e[c]=l[c]);return e}e.data={attributes:{}};const t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});const n=this.attributes;for(const l in n){const c=n[l];e.data.attributes[l]=c.toJSON(e.data)}const s={};let r=!1;for(const l in this.morphAttributes){const c=this.morphAttributes[l],h=[];for(let u=0,d=c.length;u<d;u++){const m=c[u];h.push(m.toJSON(e.data))}h.length>0&&(s[l]=h,r=!0)}r&&(e.data.morphAttributes=s,e.data.morphTargetsRelative=this.morphTargetsRelative);const a=this.groups;a.length>0&&(e.data.groups=JSON.parse(JSON.stringify(a)));const o=this.boundingSphere;return o!==null&&(e.data.boundingSphere=o.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;const t={};this.name=e.name;const n=e.index;n!==null&&this.setIndex(n.clone());const s=e.attributes;for(const c in s){const h=s[c];this.setAttribute(c,h.clone(t))}const r=e.morphAttributes;for(const c in r){const h=[],u=r[c];for(let d=0,m=u.length;d<m;d++)h.push(u[d].clone(t));this.morphAttributes[c]=h}this.morphTargetsRelative=e.morphTargetsRelative;const a=e.groups;for(let c=0,h=a.length;c<h;c++){const u=a[c];this.addGroup(u.start,u.count,u.materialIndex)}const o=e.boundingBox;o!==null&&(this.boundingBox=o.clone());const l=e.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}}class f_{constructor(e,t){this.isInterleavedBuffer=!0,this.array=e,this.stride=t,this.count=e!==void 0?e.length/t:0,this.usage=Lp,this.updateRanges=[],this.version=0,this.uuid=js()}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.array=new e.array.constructor(e.array),this.count=e.count,this.stride=e.stride,this.usage=e.usage,this}copyAt(e,t,n){e*=this.stride,n*=t.stride;for(let s=0,r=this.stride;s<r;s++)this.array[e+s]=t.array[n+s];return this}set(e,t=0){return this.array.set(e,t),this}clone(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});const t=od(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=this.array.slice(0).buffer);const n=new this.array.constructor(e.arrayBuffers[t]),s=new this.constructor(n,this.stride);return s.setUsage(this.usage),s}onUpload(e){return this.onUploadCallback=e,this}toJSON(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});const t=od(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=Array.from(new Uint32Array(this.array.slice(0).buffer)));const n={uuid:this.uuid,buffer:t,type:this.array.constructor.name,stride:this.stride};return n.usage=this.usage,n}}function od(i){return i.buffer._uuid===void 0&&(i.buffer._uuid=js()),i.byteOffset===0&&i.byteLength===i.buffer.byteLength?i.buffer._uuid:i.buffer._uuid+":"+i.byteOffset+":"+i.byteLength}const Gn=new z;class Qo{constructor(e,t,n,s=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=e,this.itemSize=t,this.offset=n,this.normalized=s,this._normalizationScale=e!==void 0?ll(e.array):void 0}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(e){this.data.needsUpdate=e}applyMatrix4(e){for(let t=0,n=this.data.count;t<n;t++)Gn.fromBufferAttribute(this,t),Gn.applyMatrix4(e),this.setXYZ(t,Gn.x,Gn.y,Gn.z);return this}applyNormalMatrix(e){for(let t=0,n=this.count;t<n;t++)Gn.fromBufferAttribute(this,t),Gn.applyNormalMatrix(e),this.setXYZ(t,Gn.x,Gn.y,Gn.z);return this}transformDirection(e){for(let t=0,n=this.count;t<n;t++)Gn.fromBufferAttribute(this,t),Gn.transformDirection(e),this.setXYZ(t,Gn.x,Gn.y,Gn.z);return this}getComponent(e,t){let n=this.array[e*this.data.stride+this.offset+t];return this.normalized&&(n=this._denormalize(n)),n}setComponent(e,t,n){return this.normalized&&(n=this._normalize(n)),this.data.array[e*this.data.stride+this.offset+t]=n,this}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset]=t,this}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+1]=t,this}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+2]=t,this}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+3]=t,this}getX(e){let t=this.data.array[e*this.data.stride+this.offset];return this.normalized&&(t=this._denormalize(t)),t}getY(e){let t=this.data.array[e*this.data.stride+this.offset+1];return this.normalized&&(t=this._denormalize(t)),t}getZ(e){let t=this.data.array[e*this.data.stride+this.offset+2];return this.normalized&&(t=this._denormalize(t)),t}getW(e){let t=this.data.array[e*this.data.stride+this.offset+3];return this.normalized&&(t=this._denormalize(t)),t}setXY(e,t,n){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n)),this.data.array[e+0]=t,this.data.array[e+1]=n,this}setXYZ(e,t,n,s){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s)),this.data.array[e+0]=t,this.data.array[e+1]=n,this.data.array[e+2]=s,this}setXYZW(e,t,n,s,r){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.data.array[e+0]=t,this.data.array[e+1]=n,this.data.array[e+2]=s,this.data.array[e+3]=r,this}clone(e){if(e===void 0){jo("InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let n=0;n<this.count;n++){const s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return new gi(new this.array.constructor(t),this.itemSize,this.normalized)}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.clone(e)),new Qo(e.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(e){if(e===void 0){jo("InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let n=0;n<this.count;n++){const s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:t,normalized:this.normalized}}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.toJSON(e)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}_denormalize(e){const t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):Np(e,this.data.array)}_normalize(e){const t=this._normalizationScale;return t!==void 0?Math.round(e*t):Ip(e,this.data.array)}}const rc=new z,p_=new z,m_=new rt;class Ai{constructor(e=new z(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,n,s){return this.normal.set(e,t,n),this.constant=s,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,n){const s=rc.subVectors(n,t).cross(p_.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(s,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){const e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,n=!0){const s=e.delta(rc),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;const a=-(e.start.dot(this.normal)+this.constant)/r;return n===!0&&(a<0||a>1)?null:t.copy(e.start).addScaledVector(s,a)}intersectsLine(e){const t=this.distanceToPoint(e.start),n=this.distanceToPoint(e.end);return t<0&&n>0||n<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){const n=t||m_.getNormalMatrix(e),s=this.coplanarPoint(rc).applyMatrix4(e),r=this.normal.applyMatrix3(n).normalize();return this.constant=-s.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}}let g_=0;class Qs extends Is{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:g_++}),this.uuid=js(),this.name="",this.type="Material",this.blending=wa,this.side=Cs,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=hp,this.blendDst=up,this.blendEquation=Lr,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new ct(0,0,0),this.blendAlpha=0,this.depthFunc=La,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=k0,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=zl,this.stencilZFail=zl,this.stencilZPass=zl,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(const t in e){const n=e[t];if(n===void 0){tt(`Material: parameter '${t}' has value of undefined.`);continue}const s=this[t];if(s===void 0){tt(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(n):s&&s.isVector2&&n&&n.isVector2||s&&s.isEuler&&n&&n.isEuler||s&&s.isVector3&&n&&n.isVector3?s.copy(n):this[t]=n}}toJSON(e){const t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});const n={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};n.uuid=this.uuid,n.type=this.type,n.blending=this.blending,n.side=this.side,n.shadowSide=this.shadowSide,n.vertexColors=this.vertexColors,n.opacity=this.opacity,n.transparent=this.transparent,n.blendSrc=this.blendSrc,n.blendDst=this.blendDst,n.blendEquation=this.blendEquation,n.blendSrcAlpha=this.blendSrcAlpha,n.blendDstAlpha=this.blendDstAlpha,n.blendEquationAlpha=this.blendEquationAlpha,n.blendColor=this.blendColor.getHex(),n.blendAlpha=this.blendAlpha,n.depthFunc=this.depthFunc,n.depthTest=this.depthTest,n.depthWrite=this.depthWrite,n.colorWrite=this.colorWrite,n.clipIntersection=this.clipIntersection,n.clipShadows=this.clipShadows,n.stencilWriteMask=this.stencilWriteMask,n.stencilFunc=this.stencilFunc,n.stencilRef=this.stencilRef,n.stencilFuncMask=this.stencilFuncMask,n.stencilFail=this.stencilFail,n.stencilZFail=this.stencilZFail,n.stencilZPass=this.stencilZPass,n.stencilWrite=this.stencilWrite,n.polygonOffset=this.polygonOffset,n.polygonOffsetFactor=this.polygonOffsetFactor,n.polygonOffsetUnits=this.polygonOffsetUnits,n.dithering=this.dithering,n.alphaTest=this.alphaTest,n.alphaHash=this.alphaHash,n.alphaToCoverage=this.alphaToCoverage,n.premultipliedAlpha=this.premultipliedAlpha,n.forceSinglePass=this.forceSinglePass,n.allowOverride=this.allowOverride,n.visible=this.visible,n.toneMapped=this.toneMapped,n.name=this.name,this.color&&this.color.isColor&&(n.color=this.color.getHex()),this.roughness!==void 0&&(n.roughness=this.roughness),this.metalness!==void 0&&(n.metalness=this.metalness),this.sheen!==void 0&&(n.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(n.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(n.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(n.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(n.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(n.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(n.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(n.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(n.shininess=this.shininess),this.clearcoat!==void 0&&(n.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(n.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(n.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(n.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(n.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(n.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(n.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,n.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(n.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(n.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(n.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(n.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(n.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(n.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(n.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(n.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(n.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(n.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(n.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(n.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(n.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(n.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(n.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(n.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(n.lightMap=this.lightMap.toJSON(e).uuid,n.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(n.aoMap=this.aoMap.toJSON(e).uuid,n.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(n.bumpMap=this.bumpMap.toJSON(e).uuid,n.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(n.normalMap=this.normalMap.toJSON(e).uuid,n.normalMapType=this.normalMapType,n.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(n.displacementMap=this.displacementMap.toJSON(e).uuid,n.displacementScale=this.displacementScale,n.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(n.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(n.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(n.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(n.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(n.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(n.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(n.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(n.combine=this.combine)),this.envMapRotation!==void 0&&(n.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(n.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(n.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(n.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(n.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(n.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(n.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(n.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(n.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(n.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(n.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(n.size=this.size),this.sizeAttenuation!==void 0&&(n.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(n.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(n.rotation=this.rotation),this.depthPacking!==void 0&&(n.depthPacking=this.depthPacking),this.linewidth!==void 0&&(n.linewidth=this.linewidth),this.linecap!==void 0&&(n.linecap=this.linecap),this.linejoin!==void 0&&(n.linejoin=this.linejoin),this.dashSize!==void 0&&(n.dashSize=this.dashSize),this.gapSize!==void 0&&(n.gapSize=this.gapSize),this.scale!==void 0&&(n.scale=this.scale),this.wireframe!==void 0&&(n.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(n.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(n.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(n.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(n.flatShading=this.flatShading),this.fog!==void 0&&(n.fog=this.fog),Object.keys(this.userData).length>0&&(n.userData=this.userData);function s(r){const a=[];for(const o in r){const l=r[o];delete l.metadata,a.push(l)}return a}if(t){const r=s(e.textures),a=s(e.images);r.length>0&&(n.textures=r),a.length>0&&(n.images=a)}return n}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new ct().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(n=>new Ai().fromJSON(n))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let n=e.normalScale;Array.isArray(n)===!1&&(n=[n,n]),this.normalScale=new Ye().fromArray(n)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new Ye().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;const t=e.clippingPlanes;let n=null;if(t!==null){const s=t.length;n=new Array(s);for(let r=0;r!==s;++r)n[r]=t[r].clone()}return this.clippingPlanes=n,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}}class zp extends Qs{constructor(e){super(),this.isSpriteMaterial=!0,this.type="SpriteMaterial",this.color=new ct(16777215),this.map=null,this.alphaMap=null,this.rotation=0,this.sizeAttenuation=!0,this.transparent=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.rotation=e.rotation,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}}let Mr;const ca=new z,br=new z,wr=new z,Er=new Ye,ha=new Ye,Hp=new Nt,ao=new z,ua=new z,oo=new z,ld=new Ye,ac=new Ye,cd=new Ye;class Gp extends Sn{constructor(e=new zp){if(super(),this.isSprite=!0,this.type="Sprite",Mr===void 0){Mr=new Gt;const t=new Float32Array([-.5,-.5,0,0,0,.5,-.5,0,1,0,.5,.5,0,1,1,-.5,.5,0,0,1]),n=new f_(t,5);Mr.setIndex([0,1,2,0,2,3]),Mr.setAttribute("position",new Qo(n,3,0,!1)),Mr.setAttribute("uv",new Qo(n,2,3,!1))}this.geometry=Mr,this.material=e,this.center=new Ye(.5,.5),this.count=1}intersectsFrustum(e){return e.intersectsSprite(this)}raycast(e,t){e.camera===null&&St('Sprite: "Raycaster.camera" needs to be set in order to raycast against sprites.'),br.setFromMatrixScale(this.matrixWorld),Hp.copy(e.camera.matrixWorld),this.modelViewMatrix.multiplyMatrices(e.camera.matrixWorldInverse,this.matrixWorld),wr.setFromMatrixPosition(this.modelViewMatrix),e.camera.isPerspectiveCamera&&this.material.sizeAttenuation===!1&&br.multiplyScalar(-wr.z);const n=this.material.rotation;let s,r;n!==0&&(r=Math.cos(n),s=Math.sin(n));const a=this.center;lo(ao.set(-.5,-.5,0),wr,a,br,s,r),lo(ua.set(.5,-.5,0),wr,a,br,s,r),lo(oo.set(.5,.5,0),wr,a,br,s,r),ld.set(0,0),ac.set(1,0),cd.set(1,1);let o=e.ray.intersectTriangle(ao,ua,oo,!1,ca);if(o===null&&(lo(ua.set(-.5,.5,0),wr,a,br,s,r),ac.set(0,1),o=e.ray.intersectTriangle(ao,oo,ua,!1,ca),o===null))return;const l=e.ray.origin.distanceTo(ca);l<e.near||l>e.far||t.push({distance:l,point:ca.clone(),uv:mi.getInterpolation(ca,ao,ua,oo,ld,ac,cd,new Ye),face:null,object:this})}copy(e,t){return super.copy(e,t),e.center!==void 0&&this.center.copy(e.center),this.material=e.material,this}toJSON(e){const t=super.toJSON(e);return t.object.center=this.center.toArray(),t}}function lo(i,e,t,n,s,r){Er.subVectors(i,t).addScalar(.5).multiply(n),s!==void 0?(ha.x=r*Er.x-s*Er.y,ha.y=s*Er.x+r*Er.y):ha.copy(Er),i.copy(e),i.x+=ha.x,i.y+=ha.y,i.applyMatrix4(Hp)}const as=new z,oc=new z,co=new z,ho=new z;class cl{constructor(e=new z,t=new z(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,as)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);const n=t.dot(this.direction);return n<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,n)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){const t=as.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(as.copy(this.origin).addScaledVector(this.direction,t),as.distanceToSquared(e))}distanceSqToSegment(e,t,n,s){oc.copy(e).add(t).multiplyScalar(.5),co.copy(t).sub(e).normalize(),ho.copy(this.origin).sub(oc);const r=e.distanceTo(t)*.5,a=-this.direction.dot(co),o=ho.dot(this.direction),l=-ho.dot(co),c=ho.lengthSq(),h=Math.abs(1-a*a);let u,d,m,_;if(h>0)if(u=a*l-o,d=a*o-l,_=r*h,u>=0)if(d>=-_)if(d<=_){const S=1/h;u*=S,d*=S,m=u*(u+a*d+2*o)+d*(a*u+d+2*l)+c}else d=r,u=Math.max(0,-(a*d+o)),m=-u*u+d*(d+2*l)+c;else d=-r,u=Math.max(0,-(a*d+o)),m=-u*u+d*(d+2*l)+c;else d<=-_?(u=Math.max(0,-(-a*r+o)),d=u>0?-r:Math.min(Math.max(-r,-l),r),m=-u*u+d*(d+2*l)+c):d<=_?(u=0,d=Math.min(Math.max(-r,-l),r),m=d*(d+2*l)+c):(u=Math.max(0,-(a*r+o)),d=u>0?r:Math.min(Math.max(-r,-l),r),m=-u*u+d*(d+2*l)+c);else d=a>0?-r:r,u=Math.max(0,-(a*d+o)),m=-u*u+d*(d+2*l)+c;return n&&n.copy(this.origin).addScaledVector(this.direction,u),s&&s.copy(oc).addScaledVector(co,d),m}intersectSphere(e,t){if(e.radius<0)return null;as.subVectors(e.center,this.origin);const n=as.dot(this.direction),s=as.dot(as)-n*n,r=e.radius*e.radius;if(s>r)return null;const a=Math.sqrt(r-s),o=n-a,l=n+a;return l<0?null:o<0?this.at(l,t):this.at(o,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){const t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;const n=-(this.origin.dot(e.normal)+e.constant)/t;return n>=0?n:null}intersectPlane(e,t){const n=this.distanceToPlane(e);return n===null?null:this.at(n,t)}intersectsPlane(e){const t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let n,s,r,a,o,l;const c=1/this.direction.x,h=1/this.direction.y,u=1/this.direction.z,d=this.origin;return c>=0?(n=(e.min.x-d.x)*c,s=(e.max.x-d.x)*c):(n=(e.max.x-d.x)*c,s=(e.min.x-d.x)*c),h>=0?(r=(e.min.y-d.y)*h,a=(e.max.y-d.y)*h):(r=(e.max.y-d.y)*h,a=(e.min.y-d.y)*h),n>a||r>s||((r>n||isNaN(n))&&(n=r),(a<s||isNaN(s))&&(s=a),u>=0?(o=(e.min.z-d.z)*u,l=(e.max.z-d.z)*u):(o=(e.max.z-d.z)*u,l=(e.min.z-d.z)*u),n>l||o>s)||((o>n||n!==n)&&(n=o),(l<s||s!==s)&&(s=l),s<0)?null:this.at(n>=0?n:s,t)}intersectsBox(e){return this.intersectBox(e,as)!==null}intersectTriangle(e,t,n,s,r){const a=this.origin,o=this.direction,l=o.x,c=o.y,h=o.z,u=e.x-a.x,d=e.y-a.y,m=e.z-a.z,_=t.x-a.x,S=t.y-a.y,p=t.z-a.z,f=n.x-a.x,x=n.y-a.y,R=n.z-a.z,y=Math.abs(l),A=Math.abs(c),w=Math.abs(h);let g,b,I,N,P,B,V,U,W,Z,H,he;if(y>=A&&y>=w?(I=l,B=u,W=_,he=f,l>=0?(g=c,b=h,N=d,P=m,V=S,U=p,Z=x,H=R):(g=h,b=c,N=m,P=d,V=p,U=S,Z=R,H=x)):A>=w?(I=c,B=d,W=S,he=x,c>=0?(g=h,b=l,N=m,P=u,V=p,U=_,Z=R,H=f):(g=l,b=h,N=u,P=m,V=_,U=p,Z=f,H=R)):(I=h,B=m,W=p,he=R,h>=0?(g=l,b=c,N=u,P=d,V=_,U=S,Z=f,H=x):(g=c,b=l,N=d,P=u,V=S,U=_,Z=x,H=f)),I===0)return null;const J=g/I,ee=b/I,se=1/I,pe=N-J*B,fe=P-ee*B,te=V-J*W,_e=U-ee*W,xe=Z-J*he,Pe=H-ee*he,Me=xe*_e-Pe*te,q=pe*Pe-fe*xe,oe=te*fe-_e*pe;if(s){if(Me<0||q<0||oe<0)return null}else if((Me<0||q<0||oe<0)&&(Me>0||q>0||oe>0))return null;const ve=Me+q+oe;if(ve===0)return null;const Xe=se*(Me*B+q*W+oe*he);return(ve>0?Xe<0:Xe>0)?null:this.at(Xe/ve,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}}class Rs extends Qs{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new ct(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ds,this.combine=dp,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}}const hd=new Nt,zs=new cl,uo=new Va,ud=new z,fo=new z,po=new z,mo=new z,lc=new z,go=new z,dd=new z,_o=new z;class on extends Sn{constructor(e=new Gt,t=new Rs){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){const t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){const s=t[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}getVertexPosition(e,t){const n=this.geometry,s=n.attributes.position,r=n.morphAttributes.position,a=n.morphTargetsRelative;t.fromBufferAttribute(s,e);const o=this.morphTargetInfluences;if(r&&o){go.set(0,0,0);for(let l=0,c=r.length;l<c;l++){const h=o[l],u=r[l];h!==0&&(lc.fromBufferAttribute(u,e),a?go.addScaledVector(lc,h):go.addScaledVector(lc.sub(t),h))}t.add(go)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){const n=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(n.boundingSphere===null&&n.computeBoundingSphere(),uo.copy(n.boundingSphere),uo.applyMatrix4(r),zs.copy(e.ray).recast(e.near),!(uo.containsPoint(zs.origin)===!1&&(zs.intersectSphere(uo,ud)===null||zs.origin.distanceToSquared(ud)>(e.far-e.near)**2))&&(hd.copy(r).invert(),zs.copy(e.ray).applyMatrix4(hd),!(n.boundingBox!==null&&zs.intersectsBox(n.boundingBox)===!1)&&this._computeIntersections(e,t,zs)))}_computeIntersections(e,t,n){let s;const r=this.geometry,a=this.material,o=r.index,l=r.attributes.position,c=r.attributes.uv,h=r.attributes.uv1,u=r.attributes.normal,d=r.groups,m=r.drawRange;if(o!==null)if(Array.isArray(a))for(let _=0,S=d.length;_<S;_++){const p=d[_],f=a[p.materialIndex],x=Math.max(p.start,m.start),R=Math.min(o.count,Math.min(p.start+p.count,m.start+m.count));for(let y=x,A=R;y<A;y+=3){const w=o.getX(y),g=o.getX(y+1),b=o.getX(y+2);s=vo(this,f,e,n,c,h,u,w,g,b),s&&(s.faceIndex=Math.floor(y/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{const _=Math.max(0,m.start),S=Math.min(o.count,m.start+m.count);for(let p=_,f=S;p<f;p+=3){const x=o.getX(p),R=o.getX(p+1),y=o.getX(p+2);s=vo(this,a,e,n,c,h,u,x,R,y),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}else if(l!==void 0)if(Array.isArray(a))for(let _=0,S=d.length;_<S;_++){const p=d[_],f=a[p.materialIndex],x=Math.max(p.start,m.start),R=Math.min(l.count,Math.min(p.start+p.count,m.start+m.count));for(let y=x,A=R;y<A;y+=3){const w=y,g=y+1,b=y+2;s=vo(this,f,e,n,c,h,u,w,g,b),s&&(s.faceIndex=Math.floor(y/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{const _=Math.max(0,m.start),S=Math.min(l.count,m.start+m.count);for(let p=_,f=S;p<f;p+=3){const x=p,R=p+1,y=p+2;s=vo(this,a,e,n,c,h,u,x,R,y),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}}}function __(i,e,t,n,s,r,a,o){let l;if(e.side===Kn?l=n.intersectTriangle(a,r,s,!0,o):l=n.intersectTriangle(s,r,a,e.side===Cs,o),l===null)return null;_o.copy(o),_o.applyMatrix4(i.matrixWorld);const c=t.ray.origin.distanceTo(_o);return c<t.near||c>t.far?null:{distance:c,point:_o.clone(),object:i}}function vo(i,e,t,n,s,r,a,o,l,c){i.getVertexPosition(o,fo),i.getVertexPosition(l,po),i.getVertexPosition(c,mo);const h=__(i,e,t,n,fo,po,mo,dd);if(h){const u=new z;mi.getBarycoord(dd,fo,po,mo,u),s&&(h.uv=mi.getInterpolatedAttribute(s,o,l,c,u,new Ye)),r&&(h.uv1=mi.getInterpolatedAttribute(r,o,l,c,u,new Ye)),a&&(h.normal=mi.getInterpolatedAttribute(a,o,l,c,u,new z),h.normal.dot(n.direction)>0&&h.normal.multiplyScalar(-1));const d={a:o,b:l,c,normal:new z,materialIndex:0};mi.getNormal(fo,po,mo,d.normal),h.face=d,h.barycoord=u}return h}class v_ extends Un{constructor(e=null,t=1,n=1,s,r,a,o,l,c=Ln,h=Ln,u,d){super(null,a,o,l,c,h,s,r,u,d),this.isDataTexture=!0,this.image={data:e,width:t,height:n},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}}const Hs=new Va,x_=new Ye(.5,.5),xo=new z;class Ua{constructor(e=new Ai,t=new Ai,n=new Ai,s=new Ai,r=new Ai,a=new Ai){this.planes=[e,t,n,s,r,a]}set(e,t,n,s,r,a){const o=this.planes;return o[0].copy(e),o[1].copy(t),o[2].copy(n),o[3].copy(s),o[4].copy(r),o[5].copy(a),this}copy(e){const t=this.planes;for(let n=0;n<6;n++)t[n].copy(e.planes[n]);return this}setFromProjectionMatrix(e,t=Ci,n=!1){const s=this.planes,r=e.elements,a=r[0],o=r[1],l=r[2],c=r[3],h=r[4],u=r[5],d=r[6],m=r[7],_=r[8],S=r[9],p=r[10],f=r[11],x=r[12],R=r[13],y=r[14],A=r[15];if(s[0].setComponents(c-a,m-h,f-_,A-x).normalize(),s[1].setComponents(c+a,m+h,f+_,A+x).normalize(),s[2].setComponents(c+o,m+u,f+S,A+R).normalize(),s[3].setComponents(c-o,m-u,f-S,A-R).normalize(),n)s[4].setComponents(l,d,p,y).normalize(),s[5].setComponents(c-l,m-d,f-p,A-y).normalize();else if(s[4].setComponents(c-l,m-d,f-p,A-y).normalize(),t===Ci)s[5].setComponents(c+l,m+d,f+p,A+y).normalize();else if(t===Ia)s[5].setComponents(l,d,p,y).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Hs.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{const t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Hs.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Hs)}intersectsSprite(e){Hs.center.set(0,0,0);const t=x_.distanceTo(e.center);return Hs.radius=.7071067811865476+t,Hs.applyMatrix4(e.matrixWorld),this.intersectsSphere(Hs)}intersectsSphere(e){const t=this.planes,n=e.center,s=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(n)<s)return!1;return!0}intersectsBox(e){const t=this.planes;for(let n=0;n<6;n++){const s=t[n];if(xo.x=s.normal.x>0?e.max.x:e.min.x,xo.y=s.normal.y>0?e.max.y:e.min.y,xo.z=s.normal.z>0?e.max.z:e.min.z,s.distanceToPoint(xo)<0)return!1}return!0}containsPoint(e){const t=this.planes;for(let n=0;n<6;n++)if(t[n].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}}const fd=new Nt;class tu{constructor(){this.coordinateSystem=Ci,this._frustums=[],this._count=0}setFromArrayCamera(e){const t=e.cameras,n=this._frustums;for(let s=0;s<t.length;s++){const r=t[s];fd.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),n[s]===void 0&&(n[s]=new Ua),n[s].setFromProjectionMatrix(fd,r.coordinateSystem,r.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsObject(e))return!0;return!1}intersectsSprite(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsSprite(e))return!0;return!1}intersectsSphere(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsSphere(e))return!0;return!1}intersectsBox(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsBox(e))return!0;return!1}containsPoint(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;const t=this._frustums,n=e._frustums;for(let s=0;s<e._count;s++)t[s]===void 0&&(t[s]=new Ua),t[s].copy(n[s]);return this._count=e._count,this}clone(){return new tu().copy(this)}}class _i extends Qs{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new ct(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}}const el=new z,tl=new z,pd=new Nt,da=new cl,So=new Va,cc=new z,md=new z;class Zi extends Sn{constructor(e=new Gt,t=new _i){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,n=[0];for(let s=1,r=t.count;s<r;s++)el.fromBufferAttribute(t,s-1),tl.fromBufferAttribute(t,s),n[s]=n[s-1],n[s]+=el.distanceTo(tl);e.setAttribute("lineDistance",new ln(n,1))}else tt("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){const n=this.geometry,s=this.matrixWorld,r=e.params.Line.threshold,a=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),So.copy(n.boundingSphere),So.applyMatrix4(s),So.radius+=r,e.ray.intersectsSphere(So)===!1)return;pd.copy(s).invert(),da.copy(e.ray).applyMatrix4(pd);const o=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=o*o,c=this.isLineSegments?2:1,h=n.index,d=n.attributes.position;if(h!==null){const m=Math.max(0,a.start),_=Math.min(h.count,a.start+a.count);for(let S=m,p=_-1;S<p;S+=c){const f=h.getX(S),x=h.getX(S+1),R=yo(this,e,da,l,f,x,S);R&&t.push(R)}if(this.isLineLoop){const S=h.getX(_-1),p=h.getX(m),f=yo(this,e,da,l,S,p,_-1);f&&t.push(f)}}else{const m=Math.max(0,a.start),_=Math.min(d.count,a.start+a.count);for(let S=m,p=_-1;S<p;S+=c){const f=yo(this,e,da,l,S,S+1,S);f&&t.push(f)}if(this.isLineLoop){const S=yo(this,e,da,l,_-1,m,_-1);S&&t.push(S)}}}updateMorphTargets(){const t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){const s=t[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}}function yo(i,e,t,n,s,r,a){const o=i.geometry.attributes.position;if(el.fromBufferAttribute(o,s),tl.fromBufferAttribute(o,r),t.distanceSqToSegment(el,tl,cc,md)>n)return;cc.applyMatrix4(i.matrixWorld);const c=e.ray.origin.distanceTo(cc);if(!(c<e.near||c>e.far))return{distance:c,point:md.clone().applyMatrix4(i.matrixWorld),index:a,face:null,faceIndex:null,barycoord:null,object:i}}const gd=new z,_d=new z;class hl extends Zi{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,n=[];for(let s=0,r=t.count;s<r;s+=2)gd.fromBufferAttribute(t,s),_d.fromBufferAttribute(t,s+1),n[s]=s===0?0:n[s-1],n[s+1]=n[s]+gd.distanceTo(_d);e.setAttribute("lineDistance",new ln(n,1))}else tt("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}}class S_ extends Zi{constructor(e,t){super(e,t),this.isLineLoop=!0,this.type="LineLoop"}}class Vp extends Un{constructor(e=[],t=Br,n,s,r,a,o,l,c,h){super(e,t,n,s,r,a,o,l,c,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}}class y_ extends Un{constructor(e,t,n,s,r,a,o,l,c){super(e,t,n,s,r,a,o,l,c),this.isCanvasTexture=!0,this.needsUpdate=!0}}class Hr extends Un{constructor(e,t,n=Yi,s,r,a,o=Ln,l=Ln,c,h=Ps,u=1){if(h!==Ps&&h!==As)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");const d={width:e,height:t,depth:u};super(d,s,r,a,o,l,h,n,c),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new Qh(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){const t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}}class Wp extends Hr{constructor(e,t=Yi,n=Br,s,r,a=Ln,o=Ln,l,c=Ps){const h={width:e,height:e,depth:1},u=[h,h,h,h,h,h];super(e,e,t,n,s,r,a,o,l,c),this.image=u,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}}class Xp extends Un{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}}class Wa extends Gt{constructor(e=1,t=1,n=1,s=1,r=1,a=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:n,widthSegments:s,heightSegments:r,depthSegments:a};const o=this;s=Math.floor(s),r=Math.floor(r),a=Math.floor(a);const l=[],c=[],h=[],u=[];let d=0,m=0;_("z","y","x",-1,-1,n,t,e,a,r,0),_("z","y","x",1,-1,n,t,-e,a,r,1),_("x","z","y",1,1,e,n,t,s,a,2),_("x","z","y",1,-1,e,n,-t,s,a,3),_("x","y","z",1,-1,e,t,n,s,r,4),_("x","y","z",-1,-1,e,t,-n,s,r,5),this.setIndex(l),this.setAttribute("position",new ln(c,3)),this.setAttribute("normal",new ln(h,3)),this.setAttribute("uv",new ln(u,2));function _(S,p,f,x,R,y,A,w,g,b,I){const N=y/g,P=A/b,B=y/2,V=A/2,U=w/2,W=g+1,Z=b+1;let H=0,he=0;const J=new z;for(let ee=0;ee<Z;ee++){const se=ee*P-V;for(let pe=0;pe<W;pe++){const fe=pe*N-B;J[S]=fe*x,J[p]=se*R,J[f]=U,c.push(J.x,J.y,J.z),J[S]=0,J[p]=0,J[f]=w>0?1:-1,h.push(J.x,J.y,J.z),u.push(pe/g),u.push(1-ee/b),H+=1}}for(let ee=0;ee<b;ee++)for(let se=0;se<g;se++){const pe=d+se+W*ee,fe=d+se+W*(ee+1),te=d+(se+1)+W*(ee+1),_e=d+(se+1)+W*ee;l.push(pe,fe,_e),l.push(fe,te,_e),he+=6}o.addGroup(m,he,I),m+=he,d+=H}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Wa(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}}class Xa extends Gt{constructor(e=1,t=1,n=1,s=32,r=1,a=!1,o=0,l=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:e,radiusBottom:t,height:n,radialSegments:s,heightSegments:r,openEnded:a,thetaStart:o,thetaLength:l};const c=this;s=Math.floor(s),r=Math.floor(r);const h=[],u=[],d=[],m=[];let _=0;const S=[],p=n/2;let f=0;x(),a===!1&&(e>0&&R(!0),t>0&&R(!1)),this.setIndex(h),this.setAttribute("position",new ln(u,3)),this.setAttribute("normal",new ln(d,3)),this.setAttribute("uv",new ln(m,2));function x(){const y=new z,A=new z;let w=0;const g=(t-e)/n;for(let b=0;b<=r;b++){const I=[],N=b/r,P=N*(t-e)+e;for(let B=0;B<=s;B++){const V=B/s,U=V*l+o,W=Math.sin(U),Z=Math.cos(U);A.x=P*W,A.y=-N*n+p,A.z=P*Z,u.push(A.x,A.y,A.z),y.set(W,g,Z).normalize(),d.push(y.x,y.y,y.z),m.push(V,1-N),I.push(_++)}S.push(I)}for(let b=0;b<s;b++)for(let I=0;I<r;I++){const N=S[I][b],P=S[I+1][b],B=S[I+1][b+1],V=S[I][b+1];(e>0||I!==0)&&(h.push(N,P,V),w+=3),(t>0||I!==r-1)&&(h.push(P,B,V),w+=3)}c.addGroup(f,w,0),f+=w}function R(y){const A=_,w=new Ye,g=new z;let b=0;const I=y===!0?e:t,N=y===!0?1:-1;for(let B=1;B<=s;B++)u.push(0,p*N,0),d.push(0,N,0),m.push(.5,.5),_++;const P=_;for(let B=0;B<=s;B++){const U=B/s*l+o,W=Math.cos(U),Z=Math.sin(U);g.x=I*Z,g.y=p*N,g.z=I*W,u.push(g.x,g.y,g.z),d.push(0,N,0),w.x=W*.5+.5,w.y=Z*.5*N+.5,m.push(w.x,w.y),_++}for(let B=0;B<s;B++){const V=A+B,U=P+B;y===!0?h.push(U,U+1,V):h.push(U+1,U,V),b+=3}c.addGroup(f,b,y===!0?1:2),f+=b}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Xa(e.radiusTop,e.radiusBottom,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}}class nu extends Xa{constructor(e=1,t=1,n=32,s=1,r=!1,a=0,o=Math.PI*2){super(0,e,t,n,s,r,a,o),this.type="ConeGeometry",this.parameters={radius:e,height:t,radialSegments:n,heightSegments:s,openEnded:r,thetaStart:a,thetaLength:o}}static fromJSON(e){return new nu(e.radius,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}}class ul extends Gt{constructor(e=1,t=1,n=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:n,heightSegments:s};const r=e/2,a=t/2,o=Math.floor(n),l=Math.floor(s),c=o+1,h=l+1,u=e/o,d=t/l,m=[],_=[],S=[],p=[];for(let f=0;f<h;f++){const x=f*d-a;for(let R=0;R<c;R++){const y=R*u-r;_.push(y,-x,0),S.push(0,0,1),p.push(R/o),p.push(1-f/l)}}for(let f=0;f<l;f++)for(let x=0;x<o;x++){const R=x+c*f,y=x+c*(f+1),A=x+1+c*(f+1),w=x+1+c*f;m.push(R,y,w),m.push(y,A,w)}this.setIndex(m),this.setAttribute("position",new ln(_,3)),this.setAttribute("normal",new ln(S,3)),this.setAttribute("uv",new ln(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new ul(e.width,e.height,e.widthSegments,e.heightSegments)}}class ls extends Gt{constructor(e=1,t=32,n=16,s=0,r=Math.PI*2,a=0,o=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:e,widthSegments:t,heightSegments:n,phiStart:s,phiLength:r,thetaStart:a,thetaLength:o},t=Math.max(3,Math.floor(t)),n=Math.max(2,Math.floor(n));const l=Math.min(a+o,Math.PI);let c=0;const h=[],u=new z,d=new z,m=[],_=[],S=[],p=[];for(let f=0;f<=n;f++){const x=[],R=f/n,y=a+R*o,A=e*Math.cos(y),w=Math.sqrt(e*e-A*A);let g=0;f===0&&a===0?g=.5/t:f===n&&l===Math.PI&&(g=-.5/t);for(let b=0;b<=t;b++){const I=b/t,N=s+I*r;u.x=-w*Math.cos(N),u.y=A,u.z=w*Math.sin(N),_.push(u.x,u.y,u.z),d.copy(u).normalize(),S.push(d.x,d.y,d.z),p.push(I+g,1-R),x.push(c++)}h.push(x)}for(let f=0;f<n;f++)for(let x=0;x<t;x++){const R=h[f][x+1],y=h[f][x],A=h[f+1][x],w=h[f+1][x+1];(f!==0||a>0)&&m.push(R,y,w),(f!==n-1||l<Math.PI)&&m.push(y,A,w)}this.setIndex(m),this.setAttribute("position",new ln(_,3)),this.setAttribute("normal",new ln(S,3)),this.setAttribute("uv",new ln(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new ls(e.radius,e.widthSegments,e.heightSegments,e.phiStart,e.phiLength,e.thetaStart,e.thetaLength)}}function Gr(i){const e={};for(const t in i){e[t]={};for(const n in i[t]){const s=i[t][n];if(vd(s))s.isRenderTargetTexture?(tt("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][n]=null):e[t][n]=s.clone();else if(Array.isArray(s))if(vd(s[0])){const r=[];for(let a=0,o=s.length;a<o;a++)r[a]=s[a].clone();e[t][n]=r}else e[t][n]=s.slice();else e[t][n]=s}}return e}function Vn(i){const e={};for(let t=0;t<i.length;t++){const n=Gr(i[t]);for(const s in n)e[s]=n[s]}return e}function vd(i){return i&&(i.isColor||i.isMatrix3||i.isMatrix4||i.isVector2||i.isVector3||i.isVector4||i.isTexture||i.isQuaternion)}function M_(i){const e=[];for(let t=0;t<i.length;t++)e.push(i[t].clone());return e}function $p(i){const e=i.getRenderTarget();return e===null?i.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:vt.workingColorSpace}const b_={clone:Gr,merge:Vn};var w_=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,E_=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`;class Zs extends Qs{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=w_,this.fragmentShader=E_,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=Gr(e.uniforms),this.uniformsGroups=M_(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){const t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(const s in this.uniforms){const a=this.uniforms[s].value;a&&a.isTexture?t.uniforms[s]={type:"t",value:a.toJSON(e).uuid}:a&&a.isColor?t.uniforms[s]={type:"c",value:a.getHex()}:a&&a.isVector2?t.uniforms[s]={type:"v2",value:a.toArray()}:a&&a.isVector3?t.uniforms[s]={type:"v3",value:a.toArray()}:a&&a.isVector4?t.uniforms[s]={type:"v4",value:a.toArray()}:a&&a.isMatrix3?t.uniforms[s]={type:"m3",value:a.toArray()}:a&&a.isMatrix4?t.uniforms[s]={type:"m4",value:a.toArray()}:t.uniforms[s]={value:a}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;const n={};for(const s in this.extensions)this.extensions[s]===!0&&(n[s]=!0);return Object.keys(n).length>0&&(t.extensions=n),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(const n in e.uniforms){const s=e.uniforms[n];switch(this.uniforms[n]={},s.type){case"t":this.uniforms[n].value=t[s.value]||null;break;case"c":this.uniforms[n].value=new ct().setHex(s.value);break;case"v2":this.uniforms[n].value=new Ye().fromArray(s.value);break;case"v3":this.uniforms[n].value=new z().fromArray(s.value);break;case"v4":this.uniforms[n].value=new an().fromArray(s.value);break;case"m3":this.uniforms[n].value=new rt().fromArray(s.value);break;case"m4":this.uniforms[n].value=new Nt().fromArray(s.value);break;default:this.uniforms[n].value=s.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(const n in e.extensions)this.extensions[n]=e.extensions[n];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}}class T_ extends Zs{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}}class Or extends Qs{constructor(e){super(),this.isMeshStandardMaterial=!0,this.type="MeshStandardMaterial",this.defines={STANDARD:""},this.color=new ct(16777215),this.roughness=1,this.metalness=0,this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new ct(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=xh,this.normalScale=new Ye(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.roughnessMap=null,this.metalnessMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ds,this.envMapIntensity=1,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.defines={STANDARD:""},this.color.copy(e.color),this.roughness=e.roughness,this.metalness=e.metalness,this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.emissive.copy(e.emissive),this.emissiveMap=e.emissiveMap,this.emissiveIntensity=e.emissiveIntensity,this.bumpMap=e.bumpMap,this.bumpScale=e.bumpScale,this.normalMap=e.normalMap,this.normalMapType=e.normalMapType,this.normalScale.copy(e.normalScale),this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.roughnessMap=e.roughnessMap,this.metalnessMap=e.metalnessMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.envMapIntensity=e.envMapIntensity,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.flatShading=e.flatShading,this.fog=e.fog,this}}class A_ extends Qs{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=F0,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}}class R_ extends Qs{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}}class qp extends _i{constructor(e){super(),this.isLineDashedMaterial=!0,this.type="LineDashedMaterial",this.scale=1,this.dashSize=3,this.gapSize=1,this.setValues(e)}copy(e){return super.copy(e),this.scale=e.scale,this.dashSize=e.dashSize,this.gapSize=e.gapSize,this}}class Yp extends Sn{static registerNode(e){this.prototype._lightNode=e}constructor(e,t=1){super(),this.isLight=!0,this.type="Light",this.color=new ct(e),this.intensity=t}copy(e,t){return super.copy(e,t),this.color.copy(e.color),this.intensity=e.intensity,this}toJSON(e){const t=super.toJSON(e);return t.object.color=this.color.getHex(),t.object.intensity=this.intensity,t}}const hc=new Nt,xd=new z,Sd=new z;class C_{constructor(e){this.camera=e,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new Ye(512,512),this.mapType=ii,this.map=null,this.mapPass=null,this.matrix=new Nt,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new Ua,this._frameExtents=new Ye(1,1),this._viewportCount=1,this._viewports=[new an(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(e){const t=this.camera;xd.setFromMatrixPosition(e.matrixWorld),t.position.copy(xd),Sd.setFromMatrixPosition(e.target.matrixWorld),t.lookAt(Sd),t.updateMatrixWorld(),this._updateMatrix(t,this.matrix,this._frustum)}_updateMatrix(e,t,n,s){hc.multiplyMatrices(e.projectionMatrix,e.matrixWorldInverse),n.setFromProjectionMatrix(hc,e.coordinateSystem,e.reversedDepth);const r=this._frameExtents,a=s?s.z/r.x:1,o=s?s.w/r.y:1,l=s?s.x/r.x:0,c=s?s.y/r.y:0;e.coordinateSystem===Ia||e.reversedDepth?t.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,1,0,0,0,0,1):t.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,.5,.5,0,0,0,1),t.multiply(hc)}getViewport(e){return this._viewports[e]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(e){return this.camera=e.camera.clone(),this.intensity=e.intensity,this.bias=e.bias,this.radius=e.radius,this.autoUpdate=e.autoUpdate,this.needsUpdate=e.needsUpdate,this.normalBias=e.normalBias,this.blurSamples=e.blurSamples,this.mapSize.copy(e.mapSize),this.mapType=e.mapType,this.biasNode=e.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){const e={};return e.intensity=this.intensity,e.bias=this.bias,e.normalBias=this.normalBias,e.radius=this.radius,e.blurSamples=this.blurSamples,e.mapSize=this.mapSize.toArray(),e.mapType=this.mapType,e.camera=this.camera.toJSON(!1).object,delete e.camera.matrix,e}}const Mo=new z,bo=new Ls,Oi=new z;class Kp extends Sn{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new Nt,this.projectionMatrix=new Nt,this.projectionMatrixInverse=new Nt,this.coordinateSystem=Ci,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(Mo,bo,Oi),Oi.x===1&&Oi.y===1&&Oi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(Mo,bo,Oi.set(1,1,1)).invert()}updateWorldMatrix(e,t,n=!1){super.updateWorldMatrix(e,t,n),this.matrixWorld.decompose(Mo,bo,Oi),Oi.x===1&&Oi.y===1&&Oi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(Mo,bo,Oi.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}}const bs=new z,yd=new Ye,Md=new Ye;class qn extends Kp{constructor(e=50,t=1,n=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=n,this.far=s,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){const t=.5*this.getFilmHeight()/e;this.fov=Sh*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){const e=Math.tan(Ea*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return Sh*2*Math.atan(Math.tan(Ea*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,n){bs.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(bs.x,bs.y).multiplyScalar(-e/bs.z),bs.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),n.set(bs.x,bs.y).multiplyScalar(-e/bs.z)}getViewSize(e,t){return this.getViewBounds(e,yd,Md),t.subVectors(Md,yd)}setViewOffset(e,t,n,s,r,a){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=this.near;let t=e*Math.tan(Ea*.5*this.fov)/this.zoom,n=2*t,s=this.aspect*n,r=-.5*s;const a=this.view;if(this.view!==null&&this.view.enabled){const l=a.fullWidth,c=a.fullHeight;r+=a.offsetX*s/l,t-=a.offsetY*n/c,s*=a.width/l,n*=a.height/c}const o=this.filmOffset;o!==0&&(r+=e*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,t,t-n,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}}class Zp extends Kp{constructor(e=-1,t=1,n=1,s=-1,r=.1,a=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=n,this.bottom=s,this.near=r,this.far=a,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,n,s,r,a){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),n=(this.right+this.left)/2,s=(this.top+this.bottom)/2;let r=n-e,a=n+e,o=s+t,l=s-t;if(this.view!==null&&this.view.enabled){const c=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=c*this.view.offsetX,a=r+c*this.view.width,o-=h*this.view.offsetY,l=o-h*this.view.height}this.projectionMatrix.makeOrthographic(r,a,o,l,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}}class P_ extends C_{constructor(){super(new Zp(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}}class L_ extends Yp{constructor(e,t){super(e,t),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(Sn.DEFAULT_UP),this.updateMatrix(),this.target=new Sn,this.shadow=new P_}dispose(){super.dispose(),this.shadow.dispose()}copy(e){return super.copy(e),this.target=e.target.clone(),this.shadow=e.shadow.clone(),this}toJSON(e){const t=super.toJSON(e);return t.object.shadow=this.shadow.toJSON(),t.object.target=this.target.uuid,t}}class D_ extends Yp{constructor(e,t){super(e,t),this.isAmbientLight=!0,this.type="AmbientLight"}}const bd=new Nt,wd=new Nt,Gs=new Nt;class Jp{constructor(){this.type="StereoCamera",this.aspect=1,this.eyeSep=.064,this.cameraL=new qn,this.cameraL.layers.enable(1),this.cameraL.matrixAutoUpdate=!1,this.cameraR=new qn,this.cameraR.layers.enable(2),this.cameraR.matrixAutoUpdate=!1,this._cache={focus:null,fov:null,aspect:null,near:null,far:null,zoom:null,eyeSep:null}}update(e){const t=this._cache;if(t.focus!==e.focus||t.fov!==e.fov||t.aspect!==e.aspect*this.aspect||t.near!==e.near||t.far!==e.far||t.zoom!==e.zoom||t.eyeSep!==this.eyeSep){t.focus=e.focus,t.fov=e.fov,t.aspect=e.aspect*this.aspect,t.near=e.near,t.far=e.far,t.zoom=e.zoom,t.eyeSep=this.eyeSep,Gs.copy(e.projectionMatrix);const s=t.eyeSep/2,r=s*t.near/t.focus,a=t.near*Math.tan(Ea*t.fov*.5)/t.zoom;let o,l;wd.elements[12]=-s,bd.elements[12]=s,o=-a*t.aspect+r,l=a*t.aspect+r,Gs.elements[0]=2*t.near/(l-o),Gs.elements[8]=(l+o)/(l-o),this.cameraL.projectionMatrix.copy(Gs),o=-a*t.aspect-r,l=a*t.aspect-r,Gs.elements[0]=2*t.near/(l-o),Gs.elements[8]=(l+o)/(l-o),this.cameraR.projectionMatrix.copy(Gs)}this.cameraL.matrix.copy(e.matrixWorld).multiply(wd),this.cameraL.matrixWorldNeedsUpdate=!0,this.cameraR.matrix.copy(e.matrixWorld).multiply(bd),this.cameraR.matrixWorldNeedsUpdate=!0}}const Tr=-90,Ar=1;class yh extends Sn{constructor(e,t,n){super(),this.type="CubeCamera",this.renderTarget=n,this.coordinateSystem=null,this.activeMipmapLevel=0;const s=new qn(Tr,Ar,e,t);s.layers=this.layers,this.add(s);const r=new qn(Tr,Ar,e,t);r.layers=this.layers,this.add(r);const a=new qn(Tr,Ar,e,t);a.layers=this.layers,this.add(a);const o=new qn(Tr,Ar,e,t);o.layers=this.layers,this.add(o);const l=new qn(Tr,Ar,e,t);l.layers=this.layers,this.add(l);const c=new qn(Tr,Ar,e,t);c.layers=this.layers,this.add(c)}updateCoordinateSystem(){const e=this.coordinateSystem,t=this.children.concat(),[n,s,r,a,o,l]=t;for(const c of t)this.remove(c);if(e===Ci)n.up.set(0,1,0),n.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),a.up.set(0,0,1),a.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(e===Ia)n.up.set(0,-1,0),n.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),a.up.set(0,0,-1),a.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(const c of t)this.add(c),c.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();const{renderTarget:n,activeMipmapLevel:s}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());const[r,a,o,l,c,h]=this.children,u=e.getRenderTarget(),d=e.getActiveCubeFace(),m=e.getActiveMipmapLevel(),_=e.xr.enabled;e.xr.enabled=!1;const S=n.texture.mipmapsAutoUpdate;n.texture.mipmapsAutoUpdate=!1;let p=!1;e.isWebGLRenderer===!0?p=e.state.buffers.depth.getReversed():p=e.reversedDepthBuffer,e.setRenderTarget(n,0,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,r),e.setRenderTarget(n,1,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(n,2,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(n,3,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),e.setRenderTarget(n,4,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),n.texture.mipmapsAutoUpdate=S,e.setRenderTarget(n,5,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,h),e.setRenderTarget(u,d,m),e.xr.enabled=_,n.texture.needsPMREMUpdate=!0}}class N_ extends qn{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}}const Ed=new Nt;class jp{constructor(e,t,n=0,s=1/0){this.ray=new cl(e,t),this.near=n,this.far=s,this.camera=null,this.layers=new eu,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(e,t){this.ray.set(e,t)}setFromCamera(e,t){t.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(e.x,e.y,.5).unproject(t).sub(this.ray.origin).normalize(),this.camera=t):t.isOrthographicCamera?(this.ray.origin.set(e.x,e.y,t.projectionMatrix.elements[14]).unproject(t),this.ray.direction.set(0,0,-1).transformDirection(t.matrixWorld),this.camera=t):St("Raycaster: Unsupported camera type: "+t.type)}setFromXRController(e){return Ed.identity().extractRotation(e.matrixWorld),this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4(Ed),this}intersectObject(e,t=!0,n=[]){return Mh(e,this,n,t),n.sort(Td),n}intersectObjects(e,t=!0,n=[]){for(let s=0,r=e.length;s<r;s++)Mh(e[s],this,n,t);return n.sort(Td),n}}function Td(i,e){return i.distance-e.distance}function Mh(i,e,t,n){let s=!0;if(i.layers.test(e.layers)&&i.raycast(e,t)===!1&&(s=!1),s===!0&&n===!0){const r=i.children;for(let a=0,o=r.length;a<o;a++)Mh(r[a],e,t,!0)}}class bh{constructor(e=1,t=0,n=0){this.radius=e,this.phi=t,this.theta=n}set(e,t,n){return this.radius=e,this.phi=t,this.theta=n,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=mt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,n){return this.radius=Math.sqrt(e*e+t*t+n*n),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,n),this.phi=Math.acos(mt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}}const Ad=new z;let wo,uc;class I_ extends Sn{constructor(e=new z(0,0,1),t=new z(0,0,0),n=1,s=16776960,r=n*.2,a=r*.2){super(),this.type="ArrowHelper",wo===void 0&&(wo=new Gt,wo.setAttribute("position",new ln([0,0,0,0,1,0],3)),uc=new nu(.5,1,5,1),uc.translate(0,-.5,0)),this.position.copy(t),this.line=new Zi(wo,new _i({color:s,toneMapped:!1})),this.line.matrixAutoUpdate=!1,this.add(this.line),this.cone=new on(uc,new Rs({color:s,toneMapped:!1})),this.cone.matrixAutoUpdate=!1,this.add(this.cone),this.setDirection(e),this.setLength(n,r,a)}setDirection(e){if(e.y>.99999)this.quaternion.set(0,0,0,1);else if(e.y<-.99999)this.quaternion.set(1,0,0,0);else{Ad.set(e.z,0,-e.x).normalize();const t=Math.acos(e.y);this.quaternion.setFromAxisAngle(Ad,t)}}setLength(e,t=e*.2,n=t*.2){this.line.scale.set(1,Math.max(1e-4,e-t),1),this.line.updateMatrix(),this.cone.scale.set(n,t,n),this.cone.position.y=e,this.cone.updateMatrix()}setColor(e){this.line.material.color.set(e),this.cone.material.color.set(e)}copy(e){return super.copy(e,!1),this.line.copy(e.line),this.cone.copy(e.cone),this}dispose(){super.dispose(),this.line.geometry.dispose(),this.line.material.dispose(),this.cone.geometry.dispose(),this.cone.material.dispose()}}class Qp extends hl{constructor(e=1){const t=[0,0,0,e,0,0,0,0,0,0,e,0,0,0,0,0,0,e],n=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new Gt;s.setAttribute("position",new ln(t,3)),s.setAttribute("color",new ln(n,3));const r=new _i({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(e,t,n){const s=new ct,r=this.geometry.attributes.color.array;return s.set(e),s.toArray(r,0),s.toArray(r,3),s.set(t),s.toArray(r,6),s.toArray(r,9),s.set(n),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}}let U_=class extends Is{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function Rd(i,e,t,n){const s=F_(n);switch(t){case Ep:return i*e;case Ap:return i*e/s.components*s.byteLength;case Zh:return i*e/s.components*s.byteLength;case Ks:return i*e*2/s.components*s.byteLength;case Jh:return i*e*2/s.components*s.byteLength;case Tp:return i*e*3/s.components*s.byteLength;case Wi:return i*e*4/s.components*s.byteLength;case jh:return i*e*4/s.components*s.byteLength;case Bo:case zo:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case Ho:case Go:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case Wc:case $c:return Math.max(i,16)*Math.max(e,8)/4;case Vc:case Xc:return Math.max(i,8)*Math.max(e,8)/2;case qc:case Yc:case Zc:case Jc:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case Kc:case qo:case jc:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case Qc:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case eh:return Math.floor((i+4)/5)*Math.floor((e+3)/4)*16;case th:return Math.floor((i+4)/5)*Math.floor((e+4)/5)*16;case nh:return Math.floor((i+5)/6)*Math.floor((e+4)/5)*16;case ih:return Math.floor((i+5)/6)*Math.floor((e+5)/6)*16;case sh:return Math.floor((i+7)/8)*Math.floor((e+4)/5)*16;case rh:return Math.floor((i+7)/8)*Math.floor((e+5)/6)*16;case ah:return Math.floor((i+7)/8)*Math.floor((e+7)/8)*16;case oh:return Math.floor((i+9)/10)*Math.floor((e+4)/5)*16;case lh:return Math.floor((i+9)/10)*Math.floor((e+5)/6)*16;case ch:return Math.floor((i+9)/10)*Math.floor((e+7)/8)*16;case hh:return Math.floor((i+9)/10)*Math.floor((e+9)/10)*16;case uh:return Math.floor((i+11)/12)*Math.floor((e+9)/10)*16;case dh:return Math.floor((i+11)/12)*Math.floor((e+11)/12)*16;case fh:case ph:case mh:return Math.ceil(i/4)*Math.ceil(e/4)*16;case gh:case _h:return Math.ceil(i/4)*Math.ceil(e/4)*8;case Yo:case vh:return Math.ceil(i/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function F_(i){switch(i){case ii:case yp:return{byteLength:1,components:1};case Na:case Mp:case Ki:return{byteLength:2,components:1};case Yh:case Kh:return{byteLength:2,components:4};case Yi:case qh:case Vi:return{byteLength:4,components:1};case bp:case wp:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${i}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:$h}}));typeof window<"u"&&(window.__THREE__?tt("WARNING: Multiple instances of Three.js being imported."):window.__THREE__=$h);function em(){let i=null,e=!1,t=null,n=null;function s(r,a){n=i.requestAnimationFrame(s),t(r,a)}return{start:function(){e!==!0&&t!==null&&i!==null&&(n=i.requestAnimationFrame(s),e=!0)},stop:function(){i!==null&&i.cancelAnimationFrame(n),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){i=r}}}function O_(i){const e=new WeakMap;function t(o,l){const c=o.array,h=o.usage,u=c.byteLength,d=i.createBuffer();i.bindBuffer(l,d),i.bufferData(l,c,h),o.onUploadCallback();let m;if(c instanceof Float32Array)m=i.FLOAT;else if(typeof Float16Array<"u"&&c instanceof Float16Array)m=i.HALF_FLOAT;else if(c instanceof Uint16Array)o.isFloat16BufferAttribute?m=i.HALF_FLOAT:m=i.UNSIGNED_SHORT;else if(c instanceof Int16Array)m=i.SHORT;else if(c instanceof Uint32Array)m=i.UNSIGNED_INT;else if(c instanceof Int32Array)m=i.INT;else if(c instanceof Int8Array)m=i.BYTE;else if(c instanceof Uint8Array)m=i.UNSIGNED_BYTE;else if(c instanceof Uint8ClampedArray)m=i.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+c);return{buffer:d,type:m,bytesPerElement:c.BYTES_PER_ELEMENT,version:o.version,size:u}}function n(o,l,c){const h=l.array,u=l.updateRanges;if(i.bindBuffer(c,o),u.length===0)i.bufferSubData(c,0,h);else{u.sort((m,_)=>m.start-_.start);let d=0;for(let m=1;m<u.length;m++){const _=u[d],S=u[m];S.start<=_.start+_.count+1?_.count=Math.max(_.count,S.start+S.count-_.start):(++d,u[d]=S)}u.length=d+1;for(let m=0,_=u.length;m<_;m++){const S=u[m];i.bufferSubData(c,S.start*h.BYTES_PER_ELEMENT,h,S.start,S.count)}l.clearUpdateRanges()}l.onUploadCallback()}function s(o){return o.isInterleavedBufferAttribute&&(o=o.data),e.get(o)}function r(o){o.isInterleavedBufferAttribute&&(o=o.data);const l=e.get(o);l&&(i.deleteBuffer(l.buffer),e.delete(o))}function a(o,l){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){const h=e.get(o);(!h||h.version<o.version)&&e.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}const c=e.get(o);if(c===void 0)e.set(o,t(o,l));else if(c.version<o.version){if(c.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");n(c.buffer,o,l),c.version=o.version}}return{get:s,remove:r,update:a}}var k_=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,B_=`#ifdef USE_ALPHAHASH
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
#endif`,z_=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,H_=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,G_=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,V_=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,W_=`#ifdef USE_AOMAP
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
#endif`,X_=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,$_=`#ifdef USE_BATCHING
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
#endif`,q_=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,Y_=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,K_=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,Z_=`float G_BlinnPhong_Implicit( ) {
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
} // validated`,J_=`#ifdef USE_IRIDESCENCE
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
#endif`,j_=`#ifdef USE_BUMPMAP
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
#endif`,Q_=`#if NUM_CLIPPING_PLANES > 0
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
#endif`,ev=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,tv=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,nv=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,iv=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,sv=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,rv=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,av=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
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
#endif`,ov=`#define PI 3.141592653589793
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
} // validated`,lv=`vec3 transformedNormal = objectNormal;
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
#endif`,cv=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,hv=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,uv=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,dv=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,fv="gl_FragColor = linearToOutputTexel( gl_FragColor );",pv=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,mv=`#ifdef USE_ENVMAP
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
#endif`,gv=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,_v=`#ifdef USE_ENVMAP
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
#endif`,vv=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,xv=`#ifdef USE_ENVMAP
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
#endif`,Sv=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,yv=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,Mv=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,bv=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,wv=`#ifdef USE_GRADIENTMAP
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
}`,Ev=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,Tv=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,Av=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,Rv=`uniform bool receiveShadow;
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
#include <lightprobes_pars_fragment>`,Cv=`#ifdef USE_ENVMAP
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
#endif`,Pv=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,Lv=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,Dv=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,Nv=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,Iv=`PhysicalMaterial material;
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
#endif`,Uv=`uniform sampler2D dfgLUT;
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
}`,Fv=`
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
#endif`,Ov=`#if defined( RE_IndirectDiffuse )
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
#endif`,kv=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,Bv=`#if NUM_LIGHT_PROBE_GRIDS > 0
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
#endif`,zv=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,Hv=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Gv=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Vv=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,Wv=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,Xv=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,$v=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
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
#endif`,qv=`#if defined( USE_POINTS_UV )
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
#endif`,Yv=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,Kv=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,Zv=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,Jv=`#if defined( USE_MORPHCOLORS )
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
#endif`,jv=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Qv=`#ifdef USE_MORPHTARGETS
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
#endif`,ex=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,tx=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
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
vec3 nonPerturbedNormal = normal;`,nx=`#ifdef USE_NORMALMAP_OBJECTSPACE
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
#endif`,ix=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,sx=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,rx=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,ax=`#ifdef USE_NORMALMAP
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
#endif`,ox=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,lx=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,cx=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,hx=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,ux=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,dx=`vec3 packNormalToRGB( const in vec3 normal ) {
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
}`,fx=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,px=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,mx=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,gx=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,_x=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,vx=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,xx=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,Sx=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,yx=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
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
#endif`,Mx=`float getShadowMask() {
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
}`,bx=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,wx=`#ifdef USE_SKINNING
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
#endif`,Ex=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,Tx=`#ifdef USE_SKINNING
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
#endif`,Ax=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,Rx=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,Cx=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,Px=`#ifndef saturate
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
vec3 CustomToneMapping( vec3 color ) { return color; }`,Lx=`#ifdef USE_TRANSMISSION
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
#endif`,Dx=`#ifdef USE_TRANSMISSION
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
#endif`,Nx=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,Ix=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,Ux=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,Fx=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`;const Ox=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,kx=`uniform sampler2D t2D;
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
}`,Bx=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,zx=`uniform float backgroundBlurriness;
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
}`,Hx=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Gx=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Vx=`#include <common>
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
}`,Wx=`#if DEPTH_PACKING == 3200
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
}`,Xx=`#define DISTANCE
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
}`,$x=`#define DISTANCE
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
}`,qx=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,Yx=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Kx=`uniform float scale;
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
}`,Zx=`uniform vec3 diffuse;
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
}`,Jx=`#include <common>
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
}`,jx=`uniform vec3 diffuse;
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
}`,Qx=`#define LAMBERT
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
}`,eS=`#define LAMBERT
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
}`,tS=`#define MATCAP
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
}`,nS=`#define MATCAP
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
}`,iS=`#define NORMAL
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
}`,sS=`#define NORMAL
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
}`,rS=`#define PHONG
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
}`,aS=`#define PHONG
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
}`,oS=`#define STANDARD
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
}`,lS=`#define STANDARD
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
}`,cS=`#define TOON
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
}`,hS=`#define TOON
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
}`,uS=`uniform float size;
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
}`,dS=`uniform vec3 diffuse;
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
}`,fS=`#include <common>
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
}`,pS=`uniform vec3 color;
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
}`,mS=`uniform float rotation;
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
}`,gS=`uniform vec3 diffuse;
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
}`,lt={alphahash_fragment:k_,alphahash_pars_fragment:B_,alphamap_fragment:z_,alphamap_pars_fragment:H_,alphatest_fragment:G_,alphatest_pars_fragment:V_,aomap_fragment:W_,aomap_pars_fragment:X_,batching_pars_vertex:$_,batching_vertex:q_,begin_vertex:Y_,beginnormal_vertex:K_,bsdfs:Z_,iridescence_fragment:J_,bumpmap_pars_fragment:j_,clipping_planes_fragment:Q_,clipping_planes_pars_fragment:ev,clipping_planes_pars_vertex:tv,clipping_planes_vertex:nv,color_fragment:iv,color_pars_fragment:sv,color_pars_vertex:rv,color_vertex:av,common:ov,defaultnormal_vertex:lv,displacementmap_pars_vertex:cv,displacementmap_vertex:hv,emissivemap_fragment:uv,emissivemap_pars_fragment:dv,colorspace_fragment:fv,colorspace_pars_fragment:pv,envmap_fragment:mv,envmap_common_pars_fragment:gv,envmap_pars_fragment:_v,envmap_pars_vertex:vv,envmap_physical_pars_fragment:Cv,envmap_vertex:xv,fog_vertex:Sv,fog_pars_vertex:yv,fog_fragment:Mv,fog_pars_fragment:bv,gradientmap_pars_fragment:wv,lightmap_pars_fragment:Ev,lights_lambert_fragment:Tv,lights_lambert_pars_fragment:Av,lights_pars_begin:Rv,lights_toon_fragment:Pv,lights_toon_pars_fragment:Lv,lights_phong_fragment:Dv,lights_phong_pars_fragment:Nv,lights_physical_fragment:Iv,lights_physical_pars_fragment:Uv,lights_fragment_begin:Fv,lights_fragment_maps:Ov,lights_fragment_end:kv,lightprobes_pars_fragment:Bv,logdepthbuf_fragment:zv,logdepthbuf_pars_fragment:Hv,logdepthbuf_pars_vertex:Gv,logdepthbuf_vertex:Vv,map_fragment:Wv,map_pars_fragment:Xv,map_particle_fragment:$v,map_particle_pars_fragment:qv,metalnessmap_fragment:Yv,metalnessmap_pars_fragment:Kv,morphinstance_vertex:Zv,morphcolor_vertex:Jv,morphnormal_vertex:jv,morphtarget_pars_vertex:Qv,morphtarget_vertex:ex,normal_fragment_begin:tx,normal_fragment_maps:nx,normal_pars_fragment:ix,normal_pars_vertex:sx,normal_vertex:rx,normalmap_pars_fragment:ax,clearcoat_normal_fragment_begin:ox,clearcoat_normal_fragment_maps:lx,clearcoat_pars_fragment:cx,iridescence_pars_fragment:hx,opaque_fragment:ux,packing:dx,premultiplied_alpha_fragment:fx,project_vertex:px,dithering_fragment:mx,dithering_pars_fragment:gx,roughnessmap_fragment:_x,roughnessmap_pars_fragment:vx,shadowmap_pars_fragment:xx,shadowmap_pars_vertex:Sx,shadowmap_vertex:yx,shadowmask_pars_fragment:Mx,skinbase_vertex:bx,skinning_pars_vertex:wx,skinning_vertex:Ex,skinnormal_vertex:Tx,specularmap_fragment:Ax,specularmap_pars_fragment:Rx,tonemapping_fragment:Cx,tonemapping_pars_fragment:Px,transmission_fragment:Lx,transmission_pars_fragment:Dx,uv_pars_fragment:Nx,uv_pars_vertex:Ix,uv_vertex:Ux,worldpos_vertex:Fx,background_vert:Ox,background_frag:kx,backgroundCube_vert:Bx,backgroundCube_frag:zx,cube_vert:Hx,cube_frag:Gx,depth_vert:Vx,depth_frag:Wx,distance_vert:Xx,distance_frag:$x,equirect_vert:qx,equirect_frag:Yx,linedashed_vert:Kx,linedashed_frag:Zx,meshbasic_vert:Jx,meshbasic_frag:jx,meshlambert_vert:Qx,meshlambert_frag:eS,meshmatcap_vert:tS,meshmatcap_frag:nS,meshnormal_vert:iS,meshnormal_frag:sS,meshphong_vert:rS,meshphong_frag:aS,meshphysical_vert:oS,meshphysical_frag:lS,meshtoon_vert:cS,meshtoon_frag:hS,points_vert:uS,points_frag:dS,shadow_vert:fS,shadow_frag:pS,sprite_vert:mS,sprite_frag:gS},Ue={common:{diffuse:{value:new ct(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new rt},alphaMap:{value:null},alphaMapTransform:{value:new rt},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new rt}},envmap:{envMap:{value:null},envMapRotation:{value:new rt},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new rt}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new rt}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new rt},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new rt},normalScale:{value:new Ye(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new rt},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new rt}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new rt}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new rt}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new ct(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new ct(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new rt},alphaTest:{value:0},uvTransform:{value:new rt}},sprite:{diffuse:{value:new ct(16777215)},opacity:{value:1},center:{value:new Ye(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new rt},alphaMap:{value:null},alphaMapTransform:{value:new rt},alphaTest:{value:0}}},Gi={basic:{uniforms:Vn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.fog]),vertexShader:lt.meshbasic_vert,fragmentShader:lt.meshbasic_frag},lambert:{uniforms:Vn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,Ue.lights,{emissive:{value:new ct(0)},envMapIntensity:{value:1}}]),vertexShader:lt.meshlambert_vert,fragmentShader:lt.meshlambert_frag},phong:{uniforms:Vn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,Ue.lights,{emissive:{value:new ct(0)},specular:{value:new ct(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:lt.meshphong_vert,fragmentShader:lt.meshphong_frag},standard:{uniforms:Vn([Ue.common,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.roughnessmap,Ue.metalnessmap,Ue.fog,Ue.lights,{emissive:{value:new ct(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:lt.meshphysical_vert,fragmentShader:lt.meshphysical_frag},toon:{uniforms:Vn([Ue.common,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.gradientmap,Ue.fog,Ue.lights,{emissive:{value:new ct(0)}}]),vertexShader:lt.meshtoon_vert,fragmentShader:lt.meshtoon_frag},matcap:{uniforms:Vn([Ue.common,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,{matcap:{value:null}}]),vertexShader:lt.meshmatcap_vert,fragmentShader:lt.meshmatcap_frag},points:{uniforms:Vn([Ue.points,Ue.fog]),vertexShader:lt.points_vert,fragmentShader:lt.points_frag},dashed:{uniforms:Vn([Ue.common,Ue.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:lt.linedashed_vert,fragmentShader:lt.linedashed_frag},depth:{uniforms:Vn([Ue.common,Ue.displacementmap]),vertexShader:lt.depth_vert,fragmentShader:lt.depth_frag},normal:{uniforms:Vn([Ue.common,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,{opacity:{value:1}}]),vertexShader:lt.meshnormal_vert,fragmentShader:lt.meshnormal_frag},sprite:{uniforms:Vn([Ue.sprite,Ue.fog]),vertexShader:lt.sprite_vert,fragmentShader:lt.sprite_frag},background:{uniforms:{uvTransform:{value:new rt},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:lt.background_vert,fragmentShader:lt.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new rt}},vertexShader:lt.backgroundCube_vert,fragmentShader:lt.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:lt.cube_vert,fragmentShader:lt.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:lt.equirect_vert,fragmentShader:lt.equirect_frag},distance:{uniforms:Vn([Ue.common,Ue.displacementmap,{referencePosition:{value:new z},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:lt.distance_vert,fragmentShader:lt.distance_frag},shadow:{uniforms:Vn([Ue.lights,Ue.fog,{color:{value:new ct(0)},opacity:{value:1}}]),vertexShader:lt.shadow_vert,fragmentShader:lt.shadow_frag}};Gi.physical={uniforms:Vn([Gi.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new rt},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new rt},clearcoatNormalScale:{value:new Ye(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new rt},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new rt},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new rt},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new rt},sheen:{value:0},sheenColor:{value:new ct(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new rt},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new rt},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new rt},transmissionSamplerSize:{value:new Ye},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new rt},attenuationDistance:{value:0},attenuationColor:{value:new ct(0)},specularColor:{value:new ct(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new rt},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new rt},anisotropyVector:{value:new Ye},anisotropyMap:{value:null},anisotropyMapTransform:{value:new rt}}]),vertexShader:lt.meshphysical_vert,fragmentShader:lt.meshphysical_frag};const Eo={r:0,b:0,g:0},_S=new Nt,tm=new rt;tm.set(-1,0,0,0,1,0,0,0,1);function vS(i,e,t,n,s,r){const a=new ct(0);let o=s===!0?0:1,l,c,h=null,u=0,d=null;function m(x){let R=x.isScene===!0?x.background:null;if(R&&R.isTexture){const y=x.backgroundBlurriness>0;R=e.get(R,y)}return R}function _(x){let R=!1;const y=m(x);y===null?p(a,o):y&&y.isColor&&(p(y,1),R=!0);const A=i.xr.getEnvironmentBlendMode();A==="additive"?t.buffers.color.setClear(0,0,0,1,r):A==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,r),(i.autoClear||R)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),i.clear(i.autoClearColor,i.autoClearDepth,i.autoClearStencil))}function S(x,R){const y=m(R);y&&y.isCubeTexture?(c===void 0&&(c=new on(new Wa(1,1,1),new Zs({name:"BackgroundCubeMaterial",uniforms:Gr(Gi.backgroundCube.uniforms),vertexShader:Gi.backgroundCube.vertexShader,fragmentShader:Gi.backgroundCube.fragmentShader,side:Kn,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),c.geometry.deleteAttribute("uv"),c.onBeforeRender=function(A,w,g){this.matrixWorld.copyPosition(g.matrixWorld)},Object.defineProperty(c.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),n.update(c)),c.material.uniforms.envMap.value=y,c.material.uniforms.backgroundBlurriness.value=R.backgroundBlurriness,c.material.uniforms.backgroundIntensity.value=R.backgroundIntensity,c.material.uniforms.backgroundRotation.value.setFromMatrix4(_S.makeRotationFromEuler(R.backgroundRotation)).transpose(),y.isRenderTargetTexture===!1&&c.material.uniforms.backgroundRotation.value.premultiply(tm),c.material.toneMapped=vt.getTransfer(y.colorSpace)!==Dt,(h!==y||u!==y.version||d!==i.toneMapping)&&(c.material.needsUpdate=!0,h=y,u=y.version,d=i.toneMapping),c.layers.enableAll(),x.unshift(c,c.geometry,c.material,0,0,null)):y&&y.isTexture&&(l===void 0&&(l=new on(new ul(2,2),new Zs({name:"BackgroundMaterial",uniforms:Gr(Gi.background.uniforms),vertexShader:Gi.background.vertexShader,fragmentShader:Gi.background.fragmentShader,side:Cs,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),n.update(l)),l.material.uniforms.t2D.value=y,l.material.uniforms.backgroundIntensity.value=R.backgroundIntensity,l.material.toneMapped=vt.getTransfer(y.colorSpace)!==Dt,y.matrixAutoUpdate===!0&&y.updateMatrix(),l.material.uniforms.uvTransform.value.copy(y.matrix),(h!==y||u!==y.version||d!==i.toneMapping)&&(l.material.needsUpdate=!0,h=y,u=y.version,d=i.toneMapping),l.layers.enableAll(),x.unshift(l,l.geometry,l.material,0,0,null))}function p(x,R){x.getRGB(Eo,$p(i)),t.buffers.color.setClear(Eo.r,Eo.g,Eo.b,R,r)}function f(){c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0),l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0)}return{getClearColor:function(){return a},setClearColor:function(x,R=1){a.set(x),o=R,p(a,o)},getClearAlpha:function(){return o},setClearAlpha:function(x){o=x,p(a,o)},render:_,addToRenderList:S,dispose:f}}function xS(i,e){const t=i.getParameter(i.MAX_VERTEX_ATTRIBS),n={},s=d(null);let r=s,a=!1;function o(P,B,V,U,W){let Z=!1;const H=u(P,U,V,B);r!==H&&(r=H,c(r.object)),Z=m(P,U,V,W),Z&&_(P,U,V,W),W!==null&&e.update(W,i.ELEMENT_ARRAY_BUFFER),(Z||a)&&(a=!1,y(P,B,V,U),W!==null&&i.bindBuffer(i.ELEMENT_ARRAY_BUFFER,e.get(W).buffer))}function l(){return i.createVertexArray()}function c(P){return i.bindVertexArray(P)}function h(P){return i.deleteVertexArray(P)}function u(P,B,V,U){const W=U.wireframe===!0;let Z=n[B.id];Z===void 0&&(Z={},n[B.id]=Z);const H=P.isInstancedMesh===!0?P.id:0;let he=Z[H];he===void 0&&(he={},Z[H]=he);let J=he[V.id];J===void 0&&(J={},he[V.id]=J);let ee=J[W];return ee===void 0&&(ee=d(l()),J[W]=ee),ee}function d(P){const B=[],V=[],U=[];for(let W=0;W<t;W++)B[W]=0,V[W]=0,U[W]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:B,enabledAttributes:V,attributeDivisors:U,object:P,attributes:{},index:null}}function m(P,B,V,U){const W=r.attributes,Z=B.attributes;let H=0;const he=V.getAttributes();for(const J in he)if(he[J].location>=0){const se=W[J];let pe=Z[J];if(pe===void 0&&(J==="instanceMatrix"&&P.instanceMatrix&&(pe=P.instanceMatrix),J==="instanceColor"&&P.instanceColor&&(pe=P.instanceColor)),se===void 0||se.attribute!==pe||pe&&se.data!==pe.data)return!0;H++}return r.attributesNum!==H||r.index!==U}function _(P,B,V,U){const W={},Z=B.attributes;let H=0;const he=V.getAttributes();for(const J in he)if(he[J].location>=0){let se=Z[J];se===void 0&&(J==="instanceMatrix"&&P.instanceMatrix&&(se=P.instanceMatrix),J==="instanceColor"&&P.instanceColor&&(se=P.instanceColor));const pe={};pe.attribute=se,se&&se.data&&(pe.data=se.data),W[J]=pe,H++}r.attributes=W,r.attributesNum=H,r.index=U}function S(){const P=r.newAttributes;for(let B=0,V=P.length;B<V;B++)P[B]=0}function p(P){f(P,0)}function f(P,B){const V=r.newAttributes,U=r.enabledAttributes,W=r.attributeDivisors;V[P]=1,U[P]===0&&(i.enableVertexAttribArray(P),U[P]=1),W[P]!==B&&(i.vertexAttribDivisor(P,B),W[P]=B)}function x(){const P=r.newAttributes,B=r.enabledAttributes;for(let V=0,U=B.length;V<U;V++)B[V]!==P[V]&&(i.disableVertexAttribArray(V),B[V]=0)}function R(P,B,V,U,W,Z,H){H===!0?i.vertexAttribIPointer(P,B,V,W,Z):i.vertexAttribPointer(P,B,V,U,W,Z)}function y(P,B,V,U){S();const W=U.attributes,Z=V.getAttributes(),H=B.defaultAttributeValues;for(const he in Z){const J=Z[he];if(J.location>=0){let ee=W[he];if(ee===void 0&&(he==="instanceMatrix"&&P.instanceMatrix&&(ee=P.instanceMatrix),he==="instanceColor"&&P.instanceColor&&(ee=P.instanceColor)),ee!==void 0){const se=ee.normalized,pe=ee.itemSize,fe=e.get(ee);if(fe===void 0)continue;const te=fe.buffer,_e=fe.type,xe=fe.bytesPerElement,Pe=_e===i.INT||_e===i.UNSIGNED_INT||ee.gpuType===qh;if(ee.isInterleavedBufferAttribute){const Me=ee.data,q=Me.isInterleavedBuffer===!0?Me.stride:Me.itemSize,oe=ee.offset;if(Me.isInstancedInterleavedBuffer||Me.isInstancedBufferAttribute){for(let ve=0;ve<J.locationSize;ve++)f(J.location+ve,Me.meshPerAttribute);P.isInstancedMesh!==!0&&U._maxInstanceCount===void 0&&(U._maxInstanceCount=Me.meshPerAttribute*Me.count)}else for(let ve=0;ve<J.locationSize;ve++)p(J.location+ve);i.bindBuffer(i.ARRAY_BUFFER,te);for(let ve=0;ve<J.locationSize;ve++)R(J.location+ve,pe/J.locationSize,_e,se,q*xe,(oe+pe/J.locationSize*ve)*xe,Pe)}else{if(ee.isInstancedBufferAttribute){for(let Me=0;Me<J.locationSize;Me++)f(J.location+Me,ee.meshPerAttribute);P.isInstancedMesh!==!0&&U._maxInstanceCount===void 0&&(U._maxInstanceCount=ee.meshPerAttribute*ee.count)}else for(let Me=0;Me<J.locationSize;Me++)p(J.location+Me);i.bindBuffer(i.ARRAY_BUFFER,te);for(let Me=0;Me<J.locationSize;Me++)R(J.location+Me,pe/J.locationSize,_e,se,pe*xe,pe/J.locationSize*Me*xe,Pe)}}else if(H!==void 0){const se=H[he];if(se!==void 0)switch(se.length){case 2:i.vertexAttrib2fv(J.location,se);break;case 3:i.vertexAttrib3fv(J.location,se);break;case 4:i.vertexAttrib4fv(J.location,se);break;default:i.vertexAttrib1fv(J.location,se)}}}}x()}function A(){I();for(const P in n){const B=n[P];for(const V in B){const U=B[V];for(const W in U){const Z=U[W];for(const H in Z)h(Z[H].object),delete Z[H];delete U[W]}}delete n[P]}}function w(P){if(n[P.id]===void 0)return;const B=n[P.id];for(const V in B){const U=B[V];for(const W in U){const Z=U[W];for(const H in Z)h(Z[H].object),delete Z[H];delete U[W]}}delete n[P.id]}function g(P){for(const B in n){const V=n[B];for(const U in V){const W=V[U];if(W[P.id]===void 0)continue;const Z=W[P.id];for(const H in Z)h(Z[H].object),delete Z[H];delete W[P.id]}}}function b(P){for(const B in n){const V=n[B],U=P.isInstancedMesh===!0?P.id:0,W=V[U];if(W!==void 0){for(const Z in W){const H=W[Z];for(const he in H)h(H[he].object),delete H[he];delete W[Z]}delete V[U],Object.keys(V).length===0&&delete n[B]}}}function I(){N(),a=!0,r!==s&&(r=s,c(r.object))}function N(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:o,reset:I,resetDefaultState:N,dispose:A,releaseStatesOfGeometry:w,releaseStatesOfObject:b,releaseStatesOfProgram:g,initAttributes:S,enableAttribute:p,disableUnusedAttributes:x}}function SS(i,e,t){let n;function s(l){n=l}function r(l,c){i.drawArrays(n,l,c),t.update(c,n,1)}function a(l,c,h){h!==0&&(i.drawArraysInstanced(n,l,c,h),t.update(c,n,h))}function o(l,c,h){if(h===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(n,l,0,c,0,h);let d=0;for(let m=0;m<h;m++)d+=c[m];t.update(d,n,1)}this.setMode=s,this.render=r,this.renderInstances=a,this.renderMultiDraw=o}function yS(i,e,t,n){let s;function r(){if(s!==void 0)return s;if(e.has("EXT_texture_filter_anisotropic")===!0){const g=e.get("EXT_texture_filter_anisotropic");s=i.getParameter(g.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function a(g){return!(g!==Wi&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(g){const b=g===Ki&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(g!==ii&&g!==Vi&&!b&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_TYPE))}function l(g){if(g==="highp"){if(i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.HIGH_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.HIGH_FLOAT).precision>0)return"highp";g="mediump"}return g==="mediump"&&i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.MEDIUM_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let c=t.precision!==void 0?t.precision:"highp";const h=l(c);h!==c&&(tt("WebGLRenderer:",c,"not supported, using",h,"instead."),c=h);const u=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),d=t.logarithmicDepthBuffer===!0&&u===!1;t.reversedDepthBuffer===!0&&u===!1&&tt("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&u===!0&&tt("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");const m=i.getParameter(i.MAX_TEXTURE_IMAGE_UNITS),_=i.getParameter(i.MAX_VERTEX_TEXTURE_IMAGE_UNITS),S=i.getParameter(i.MAX_TEXTURE_SIZE),p=i.getParameter(i.MAX_CUBE_MAP_TEXTURE_SIZE),f=i.getParameter(i.MAX_VERTEX_ATTRIBS),x=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),R=i.getParameter(i.MAX_VARYING_VECTORS),y=i.getParameter(i.MAX_FRAGMENT_UNIFORM_VECTORS),A=i.getParameter(i.MAX_SAMPLES),w=i.getParameter(i.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:l,textureFormatReadable:a,textureTypeReadable:o,precision:c,logarithmicDepthBuffer:d,reversedDepthBuffer:u,maxTextures:m,maxVertexTextures:_,maxTextureSize:S,maxCubemapSize:p,maxAttributes:f,maxVertexUniforms:x,maxVaryings:R,maxFragmentUniforms:y,maxSamples:A,samples:w}}function MS(i){const e=this;let t=null,n=0,s=!1,r=!1;const a=new Ai,o=new rt,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(u,d){const m=u.length!==0||d||n!==0||s;return s=d,n=u.length,m},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(u,d){t=h(u,d,0)},this.setState=function(u,d,m){const _=u.clippingPlanes,S=u.clipIntersection,p=u.clipShadows,f=i.get(u);if(!s||_===null||_.length===0||r&&!p)r?h(null):c();else{const x=r?0:n,R=x*4;let y=f.clippingState||null;l.value=y,y=h(_,d,R,m);for(let A=0;A!==R;++A)y[A]=t[A];f.clippingState=y,this.numIntersection=S?this.numPlanes:0,this.numPlanes+=x}};function c(){l.value!==t&&(l.value=t,l.needsUpdate=n>0),e.numPlanes=n,e.numIntersection=0}function h(u,d,m,_){const S=u!==null?u.length:0;let p=null;if(S!==0){if(p=l.value,_!==!0||p===null){const f=m+S*4,x=d.matrixWorldInverse;o.getNormalMatrix(x),(p===null||p.length<f)&&(p=new Float32Array(f));for(let R=0,y=m;R!==S;++R,y+=4)a.copy(u[R]).applyMatrix4(x,o),a.normal.toArray(p,y),p[y+3]=a.constant}l.value=p,l.needsUpdate=!0}return e.numPlanes=S,e.numIntersection=0,p}}class iu extends qi{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;const n={width:e,height:e,depth:1},s=[n,n,n,n,n,n];this.texture=new Vp(s),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;const n={uniforms:{tEquirect:{value:null}},vertexShader:`

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
			`},s=new Wa(5,5,5),r=new Zs({name:"CubemapFromEquirect",uniforms:Gr(n.uniforms),vertexShader:n.vertexShader,fragmentShader:n.fragmentShader,side:Kn,blending:Ur});r.uniforms.tEquirect.value=t;const a=new on(s,r),o=t.minFilter;return t.minFilter===Ts&&(t.minFilter=Yn),new yh(1,10,this).update(e,a),t.minFilter=o,a.geometry.dispose(),a.material.dispose(),this}clear(e,t=!0,n=!0,s=!0){const r=e.getRenderTarget();for(let a=0;a<6;a++)e.setRenderTarget(this,a),e.clear(t,n,s);e.setRenderTarget(r)}}const Cd=256,bS=3,wS=20,nm=256,im=16,ES=3,TS=new z,AS=new ct;class nl{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new yh(1,10,null),this._boxMesh=new on(new Wa(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,n=.1,s=100,r={}){const{size:a=256,position:o=TS}=r,l=this._renderer;this._setSize(a);const c=this._allocateTarget(),h=this._getSourceTarget(!0);t>0&&(h.texture.mipmapsAutoUpdate=!1);const u=l.autoClear,d=l.autoClearColor,m=l.autoClearDepth,_=l.autoClearStencil,S=e.background;l.autoClear=!0,l.autoClearColor=!0,l.autoClearDepth=!0,l.autoClearStencil=!0,S===null&&(e.background=l.getClearColor(AS));const p=new yh(n,s,h);return p.position.copy(o),p.update(l,e),l.autoClear=u,l.autoClearColor=d,l.autoClearDepth=m,l.autoClearStencil=_,e.background=S,t>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(c,t)),this._applyPMREM(c),c}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=Dd(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Ld(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(Cd,K0(e))}_fromTexture(e,t){e.mapping===Br||e.mapping===Da?this._setSize(e.image.length===0?Cd:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);const n=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(n),n}_allocateTarget(){const e=this._cubeSize,t=Pd(e,!1,!1),n=Math.log2(e)-bS;for(let s=0;s<=n;s++)t.texture.mipmaps.push({width:e>>s,height:e>>s});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){const t=this._cubeSize,n=this._sourceTarget;return(n===null||n.width!==t||e&&n.depthBuffer===!1)&&(n!==null&&n.dispose(),this._sourceTarget=Pd(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,n){const s=this._boxMesh,r=this._cubeCamera;s.material=n,r.renderTarget=e,r.activeMipmapLevel=t;const a=e.width>>t;e.viewport.set(0,0,a,a),r.update(this._renderer,s),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===Br||e.mapping===Da?(this._cubemapMaterial===null&&(this._cubemapMaterial=Dd()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Ld()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=RS(),this._integrationMaterial=CS());const t=this._cubeSize,n=e.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;const r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(t/im);for(let a=0;a<=n;a++){const o=nl.lodToRoughness(a,n);if(a>n-ES)r.roughness.value=o,this._renderCube(e,a,this._integrationMaterial);else{const l=o>0?Math.log2(t)+.5*Math.log2(6/(nm*Math.pow(o,4)))+.5:0;s.roughness.value=o,s.lodBias.value=l,this._renderCube(e,a,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=PS());const n=this._blurMaterial,s=n.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(e,0,n),s.envMap.value=e.texture,this._renderCube(r,0,n)}}function Pd(i,e,t){return new iu(i,{minFilter:Ts,generateMipmaps:e,type:Ki,colorSpace:Ko,depthBuffer:t})}function $a(i,e,t){return new Zs({name:i,uniforms:e,vertexShader:lt.cube_vert,fragmentShader:t,side:Kn,blending:Ur,depthTest:!1,depthWrite:!1})}function RS(){return $a("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${nm}u

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
	`)}function CS(){return $a("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:im}},`

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
	`)}function PS(){return $a("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${wS}
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
	`)}function Ld(){return $a("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

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
	`)}function Dd(){return $a("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function LS(i){let e=new WeakMap,t=new WeakMap,n=null;function s(d,m=!1){return d==null?null:m?a(d):r(d)}function r(d){if(d&&d.isTexture){const m=d.mapping;if(m===Ol||m===kl)if(e.has(d)){const _=e.get(d).texture;return o(_,d.mapping)}else{const _=d.image;if(_&&_.height>0){const S=new iu(_.height);return S.fromEquirectangularTexture(i,d),e.set(d,S),d.addEventListener("dispose",c),o(S.texture,d.mapping)}else return null}}return d}function a(d){if(d&&d.isTexture&&d.isPMREMTexture!==!0){const m=d.mapping,_=m===Ol||m===kl,S=m===Br||m===Da;if(_||S){let p=t.get(d);const f=p!==void 0?p.texture.pmremVersion:0;if(d.isRenderTargetTexture&&d.pmremVersion!==f)return n===null&&(n=new nl(i)),p=_?n.fromEquirectangular(d,p):n.fromCubemap(d,p),p.texture.pmremVersion=d.pmremVersion,t.set(d,p),p.texture;if(p!==void 0)return p.texture;{const x=d.image;return _&&x&&x.height>0||S&&x&&l(x)?(n===null&&(n=new nl(i)),p=_?n.fromEquirectangular(d):n.fromCubemap(d),p.texture.pmremVersion=d.pmremVersion,t.set(d,p),d.addEventListener("dispose",h),p.texture):null}}}return d}function o(d,m){return m===Ol?d.mapping=Br:m===kl&&(d.mapping=Da),d}function l(d){let m=0;const _=6;for(let S=0;S<_;S++)d[S]!==void 0&&m++;return m===_}function c(d){const m=d.target;m.removeEventListener("dispose",c);const _=e.get(m);_!==void 0&&(e.delete(m),_.dispose())}function h(d){const m=d.target;m.removeEventListener("dispose",h);const _=t.get(m);_!==void 0&&(t.delete(m),_.dispose())}function u(){e=new WeakMap,t=new WeakMap,n!==null&&(n.dispose(),n=null)}return{get:s,dispose:u}}function DS(i){const e={};function t(n){if(e[n]!==void 0)return e[n];const s=i.getExtension(n);return e[n]=s,s}return{has:function(n){return t(n)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(n){const s=t(n);return s===null&&Vo("WebGLRenderer: "+n+" extension not supported."),s}}}function NS(i,e,t,n){const s={},r=new WeakMap,a=new FinalizationRegistry(_=>delete s[_]);function o(_){l(_.target)}function l(_){_.index!==null&&e.remove(_.index);for(const p in _.attributes)e.remove(_.attributes[p]);_.removeEventListener("dispose",o),delete s[_.id],a.unregister(_);const S=r.get(_);S&&(e.remove(S),r.delete(_)),n.releaseStatesOfGeometry(_),_.isInstancedBufferGeometry===!0&&delete _._maxInstanceCount,t.memory.geometries--}function c(_,S){return s[S.id]!==void 0||(S.addEventListener("dispose",o),s[S.id]=new WeakRef(S),a.register(S,S.id,S),t.memory.geometries++),S}function h(_){const S=_.attributes;for(const p in S)e.update(S[p],i.ARRAY_BUFFER)}function u(_){const S=_.index,p=_.attributes.position;let f=0;if(p===void 0)return;const x=S!==null?S.array.length:p.array.length/3-1,R=p.count>=65535?Bp:kp,y=new R(Math.ceil(x/3)*6,1),A=y.array;if(S!==null){const g=S.array;f=S.version;for(let b=0,I=0;b<x;b+=3){const N=g[b+0],P=g[b+1],B=g[b+2];A[I++]=N,A[I++]=P,A[I++]=P,A[I++]=B,A[I++]=B,A[I++]=N}}else{f=p.version;for(let g=0,b=0;g<x;g+=3){const I=g+0,N=g+1,P=g+2;A[b++]=I,A[b++]=N,A[b++]=N,A[b++]=P,A[b++]=P,A[b++]=I}}y.version=f;const w=r.get(_);w&&e.remove(w),r.set(_,y)}function d(_){const S=r.get(_);if(S){const p=_.index;p!==null&&S.version<p.version&&u(_)}else u(_);return r.get(_)}function m(){for(const _ in s){const S=s[_].deref();S!==void 0&&l(S)}}return{get:c,update:h,getWireframeAttribute:d,dispose:m}}function IS(i,e,t){let n;function s(u){n=u}let r,a;function o(u){r=u.type,a=u.bytesPerElement}function l(u,d){i.drawElements(n,d,r,u*a),t.update(d,n,1)}function c(u,d,m){m!==0&&(i.drawElementsInstanced(n,d,r,u*a,m),t.update(d,n,m))}function h(u,d,m){if(m===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(n,d,0,r,u,0,m);let S=0;for(let p=0;p<m;p++)S+=d[p];t.update(S,n,1)}this.setMode=s,this.setIndex=o,this.render=l,this.renderInstances=c,this.renderMultiDraw=h}function US(i){const e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function n(r,a,o){switch(t.calls++,a){case i.TRIANGLES:t.triangles+=o*(r/3);break;case i.LINES:t.lines+=o*(r/2);break;case i.LINE_STRIP:t.lines+=o*(r-1);break;case i.LINE_LOOP:t.lines+=o*r;break;case i.POINTS:t.points+=o*r;break;default:St("WebGLInfo: Unknown draw mode:",a);break}}function s(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:s,update:n}}function FS(i,e,t){const n=new WeakMap,s=new an;function r(a,o,l){const c=a.morphTargetInfluences,h=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,u=h!==void 0?h.length:0;let d=n.get(o);if(d===void 0||d.count!==u){let N=function(){b.dispose(),n.delete(o),o.removeEventListener("dispose",N)};var m=N;d!==void 0&&d.texture.dispose();const _=o.morphAttributes.position!==void 0,S=o.morphAttributes.normal!==void 0,p=o.morphAttributes.color!==void 0,f=o.morphAttributes.position||[],x=o.morphAttributes.normal||[],R=o.morphAttributes.color||[];let y=0;_===!0&&(y=1),S===!0&&(y=2),p===!0&&(y=3);let A=o.attributes.position.count*y,w=1;A>e.maxTextureSize&&(w=Math.ceil(A/e.maxTextureSize),A=e.maxTextureSize);const g=new Float32Array(A*w*4*u),b=new Up(g,A,w,u);b.type=Vi,b.needsUpdate=!0;const I=y*4;for(let P=0;P<u;P++){const B=f[P],V=x[P],U=R[P],W=A*w*4*P;for(let Z=0;Z<B.count;Z++){const H=Z*I;_===!0&&(s.fromBufferAttribute(B,Z),g[W+H+0]=s.x,g[W+H+1]=s.y,g[W+H+2]=s.z,g[W+H+3]=0),S===!0&&(s.fromBufferAttribute(V,Z),g[W+H+4]=s.x,g[W+H+5]=s.y,g[W+H+6]=s.z,g[W+H+7]=0),p===!0&&(s.fromBufferAttribute(U,Z),g[W+H+8]=s.x,g[W+H+9]=s.y,g[W+H+10]=s.z,g[W+H+11]=U.itemSize===4?s.w:1)}}d={count:u,texture:b,size:new Ye(A,w)},n.set(o,d),o.addEventListener("dispose",N)}if(a.isInstancedMesh===!0&&a.morphTexture!==null)l.getUniforms().setValue(i,"morphTexture",a.morphTexture,t);else{let _=0;for(let p=0;p<c.length;p++)_+=c[p];const S=o.morphTargetsRelative?1:1-_;l.getUniforms().setValue(i,"morphTargetBaseInfluence",S),l.getUniforms().setValue(i,"morphTargetInfluences",c)}l.getUniforms().setValue(i,"morphTargetsTexture",d.texture,t),l.getUniforms().setValue(i,"morphTargetsTextureSize",d.size)}return{update:r}}function OS(i,e,t,n,s){let r=new WeakMap;function a(c){const h=s.render.frame,u=c.geometry,d=e.get(c,u);if(r.get(d)!==h&&(e.update(d),r.set(d,h)),c.isInstancedMesh&&(c.hasEventListener("dispose",l)===!1&&c.addEventListener("dispose",l),r.get(c)!==h&&(t.update(c.instanceMatrix,i.ARRAY_BUFFER),c.instanceColor!==null&&t.update(c.instanceColor,i.ARRAY_BUFFER),r.set(c,h))),c.isSkinnedMesh){const m=c.skeleton;r.get(m)!==h&&(m.update(),r.set(m,h))}return d}function o(){r=new WeakMap}function l(c){const h=c.target;h.removeEventListener("dispose",l),n.releaseStatesOfObject(h),t.remove(h.instanceMatrix),h.instanceColor!==null&&t.remove(h.instanceColor)}return{update:a,dispose:o}}const kS={[fp]:"LINEAR_TONE_MAPPING",[pp]:"REINHARD_TONE_MAPPING",[mp]:"CINEON_TONE_MAPPING",[gp]:"ACES_FILMIC_TONE_MAPPING",[vp]:"AGX_TONE_MAPPING",[xp]:"NEUTRAL_TONE_MAPPING",[_p]:"CUSTOM_TONE_MAPPING"};function BS(i,e,t,n,s,r){const a=new qi(e,t,{type:i,depthBuffer:s,stencilBuffer:r,samples:n?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1});let o=null,l=null,c=null;const h=new Gt;h.setAttribute("position",new ln([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new ln([0,2,0,0,2,0],2));const u=new T_({uniforms:{tDiffuse:{value:null}},vertexShader:`
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
			}`,depthTest:!1,depthWrite:!1}),d=new on(h,u),m=new Zp(-1,1,1,-1,0,1);let _=null,S=null,p=!1,f,x=null,R=[],y=!1;this.setSize=function(A,w){a.setSize(A,w),o!==null&&o.setSize(A,w),l!==null&&l.setSize(A,w);for(let g=0;g<R.length;g++){const b=R[g];b.setSize&&b.setSize(A,w)}},this.setEffects=function(A){R=A,y=R.length>0&&R[0].isRenderPass===!0;const w=a.width,g=a.height;R.length>0&&o===null&&(o=new qi(w,g,{type:Ki,depthBuffer:!1,stencilBuffer:!1}),l=new qi(w,g,{type:Ki,depthBuffer:!1,stencilBuffer:!1}));const b=s===!0&&R.some(I=>I.needsDepthTexture===!0);b!==(a.depthTexture!==null)&&(b===!0&&c===null&&(c=new Hr(w,g),r===!0&&(c.format=As,c.type=zr)),a.dispose(),a.depthTexture=b?c:null,a.resolveDepthBuffer=b,a.storeMultisampledDepthBuffer=b);for(let I=0;I<R.length;I++){const N=R[I];N.setSize&&N.setSize(w,g),b&&N.needsDepthTexture===!0&&N.setDepthTexture&&N.setDepthTexture(c)}},this.begin=function(A,w){if(p||A.toneMapping===cs&&R.length===0)return!1;if(x=w,w!==null){const g=w.width,b=w.height;(a.width!==g||a.height!==b)&&this.setSize(g,b)}return y===!1&&A.setRenderTarget(a),f=A.toneMapping,A.toneMapping=cs,!0},this.hasRenderPass=function(){return y},this.end=function(A,w){A.toneMapping=f,p=!0;let g=a,b=o;for(let I=0;I<R.length;I++){const N=R[I];N.enabled!==!1&&(N.render(A,b,g,w),N.needsSwap!==!1&&(g=b,b=b===o?l:o))}if(_!==A.outputColorSpace||S!==A.toneMapping){_=A.outputColorSpace,S=A.toneMapping,u.defines={},vt.getTransfer(_)===Dt&&(u.defines.SRGB_TRANSFER="");const I=kS[S];I&&(u.defines[I]=""),u.needsUpdate=!0}u.uniforms.tDiffuse.value=g.texture,A.setRenderTarget(x),A.render(d,m),x=null,p=!1},this.isCompositing=function(){return p},this.dispose=function(){a.dispose(),o!==null&&o.dispose(),l!==null&&l.dispose(),h.dispose(),u.dispose()}}const sm=new Un,rm=new Hr(1,1),am=new Wp(1),om=new Up,lm=new n_,cm=new Vp,Nd=[],Id=[],Ud=new Float32Array(16),Fd=new Float32Array(9),Od=new Float32Array(4);function qr(i,e,t){const n=i[0];if(n<=0||n>0)return i;const s=e*t;let r=Nd[s];if(r===void 0&&(r=new Float32Array(s),Nd[s]=r),e!==0){n.toArray(r,0);for(let a=1,o=0;a!==e;++a)o+=t,i[a].toArray(r,o)}return r}function yn(i,e){if(i.length!==e.length)return!1;for(let t=0,n=i.length;t<n;t++)if(i[t]!==e[t])return!1;return!0}function Mn(i,e){for(let t=0,n=e.length;t<n;t++)i[t]=e[t]}function dl(i,e){let t=Id[e];t===void 0&&(t=new Int32Array(e),Id[e]=t);for(let n=0;n!==e;++n)t[n]=i.allocateTextureUnit();return t}function zS(i,e){const t=this.cache;t[0]!==e&&(i.uniform1f(this.addr,e),t[0]=e)}function HS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(yn(t,e))return;i.uniform2fv(this.addr,e),Mn(t,e)}}function GS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(i.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(yn(t,e))return;i.uniform3fv(this.addr,e),Mn(t,e)}}function VS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(yn(t,e))return;i.uniform4fv(this.addr,e),Mn(t,e)}}function WS(i,e){const t=this.cache,n=e.elements;if(n===void 0){if(yn(t,e))return;i.uniformMatrix2fv(this.addr,!1,e),Mn(t,e)}else{if(yn(t,n))return;Od.set(n),i.uniformMatrix2fv(this.addr,!1,Od),Mn(t,n)}}function XS(i,e){const t=this.cache,n=e.elements;if(n===void 0){if(yn(t,e))return;i.uniformMatrix3fv(this.addr,!1,e),Mn(t,e)}else{if(yn(t,n))return;Fd.set(n),i.uniformMatrix3fv(this.addr,!1,Fd),Mn(t,n)}}function $S(i,e){const t=this.cache,n=e.elements;if(n===void 0){if(yn(t,e))return;i.uniformMatrix4fv(this.addr,!1,e),Mn(t,e)}else{if(yn(t,n))return;Ud.set(n),i.uniformMatrix4fv(this.addr,!1,Ud),Mn(t,n)}}function qS(i,e){const t=this.cache;t[0]!==e&&(i.uniform1i(this.addr,e),t[0]=e)}function YS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(yn(t,e))return;i.uniform2iv(this.addr,e),Mn(t,e)}}function KS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(yn(t,e))return;i.uniform3iv(this.addr,e),Mn(t,e)}}function ZS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(yn(t,e))return;i.uniform4iv(this.addr,e),Mn(t,e)}}function JS(i,e){const t=this.cache;t[0]!==e&&(i.uniform1ui(this.addr,e),t[0]=e)}function jS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(yn(t,e))return;i.uniform2uiv(this.addr,e),Mn(t,e)}}function QS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(yn(t,e))return;i.uniform3uiv(this.addr,e),Mn(t,e)}}function ey(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(yn(t,e))return;i.uniform4uiv(this.addr,e),Mn(t,e)}}function fl(i){return i.version===0&&(i.compareFunction=Pp,i.needsUpdate=!0),i}function ty(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_2D_SHADOW?r=fl(rm):r=sm,t.setTexture2D(e||r,s)}function ny(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),t.setTexture3D(e||lm,s)}function iy(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_CUBE_SHADOW?r=fl(am):r=cm,t.setTextureCube(e||r,s)}function sy(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),t.setTexture2DArray(e||om,s)}function ry(i){switch(i){case 5126:return zS;case 35664:return HS;case 35665:return GS;case 35666:return VS;case 35674:return WS;case 35675:return XS;case 35676:return $S;case 5124:case 35670:return qS;case 35667:case 35671:return YS;case 35668:case 35672:return KS;case 35669:case 35673:return ZS;case 5125:return JS;case 36294:return jS;case 36295:return QS;case 36296:return ey;case 35678:case 36198:case 36298:case 36306:case 35682:return ty;case 35679:case 36299:case 36307:return ny;case 35680:case 36300:case 36308:case 36293:return iy;case 36289:case 36303:case 36311:case 36292:return sy}}function ay(i,e){i.uniform1fv(this.addr,e)}function oy(i,e){const t=qr(e,this.size,2);i.uniform2fv(this.addr,t)}function ly(i,e){const t=qr(e,this.size,3);i.uniform3fv(this.addr,t)}function cy(i,e){const t=qr(e,this.size,4);i.uniform4fv(this.addr,t)}function hy(i,e){const t=qr(e,this.size,4);i.uniformMatrix2fv(this.addr,!1,t)}function uy(i,e){const t=qr(e,this.size,9);i.uniformMatrix3fv(this.addr,!1,t)}function dy(i,e){const t=qr(e,this.size,16);i.uniformMatrix4fv(this.addr,!1,t)}function fy(i,e){i.uniform1iv(this.addr,e)}function py(i,e){i.uniform2iv(this.addr,e)}function my(i,e){i.uniform3iv(this.addr,e)}function gy(i,e){i.uniform4iv(this.addr,e)}function _y(i,e){i.uniform1uiv(this.addr,e)}function vy(i,e){i.uniform2uiv(this.addr,e)}function xy(i,e){i.uniform3uiv(this.addr,e)}function Sy(i,e){i.uniform4uiv(this.addr,e)}function yy(i,e,t){const n=this.cache,s=e.length,r=dl(t,s);yn(n,r)||(i.uniform1iv(this.addr,r),Mn(n,r));let a;this.type===i.SAMPLER_2D_SHADOW?a=fl(rm):a=sm;for(let o=0;o!==s;++o)t.setTexture2D(e[o]||a,r[o])}function My(i,e,t){const n=this.cache,s=e.length,r=dl(t,s);yn(n,r)||(i.uniform1iv(this.addr,r),Mn(n,r));for(let a=0;a!==s;++a)t.setTexture3D(e[a]||lm,r[a])}function by(i,e,t){const n=this.cache,s=e.length,r=dl(t,s);yn(n,r)||(i.uniform1iv(this.addr,r),Mn(n,r));let a;this.type===i.SAMPLER_CUBE_SHADOW?a=fl(am):a=cm;for(let o=0;o!==s;++o)t.setTextureCube(e[o]||a,r[o])}function wy(i,e,t){const n=this.cache,s=e.length,r=dl(t,s);yn(n,r)||(i.uniform1iv(this.addr,r),Mn(n,r));for(let a=0;a!==s;++a)t.setTexture2DArray(e[a]||om,r[a])}function Ey(i){switch(i){case 5126:return ay;case 35664:return oy;case 35665:return ly;case 35666:return cy;case 35674:return hy;case 35675:return uy;case 35676:return dy;case 5124:case 35670:return fy;case 35667:case 35671:return py;case 35668:case 35672:return my;case 35669:case 35673:return gy;case 5125:return _y;case 36294:return vy;case 36295:return xy;case 36296:return Sy;case 35678:case 36198:case 36298:case 36306:case 35682:return yy;case 35679:case 36299:case 36307:return My;case 35680:case 36300:case 36308:case 36293:return by;case 36289:case 36303:case 36311:case 36292:return wy}}class Ty{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.setValue=ry(t.type)}}class Ay{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=Ey(t.type)}}class Ry{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,n){const s=this.seq;for(let r=0,a=s.length;r!==a;++r){const o=s[r];o.setValue(e,t[o.id],n)}}}const dc=/(\w+)(\])?(\[|\.)?/g;function kd(i,e){i.seq.push(e),i.map[e.id]=e}function Cy(i,e,t){const n=i.name,s=n.length;for(dc.lastIndex=0;;){const r=dc.exec(n),a=dc.lastIndex;let o=r[1];const l=r[2]==="]",c=r[3];if(l&&(o=o|0),c===void 0||c==="["&&a+2===s){kd(t,c===void 0?new Ty(o,i,e):new Ay(o,i,e));break}else{let u=t.map[o];u===void 0&&(u=new Ry(o),kd(t,u)),t=u}}}class Wo{constructor(e,t){this.seq=[],this.map={};const n=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let a=0;a<n;++a){const o=e.getActiveUniform(t,a),l=e.getUniformLocation(t,o.name);Cy(o,l,this)}const s=[],r=[];for(const a of this.seq)a.type===e.SAMPLER_2D_SHADOW||a.type===e.SAMPLER_CUBE_SHADOW||a.type===e.SAMPLER_2D_ARRAY_SHADOW?s.push(a):r.push(a);s.length>0&&(this.seq=s.concat(r))}setValue(e,t,n,s){const r=this.map[t];r!==void 0&&r.setValue(e,n,s)}setOptional(e,t,n){const s=t[n];s!==void 0&&this.setValue(e,n,s)}static upload(e,t,n,s){for(let r=0,a=t.length;r!==a;++r){const o=t[r],l=n[o.id];l.needsUpdate!==!1&&o.setValue(e,l.value,s)}}static seqWithValue(e,t){const n=[];for(let s=0,r=e.length;s!==r;++s){const a=e[s];a.id in t&&n.push(a)}return n}}function Bd(i,e,t){const n=i.createShader(e);return i.shaderSource(n,t),i.compileShader(n),n}const Py=37297;let Ly=0;function Dy(i,e){const t=i.split(`
`),n=[],s=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let a=s;a<r;a++){const o=a+1;n.push(`${o===e?">":" "} ${o}: ${t[a]}`)}return n.join(`
`)}const zd=new rt;function Ny(i){vt._getMatrix(zd,vt.workingColorSpace,i);const e=`mat3( ${zd.elements.map(t=>t.toFixed(4))} )`;switch(vt.getTransfer(i)){case Zo:return[e,"LinearTransferOETF"];case Dt:return[e,"sRGBTransferOETF"];default:return tt("WebGLProgram: Unsupported color space: ",i),[e,"LinearTransferOETF"]}}function Hd(i,e,t){const n=i.getShaderParameter(e,i.COMPILE_STATUS),r=(i.getShaderInfoLog(e)||"").trim();if(n&&r==="")return"";const a=/ERROR: 0:(\d+)/.exec(r);if(a){const o=parseInt(a[1]);return t.toUpperCase()+`

`+r+`

`+Dy(i.getShaderSource(e),o)}else return r}function Iy(i,e){const t=Ny(e);return[`vec4 ${i}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}const Uy={[fp]:"Linear",[pp]:"Reinhard",[mp]:"Cineon",[gp]:"ACESFilmic",[vp]:"AgX",[xp]:"Neutral",[_p]:"Custom"};function Fy(i,e){const t=Uy[e];return t===void 0?(tt("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+i+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+i+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}const To=new z;function Oy(){vt.getLuminanceCoefficients(To);const i=To.x.toFixed(4),e=To.y.toFixed(4),t=To.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${i}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function ky(i){return[i.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",i.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(_a).join(`
`)}function By(i){const e=[];for(const t in i){const n=i[t];n!==!1&&e.push("#define "+t+" "+n)}return e.join(`
`)}function zy(i,e){const t={},n=i.getProgramParameter(e,i.ACTIVE_ATTRIBUTES);for(let s=0;s<n;s++){const r=i.getActiveAttrib(e,s),a=r.name;let o=1;r.type===i.FLOAT_MAT2&&(o=2),r.type===i.FLOAT_MAT3&&(o=3),r.type===i.FLOAT_MAT4&&(o=4),t[a]={type:r.type,location:i.getAttribLocation(e,a),locationSize:o}}return t}function _a(i){return i!==""}function Gd(i,e){const t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return i.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function Vd(i,e){return i.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}const Hy=/^[ \t]*#include +<([\w\d./]+)>/gm;function wh(i){return i.replace(Hy,Gy)}function Gy(i,e){const t=lt[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return wh(t)}const Vy=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function Wd(i){return i.replace(Vy,Wy)}function Wy(i,e,t,n){let s="";for(let r=parseInt(e);r<parseInt(t);r++)s+=n.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function Xd(i){let e=`precision ${i.precision} float;
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
#define LOW_PRECISION`),e}const Xy={[ko]:"SHADOWMAP_TYPE_PCF",[ga]:"SHADOWMAP_TYPE_VSM"};function $y(i){return Xy[i.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}const qy={[Da]:"ENVMAP_MODE_REFRACTION"};function Yy(i){return i.envMap===!1?"ENVMAP_MODE_REFLECTION":qy[i.envMapMode]||"ENVMAP_MODE_REFLECTION"}const Ky={[dp]:"ENVMAP_BLENDING_MULTIPLY",[N0]:"ENVMAP_BLENDING_MIX",[I0]:"ENVMAP_BLENDING_ADD"};function Zy(i){return i.envMap===!1?"ENVMAP_BLENDING_NONE":Ky[i.combine]||"ENVMAP_BLENDING_NONE"}function Jy(i,e,t,n){const s=i.getContext(),r=t.defines;let a=t.vertexShader,o=t.fragmentShader;const l=$y(t),c=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=Yy(t),u=Zy(t),d=ky(t),m=By(r),_=s.createProgram();let S,p,f=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(S=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(_a).join(`
`),S.length>0&&(S+=`
`),p=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(_a).join(`
`),p.length>0&&(p+=`
`)):(S=[Xd(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+h:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(_a).join(`
`),p=[Xd(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+c:"",t.envMap?"#define "+h:"",t.envMap?"#define "+u:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==cs?"#define TONE_MAPPING":"",t.toneMapping!==cs?lt.tonemapping_pars_fragment:"",t.toneMapping!==cs?Fy("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",lt.colorspace_pars_fragment,Iy("linearToOutputTexel",t.outputColorSpace),Oy(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(_a).join(`
`)),a=wh(a),a=Gd(a,t),a=Vd(a,t),o=wh(o),o=Gd(o,t),o=Vd(o,t),a=Wd(a),o=Wd(o),t.isRawShaderMaterial!==!0&&(f=`#version 300 es
`,S=[d,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+S,p=["#define varying in",t.glslVersion===Yu?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===Yu?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+p);const x=f+S+a,R=f+p+o,y=Bd(s,s.VERTEX_SHADER,x),A=Bd(s,s.FRAGMENT_SHADER,R);s.attachShader(_,y),s.attachShader(_,A),t.index0AttributeName!==void 0?s.bindAttribLocation(_,0,t.index0AttributeName):t.hasPositionAttribute===!0&&s.bindAttribLocation(_,0,"position"),s.linkProgram(_);function w(N){if(i.debug.checkShaderErrors){const P=s.getProgramInfoLog(_)||"",B=s.getShaderInfoLog(y)||"",V=s.getShaderInfoLog(A)||"",U=P.trim(),W=B.trim(),Z=V.trim();let H=!0,he=!0;if(s.getProgramParameter(_,s.LINK_STATUS)===!1)if(H=!1,typeof i.debug.onShaderError=="function")i.debug.onShaderError(s,_,y,A);else{const J=Hd(s,y,"vertex"),ee=Hd(s,A,"fragment");St("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(_,s.VALIDATE_STATUS)+`

Material Name: `+N.name+`
Material Type: `+N.type+`

Program Info Log: `+U+`
`+J+`
`+ee)}else U!==""?tt("WebGLProgram: Program Info Log:",U):(W===""||Z==="")&&(he=!1);he&&(N.diagnostics={runnable:H,programLog:U,vertexShader:{log:W,prefix:S},fragmentShader:{log:Z,prefix:p}})}s.deleteShader(y),s.deleteShader(A),g=new Wo(s,_),b=zy(s,_)}let g;this.getUniforms=function(){return g===void 0&&w(this),g};let b;this.getAttributes=function(){return b===void 0&&w(this),b};let I=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return I===!1&&(I=s.getProgramParameter(_,Py)),I},this.destroy=function(){n.releaseStatesOfProgram(this),s.deleteProgram(_),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=Ly++,this.cacheKey=e,this.usedTimes=1,this.program=_,this.vertexShader=y,this.fragmentShader=A,this}let jy=0;class Qy{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,n){const s=this._getShaderCacheForMaterial(e);return s.has(t)===!1&&(s.add(t),t.usedTimes++),s.has(n)===!1&&(s.add(n),n.usedTimes++),this}remove(e){const t=this.materialCache.get(e);for(const n of t)n.usedTimes--,n.usedTimes===0&&this.shaderCache.delete(n.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){const t=this.materialCache;let n=t.get(e);return n===void 0&&(n=new Set,t.set(e,n)),n}_getShaderStage(e){const t=this.shaderCache;let n=t.get(e);return n===void 0&&(n=new eM(e),t.set(e,n)),n}}class eM{constructor(e){this.id=jy++,this.code=e,this.usedTimes=0}}function tM(i){return i===Ks||i===qo||i===Yo}function nM(i,e,t,n,s,r){const a=new eu,o=new Qy,l=new Set,c=[],h=new Map,u=n.logarithmicDepthBuffer,d={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function m(g){return l.add(g),g===0?"uv":`uv${g}`}function _(g,b,I,N,P,B){const V=N.fog,U=P.geometry,W=g.isMeshStandardMaterial||g.isMeshLambertMaterial||g.isMeshPhongMaterial?N.environment:null,Z=g.isMeshStandardMaterial||g.isMeshLambertMaterial&&!g.envMap||g.isMeshPhongMaterial&&!g.envMap,H=e.get(g.envMap||W,Z),he=d[g.type];let J=n.precision;g.precision!==null&&(J=n.getMaxPrecision(g.precision),J!==g.precision&&tt("WebGLProgram.getParameters:",g.precision,"not supported, using",J,"instead."));const ee=U.morphAttributes.position||U.morphAttributes.normal||U.morphAttributes.color,se=ee!==void 0?ee.length:0;let pe=0;U.morphAttributes.position!==void 0&&(pe=1),U.morphAttributes.normal!==void 0&&(pe=2),U.morphAttributes.color!==void 0&&(pe=3);let fe,te,_e,xe;if(he){const De=Gi[he];fe=De.vertexShader,te=De.fragmentShader}else{fe=g.vertexShader,te=g.fragmentShader;const De=o.getVertexShaderStage(g),at=o.getFragmentShaderStage(g);o.update(g,De,at),_e=De.id,xe=at.id}const Pe=i.getRenderTarget(),Me=i.state.buffers.depth.getReversed(),q=P.isInstancedMesh===!0,oe=P.isBatchedMesh===!0,ve=!!g.map,Xe=!!g.matcap,Ze=!!H,je=Ze&&H.isPMREMTexture===!0,Ut=!!g.aoMap,At=!!g.lightMap,zt=!!g.bumpMap&&g.wireframe===!1,xt=!!g.normalMap,Jt=!!g.displacementMap,dt=!!g.emissiveMap,Rt=!!g.metalnessMap,Vt=!!g.roughnessMap,Kt=g.anisotropy>0,O=g.clearcoat>0,Le=g.diffuseRoughness>0,qe=g.dispersion>0,st=g.retroreflectivity>0,Te=g.iridescence>0,Ft=g.sheen>0,Ve=g.transmission>0,Ke=Kt&&!!g.anisotropyMap,C=O&&!!g.clearcoatMap,M=O&&!!g.clearcoatNormalMap,$=O&&!!g.clearcoatRoughnessMap,de=Le&&!!g.diffuseRoughnessMap,le=Te&&!!g.iridescenceMap,ye=Te&&!!g.iridescenceThicknessMap,be=Ft&&!!g.sheenColorMap,ne=Ft&&!!g.sheenRoughnessMap,re=!!g.specularMap,ge=!!g.specularColorMap,k=!!g.specularIntensityMap,ae=Ve&&!!g.transmissionMap,ie=Ve&&!!g.thicknessMap,Ae=!!g.gradientMap,Se=!!g.alphaMap,Ee=g.alphaTest>0,We=!!g.alphaHash,Qe=!!g.extensions;let ue=cs;g.toneMapped&&(Pe===null||Pe.isXRRenderTarget===!0)&&(ue=i.toneMapping);const ze=je?H.isCompressedCubeTexture?H.image[0].mipmaps:H.mipmaps:null,et={shaderID:he,shaderType:g.type,shaderName:g.name,vertexShader:fe,fragmentShader:te,defines:g.defines,customVertexShaderID:_e,customFragmentShaderID:xe,isRawShaderMaterial:g.isRawShaderMaterial===!0,glslVersion:g.glslVersion,precision:J,batching:oe,batchingColor:oe&&P._colorsTexture!==null,instancing:q,instancingColor:q&&P.instanceColor!==null,instancingMorph:q&&P.morphTexture!==null,outputColorSpace:Pe===null?i.outputColorSpace:Pe.isXRRenderTarget===!0?Pe.texture.colorSpace:vt.workingColorSpace,alphaToCoverage:!!g.alphaToCoverage,map:ve,matcap:Xe,envMap:Ze,envMapMode:Ze&&H.mapping,envMapPMREM:je,envMapMaxLod:je?ze.length-1:null,envMapSize:je?ze[0].width:null,aoMap:Ut,lightMap:At,bumpMap:zt,normalMap:xt,displacementMap:Jt,emissiveMap:dt,normalMapObjectSpace:xt&&g.normalMapType===O0,normalMapTangentSpace:xt&&g.normalMapType===xh,packedNormalMap:xt&&g.normalMapType===xh&&tM(g.normalMap.format),metalnessMap:Rt,roughnessMap:Vt,anisotropy:Kt,anisotropyMap:Ke,clearcoat:O,clearcoatMap:C,clearcoatNormalMap:M,clearcoatRoughnessMap:$,diffuseRoughness:Le,diffuseRoughnessMap:de,dispersion:qe,retroreflection:st,iridescence:Te,iridescenceMap:le,iridescenceThicknessMap:ye,sheen:Ft,sheenColorMap:be,sheenRoughnessMap:ne,specularMap:re,specularColorMap:ge,specularIntensityMap:k,transmission:Ve,transmissionMap:ae,thicknessMap:ie,gradientMap:Ae,opaque:g.transparent===!1&&g.blending===wa&&g.alphaToCoverage===!1,alphaMap:Se,alphaTest:Ee,alphaHash:We,combine:g.combine,mapUv:ve&&m(g.map.channel),aoMapUv:Ut&&m(g.aoMap.channel),lightMapUv:At&&m(g.lightMap.channel),bumpMapUv:zt&&m(g.bumpMap.channel),normalMapUv:xt&&m(g.normalMap.channel),displacementMapUv:Jt&&m(g.displacementMap.channel),emissiveMapUv:dt&&m(g.emissiveMap.channel),metalnessMapUv:Rt&&m(g.metalnessMap.channel),roughnessMapUv:Vt&&m(g.roughnessMap.channel),anisotropyMapUv:Ke&&m(g.anisotropyMap.channel),clearcoatMapUv:C&&m(g.clearcoatMap.channel),clearcoatNormalMapUv:M&&m(g.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:$&&m(g.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:de&&m(g.diffuseRoughnessMap.channel),iridescenceMapUv:le&&m(g.iridescenceMap.channel),iridescenceThicknessMapUv:ye&&m(g.iridescenceThicknessMap.channel),sheenColorMapUv:be&&m(g.sheenColorMap.channel),sheenRoughnessMapUv:ne&&m(g.sheenRoughnessMap.channel),specularMapUv:re&&m(g.specularMap.channel),specularColorMapUv:ge&&m(g.specularColorMap.channel),specularIntensityMapUv:k&&m(g.specularIntensityMap.channel),transmissionMapUv:ae&&m(g.transmissionMap.channel),thicknessMapUv:ie&&m(g.thicknessMap.channel),alphaMapUv:Se&&m(g.alphaMap.channel),vertexTangents:!!U.attributes.tangent&&(xt||Kt),vertexNormals:!!U.attributes.normal,vertexColors:g.vertexColors,vertexAlphas:g.vertexColors===!0&&!!U.attributes.color&&U.attributes.color.itemSize===4,pointsUvs:P.isPoints===!0&&!!U.attributes.uv&&(ve||Se),fog:!!V,useFog:g.fog===!0,fogExp2:!!V&&V.isFogExp2,flatShading:g.wireframe===!1&&(g.flatShading===!0||U.attributes.normal===void 0&&xt===!1&&(g.isMeshLambertMaterial||g.isMeshPhongMaterial||g.isMeshStandardMaterial||g.isMeshPhysicalMaterial)),sizeAttenuation:g.sizeAttenuation===!0,logarithmicDepthBuffer:u,reversedDepthBuffer:Me,skinning:P.isSkinnedMesh===!0,hasPositionAttribute:U.attributes.position!==void 0,morphTargets:U.morphAttributes.position!==void 0,morphNormals:U.morphAttributes.normal!==void 0,morphColors:U.morphAttributes.color!==void 0,morphTargetsCount:se,morphTextureStride:pe,numSunLights:b.sun.length,numDirLights:b.directional.length,numPointLights:b.point.length,numSpotLights:b.spot.length,numSpotLightMaps:b.spotLightMap.length,numRectAreaLights:b.rectArea.length,numHemiLights:b.hemi.length,numSunLightShadows:b.sunShadowMap.length,numDirLightShadows:b.directionalShadowMap.length,numPointLightShadows:b.pointShadowMap.length,numSpotLightShadows:b.spotShadowMap.length,numSpotLightShadowsWithMaps:b.numSpotLightShadowsWithMaps,numLightProbes:b.numLightProbes,numLightProbeGrids:B.filter(De=>De.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:g.dithering,shadowMapEnabled:i.shadowMap.enabled&&I.length>0,shadowMapType:i.shadowMap.type,toneMapping:ue,decodeVideoTexture:ve&&g.map.isVideoTexture===!0&&vt.getTransfer(g.map.colorSpace)===Dt,decodeVideoTextureEmissive:dt&&g.emissiveMap.isVideoTexture===!0&&vt.getTransfer(g.emissiveMap.colorSpace)===Dt,premultipliedAlpha:g.premultipliedAlpha,doubleSided:g.side===pi,flipSided:g.side===Kn,useDepthPacking:g.depthPacking>=0,depthPacking:g.depthPacking||0,index0AttributeName:g.index0AttributeName,extensionClipCullDistance:Qe&&g.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Qe&&g.extensions.multiDraw===!0||oe)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:g.customProgramCacheKey()};return et.vertexUv1s=l.has(1),et.vertexUv2s=l.has(2),et.vertexUv3s=l.has(3),l.clear(),et}function S(g){const b=[];if(g.shaderID?b.push(g.shaderID):(b.push(g.customVertexShaderID),b.push(g.customFragmentShaderID)),g.defines!==void 0)for(const I in g.defines)b.push(I),b.push(g.defines[I]);return g.isRawShaderMaterial===!1&&(p(b,g),f(b,g),b.push(i.outputColorSpace)),b.push(g.customProgramCacheKey),b.join()}function p(g,b){g.push(b.precision),g.push(b.outputColorSpace),g.push(b.envMapMode),g.push(b.envMapPMREM),g.push(b.envMapMaxLod),g.push(b.envMapSize),g.push(b.mapUv),g.push(b.alphaMapUv),g.push(b.lightMapUv),g.push(b.aoMapUv),g.push(b.bumpMapUv),g.push(b.normalMapUv),g.push(b.displacementMapUv),g.push(b.emissiveMapUv),g.push(b.metalnessMapUv),g.push(b.roughnessMapUv),g.push(b.anisotropyMapUv),g.push(b.clearcoatMapUv),g.push(b.clearcoatNormalMapUv),g.push(b.clearcoatRoughnessMapUv),g.push(b.diffuseRoughnessMapUv),g.push(b.iridescenceMapUv),g.push(b.iridescenceThicknessMapUv),g.push(b.sheenColorMapUv),g.push(b.sheenRoughnessMapUv),g.push(b.specularMapUv),g.push(b.specularColorMapUv),g.push(b.specularIntensityMapUv),g.push(b.transmissionMapUv),g.push(b.thicknessMapUv),g.push(b.combine),g.push(b.fogExp2),g.push(b.sizeAttenuation),g.push(b.morphTargetsCount),g.push(b.numSunLights),g.push(b.numDirLights),g.push(b.numPointLights),g.push(b.numSpotLights),g.push(b.numSpotLightMaps),g.push(b.numHemiLights),g.push(b.numRectAreaLights),g.push(b.numSunLightShadows),g.push(b.numDirLightShadows),g.push(b.numPointLightShadows),g.push(b.numSpotLightShadows),g.push(b.numSpotLightShadowsWithMaps),g.push(b.numLightProbes),g.push(b.numLightProbeGrids),g.push(b.shadowMapType),g.push(b.toneMapping),g.push(b.numClippingPlanes),g.push(b.numClipIntersection),g.push(b.depthPacking)}function f(g,b){a.disableAll(),b.instancing&&a.enable(0),b.instancingColor&&a.enable(1),b.instancingMorph&&a.enable(2),b.matcap&&a.enable(3),b.envMap&&a.enable(4),b.normalMapObjectSpace&&a.enable(5),b.normalMapTangentSpace&&a.enable(6),b.clearcoat&&a.enable(7),b.iridescence&&a.enable(8),b.alphaTest&&a.enable(9),b.vertexColors&&a.enable(10),b.vertexAlphas&&a.enable(11),b.vertexUv1s&&a.enable(12),b.vertexUv2s&&a.enable(13),b.vertexUv3s&&a.enable(14),b.vertexTangents&&a.enable(15),b.anisotropy&&a.enable(16),b.alphaHash&&a.enable(17),b.batching&&a.enable(18),b.dispersion&&a.enable(19),b.retroreflection&&a.enable(24),b.diffuseRoughness&&a.enable(25),b.batchingColor&&a.enable(20),b.gradientMap&&a.enable(21),b.packedNormalMap&&a.enable(22),b.vertexNormals&&a.enable(23),g.push(a.mask),a.disableAll(),b.fog&&a.enable(0),b.useFog&&a.enable(1),b.flatShading&&a.enable(2),b.logarithmicDepthBuffer&&a.enable(3),b.reversedDepthBuffer&&a.enable(4),b.skinning&&a.enable(5),b.morphTargets&&a.enable(6),b.morphNormals&&a.enable(7),b.morphColors&&a.enable(8),b.premultipliedAlpha&&a.enable(9),b.shadowMapEnabled&&a.enable(10),b.doubleSided&&a.enable(11),b.flipSided&&a.enable(12),b.useDepthPacking&&a.enable(13),b.dithering&&a.enable(14),b.transmission&&a.enable(15),b.sheen&&a.enable(16),b.opaque&&a.enable(17),b.pointsUvs&&a.enable(18),b.decodeVideoTexture&&a.enable(19),b.decodeVideoTextureEmissive&&a.enable(20),b.alphaToCoverage&&a.enable(21),b.numLightProbeGrids>0&&a.enable(22),b.hasPositionAttribute&&a.enable(23),g.push(a.mask)}function x(g){const b=d[g.type];let I;if(b){const N=Gi[b];I=b_.clone(N.uniforms)}else I=g.uniforms;return I}function R(g,b){let I=h.get(b);return I!==void 0?++I.usedTimes:(I=new Jy(i,b,g,s),c.push(I),h.set(b,I)),I}function y(g){if(--g.usedTimes===0){const b=c.indexOf(g);c[b]=c[c.length-1],c.pop(),h.delete(g.cacheKey),g.destroy()}}function A(g){o.remove(g)}function w(){o.dispose()}return{getParameters:_,getProgramCacheKey:S,getUniforms:x,acquireProgram:R,releaseProgram:y,releaseShaderCache:A,programs:c,dispose:w}}function iM(){let i=new WeakMap;function e(a){return i.has(a)}function t(a){let o=i.get(a);return o===void 0&&(o={},i.set(a,o)),o}function n(a){i.delete(a)}function s(a,o,l){i.get(a)[o]=l}function r(){i=new WeakMap}return{has:e,get:t,remove:n,update:s,dispose:r}}function sM(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.material.id!==e.material.id?i.material.id-e.material.id:i.materialVariant!==e.materialVariant?i.materialVariant-e.materialVariant:i.z!==e.z?i.z-e.z:i.id-e.id}function $d(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.z!==e.z?e.z-i.z:i.id-e.id}function qd(){const i=[];let e=0;const t=[],n=[],s=[];function r(){e=0,t.length=0,n.length=0,s.length=0}function a(d){let m=0;return d.isInstancedMesh&&(m+=2),d.isSkinnedMesh&&(m+=1),m}function o(d,m,_,S,p,f){let x=i[e];return x===void 0?(x={id:d.id,object:d,geometry:m,material:_,materialVariant:a(d),groupOrder:S,renderOrder:d.renderOrder,z:p,group:f},i[e]=x):(x.id=d.id,x.object=d,x.geometry=m,x.material=_,x.materialVariant=a(d),x.groupOrder=S,x.renderOrder=d.renderOrder,x.z=p,x.group=f),e++,x}function l(d,m,_,S,p,f,x){x.reversedDepth===!0&&(p=-p);const R=o(d,m,_,S,p,f);_.transmission>0?n.push(R):_.transparent===!0?s.push(R):t.push(R)}function c(d,m,_,S,p,f){const x=o(d,m,_,S,p,f);_.transmission>0?n.unshift(x):_.transparent===!0?s.unshift(x):t.unshift(x)}function h(d,m){t.length>1&&t.sort(d||sM),n.length>1&&n.sort(m||$d),s.length>1&&s.sort(m||$d)}function u(){for(let d=e,m=i.length;d<m;d++){const _=i[d];if(_.id===null)break;_.id=null,_.object=null,_.geometry=null,_.material=null,_.group=null}}return{opaque:t,transmissive:n,transparent:s,init:r,push:l,unshift:c,finish:u,sort:h}}function rM(){let i=new WeakMap;function e(n,s){const r=i.get(n);let a;return r===void 0?(a=new qd,i.set(n,[a])):s>=r.length?(a=new qd,r.push(a)):a=r[s],a}function t(){i=new WeakMap}return{get:e,dispose:t}}function aM(){const i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new z,color:new ct};break;case"SpotLight":t={position:new z,direction:new z,color:new ct,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new z,color:new ct,distance:0,decay:0};break;case"HemisphereLight":t={direction:new z,skyColor:new ct,groundColor:new ct};break;case"RectAreaLight":t={color:new ct,position:new z,halfWidth:new z,halfHeight:new z};break}return i[e.id]=t,t}}}function oM(){const i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ye};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ye};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ye,shadowCameraNear:1,shadowCameraFar:1e3};break}return i[e.id]=t,t}}}let lM=0;function cM(i,e){return(e.castShadow?2:0)-(i.castShadow?2:0)+(e.map?1:0)-(i.map?1:0)}function hM(i){const e=new aM,t=oM(),n={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let c=0;c<9;c++)n.probe.push(new z);const s=new z,r=new Nt,a=new Nt;function o(c){let h=0,u=0,d=0;for(let B=0;B<9;B++)n.probe[B].set(0,0,0);let m=0,_=0,S=0,p=0,f=0,x=0,R=0,y=0,A=0,w=0,g=0,b=0,I=0,N=0;c.sort(cM);for(let B=0,V=c.length;B<V;B++){const U=c[B],W=U.color,Z=U.intensity,H=U.distance;let he=null;if(U.shadow&&U.shadow.map&&(U.shadow.map.texture.format===Ks?he=U.shadow.map.texture:he=U.shadow.map.depthTexture||U.shadow.map.texture),U.isAmbientLight)h+=W.r*Z,u+=W.g*Z,d+=W.b*Z;else if(U.isLightProbe){for(let J=0;J<9;J++)n.probe[J].addScaledVector(U.sh.coefficients[J],Z);N++}else if(U.isSunLight){const J=e.get(U);if(J.color.copy(U.color).multiplyScalar(U.intensity),U.castShadow){const ee=U.shadow,se=t.get(U);se.shadowIntensity=ee.intensity,se.shadowBias=ee.bias,se.shadowNormalBias=ee.normalBias,se.shadowRadius=ee.radius,se.shadowMapSize.copy(ee.mapSize).multiply(ee.getFrameExtents()),n.sunShadow[_]=se,n.sunShadowMap[_]=he;const pe=ee.getViewportCount();for(let fe=0;fe<pe;fe++)n.sunShadowMatrix[S+fe]=ee.getMatrix(fe),n.sunShadowCascade[S+fe]=ee._cascadeData[fe];S+=pe,_++}n.sun[m]=J,m++}else if(U.isDirectionalLight){const J=e.get(U);if(J.color.copy(U.color).multiplyScalar(U.intensity),U.castShadow){const ee=U.shadow,se=t.get(U);se.shadowIntensity=ee.intensity,se.shadowBias=ee.bias,se.shadowNormalBias=ee.normalBias,se.shadowRadius=ee.radius,se.shadowMapSize=ee.mapSize,n.directionalShadow[p]=se,n.directionalShadowMap[p]=he,n.directionalShadowMatrix[p]=U.shadow.matrix,A++}n.directional[p]=J,p++}else if(U.isSpotLight){const J=e.get(U);J.position.setFromMatrixPosition(U.matrixWorld),J.color.copy(W).multiplyScalar(Z),J.distance=H,J.coneCos=Math.cos(U.angle),J.penumbraCos=Math.cos(U.angle*(1-U.penumbra)),J.decay=U.decay,n.spot[x]=J;const ee=U.shadow;if(U.map&&(n.spotLightMap[b]=U.map,b++,ee.updateMatrices(U),U.castShadow&&I++),n.spotLightMatrix[x]=ee.matrix,U.castShadow){const se=t.get(U);se.shadowIntensity=ee.intensity,se.shadowBias=ee.bias,se.shadowNormalBias=ee.normalBias,se.shadowRadius=ee.radius,se.shadowMapSize=ee.mapSize,n.spotShadow[x]=se,n.spotShadowMap[x]=he,g++}x++}else if(U.isRectAreaLight){const J=e.get(U);J.color.copy(W).multiplyScalar(Z),J.halfWidth.set(U.width*.5,0,0),J.halfHeight.set(0,U.height*.5,0),n.rectArea[R]=J,R++}else if(U.isPointLight){const J=e.get(U);if(J.color.copy(U.color).multiplyScalar(U.intensity),J.distance=U.distance,J.decay=U.decay,U.castShadow){const ee=U.shadow,se=t.get(U);se.shadowIntensity=ee.intensity,se.shadowBias=ee.bias,se.shadowNormalBias=ee.normalBias,se.shadowRadius=ee.radius,se.shadowMapSize=ee.mapSize,se.shadowCameraNear=ee.camera.near,se.shadowCameraFar=ee.camera.far,n.pointShadow[f]=se,n.pointShadowMap[f]=he,n.pointShadowMatrix[f]=U.shadow.matrix,w++}n.point[f]=J,f++}else if(U.isHemisphereLight){const J=e.get(U);J.skyColor.copy(U.color).multiplyScalar(Z),J.groundColor.copy(U.groundColor).multiplyScalar(Z),n.hemi[y]=J,y++}}R>0&&(i.has("OES_texture_float_linear")===!0?(n.rectAreaLTC1=Ue.LTC_FLOAT_1,n.rectAreaLTC2=Ue.LTC_FLOAT_2):(n.rectAreaLTC1=Ue.LTC_HALF_1,n.rectAreaLTC2=Ue.LTC_HALF_2)),n.ambient[0]=h,n.ambient[1]=u,n.ambient[2]=d;const P=n.hash;(P.sunLength!==m||P.directionalLength!==p||P.pointLength!==f||P.spotLength!==x||P.rectAreaLength!==R||P.hemiLength!==y||P.numSunShadows!==_||P.numDirectionalShadows!==A||P.numPointShadows!==w||P.numSpotShadows!==g||P.numSpotMaps!==b||P.numLightProbes!==N)&&(n.sun.length=m,n.directional.length=p,n.spot.length=x,n.rectArea.length=R,n.point.length=f,n.hemi.length=y,n.sunShadow.length=_,n.sunShadowMap.length=_,n.sunShadowMatrix.length=S,n.sunShadowCascade.length=S,n.directionalShadow.length=A,n.directionalShadowMap.length=A,n.directionalShadowMatrix.length=A,n.pointShadow.length=w,n.pointShadowMap.length=w,n.pointShadowMatrix.length=w,n.spotShadow.length=g,n.spotShadowMap.length=g,n.spotLightMatrix.length=g+b-I,n.spotLightMap.length=b,n.numSpotLightShadowsWithMaps=I,n.numLightProbes=N,P.sunLength=m,P.directionalLength=p,P.pointLength=f,P.spotLength=x,P.rectAreaLength=R,P.hemiLength=y,P.numSunShadows=_,P.numDirectionalShadows=A,P.numPointShadows=w,P.numSpotShadows=g,P.numSpotMaps=b,P.numLightProbes=N,n.version=lM++)}function l(c,h){let u=0,d=0,m=0,_=0,S=0,p=0;const f=h.matrixWorldInverse;for(let x=0,R=c.length;x<R;x++){const y=c[x];if(y.isSunLight){const A=n.sun[u];A.direction.setFromMatrixPosition(y.matrixWorld),A.direction.transformDirection(f),u++}else if(y.isDirectionalLight){const A=n.directional[d];A.direction.setFromMatrixPosition(y.matrixWorld),s.setFromMatrixPosition(y.target.matrixWorld),A.direction.sub(s),A.direction.transformDirection(f),d++}else if(y.isSpotLight){const A=n.spot[_];A.position.setFromMatrixPosition(y.matrixWorld),A.position.applyMatrix4(f),A.direction.setFromMatrixPosition(y.matrixWorld),s.setFromMatrixPosition(y.target.matrixWorld),A.direction.sub(s),A.direction.transformDirection(f),_++}else if(y.isRectAreaLight){const A=n.rectArea[S];A.position.setFromMatrixPosition(y.matrixWorld),A.position.applyMatrix4(f),a.identity(),r.copy(y.matrixWorld),r.premultiply(f),a.extractRotation(r),A.halfWidth.set(y.width*.5,0,0),A.halfHeight.set(0,y.height*.5,0),A.halfWidth.applyMatrix4(a),A.halfHeight.applyMatrix4(a),S++}else if(y.isPointLight){const A=n.point[m];A.position.setFromMatrixPosition(y.matrixWorld),A.position.applyMatrix4(f),m++}else if(y.isHemisphereLight){const A=n.hemi[p];A.direction.setFromMatrixPosition(y.matrixWorld),A.direction.transformDirection(f),p++}}}return{setup:o,setupView:l,state:n}}function Yd(i){const e=new hM(i),t=[],n=[],s=[];function r(u){h.camera=u,t.length=0,n.length=0,s.length=0}function a(u){u.isLightProbeGrid?s.push(u):t.push(u)}function o(u){n.push(u)}function l(){e.setup(t),s.sort((u,d)=>u.priority-d.priority||u.id-d.id)}function c(u){e.setupView(t,u)}const h={lightsArray:t,shadowsArray:n,lightProbeGridArray:s,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:h,setupLights:l,setupLightsView:c,pushLight:a,pushShadow:o}}function uM(i){let e=new WeakMap;function t(s,r=0){const a=e.get(s);let o;return a===void 0?(o=new Yd(i),e.set(s,[o])):r>=a.length?(o=new Yd(i),a.push(o)):o=a[r],o}function n(){e=new WeakMap}return{get:t,dispose:n}}const dM=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,fM=`uniform sampler2D shadow_pass;
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
}`,pM=[new z(1,0,0),new z(-1,0,0),new z(0,1,0),new z(0,-1,0),new z(0,0,1),new z(0,0,-1)],mM=[new z(0,-1,0),new z(0,-1,0),new z(0,0,1),new z(0,0,-1),new z(0,-1,0),new z(0,-1,0)],Kd=new Nt,fa=new z,fc=new z;function gM(i,e,t){let n=new Ua;const s=new Ye,r=new Ye,a=new an,o=new A_,l=new R_,c={},h=t.maxTextureSize,u={[Cs]:Kn,[Kn]:Cs,[pi]:pi},d=new Zs({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new Ye},radius:{value:4}},vertexShader:dM,fragmentShader:fM}),m=d.clone();m.defines.HORIZONTAL_PASS=1;const _=new Gt;_.setAttribute("position",new gi(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));const S=new on(_,d),p=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=ko;let f=this.type;this.render=function(w,g,b){if(p.enabled===!1||p.autoUpdate===!1&&p.needsUpdate===!1||w.length===0)return;this.type===p0&&(tt("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=ko);const I=i.getRenderTarget(),N=i.getActiveCubeFace(),P=i.getActiveMipmapLevel(),B=i.state;B.setBlending(Ur),B.buffers.depth.getReversed()===!0?B.buffers.color.setClear(0,0,0,0):B.buffers.color.setClear(1,1,1,1),B.buffers.depth.setTest(!0),B.setScissorTest(!1);const V=f!==this.type;V&&g.traverse(function(U){U.material&&(Array.isArray(U.material)?U.material.forEach(W=>W.needsUpdate=!0):U.material.needsUpdate=!0)});for(let U=0,W=w.length;U<W;U++){const Z=w[U],H=Z.shadow;if(H===void 0){tt("WebGLShadowMap:",Z,"has no shadow.");continue}if(H.autoUpdate===!1&&H.needsUpdate===!1)continue;s.copy(H.mapSize);const he=H.getFrameExtents();s.multiply(he),r.copy(H.mapSize),(s.x>h||s.y>h)&&(s.x>h&&(r.x=Math.floor(h/he.x),s.x=r.x*he.x,H.mapSize.x=r.x),s.y>h&&(r.y=Math.floor(h/he.y),s.y=r.y*he.y,H.mapSize.y=r.y));const J=i.state.buffers.depth.getReversed();if(H.camera._reversedDepth=J,H.map===null||V===!0){if(H.map!==null&&(H.map.depthTexture!==null&&(H.map.depthTexture.dispose(),H.map.depthTexture=null),H.map.dispose()),this.type===ga){if(Z.isPointLight){tt("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}H.map=new qi(s.x,s.y,{format:Ks,type:Ki,minFilter:Yn,magFilter:Yn,generateMipmaps:!1}),H.map.texture.name=Z.name+".shadowMap",H.map.depthTexture=new Hr(s.x,s.y,Vi),H.map.depthTexture.name=Z.name+".shadowMapDepth",H.map.depthTexture.format=Ps,H.map.depthTexture.compareFunction=null,H.map.depthTexture.minFilter=Ln,H.map.depthTexture.magFilter=Ln}else Z.isPointLight?(H.map=new iu(s.x),H.map.depthTexture=new Wp(s.x,Yi)):(H.map=new qi(s.x,s.y),H.map.depthTexture=new Hr(s.x,s.y,Yi)),H.map.depthTexture.name=Z.name+".shadowMap",H.map.depthTexture.format=Ps,this.type===ko?(H.map.depthTexture.compareFunction=J?Cp:Rp,H.map.depthTexture.minFilter=Yn,H.map.depthTexture.magFilter=Yn):(H.map.depthTexture.compareFunction=null,H.map.depthTexture.minFilter=Ln,H.map.depthTexture.magFilter=Ln);H.camera.updateProjectionMatrix()}H.map.isWebGLCubeRenderTarget!==!0&&(H.map.width!==s.x||H.map.height!==s.y)&&H.map.setSize(s.x,s.y);const ee=H.map.isWebGLCubeRenderTarget?6:H.getViewportCount();Z.isPointLight!==!0&&H.updateMatrices(Z,b);const se=(H.camera.layers.mask&4294967294)!==0?H.camera.layers:b.layers;for(let pe=0;pe<ee;pe++){const fe=H.getCamera(pe);if(Z.isPointLight){const te=H.camera,_e=H.matrix,xe=Z.distance||te.far;xe!==te.far&&(te.far=xe,te.updateProjectionMatrix()),fa.setFromMatrixPosition(Z.matrixWorld),te.position.copy(fa),fc.copy(te.position),fc.add(pM[pe]),te.up.copy(mM[pe]),te.lookAt(fc),te.updateMatrixWorld(),_e.makeTranslation(-fa.x,-fa.y,-fa.z),Kd.multiplyMatrices(te.projectionMatrix,te.matrixWorldInverse),H._frustum.setFromProjectionMatrix(Kd,te.coordinateSystem,te.reversedDepth)}if(H.map.isWebGLCubeRenderTarget)i.setRenderTarget(H.map,pe),i.clear();else{pe===0&&(i.setRenderTarget(H.map),i.clear());const te=H.getViewport(pe);a.set(r.x*te.x,r.y*te.y,r.x*te.z,r.y*te.w),B.viewport(a)}n=H.getFrustum(pe),y(g,b,fe,Z,se,this.type)}H.isPointLightShadow!==!0&&this.type===ga&&x(H,b),H.needsUpdate=!1}f=this.type,p.needsUpdate=!1,i.setRenderTarget(I,N,P)};function x(w,g){const b=e.update(S);d.defines.VSM_SAMPLES!==w.blurSamples&&(d.defines.VSM_SAMPLES=w.blurSamples,m.defines.VSM_SAMPLES=w.blurSamples,d.needsUpdate=!0,m.needsUpdate=!0),w.mapPass===null?w.mapPass=new qi(s.x,s.y,{format:Ks,type:Ki}):(w.mapPass.width!==w.map.width||w.mapPass.height!==w.map.height)&&w.mapPass.setSize(w.map.width,w.map.height),d.uniforms.shadow_pass.value=w.map.depthTexture,d.uniforms.resolution.value.set(w.map.width,w.map.height),d.uniforms.radius.value=w.radius,i.setRenderTarget(w.mapPass),i.clear(),i.renderBufferDirect(g,null,b,d,S,null),m.uniforms.shadow_pass.value=w.mapPass.texture,m.uniforms.resolution.value.set(w.map.width,w.map.height),m.uniforms.radius.value=w.radius,i.setRenderTarget(w.map),i.clear(),i.renderBufferDirect(g,null,b,m,S,null)}function R(w,g,b,I){let N=null;const P=b.isPointLight===!0?w.customDistanceMaterial:w.customDepthMaterial;if(P!==void 0)N=P;else if(N=b.isPointLight===!0?l:o,i.localClippingEnabled&&g.clipShadows===!0&&Array.isArray(g.clippingPlanes)&&g.clippingPlanes.length!==0||g.displacementMap&&g.displacementScale!==0||g.alphaMap&&g.alphaTest>0||g.map&&g.alphaTest>0||g.alphaToCoverage===!0){const B=N.uuid,V=g.uuid;let U=c[B];U===void 0&&(U={},c[B]=U);let W=U[V];W===void 0&&(W=N.clone(),U[V]=W,g.addEventListener("dispose",A)),N=W}if(N.visible=g.visible,N.wireframe=g.wireframe,I===ga?N.side=g.shadowSide!==null?g.shadowSide:g.side:N.side=g.shadowSide!==null?g.shadowSide:u[g.side],N.alphaMap=g.alphaMap,N.alphaTest=g.alphaToCoverage===!0?.5:g.alphaTest,N.map=g.map,N.clipShadows=g.clipShadows,N.clippingPlanes=g.clippingPlanes,N.clipIntersection=g.clipIntersection,N.displacementMap=g.displacementMap,N.displacementScale=g.displacementScale,N.displacementBias=g.displacementBias,N.wireframeLinewidth=g.wireframeLinewidth,N.linewidth=g.linewidth,b.isPointLight===!0&&N.isMeshDistanceMaterial===!0){const B=i.properties.get(N);B.light=b}return N}function y(w,g,b,I,N,P){if(w.visible===!1)return;if(w.layers.test(N)&&(w.isMesh||w.isLine||w.isPoints)&&(w.castShadow||w.receiveShadow&&P===ga)&&(!w.frustumCulled||w.intersectsFrustum(n))){w.modelViewMatrix.multiplyMatrices(b.matrixWorldInverse,w.matrixWorld);const U=e.update(w),W=w.material;if(Array.isArray(W)){const Z=U.groups;for(let H=0,he=Z.length;H<he;H++){const J=Z[H],ee=W[J.materialIndex];if(ee&&ee.visible){const se=R(w,ee,I,P);w.onBeforeShadow(i,w,g,b,U,se,J),i.renderBufferDirect(b,null,U,se,w,J),w.onAfterShadow(i,w,g,b,U,se,J)}}}else if(W.visible){const Z=R(w,W,I,P);w.onBeforeShadow(i,w,g,b,U,Z,null),i.renderBufferDirect(b,null,U,Z,w,null),w.onAfterShadow(i,w,g,b,U,Z,null)}}const V=w.children;for(let U=0,W=V.length;U<W;U++)y(V[U],g,b,I,N,P)}function A(w){w.target.removeEventListener("dispose",A);for(const b in c){const I=c[b],N=w.target.uuid;N in I&&(I[N].dispose(),delete I[N])}}}function _M(i,e){function t(){let k=!1;const ae=new an;let ie=null;const Ae=new an(0,0,0,0);return{setMask:function(Se){ie!==Se&&!k&&(i.colorMask(Se,Se,Se,Se),ie=Se)},setLocked:function(Se){k=Se},setClear:function(Se,Ee,We,Qe,ue){ue===!0&&(Se*=Qe,Ee*=Qe,We*=Qe),ae.set(Se,Ee,We,Qe),Ae.equals(ae)===!1&&(i.clearColor(Se,Ee,We,Qe),Ae.copy(ae))},reset:function(){k=!1,ie=null,Ae.set(-1,0,0,0)}}}function n(){let k=!1,ae=!1,ie=null,Ae=null,Se=null;return{setReversed:function(Ee){if(ae!==Ee){const We=e.get("EXT_clip_control");Ee?We.clipControlEXT(We.LOWER_LEFT_EXT,We.ZERO_TO_ONE_EXT):We.clipControlEXT(We.LOWER_LEFT_EXT,We.NEGATIVE_ONE_TO_ONE_EXT),ae=Ee;const Qe=Se;Se=null,this.setClear(Qe)}},getReversed:function(){return ae},setTest:function(Ee){Ee?Me(i.DEPTH_TEST):q(i.DEPTH_TEST)},setMask:function(Ee){ie!==Ee&&!k&&(i.depthMask(Ee),ie=Ee)},setFunc:function(Ee){if(ae&&(Ee=q0[Ee]),Ae!==Ee){switch(Ee){case Ic:i.depthFunc(i.NEVER);break;case Uc:i.depthFunc(i.ALWAYS);break;case Fc:i.depthFunc(i.LESS);break;case La:i.depthFunc(i.LEQUAL);break;case Oc:i.depthFunc(i.EQUAL);break;case kc:i.depthFunc(i.GEQUAL);break;case Bc:i.depthFunc(i.GREATER);break;case zc:i.depthFunc(i.NOTEQUAL);break;default:i.depthFunc(i.LEQUAL)}Ae=Ee}},setLocked:function(Ee){k=Ee},setClear:function(Ee){Se!==Ee&&(Se=Ee,ae&&(Ee=1-Ee),i.clearDepth(Ee))},reset:function(){k=!1,ie=null,Ae=null,Se=null,ae=!1}}}function s(){let k=!1,ae=null,ie=null,Ae=null,Se=null,Ee=null,We=null,Qe=null,ue=null;return{setTest:function(ze){k||(ze?Me(i.STENCIL_TEST):q(i.STENCIL_TEST))},setMask:function(ze){ae!==ze&&!k&&(i.stencilMask(ze),ae=ze)},setFunc:function(ze,et,De){(ie!==ze||Ae!==et||Se!==De)&&(i.stencilFunc(ze,et,De),ie=ze,Ae=et,Se=De)},setOp:function(ze,et,De){(Ee!==ze||We!==et||Qe!==De)&&(i.stencilOp(ze,et,De),Ee=ze,We=et,Qe=De)},setLocked:function(ze){k=ze},setClear:function(ze){ue!==ze&&(i.clearStencil(ze),ue=ze)},reset:function(){k=!1,ae=null,ie=null,Ae=null,Se=null,Ee=null,We=null,Qe=null,ue=null}}}const r=new t,a=new n,o=new s;let l={};const c=new WeakMap;let h={},u={},d={},m=new WeakMap,_=[],S=null,p=!1,f=null,x=null,R=null,y=null,A=null,w=null,g=null,b=new ct(0,0,0),I=0,N=!1,P=null,B=null,V=null,U=null,W=null;const Z=i.getParameter(i.MAX_COMBINED_TEXTURE_IMAGE_UNITS);let H=!1,he=0;const J=i.getParameter(i.VERSION);J.indexOf("WebGL")!==-1?(he=parseFloat(/^WebGL (\d)/.exec(J)[1]),H=he>=1):J.indexOf("OpenGL ES")!==-1&&(he=parseFloat(/^OpenGL ES (\d)/.exec(J)[1]),H=he>=2);let ee=null,se={};const pe=i.getParameter(i.SCISSOR_BOX),fe=i.getParameter(i.VIEWPORT),te=new an().fromArray(pe),_e=new an().fromArray(fe);function xe(k,ae,ie,Ae){const Se=new Uint8Array(4),Ee=i.createTexture();i.bindTexture(k,Ee),i.texParameteri(k,i.TEXTURE_MIN_FILTER,i.NEAREST),i.texParameteri(k,i.TEXTURE_MAG_FILTER,i.NEAREST);for(let We=0;We<ie;We++)k===i.TEXTURE_3D||k===i.TEXTURE_2D_ARRAY?i.texImage3D(ae,0,i.RGBA,1,1,Ae,0,i.RGBA,i.UNSIGNED_BYTE,Se):i.texImage2D(ae+We,0,i.RGBA,1,1,0,i.RGBA,i.UNSIGNED_BYTE,Se);return Ee}const Pe={};Pe[i.TEXTURE_2D]=xe(i.TEXTURE_2D,i.TEXTURE_2D,1),Pe[i.TEXTURE_CUBE_MAP]=xe(i.TEXTURE_CUBE_MAP,i.TEXTURE_CUBE_MAP_POSITIVE_X,6),Pe[i.TEXTURE_2D_ARRAY]=xe(i.TEXTURE_2D_ARRAY,i.TEXTURE_2D_ARRAY,1,1),Pe[i.TEXTURE_3D]=xe(i.TEXTURE_3D,i.TEXTURE_3D,1,1),r.setClear(0,0,0,1),a.setClear(1),o.setClear(0),Me(i.DEPTH_TEST),a.setFunc(La),zt(!1),xt(Wu),Me(i.CULL_FACE),Ut(Ur);function Me(k){h[k]!==!0&&(i.enable(k),h[k]=!0)}function q(k){h[k]!==!1&&(i.disable(k),h[k]=!1)}function oe(k,ae){return d[k]!==ae?(i.bindFramebuffer(k,ae),d[k]=ae,k===i.DRAW_FRAMEBUFFER&&(d[i.FRAMEBUFFER]=ae),k===i.FRAMEBUFFER&&(d[i.DRAW_FRAMEBUFFER]=ae),!0):!1}function ve(k,ae){let ie=_,Ae=!1;if(k){ie=m.get(ae),ie===void 0&&(ie=[],m.set(ae,ie));const Se=k.textures;if(ie.length!==Se.length||ie[0]!==i.COLOR_ATTACHMENT0){for(let Ee=0,We=Se.length;Ee<We;Ee++)ie[Ee]=i.COLOR_ATTACHMENT0+Ee;ie.length=Se.length,Ae=!0}}else ie[0]!==i.BACK&&(ie[0]=i.BACK,Ae=!0);Ae&&i.drawBuffers(ie)}function Xe(k){return S!==k?(i.useProgram(k),S=k,!0):!1}const Ze={[Lr]:i.FUNC_ADD,[g0]:i.FUNC_SUBTRACT,[_0]:i.FUNC_REVERSE_SUBTRACT};Ze[v0]=i.MIN,Ze[x0]=i.MAX;const je={[S0]:i.ZERO,[y0]:i.ONE,[M0]:i.SRC_COLOR,[hp]:i.SRC_ALPHA,[R0]:i.SRC_ALPHA_SATURATE,[T0]:i.DST_COLOR,[w0]:i.DST_ALPHA,[b0]:i.ONE_MINUS_SRC_COLOR,[up]:i.ONE_MINUS_SRC_ALPHA,[A0]:i.ONE_MINUS_DST_COLOR,[E0]:i.ONE_MINUS_DST_ALPHA,[C0]:i.CONSTANT_COLOR,[P0]:i.ONE_MINUS_CONSTANT_COLOR,[L0]:i.CONSTANT_ALPHA,[D0]:i.ONE_MINUS_CONSTANT_ALPHA};function Ut(k,ae,ie,Ae,Se,Ee,We,Qe,ue,ze){if(k===Ur){p===!0&&(q(i.BLEND),p=!1);return}if(p===!1&&(Me(i.BLEND),p=!0),k!==m0){if(k!==f||ze!==N){if((x!==Lr||A!==Lr)&&(i.blendEquation(i.FUNC_ADD),x=Lr,A=Lr),ze)switch(k){case wa:i.blendFuncSeparate(i.ONE,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Xu:i.blendFunc(i.ONE,i.ONE);break;case $u:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case qu:i.blendFuncSeparate(i.DST_COLOR,i.ONE_MINUS_SRC_ALPHA,i.ZERO,i.ONE);break;default:St("WebGLState: Invalid blending: ",k);break}else switch(k){case wa:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Xu:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE,i.ONE,i.ONE);break;case $u:St("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case qu:St("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:St("WebGLState: Invalid blending: ",k);break}R=null,y=null,w=null,g=null,b.set(0,0,0),I=0,f=k,N=ze}return}Se=Se||ae,Ee=Ee||ie,We=We||Ae,(ae!==x||Se!==A)&&(i.blendEquationSeparate(Ze[ae],Ze[Se]),x=ae,A=Se),(ie!==R||Ae!==y||Ee!==w||We!==g)&&(i.blendFuncSeparate(je[ie],je[Ae],je[Ee],je[We]),R=ie,y=Ae,w=Ee,g=We),(Qe.equals(b)===!1||ue!==I)&&(i.blendColor(Qe.r,Qe.g,Qe.b,ue),b.copy(Qe),I=ue),f=k,N=!1}function At(k,ae){k.side===pi?q(i.CULL_FACE):Me(i.CULL_FACE);let ie=k.side===Kn;ae&&(ie=!ie),zt(ie),k.blending===wa&&k.transparent===!1?Ut(Ur):Ut(k.blending,k.blendEquation,k.blendSrc,k.blendDst,k.blendEquationAlpha,k.blendSrcAlpha,k.blendDstAlpha,k.blendColor,k.blendAlpha,k.premultipliedAlpha),a.setFunc(k.depthFunc),a.setTest(k.depthTest),a.setMask(k.depthWrite),r.setMask(k.colorWrite);const Ae=k.stencilWrite;o.setTest(Ae),Ae&&(o.setMask(k.stencilWriteMask),o.setFunc(k.stencilFunc,k.stencilRef,k.stencilFuncMask),o.setOp(k.stencilFail,k.stencilZFail,k.stencilZPass)),dt(k.polygonOffset,k.polygonOffsetFactor,k.polygonOffsetUnits),k.alphaToCoverage===!0?Me(i.SAMPLE_ALPHA_TO_COVERAGE):q(i.SAMPLE_ALPHA_TO_COVERAGE)}function zt(k){P!==k&&(k?i.frontFace(i.CW):i.frontFace(i.CCW),P=k)}function xt(k){k!==d0?(Me(i.CULL_FACE),k!==B&&(k===Wu?i.cullFace(i.BACK):k===f0?i.cullFace(i.FRONT):i.cullFace(i.FRONT_AND_BACK))):q(i.CULL_FACE),B=k}function Jt(k){k!==V&&(H&&i.lineWidth(k),V=k)}function dt(k,ae,ie){k?(Me(i.POLYGON_OFFSET_FILL),(U!==ae||W!==ie)&&(U=ae,W=ie,a.getReversed()&&(ae=-ae,ie=-ie),i.polygonOffset(ae,ie))):q(i.POLYGON_OFFSET_FILL)}function Rt(k){k?Me(i.SCISSOR_TEST):q(i.SCISSOR_TEST)}function Vt(k){k===void 0&&(k=i.TEXTURE0+Z-1),ee!==k&&(i.activeTexture(k),ee=k)}function Kt(k,ae,ie){ie===void 0&&(ee===null?ie=i.TEXTURE0+Z-1:ie=ee);let Ae=se[ie];Ae===void 0&&(Ae={type:void 0,texture:void 0},se[ie]=Ae),(Ae.type!==k||Ae.texture!==ae)&&(ee!==ie&&(i.activeTexture(ie),ee=ie),i.bindTexture(k,ae||Pe[k]),Ae.type=k,Ae.texture=ae)}function O(){const k=se[ee];k!==void 0&&k.type!==void 0&&(i.bindTexture(k.type,null),k.type=void 0,k.texture=void 0)}function Le(){try{i.compressedTexImage2D(...arguments)}catch(k){St("WebGLState:",k)}}function qe(){try{i.compressedTexImage3D(...arguments)}catch(k){St("WebGLState:",k)}}function st(){try{i.texSubImage2D(...arguments)}catch(k){St("WebGLState:",k)}}function Te(){try{i.texSubImage3D(...arguments)}catch(k){St("WebGLState:",k)}}function Ft(){try{i.compressedTexSubImage2D(...arguments)}catch(k){St("WebGLState:",k)}}function Ve(){try{i.compressedTexSubImage3D(...arguments)}catch(k){St("WebGLState:",k)}}function Ke(){try{i.texStorage2D(...arguments)}catch(k){St("WebGLState:",k)}}function C(){try{i.texStorage3D(...arguments)}catch(k){St("WebGLState:",k)}}function M(){try{i.texImage2D(...arguments)}catch(k){St("WebGLState:",k)}}function $(){try{i.texImage3D(...arguments)}catch(k){St("WebGLState:",k)}}function de(k){return u[k]!==void 0?u[k]:i.getParameter(k)}function le(k,ae){u[k]!==ae&&(i.pixelStorei(k,ae),u[k]=ae)}function ye(k){te.equals(k)===!1&&(i.scissor(k.x,k.y,k.z,k.w),te.copy(k))}function be(k){_e.equals(k)===!1&&(i.viewport(k.x,k.y,k.z,k.w),_e.copy(k))}function ne(k,ae){let ie=c.get(ae);ie===void 0&&(ie=new WeakMap,c.set(ae,ie));let Ae=ie.get(k);Ae===void 0&&(Ae=i.getUniformBlockIndex(ae,k.name),i.uniformBlockBinding(ae,Ae,Ae),ie.set(k,Ae))}function re(k,ae,ie){const Se=c.get(ae).get(k);l[Se]!==ie&&(i.bindBufferBase(i.UNIFORM_BUFFER,Se,ie),l[Se]=ie)}function ge(){i.disable(i.BLEND),i.disable(i.CULL_FACE),i.disable(i.DEPTH_TEST),i.disable(i.POLYGON_OFFSET_FILL),i.disable(i.SCISSOR_TEST),i.disable(i.STENCIL_TEST),i.disable(i.SAMPLE_ALPHA_TO_COVERAGE),i.blendEquation(i.FUNC_ADD),i.blendFunc(i.ONE,i.ZERO),i.blendFuncSeparate(i.ONE,i.ZERO,i.ONE,i.ZERO),i.blendColor(0,0,0,0),i.colorMask(!0,!0,!0,!0),i.clearColor(0,0,0,0),i.depthMask(!0),i.depthFunc(i.LESS),a.setReversed(!1),i.clearDepth(1),i.stencilMask(4294967295),i.stencilFunc(i.ALWAYS,0,4294967295),i.stencilOp(i.KEEP,i.KEEP,i.KEEP),i.clearStencil(0),i.cullFace(i.BACK),i.frontFace(i.CCW),i.polygonOffset(0,0),i.activeTexture(i.TEXTURE0),i.bindFramebuffer(i.FRAMEBUFFER,null),i.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),i.bindFramebuffer(i.READ_FRAMEBUFFER,null),i.useProgram(null),i.lineWidth(1),i.scissor(0,0,i.canvas.width,i.canvas.height),i.viewport(0,0,i.canvas.width,i.canvas.height),i.pixelStorei(i.PACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,!1),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,i.BROWSER_DEFAULT_WEBGL),i.pixelStorei(i.PACK_ROW_LENGTH,0),i.pixelStorei(i.PACK_SKIP_PIXELS,0),i.pixelStorei(i.PACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_ROW_LENGTH,0),i.pixelStorei(i.UNPACK_IMAGE_HEIGHT,0),i.pixelStorei(i.UNPACK_SKIP_PIXELS,0),i.pixelStorei(i.UNPACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_SKIP_IMAGES,0),h={},u={},ee=null,se={},d={},l={},m=new WeakMap,_=[],S=null,p=!1,f=null,x=null,R=null,y=null,A=null,w=null,g=null,b=new ct(0,0,0),I=0,N=!1,P=null,B=null,V=null,U=null,W=null,te.set(0,0,i.canvas.width,i.canvas.height),_e.set(0,0,i.canvas.width,i.canvas.height),r.reset(),a.reset(),o.reset()}return{buffers:{color:r,depth:a,stencil:o},enable:Me,disable:q,bindFramebuffer:oe,drawBuffers:ve,useProgram:Xe,setBlending:Ut,setMaterial:At,setFlipSided:zt,setCullFace:xt,setLineWidth:Jt,setPolygonOffset:dt,setScissorTest:Rt,activeTexture:Vt,bindTexture:Kt,unbindTexture:O,compressedTexImage2D:Le,compressedTexImage3D:qe,texImage2D:M,texImage3D:$,pixelStorei:le,getParameter:de,updateUBOMapping:ne,uniformBlockBinding:re,texStorage2D:Ke,texStorage3D:C,texSubImage2D:st,texSubImage3D:Te,compressedTexSubImage2D:Ft,compressedTexSubImage3D:Ve,scissor:ye,viewport:be,reset:ge}}function vM(i,e,t,n,s,r,a){const o=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),c=new Ye,h=new WeakMap,u=new Set;let d;const m=new WeakMap,_=new Set,S=new FinalizationRegistry(C=>_.delete(C));let p=!1;try{p=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function f(C,M){return p?new OffscreenCanvas(C,M):Jo("canvas")}function x(C,M,$){let de=1;const le=Ke(C);if((le.width>$||le.height>$)&&(de=$/Math.max(le.width,le.height)),de<1)if(typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&C instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&C instanceof ImageBitmap||typeof VideoFrame<"u"&&C instanceof VideoFrame){const ye=Math.floor(de*le.width),be=Math.floor(de*le.height);d===void 0&&(d=f(ye,be));const ne=M?f(ye,be):d;return ne.width=ye,ne.height=be,ne.getContext("2d").drawImage(C,0,0,ye,be),tt("WebGLRenderer: Texture has been resized from ("+le.width+"x"+le.height+") to ("+ye+"x"+be+")."),ne}else return"data"in C&&tt("WebGLRenderer: Image in DataTexture is too big ("+le.width+"x"+le.height+")."),C;return C}function R(C){return C.generateMipmaps}function y(C){i.generateMipmap(C)}function A(C){return C.isWebGLCubeRenderTarget?i.TEXTURE_CUBE_MAP:C.isWebGL3DRenderTarget?i.TEXTURE_3D:C.isWebGLArrayRenderTarget||C.isCompressedArrayTexture?i.TEXTURE_2D_ARRAY:i.TEXTURE_2D}function w(C,M,$,de,le,ye=!1){if(C!==null){if(i[C]!==void 0)return i[C];tt("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+C+"'")}let be;de&&(be=e.get("EXT_texture_norm16"),be||tt("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let ne=M;if(M===i.RED&&($===i.FLOAT&&(ne=i.R32F),$===i.HALF_FLOAT&&(ne=i.R16F),$===i.UNSIGNED_BYTE&&(ne=i.R8),$===i.UNSIGNED_SHORT&&be&&(ne=be.R16_EXT),$===i.SHORT&&be&&(ne=be.R16_SNORM_EXT)),M===i.RED_INTEGER&&($===i.UNSIGNED_BYTE&&(ne=i.R8UI),$===i.UNSIGNED_SHORT&&(ne=i.R16UI),$===i.UNSIGNED_INT&&(ne=i.R32UI),$===i.BYTE&&(ne=i.R8I),$===i.SHORT&&(ne=i.R16I),$===i.INT&&(ne=i.R32I)),M===i.RG&&($===i.FLOAT&&(ne=i.RG32F),$===i.HALF_FLOAT&&(ne=i.RG16F),$===i.UNSIGNED_BYTE&&(ne=i.RG8),$===i.UNSIGNED_SHORT&&be&&(ne=be.RG16_EXT),$===i.SHORT&&be&&(ne=be.RG16_SNORM_EXT)),M===i.RG_INTEGER&&($===i.UNSIGNED_BYTE&&(ne=i.RG8UI),$===i.UNSIGNED_SHORT&&(ne=i.RG16UI),$===i.UNSIGNED_INT&&(ne=i.RG32UI),$===i.BYTE&&(ne=i.RG8I),$===i.SHORT&&(ne=i.RG16I),$===i.INT&&(ne=i.RG32I)),M===i.RGB_INTEGER&&($===i.UNSIGNED_BYTE&&(ne=i.RGB8UI),$===i.UNSIGNED_SHORT&&(ne=i.RGB16UI),$===i.UNSIGNED_INT&&(ne=i.RGB32UI),$===i.BYTE&&(ne=i.RGB8I),$===i.SHORT&&(ne=i.RGB16I),$===i.INT&&(ne=i.RGB32I)),M===i.RGBA_INTEGER&&($===i.UNSIGNED_BYTE&&(ne=i.RGBA8UI),$===i.UNSIGNED_SHORT&&(ne=i.RGBA16UI),$===i.UNSIGNED_INT&&(ne=i.RGBA32UI),$===i.BYTE&&(ne=i.RGBA8I),$===i.SHORT&&(ne=i.RGBA16I),$===i.INT&&(ne=i.RGBA32I)),M===i.RGB&&($===i.UNSIGNED_SHORT&&be&&(ne=be.RGB16_EXT),$===i.SHORT&&be&&(ne=be.RGB16_SNORM_EXT),$===i.UNSIGNED_INT_5_9_9_9_REV&&(ne=i.RGB9_E5),$===i.UNSIGNED_INT_10F_11F_11F_REV&&(ne=i.R11F_G11F_B10F)),M===i.RGBA){const re=ye?Zo:vt.getTransfer(le);$===i.FLOAT&&(ne=i.RGBA32F),$===i.HALF_FLOAT&&(ne=i.RGBA16F),$===i.UNSIGNED_BYTE&&(ne=re===Dt?i.SRGB8_ALPHA8:i.RGBA8),$===i.UNSIGNED_SHORT&&be&&(ne=be.RGBA16_EXT),$===i.SHORT&&be&&(ne=be.RGBA16_SNORM_EXT),$===i.UNSIGNED_SHORT_4_4_4_4&&(ne=i.RGBA4),$===i.UNSIGNED_SHORT_5_5_5_1&&(ne=i.RGB5_A1)}return(ne===i.R16F||ne===i.R32F||ne===i.RG16F||ne===i.RG32F||ne===i.RGBA16F||ne===i.RGBA32F)&&e.get("EXT_color_buffer_float"),ne}function g(C,M){let $;return C?M===null||M===Yi||M===zr?$=i.DEPTH24_STENCIL8:M===Vi?$=i.DEPTH32F_STENCIL8:M===Na&&($=i.DEPTH24_STENCIL8,tt("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):M===null||M===Yi||M===zr?$=i.DEPTH_COMPONENT24:M===Vi?$=i.DEPTH_COMPONENT32F:M===Na&&($=i.DEPTH_COMPONENT16),$}function b(C,M){return R(C)===!0||C.isFramebufferTexture&&C.minFilter!==Ln&&C.minFilter!==Yn?Math.log2(Math.max(M.width,M.height))+1:C.mipmaps.length>0?C.mipmaps.length:C.isCompressedTexture&&Array.isArray(C.image)?M.mipmaps.length:1}function I(C){const M=new WeakRef(C);n.get(C).__ref=M,_.add(M),S.register(C,M,M)}function N(C){const M=n.get(C).__ref;M!==void 0&&(_.delete(M),S.unregister(M))}function P(C){V(C.target)}function B(C){U(C.target)}function V(C){C.removeEventListener("dispose",P),N(C),Z(C),C.isVideoTexture&&h.delete(C),C.isHTMLTexture&&u.delete(C)}function U(C){C.removeEventListener("dispose",B),N(C),he(C)}function W(){for(const C of _){const M=C.deref();M!==void 0&&(M.isRenderTarget===!0?U(M):V(M))}_.clear(),u.clear()}function Z(C){const M=n.get(C);if(M.__webglInit===void 0)return;const $=C.source,de=m.get($);if(de){const le=de[M.__cacheKey];le.usedTimes--,le.usedTimes===0&&H(C),Object.keys(de).length===0&&m.delete($)}n.remove(C)}function H(C){const M=n.get(C);i.deleteTexture(M.__webglTexture);const $=C.source,de=m.get($);delete de[M.__cacheKey],a.memory.textures--}function he(C){const M=n.get(C);M.__depthDisposeCallback&&M.__depthDisposeCallback();const $=C.depthTexture;if($&&$.renderTarget===C&&V($),C.isWebGLCubeRenderTarget)for(let le=0;le<6;le++){if(Array.isArray(M.__webglFramebuffer[le]))for(let ye=0;ye<M.__webglFramebuffer[le].length;ye++)i.deleteFramebuffer(M.__webglFramebuffer[le][ye]);else i.deleteFramebuffer(M.__webglFramebuffer[le]);M.__webglDepthbuffer&&i.deleteRenderbuffer(M.__webglDepthbuffer[le])}else{if(Array.isArray(M.__webglFramebuffer))for(let le=0;le<M.__webglFramebuffer.length;le++)i.deleteFramebuffer(M.__webglFramebuffer[le]);else i.deleteFramebuffer(M.__webglFramebuffer);if(M.__webglDepthbuffer&&i.deleteRenderbuffer(M.__webglDepthbuffer),M.__webglMultisampledFramebuffer&&i.deleteFramebuffer(M.__webglMultisampledFramebuffer),M.__webglColorRenderbuffer)for(let le=0;le<M.__webglColorRenderbuffer.length;le++)M.__webglColorRenderbuffer[le]&&i.deleteRenderbuffer(M.__webglColorRenderbuffer[le]);M.__webglDepthRenderbuffer&&i.deleteRenderbuffer(M.__webglDepthRenderbuffer)}const de=C.textures;for(let le=0,ye=de.length;le<ye;le++){const be=n.get(de[le]);be.__webglTexture&&(i.deleteTexture(be.__webglTexture),a.memory.textures--),n.remove(de[le])}n.remove(C)}let J=0;function ee(){J=0}function se(){return J}function pe(C){J=C}function fe(){const C=J;return C>=s.maxTextures&&tt("WebGLTextures: Trying to use "+(C+1)+" texture units while this GPU supports only "+s.maxTextures),J+=1,C}function te(C){const M=[];return M.push(C.wrapS),M.push(C.wrapT),M.push(C.wrapR||0),M.push(C.magFilter),M.push(C.minFilter),M.push(C.anisotropy),M.push(C.internalFormat),M.push(C.format),M.push(C.type),M.push(C.generateMipmaps),M.push(C.mipmapsAutoUpdate),M.push(C.premultiplyAlpha),M.push(C.flipY),M.push(C.unpackAlignment),M.push(C.colorSpace),M.join()}function _e(C,M){const $=n.get(C);if(C.isVideoTexture&&Ft(C),C.isRenderTargetTexture===!1&&C.isExternalTexture!==!0&&C.version>0&&$.__version!==C.version){const de=C.image;if(de===null)tt("WebGLRenderer: Texture marked for update but no image data found.");else if(de.complete===!1)tt("WebGLRenderer: Texture marked for update but image is incomplete");else{At($,C,M);return}}else C.isExternalTexture&&($.__webglTexture=C.sourceTexture?C.sourceTexture:null);t.bindTexture(i.TEXTURE_2D,$.__webglTexture,i.TEXTURE0+M)}function xe(C,M){const $=n.get(C);if(C.isRenderTargetTexture===!1&&C.version>0&&$.__version!==C.version){At($,C,M);return}else C.isExternalTexture&&($.__webglTexture=C.sourceTexture?C.sourceTexture:null);t.bindTexture(i.TEXTURE_2D_ARRAY,$.__webglTexture,i.TEXTURE0+M)}function Pe(C,M){const $=n.get(C);if(C.isRenderTargetTexture===!1&&C.version>0&&$.__version!==C.version){At($,C,M);return}t.bindTexture(i.TEXTURE_3D,$.__webglTexture,i.TEXTURE0+M)}function Me(C,M){const $=n.get(C);if(C.version>0&&$.__version!==C.version){zt($,C,M);return}t.bindTexture(i.TEXTURE_CUBE_MAP,$.__webglTexture,i.TEXTURE0+M)}const q={[Hc]:i.REPEAT,[os]:i.CLAMP_TO_EDGE,[Gc]:i.MIRRORED_REPEAT},oe={[Ln]:i.NEAREST,[U0]:i.NEAREST_MIPMAP_NEAREST,[ja]:i.NEAREST_MIPMAP_LINEAR,[Yn]:i.LINEAR,[Bl]:i.LINEAR_MIPMAP_NEAREST,[Ts]:i.LINEAR_MIPMAP_LINEAR},ve={[B0]:i.NEVER,[Pp]:i.ALWAYS,[z0]:i.LESS,[Rp]:i.LEQUAL,[H0]:i.EQUAL,[Cp]:i.GEQUAL,[G0]:i.GREATER,[V0]:i.NOTEQUAL};function Xe(C,M){if(M.type===Vi&&e.has("OES_texture_float_linear")===!1&&(M.magFilter===Yn||M.magFilter===Bl||M.magFilter===ja||M.magFilter===Ts||M.minFilter===Yn||M.minFilter===Bl||M.minFilter===ja||M.minFilter===Ts)&&tt("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),i.texParameteri(C,i.TEXTURE_WRAP_S,q[M.wrapS]),i.texParameteri(C,i.TEXTURE_WRAP_T,q[M.wrapT]),(C===i.TEXTURE_3D||C===i.TEXTURE_2D_ARRAY)&&i.texParameteri(C,i.TEXTURE_WRAP_R,q[M.wrapR]),i.texParameteri(C,i.TEXTURE_MAG_FILTER,oe[M.magFilter]),i.texParameteri(C,i.TEXTURE_MIN_FILTER,oe[M.minFilter]),M.compareFunction&&(i.texParameteri(C,i.TEXTURE_COMPARE_MODE,i.COMPARE_REF_TO_TEXTURE),i.texParameteri(C,i.TEXTURE_COMPARE_FUNC,ve[M.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(M.magFilter===Ln||M.minFilter!==ja&&M.minFilter!==Ts||M.type===Vi&&e.has("OES_texture_float_linear")===!1)return;if(M.anisotropy>1||n.get(M).__currentAnisotropy){const $=e.get("EXT_texture_filter_anisotropic");i.texParameterf(C,$.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(M.anisotropy,s.getMaxAnisotropy())),n.get(M).__currentAnisotropy=M.anisotropy}}}function Ze(C,M){let $=!1;C.__webglInit===void 0&&(C.__webglInit=!0,M.addEventListener("dispose",P),I(M));const de=M.source;let le=m.get(de);le===void 0&&(le={},m.set(de,le));const ye=te(M);if(ye!==C.__cacheKey){le[ye]===void 0&&(le[ye]={texture:i.createTexture(),usedTimes:0},a.memory.textures++,$=!0),le[ye].usedTimes++;const be=le[C.__cacheKey];be!==void 0&&(le[C.__cacheKey].usedTimes--,be.usedTimes===0&&H(M)),C.__cacheKey=ye,C.__webglTexture=le[ye].texture}return $}function je(C,M,$){return Math.floor(Math.floor(C/$)/M)}function Ut(C,M,$,de){const ye=C.updateRanges;if(ye.length===0)t.texSubImage2D(i.TEXTURE_2D,0,0,0,M.width,M.height,$,de,M.data);else{ye.sort((k,ae)=>k.start-ae.start);let be=0;for(let k=1;k<ye.length;k++){const ae=ye[be],ie=ye[k],Ae=ae.start+ae.count,Se=je(ie.start,M.width,4),Ee=je(ae.start,M.width,4);ie.start<=Ae+1&&Se===Ee&&je(ie.start+ie.count-1,M.width,4)===Se?ae.count=Math.max(ae.count,ie.start+ie.count-ae.start):(++be,ye[be]=ie)}ye.length=be+1;const ne=t.getParameter(i.UNPACK_ROW_LENGTH),re=t.getParameter(i.UNPACK_SKIP_PIXELS),ge=t.getParameter(i.UNPACK_SKIP_ROWS);t.pixelStorei(i.UNPACK_ROW_LENGTH,M.width);for(let k=0,ae=ye.length;k<ae;k++){const ie=ye[k],Ae=Math.floor(ie.start/4),Se=Math.ceil(ie.count/4),Ee=Ae%M.width,We=Math.floor(Ae/M.width),Qe=Se,ue=1;t.pixelStorei(i.UNPACK_SKIP_PIXELS,Ee),t.pixelStorei(i.UNPACK_SKIP_ROWS,We),t.texSubImage2D(i.TEXTURE_2D,0,Ee,We,Qe,ue,$,de,M.data)}C.clearUpdateRanges(),t.pixelStorei(i.UNPACK_ROW_LENGTH,ne),t.pixelStorei(i.UNPACK_SKIP_PIXELS,re),t.pixelStorei(i.UNPACK_SKIP_ROWS,ge)}}function At(C,M,$){let de=i.TEXTURE_2D;(M.isDataArrayTexture||M.isCompressedArrayTexture)&&(de=i.TEXTURE_2D_ARRAY),M.isData3DTexture&&(de=i.TEXTURE_3D);const le=Ze(C,M),ye=M.source;t.bindTexture(de,C.__webglTexture,i.TEXTURE0+$);const be=n.get(ye);if(ye.version!==be.__version||le===!0){if(t.activeTexture(i.TEXTURE0+$),(typeof ImageBitmap<"u"&&M.image instanceof ImageBitmap)===!1){const ue=vt.getPrimaries(vt.workingColorSpace),ze=M.colorSpace===Es?null:vt.getPrimaries(M.colorSpace),et=M.colorSpace===Es||ue===ze?i.NONE:i.BROWSER_DEFAULT_WEBGL;t.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,M.flipY),t.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,M.premultiplyAlpha),t.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,et)}t.pixelStorei(i.UNPACK_ALIGNMENT,M.unpackAlignment);let re=x(M.image,!1,s.maxTextureSize);re=Ve(M,re);const ge=r.convert(M.format,M.colorSpace),k=r.convert(M.type);let ae=w(M.internalFormat,ge,k,M.normalized,M.colorSpace,M.isVideoTexture);Xe(de,M);let ie;const Ae=M.mipmaps,Se=M.isVideoTexture!==!0,Ee=be.__version===void 0||le===!0,We=ye.dataReady,Qe=b(M,re);if(M.isDepthTexture)ae=g(M.format===As,M.type),Ee&&(Se?t.texStorage2D(i.TEXTURE_2D,1,ae,re.width,re.height):t.texImage2D(i.TEXTURE_2D,0,ae,re.width,re.height,0,ge,k,null));else if(M.isDataTexture)if(Ae.length>0){Se&&Ee&&t.texStorage2D(i.TEXTURE_2D,Qe,ae,Ae[0].width,Ae[0].height);for(let ue=0,ze=Ae.length;ue<ze;ue++)ie=Ae[ue],Se?We&&t.texSubImage2D(i.TEXTURE_2D,ue,0,0,ie.width,ie.height,ge,k,ie.data):t.texImage2D(i.TEXTURE_2D,ue,ae,ie.width,ie.height,0,ge,k,ie.data);M.generateMipmaps=!1}else Se?(Ee&&t.texStorage2D(i.TEXTURE_2D,Qe,ae,re.width,re.height),We&&Ut(M,re,ge,k)):t.texImage2D(i.TEXTURE_2D,0,ae,re.width,re.height,0,ge,k,re.data);else if(M.isCompressedTexture)if(M.isCompressedArrayTexture){Se&&Ee&&t.texStorage3D(i.TEXTURE_2D_ARRAY,Qe,ae,Ae[0].width,Ae[0].height,re.depth);for(let ue=0,ze=Ae.length;ue<ze;ue++)if(ie=Ae[ue],M.format!==Wi)if(ge!==null)if(Se){if(We)if(M.layerUpdates.size>0){const et=Rd(ie.width,ie.height,M.format,M.type);for(const De of M.layerUpdates){const at=ie.data.subarray(De*et/ie.data.BYTES_PER_ELEMENT,(De+1)*et/ie.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ue,0,0,De,ie.width,ie.height,1,ge,at)}}else t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ue,0,0,0,ie.width,ie.height,re.depth,ge,ie.data)}else t.compressedTexImage3D(i.TEXTURE_2D_ARRAY,ue,ae,ie.width,ie.height,re.depth,0,ie.data,0,0);else tt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else Se?We&&t.texSubImage3D(i.TEXTURE_2D_ARRAY,ue,0,0,0,ie.width,ie.height,re.depth,ge,k,ie.data):t.texImage3D(i.TEXTURE_2D_ARRAY,ue,ae,ie.width,ie.height,re.depth,0,ge,k,ie.data);M.layerUpdates.size>0&&M.clearLayerUpdates()}else{Se&&Ee&&t.texStorage2D(i.TEXTURE_2D,Qe,ae,Ae[0].width,Ae[0].height);for(let ue=0,ze=Ae.length;ue<ze;ue++)ie=Ae[ue],M.format!==Wi?ge!==null?Se?We&&t.compressedTexSubImage2D(i.TEXTURE_2D,ue,0,0,ie.width,ie.height,ge,ie.data):t.compressedTexImage2D(i.TEXTURE_2D,ue,ae,ie.width,ie.height,0,ie.data):tt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):Se?We&&t.texSubImage2D(i.TEXTURE_2D,ue,0,0,ie.width,ie.height,ge,k,ie.data):t.texImage2D(i.TEXTURE_2D,ue,ae,ie.width,ie.height,0,ge,k,ie.data)}else if(M.isDataArrayTexture)if(Se){if(Ee&&t.texStorage3D(i.TEXTURE_2D_ARRAY,Qe,ae,re.width,re.height,re.depth),We)if(M.layerUpdates.size>0){const ue=Rd(re.width,re.height,M.format,M.type);for(const ze of M.layerUpdates){const et=re.data.subarray(ze*ue/re.data.BYTES_PER_ELEMENT,(ze+1)*ue/re.data.BYTES_PER_ELEMENT);t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,ze,re.width,re.height,1,ge,k,et)}M.clearLayerUpdates()}else t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,0,re.width,re.height,re.depth,ge,k,re.data)}else t.texImage3D(i.TEXTURE_2D_ARRAY,0,ae,re.width,re.height,re.depth,0,ge,k,re.data);else if(M.isData3DTexture)Se?(Ee&&t.texStorage3D(i.TEXTURE_3D,Qe,ae,re.width,re.height,re.depth),We&&t.texSubImage3D(i.TEXTURE_3D,0,0,0,0,re.width,re.height,re.depth,ge,k,re.data)):t.texImage3D(i.TEXTURE_3D,0,ae,re.width,re.height,re.depth,0,ge,k,re.data);else if(M.isFramebufferTexture){if(Ee)if(Se)t.texStorage2D(i.TEXTURE_2D,Qe,ae,re.width,re.height);else{let ue=re.width,ze=re.height;for(let et=0;et<Qe;et++)t.texImage2D(i.TEXTURE_2D,et,ae,ue,ze,0,ge,k,null),ue>>=1,ze>>=1}}else if(M.isHTMLTexture){if("texElementImage2D"in i){const ue=i.canvas;if(ue.hasAttribute("layoutsubtree")||ue.setAttribute("layoutsubtree","true"),re.parentNode!==ue){ue.appendChild(re),u.add(M),ue.onpaint=ze=>{const et=ze.changedElements;for(const De of u)et.includes(De.image)&&(De.needsUpdate=!0)},ue.requestPaint();return}if(i.texElementImage2D.length===3)i.texElementImage2D(i.TEXTURE_2D,i.RGBA8,re);else{const et=i.RGBA,De=i.RGBA,at=i.UNSIGNED_BYTE;i.texElementImage2D(i.TEXTURE_2D,0,et,De,at,re)}i.texParameteri(i.TEXTURE_2D,i.TEXTURE_MIN_FILTER,i.LINEAR),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_S,i.CLAMP_TO_EDGE),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_T,i.CLAMP_TO_EDGE)}}else if(Ae.length>0){if(Se&&Ee){const ue=Ke(Ae[0]);t.texStorage2D(i.TEXTURE_2D,Qe,ae,ue.width,ue.height)}for(let ue=0,ze=Ae.length;ue<ze;ue++)ie=Ae[ue],Se?We&&t.texSubImage2D(i.TEXTURE_2D,ue,0,0,ge,k,ie):t.texImage2D(i.TEXTURE_2D,ue,ae,ge,k,ie);M.generateMipmaps=!1}else if(Se){if(Ee){const ue=Ke(re);t.texStorage2D(i.TEXTURE_2D,Qe,ae,ue.width,ue.height)}We&&t.texSubImage2D(i.TEXTURE_2D,0,0,0,ge,k,re)}else t.texImage2D(i.TEXTURE_2D,0,ae,ge,k,re);R(M)&&M.mipmapsAutoUpdate===!0&&y(de),be.__version=ye.version,M.onUpdate&&M.onUpdate(M)}C.__version=M.version}function zt(C,M,$){if(M.image.length!==6)return;const de=Ze(C,M),le=M.source;t.bindTexture(i.TEXTURE_CUBE_MAP,C.__webglTexture,i.TEXTURE0+$);const ye=n.get(le);if(le.version!==ye.__version||de===!0){t.activeTexture(i.TEXTURE0+$);const be=vt.getPrimaries(vt.workingColorSpace),ne=M.colorSpace===Es?null:vt.getPrimaries(M.colorSpace),re=M.colorSpace===Es||be===ne?i.NONE:i.BROWSER_DEFAULT_WEBGL;t.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,M.flipY),t.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,M.premultiplyAlpha),t.pixelStorei(i.UNPACK_ALIGNMENT,M.unpackAlignment),t.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,re);const ge=M.isCompressedTexture||M.image[0].isCompressedTexture,k=M.image[0]&&M.image[0].isDataTexture,ae=[];for(let De=0;De<6;De++)!ge&&!k?ae[De]=x(M.image[De],!0,s.maxCubemapSize):ae[De]=k?M.image[De].image:M.image[De],ae[De]=Ve(M,ae[De]);const ie=ae[0],Ae=r.convert(M.format,M.colorSpace),Se=r.convert(M.type);let Ee=w(M.internalFormat,Ae,Se,M.normalized,M.colorSpace);const We=M.isVideoTexture!==!0,Qe=ye.__version===void 0||de===!0,ue=le.dataReady;let ze=b(M,ie);Xe(i.TEXTURE_CUBE_MAP,M);let et;if(M.isDepthTexture){if(Ee=g(M.format===As,M.type),Qe)if(We)t.texStorage2D(i.TEXTURE_CUBE_MAP,1,Ee,ie.width,ie.height);else for(let De=0;De<6;De++)t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,0,Ee,ie.width,ie.height,0,Ae,Se,null)}else if(ge){We&&Qe&&t.texStorage2D(i.TEXTURE_CUBE_MAP,ze,Ee,ie.width,ie.height);for(let De=0;De<6;De++){et=ae[De].mipmaps;for(let at=0;at<et.length;at++){const Wt=et[at];M.format!==Wi?Ae!==null?We?ue&&t.compressedTexSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,at,0,0,Wt.width,Wt.height,Ae,Wt.data):t.compressedTexImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,at,Ee,Wt.width,Wt.height,0,Wt.data):tt("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):We?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,at,0,0,Wt.width,Wt.height,Ae,Se,Wt.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,at,Ee,Wt.width,Wt.height,0,Ae,Se,Wt.data)}}}else{if(et=M.mipmaps,We&&Qe){et.length>0&&ze++;const De=Ke(ae[0]);t.texStorage2D(i.TEXTURE_CUBE_MAP,ze,Ee,De.width,De.height)}for(let De=0;De<6;De++)if(k){We?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,0,0,0,ae[De].width,ae[De].height,Ae,Se,ae[De].data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,0,Ee,ae[De].width,ae[De].height,0,Ae,Se,ae[De].data);for(let at=0;at<et.length;at++){const On=et[at].image[De].image;We?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,at+1,0,0,On.width,On.height,Ae,Se,On.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,at+1,Ee,On.width,On.height,0,Ae,Se,On.data)}}else{We?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,0,0,0,Ae,Se,ae[De]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,0,Ee,Ae,Se,ae[De]);for(let at=0;at<et.length;at++){const Wt=et[at];We?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,at+1,0,0,Ae,Se,Wt.image[De]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+De,at+1,Ee,Ae,Se,Wt.image[De])}}}R(M)&&M.mipmapsAutoUpdate===!0&&y(i.TEXTURE_CUBE_MAP),ye.__version=le.version,M.onUpdate&&M.onUpdate(M)}C.__version=M.version}function xt(C,M,$,de,le,ye){const be=r.convert($.format,$.colorSpace),ne=r.convert($.type),re=w($.internalFormat,be,ne,$.normalized,$.colorSpace),ge=n.get(M),k=n.get($);if(k.__renderTarget=M,!ge.__hasExternalTextures){const ae=Math.max(1,M.width>>ye),ie=Math.max(1,M.height>>ye);le===i.TEXTURE_3D||le===i.TEXTURE_2D_ARRAY?t.texImage3D(le,ye,re,ae,ie,M.depth,0,be,ne,null):t.texImage2D(le,ye,re,ae,ie,0,be,ne,null)}t.bindFramebuffer(i.FRAMEBUFFER,C),Te(M)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,de,le,k.__webglTexture,0,st(M)):(le===i.TEXTURE_2D||le>=i.TEXTURE_CUBE_MAP_POSITIVE_X&&le<=i.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&i.framebufferTexture2D(i.FRAMEBUFFER,de,le,k.__webglTexture,ye),t.bindFramebuffer(i.FRAMEBUFFER,null)}function Jt(C,M,$){if(i.bindRenderbuffer(i.RENDERBUFFER,C),M.depthBuffer){const de=M.depthTexture,le=de&&de.isDepthTexture?de.type:null,ye=g(M.stencilBuffer,le),be=M.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;Te(M)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,st(M),ye,M.width,M.height):$?i.renderbufferStorageMultisample(i.RENDERBUFFER,st(M),ye,M.width,M.height):i.renderbufferStorage(i.RENDERBUFFER,ye,M.width,M.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,be,i.RENDERBUFFER,C)}else{const de=M.textures;for(let le=0;le<de.length;le++){const ye=de[le],be=r.convert(ye.format,ye.colorSpace),ne=r.convert(ye.type),re=w(ye.internalFormat,be,ne,ye.normalized,ye.colorSpace);Te(M)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,st(M),re,M.width,M.height):$?i.renderbufferStorageMultisample(i.RENDERBUFFER,st(M),re,M.width,M.height):i.renderbufferStorage(i.RENDERBUFFER,re,M.width,M.height)}}i.bindRenderbuffer(i.RENDERBUFFER,null)}function dt(C,M,$){const de=M.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(i.FRAMEBUFFER,C),!(M.depthTexture&&M.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");const le=n.get(M.depthTexture);le.__renderTarget=M;const ye=de?M.depthTexture.image[0]:M.depthTexture.image;(!le.__webglTexture||ye.width!==M.width||ye.height!==M.height)&&(ye.width=M.width,ye.height=M.height,M.depthTexture.needsUpdate=!0),de?Me(M.depthTexture,0):_e(M.depthTexture,0);const be=le.__webglTexture,ne=st(M),re=de?i.TEXTURE_CUBE_MAP_POSITIVE_X+$:i.TEXTURE_2D,ge=M.depthTexture.format===As?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;if(M.depthTexture.format===Ps)Te(M)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,ge,re,be,0,ne):i.framebufferTexture2D(i.FRAMEBUFFER,ge,re,be,0);else if(M.depthTexture.format===As)Te(M)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,ge,re,be,0,ne):i.framebufferTexture2D(i.FRAMEBUFFER,ge,re,be,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function Rt(C){const M=n.get(C),$=C.isWebGLCubeRenderTarget===!0;if(M.__boundDepthTexture!==C.depthTexture){const de=C.depthTexture;if(M.__depthDisposeCallback&&M.__depthDisposeCallback(),de){const le=()=>{delete M.__boundDepthTexture,delete M.__depthDisposeCallback,de.removeEventListener("dispose",le)};de.addEventListener("dispose",le),M.__depthDisposeCallback=le}M.__boundDepthTexture=de}if(C.depthTexture&&!M.__autoAllocateDepthBuffer)if($)for(let de=0;de<6;de++)dt(M.__webglFramebuffer[de],C,de);else C.texture.mipmaps.length>0?dt(M.__webglFramebuffer[0],C,0):dt(M.__webglFramebuffer,C,0);else if($){M.__webglDepthbuffer=[];for(let de=0;de<6;de++)if(t.bindFramebuffer(i.FRAMEBUFFER,M.__webglFramebuffer[de]),M.__webglDepthbuffer[de]===void 0)M.__webglDepthbuffer[de]=i.createRenderbuffer(),Jt(M.__webglDepthbuffer[de],C,!1);else{const le=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,ye=M.__webglDepthbuffer[de];i.bindRenderbuffer(i.RENDERBUFFER,ye),i.framebufferRenderbuffer(i.FRAMEBUFFER,le,i.RENDERBUFFER,ye)}}else if(C.texture.mipmaps.length>0?t.bindFramebuffer(i.FRAMEBUFFER,M.__webglFramebuffer[0]):t.bindFramebuffer(i.FRAMEBUFFER,M.__webglFramebuffer),M.__webglDepthbuffer===void 0)M.__webglDepthbuffer=i.createRenderbuffer(),Jt(M.__webglDepthbuffer,C,!1);else{const le=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,ye=M.__webglDepthbuffer;i.bindRenderbuffer(i.RENDERBUFFER,ye),i.framebufferRenderbuffer(i.FRAMEBUFFER,le,i.RENDERBUFFER,ye)}t.bindFramebuffer(i.FRAMEBUFFER,null)}function Vt(C,M,$){const de=n.get(C);M!==void 0&&xt(de.__webglFramebuffer,C,C.texture,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,0),$!==void 0&&Rt(C)}function Kt(C){const M=C.texture,$=n.get(C),de=n.get(M);C.addEventListener("dispose",B),I(C);const le=C.textures,ye=C.isWebGLCubeRenderTarget===!0,be=le.length>1;if(be||(de.__webglTexture===void 0&&(de.__webglTexture=i.createTexture()),de.__version=M.version,a.memory.textures++),ye){$.__webglFramebuffer=[];for(let ne=0;ne<6;ne++)if(M.mipmaps.length>0){$.__webglFramebuffer[ne]=[];for(let re=0;re<M.mipmaps.length;re++)$.__webglFramebuffer[ne][re]=i.createFramebuffer()}else $.__webglFramebuffer[ne]=i.createFramebuffer()}else{if(M.mipmaps.length>0){$.__webglFramebuffer=[];for(let ne=0;ne<M.mipmaps.length;ne++)$.__webglFramebuffer[ne]=i.createFramebuffer()}else $.__webglFramebuffer=i.createFramebuffer();if(be)for(let ne=0,re=le.length;ne<re;ne++){const ge=n.get(le[ne]);ge.__webglTexture===void 0&&(ge.__webglTexture=i.createTexture(),a.memory.textures++)}if(C.samples>0&&Te(C)===!1){$.__webglMultisampledFramebuffer=i.createFramebuffer(),$.__webglColorRenderbuffer=[],t.bindFramebuffer(i.FRAMEBUFFER,$.__webglMultisampledFramebuffer);for(let ne=0;ne<le.length;ne++){const re=le[ne];$.__webglColorRenderbuffer[ne]=i.createRenderbuffer(),i.bindRenderbuffer(i.RENDERBUFFER,$.__webglColorRenderbuffer[ne]);const ge=r.convert(re.format,re.colorSpace),k=r.convert(re.type),ae=w(re.internalFormat,ge,k,re.normalized,re.colorSpace,C.isXRRenderTarget===!0),ie=st(C);i.renderbufferStorageMultisample(i.RENDERBUFFER,ie,ae,C.width,C.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ne,i.RENDERBUFFER,$.__webglColorRenderbuffer[ne])}i.bindRenderbuffer(i.RENDERBUFFER,null),C.depthBuffer&&($.__webglDepthRenderbuffer=i.createRenderbuffer(),Jt($.__webglDepthRenderbuffer,C,!0)),t.bindFramebuffer(i.FRAMEBUFFER,null)}}if(ye){t.bindTexture(i.TEXTURE_CUBE_MAP,de.__webglTexture),Xe(i.TEXTURE_CUBE_MAP,M);for(let ne=0;ne<6;ne++)if(M.mipmaps.length>0)for(let re=0;re<M.mipmaps.length;re++)xt($.__webglFramebuffer[ne][re],C,M,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+ne,re);else xt($.__webglFramebuffer[ne],C,M,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+ne,0);R(M)?y(i.TEXTURE_CUBE_MAP):M.mipmaps.length>0&&i.texParameteri(i.TEXTURE_CUBE_MAP,i.TEXTURE_MAX_LEVEL,M.mipmaps.length-1),t.unbindTexture()}else if(be){for(let ne=0,re=le.length;ne<re;ne++){const ge=le[ne],k=n.get(ge);let ae=i.TEXTURE_2D;(C.isWebGL3DRenderTarget||C.isWebGLArrayRenderTarget)&&(ae=C.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),t.bindTexture(ae,k.__webglTexture),Xe(ae,ge),xt($.__webglFramebuffer,C,ge,i.COLOR_ATTACHMENT0+ne,ae,0),R(ge)&&y(ae)}t.unbindTexture()}else{let ne=i.TEXTURE_2D;if((C.isWebGL3DRenderTarget||C.isWebGLArrayRenderTarget)&&(ne=C.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),t.bindTexture(ne,de.__webglTexture),Xe(ne,M),M.mipmaps.length>0)for(let re=0;re<M.mipmaps.length;re++)xt($.__webglFramebuffer[re],C,M,i.COLOR_ATTACHMENT0,ne,re);else xt($.__webglFramebuffer,C,M,i.COLOR_ATTACHMENT0,ne,0);R(M)?y(ne):M.mipmaps.length>0&&i.texParameteri(ne,i.TEXTURE_MAX_LEVEL,M.mipmaps.length-1),t.unbindTexture()}C.depthBuffer&&Rt(C)}function O(C){const M=C.textures;for(let $=0,de=M.length;$<de;$++){const le=M[$];if(R(le)&&le.mipmapsAutoUpdate===!0){const ye=A(C),be=n.get(le).__webglTexture;t.bindTexture(ye,be),y(ye),t.unbindTexture()}}}const Le=[];function qe(C){if(C.samples>0){if(Te(C)===!1){const M=C.textures,$=C.width,de=C.height;let le=i.COLOR_BUFFER_BIT;const ye=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,be=n.get(C),ne=M.length>1;if(ne)for(let ge=0;ge<M.length;ge++)t.bindFramebuffer(i.FRAMEBUFFER,be.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ge,i.RENDERBUFFER,null),t.bindFramebuffer(i.FRAMEBUFFER,be.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+ge,i.TEXTURE_2D,null,0);t.bindFramebuffer(i.READ_FRAMEBUFFER,be.__webglMultisampledFramebuffer),C.texture.mipmaps.length>0?t.bindFramebuffer(i.DRAW_FRAMEBUFFER,be.__webglFramebuffer[0]):t.bindFramebuffer(i.DRAW_FRAMEBUFFER,be.__webglFramebuffer);for(let ge=0;ge<M.length;ge++){if(C.resolveDepthBuffer&&(C.depthBuffer&&(le|=i.DEPTH_BUFFER_BIT),C.stencilBuffer&&C.resolveStencilBuffer&&(le|=i.STENCIL_BUFFER_BIT)),ne){i.framebufferRenderbuffer(i.READ_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.RENDERBUFFER,be.__webglColorRenderbuffer[ge]);const k=n.get(M[ge]).__webglTexture;i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,k,0)}i.blitFramebuffer(0,0,$,de,0,0,$,de,le,i.NEAREST),l===!0&&(Le.length=0,Le.push(i.COLOR_ATTACHMENT0+ge),C.depthBuffer&&C.storeMultisampledDepthBuffer===!1&&Le.push(ye),i.invalidateFramebuffer(i.READ_FRAMEBUFFER,Le))}if(t.bindFramebuffer(i.READ_FRAMEBUFFER,null),t.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),ne)for(let ge=0;ge<M.length;ge++){t.bindFramebuffer(i.FRAMEBUFFER,be.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ge,i.RENDERBUFFER,be.__webglColorRenderbuffer[ge]);const k=n.get(M[ge]).__webglTexture;t.bindFramebuffer(i.FRAMEBUFFER,be.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+ge,i.TEXTURE_2D,k,0)}t.bindFramebuffer(i.DRAW_FRAMEBUFFER,be.__webglMultisampledFramebuffer)}else if(C.depthBuffer&&C.storeMultisampledDepthBuffer===!1&&l){const M=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,[M])}}}function st(C){return Math.min(s.maxSamples,C.samples)}function Te(C){const M=n.get(C);return C.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&M.__useRenderToTexture!==!1}function Ft(C){const M=a.render.frame;h.get(C)!==M&&(h.set(C,M),C.update())}function Ve(C,M){const $=C.colorSpace,de=C.format,le=C.type;return C.isCompressedTexture===!0||C.isVideoTexture===!0||$!==Ko&&$!==Es&&(vt.getTransfer($)===Dt?(de!==Wi||le!==ii)&&tt("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):St("WebGLTextures: Unsupported texture color space:",$)),M}function Ke(C){return typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement?(c.width=C.naturalWidth||C.width,c.height=C.naturalHeight||C.height):typeof VideoFrame<"u"&&C instanceof VideoFrame?(c.width=C.displayWidth,c.height=C.displayHeight):(c.width=C.width,c.height=C.height),c}this.allocateTextureUnit=fe,this.resetTextureUnits=ee,this.getTextureUnits=se,this.setTextureUnits=pe,this.setTexture2D=_e,this.setTexture2DArray=xe,this.setTexture3D=Pe,this.setTextureCube=Me,this.rebindTextures=Vt,this.setupRenderTarget=Kt,this.updateRenderTargetMipmap=O,this.updateMultisampleRenderTarget=qe,this.setupDepthRenderbuffer=Rt,this.setupFrameBufferTexture=xt,this.useMultisampledRTT=Te,this.dispose=W}function xM(i,e){function t(n,s=Es){let r;const a=vt.getTransfer(s);if(n===ii)return i.UNSIGNED_BYTE;if(n===Yh)return i.UNSIGNED_SHORT_4_4_4_4;if(n===Kh)return i.UNSIGNED_SHORT_5_5_5_1;if(n===bp)return i.UNSIGNED_INT_5_9_9_9_REV;if(n===wp)return i.UNSIGNED_INT_10F_11F_11F_REV;if(n===yp)return i.BYTE;if(n===Mp)return i.SHORT;if(n===Na)return i.UNSIGNED_SHORT;if(n===qh)return i.INT;if(n===Yi)return i.UNSIGNED_INT;if(n===Vi)return i.FLOAT;if(n===Ki)return i.HALF_FLOAT;if(n===Ep)return i.ALPHA;if(n===Tp)return i.RGB;if(n===Wi)return i.RGBA;if(n===Ps)return i.DEPTH_COMPONENT;if(n===As)return i.DEPTH_STENCIL;if(n===Ap)return i.RED;if(n===Zh)return i.RED_INTEGER;if(n===Ks)return i.RG;if(n===Jh)return i.RG_INTEGER;if(n===jh)return i.RGBA_INTEGER;if(n===Bo||n===zo||n===Ho||n===Go)if(a===Dt)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(n===Bo)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(n===zo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(n===Ho)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(n===Go)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(n===Bo)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(n===zo)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(n===Ho)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(n===Go)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(n===Vc||n===Wc||n===Xc||n===$c)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(n===Vc)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(n===Wc)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(n===Xc)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(n===$c)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(n===qc||n===Yc||n===Kc||n===Zc||n===Jc||n===qo||n===jc)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(n===qc||n===Yc)return a===Dt?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(n===Kc)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(n===Zc)return r.COMPRESSED_R11_EAC;if(n===Jc)return r.COMPRESSED_SIGNED_R11_EAC;if(n===qo)return r.COMPRESSED_RG11_EAC;if(n===jc)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(n===Qc||n===eh||n===th||n===nh||n===ih||n===sh||n===rh||n===ah||n===oh||n===lh||n===ch||n===hh||n===uh||n===dh)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(n===Qc)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(n===eh)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(n===th)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(n===nh)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(n===ih)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(n===sh)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(n===rh)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(n===ah)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(n===oh)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(n===lh)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(n===ch)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(n===hh)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(n===uh)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(n===dh)return a===Dt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(n===fh||n===ph||n===mh)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(n===fh)return a===Dt?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(n===ph)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(n===mh)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(n===gh||n===_h||n===Yo||n===vh)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(n===gh)return r.COMPRESSED_RED_RGTC1_EXT;if(n===_h)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(n===Yo)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(n===vh)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return n===zr?i.UNSIGNED_INT_24_8:i[n]!==void 0?i[n]:null}return{convert:t}}const SM=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,yM=`
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

}`;class MM{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){const n=new Xp(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=n}}getMesh(e){if(this.texture!==null&&this.mesh===null){const t=e.cameras[0].viewport,n=new Zs({vertexShader:SM,fragmentShader:yM,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new on(new ul(20,20),n)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}}class bM extends Is{constructor(e,t){super();const n=this;let s=null,r=1,a=null,o="local-floor",l=1,c=null,h=null,u=null,d=null,m=null,_=null;const S=typeof XRWebGLBinding<"u",p=new MM,f={},x=t.getContextAttributes();let R=null,y=null;const A=[],w=[],g=new Ye;let b=null,I=null;const N=new qn;N.viewport=new an;const P=new qn;P.viewport=new an;const B=[N,P],V=new N_;let U=null,W=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(te){let _e=A[te];return _e===void 0&&(_e=new ql,A[te]=_e),_e.getTargetRaySpace()},this.getControllerGrip=function(te){let _e=A[te];return _e===void 0&&(_e=new ql,A[te]=_e),_e.getGripSpace()},this.getHand=function(te){let _e=A[te];return _e===void 0&&(_e=new ql,A[te]=_e),_e.getHandSpace()};function Z(te){const _e=w.indexOf(te.inputSource);if(_e===-1)return;const xe=A[_e];xe!==void 0&&(xe.update(te.inputSource,te.frame,c||a),xe.dispatchEvent({type:te.type,data:te.inputSource}))}function H(){s.removeEventListener("select",Z),s.removeEventListener("selectstart",Z),s.removeEventListener("selectend",Z),s.removeEventListener("squeeze",Z),s.removeEventListener("squeezestart",Z),s.removeEventListener("squeezeend",Z),s.removeEventListener("end",H),s.removeEventListener("inputsourceschange",he);for(let te=0;te<A.length;te++){const _e=w[te];_e!==null&&(w[te]=null,A[te].disconnect(_e))}U=null,W=null,p.reset();for(const te in f)delete f[te];if(e.setRenderTarget(R),m=null,d=null,u=null,s=null,y=null,fe.stop(),n.isPresenting=!1,e.setPixelRatio(b),e.setSize(g.width,g.height,!1),I!==null){const te=I.camera;te.fov=I.fov,te.zoom=I.zoom,te.updateProjectionMatrix(),I=null}n.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(te){r=te,n.isPresenting===!0&&tt("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(te){o=te,n.isPresenting===!0&&tt("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return c||a},this.setReferenceSpace=function(te){c=te},this.getBaseLayer=function(){return d!==null?d:m},this.getBinding=function(){return u===null&&S&&(u=new XRWebGLBinding(s,t)),u},this.getFrame=function(){return _},this.getSession=function(){return s},this.setSession=async function(te){if(s=te,s!==null){if(R=e.getRenderTarget(),s.addEventListener("select",Z),s.addEventListener("selectstart",Z),s.addEventListener("selectend",Z),s.addEventListener("squeeze",Z),s.addEventListener("squeezestart",Z),s.addEventListener("squeezeend",Z),s.addEventListener("end",H),s.addEventListener("inputsourceschange",he),x.xrCompatible!==!0&&await t.makeXRCompatible(),b=e.getPixelRatio(),e.getSize(g),S&&"createProjectionLayer"in XRWebGLBinding.prototype){let xe=null,Pe=null,Me=null;x.depth&&(Me=x.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,xe=x.stencil?As:Ps,Pe=x.stencil?zr:Yi);const q={colorFormat:t.RGBA8,depthFormat:Me,scaleFactor:r};u=this.getBinding(),d=u.createProjectionLayer(q),s.updateRenderState({layers:[d]}),e.setPixelRatio(1),e.setSize(d.textureWidth,d.textureHeight,!1),y=new qi(d.textureWidth,d.textureHeight,{format:Wi,type:ii,depthTexture:new Hr(d.textureWidth,d.textureHeight,Pe,void 0,void 0,void 0,void 0,void 0,void 0,xe),stencilBuffer:x.stencil,colorSpace:e.outputColorSpace,samples:x.antialias?4:0,resolveDepthBuffer:d.ignoreDepthValues===!1,resolveStencilBuffer:d.ignoreDepthValues===!1,storeMultisampledDepthBuffer:d.ignoreDepthValues===!1,storeMultisampledStencilBuffer:d.ignoreDepthValues===!1})}else{const xe={antialias:x.antialias,alpha:!0,depth:x.depth,stencil:x.stencil,framebufferScaleFactor:r};m=new XRWebGLLayer(s,t,xe),s.updateRenderState({baseLayer:m}),e.setPixelRatio(1),e.setSize(m.framebufferWidth,m.framebufferHeight,!1),y=new qi(m.framebufferWidth,m.framebufferHeight,{format:Wi,type:ii,colorSpace:e.outputColorSpace,stencilBuffer:x.stencil,resolveDepthBuffer:m.ignoreDepthValues===!1,resolveStencilBuffer:m.ignoreDepthValues===!1,storeMultisampledDepthBuffer:m.ignoreDepthValues===!1,storeMultisampledStencilBuffer:m.ignoreDepthValues===!1})}y.isXRRenderTarget=!0,this.setFoveation(l),c=null,a=await s.requestReferenceSpace(o),fe.setContext(s),fe.start(),n.isPresenting=!0,n.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return p.getDepthTexture()};function he(te){for(let _e=0;_e<te.removed.length;_e++){const xe=te.removed[_e],Pe=w.indexOf(xe);Pe>=0&&(w[Pe]=null,A[Pe].disconnect(xe))}for(let _e=0;_e<te.added.length;_e++){const xe=te.added[_e];let Pe=w.indexOf(xe);if(Pe===-1){for(let q=0;q<A.length;q++)if(q>=w.length){w.push(xe),Pe=q;break}else if(w[q]===null){w[q]=xe,Pe=q;break}if(Pe===-1)break}const Me=A[Pe];Me&&Me.connect(xe)}}function J(te,_e){_e===null?te.matrixWorld.copy(te.matrix):te.matrixWorld.multiplyMatrices(_e.matrixWorld,te.matrix),te.matrixWorldInverse.copy(te.matrixWorld).invert()}this.updateCamera=function(te){if(s===null)return;let _e=te.near,xe=te.far;p.texture!==null&&(p.depthNear>0&&(_e=p.depthNear),p.depthFar>0&&(xe=p.depthFar)),V.near=P.near=N.near=_e,V.far=P.far=N.far=xe,(U!==V.near||W!==V.far)&&(s.updateRenderState({depthNear:V.near,depthFar:V.far}),U=V.near,W=V.far),V.layers.mask=te.layers.mask|6,N.layers.mask=V.layers.mask&-5,P.layers.mask=V.layers.mask&-3;const Pe=te.parent,Me=V.cameras;J(V,Pe);for(let q=0;q<Me.length;q++)J(Me[q],Pe);V.projectionMatrix.copy(N.projectionMatrix),V.projectionMatrixInverse.copy(N.projectionMatrixInverse),I===null&&te.isPerspectiveCamera&&(I={camera:te,fov:te.fov,zoom:te.zoom}),ee(te,V,Pe)};function ee(te,_e,xe){xe===null?te.matrix.copy(_e.matrixWorld):(te.matrix.copy(xe.matrixWorld),te.matrix.invert(),te.matrix.multiply(_e.matrixWorld)),te.matrix.decompose(te.position,te.quaternion,te.scale),te.updateMatrixWorld(!0),te.projectionMatrix.copy(_e.projectionMatrix),te.projectionMatrixInverse.copy(_e.projectionMatrixInverse),te.isPerspectiveCamera&&(te.fov=Sh*2*Math.atan(1/te.projectionMatrix.elements[5]),te.zoom=1)}this.getCamera=function(){return V},this.getFoveation=function(){if(!(d===null&&m===null))return l},this.setFoveation=function(te){l=te,d!==null&&(d.fixedFoveation=te),m!==null&&m.fixedFoveation!==void 0&&(m.fixedFoveation=te)},this.hasDepthSensing=function(){return p.texture!==null},this.getDepthSensingMesh=function(){return p.getMesh(V)},this.getCameraTexture=function(te){return f[te]};let se=null;function pe(te,_e){if(h=_e.getViewerPose(c||a),_=_e,h!==null){const xe=h.views;m!==null&&(e.setRenderTargetFramebuffer(y,m.framebuffer),e.setRenderTarget(y));let Pe=!1;xe.length!==V.cameras.length&&(V.cameras.length=0,Pe=!0);for(let ve=0;ve<xe.length;ve++){const Xe=xe[ve];let Ze=null;if(m!==null)Ze=m.getViewport(Xe);else{const Ut=u.getViewSubImage(d,Xe);Ze=Ut.viewport,ve===0&&(e.setRenderTargetTextures(y,Ut.colorTexture,Ut.depthStencilTexture),e.setRenderTarget(y))}let je=B[ve];je===void 0&&(je=new qn,je.layers.enable(ve),je.viewport=new an,B[ve]=je),je.matrix.fromArray(Xe.transform.matrix),je.matrix.decompose(je.position,je.quaternion,je.scale),je.projectionMatrix.fromArray(Xe.projectionMatrix),je.projectionMatrixInverse.copy(je.projectionMatrix).invert(),je.viewport.set(Ze.x,Ze.y,Ze.width,Ze.height),ve===0&&(V.matrix.copy(je.matrix),V.matrix.decompose(V.position,V.quaternion,V.scale)),Pe===!0&&V.cameras.push(je)}const Me=s.enabledFeatures;if(Me&&Me.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&S){u=n.getBinding();const ve=u.getDepthInformation(xe[0]);ve&&ve.isValid&&ve.texture&&p.init(ve,s.renderState)}if(Me&&Me.includes("camera-access")&&S){e.state.unbindTexture(),u=n.getBinding();for(let ve=0;ve<xe.length;ve++){const Xe=xe[ve].camera;if(Xe){let Ze=f[Xe];Ze||(Ze=new Xp,f[Xe]=Ze);const je=u.getCameraImage(Xe);Ze.sourceTexture=je}}}}for(let xe=0;xe<A.length;xe++){const Pe=w[xe],Me=A[xe];Pe!==null&&Me!==void 0&&Me.update(Pe,_e,c||a)}se&&se(te,_e),_e.detectedPlanes&&n.dispatchEvent({type:"planesdetected",data:_e}),_=null}const fe=new em;fe.setAnimationLoop(pe),this.setAnimationLoop=function(te){se=te},this.dispose=function(){}}}const wM=new Nt,hm=new rt;hm.set(-1,0,0,0,1,0,0,0,1);function EM(i,e){function t(p,f){p.matrixAutoUpdate===!0&&p.updateMatrix(),f.value.copy(p.matrix)}function n(p,f){f.color.getRGB(p.fogColor.value,$p(i)),f.isFog?(p.fogNear.value=f.near,p.fogFar.value=f.far):f.isFogExp2&&(p.fogDensity.value=f.density)}function s(p,f,x,R,y){f.isNodeMaterial?f.uniformsNeedUpdate=!1:f.isMeshBasicMaterial?r(p,f):f.isMeshLambertMaterial?(r(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshToonMaterial?(r(p,f),u(p,f)):f.isMeshPhongMaterial?(r(p,f),h(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshStandardMaterial?(r(p,f),d(p,f),f.isMeshPhysicalMaterial&&m(p,f,y)):f.isMeshMatcapMaterial?(r(p,f),_(p,f)):f.isMeshDepthMaterial?r(p,f):f.isMeshDistanceMaterial?(r(p,f),S(p,f)):f.isMeshNormalMaterial?r(p,f):f.isLineBasicMaterial?(a(p,f),f.isLineDashedMaterial&&o(p,f)):f.isPointsMaterial?l(p,f,x,R):f.isSpriteMaterial?c(p,f):f.isShadowMaterial?(p.color.value.copy(f.color),p.opacity.value=f.opacity):f.isShaderMaterial&&(f.uniformsNeedUpdate=!1)}function r(p,f){p.opacity.value=f.opacity,f.color&&p.diffuse.value.copy(f.color),f.emissive&&p.emissive.value.copy(f.emissive).multiplyScalar(f.emissiveIntensity),f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.bumpMap&&(p.bumpMap.value=f.bumpMap,t(f.bumpMap,p.bumpMapTransform),p.bumpScale.value=f.bumpScale,f.side===Kn&&(p.bumpScale.value*=-1)),f.normalMap&&(p.normalMap.value=f.normalMap,t(f.normalMap,p.normalMapTransform),p.normalScale.value.copy(f.normalScale),f.side===Kn&&p.normalScale.value.negate()),f.displacementMap&&(p.displacementMap.value=f.displacementMap,t(f.displacementMap,p.displacementMapTransform),p.displacementScale.value=f.displacementScale,p.displacementBias.value=f.displacementBias),f.emissiveMap&&(p.emissiveMap.value=f.emissiveMap,t(f.emissiveMap,p.emissiveMapTransform)),f.specularMap&&(p.specularMap.value=f.specularMap,t(f.specularMap,p.specularMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest);const x=e.get(f),R=x.envMap,y=x.envMapRotation;R&&(p.envMap.value=R,p.envMapRotation.value.setFromMatrix4(wM.makeRotationFromEuler(y)).transpose(),R.isCubeTexture&&R.isRenderTargetTexture===!1&&p.envMapRotation.value.premultiply(hm),p.reflectivity.value=f.reflectivity,p.ior.value=f.ior,p.refractionRatio.value=f.refractionRatio),f.lightMap&&(p.lightMap.value=f.lightMap,p.lightMapIntensity.value=f.lightMapIntensity,t(f.lightMap,p.lightMapTransform)),f.aoMap&&(p.aoMap.value=f.aoMap,p.aoMapIntensity.value=f.aoMapIntensity,t(f.aoMap,p.aoMapTransform))}function a(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform))}function o(p,f){p.dashSize.value=f.dashSize,p.totalSize.value=f.dashSize+f.gapSize,p.scale.value=f.scale}function l(p,f,x,R){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.size.value=f.size*x,p.scale.value=R*.5,f.map&&(p.map.value=f.map,t(f.map,p.uvTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function c(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.rotation.value=f.rotation,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function h(p,f){p.specular.value.copy(f.specular),p.shininess.value=Math.max(f.shininess,1e-4)}function u(p,f){f.gradientMap&&(p.gradientMap.value=f.gradientMap)}function d(p,f){p.metalness.value=f.metalness,f.metalnessMap&&(p.metalnessMap.value=f.metalnessMap,t(f.metalnessMap,p.metalnessMapTransform)),p.roughness.value=f.roughness,f.roughnessMap&&(p.roughnessMap.value=f.roughnessMap,t(f.roughnessMap,p.roughnessMapTransform)),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)}function m(p,f,x){p.ior.value=f.ior,f.diffuseRoughness>0&&(p.diffuseRoughness.value=f.diffuseRoughness,f.diffuseRoughnessMap&&(p.diffuseRoughnessMap.value=f.diffuseRoughnessMap,t(f.diffuseRoughnessMap,p.diffuseRoughnessMapTransform))),f.sheen>0&&(p.sheenColor.value.copy(f.sheenColor).multiplyScalar(f.sheen),p.sheenRoughness.value=f.sheenRoughness,f.sheenColorMap&&(p.sheenColorMap.value=f.sheenColorMap,t(f.sheenColorMap,p.sheenColorMapTransform)),f.sheenRoughnessMap&&(p.sheenRoughnessMap.value=f.sheenRoughnessMap,t(f.sheenRoughnessMap,p.sheenRoughnessMapTransform))),f.clearcoat>0&&(p.clearcoat.value=f.clearcoat,p.clearcoatRoughness.value=f.clearcoatRoughness,f.clearcoatMap&&(p.clearcoatMap.value=f.clearcoatMap,t(f.clearcoatMap,p.clearcoatMapTransform)),f.clearcoatRoughnessMap&&(p.clearcoatRoughnessMap.value=f.clearcoatRoughnessMap,t(f.clearcoatRoughnessMap,p.clearcoatRoughnessMapTransform)),f.clearcoatNormalMap&&(p.clearcoatNormalMap.value=f.clearcoatNormalMap,t(f.clearcoatNormalMap,p.clearcoatNormalMapTransform),p.clearcoatNormalScale.value.copy(f.clearcoatNormalScale),f.side===Kn&&p.clearcoatNormalScale.value.negate())),f.dispersion>0&&(p.dispersion.value=f.dispersion),f.retroreflectivity>0&&(p.retroreflectivity.value=f.retroreflectivity),f.iridescence>0&&(p.iridescence.value=f.iridescence,p.iridescenceIOR.value=f.iridescenceIOR,p.iridescenceThicknessMinimum.value=f.iridescenceThicknessMinimum,p.iridescenceThicknessMaximum.value=f.iridescenceThicknessMaximum,f.iridescenceMap&&(p.iridescenceMap.value=f.iridescenceMap,t(f.iridescenceMap,p.iridescenceMapTransform)),f.iridescenceThicknessMap&&(p.iridescenceThicknessMap.value=f.iridescenceThicknessMap,t(f.iridescenceThicknessMap,p.iridescenceThicknessMapTransform))),f.transmission>0&&(p.transmission.value=f.transmission,p.transmissionSamplerMap.value=x.texture,p.transmissionSamplerSize.value.set(x.width,x.height),f.transmissionMap&&(p.transmissionMap.value=f.transmissionMap,t(f.transmissionMap,p.transmissionMapTransform)),p.thickness.value=f.thickness,f.thicknessMap&&(p.thicknessMap.value=f.thicknessMap,t(f.thicknessMap,p.thicknessMapTransform)),p.attenuationDistance.value=f.attenuationDistance,p.attenuationColor.value.copy(f.attenuationColor)),f.anisotropy>0&&(p.anisotropyVector.value.set(f.anisotropy*Math.cos(f.anisotropyRotation),f.anisotropy*Math.sin(f.anisotropyRotation)),f.anisotropyMap&&(p.anisotropyMap.value=f.anisotropyMap,t(f.anisotropyMap,p.anisotropyMapTransform))),p.specularIntensity.value=f.specularIntensity,p.specularColor.value.copy(f.specularColor),f.specularColorMap&&(p.specularColorMap.value=f.specularColorMap,t(f.specularColorMap,p.specularColorMapTransform)),f.specularIntensityMap&&(p.specularIntensityMap.value=f.specularIntensityMap,t(f.specularIntensityMap,p.specularIntensityMapTransform))}function _(p,f){f.matcap&&(p.matcap.value=f.matcap)}function S(p,f){const x=e.get(f).light;p.referencePosition.value.setFromMatrixPosition(x.matrixWorld),p.nearDistance.value=x.shadow.camera.near,p.farDistance.value=x.shadow.camera.far}return{refreshFogUniforms:n,refreshMaterialUniforms:s}}function TM(i,e,t,n){let s={},r={};function a(x,R){const y=R.program;n.uniformBlockBinding(x,y,s[x.id])}function o(x,R){let y=s[x.id];y===void 0&&(_(x),y=l(x),s[x.id]=y,x.addEventListener("dispose",p));const A=R.program;n.updateUBOMapping(x,A);const w=e.render.frame;r[x.id]!==w&&(c(x),r[x.id]=w)}function l(x){const R=i.createBuffer(),y=x.__size,A=x.usage;return i.bindBuffer(i.UNIFORM_BUFFER,R),i.bufferData(i.UNIFORM_BUFFER,y,A),i.bindBuffer(i.UNIFORM_BUFFER,null),R}function c(x){const R=s[x.id],y=x.uniforms,A=x.__cache;i.bindBuffer(i.UNIFORM_BUFFER,R);for(let w=0,g=y.length;w<g;w++){const b=y[w];if(Array.isArray(b))for(let I=0,N=b.length;I<N;I++)h(b[I],w,I,A);else h(b,w,0,A)}i.bindBuffer(i.UNIFORM_BUFFER,null)}function h(x,R,y,A){if(d(x,R,y,A)===!0){const w=x.__offset,g=x.value;if(Array.isArray(g)){let b=0;for(let I=0;I<g.length;I++){const N=g[I],P=S(N,!0);u(N,x.__data,b),b+=P.storage/Float32Array.BYTES_PER_ELEMENT}}else u(g,x.__data,0);i.bufferSubData(i.UNIFORM_BUFFER,w,x.__data)}}function u(x,R,y){typeof x=="number"||typeof x=="boolean"?R[y]=x:x.isMatrix3?(R[y]=x.elements[0],R[y+1]=x.elements[1],R[y+2]=x.elements[2],R[y+3]=0,R[y+4]=x.elements[3],R[y+5]=x.elements[4],R[y+6]=x.elements[5],R[y+7]=0,R[y+8]=x.elements[6],R[y+9]=x.elements[7],R[y+10]=x.elements[8],R[y+11]=0):ArrayBuffer.isView(x)?R.set(x.subarray(0,R.length-y),y):x.toArray(R,y)}function d(x,R,y,A){const w=x.value,g=R+"_"+y;if(Array.isArray(w)){A[g]===void 0&&(A[g]=[]);const b=A[g];let I=!1;for(let N=0;N<w.length;N++)m(w[N],b,N)===!0&&(I=!0);return I}return m(w,A,g)}function m(x,R,y){if(R[y]===void 0)return typeof x=="number"||typeof x=="boolean"?R[y]=x:ArrayBuffer.isView(x)?R[y]=x.slice():R[y]=x.clone(),!0;{const A=R[y];if(typeof x=="number"||typeof x=="boolean"){if(A!==x)return R[y]=x,!0}else{if(ArrayBuffer.isView(x))return!0;if(A.equals(x)===!1)return A.copy(x),!0}}return!1}function _(x){const R=x.uniforms;let y=0;const A=16;for(let g=0,b=R.length;g<b;g++){const I=Array.isArray(R[g])?R[g]:[R[g]];for(let N=0,P=I.length;N<P;N++){const B=I[N],V=Array.isArray(B.value)?B.value:[B.value],U=Array.isArray(R[g])||Array.isArray(B.value);let W=y;for(let H=0,he=V.length;H<he;H++){const J=V[H],ee=S(J,U),se=y%A,pe=se%ee.boundary,fe=se+pe;y+=pe,fe!==0&&A-fe<ee.storage&&(y+=A-fe),H===0&&(W=y),y+=ee.storage}const Z=B.type==="int"?Int32Array:B.type==="uint"?Uint32Array:Float32Array;B.__data=new Z((y-W)/Float32Array.BYTES_PER_ELEMENT),B.__offset=W}}const w=y%A;return w>0&&(y+=A-w),x.__size=y,x.__cache={},this}function S(x,R){const y={boundary:0,storage:0};return typeof x=="number"||typeof x=="boolean"?(y.boundary=4,y.storage=4):x.isVector2?(y.boundary=8,y.storage=8):x.isVector3||x.isColor?(y.boundary=16,y.storage=12):x.isVector4?(y.boundary=16,y.storage=16):x.isMatrix3?(y.boundary=16,y.storage=48):x.isMatrix4?(y.boundary=16,y.storage=64):x.isTexture?tt("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(x)?(y.boundary=16,y.storage=x.byteLength):tt("WebGLRenderer: Unsupported uniform value type.",x),R===!0&&(y.boundary=16,y.storage=Math.ceil(y.storage/16)*16),y}function p(x){const R=x.target;R.removeEventListener("dispose",p),i.deleteBuffer(s[R.id]),delete s[R.id],delete r[R.id]}function f(){for(const x in s)i.deleteBuffer(s[x]);s={},r={}}return{bind:a,update:o,dispose:f}}const AM=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]);let ki=null;function RM(){return ki===null&&(ki=new v_(AM,16,16,Ks,Ki),ki.name="DFG_LUT",ki.minFilter=Yn,ki.magFilter=Yn,ki.wrapS=os,ki.wrapT=os,ki.generateMipmaps=!1,ki.needsUpdate=!0),ki}class um{constructor(e={}){const{canvas:t=X0(),context:n=null,depth:s=!0,stencil:r=!1,alpha:a=!1,antialias:o=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:c=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:u=!1,reversedDepthBuffer:d=!1,outputBufferType:m=ii}=e;this.isWebGLRenderer=!0;let _;if(n!==null){if(typeof WebGLRenderingContext<"u"&&n instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");_=n.getContextAttributes().alpha}else _=a;const S=m,p=new Set([jh,Jh,Zh]),f=new Set([ii,Yi,Na,zr,Yh,Kh]),x=new Uint32Array(4),R=new Int32Array(4),y={textures:[],min:[],max:[],resolution:[]};let A=null,w=null;const g=[],b=[];let I=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=cs,this.toneMappingExposure=1,this.transmissionResolutionScale=1;const N=this;let P=!1,B=null,V=null,U=null,W=null;this._outputColorSpace=ui;let Z=0,H=0,he=null,J=-1,ee=null;const se=new an,pe=new an;let fe=null;const te=new ct(0);let _e=0,xe=t.width,Pe=t.height,Me=1,q=null,oe=null;const ve=new an(0,0,xe,Pe),Xe=new an(0,0,xe,Pe);let Ze=!1;const je=new Ua,Ut=new tu;let At=!1,zt=!1;const xt=new Nt,Jt=new z,dt=new an,Rt={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0};let Vt=!1;function Kt(){return he===null?Me:1}let O=n;function Le(T,G){return t.getContext(T,G)}let qe,st,Te,Ft,Ve,Ke,C,M,$,de,le,ye,be,ne,re,ge,k,ae,ie,Ae,Se,Ee,We;try{const T={alpha:!0,depth:s,stencil:r,antialias:o,premultipliedAlpha:l,preserveDrawingBuffer:c,powerPreference:h,failIfMajorPerformanceCaveat:u};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${$h}`),t.addEventListener("webglcontextlost",ze,!1),t.addEventListener("webglcontextrestored",et,!1),t.addEventListener("webglcontextcreationerror",De,!1),O===null){const G="webgl2";if(O=Le(G,T),O===null)throw Le(G)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}Qe()}catch(T){throw t.removeEventListener("webglcontextlost",ze,!1),t.removeEventListener("webglcontextrestored",et,!1),t.removeEventListener("webglcontextcreationerror",De,!1),St("WebGLRenderer: "+T.message),T}function Qe(){qe=new DS(O),qe.init(),Se=new xM(O,qe),st=new yS(O,qe,e,Se),Te=new _M(O,qe),st.reversedDepthBuffer&&d&&Te.buffers.depth.setReversed(!0),V=O.createFramebuffer(),U=O.createFramebuffer(),W=O.createFramebuffer(),Ft=new US(O),Ve=new iM,Ke=new vM(O,qe,Te,Ve,st,Se,Ft),C=new LS(N),M=new O_(O),Ee=new xS(O,M),$=new NS(O,M,Ft,Ee),de=new OS(O,$,M,Ee,Ft),ae=new FS(O,st,Ke),re=new MS(Ve),le=new nM(N,C,qe,st,Ee,re),ye=new EM(N,Ve),be=new rM,ne=new uM(qe),k=new vS(N,C,Te,de,_,l),ge=new gM(N,de,st),We=new TM(O,Ft,st,Te),ie=new SS(O,qe,Ft),Ae=new IS(O,qe,Ft),Ft.programs=le.programs,N.capabilities=st,N.extensions=qe,N.properties=Ve,N.renderLists=be,N.shadowMap=ge,N.state=Te,N.info=Ft}S!==ii&&(I=new BS(S,t.width,t.height,o,s,r));const ue=new bM(N,O);this.xr=ue,this.getContext=function(){return O},this.getContextAttributes=function(){return O.getContextAttributes()},this.forceContextLoss=function(){const T=qe.get("WEBGL_lose_context");T&&T.loseContext()},this.forceContextRestore=function(){const T=qe.get("WEBGL_lose_context");T&&T.restoreContext()},this.getPixelRatio=function(){return Me},this.setPixelRatio=function(T){T!==void 0&&(Me=T,this.setSize(xe,Pe,!1))},this.getSize=function(T){return T.set(xe,Pe)},this.setSize=function(T,G,Q=!0){if(ue.isPresenting){tt("WebGLRenderer: Can't change size while VR device is presenting.");return}xe=T,Pe=G,t.width=Math.floor(T*Me),t.height=Math.floor(G*Me),Q===!0&&(t.style.width=T+"px",t.style.height=G+"px"),I!==null&&I.setSize(t.width,t.height),this.setViewport(0,0,T,G)},this.getDrawingBufferSize=function(T){return T.set(xe*Me,Pe*Me).floor()},this.setDrawingBufferSize=function(T,G,Q){xe=T,Pe=G,Me=Q,t.width=Math.floor(T*Q),t.height=Math.floor(G*Q),this.setViewport(0,0,T,G)},this.setEffects=function(T){if(S===ii){St("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(T){for(let G=0;G<T.length;G++)if(T[G].isOutputPass===!0){tt("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}I.setEffects(T||[])},this.getCurrentViewport=function(T){return T.copy(se)},this.getViewport=function(T){return T.copy(ve)},this.setViewport=function(T,G,Q,Y){T.isVector4?ve.set(T.x,T.y,T.z,T.w):ve.set(T,G,Q,Y),Te.viewport(se.copy(ve).multiplyScalar(Kt()).round())},this.getScissor=function(T){return T.copy(Xe)},this.setScissor=function(T,G,Q,Y){T.isVector4?Xe.set(T.x,T.y,T.z,T.w):Xe.set(T,G,Q,Y),Te.scissor(pe.copy(Xe).multiplyScalar(Kt()).round())},this.getScissorTest=function(){return Ze},this.setScissorTest=function(T){Te.setScissorTest(Ze=T)},this.setOpaqueSort=function(T){q=T},this.setTransparentSort=function(T){oe=T},this.getClearColor=function(T){return T.copy(k.getClearColor())},this.setClearColor=function(){k.setClearColor(...arguments)},this.getClearAlpha=function(){return k.getClearAlpha()},this.setClearAlpha=function(){k.setClearAlpha(...arguments)},this.clear=function(T=!0,G=!0,Q=!0){let Y=0;if(T){let K=!1;if(he!==null){const Re=he.texture.format;K=p.has(Re)}if(K){const Re=he.texture.type,Ne=f.has(Re),Ce=k.getClearColor(),Ie=k.getClearAlpha(),Ge=Ce.r,nt=Ce.g,ht=Ce.b;Ne?(x[0]=Ge,x[1]=nt,x[2]=ht,x[3]=Ie,O.clearBufferuiv(O.COLOR,0,x)):(R[0]=Ge,R[1]=nt,R[2]=ht,R[3]=Ie,O.clearBufferiv(O.COLOR,0,R))}else Y|=O.COLOR_BUFFER_BIT}G&&(Y|=O.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),Q&&(Y|=O.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),Y!==0&&O.clear(Y)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(T){T.setRenderer(this),B=T},this.dispose=function(){t.removeEventListener("webglcontextlost",ze,!1),t.removeEventListener("webglcontextrestored",et,!1),t.removeEventListener("webglcontextcreationerror",De,!1),k.dispose(),be.dispose(),ne.dispose(),Ke.dispose(),Ve.dispose(),C.dispose(),de.dispose(),$.dispose(),Ee.dispose(),We.dispose(),le.dispose(),ue.dispose(),ue.removeEventListener("sessionstart",qa),ue.removeEventListener("sessionend",Pi),Ji.stop()};function ze(T){T.preventDefault(),jo("WebGLRenderer: Context Lost."),P=!0}function et(){jo("WebGLRenderer: Context Restored."),P=!1;const T=Ft.autoReset,G=ge.enabled,Q=ge.autoUpdate,Y=ge.needsUpdate,K=ge.type;Qe(),Ft.autoReset=T,ge.enabled=G,ge.autoUpdate=Q,ge.needsUpdate=Y,ge.type=K}function De(T){St("WebGLRenderer: A WebGL context could not be created. Reason: ",T.statusMessage)}function at(T){const G=T.target;G.removeEventListener("dispose",at),Wt(G)}function Wt(T){On(T),Ve.remove(T)}function On(T){const G=Ve.get(T).programs;G!==void 0&&(G.forEach(function(Q){le.releaseProgram(Q)}),T.isShaderMaterial&&le.releaseShaderCache(T))}this.renderBufferDirect=function(T,G,Q,Y,K,Re){G===null&&(G=Rt);const Ne=K.isMesh&&K.matrixWorld.determinantAffine()<0,Ce=ea(T,G,Q,Y,K);Te.setMaterial(Y,Ne);let Ie=Q.index,Ge=1;if(Y.wireframe===!0){if(Ie=$.getWireframeAttribute(Q),Ie===void 0)return;Ge=2}const nt=Q.drawRange,ht=Q.attributes.position;let He=nt.start*Ge,ut=(nt.start+nt.count)*Ge;Re!==null&&(He=Math.max(He,Re.start*Ge),ut=Math.min(ut,(Re.start+Re.count)*Ge)),Ie!==null?(He=Math.max(He,0),ut=Math.min(ut,Ie.count)):ht!=null&&(He=Math.max(He,0),ut=Math.min(ut,ht.count));const jt=ut-He;if(jt<0||jt===1/0)return;Ee.setup(K,Y,Ce,Q,Ie);let Ct,Pt=ie;if(Ie!==null&&(Ct=M.get(Ie),Pt=Ae,Pt.setIndex(Ct)),K.isMesh)Y.wireframe===!0?(Te.setLineWidth(Y.wireframeLinewidth*Kt()),Pt.setMode(O.LINES)):Pt.setMode(O.TRIANGLES);else if(K.isLine){let mn=Y.linewidth;mn===void 0&&(mn=1),Te.setLineWidth(mn*Kt()),K.isLineSegments?Pt.setMode(O.LINES):K.isLineLoop?Pt.setMode(O.LINE_LOOP):Pt.setMode(O.LINE_STRIP)}else K.isPoints?Pt.setMode(O.POINTS):K.isSprite&&Pt.setMode(O.TRIANGLES);if(K.isBatchedMesh)if(qe.get("WEBGL_multi_draw"))Pt.renderMultiDraw(K._multiDrawStarts,K._multiDrawCounts,K._multiDrawCount);else{const mn=K._multiDrawStarts,ke=K._multiDrawCounts,cn=K._multiDrawCount,gt=Ie?M.get(Ie).bytesPerElement:1,Qi=Ve.get(Y).currentProgram.getUniforms();for(let hn=0;hn<cn;hn++)Qi.setValue(O,"_gl_DrawID",hn),Pt.render(mn[hn]/gt,ke[hn])}else if(K.isInstancedMesh)Pt.renderInstances(He,jt,K.count);else if(Q.isInstancedBufferGeometry){const mn=Q._maxInstanceCount!==void 0?Q._maxInstanceCount:1/0,ke=Math.min(Q.instanceCount,mn);Pt.renderInstances(He,jt,ke)}else Pt.render(He,jt)};function Jr(T,G,Q,Y){B!==null&&T.isNodeMaterial&&B.setObject(Y,T),At===!0&&re.setState(T,Q,!1),T.transparent===!0&&T.side===pi&&T.forceSinglePass===!1?(T.side=Kn,T.needsUpdate=!0,Li(T,G,Y),T.side=Cs,T.needsUpdate=!0,Li(T,G,Y),T.side=pi):Li(T,G,Y)}this.compile=function(T,G,Q=null){Q===null&&(Q=T),B!==null&&B.renderStart(T,G,Q),w=ne.get(Q),w.init(G),b.push(w),Q.traverseVisible(function(K){K.isLight&&K.layers.test(G.layers)&&(w.pushLight(K),K.castShadow&&w.pushShadow(K))}),T!==Q&&T.traverseVisible(function(K){K.isLight&&K.layers.test(G.layers)&&(w.pushLight(K),K.castShadow&&w.pushShadow(K))}),w.setupLights(),B!==null&&B.updateLights(w.state.lightsArray),zt=this.localClippingEnabled,At=re.init(this.clippingPlanes,zt),At===!0&&re.setGlobalState(this.clippingPlanes,G),B!==null&&ge.render(w.state.shadowsArray,Q,G);const Y=new Set;return T.traverse(function(K){if(!(K.isMesh||K.isPoints||K.isLine||K.isSprite))return;const Re=K.material;if(Re)if(Array.isArray(Re))for(let Ne=0;Ne<Re.length;Ne++){const Ce=Re[Ne];Jr(Ce,Q,G,K),Y.add(Ce)}else Jr(Re,Q,G,K),Y.add(Re)}),w=b.pop(),B!==null&&B.renderEnd(),Y},this.compileAsync=function(T,G,Q=null){const Y=this.compile(T,G,Q);return new Promise(K=>{function Re(){if(Y.forEach(function(Ne){const Ie=Ve.get(Ne).currentProgram;(Ie===void 0||Ie.isReady())&&Y.delete(Ne)}),Y.size===0){K(T);return}setTimeout(Re,10)}qe.get("KHR_parallel_shader_compile")!==null?Re():setTimeout(Re,10)})};let tr=null;function bl(T){tr&&tr(T)}function qa(){Ji.stop()}function Pi(){Ji.start()}const Ji=new em;Ji.setAnimationLoop(bl),typeof self<"u"&&Ji.setContext(self),this.setAnimationLoop=function(T){tr=T,ue.setAnimationLoop(T),T===null?Ji.stop():Ji.start()},ue.addEventListener("sessionstart",qa),ue.addEventListener("sessionend",Pi),this.render=function(T,G){if(G!==void 0&&G.isCamera!==!0){St("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(P===!0)return;B!==null&&B.renderStart(T,G);const Q=ue.enabled===!0&&ue.isPresenting===!0,Y=I!==null&&(he===null||Q)&&I.begin(N,he);if(T.matrixWorldAutoUpdate===!0&&T.updateMatrixWorld(),G.parent===null&&G.matrixWorldAutoUpdate===!0&&G.updateMatrixWorld(),ue.enabled===!0&&ue.isPresenting===!0&&(I===null||I.isCompositing()===!1)&&(ue.cameraAutoUpdate===!0&&ue.updateCamera(G),G=ue.getCamera()),T.isScene===!0&&T.onBeforeRender(N,T,G,he),w=ne.get(T,b.length),w.init(G),w.state.textureUnits=Ke.getTextureUnits(),b.push(w),xt.multiplyMatrices(G.projectionMatrix,G.matrixWorldInverse),G.isArrayCamera?Ut.setFromArrayCamera(G):je.setFromProjectionMatrix(xt,Ci,G.reversedDepth),zt=this.localClippingEnabled,At=re.init(this.clippingPlanes,zt),A=be.get(T,g.length),A.init(),g.push(A),this.info.render.frame++,ue.enabled===!0&&ue.isPresenting===!0){const Ne=N.xr.getDepthSensingMesh();Ne!==null&&ji(Ne,G,-1/0,N.sortObjects)}ji(T,G,0,N.sortObjects),A.finish(),B!==null&&B.updateLights(w.state.lightsArray),N.sortObjects===!0&&A.sort(q,oe),Vt=ue.enabled===!1||ue.isPresenting===!1||ue.hasDepthSensing()===!1,Vt&&k.addToRenderList(A,T),this.info.autoReset===!0&&this.info.reset(),At===!0&&re.beginShadows();const K=w.state.shadowsArray;if(ge.render(K,T,G),At===!0&&re.endShadows(),(Y&&I.hasRenderPass())===!1){const Ne=A.opaque,Ce=A.transmissive;if(w.setupLights(),G.isArrayCamera){const Ie=G.cameras;if(Ce.length>0)for(let Ge=0,nt=Ie.length;Ge<nt;Ge++){const ht=Ie[Ge];vi(Ne,Ce,T,ht)}Vt&&k.render(T);for(let Ge=0,nt=Ie.length;Ge<nt;Ge++){const ht=Ie[Ge];jr(A,T,ht,ht.viewport)}}else Ce.length>0&&vi(Ne,Ce,T,G),Vt&&k.render(T),jr(A,T,G)}he!==null&&H===0&&(Ke.updateMultisampleRenderTarget(he),Ke.updateRenderTargetMipmap(he)),Y&&I.end(N),T.isScene===!0&&T.onAfterRender(N,T,G),Ee.resetDefaultState(),J=-1,ee=null,b.pop(),b.length>0?(w=b[b.length-1],Ke.setTextureUnits(w.state.textureUnits),At===!0&&re.setGlobalState(N.clippingPlanes,w.state.camera)):w=null,g.pop(),g.length>0?A=g[g.length-1]:A=null,B!==null&&B.renderEnd()};function ji(T,G,Q,Y){if(T.visible===!1)return;if(T.layers.test(G.layers)){if(T.isGroup)Q=T.renderOrder;else if(T.isLOD)T.autoUpdate===!0&&T.update(G);else if(T.isLight)w.pushLight(T),T.castShadow&&w.pushShadow(T);else if(T.isSprite){const Ne=G.isArrayCamera?Ut:je;if(!T.frustumCulled||T.intersectsFrustum(Ne)){Y&&dt.setFromMatrixPosition(T.matrixWorld).applyMatrix4(xt);const Ce=de.update(T),Ie=T.material;Ie.visible&&A.push(T,Ce,Ie,Q,dt.z,null,G)}}else if(T.isMesh||T.isLine||T.isPoints){const Ne=G.isArrayCamera?Ut:je;if(!T.frustumCulled||T.intersectsFrustum(Ne)){const Ce=de.update(T),Ie=T.material;if(Y&&(T.boundingSphere!==void 0?(T.boundingSphere===null&&T.computeBoundingSphere(),dt.copy(T.boundingSphere.center)):(Ce.boundingSphere===null&&Ce.computeBoundingSphere(),dt.copy(Ce.boundingSphere.center)),dt.applyMatrix4(T.matrixWorld).applyMatrix4(xt)),Array.isArray(Ie)){const Ge=Ce.groups;for(let nt=0,ht=Ge.length;nt<ht;nt++){const He=Ge[nt],ut=Ie[He.materialIndex];ut&&ut.visible&&A.push(T,Ce,ut,Q,dt.z,He,G)}}else Ie.visible&&A.push(T,Ce,Ie,Q,dt.z,null,G)}}}const Re=T.children;for(let Ne=0,Ce=Re.length;Ne<Ce;Ne++)ji(Re[Ne],G,Q,Y)}function jr(T,G,Q,Y){const{opaque:K,transmissive:Re,transparent:Ne}=T;w.setupLightsView(Q),At===!0&&re.setGlobalState(N.clippingPlanes,Q),Y&&Te.viewport(se.copy(Y)),K.length>0&&Qt(K,G,Q),Re.length>0&&Qt(Re,G,Q),Ne.length>0&&Qt(Ne,G,Q),Te.buffers.depth.setTest(!0),Te.buffers.depth.setMask(!0),Te.buffers.color.setMask(!0),Te.setPolygonOffset(!1)}function vi(T,G,Q,Y){if((Q.isScene===!0?Q.overrideMaterial:null)!==null)return;if(w.state.transmissionRenderTarget[Y.id]===void 0){const He=qe.has("EXT_color_buffer_half_float")||qe.has("EXT_color_buffer_float");w.state.transmissionRenderTarget[Y.id]=new qi(1,1,{generateMipmaps:!0,type:He?Ki:ii,minFilter:Ts,samples:Math.max(4,st.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:vt.workingColorSpace})}const Re=w.state.transmissionRenderTarget[Y.id],Ne=Y.viewport||se;Re.setSize(Ne.z*N.transmissionResolutionScale,Ne.w*N.transmissionResolutionScale);const Ce=N.getRenderTarget(),Ie=N.getActiveCubeFace(),Ge=N.getActiveMipmapLevel();N.setRenderTarget(Re),N.getClearColor(te),_e=N.getClearAlpha(),_e<1&&N.setClearColor(16777215,.5),N.clear(),Vt&&k.render(Q);const nt=N.toneMapping;N.toneMapping=cs;const ht=Y.viewport;if(Y.viewport!==void 0&&(Y.viewport=void 0),w.setupLightsView(Y),At===!0&&re.setGlobalState(N.clippingPlanes,Y),Qt(T,Q,Y),Ke.updateMultisampleRenderTarget(Re),Ke.updateRenderTargetMipmap(Re),qe.has("WEBGL_multisampled_render_to_texture")===!1){let He=!1;for(let ut=0,jt=G.length;ut<jt;ut++){const Ct=G[ut],{object:Pt,geometry:mn,material:ke,group:cn}=Ct;if(ke.side===pi&&Pt.layers.test(Y.layers)){const gt=ke.side;ke.side=Kn,ke.needsUpdate=!0,sn(Pt,Q,Y,mn,ke,cn),ke.side=gt,ke.needsUpdate=!0,He=!0}}He===!0&&(Ke.updateMultisampleRenderTarget(Re),Ke.updateRenderTargetMipmap(Re))}N.setRenderTarget(Ce,Ie,Ge),N.setClearColor(te,_e),ht!==void 0&&(Y.viewport=ht),N.toneMapping=nt}function Qt(T,G,Q){const Y=G.isScene===!0?G.overrideMaterial:null;for(let K=0,Re=T.length;K<Re;K++){const Ne=T[K],{object:Ce,geometry:Ie,group:Ge}=Ne;let nt=Ne.material;nt.allowOverride===!0&&Y!==null&&(nt=Y),Ce.layers.test(Q.layers)&&sn(Ce,G,Q,Ie,nt,Ge)}}function sn(T,G,Q,Y,K,Re){B!==null&&K.isNodeMaterial&&B.setObject(T,K),T.onBeforeRender(N,G,Q,Y,K,Re),T.modelViewMatrix.multiplyMatrices(Q.matrixWorldInverse,T.matrixWorld),T.normalMatrix.getNormalMatrix(T.modelViewMatrix),K.onBeforeRender(N,G,Q,Y,T,Re),K.transparent===!0&&K.side===pi&&K.forceSinglePass===!1?(K.side=Kn,K.needsUpdate=!0,N.renderBufferDirect(Q,G,Y,K,T,Re),K.side=Cs,K.needsUpdate=!0,N.renderBufferDirect(Q,G,Y,K,T,Re),K.side=pi):N.renderBufferDirect(Q,G,Y,K,T,Re),T.onAfterRender(N,G,Q,Y,K,Re)}function rn(T){let G=0;for(const Q of T)Q.texture!==null&&G++;return G}function Li(T,G,Q){G.isScene!==!0&&(G=Rt);const Y=Ve.get(T),K=w.state.lights,Re=w.state.shadowsArray,Ne=K.state.version,Ce=le.getParameters(T,K.state,Re,G,Q,w.state.lightProbeGridArray),Ie=le.getProgramCacheKey(Ce);let Ge=Y.programs;Y.environment=T.isMeshStandardMaterial||T.isMeshLambertMaterial||T.isMeshPhongMaterial?G.environment:null,Y.fog=G.fog;const nt=T.isMeshStandardMaterial||T.isMeshLambertMaterial&&!T.envMap||T.isMeshPhongMaterial&&!T.envMap;Y.envMap=C.get(T.envMap||Y.environment,nt),Y.envMapRotation=Y.environment!==null&&T.envMap===null?G.environmentRotation:T.envMapRotation,Ge===void 0&&(T.addEventListener("dispose",at),Ge=new Map,Y.programs=Ge,Y.programVariants=new Map);let ht=Ge.get(Ie);if(ht!==void 0){if(Y.currentProgram===ht&&Y.lightsStateVersion===Ne)return Qr(T,Ce),ht}else Ce.uniforms=le.getUniforms(T),B!==null&&T.isNodeMaterial&&B.build(T,Q,Ce),T.onBeforeCompile(Ce,N),ht=le.acquireProgram(Ce,Ie),Ge.set(Ie,ht),Y.uniforms=Ce.uniforms;const He=Y.uniforms;return(!T.isShaderMaterial&&!T.isRawShaderMaterial||T.clipping===!0)&&(He.clippingPlanes=re.uniform),Qr(T,Ce),Y.needsLights=ps(T),Y.lightsStateVersion=Ne,Y.needsLights&&(He.ambientLightColor.value=K.state.ambient,He.lightProbe.value=K.state.probe,He.sunLights.value=K.state.sun,He.sunLightShadows.value=K.state.sunShadow,He.directionalLights.value=K.state.directional,He.directionalLightShadows.value=K.state.directionalShadow,He.spotLights.value=K.state.spot,He.spotLightShadows.value=K.state.spotShadow,He.rectAreaLights.value=K.state.rectArea,He.ltc_1.value=K.state.rectAreaLTC1,He.ltc_2.value=K.state.rectAreaLTC2,He.pointLights.value=K.state.point,He.pointLightShadows.value=K.state.pointShadow,He.hemisphereLights.value=K.state.hemi,He.sunShadowMatrix.value=K.state.sunShadowMatrix,He.sunShadowCascade.value=K.state.sunShadowCascade,He.directionalShadowMatrix.value=K.state.directionalShadowMatrix,He.spotLightMatrix.value=K.state.spotLightMatrix,He.spotLightMap.value=K.state.spotLightMap,He.pointShadowMatrix.value=K.state.pointShadowMatrix),Y.numLightProbeGrids=rn(w.state.lightProbeGridArray),Y.currentProgram=ht,Y.uniformsList=null,ht}function Zn(T,G,Q,Y,K){const Re=Ve.get(T),Ne=Re.currentProgram.id+","+Y+","+K;let Ce=Re.programVariants.get(Ne);return Ce===void 0?(Ce=Li(T,G,Q),Re.programVariants.set(Ne,Ce)):(Re.currentProgram=Ce,Re.uniformsList=null,Re.outputColorSpace=Y,Re.toneMapping=K),Ce}function fs(T){if(T.uniformsList===null){const G=T.currentProgram.getUniforms();T.uniformsList=Wo.seqWithValue(G.seq,T.uniforms)}return T.uniformsList}function Qr(T,G){const Q=Ve.get(T);Q.outputColorSpace=G.outputColorSpace,Q.batching=G.batching,Q.batchingColor=G.batchingColor,Q.instancing=G.instancing,Q.instancingColor=G.instancingColor,Q.instancingMorph=G.instancingMorph,Q.skinning=G.skinning,Q.morphTargets=G.morphTargets,Q.morphNormals=G.morphNormals,Q.morphColors=G.morphColors,Q.morphTargetsCount=G.morphTargetsCount,Q.numClippingPlanes=G.numClippingPlanes,Q.numIntersection=G.numClipIntersection,Q.vertexAlphas=G.vertexAlphas,Q.vertexTangents=G.vertexTangents,Q.toneMapping=G.toneMapping}function ea(T,G,Q,Y,K){G.isScene!==!0&&(G=Rt),Ke.resetTextureUnits();const Re=G.fog,Ne=Y.isMeshStandardMaterial||Y.isMeshLambertMaterial||Y.isMeshPhongMaterial?G.environment:null,Ce=he===null?N.outputColorSpace:he.isXRRenderTarget===!0?he.texture.colorSpace:vt.workingColorSpace,Ie=Y.isMeshStandardMaterial||Y.isMeshLambertMaterial&&!Y.envMap||Y.isMeshPhongMaterial&&!Y.envMap,Ge=C.get(Y.envMap||Ne,Ie),nt=Y.vertexColors===!0&&!!Q.attributes.color&&Q.attributes.color.itemSize===4,ht=!!Q.attributes.tangent&&(!!Y.normalMap||Y.anisotropy>0),He=!!Q.morphAttributes.position,ut=!!Q.morphAttributes.normal,jt=!!Q.morphAttributes.color;let Ct=cs;Y.toneMapped&&(he===null||he.isXRRenderTarget===!0)&&(Ct=N.toneMapping);const Pt=Q.morphAttributes.position||Q.morphAttributes.normal||Q.morphAttributes.color,mn=Pt!==void 0?Pt.length:0,ke=Ve.get(Y),cn=w.state.lights;if(At===!0&&(zt===!0||T!==ee)){const Lt=T===ee&&Y.id===J;re.setState(Y,T,Lt)}let gt=!1,Qi=!1;Y.version===ke.__version?ke.needsLights&&ke.lightsStateVersion!==cn.state.version||K.isBatchedMesh&&ke.batching===!1||!K.isBatchedMesh&&ke.batching===!0||K.isBatchedMesh&&ke.batchingColor===!0&&K._colorsTexture===null||K.isBatchedMesh&&ke.batchingColor===!1&&K._colorsTexture!==null||K.isInstancedMesh&&ke.instancing===!1||!K.isInstancedMesh&&ke.instancing===!0||K.isSkinnedMesh&&ke.skinning===!1||!K.isSkinnedMesh&&ke.skinning===!0||K.isInstancedMesh&&ke.instancingColor===!0&&K.instanceColor===null||K.isInstancedMesh&&ke.instancingColor===!1&&K.instanceColor!==null||K.isInstancedMesh&&ke.instancingMorph===!0&&K.morphTexture===null||K.isInstancedMesh&&ke.instancingMorph===!1&&K.morphTexture!==null||ke.envMap!==Ge||Y.fog===!0&&ke.fog!==Re||ke.numClippingPlanes!==void 0&&(ke.numClippingPlanes!==re.numPlanes||ke.numIntersection!==re.numIntersection)||ke.vertexAlphas!==nt||ke.vertexTangents!==ht||ke.morphTargets!==He||ke.morphNormals!==ut||ke.morphColors!==jt||ke.morphTargetsCount!==mn||ke.numLightProbeGrids!==rn(w.state.lightProbeGridArray)?gt=!0:(ke.outputColorSpace!==Ce||ke.toneMapping!==Ct)&&(Qi=!0):(gt=!0,ke.__version=Y.version);let hn=ke.currentProgram;(gt===!0||Qi===!0)&&(hn=Qi===!0?Zn(Y,G,K,Ce,Ct):Li(Y,G,K),B&&Y.isNodeMaterial&&B.onUpdateProgram(Y,hn,ke));let sr=!1,Di=!1,es=!1;const ot=hn.getUniforms(),en=ke.uniforms;if(Te.useProgram(hn.program)&&(sr=!0,Di=!0,es=!0),Y.id!==J&&(J=Y.id,Di=!0),sr||ee!==T){Te.buffers.depth.getReversed()&&T.reversedDepth!==!0&&(T._reversedDepth=!0,T.updateProjectionMatrix()),ot.setValue(O,"projectionMatrix",T.projectionMatrix),ot.setValue(O,"viewMatrix",T.matrixWorldInverse);const un=ot.map.cameraPosition;un!==void 0&&un.setValue(O,Jt.setFromMatrixPosition(T.matrixWorld)),st.logarithmicDepthBuffer&&ot.setValue(O,"logDepthBufFC",2/(Math.log(T.far+1)/Math.LN2)),(Y.isMeshPhongMaterial||Y.isMeshToonMaterial||Y.isMeshLambertMaterial||Y.isMeshBasicMaterial||Y.isMeshStandardMaterial||Y.isShaderMaterial)&&ot.setValue(O,"isOrthographic",T.isOrthographicCamera===!0),ee!==T&&(ee=T,Di=!0,es=!0)}if(ke.needsLights&&(cn.state.sunShadowMap.length>0&&ot.setValue(O,"sunShadowMap",cn.state.sunShadowMap,Ke),cn.state.directionalShadowMap.length>0&&ot.setValue(O,"directionalShadowMap",cn.state.directionalShadowMap,Ke),cn.state.spotShadowMap.length>0&&ot.setValue(O,"spotShadowMap",cn.state.spotShadowMap,Ke),cn.state.pointShadowMap.length>0&&ot.setValue(O,"pointShadowMap",cn.state.pointShadowMap,Ke)),K.isSkinnedMesh){ot.setOptional(O,K,"bindMatrix"),ot.setOptional(O,K,"bindMatrixInverse");const Lt=K.skeleton;Lt&&(Lt.boneTexture===null&&Lt.computeBoneTexture(),ot.setValue(O,"boneTexture",Lt.boneTexture,Ke))}K.isBatchedMesh&&(ot.setOptional(O,K,"batchingTexture"),ot.setValue(O,"batchingTexture",K._matricesTexture,Ke),ot.setOptional(O,K,"batchingIdTexture"),ot.setValue(O,"batchingIdTexture",K._indirectTexture,Ke),ot.setOptional(O,K,"batchingColorTexture"),K._colorsTexture!==null&&ot.setValue(O,"batchingColorTexture",K._colorsTexture,Ke));const kn=Q.morphAttributes;if((kn.position!==void 0||kn.normal!==void 0||kn.color!==void 0)&&ae.update(K,Q,hn),(Di||ke.receiveShadow!==K.receiveShadow)&&(ke.receiveShadow=K.receiveShadow,ot.setValue(O,"receiveShadow",K.receiveShadow)),(Y.isMeshStandardMaterial||Y.isMeshLambertMaterial||Y.isMeshPhongMaterial)&&Y.envMap===null&&G.environment!==null&&(en.envMapIntensity.value=G.environmentIntensity),en.dfgLUT!==void 0&&(en.dfgLUT.value=RM()),Di){if(ot.setValue(O,"toneMappingExposure",N.toneMappingExposure),ke.needsLights&&nr(en,es),Re&&Y.fog===!0&&ye.refreshFogUniforms(en,Re),ye.refreshMaterialUniforms(en,Y,Me,Pe,w.state.transmissionRenderTarget[T.id]),ke.needsLights&&ke.numLightProbeGrids>0){const Lt=y;let un=0;for(const Dn of w.state.lightProbeGridArray)Dn.texture!==null&&(Lt.textures[un]=Dn.texture,Lt.min[un]=Dn.boundingBox.min,Lt.max[un]=Dn.boundingBox.max,Lt.resolution[un]=Dn.resolution,un++);for(const Dn in Lt)Lt[Dn].length=un;en.probesSH.value=Lt.textures,en.probesMin.value=Lt.min,en.probesMax.value=Lt.max,en.probesResolution.value=Lt.resolution}Wo.upload(O,fs(ke),en,Ke)}if(Y.isShaderMaterial&&Y.uniformsNeedUpdate===!0&&(Wo.upload(O,fs(ke),en,Ke),Y.uniformsNeedUpdate=!1),Y.isSpriteMaterial&&ot.setValue(O,"center",K.center),ot.setValue(O,"modelViewMatrix",K.modelViewMatrix),ot.setValue(O,"normalMatrix",K.normalMatrix),ot.setValue(O,"modelMatrix",K.matrixWorld),Y.uniformsGroups!==void 0){const Lt=Y.uniformsGroups;for(let un=0,Dn=Lt.length;un<Dn;un++){const Ya=Lt[un];We.update(Ya,hn),We.bind(Ya,hn)}}return hn}function nr(T,G){T.ambientLightColor.needsUpdate=G,T.lightProbe.needsUpdate=G,T.sunLights.needsUpdate=G,T.sunLightShadows.needsUpdate=G,T.directionalLights.needsUpdate=G,T.directionalLightShadows.needsUpdate=G,T.pointLights.needsUpdate=G,T.pointLightShadows.needsUpdate=G,T.spotLights.needsUpdate=G,T.spotLightShadows.needsUpdate=G,T.rectAreaLights.needsUpdate=G,T.hemisphereLights.needsUpdate=G}function ps(T){return T.isMeshLambertMaterial||T.isMeshToonMaterial||T.isMeshPhongMaterial||T.isMeshStandardMaterial||T.isShadowMaterial||T.isShaderMaterial&&T.lights===!0}this.getActiveCubeFace=function(){return Z},this.getActiveMipmapLevel=function(){return H},this.getRenderTarget=function(){return he},this.setRenderTargetTextures=function(T,G,Q){const Y=Ve.get(T);Y.__autoAllocateDepthBuffer=T.resolveDepthBuffer===!1,Y.__autoAllocateDepthBuffer===!1&&(Y.__useRenderToTexture=!1),Ve.get(T.texture).__webglTexture=G,Ve.get(T.depthTexture).__webglTexture=Y.__autoAllocateDepthBuffer?void 0:Q,Y.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(T,G){const Q=Ve.get(T);Q.__webglFramebuffer=G,Q.__useDefaultFramebuffer=G===void 0},this.setRenderTarget=function(T,G=0,Q=0){he=T,Z=G,H=Q;let Y=null,K=!1,Re=!1;if(T){const Ce=Ve.get(T);if(Ce.__useDefaultFramebuffer!==void 0){Te.bindFramebuffer(O.FRAMEBUFFER,Ce.__webglFramebuffer),se.copy(T.viewport),pe.copy(T.scissor),fe=T.scissorTest,Te.viewport(se),Te.scissor(pe),Te.setScissorTest(fe),J=-1;return}else if(Ce.__webglFramebuffer===void 0)Ke.setupRenderTarget(T);else if(Ce.__hasExternalTextures)Ke.rebindTextures(T,Ve.get(T.texture).__webglTexture,Ve.get(T.depthTexture).__webglTexture);else if(T.depthBuffer){const nt=T.depthTexture;if(Ce.__boundDepthTexture!==nt){if(nt!==null&&Ve.has(nt)&&(T.width!==nt.image.width||T.height!==nt.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Ke.setupDepthRenderbuffer(T)}}const Ie=T.texture;(Ie.isData3DTexture||Ie.isDataArrayTexture||Ie.isCompressedArrayTexture)&&(Re=!0);const Ge=Ve.get(T).__webglFramebuffer;T.isWebGLCubeRenderTarget?(Array.isArray(Ge[G])?Y=Ge[G][Q]:Y=Ge[G],K=!0):T.samples>0&&Ke.useMultisampledRTT(T)===!1?Y=Ve.get(T).__webglMultisampledFramebuffer:Array.isArray(Ge)?Y=Ge[Q]:Y=Ge,se.copy(T.viewport),pe.copy(T.scissor),fe=T.scissorTest}else se.copy(ve).multiplyScalar(Me).floor(),pe.copy(Xe).multiplyScalar(Me).floor(),fe=Ze;if(Q!==0&&(Y=V),Te.bindFramebuffer(O.FRAMEBUFFER,Y)&&Te.drawBuffers(T,Y),Te.viewport(se),Te.scissor(pe),Te.setScissorTest(fe),K){const Ce=Ve.get(T.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_CUBE_MAP_POSITIVE_X+G,Ce.__webglTexture,Q)}else if(Re){const Ce=G;for(let Ie=0;Ie<T.textures.length;Ie++){const Ge=Ve.get(T.textures[Ie]);O.framebufferTextureLayer(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0+Ie,Ge.__webglTexture,Q,Ce)}}else if(T!==null&&Q!==0){const Ce=Ve.get(T.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,Ce.__webglTexture,Q)}J=-1};function ir(T){const G=Ve.get(T);return(G.__readFormat!==T.format||G.__readType!==T.type)&&(G.__readFormat=T.format,G.__readType=T.type,G.__formatReadable=st.textureFormatReadable(T.format),G.__typeReadable=st.textureTypeReadable(T.type)),G}this.readRenderTargetPixels=function(T,G,Q,Y,K,Re,Ne,Ce=0){if(!(T&&T.isWebGLRenderTarget)){St("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Ie=Ve.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Ne!==void 0&&(Ie=Ie[Ne],Array.isArray(Ie)&&(Ie=Ie[0])),Ie){Te.bindFramebuffer(O.FRAMEBUFFER,Ie);try{const Ge=T.textures[Ce],nt=Ge.format,ht=Ge.type;T.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Ce);const He=ir(Ge);if(He.__formatReadable===!1){St("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(He.__typeReadable===!1){St("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}G>=0&&G<=T.width-Y&&Q>=0&&Q<=T.height-K&&O.readPixels(G,Q,Y,K,Se.convert(nt),Se.convert(ht),Re)}finally{const Ge=he!==null?Ve.get(he).__webglFramebuffer:null;Te.bindFramebuffer(O.FRAMEBUFFER,Ge)}}},this.readRenderTargetPixelsAsync=async function(T,G,Q,Y,K,Re,Ne,Ce=0){if(!(T&&T.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Ie=Ve.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Ne!==void 0&&(Ie=Ie[Ne],Array.isArray(Ie)&&(Ie=Ie[0])),Ie)if(G>=0&&G<=T.width-Y&&Q>=0&&Q<=T.height-K){Te.bindFramebuffer(O.FRAMEBUFFER,Ie);const Ge=T.textures[Ce],nt=Ge.format,ht=Ge.type;T.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Ce);const He=ir(Ge);if(He.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(He.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");const ut=O.createBuffer();O.bindBuffer(O.PIXEL_PACK_BUFFER,ut),O.bufferData(O.PIXEL_PACK_BUFFER,Re.byteLength,O.STREAM_READ),O.readPixels(G,Q,Y,K,Se.convert(nt),Se.convert(ht),0),O.bindBuffer(O.PIXEL_PACK_BUFFER,null);const jt=he!==null?Ve.get(he).__webglFramebuffer:null;Te.bindFramebuffer(O.FRAMEBUFFER,jt);const Ct=O.fenceSync(O.SYNC_GPU_COMMANDS_COMPLETE,0);return O.flush(),await $0(O,Ct,4),O.bindBuffer(O.PIXEL_PACK_BUFFER,ut),O.getBufferSubData(O.PIXEL_PACK_BUFFER,0,Re),O.bindBuffer(O.PIXEL_PACK_BUFFER,null),O.deleteBuffer(ut),O.deleteSync(Ct),Re}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(T,G=null,Q=0){const Y=Math.pow(2,-Q),K=Math.floor(T.image.width*Y),Re=Math.floor(T.image.height*Y),Ne=G!==null?G.x:0,Ce=G!==null?G.y:0;Ke.setTexture2D(T,0),O.copyTexSubImage2D(O.TEXTURE_2D,Q,0,0,Ne,Ce,K,Re),Te.unbindTexture()},this.copyTextureToTexture=function(T,G,Q=null,Y=null,K=0,Re=0){let Ne,Ce,Ie,Ge,nt,ht,He,ut,jt;const Ct=T.isCompressedTexture?T.mipmaps[Re]:T.image;if(Q!==null)Ne=Q.max.x-Q.min.x,Ce=Q.max.y-Q.min.y,Ie=Q.isBox3?Q.max.z-Q.min.z:1,Ge=Q.min.x,nt=Q.min.y,ht=Q.isBox3?Q.min.z:0;else{const ot=Math.pow(2,-K);Ne=Math.floor(Ct.width*ot),Ce=Math.floor(Ct.height*ot),T.isDataArrayTexture?Ie=Ct.depth:T.isData3DTexture?Ie=Math.floor(Ct.depth*ot):Ie=1,Ge=0,nt=0,ht=0}Y!==null?(He=Y.x,ut=Y.y,jt=Y.z):(He=0,ut=0,jt=0);const Pt=Se.convert(G.format),mn=Se.convert(G.type);let ke;G.isData3DTexture?(Ke.setTexture3D(G,0),ke=O.TEXTURE_3D):G.isDataArrayTexture||G.isCompressedArrayTexture?(Ke.setTexture2DArray(G,0),ke=O.TEXTURE_2D_ARRAY):(Ke.setTexture2D(G,0),ke=O.TEXTURE_2D),Te.activeTexture(O.TEXTURE0),Te.pixelStorei(O.UNPACK_FLIP_Y_WEBGL,G.flipY),Te.pixelStorei(O.UNPACK_PREMULTIPLY_ALPHA_WEBGL,G.premultiplyAlpha),Te.pixelStorei(O.UNPACK_ALIGNMENT,G.unpackAlignment);const cn=Te.getParameter(O.UNPACK_ROW_LENGTH),gt=Te.getParameter(O.UNPACK_IMAGE_HEIGHT),Qi=Te.getParameter(O.UNPACK_SKIP_PIXELS),hn=Te.getParameter(O.UNPACK_SKIP_ROWS),sr=Te.getParameter(O.UNPACK_SKIP_IMAGES);Te.pixelStorei(O.UNPACK_ROW_LENGTH,Ct.width),Te.pixelStorei(O.UNPACK_IMAGE_HEIGHT,Ct.height),Te.pixelStorei(O.UNPACK_SKIP_PIXELS,Ge),Te.pixelStorei(O.UNPACK_SKIP_ROWS,nt),Te.pixelStorei(O.UNPACK_SKIP_IMAGES,ht);const Di=T.isDataArrayTexture||T.isData3DTexture,es=G.isDataArrayTexture||G.isData3DTexture;if(T.isDepthTexture){const ot=Ve.get(T),en=Ve.get(G),kn=Ve.get(ot.__renderTarget),Lt=Ve.get(en.__renderTarget);Te.bindFramebuffer(O.READ_FRAMEBUFFER,kn.__webglFramebuffer),Te.bindFramebuffer(O.DRAW_FRAMEBUFFER,Lt.__webglFramebuffer);for(let un=0;un<Ie;un++)Di&&(O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Ve.get(T).__webglTexture,K,ht+un),O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Ve.get(G).__webglTexture,Re,jt+un)),O.blitFramebuffer(Ge,nt,Ge+Ne,nt+Ce,He,ut,He+Ne,ut+Ce,O.DEPTH_BUFFER_BIT,O.NEAREST);Te.bindFramebuffer(O.READ_FRAMEBUFFER,null),Te.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else if(K!==0||T.isRenderTargetTexture||Ve.has(T)){const ot=Ve.get(T),en=Ve.get(G);Te.bindFramebuffer(O.READ_FRAMEBUFFER,U),Te.bindFramebuffer(O.DRAW_FRAMEBUFFER,W);for(let kn=0;kn<Ie;kn++)Di?O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,ot.__webglTexture,K,ht+kn):O.framebufferTexture2D(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,ot.__webglTexture,K),es?O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,en.__webglTexture,Re,jt+kn):O.framebufferTexture2D(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,en.__webglTexture,Re),K!==0?O.blitFramebuffer(Ge,nt,Ge+Ne,nt+Ce,He,ut,He+Ne,ut+Ce,O.COLOR_BUFFER_BIT,O.NEAREST):es?O.copyTexSubImage3D(ke,Re,He,ut,jt+kn,Ge,nt,Ne,Ce):O.copyTexSubImage2D(ke,Re,He,ut,Ge,nt,Ne,Ce);Te.bindFramebuffer(O.READ_FRAMEBUFFER,null),Te.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else es?T.isDataTexture||T.isData3DTexture?O.texSubImage3D(ke,Re,He,ut,jt,Ne,Ce,Ie,Pt,mn,Ct.data):G.isCompressedArrayTexture?O.compressedTexSubImage3D(ke,Re,He,ut,jt,Ne,Ce,Ie,Pt,Ct.data):O.texSubImage3D(ke,Re,He,ut,jt,Ne,Ce,Ie,Pt,mn,Ct):T.isDataTexture?O.texSubImage2D(O.TEXTURE_2D,Re,He,ut,Ne,Ce,Pt,mn,Ct.data):T.isCompressedTexture?O.compressedTexSubImage2D(O.TEXTURE_2D,Re,He,ut,Ct.width,Ct.height,Pt,Ct.data):O.texSubImage2D(O.TEXTURE_2D,Re,He,ut,Ne,Ce,Pt,mn,Ct);Te.pixelStorei(O.UNPACK_ROW_LENGTH,cn),Te.pixelStorei(O.UNPACK_IMAGE_HEIGHT,gt),Te.pixelStorei(O.UNPACK_SKIP_PIXELS,Qi),Te.pixelStorei(O.UNPACK_SKIP_ROWS,hn),Te.pixelStorei(O.UNPACK_SKIP_IMAGES,sr),Re===0&&G.generateMipmaps===!0&&G.mipmapsAutoUpdate===!0&&O.generateMipmap(ke),Te.unbindTexture()},this.initRenderTarget=function(T){Ve.get(T).__webglFramebuffer===void 0&&Ke.setupRenderTarget(T)},this.initTexture=function(T){T.isCubeTexture?Ke.setTextureCube(T,0):T.isData3DTexture?Ke.setTexture3D(T,0):T.isDataArrayTexture||T.isCompressedArrayTexture?Ke.setTexture2DArray(T,0):Ke.setTexture2D(T,0),Te.unbindTexture()},this.resetState=function(){Z=0,H=0,he=null,Te.reset(),Ee.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Ci}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;const t=this.getContext();t.drawingBufferColorSpace=vt._getDrawingBufferColorSpace(e),t.unpackColorSpace=vt._getUnpackColorSpace()}}const Zd={type:"change"},su={type:"start"},dm={type:"end"},Ao=new cl,Jd=new Ai,CM=Math.cos(70*Z0.DEG2RAD),_n=new z,Xn=2*Math.PI,Et={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},pc=1e-6;class fm extends U_{constructor(e,t=null){super(e,t),this.state=Et.NONE,this.target=new z,this.cursor=new z,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:Ir.ROTATE,MIDDLE:Ir.DOLLY,RIGHT:Ir.PAN},this.touches={ONE:Nr.ROTATE,TWO:Nr.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new z,this._lastQuaternion=new Ls,this._lastTargetPosition=new z,this._quat=new Ls().setFromUnitVectors(e.up,new z(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new bh,this._sphericalDelta=new bh,this._scale=1,this._panOffset=new z,this._rotateStart=new Ye,this._rotateEnd=new Ye,this._rotateDelta=new Ye,this._panStart=new Ye,this._panEnd=new Ye,this._panDelta=new Ye,this._dollyStart=new Ye,this._dollyEnd=new Ye,this._dollyDelta=new Ye,this._dollyDirection=new z,this._mouse=new Ye,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=LM.bind(this),this._onPointerDown=PM.bind(this),this._onPointerUp=DM.bind(this),this._onContextMenu=BM.bind(this),this._onMouseWheel=UM.bind(this),this._onKeyDown=FM.bind(this),this._onTouchStart=OM.bind(this),this._onTouchMove=kM.bind(this),this._onMouseDown=NM.bind(this),this._onMouseMove=IM.bind(this),this._interceptControlDown=zM.bind(this),this._interceptControlUp=HM.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Et.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(Zd),this.update(),this.state=Et.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){const t=this.object.position;_n.copy(t).sub(this.target),_n.applyQuaternion(this._quat),this._spherical.setFromVector3(_n),this.autoRotate&&this.state===Et.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let n=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(n)&&isFinite(s)&&(n<-Math.PI?n+=Xn:n>Math.PI&&(n-=Xn),s<-Math.PI?s+=Xn:s>Math.PI&&(s-=Xn),n<=s?this._spherical.theta=Math.max(n,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(n+s)/2?Math.max(n,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{const a=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=a!=this._spherical.radius}if(_n.setFromSpherical(this._spherical),_n.applyQuaternion(this._quatInverse),t.copy(this.target).add(_n),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let a=null;if(this.object.isPerspectiveCamera){const o=_n.length();a=this._clampDistance(o*this._scale);const l=o-a;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),r=!!l}else if(this.object.isOrthographicCamera){const o=new z(this._mouse.x,this._mouse.y,0);o.unproject(this.object);const l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=l!==this.object.zoom;const c=new z(this._mouse.x,this._mouse.y,0);c.unproject(this.object),this.object.position.sub(c).add(o),this.object.updateMatrixWorld(),a=_n.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;a!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(a).add(this.object.position):(Ao.origin.copy(this.object.position),Ao.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(Ao.direction))<CM?this.object.lookAt(this.target):(Jd.setFromNormalAndCoplanarPoint(this.object.up,this.target),Ao.intersectPlane(Jd,this.target))))}else if(this.object.isOrthographicCamera){const a=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),a!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>pc||8*(1-this._lastQuaternion.dot(this.object.quaternion))>pc||this._lastTargetPosition.distanceToSquared(this.target)>pc?(this.dispatchEvent(Zd),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?Xn/60*this.autoRotateSpeed*e:Xn/60/60*this.autoRotateSpeed}_getZoomScale(e){const t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){_n.setFromMatrixColumn(t,0),_n.multiplyScalar(-e),this._panOffset.add(_n)}_panUp(e,t){this.screenSpacePanning===!0?_n.setFromMatrixColumn(t,1):(_n.setFromMatrixColumn(t,0),_n.crossVectors(this.object.up,_n)),_n.multiplyScalar(e),this._panOffset.add(_n)}_pan(e,t){const n=this.domElement;if(this.object.isPerspectiveCamera){const s=this.object.position;_n.copy(s).sub(this.target);let r=_n.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/n.clientHeight,this.object.matrix),this._panUp(2*t*r/n.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/n.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/n.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;const n=this.domElement.getBoundingClientRect(),s=e-n.left,r=t-n.top,a=n.width,o=n.height;this._mouse.x=s/a*2-1,this._mouse.y=-(r/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(Xn*this._rotateDelta.x/t.clientHeight),this._rotateUp(Xn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(Xn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-Xn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(Xn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-Xn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._rotateStart.set(n,s)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panStart.set(n,s)}}_handleTouchStartDolly(e){const t=this._getSecondPointerPosition(e),n=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(n*n+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{const n=this._getSecondPointerPosition(e),s=.5*(e.pageX+n.x),r=.5*(e.pageY+n.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(Xn*this._rotateDelta.x/t.clientHeight),this._rotateUp(Xn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panEnd.set(n,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){const t=this._getSecondPointerPosition(e),n=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(n*n+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);const a=(e.pageX+t.x)*.5,o=(e.pageY+t.y)*.5;this._updateZoomParameters(a,o)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new Ye,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){const t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){const t=e.deltaMode,n={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:n.deltaY*=16;break;case 2:n.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(n.deltaY*=10),n}}function PM(i){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(i.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(i)&&(this._addPointer(i),i.pointerType==="touch"?this._onTouchStart(i):this._onMouseDown(i),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function LM(i){this.enabled!==!1&&(i.pointerType==="touch"?this._onTouchMove(i):this._onMouseMove(i))}function DM(i){switch(this._removePointer(i),this._pointers.length){case 0:this.domElement.releasePointerCapture(i.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(dm),this.state=Et.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:const e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function NM(i){let e;switch(i.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case Ir.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(i),this.state=Et.DOLLY;break;case Ir.ROTATE:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Et.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Et.ROTATE}break;case Ir.PAN:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Et.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Et.PAN}break;default:this.state=Et.NONE}this.state!==Et.NONE&&this.dispatchEvent(su)}function IM(i){switch(this.state){case Et.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(i);break;case Et.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(i);break;case Et.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(i);break}}function UM(i){this.enabled===!1||this.enableZoom===!1||this.state!==Et.NONE||(i.preventDefault(),this.dispatchEvent(su),this._handleMouseWheel(this._customWheelEvent(i)),this.dispatchEvent(dm))}function FM(i){this.enabled!==!1&&this._handleKeyDown(i)}function OM(i){switch(this._trackPointer(i),this._pointers.length){case 1:switch(this.touches.ONE){case Nr.ROTATE:if(this.enableRotate===!1){this.state=Et.NONE;break}this._handleTouchStartRotate(i),this.state=Et.TOUCH_ROTATE;break;case Nr.PAN:if(this.enablePan===!1){this.state=Et.NONE;break}this._handleTouchStartPan(i),this.state=Et.TOUCH_PAN;break;default:this.state=Et.NONE}break;case 2:switch(this.touches.TWO){case Nr.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(i),this.state=Et.TOUCH_DOLLY_PAN;break;case Nr.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(i),this.state=Et.TOUCH_DOLLY_ROTATE;break;default:this.state=Et.NONE}break;default:this.state=Et.NONE}this.state!==Et.NONE&&this.dispatchEvent(su)}function kM(i){switch(this._trackPointer(i),this.state){case Et.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(i),this.update();break;case Et.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(i),this.update();break;case Et.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(i),this.update();break;case Et.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(i),this.update();break;default:this.state=Et.NONE}}function BM(i){this.enabled!==!1&&i.preventDefault()}function zM(i){i.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function HM(i){i.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}class GM{constructor(e){const t=new Jp;t.aspect=.5;const n=new Ye;this.setEyeSeparation=function(s){t.eyeSep=s},this.setSize=function(s,r){e.setSize(s,r)},this.render=function(s,r){s.matrixWorldAutoUpdate===!0&&s.updateMatrixWorld(),r.parent===null&&r.matrixWorldAutoUpdate===!0&&r.updateMatrixWorld(),t.update(r);const a=e.autoClear;e.getSize(n),e.autoClear=!1,e.clear(),e.setScissorTest(!0),e.setScissor(0,0,n.width/2,n.height),e.setViewport(0,0,n.width/2,n.height),e.render(s,t.cameraL),e.setScissor(n.width/2,0,n.width/2,n.height),e.setViewport(n.width/2,0,n.width/2,n.height),e.render(s,t.cameraR),e.setScissorTest(!1),e.autoClear=a}}}const Ro=(i,e)=>i[0]*e[0]+i[1]*e[1]+i[2]*e[2],mc=(i,e)=>[i[0]+e[0],i[1]+e[1],i[2]+e[2]],gc=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]],Hi=(i,e)=>[i[0]*e,i[1]*e,i[2]*e];function VM(i,e){return 4*Math.sqrt(Math.max(Math.abs(e),1)*Math.max(i,0))}function WM(i,e,t,n,s){const r=Math.hypot(...t),a=Math.hypot(...i.direction);if(!(r>0)||!(a>0)||!(n>0)||!Number.isFinite(r)||!Number.isFinite(a)||![...e,...i.origin].every(Number.isFinite))return null;const o=Hi(t,1/r),l=Hi(i.direction,1/a),c=mc(e,t),h=gc(c,i.origin),u=Ro(o,l),d=Math.abs(u)>1e-9?Ro(o,h)/u:-1,m=d>0?mc(i.origin,Hi(l,d)):mc(i.origin,Hi(l,Math.max(Ro(h,l),0)));let _=gc(m,c);_=gc(_,Hi(o,Ro(_,o)));let S=Hi(_,1/n);const p=Math.hypot(...S);if(!Number.isFinite(p))return null;const f=Math.max(s,0);return p>f?(S=p>0?Hi(S,f/p):[0,0,0],{v:S,speed:f,capped:!0}):{v:S,speed:p,capped:!1}}function XM(i,e,t,n){const s=Hi(e,t),r=Math.hypot(...s);if(r>=n)return s;if(r>1e-12*n)return Hi(s,n/r);const a=[-i[1],i[0],0],o=Math.hypot(...a);return o>1e-12*Math.hypot(...i)&&o>0?Hi(a,n/o):[n,0,0]}function $M(i,e,t){const n=i.intersectSphere(new Va(e,t),new z);if(n!==null)return n.sub(e);const s=i.closestPointToPoint(e,new z).sub(e),r=s.length();return r>0?s.multiplyScalar(t/r):new z(0,0,-t)}class qM{constructor(e,t,n,s,r,a){this.canvas=e,this.camera=t,this.controls=n,this.bob=s,this.onDrag=r,this.sphere=a,e.addEventListener("pointerdown",o=>this.down(o),{capture:!0}),e.addEventListener("pointermove",o=>this.move(o)),e.addEventListener("pointerup",o=>this.up(o)),e.addEventListener("pointercancel",o=>this.up(o))}canvas;camera;controls;bob;onDrag;sphere;dragging=!1;raycaster=new jp;get active(){return this.dragging}ray(e){const t=this.canvas.getBoundingClientRect(),n=new Ye((e.clientX-t.left)/t.width*2-1,-((e.clientY-t.top)/t.height)*2+1);return this.raycaster.setFromCamera(n,this.camera),this.raycaster.ray}position(e){const{pivot:t,length:n}=this.sphere(),s=$M(this.ray(e),t,n);return[s.x,s.y,s.z]}down(e){e.button!==0||!this.bob.visible||(this.ray(e),this.raycaster.intersectObject(this.bob,!1).length!==0&&(this.dragging=!0,this.controls.enabled=!1,this.canvas.setPointerCapture?.(e.pointerId),e.stopImmediatePropagation(),this.onDrag(this.position(e),"start")))}move(e){this.dragging&&this.onDrag(this.position(e),"move")}up(e){this.dragging&&(this.dragging=!1,this.controls.enabled=!0,this.onDrag(this.position(e),"end"))}}class YM{constructor(e,t,n,s,r,a,o,l){this.canvas=e,this.camera=t,this.controls=n,this.handle=s,this.occluder=r,this.grabRadius=a,this.pullBasis=o,this.onPull=l,e.addEventListener("pointerdown",c=>this.down(c),{capture:!0}),e.addEventListener("pointermove",c=>this.move(c)),e.addEventListener("pointerup",c=>this.up(c)),e.addEventListener("pointercancel",c=>this.up(c))}canvas;camera;controls;handle;occluder;grabRadius;pullBasis;onPull;basis=null;moved=!1;raycaster=new jp;tmp=new z;get active(){return this.basis!==null}ray(e){const t=this.canvas.getBoundingClientRect(),n=new Ye((e.clientX-t.left)/t.width*2-1,-((e.clientY-t.top)/t.height)*2+1);return this.raycaster.setFromCamera(n,this.camera),this.raycaster.ray}pulled(e){if(this.basis===null)return null;const t=this.ray(e),{pivot:n,x:s,arrowScale:r,vmax:a}=this.basis;return WM({origin:[t.origin.x,t.origin.y,t.origin.z],direction:[t.direction.x,t.direction.y,t.direction.z]},n,s,r,a)}down(e){if(e.button!==0||!this.handle.visible)return;const t=this.ray(e),n=this.handle.getWorldPosition(this.tmp),s=this.grabRadius();if(t.distanceToPoint(n)>s)return;const r=this.raycaster.intersectObject(this.occluder,!1)[0];if(r!==void 0&&r.distance<n.sub(t.origin).dot(t.direction)-s)return;const a=this.pullBasis();a!==null&&(this.basis=a,this.moved=!1,this.controls.enabled=!1,this.canvas.setPointerCapture?.(e.pointerId),e.stopImmediatePropagation(),this.onPull(a.x,null,"start"))}move(e){this.basis!==null&&(this.moved=!0,this.onPull(this.basis.x,this.pulled(e),"move"))}up(e){if(this.basis===null)return;const t=this.moved?this.pulled(e):null,n=this.basis.x;this.basis=null,this.controls.enabled=!0,this.onPull(n,t,"end")}}const Cn=180/Math.PI;function Fa(i){return{theta:Math.atan2(Math.hypot(i[0],i[1]),-i[2]),phi:Math.atan2(i[1],i[0])}}function KM(i){let e=i%(2*Math.PI);return e<=-Math.PI&&(e+=2*Math.PI),e>Math.PI&&(e-=2*Math.PI),e}class ZM{constructor(e=8){this.maxLaps=e}maxLaps;acc=0;since=null;laps=[];get running(){return this.since!==null}reading(e){return this.acc+(this.since===null?0:Math.max(0,e-this.since))}start(e){this.since===null&&(this.since=e)}stop(e){this.since!==null&&(this.acc=this.reading(e),this.since=null)}lap(e){this.laps.push(this.reading(e)),this.laps.length>this.maxLaps&&this.laps.shift()}reset(){[this.acc,this.since,this.laps]=[0,null,[]]}}const Co={kind:null,period:null,advance:null,precession:null,lowPerPeriod:1,intervals:0,amplitude:null,thetaMin:null,thetaMax:null,from:null,to:null};class JM{constructor(e=1e-7,t=10,n=.02){this.minRise=e,this.keep=t,this.planarRatio=n}minRise;keep;planarRatio;prev=null;phi=0;lows=[];zLow=1/0;zHigh=-1/0;rMax=0;thMax=0;thMin=1/0;reset(){this.prev=null,this.phi=0,this.lows=[],this.zLow=1/0,this.zHigh=-1/0,this.rMax=0,this.thMax=0,this.thMin=1/0}push(e){const t=this.prev;if(t!==null&&e.t<=t.t)return;const n=Math.atan2(e.x[1],e.x[0]),s=Math.hypot(e.x[0],e.x[1]),r=Math.atan2(s,-e.x[2]);if(t===null){this.phi=n,this.prev=e,this.zLow=this.zHigh=e.x[2],[this.rMax,this.thMax,this.thMin]=[s,r,r];return}const a=this.phi;this.phi=a+KM(n-Math.atan2(t.x[1],t.x[0])),this.zLow=Math.min(this.zLow,e.x[2]),this.zHigh=Math.max(this.zHigh,e.x[2]);const[o,l]=[t.v[2],e.v[2]];if(o<0&&l>=0){const c=o===l?0:-o/(l-o),h=t.t+c*(e.t-t.t),u=a+c*(this.phi-a);if(this.lows.length===0||this.zHigh-this.zLow>this.minRise){const d=(y,A)=>y+c*(A-y),m=d(t.x[0],e.x[0]),_=d(t.x[1],e.x[1]),S=d(t.v[0],e.v[0]),p=d(t.v[1],e.v[1]),f=Math.hypot(S,p)||1,x=Math.hypot(m,_),R=Math.max(this.rMax,x);this.lows.push({t:h,phi:u,dir:[S/f,p/f],through:R>0&&x<=this.planarRatio*R,thetaMax:this.thMax,thetaMin:Math.min(this.thMin,r)}),this.lows.length>2*this.keep+1&&this.lows.shift()}this.zLow=this.zHigh=e.x[2],[this.rMax,this.thMax,this.thMin]=[s,r,r],this.prev=e;return}this.rMax=Math.max(this.rMax,s),this.thMax=Math.max(this.thMax,r),this.thMin=Math.min(this.thMin,r),this.prev=e}reading(){const e=this.lows,t=e[e.length-1];if(t===void 0||e.length<2)return{...Co};const n={thetaMin:Math.min(t.thetaMin,this.thMin),thetaMax:Math.max(t.thetaMax,this.thMax)};if(t.through){const l=[];let c=0;for(let p=e.length-1;p>=0&&l.length<=this.keep;p--){const f=e[p];if(!f.through)break;f.dir[0]*t.dir[0]+f.dir[1]*t.dir[1]>0&&l.push(f),c=p}const h=l.length-1,u=l[h],d=e[e.length-2],m=d.dir[0]*t.dir[0]+d.dir[1]*t.dir[1]>0?1:2,_=e.slice(Math.max(c,e.indexOf(u))+1),S=_.length>0?Math.sqrt(_.reduce((p,f)=>p+f.thetaMax**2,0)/_.length):t.thetaMax;return{...Co,kind:"swing",period:h<1?null:(t.t-u.t)/h,lowPerPeriod:m,intervals:Math.max(h,0),amplitude:S,...n,from:h<1?null:u.t,to:t.t}}let s=e.length-1;for(;s>0&&e.length-1-s<this.keep&&!e[s-1].through;)s--;const r=e[s],a=e.length-1-s;if(a<1)return{...Co,kind:"orbit",...n};const o=(t.phi-r.phi)/a;return{...Co,kind:"orbit",period:(t.t-r.t)/a,advance:o,precession:Math.sign(o)*(2*Math.abs(o)-2*Math.PI),intervals:a,...n,from:r.t,to:t.t}}}function jM(i){let[e,t]=[1,Math.sqrt(1-i)];for(let n=0;n<40&&Math.abs(e-t)>1e-16*e;n++)[e,t]=[(e+t)/2,Math.sqrt(e*t)];return Math.PI/(2*e)}function QM(i,e,t,n){if(!(e>0)||!(i>0)||!(n>=0)||n>=Math.PI)return null;const s=e/i,r=Math.sqrt(s-t**2/4);return r>0?4*jM(Math.sin(n/2)**2)/r:null}function jd(i,e,t,n,s){const r=.5*e*(i.v[0]**2+i.v[1]**2+i.v[2]**2),a=i.energy-r+e*Math.abs(t)*n,o=-s;return{kinetic:r,potential:a,lost:o,total:r+a+o}}function eb(i,e){return .5*(i.power+e.power)*(e.t-i.t)}function tb(i,e,t=null){const n=i.kind===null?e?.kind==="planar":i.kind==="swing",s=e===null||e.period_z_infinite||e.period_z===null?null:e.period_z;let r=s;n&&s!==null&&e?.kind!=="planar"&&(r=i.lowPerPeriod*s),e===null&&(r=t);const a=e?.azimuth_advance??null,o=l=>l===null?null:Math.sign(l)*(2*Math.abs(l)-2*Math.PI);return{swing:n,period:[i.period,r],advance:[n?null:i.advance,n?null:a],precession:[n?null:i.precession,n?null:o(a)]}}const Qd=512,$s=4e3,nb=4e3,ib=2e5,sb=3,rb=["t [s]","x1 [m]","x2 [m]","x3 [m]","v1 [m/s]","v2 [m/s]","v3 [m/s]","energy [J]","j3 [kg m^2/s]","tension [N]","power [W]","a1 [m/s^2]","a2 [m/s^2]","a3 [m/s^2]","pivot1 [m]","pivot2 [m]","pivot3 [m]","taut [1]","error_x [m]"];function ef(){return{t:[],dE:[],dJ3:[],z:[],zdot:[],tension:[],frames:[]}}function Bi(i,e,t){return i+(e-i)*t}function ab(i,e,t){const n=(o,l)=>[Bi(o[0],l[0],t),Bi(o[1],l[1],t),Bi(o[2],l[2],t)],s=n(i.x,e.x),r=Bi(Math.hypot(...i.x),Math.hypot(...e.x),t),a=Math.hypot(...s);if(a>0)for(let o=0;o<3;o++)s[o]=s[o]*(r/a);return{t:Bi(i.t,e.t,t),x:s,v:n(i.v,e.v),energy:Bi(i.energy,e.energy,t),j3:Bi(i.j3,e.j3,t),tension:Bi(i.tension,e.tension,t),power:Bi(i.power,e.power,t),a:n(i.a,e.a),pivot:n(i.pivot,e.pivot),taut:i.taut&&e.taut,errorX:i.errorX<0||e.errorX<0?-1:Bi(i.errorX,e.errorX,t)}}function ob(i,e,t){return i===null||e.epoch!==i.epoch||t!==null&&e.t<t}function tf(i,e,t){let n=0,s=i.length;for(;n<s;){const r=n+s>>1,a=i[r].t;(t?a<e:a<=e)?n=r+1:s=r}return n}class pm{status=null;frames=[];trail=[];history=ef();trajectory=[];trajectoryTruncated=!1;reference=null;tensionExtremes=null;playT=null;exact=null;exactError=null;errors=[];events=[];connected=!1;tickHz=60;work=0;periodTimer=new JM;historyStride=1;historyCount=0;disconnected=!1;listeners=new Set;subscribe(e){return this.listeners.add(e),()=>this.listeners.delete(e)}emit(){for(const e of this.listeners)e()}onStatus(e){const t=this.disconnected||ob(this.status,e,this.latest()?.t??null);this.disconnected=!1,this.status=e,t&&this.clear(),this.emit()}clear(){this.frames=[],this.trail=[],this.history=ef(),this.trajectory=[],this.trajectoryTruncated=!1,this.reference=null,this.tensionExtremes=null,this.playT=null,this.exact=null,this.exactError=null,this.events=[],this.work=0,this.periodTimer.reset(),this.historyStride=1,this.historyCount=0}onError(e){this.errors.push(e),this.errors.length>20&&this.errors.shift(),this.emit()}onEvent(e){const t=this.events;this.events=Gg(t,e,this.status?.epoch??null),this.events!==t&&(this.work-=e.energy_lost,this.emit())}setConnected(e){this.connected=e,e||(this.disconnected=!0),this.emit()}setExact(e,t=null){this.exact=e,this.exactError=t,this.emit()}onFrames(e){for(const t of e){const n=this.frames[this.frames.length-1];if(n!==void 0&&t.t<n.t)continue;n!==void 0&&t.t===n.t?this.frames.pop():n!==void 0&&(this.work+=eb(n,t)),this.frames.push(t),this.periodTimer.push(t),this.reference===null&&(this.reference={energy:t.energy,j3:t.j3});const s=this.tensionExtremes;s===null?this.tensionExtremes={min:t.tension,tMin:t.t,max:t.tension,tMax:t.t}:(t.tension<s.min&&([s.min,s.tMin]=[t.tension,t.t]),t.tension>s.max&&([s.max,s.tMax]=[t.tension,t.t])),this.pushTrail(t),this.pushHistory(t),this.trajectory.length<ib?this.trajectory.push(t):this.trajectoryTruncated=!0,this.playT===null&&(this.playT=t.t)}this.frames.length>Qd&&this.frames.splice(0,this.frames.length-Qd)}pushTrail(e){const t=this.trail[this.trail.length-1];t!==void 0&&t.t===e.t&&this.trail.pop(),this.trail.push(e),this.trail.length>$s&&this.trail.splice(0,this.trail.length-$s)}pushHistory(e){const t=this.reference;if(t===null)return;const n=this.history;if(!(n.t.length>0&&e.t<=n.t[n.t.length-1])&&this.historyCount++%this.historyStride===0&&(n.t.push(e.t),n.dE.push(e.energy-t.energy),n.dJ3.push(e.j3-t.j3),n.z.push(e.x[2]),n.zdot.push(e.v[2]),n.tension.push(e.tension),n.frames.push(e),n.t.length>nb)){const s=r=>r.filter((a,o)=>o%2===0);this.history={t:s(n.t),dE:s(n.dE),dJ3:s(n.dJ3),z:s(n.z),zdot:s(n.zdot),tension:s(n.tension),frames:s(n.frames)},this.historyStride*=2,this.historyCount=1}}latest(){return this.frames[this.frames.length-1]??null}advancePlayhead(e){const t=this.latest(),n=this.frames[0];if(t==null||n===void 0)return this.playT=null;const s=this.status;if(s===null||s.paused||this.playT===null)return this.playT=t.t,this.playT;const r=sb*s.time_scale/this.tickHz;let a=this.playT+Math.max(0,e)*s.time_scale;return a=Math.min(a,t.t),a=Math.max(a,t.t-r,n.t),this.playT=a,a}displayed(){const e=this.playT,t=this.frames;if(e===null||t.length===0)return null;const n=t[t.length-1];if(e>=n.t)return n;let s=0,r=t.length-1;if(e<=t[0].t)return t[0];for(;r-s>1;){const c=s+r>>1;t[c].t<=e?s=c:r=c}const a=t[s],o=t[r],l=o.t-a.t;return ab(a,o,l>0?(e-a.t)/l:1)}trailRange(e){const t=this.playT;if(t===null)return{start:0,end:0};const n=tf(this.trail,t,!1),s=tf(this.trail,t-e,!0);return{start:Math.min(s,n),end:n}}trailWindow(e){const{start:t,end:n}=this.trailRange(e);return this.trail.slice(t,n)}toCSV(){const e=this.status,t={source:"pendulab lab",scenario:e?.scenario??null,params:e?.params??null,model:e?.model??null,model_params:e?.model_params??null,method:e?.method??null,dt:e?.dt??null,truncated:this.trajectoryTruncated},n=rb.join(","),s=this.trajectory.map(r=>[r.t,...r.x,...r.v,r.energy,r.j3,r.tension,r.power,...r.a,...r.pivot,r.taut?1:0,r.errorX].map(a=>String(a)).join(","));return[`# ${JSON.stringify(t)}`,n,...s].join(`
`)+`
`}}const nf=(i,e)=>[i[1]*e[2]-i[2]*e[1],i[2]*e[0]-i[0]*e[2],i[0]*e[1]-i[1]*e[0]],va=(i,e)=>[i[0]*e,i[1]*e,i[2]*e],lb=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]];function cb(i){const e=[i?.gravity_x??0,i?.gravity_y??0,i?.gravity_z??-1],t=Math.hypot(...e);return t>0?va(e,1/t):[0,0,-1]}function hb(i,e,t,n,s){const r=Math.hypot(...i.x),a=va(i.v,e),o=va(i.a,e),l=lb(i.x,s);return{velocity:i.v,momentum:a,gravity:va(n,e*t),tension:r>0?va(i.x,-i.tension/r):[0,0,0],net:o,angularMomentum:nf(l,a),torque:nf(l,o)}}function _c(i,e,t){const n=Math.max(Math.abs(t),1),s=.5*i/(e*n),r=Math.sqrt(n/i);return{velocity:.25,momentum:.25,gravity:s,tension:s,net:s,angularMomentum:.5*i/(e*i*i*r),torque:s/i}}const mm=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]],Oa=i=>Math.hypot(i[0],i[1],i[2]),ka=(i,e)=>[i[0]*e,i[1]*e,i[2]*e],Eh=(i,e)=>[i[1]*e[2]-i[2]*e[1],i[2]*e[0]-i[0]*e[2],i[0]*e[1]-i[1]*e[0]];function gm(i,e){const t=e[0]*i[0]+e[1]*i[1]+e[2]*i[2];let n=mm(e,ka(i,t));return Oa(n)<1e-9&&(n=Math.abs(i[0])<.9?Eh(i,[1,0,0]):Eh(i,[0,1,0])),ka(n,1/Oa(n))}function ub(i,e,t,n){const s=Oa(i);if(!(s>0))return[[0,0,0],[...i]];const r=ka(i,1/s),a=gm(r,[0,0,1]),o=Eh(r,a),l=[];for(let c=0;c<=n;c++){const h=c/n,u=t*Math.min(1,h/.05,(1-h)/.05),d=2*Math.PI*e*h,[m,_]=[Math.cos(d)*u,Math.sin(d)*u];l.push([i[0]*h+a[0]*m+o[0]*_,i[1]*h+a[1]*m+o[1]*_,i[2]*h+a[2]*m+o[2]*_])}return l}function db(i){let e=0;for(let t=1;t<i.length;t++)e+=Oa(mm(i[t],i[t-1]));return e}function sf(i,e,t){const n=[];for(let s=0;s<=t;s++){const r=s/t,[a,o]=[2*r*(1-r),r*r];n.push([e[0]*a+i[0]*o,e[1]*a+i[1]*o,e[2]*a+i[2]*o])}return n}function fb(i,e,t,n=[0,0,-1]){const s=Oa(i),r=ka(i,.5);if(!(s>0)||s>=e)return sf(i,r,t);const a=gm(ka(i,1/s),n),o=h=>sf(i,[r[0]+a[0]*h,r[1]+a[1]*h,r[2]+a[2]*h],t);let[l,c]=[0,e];for(let h=0;h<40&&c-l>1e-4*e;h++){const u=.5*(l+c);db(o(u))<e?l=u:c=u}return o(.5*(l+c))}const rf=400,af=48;class pb{group=new Xi;coil;slack;constructor(){this.coil=new Zi(new Gt().setFromPoints(Array.from({length:rf+1},()=>new z)),new _i({color:14211288})),this.slack=new Zi(new Gt().setFromPoints(Array.from({length:af+1},()=>new z)),new qp({color:15918793,dashSize:.04,gapSize:.03}));for(const e of[this.coil,this.slack])e.frustumCulled=!1,e.visible=!1;this.group.add(this.coil,this.slack)}update(e,t,n,s,r){if(this.coil.visible=e==="coil",this.slack.visible=e==="slack string",this.group.position.set(...n),e==="coil"&&this.fill(this.coil,ub(t,14,.035*s,rf)),e==="slack string"){this.fill(this.slack,fb(t,s,af,r));const a=this.slack.material;a.dashSize=.04*s,a.gapSize=.03*s,this.slack.computeLineDistances()}}fill(e,t){const n=e.geometry.getAttribute("position");t.forEach((s,r)=>n.setXYZ(r,s[0],s[1],s[2])),n.needsUpdate=!0}}const mb=/swiftshader|llvmpipe|softpipe|software|basic render driver|lavapipe/i;function gb(i){return i!==null&&mb.test(i)}function _b(i,e){return 1-(1-i)**e}function vb(i,e){const t=gb(i),n=Number.isFinite(e)&&e>0?e:1;return{renderer:i,software:t,antialias:!t,pixelRatio:Math.min(n,t?1:2),reachLayers:t?1:2}}function xb(){const i=document.createElement("canvas"),e=i.getContext("webgl2")??i.getContext("webgl");if(e===null)return null;let t=e.getParameter(e.RENDERER);if(typeof t!="string"||t===""||/^webkit webgl$/i.test(t)){const n=e.getExtension("WEBGL_debug_renderer_info");n!==null&&(t=e.getParameter(n.UNMASKED_RENDERER_WEBGL))}return e.getExtension("WEBGL_lose_context")?.loseContext(),typeof t=="string"&&t!==""&&!/^webkit webgl$/i.test(t)?t:null}const _m=15127459;function Sb(i){const e=i/20,t=10**Math.floor(Math.log10(e)),n=e/t;return(n<1.5?1:n<3.5?2:5)*t}class vc{sprite;canvas=document.createElement("canvas");texture;text="";constructor(e,t){this.canvas.width=256,this.canvas.height=64,this.texture=new y_(this.canvas),this.sprite=new Gp(new zp({map:this.texture,depthTest:!1,transparent:!0})),this.sprite.scale.set(4*t,t,1),this.set(e)}set(e){if(e===this.text)return;this.text=e;const t=this.canvas.getContext("2d");t!==null&&(t.clearRect(0,0,256,64),t.font="bold 44px system-ui, sans-serif",t.fillStyle=`#${_m.toString(16)}`,t.textAlign="center",t.textBaseline="middle",t.fillText(e,128,32),this.texture.needsUpdate=!0)}}function of(i){const e=new Gt().setFromPoints(i);return new hl(e,new _i({color:_m}))}class yb{ruler=new Xi;protractor=new Xi;dial=new Xi;thetaLabel=new vc("",.1);built=-1;constructor(){this.ruler.visible=!1,this.protractor.visible=!1,this.protractor.add(this.dial,this.thetaLabel.sprite)}build(e){if(e===this.built)return;this.built=e;for(const l of[this.ruler,this.dial])for(const c of[...l.children])l.remove(c),(c instanceof on||c instanceof hl||c instanceof Gp)&&(c.geometry.dispose(),c.material.dispose());const t=Sb(2*e),n=1.1*e,s=[new z(n,0,-e),new z(n,0,e)],r=Math.floor(e/t+1e-9);for(let l=-r;l<=r;l++){const c=l*t,h=l%5===0;if(s.push(new z(n,0,c),new z(n-(h?.08:.04)*e,0,c)),h){const u=new vc(`${+c.toPrecision(6)} m`,.07*e);u.sprite.position.set(n+.16*e,0,c),this.ruler.add(u.sprite)}}this.ruler.add(of(s));const a=.4*e,o=[];for(let l=0;l<360;l+=2){const c=l*Math.PI/180,h=(l+2)*Math.PI/180;o.push(new z(a*Math.sin(c),0,-a*Math.cos(c)),new z(a*Math.sin(h),0,-a*Math.cos(h)))}for(let l=0;l<360;l+=10){const c=l*Math.PI/180,h=l%30===0?.85:.92;if(o.push(new z(a*Math.sin(c),0,-a*Math.cos(c)),new z(h*a*Math.sin(c),0,-h*a*Math.cos(c))),l%30===0&&l<=180){const u=new vc(`${l}°`,.06*e);u.sprite.position.set(1.2*a*Math.sin(c),0,-1.2*a*Math.cos(c)),this.dial.add(u.sprite)}}o.push(new z(0,0,-a),new z(0,0,a)),this.dial.add(of(o))}face(e){const t=this.ruler.position;this.ruler.rotation.set(0,0,Math.atan2(e.x-t.x,-(e.y-t.y)))}update(e,t,n,s,r,a){if(this.ruler.visible=s,this.protractor.visible=r,!s&&!r)return;this.build(n),this.ruler.position.copy(e),this.face(a),this.protractor.position.copy(e);const o=Math.atan2(t[1],t[0]),l=Math.atan2(Math.hypot(t[0],t[1]),-t[2]);this.dial.rotation.set(0,0,Number.isFinite(o)?o:0);const c=.55*n,h=l/2;this.thetaLabel.sprite.position.set(c*Math.sin(h)*Math.cos(o),c*Math.sin(h)*Math.sin(o),-c*Math.cos(h)),this.thetaLabel.sprite.scale.set(.4*n,.1*n,1),this.thetaLabel.set(`θ = ${(l*180/Math.PI).toFixed(1)}°`)}}class Mb{constructor(e){this.renderer=e,this.stereo.aspect=1}renderer;stereo=new Jp;render(e,t,n,s,r){const a=this.renderer,o=a.getContext();t.focus=s,t.updateMatrixWorld(),this.stereo.eyeSep=n,this.stereo.update(t);const l=a.autoClear,c=e.background;a.autoClear=!1,e.background=null,a.setClearColor(r,1),a.clear();try{o.colorMask(!0,!1,!1,!0),a.render(e,this.stereo.cameraL),a.clearDepth(),o.colorMask(!1,!0,!0,!0),a.render(e,this.stereo.cameraR)}finally{o.colorMask(!0,!0,!0,!0),e.background=c,a.autoClear=l}}}function bb(i,e,t,n=.9){const s=e*Math.PI/360,r=Math.atan(Math.tan(s)*Math.max(t,.001)),a=Math.min(s,r);return i/Math.sin(a*n)}function wb(i,e){const t=[],s=a=>{for(let o=0;o<96;o++)t.push(a(2*Math.PI*o/96),a(2*Math.PI*(o+1)/96))};for(let a=0;a<6;a++){const o=a*Math.PI/6;s(l=>new z(Math.sin(l)*Math.cos(o),Math.sin(l)*Math.sin(o),Math.cos(l)))}for(const a of[-.75,-.5,-.25,.25,.5,.75]){const o=Math.sqrt(1-a*a);s(l=>new z(o*Math.cos(l),o*Math.sin(l),a))}const r=new hl(new Gt().setFromPoints(t),new _i({color:i,transparent:!0,opacity:e}));return r.visible=!1,r}function Eb(i,e,t,n){const s=t.position.clone().sub(i).normalize(),r=new z().crossVectors(s,new z(0,0,1));r.lengthSq()<1e-12&&r.set(1,0,0),r.normalize();const a=new z().crossVectors(s,r).normalize(),o=t.position.distanceTo(i),l=e*Math.sqrt(Math.max(0,1-e*e/(o*o))),c=i.clone().addScaledVector(s,e*e/o),h=n.getBoundingClientRect(),u={left:1/0,right:-1/0,top:1/0,bottom:-1/0};for(let d=0;d<64;d++){const m=2*Math.PI*d/64,_=c.clone().addScaledVector(r,l*Math.cos(m)).addScaledVector(a,l*Math.sin(m)).project(t),S=h.left+(_.x+1)/2*h.width,p=h.top+(1-_.y)/2*h.height;u.left=Math.min(u.left,S),u.right=Math.max(u.right,S),u.top=Math.min(u.top,p),u.bottom=Math.max(u.bottom,p)}return u}const Po=13170016,Tb=new z(0,1,0);class Ab{group=new Xi;bob;rod;pivotMark;trail;positions=new Float32Array(3*($s+1));tmpX=new z;tmpPivot=new z;tmpDir=new z;length=1;offset=new z;constructor(){this.bob=new on(new ls(1,24,16),new Or({color:Po,roughness:.4})),this.rod=new on(new Xa(1,1,1,8),new Or({color:Po,metalness:.3,roughness:.5}));const e=new Gt;e.setAttribute("position",new gi(this.positions,3)),e.setDrawRange(0,0),this.trail=new Zi(e,new _i({color:Po,transparent:!0,opacity:.6})),this.trail.frustumCulled=!1,this.pivotMark=new on(new ls(1,12,8),new Or({color:Po})),this.pivotMark.visible=!1,this.group.add(this.bob,this.rod,this.trail,this.pivotMark),this.group.visible=!1}setLength(e){this.length=e,this.bob.scale.setScalar(.045*e)}setOffset(e){e===null?this.offset.set(0,0,0):this.offset.fromArray(e),this.pivotMark.visible=e!==null,this.pivotMark.position.copy(this.offset),this.pivotMark.scale.setScalar(.03*this.length)}update(e,t){if(this.group.visible=e!==null,e===null)return;const n=this.tmpX.fromArray(e.x),s=this.tmpPivot.fromArray(e.pivot).add(this.offset);this.bob.position.copy(n).add(s);const r=n.length();r>0&&(this.rod.position.copy(n).multiplyScalar(.5).add(s),this.rod.quaternion.setFromUnitVectors(Tb,this.tmpDir.copy(n).divideScalar(r)),this.rod.scale.set(.005*this.length,r,.005*this.length));const a=Math.max(0,Math.min(t.end-t.start,$s)),o=this.positions;for(let h=0;h<a;h++){const u=t.frames[t.end-a+h];o[3*h]=u.x[0]+u.pivot[0]+this.offset.x,o[3*h+1]=u.x[1]+u.pivot[1]+this.offset.y,o[3*h+2]=u.x[2]+u.pivot[2]+this.offset.z}const l=this.trail.geometry;l.setDrawRange(0,a);const c=l.getAttribute("position");c.clearUpdateRanges(),c.addUpdateRange(0,3*Math.max(a,1)),c.needsUpdate=!0}}const Rb=16766720,Cb=4e3;function Pb(i,e=[0,0,0]){const t=i.filter(s=>s.every(Number.isFinite)).slice(0,Cb),n=new Float32Array(3*t.length);return t.forEach((s,r)=>{n[3*r]=s[0]+e[0],n[3*r+1]=s[1]+e[1],n[3*r+2]=s[2]+e[2]}),n}function Lb(i,e){const t=e>1?i/(e-1):0,n=Math.max(t/3,1e-4);return{dash:n,gap:Math.max(2*n,1e-4)}}class Db{line;material=new qp({color:Rb,dashSize:.01,gapSize:.02});constructor(){this.line=new Zi(new Gt,this.material),this.line.frustumCulled=!1,this.line.visible=!1,this.line.name="measured-path"}set(e){this.line.geometry.dispose();const t=new Gt,n=Pb(e??[]);t.setAttribute("position",new gi(n,3)),this.line.geometry=t;const s=n.length/3;if(this.line.visible=s>1,s<2)return;this.line.computeLineDistances();const r=t.getAttribute("lineDistance"),{dash:a,gap:o}=Lb(r.getX(s-1),s);this.material.dashSize=a,this.material.gapSize=o}get points(){return this.line.visible?this.line.geometry.getAttribute("position").count:0}}const vm=["off","anaglyph","side by side"],xc={trail:!0,trailSeconds:10,sphere:!0,axes:!0,velocity:!0,momentum:!1,gravity:!1,tension:!1,net:!1,angularMomentum:!1,torque:!1,originX:0,originY:0,originZ:0,stereo:"off",ruler:!1,protractor:!1},ru={velocity:14711807,momentum:10194175,gravity:16757575,tension:16735603,net:16777215,angularMomentum:5102016,torque:16769357},Nb=["angularMomentum","torque"],Sc=new ct(1119259),lf=.06,Ib=new ct(5882879),Ub=new z(0,1,0),Fb=.025,Ob=.06,kb=.085,Bb={frames:[],start:0,end:0};function zb(i){const e=new I_(new z(1,0,0),new z,1,i);return e.visible=!1,e}class Hb{constructor(e,t){this.container=e,this.renderer=new um({antialias:t.antialias}),this.renderer.setPixelRatio(t.pixelRatio),this.renderer.domElement.id="scene-canvas",e.appendChild(this.renderer.domElement),this.scene.background=Sc,this.camera=new qn(40,1,.01,1e3),this.camera.up.set(0,0,1),this.controls=new fm(this.camera,this.renderer.domElement),this.controls.enableDamping=!0,this.scene.add(new D_(16777215,.6));const n=new L_(16777215,1.6);n.position.set(2,-3,4),this.scene.add(n),this.sphere=new on(new ls(1,48,32),new Rs({color:9417727,transparent:!0,opacity:t.reachLayers===1?_b(lf,2):lf,depthWrite:!1,side:t.reachLayers===2?pi:Cs}));const s=new Gt().setFromPoints(Array.from({length:128},(a,o)=>{const l=2*Math.PI*o/128;return new z(Math.cos(l),Math.sin(l),0)}));this.equator=new S_(s,new _i({color:9417727,transparent:!0,opacity:.25})),this.pivot=new on(new ls(.02,16,12),new Or({color:13421772})),this.rod=new on(new Xa(1,1,1,12),new Or({color:14211288,metalness:.6,roughness:.3})),this.bob=new on(new ls(1,32,24),new Or({color:16747586,roughness:.35})),this.axes=new Qp(1.3),this.handle=new on(new ls(1,16,12),new Rs({color:15911167})),this.handle.name="velocity handle",this.handle.visible=!1,this.trailPositions=new Float32Array(3*($s+1)),this.trailColors=new Float32Array(3*($s+1));const r=new Gt;r.setAttribute("position",new gi(this.trailPositions,3)),r.setAttribute("color",new gi(this.trailColors,3)),r.setDrawRange(0,0),this.trail=new Zi(r,new _i({vertexColors:!0})),this.trail.frustumCulled=!1,this.boom=new Zi(new Gt().setFromPoints([new z,new z]),new _i({color:10134712})),this.boom.visible=!1,this.boom.frustumCulled=!1,this.scene.add(this.sphere,this.equator,this.reachLines,this.pivot,this.rod,this.bob,this.axes,this.trail,this.tether.group,this.handle,this.boom,this.twin.group,this.measured.line,this.instruments.ruler,this.instruments.protractor,...Object.values(this.arrows)),this.setLength(1),this.resetCamera(),new ResizeObserver(()=>this.resize()).observe(e),this.resize()}container;renderer;camera;controls;scene=new Op;sphere;equator;reachLines=wb(9417727,.18);rod;bob;pivot;axes;trail;trailPositions;trailColors;trailColored=-1;tmpX=new z;tmpBob=new z;tmpDir=new z;tmpVec=new z;tmpOrigin=new z;arrows=Object.fromEntries(Object.entries(ru).map(([e,t])=>[e,zb(t)]));length=1;extent=1;stereo="off";anaglyph=null;instruments=new yb;boom;twin=new Ab;measured=new Db;follow=!1;followAt=null;reach=1;twinLayoutKey="";twinLayout=null;sideBySide=null;drag=null;pull=null;handle;drawn=null;velocityScale=_c(1,1,9.81).velocity;gNow=9.81;tmpHandle=new z;pivotNow=new z;topView=!1;tether=new pb;model="ideal";invalid=!0;setLength(e){if(!(e>0))return;const t=Math.abs(e-this.length)>1e-12*e;this.length=e,t&&(this.extent=this.reach=e),this.sphere.scale.setScalar(e),this.equator.scale.setScalar(e),this.reachLines.scale.setScalar(e),this.pivot.scale.setScalar(e),this.bob.scale.setScalar(.05*e),this.twin.setLength(this.twinLayout?.length??e),this.handle.scale.setScalar(Fb*e),this.axes.scale.setScalar(e),t&&this.resetCamera(),this.invalid=!0}fit(e){Math.abs(e-this.extent)<=.2*this.extent||(this.extent=e,this.resetCamera())}resetCamera(){const e=this.twinLayout,t=e===null?0:.5*Math.hypot(...e.offset),n=e===null?this.extent:t+Math.max(this.extent,e.length),s=1.1*n,r=this.stereo==="side by side"?this.camera.aspect/2:this.camera.aspect,a=bb(s,this.camera.fov,r),o=this.follow&&this.followAt!==null?this.followAt.clone():new z;e!==null&&o.add(new z(...e.offset).multiplyScalar(.5)),this.topView?this.camera.position.set(0,-1e-4*a,a).add(o):this.camera.position.set(3.3,-3.9,1.5).normalize().multiplyScalar(a).add(o),this.controls.target.copy(o),this.camera.near=.01*this.length,this.camera.far=100*n,this.camera.updateProjectionMatrix(),this.controls.update(),this.invalid=!0}setModel(e){e!==this.model&&(this.invalid=!0,this.model=e,this.follow=e==="slewing",this.followAt=null,this.extent=this.reach=this.length,this.resetCamera())}setTopView(e){this.topView=e,this.resetCamera()}enableDrag(e,t){const n=this.renderer.domElement;this.pull=new YM(n,this.camera,this.controls,this.handle,this.bob,()=>Ob*this.length,()=>this.pullBasis(),t),this.drag=new qM(n,this.camera,this.controls,this.bob,e,()=>({pivot:this.pivotNow,length:this.length}))}pullBasis(){const e=this.drawn;return e===null?null:{pivot:[...e.pivot],x:[...e.x],arrowScale:this.velocityScale,vmax:VM(this.length,this.gNow)}}onScreen(e){if(!e.visible)return null;const t=e.position.clone().project(this.camera),n=this.renderer.domElement.getBoundingClientRect();return{x:n.left+(t.x+1)/2*n.width,y:n.top+(1-t.y)/2*n.height}}bobOnScreen(){return this.onScreen(this.bob)}handleOnScreen(){return this.onScreen(this.handle)}setStereo(e){this.stereo=e,e==="anaglyph"&&this.anaglyph===null&&(this.anaglyph=new Mb(this.renderer)),e==="side by side"&&this.sideBySide===null&&(this.sideBySide=new GM(this.renderer)),this.resize(),this.resetCamera()}resize(){const e=Math.max(1,this.container.clientWidth),t=Math.max(1,this.container.clientHeight);this.renderer.setSize(e,t,!1),this.stereo==="side by side"&&this.sideBySide?.setSize(e,t),this.renderer.domElement.style.width="",this.renderer.domElement.style.height="",this.camera.aspect=e/t,this.camera.updateProjectionMatrix(),this.resetCamera(),this.invalid=!0}update(e,t,n,s,r,a){const o=this.stereo==="anaglyph";this.sphere.visible=n.sphere&&!o,this.reachLines.visible=n.sphere&&o,this.equator.visible=n.sphere,this.axes.visible=n.axes;const l=e!==null,c=ap(this.model,e?.taut??!0);if(this.rod.visible=l&&(c==="rod"||c==="taut string"),this.bob.visible=l,this.drawn=e,this.gNow=r,this.velocityScale=_c(this.length,s,r).velocity,this.handle.visible=l&&n.velocity,e===null){this.tether.update("rod",[0,0,0],[0,0,0],this.length,a),this.trail.geometry.setDrawRange(0,0);for(const A of Object.values(this.arrows))A.visible=!1;return}const h=this.pivotNow.fromArray(e.pivot);this.followPivot(h),this.reach=Math.max(this.reach,Math.hypot(...e.x)),this.fit(this.reach+(this.follow?0:h.length())),this.instruments.update(h,e.x,this.length,n.ruler,n.protractor,this.camera.position);const u=Math.hypot(h.x,h.y);if(this.boom.visible=u>1e-9*this.length,this.boom.visible){const A=this.boom.geometry.getAttribute("position");A.setXYZ(0,0,0,h.z),A.setXYZ(1,h.x,h.y,h.z),A.needsUpdate=!0}for(const A of[this.sphere,this.equator,this.reachLines,this.pivot])A.position.copy(h);const d=this.tmpX.fromArray(e.x),m=d.length(),_=this.tmpBob.copy(d).add(h);if(this.bob.position.copy(_),m>0){this.rod.position.copy(d).multiplyScalar(.5).add(h),this.rod.quaternion.setFromUnitVectors(Ub,this.tmpDir.copy(d).divideScalar(m));const A=c==="taut string"?.003:.008;this.rod.scale.set(A*this.length,m,A*this.length)}const S=r<0?[-a[0],-a[1],-a[2]]:a;if(this.tether.update(c,e.x,e.pivot,this.length,S),this.updateTrail(n.trail?t:Bb,e),this.handle.visible){const A=XM(e.x,e.v,this.velocityScale,kb*this.length);this.handle.position.copy(this.tmpHandle.fromArray(A).add(_))}const p=Object.keys(this.arrows);if(!p.some(A=>n[A])){for(const A of p)this.arrows[A].visible=!1;return}const f=[n.originX,n.originY,n.originZ],x=hb(e,s,r,a,f),R=_c(this.length,s,r),y=this.tmpOrigin.fromArray(f).add(h);for(const A of p){const w=Nb.includes(A)?y:_,g=this.tmpVec.fromArray(x[A]).multiplyScalar(R[A]);this.setArrow(this.arrows[A],n[A],w,g)}}followPivot(e){if(!this.follow)return;if(this.followAt===null){this.followAt=e.clone(),this.resetCamera();return}const t=this.tmpVec.copy(e).sub(this.followAt);t.lengthSq()!==0&&(this.camera.position.add(t),this.controls.target.add(t),this.followAt.copy(e))}orbitBy(e,t,n=1){const s=this.camera.position.clone().sub(this.controls.target),r=new bh().setFromCartesianCoords(s.x,s.z,-s.y);r.theta+=e,r.phi=Math.min(Math.max(r.phi-t,.05),Math.PI-.05),r.radius*=n;const a=new z().setFromSpherical(r);this.camera.position.set(a.x,-a.z,a.y).add(this.controls.target),this.camera.lookAt(this.controls.target),this.controls.update(),this.invalid=!0}setTwinLayout(e){const t=e===null?"":`${e.offset.join(",")}|${e.length}`;t!==this.twinLayoutKey&&(this.twinLayoutKey=t,this.twinLayout=e,this.twin.setLength(e?.length??this.length),this.twin.setOffset(e?.offset??null),this.resetCamera())}updateTwin(e,t){this.twin.update(e,t),this.invalid=!0}setMeasured(e){this.measured.set(e),this.invalid=!0}measuredPoints(){return this.measured.points}sphereOnScreen(){return Eb(this.sphere.position,this.sphere.scale.x,this.camera,this.renderer.domElement)}twinOnScreen(){return this.twin.group.visible?this.onScreen(this.twin.bob):null}setArrow(e,t,n,s){const r=s.length();if(e.visible=t&&r>1e-6*this.length,!e.visible)return;e.position.copy(n),e.setDirection(s.divideScalar(r));const a=Math.min(.25*r,.08*this.length);e.setLength(r,a,.5*a)}updateTrail(e,t){const n=Math.min(e.end-e.start,$s),s=this.trail.geometry;if(n<=0){s.setDrawRange(0,0);return}const r=e.end-n,a=this.trailPositions,o=n+1;for(let c=0;c<o;c++){const h=c<n?e.frames[r+c]:t;a[3*c]=h.x[0]+h.pivot[0],a[3*c+1]=h.x[1]+h.pivot[1],a[3*c+2]=h.x[2]+h.pivot[2]}s.setDrawRange(0,o);const l=s.getAttribute("position");if(l.clearUpdateRanges(),l.addUpdateRange(0,3*o),l.needsUpdate=!0,o!==this.trailColored){this.trailColored=o;const c=this.trailColors,h=new ct;for(let d=0;d<o;d++)h.copy(Sc).lerp(Ib,(d+1)/o),c[3*d]=h.r,c[3*d+1]=h.g,c[3*d+2]=h.b;const u=s.getAttribute("color");u.clearUpdateRanges(),u.addUpdateRange(0,3*o),u.needsUpdate=!0}}draw(e){const t=this.controls.update();return t&&this.instruments.ruler.visible&&this.instruments.face(this.camera.position),!e&&!t&&!this.invalid?!1:(this.invalid=!1,this.render(),!0)}render(){const e=this.camera.position.distanceTo(this.controls.target);this.stereo==="anaglyph"&&this.anaglyph!==null?this.anaglyph.render(this.scene,this.camera,e/30,e,Sc):this.stereo==="side by side"&&this.sideBySide!==null?(this.camera.focus=e,this.sideBySide.setEyeSeparation(e/30),this.sideBySide.render(this.scene,this.camera)):this.renderer.render(this.scene,this.camera)}screenshot(){return this.render(),this.renderer.domElement.toDataURL("image/png")}}const Gb={velocity:["vec.velocity","vec.velocityHelp"],momentum:["vec.momentum","vec.momentumHelp"],gravity:["vec.gravity","vec.gravityHelp"],tension:["vec.tension","vec.tensionHelp"],net:["vec.net","vec.netHelp"],angularMomentum:["vec.angularMomentum","vec.angularMomentumHelp"],torque:["vec.torque","vec.torqueHelp"]};function Vb(i,e,t,n){const s=i.addFolder(L("gui.view"));s.add(e,"trail").name(L("gui.trail")).onChange(t),s.add(e,"trailSeconds",1,120,1).name(L("gui.trailSeconds")).onChange(t),s.add(e,"sphere").name(L("gui.sphere")).onChange(t),s.add(e,"axes").name(L("gui.axes")).onChange(t);const r={topView:!1};s.add(r,"topView").name(L("gui.topView")).onChange(h=>{n(h),t()});const a={off:"stereo.off",anaglyph:"stereo.anaglyph","side by side":"stereo.sideBySide"},o=Object.fromEntries(vm.map(h=>[a[h]?L(a[h]):h,h])),l=s.add(e,"stereo",o).name(L("gui.stereo")).onChange(t);l.domElement.title=L("gui.stereoHelp"),l.domElement.dataset.control="stereo",s.close();const c=i.addFolder(L("gui.vectors"));for(const[h,[u,d]]of Object.entries(Gb)){const m=c.add(e,h).name(L(u)).onChange(t);m.domElement.title=L(d),m.domElement.dataset.vector=h,m.$name.style.borderLeft=`10px solid #${ru[h].toString(16).padStart(6,"0")}`,m.$name.style.paddingLeft="4px"}for(const h of["X","Y","Z"]){const u=`origin${h}`;c.add(e,u,-5,5,.01).name(L("gui.origin",{axis:h.toLowerCase()})).onChange(t).domElement.title=L("gui.originHelp")}return c.close(),s}class Wb{constructor(e,t,n,s,r){this.view=s,this.gui=new Wh({container:e,title:L("gui.title"),width:270});const a={};this.model=a;const o=this.gui.addFolder(L("gui.pendulum")),l=Xh((w,g)=>{r.send({type:"set_params",[w]:g})},50);for(const w of t.model.params){const g=b=>l(w.name,b);this.synced.push(cp(o,a,w,g,r.explain))}this.modelControls=new u0(o,t,r);const c=this.gui.addFolder(L("gui.integrator")).close(),h={};for(const w of t.methods)h[$o(w.name,w.order)]=w.name;a.method=t.methods.find(w=>w.default)?.name??t.methods[0]?.name??"rattle";const u=c.add(a,"method",h).name(L("gui.method")).onChange(w=>r.send({type:"set_method",method:w}));u.domElement.title=t.methods.map(w=>`${$o(w.name,w.order)} — ${w.name}: ${w.summary}`).join(`
`),this.synced.push(u);const d=t.controls.dt;a.dt=d.default??.001;const m=c.add(a,"dt").name("dt [s]").decimals(6).onFinishChange(w=>{if(!(w>=d.min&&w<=d.max)){r.explain(L("gui.dtRange",{min:d.min,max:d.max}));return}r.send({type:"set_method",dt:w})});m.domElement.title=L("gui.dtHelp",{min:d.min,max:d.max}),this.synced.push(m);const _=this.gui.addFolder(L("gui.run")),S=t.controls.time_scale;a.time_scale=S.default??1;const p=_.add(a,"time_scale").name(L("gui.timeScale")).decimals(3).onFinishChange(w=>{if(!(w>=S.min&&w<=S.max)){r.explain(L("gui.tsRange",{min:S.min,max:S.max}));return}r.send({type:"set_time_scale",time_scale:w})});p.domElement.title=L("gui.tsHelp",{min:S.min,max:S.max}),this.synced.push(p),a.paused=!1,a.run=()=>r.send({type:a.paused===!0?"resume":"pause"}),this.runButton=_.add(a,"run").name(L("toolbar.pause")),a.stepN=1;const f=t.controls.step_n;_.add(a,"stepN",f.min,Math.min(f.max,1e3),1).name(L("gui.stepN")),a.step=()=>r.send({type:"step",n:Math.round(Number(a.stepN))}),_.add(a,"step").name(L("toolbar.step")),a.reset=()=>r.send({type:"reset"}),_.add(a,"reset").name(L("toolbar.reset"));const x={};for(const w of n)w.error===void 0&&(x[w.title?`${w.title}`:w.name]=w.name);a.scenario="";const R=_.add(a,"scenario",x).name(L("gui.scenario")).onChange(w=>r.send({type:"load_scenario",name:w}));R.domElement.title=n.filter(w=>w.error===void 0).map(w=>`${w.name}: ${w.title??""}`).join(`
`),this.synced.push(R),Vb(this.gui,s,()=>r.viewChanged(this.view,this.topView),w=>{this.topView=w});const y=this.gui.addFolder(L("gui.export")).close();a.csv=()=>r.downloadCSV(),y.add(a,"csv").name(L("gui.csv")),a.toml=()=>r.downloadTOML();const A=y.add(a,"toml").name(L("gui.toml"));A.domElement.dataset.control="toml",A.domElement.title=L("gui.tomlHelp"),a.png=()=>r.screenshot(),y.add(a,"png").name(L("gui.png")),a.link=()=>r.copyLink(),y.add(a,"link").name(L("gui.link"))}view;gui;model;synced=[];runButton;modelControls;topView=!1;sync(e){const t=this.model;t.length=e.params.length,t.mass=e.params.mass,t.g=e.params.g,t.method=e.method,t.dt=e.dt,t.time_scale=e.time_scale,t.paused=e.paused,t.scenario=e.scenario??"";for(const n of this.synced)n.domElement.contains(document.activeElement)||n.updateDisplay();this.runButton.name(e.paused?L("toolbar.start"):L("toolbar.pause")),this.modelControls.sync(e)}}const Xb=!0,bn="u-",$b="uplot",qb=bn+"hz",Yb=bn+"vt",Kb=bn+"title",Zb=bn+"wrap",Jb=bn+"under",jb=bn+"over",Qb=bn+"axis",Xs=bn+"off",ew=bn+"select",tw=bn+"cursor-x",nw=bn+"cursor-y",iw=bn+"cursor-pt",sw=bn+"legend",rw=bn+"live",aw=bn+"inline",ow=bn+"series",lw=bn+"marker",cf=bn+"label",cw=bn+"value",xa="width",Sa="height",pa="top",hf="bottom",Rr="left",yc="right",au="#000",uf=au+"0",Mc="mousemove",df="mousedown",bc="mouseup",ff="mouseenter",pf="mouseleave",mf="dblclick",hw="resize",uw="scroll",gf="change",il="dppxchange",ou="--",Yr=typeof window<"u",Th=Yr?document:null,kr=Yr?window:null,dw=Yr?navigator:null;let wt,Lo;function Ah(){let i=devicePixelRatio;wt!=i&&(wt=i,Lo&&Ch(gf,Lo,Ah),Lo=matchMedia(`(min-resolution: ${wt-.001}dppx) and (max-resolution: ${wt+.001}dppx)`),qs(gf,Lo,Ah),kr.dispatchEvent(new CustomEvent(il)))}function ni(i,e){if(e!=null){let t=i.classList;!t.contains(e)&&t.add(e)}}function Rh(i,e){let t=i.classList;t.contains(e)&&t.remove(e)}function Yt(i,e,t){i.style[e]=t+"px"}function Ei(i,e,t,n){let s=Th.createElement(i);return e!=null&&ni(s,e),t?.insertBefore(s,n),s}function hi(i,e){return Ei("div",i,e)}const _f=new WeakMap;function zi(i,e,t,n,s){let r="translate("+e+"px,"+t+"px)",a=_f.get(i);r!=a&&(i.style.transform=r,_f.set(i,r),e<0||t<0||e>n||t>s?ni(i,Xs):Rh(i,Xs))}const vf=new WeakMap;function xf(i,e,t){let n=e+t,s=vf.get(i);n!=s&&(vf.set(i,n),i.style.background=e,i.style.borderColor=t)}const Sf=new WeakMap;function yf(i,e,t,n){let s=e+""+t,r=Sf.get(i);s!=r&&(Sf.set(i,s),i.style.height=t+"px",i.style.width=e+"px",i.style.marginLeft=n?-e/2+"px":0,i.style.marginTop=n?-t/2+"px":0)}const lu={passive:!0},fw={...lu,capture:!0};function qs(i,e,t,n){e.addEventListener(i,t,n?fw:lu)}function Ch(i,e,t,n){e.removeEventListener(i,t,lu)}Yr&&Ah();function Ti(i,e,t,n){let s;t=t||0,n=n||e.length-1;let r=n<=2147483647;for(;n-t>1;)s=r?t+n>>1:si((t+n)/2),e[s]<i?t=s:n=s;return i-e[t]<=e[n]-i?t:n}function xm(i){return(t,n,s)=>{let r=-1,a=-1;for(let o=n;o<=s;o++)if(i(t[o])){r=o;break}for(let o=s;o>=n;o--)if(i(t[o])){a=o;break}return[r,a]}}const Sm=i=>i!=null,ym=i=>i!=null&&i>0,pl=xm(Sm),pw=xm(ym);function mw(i,e,t,n=0,s=!1){let r=s?pw:pl,a=s?ym:Sm;[e,t]=r(i,e,t);let o=i[e],l=i[e];if(e>-1)if(n==1)o=i[e],l=i[t];else if(n==-1)o=i[t],l=i[e];else for(let c=e;c<=t;c++){let h=i[c];a(h)&&(h<o?o=h:h>l&&(l=h))}return[o??kt,l??-kt]}function ml(i,e,t,n){let s=wf(i),r=wf(e);i==e&&(s==-1?(i*=t,e/=t):(i/=t,e*=t));let a=t==10?us:Mm,o=s==1?si:di,l=r==1?di:si,c=o(a(xn(i))),h=l(a(xn(e))),u=Vr(t,c),d=Vr(t,h);return t==10&&(c<0&&(u=Bt(u,-c)),h<0&&(d=Bt(d,-h))),n||t==2?(i=u*s,e=d*r):(i=Tm(i,u),e=gl(e,d)),[i,e]}function cu(i,e,t,n){let s=ml(i,e,t,n);return i==0&&(s[0]=0),e==0&&(s[1]=0),s}const hu=.1,Mf={mode:3,pad:hu},Ta={pad:0,soft:null,mode:0},gw={min:Ta,max:Ta};function sl(i,e,t,n){return _l(t)?bf(i,e,t):(Ta.pad=t,Ta.soft=n?0:null,Ta.mode=n?3:0,bf(i,e,gw))}function Mt(i,e){return i??e}function _w(i,e,t){for(e=Mt(e,0),t=Mt(t,i.length-1);e<=t;){if(i[e]!=null)return!0;e++}return!1}function bf(i,e,t){let n=t.min,s=t.max,r=Mt(n.pad,0),a=Mt(s.pad,0),o=Mt(n.hard,-kt),l=Mt(s.hard,kt),c=Mt(n.soft,kt),h=Mt(s.soft,-kt),u=Mt(n.mode,0),d=Mt(s.mode,0),m=e-i,_=us(m),S=Wn(xn(i),xn(e)),p=us(S),f=xn(p-_);(m<1e-24||f>10)&&(m=0,(i==0||e==0)&&(m=1e-24,u==2&&c!=kt&&(r=0),d==2&&h!=-kt&&(a=0)));let x=m||S||1e3,R=us(x),y=Vr(10,si(R)),A=x*(m==0?i==0?.1:1:r),w=Bt(Tm(i-A,y/10),24),g=i>=c&&(u==1||u==3&&w<=c||u==2&&w>=c)?c:kt,b=Wn(o,w<g&&i>=g?g:Ri(g,w)),I=x*(m==0?e==0?.1:1:a),N=Bt(gl(e+I,y/10),24),P=e<=h&&(d==1||d==3&&N>=h||d==2&&N<=h)?h:-kt,B=Ri(l,N>P&&e<=P?P:Wn(P,N));return b==B&&b==0&&(B=100),[b,B]}const vw=new Intl.NumberFormat(Yr?dw.language:"en-US"),uu=i=>vw.format(i),ri=Math,Xo=ri.PI,xn=ri.abs,si=ri.floor,vn=ri.round,di=ri.ceil,Ri=ri.min,Wn=ri.max,Vr=ri.pow,wf=ri.sign,us=ri.log10,Mm=ri.log2,xw=(i,e=1)=>ri.sinh(i)*e,wc=(i,e=1)=>ri.asinh(i/e),kt=1/0;function Ef(i){return(us((i^i>>31)-(i>>31))|0)+1}function Ph(i,e,t){return Ri(Wn(i,e),t)}function bm(i){return typeof i=="function"}function _t(i){return bm(i)?i:()=>i}const Sw=()=>{},wm=i=>i,Em=(i,e)=>e,yw=i=>null,Tf=i=>!0,Af=(i,e)=>i==e,Mw=/\.\d*?(?=9{6,}|0{6,})/gm,Js=i=>{if(Rm(i)||Ns.has(i))return i;const e=`${i}`,t=e.match(Mw);if(t==null)return i;let n=t[0].length-1;if(e.indexOf("e-")!=-1){let[s,r]=e.split("e");return+`${Js(s)}e${r}`}return Bt(i,n)};function Vs(i,e){return Js(Bt(Js(i/e))*e)}function gl(i,e){return Js(di(Js(i/e))*e)}function Tm(i,e){return Js(si(Js(i/e))*e)}function Bt(i,e=0){if(Rm(i))return i;let t=10**e,n=i*t*(1+Number.EPSILON);return vn(n)/t}const Ns=new Map;function Am(i){return((""+i).split(".")[1]||"").length}function Ba(i,e,t,n){let s=[],r=n.map(Am);for(let a=e;a<t;a++){let o=xn(a),l=Bt(Vr(i,a),o);for(let c=0;c<n.length;c++){let h=i==10?+`${n[c]}e${a}`:n[c]*l,u=(a>=0?0:o)+(a>=r[c]?0:r[c]),d=i==10?h:Bt(h,u);s.push(d),Ns.set(d,u)}}return s}const Aa={},du=[],Wr=[null,null],ws=Array.isArray,Rm=Number.isInteger,bw=i=>i===void 0;function Rf(i){return typeof i=="string"}function _l(i){let e=!1;if(i!=null){let t=i.constructor;e=t==null||t==Object}return e}function ww(i){return i!=null&&typeof i=="object"}const Ew=Object.getPrototypeOf(Uint8Array),Cm="__proto__";function Xr(i,e=_l){let t;if(ws(i)){let n=i.find(s=>s!=null);if(ws(n)||e(n)){t=Array(i.length);for(let s=0;s<i.length;s++)t[s]=Xr(i[s],e)}else t=i.slice()}else if(i instanceof Ew)t=i.slice();else if(e(i)){t={};for(let n in i)n!=Cm&&(t[n]=Xr(i[n],e))}else t=i;return t}function pn(i){let e=arguments;for(let t=1;t<e.length;t++){let n=e[t];for(let s in n)s!=Cm&&(_l(i[s])?pn(i[s],Xr(n[s])):i[s]=Xr(n[s]))}return i}const Tw=0,Aw=1,Rw=2;function Cw(i,e,t){for(let n=0,s,r=-1;n<e.length;n++){let a=e[n];if(a>r){for(s=a-1;s>=0&&i[s]==null;)i[s--]=null;for(s=a+1;s<t&&i[s]==null;)i[r=s++]=null}}}function Pw(i,e){if(Nw(i)){let a=i[0].slice();for(let o=1;o<i.length;o++)a.push(...i[o].slice(1));return Iw(a[0])||(a=Dw(a)),a}let t=new Set;for(let a=0;a<i.length;a++){let l=i[a][0],c=l.length;for(let h=0;h<c;h++)t.add(l[h])}let n=[Array.from(t).sort((a,o)=>a-o)],s=n[0].length,r=new Map;for(let a=0;a<s;a++)r.set(n[0][a],a);for(let a=0;a<i.length;a++){let o=i[a],l=o[0];for(let c=1;c<o.length;c++){let h=o[c],u=Array(s).fill(void 0),d=e?e[a][c]:Aw,m=[];for(let _=0;_<h.length;_++){let S=h[_],p=r.get(l[_]);S===null?d!=Tw&&(u[p]=S,d==Rw&&m.push(p)):u[p]=S}Cw(u,m,s),n.push(u)}}return n}const Lw=typeof queueMicrotask>"u"?i=>Promise.resolve().then(i):queueMicrotask;function Dw(i){let e=i[0],t=e.length,n=Array(t);for(let r=0;r<n.length;r++)n[r]=r;n.sort((r,a)=>e[r]-e[a]);let s=[];for(let r=0;r<i.length;r++){let a=i[r],o=Array(t);for(let l=0;l<t;l++)o[l]=a[n[l]];s.push(o)}return s}function Nw(i){let e=i[0][0],t=e.length;for(let n=1;n<i.length;n++){let s=i[n][0];if(s.length!=t)return!1;if(s!=e){for(let r=0;r<t;r++)if(s[r]!=e[r])return!1}}return!0}function Iw(i,e=100){const t=i.length;if(t<=1)return!0;let n=0,s=t-1;for(;n<=s&&i[n]==null;)n++;for(;s>=n&&i[s]==null;)s--;if(s<=n)return!0;const r=Wn(1,si((s-n+1)/e));for(let a=i[n],o=n+r;o<=s;o+=r){const l=i[o];if(l!=null){if(l<=a)return!1;a=l}}return!0}const Pm=["January","February","March","April","May","June","July","August","September","October","November","December"],Lm=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function Dm(i){return i.slice(0,3)}const Uw=Lm.map(Dm),Fw=Pm.map(Dm),Ow={MMMM:Pm,MMM:Fw,WWWW:Lm,WWW:Uw};function ma(i){return(i<10?"0":"")+i}function kw(i){return(i<10?"00":i<100?"0":"")+i}const Bw={YYYY:i=>i.getFullYear(),YY:i=>(i.getFullYear()+"").slice(2),MMMM:(i,e)=>e.MMMM[i.getMonth()],MMM:(i,e)=>e.MMM[i.getMonth()],MM:i=>ma(i.getMonth()+1),M:i=>i.getMonth()+1,DD:i=>ma(i.getDate()),D:i=>i.getDate(),WWWW:(i,e)=>e.WWWW[i.getDay()],WWW:(i,e)=>e.WWW[i.getDay()],HH:i=>ma(i.getHours()),H:i=>i.getHours(),h:i=>{let e=i.getHours();return e==0?12:e>12?e-12:e},AA:i=>i.getHours()>=12?"PM":"AM",aa:i=>i.getHours()>=12?"pm":"am",a:i=>i.getHours()>=12?"p":"a",mm:i=>ma(i.getMinutes()),m:i=>i.getMinutes(),ss:i=>ma(i.getSeconds()),s:i=>i.getSeconds(),fff:i=>kw(i.getMilliseconds())};function fu(i,e){e=e||Ow;let t=[],n=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=n.exec(i);)t.push(s[0][0]=="{"?Bw[s[1]]:s[0]);return r=>{let a="";for(let o=0;o<t.length;o++)a+=typeof t[o]=="string"?t[o]:t[o](r,e);return a}}const zw=new Intl.DateTimeFormat().resolvedOptions().timeZone;function Hw(i,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+i+i.getTimezoneOffset()*6e4):e==zw?t=i:(t=new Date(i.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(i.getMilliseconds())),t}const Nm=i=>i%1==0,rl=[1,2,2.5,5],Gw=Ba(10,-32,0,rl),Im=Ba(10,0,32,rl),Vw=Im.filter(Nm),Ws=Gw.concat(Im),pu=`
`,Um="{YYYY}",Cf=pu+Um,Fm="{M}/{D}",ya=pu+Fm,Do=ya+"/{YY}",Om="{aa}",Ww="{h}:{mm}",Dr=Ww+Om,Pf=pu+Dr,Lf=":{ss}",Tt=null;function km(i){let e=i*1e3,t=e*60,n=t*60,s=n*24,r=s*30,a=s*365,l=(i==1?Ba(10,0,3,rl).filter(Nm):Ba(10,-3,0,rl)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,n,n*2,n*3,n*4,n*6,n*8,n*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,a,a*2,a*5,a*10,a*25,a*50,a*100]);const c=[[a,Um,Tt,Tt,Tt,Tt,Tt,Tt,1],[s*28,"{MMM}",Cf,Tt,Tt,Tt,Tt,Tt,1],[s,Fm,Cf,Tt,Tt,Tt,Tt,Tt,1],[n,"{h}"+Om,Do,Tt,ya,Tt,Tt,Tt,1],[t,Dr,Do,Tt,ya,Tt,Tt,Tt,1],[e,Lf,Do+" "+Dr,Tt,ya+" "+Dr,Tt,Pf,Tt,1],[i,Lf+".{fff}",Do+" "+Dr,Tt,ya+" "+Dr,Tt,Pf,Tt,1]];function h(u){return(d,m,_,S,p,f)=>{let x=[],R=p>=a,y=p>=r&&p<a,A=u(_),w=Bt(A*i,3),g=Ec(A.getFullYear(),R?0:A.getMonth(),y||R?1:A.getDate()),b=Bt(g*i,3);if(y||R){let I=y?p/r:0,N=R?p/a:0,P=w==b?w:Bt(Ec(g.getFullYear()+N,g.getMonth()+I,1)*i,3),B=new Date(vn(P/i)),V=B.getFullYear(),U=B.getMonth();for(let W=0;P<=S;W++){let Z=Ec(V+N*W,U+I*W,1),H=Z-u(Bt(Z*i,3));P=Bt((+Z+H)*i,3),P<=S&&x.push(P)}}else{let I=p>=s?s:p,N=si(_)-si(w),P=b+N+gl(w-b,I);x.push(P);let B=u(P),V=B.getHours()+B.getMinutes()/t+B.getSeconds()/n,U=p/n,W=d.axes[m]._space,Z=f/W;for(;P=Bt(P+p,i==1?0:3),!(P>S);)if(U>1){let H=si(Bt(V+U,6))%24,ee=u(P).getHours()-H;ee>1&&(ee=-1),P-=ee*n,V=(V+U)%24;let se=x[x.length-1];Bt((P-se)/p,3)*Z>=.7&&x.push(P)}else x.push(P)}return x}}return[l,c,h]}const[Xw,$w,qw]=km(1),[Yw,Kw,Zw]=km(.001);Ba(2,-53,53,[1]);function Df(i,e){return i.map(t=>t.map((n,s)=>s==0||s==8||n==null?n:e(s==1||t[8]==0?n:t[1]+n)))}function Nf(i,e){return(t,n,s,r,a)=>{let o=e.find(_=>a>=_[0])||e[e.length-1],l,c,h,u,d,m;return n.map(_=>{let S=i(_),p=S.getFullYear(),f=S.getMonth(),x=S.getDate(),R=S.getHours(),y=S.getMinutes(),A=S.getSeconds(),w=p!=l&&o[2]||f!=c&&o[3]||x!=h&&o[4]||R!=u&&o[5]||y!=d&&o[6]||A!=m&&o[7]||o[1];return l=p,c=f,h=x,u=R,d=y,m=A,w(S)})}}function Jw(i,e){let t=fu(e);return(n,s,r,a,o)=>s.map(l=>t(i(l)))}function Ec(i,e,t){return new Date(i,e,t)}function If(i,e){return e(i)}const jw="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function Uf(i,e){return(t,n,s,r)=>r==null?ou:e(i(n))}function Qw(i,e){let t=i.series[e];return t.width?t.stroke(i,e):t.points.width?t.points.stroke(i,e):null}function eE(i,e){return i.series[e].fill(i,e)}const tE={show:!0,live:!0,isolate:!1,mount:Sw,markers:{show:!0,width:2,stroke:Qw,fill:eE,dash:"solid"},idx:null,idxs:null,values:[]};function nE(i,e){let t=i.cursor.points,n=hi(),s=t.size(i,e);Yt(n,xa,s),Yt(n,Sa,s);let r=s/-2;Yt(n,"marginLeft",r),Yt(n,"marginTop",r);let a=t.width(i,e,s);return a&&Yt(n,"borderWidth",a),n}function iE(i,e){let t=i.series[e].points;return t._fill||t._stroke}function sE(i,e){let t=i.series[e].points;return t._stroke||t._fill}function rE(i,e){return i.series[e].points.size}const Tc=[0,0];function aE(i,e,t){return Tc[0]=e,Tc[1]=t,Tc}function No(i,e,t,n=!0){return s=>{s.button==0&&(!n||s.target==e)&&t(s)}}function Ac(i,e,t,n=!0){return s=>{(!n||s.target==e)&&t(s)}}const oE={show:!0,x:!0,y:!0,lock:!1,move:aE,points:{one:!1,show:nE,size:rE,width:0,stroke:sE,fill:iE},bind:{mousedown:No,mouseup:No,click:No,dblclick:No,mousemove:Ac,mouseleave:Ac,mouseenter:Ac},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(i,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(i,e,t,n,s)=>n-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},Bm={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},mu=pn({},Bm,{filter:Em}),zm=pn({},mu,{size:10}),Hm=pn({},Bm,{show:!1}),gu='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',Gm="bold "+gu,Vm=1.5,Ff={show:!0,scale:"x",stroke:au,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Gm,side:2,grid:mu,ticks:zm,border:Hm,font:gu,lineGap:Vm,rotate:0},lE="Value",cE="Time",Of={show:!0,scale:"x",auto:!1,sorted:1,min:kt,max:-kt,idxs:[]};function hE(i,e,t,n,s){return e.map(r=>r==null?"":uu(r))}function uE(i,e,t,n,s,r,a){let o=[],l=Ns.get(s)||0;t=a?t:Bt(gl(t,s),l);for(let c=t;c<=n;c=Bt(c+s,l))o.push(Object.is(c,-0)?0:c);return o}function Lh(i,e,t,n,s,r,a){const o=[],l=i.scales[i.axes[e].scale].log,c=l==10?us:Mm,h=si(c(t));s=Vr(l,h),l==10&&(s=Ws[Ti(s,Ws)]);let u=t,d=s*l;l==10&&(d=Ws[Ti(d,Ws)]);do o.push(u),u=u+s,l==10&&!Ns.has(u)&&(u=Bt(u,Ns.get(s))),u>=d&&(s=u,d=s*l,l==10&&(d=Ws[Ti(d,Ws)]));while(u<=n);return o}function dE(i,e,t,n,s,r,a){let l=i.scales[i.axes[e].scale].asinh,c=n>l?Lh(i,e,Wn(l,t),n,s):[l],h=n>=0&&t<=0?[0]:[];return(t<-l?Lh(i,e,Wn(l,-n),-t,s):[l]).reverse().map(d=>-d).concat(h,c)}const Wm=/./,fE=/[12357]/,pE=/[125]/,kf=/1/,Dh=(i,e,t,n)=>i.map((s,r)=>e==4&&s==0||r%n==0&&t.test(s.toExponential()[s<0?1:0])?s:null);function mE(i,e,t,n,s){let r=i.axes[t],a=r.scale,o=i.scales[a],l=i.valToPos,c=r._space,h=l(10,a),u=l(9,a)-h>=c?Wm:l(7,a)-h>=c?fE:l(5,a)-h>=c?pE:kf;if(u==kf){let d=xn(l(1,a)-h);if(d<c)return Dh(e.slice().reverse(),o.distr,u,di(c/d)).reverse()}return Dh(e,o.distr,u,1)}function gE(i,e,t,n,s){let r=i.axes[t],a=r.scale,o=r._space,l=i.valToPos,c=xn(l(1,a)-l(2,a));return c<o?Dh(e.slice().reverse(),3,Wm,di(o/c)).reverse():e}function _E(i,e,t,n){return n==null?ou:e==null?"":uu(e)}const Bf={show:!0,scale:"y",stroke:au,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Gm,side:3,grid:mu,ticks:zm,border:Hm,font:gu,lineGap:Vm,rotate:0};function vE(i,e){let t=3+(i||1)*2;return Bt(t*e,3)}function xE(i,e){let{scale:t,idxs:n}=i.series[0],s=i._data[0],r=i.valToPos(s[n[0]],t,!0),a=i.valToPos(s[n[1]],t,!0),o=xn(a-r),l=i.series[e],c=o/(l.points.space*wt);return n[1]-n[0]<=c}const zf={scale:null,auto:!0,sorted:0,min:kt,max:-kt},Xm=(i,e,t,n,s)=>s,Hf={show:!0,auto:!0,sorted:0,gaps:Xm,alpha:1,facets:[pn({},zf,{scale:"x"}),pn({},zf,{scale:"y"})]},Gf={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:Xm,alpha:1,points:{show:xE,filter:null},values:null,min:kt,max:-kt,idxs:[],path:null,clip:null};function SE(i,e,t,n,s){return t/10}const $m={time:Xb,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},yE=pn({},$m,{time:!1,ori:1}),Vf={};function qm(i,e){let t=Vf[i];return t||(t={key:i,plots:[],sub(n){t.plots.push(n)},unsub(n){t.plots=t.plots.filter(s=>s!=n)},pub(n,s,r,a,o,l,c){for(let h=0;h<t.plots.length;h++)t.plots[h]!=s&&t.plots[h].pub(n,s,r,a,o,l,c)}},i!=null&&(Vf[i]=t)),t}const $r=1,Nh=2;function er(i,e,t){const n=i.mode,s=i.series[e],r=n==2?i._data[e]:i._data,a=i.scales,o=i.bbox;let l=r[0],c=n==2?r[1]:r[e],h=n==2?a[s.facets[0].scale]:a[i.series[0].scale],u=n==2?a[s.facets[1].scale]:a[s.scale],d=o.left,m=o.top,_=o.width,S=o.height,p=i.valToPosH,f=i.valToPosV;return h.ori==0?t(s,l,c,h,u,p,f,d,m,_,S,xl,Kr,yl,Km,Jm):t(s,l,c,h,u,f,p,m,d,S,_,Sl,Zr,xu,Zm,jm)}function _u(i,e){let t=0,n=0,s=Mt(i.bands,du);for(let r=0;r<s.length;r++){let a=s[r];a.series[0]==e?t=a.dir:a.series[1]==e&&(a.dir==1?n|=1:n|=2)}return[t,n==1?-1:n==2?1:n==3?2:0]}function ME(i,e,t,n,s){let r=i.mode,a=i.series[e],o=r==2?a.facets[1].scale:a.scale,l=i.scales[o];return s==-1?l.min:s==1?l.max:l.distr==3?l.dir==1?l.min:l.max:0}function ds(i,e,t,n,s,r){return er(i,e,(a,o,l,c,h,u,d,m,_,S,p)=>{let f=a.pxRound;const x=c.dir*(c.ori==0?1:-1),R=c.ori==0?Kr:Zr;let y,A;x==1?(y=t,A=n):(y=n,A=t);let w=f(u(o[y],c,S,m)),g=f(d(l[y],h,p,_)),b=f(u(o[A],c,S,m)),I=f(d(r==1?h.max:h.min,h,p,_)),N=new Path2D(s);return R(N,b,I),R(N,w,I),R(N,w,g),N})}function vl(i,e,t,n,s,r){let a=null;if(i.length>0){a=new Path2D;const o=e==0?yl:xu;let l=t;for(let u=0;u<i.length;u++){let d=i[u];if(d[1]>d[0]){let m=d[0]-l;m>0&&o(a,l,n,m,n+r),l=d[1]}}let c=t+s-l,h=10;c>0&&o(a,l,n-h/2,c,n+r+h)}return a}function bE(i,e,t){let n=i[i.length-1];n&&n[0]==e?n[1]=t:i.push([e,t])}function vu(i,e,t,n,s,r,a){let o=[],l=i.length;for(let c=s==1?t:n;c>=t&&c<=n;c+=s)if(e[c]===null){let u=c,d=c;if(s==1)for(;++c<=n&&e[c]===null;)d=c;else for(;--c>=t&&e[c]===null;)d=c;let m=r(i[u]),_=d==u?m:r(i[d]),S=u-s;m=a<=0&&S>=0&&S<l?r(i[S]):m;let f=d+s;_=a>=0&&f>=0&&f<l?r(i[f]):_,_>=m&&o.push([m,_])}return o}function Wf(i){return i==0?wm:i==1?vn:e=>Vs(e,i)}function Ym(i){let e=i==0?xl:Sl,t=i==0?(s,r,a,o,l,c)=>{s.arcTo(r,a,o,l,c)}:(s,r,a,o,l,c)=>{s.arcTo(a,r,l,o,c)},n=i==0?(s,r,a,o,l)=>{s.rect(r,a,o,l)}:(s,r,a,o,l)=>{s.rect(a,r,l,o)};return(s,r,a,o,l,c=0,h=0)=>{c==0&&h==0?n(s,r,a,o,l):(c=Ri(c,o/2,l/2),h=Ri(h,o/2,l/2),e(s,r+c,a),t(s,r+o,a,r+o,a+l,c),t(s,r+o,a+l,r,a+l,h),t(s,r,a+l,r,a,h),t(s,r,a,r+o,a,c),s.closePath())}}const xl=(i,e,t)=>{i.moveTo(e,t)},Sl=(i,e,t)=>{i.moveTo(t,e)},Kr=(i,e,t)=>{i.lineTo(e,t)},Zr=(i,e,t)=>{i.lineTo(t,e)},yl=Ym(0),xu=Ym(1),Km=(i,e,t,n,s,r)=>{i.arc(e,t,n,s,r)},Zm=(i,e,t,n,s,r)=>{i.arc(t,e,n,s,r)},Jm=(i,e,t,n,s,r,a)=>{i.bezierCurveTo(e,t,n,s,r,a)},jm=(i,e,t,n,s,r,a)=>{i.bezierCurveTo(t,e,s,n,a,r)};function Qm(i){return(e,t,n,s,r)=>er(e,t,(a,o,l,c,h,u,d,m,_,S,p)=>{let{pxRound:f,points:x}=a,R,y;c.ori==0?(R=xl,y=Km):(R=Sl,y=Zm);const A=Bt(x.width*wt,3);let w=(x.size-x.width)/2*wt,g=Bt(w*2,3),b=new Path2D,I=new Path2D,{left:N,top:P,width:B,height:V}=e.bbox;yl(I,N-g,P-g,B+g*2,V+g*2);const U=W=>{if(l[W]!=null){let Z=f(u(o[W],c,S,m)),H=f(d(l[W],h,p,_));R(b,Z+w,H),y(b,Z,H,w,0,Xo*2)}};if(r)r.forEach(U);else for(let W=n;W<=s;W++)U(W);return{stroke:A>0?b:null,fill:b,clip:I,flags:$r|Nh}})}function eg(i){return(e,t,n,s,r,a)=>{n!=s&&(r!=n&&a!=n&&i(e,t,n),r!=s&&a!=s&&i(e,t,s),i(e,t,a))}}const wE=eg(Kr),EE=eg(Zr);function tg(i){const e=Mt(i?.alignGaps,0);return(t,n,s,r)=>er(t,n,(a,o,l,c,h,u,d,m,_,S,p)=>{[s,r]=pl(l,s,r);let f=a.pxRound,x=V=>f(u(V,c,S,m)),R=V=>f(d(V,h,p,_)),y,A;c.ori==0?(y=Kr,A=wE):(y=Zr,A=EE);const w=c.dir*(c.ori==0?1:-1),g={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:$r},b=g.stroke;let I=!1;if(r-s>=S*4){let V=fe=>t.posToVal(fe,c.key,!0),U=null,W=null,Z,H,he,J=x(o[w==1?s:r]),ee=x(o[s]),se=x(o[r]),pe=V(w==1?ee+1:se-1);for(let fe=w==1?s:r;fe>=s&&fe<=r;fe+=w){let te=o[fe],xe=(w==1?te<pe:te>pe)?J:x(te),Pe=l[fe];xe==J?Pe!=null?(H=Pe,U==null?(y(b,xe,R(H)),Z=U=W=H):H<U?U=H:H>W&&(W=H)):Pe===null&&(I=!0):(U!=null&&A(b,J,R(U),R(W),R(Z),R(H)),Pe!=null?(H=Pe,y(b,xe,R(H)),U=W=Z=H):(U=W=null,Pe===null&&(I=!0)),J=xe,pe=V(J+w))}U!=null&&U!=W&&he!=J&&A(b,J,R(U),R(W),R(Z),R(H))}else for(let V=w==1?s:r;V>=s&&V<=r;V+=w){let U=l[V];U===null?I=!0:U!=null&&y(b,x(o[V]),R(U))}let[P,B]=_u(t,n);if(a.fill!=null||P!=0){let V=g.fill=new Path2D(b),U=a.fillTo(t,n,a.min,a.max,P),W=R(U),Z=x(o[s]),H=x(o[r]);w==-1&&([H,Z]=[Z,H]),y(V,H,W),y(V,Z,W)}if(!a.spanGaps){let V=[];I&&V.push(...vu(o,l,s,r,w,x,e)),g.gaps=V=a.gaps(t,n,s,r,V),g.clip=vl(V,c.ori,m,_,S,p)}return B!=0&&(g.band=B==2?[ds(t,n,s,r,b,-1),ds(t,n,s,r,b,1)]:ds(t,n,s,r,b,B)),g})}function TE(i){const e=Mt(i.align,1),t=Mt(i.ascDesc,!1),n=Mt(i.alignGaps,0),s=Mt(i.extend,!1);return(r,a,o,l)=>er(r,a,(c,h,u,d,m,_,S,p,f,x,R)=>{[o,l]=pl(u,o,l);let y=c.pxRound,{left:A,width:w}=r.bbox,g=ee=>y(_(ee,d,x,p)),b=ee=>y(S(ee,m,R,f)),I=d.ori==0?Kr:Zr;const N={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:$r},P=N.stroke,B=d.dir*(d.ori==0?1:-1);let V=b(u[B==1?o:l]),U=g(h[B==1?o:l]),W=U,Z=U;s&&e==-1&&(Z=A,I(P,Z,V)),I(P,U,V);for(let ee=B==1?o:l;ee>=o&&ee<=l;ee+=B){let se=u[ee];if(se==null)continue;let pe=g(h[ee]),fe=b(se);e==1?I(P,pe,V):I(P,W,fe),I(P,pe,fe),V=fe,W=pe}let H=W;s&&e==1&&(H=A+w,I(P,H,V));let[he,J]=_u(r,a);if(c.fill!=null||he!=0){let ee=N.fill=new Path2D(P),se=c.fillTo(r,a,c.min,c.max,he),pe=b(se);I(ee,H,pe),I(ee,Z,pe)}if(!c.spanGaps){let ee=[];ee.push(...vu(h,u,o,l,B,g,n));let se=c.width*wt/2,pe=t||e==1?se:-se,fe=t||e==-1?-se:se;ee.forEach(te=>{te[0]+=pe,te[1]+=fe}),N.gaps=ee=c.gaps(r,a,o,l,ee),N.clip=vl(ee,d.ori,p,f,x,R)}return J!=0&&(N.band=J==2?[ds(r,a,o,l,P,-1),ds(r,a,o,l,P,1)]:ds(r,a,o,l,P,J)),N})}function Xf(i,e,t,n,s,r,a=kt){if(i.length>1){let o=null;for(let l=0,c=1/0;l<i.length;l++)if(e[l]!==void 0){if(o!=null){let h=xn(i[l]-i[o]);h<c&&(c=h,a=xn(t(i[l],n,s,r)-t(i[o],n,s,r)))}o=l}}return a}function AE(i){i=i||Aa;const e=Mt(i.size,[.6,kt,1]),t=i.align||0,n=i.gap||0;let s=i.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;const r=_t(s),a=1-e[0],o=Mt(e[1],kt),l=Mt(e[2],1),c=Mt(i.disp,Aa),h=Mt(i.each,m=>{}),{fill:u,stroke:d}=c;return(m,_,S,p)=>er(m,_,(f,x,R,y,A,w,g,b,I,N,P)=>{let B=f.pxRound,V=t,U=n*wt,W=o*wt,Z=l*wt,H,he;y.ori==0?[H,he]=r(m,_):[he,H]=r(m,_);const J=y.dir*(y.ori==0?1:-1);let ee=y.ori==0?yl:xu,se=y.ori==0?h:(Le,qe,st,Te,Ft,Ve,Ke)=>{h(Le,qe,st,Ft,Te,Ke,Ve)},pe=Mt(m.bands,du).find(Le=>Le.series[0]==_),fe=pe!=null?pe.dir:0,te=f.fillTo(m,_,f.min,f.max,fe),_e=B(g(te,A,P,I)),xe,Pe,Me,q=N,oe=B(f.width*wt),ve=!1,Xe=null,Ze=null,je=null,Ut=null;u!=null&&(oe==0||d!=null)&&(ve=!0,Xe=u.values(m,_,S,p),Ze=new Map,new Set(Xe).forEach(Le=>{Le!=null&&Ze.set(Le,new Path2D)}),oe>0&&(je=d.values(m,_,S,p),Ut=new Map,new Set(je).forEach(Le=>{Le!=null&&Ut.set(Le,new Path2D)})));let{x0:At,size:zt}=c;if(At!=null&&zt!=null){V=1,x=At.values(m,_,S,p),At.unit==2&&(x=x.map(st=>m.posToVal(b+st*N,y.key,!0)));let Le=zt.values(m,_,S,p);zt.unit==2?Pe=Le[0]*N:Pe=w(Le[0],y,N,b)-w(0,y,N,b),q=Xf(x,R,w,y,N,b,q),Me=q-Pe+U}else q=Xf(x,R,w,y,N,b,q),Me=q*a+U,Pe=q-Me;Me<1&&(Me=0),oe>=Pe/2&&(oe=0),Me<5&&(B=wm);let xt=Me>0,Jt=q-Me-(xt?oe:0);Pe=B(Ph(Jt,Z,W)),xe=(V==0?Pe/2:V==J?0:Pe)-V*J*((V==0?U/2:0)+(xt?oe/2:0));const dt={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},Rt=ve?null:new Path2D;let Vt=null;if(pe!=null)Vt=m.data[pe.series[1]];else{let{y0:Le,y1:qe}=c;Le!=null&&qe!=null&&(R=qe.values(m,_,S,p),Vt=Le.values(m,_,S,p))}let Kt=H*Pe,O=he*Pe;for(let Le=J==1?S:p;Le>=S&&Le<=p;Le+=J){let qe=R[Le];if(qe==null)continue;if(Vt!=null){let $=Vt[Le]??0;if(qe-$==0)continue;_e=g($,A,P,I)}let st=y.distr!=2||c!=null?x[Le]:Le,Te=w(st,y,N,b),Ft=g(Mt(qe,te),A,P,I),Ve=B(Te-xe),Ke=B(Wn(Ft,_e)),C=B(Ri(Ft,_e)),M=Ke-C;if(qe!=null){let $=qe<0?O:Kt,de=qe<0?Kt:O;ve?(oe>0&&je[Le]!=null&&ee(Ut.get(je[Le]),Ve,C+si(oe/2),Pe,Wn(0,M-oe),$,de),Xe[Le]!=null&&ee(Ze.get(Xe[Le]),Ve,C+si(oe/2),Pe,Wn(0,M-oe),$,de)):ee(Rt,Ve,C+si(oe/2),Pe,Wn(0,M-oe),$,de),se(m,_,Le,Ve-oe/2,C,Pe+oe,M)}}return oe>0?dt.stroke=ve?Ut:Rt:ve||(dt._fill=f.width==0?f._fill:f._stroke??f._fill,dt.width=0),dt.fill=ve?Ze:Rt,dt})}function RE(i,e){const t=Mt(e?.alignGaps,0);return(n,s,r,a)=>er(n,s,(o,l,c,h,u,d,m,_,S,p,f)=>{[r,a]=pl(c,r,a);let x=o.pxRound,R=H=>x(d(H,h,p,_)),y=H=>x(m(H,u,f,S)),A,w,g;h.ori==0?(A=xl,g=Kr,w=Jm):(A=Sl,g=Zr,w=jm);const b=h.dir*(h.ori==0?1:-1);let I=R(l[b==1?r:a]),N=I,P=[],B=[];for(let H=b==1?r:a;H>=r&&H<=a;H+=b)if(c[H]!=null){let J=l[H],ee=R(J);P.push(N=ee),B.push(y(c[H]))}const V={stroke:i(P,B,A,g,w,x),fill:null,clip:null,band:null,gaps:null,flags:$r},U=V.stroke;let[W,Z]=_u(n,s);if(o.fill!=null||W!=0){let H=V.fill=new Path2D(U),he=o.fillTo(n,s,o.min,o.max,W),J=y(he);g(H,N,J),g(H,I,J)}if(!o.spanGaps){let H=[];H.push(...vu(l,c,r,a,b,R,t)),V.gaps=H=o.gaps(n,s,r,a,H),V.clip=vl(H,h.ori,_,S,p,f)}return Z!=0&&(V.band=Z==2?[ds(n,s,r,a,U,-1),ds(n,s,r,a,U,1)]:ds(n,s,r,a,U,Z)),V})}function CE(i){return RE(PE,i)}function PE(i,e,t,n,s,r){const a=i.length;if(a<2)return null;const o=new Path2D;if(t(o,i[0],e[0]),a==2)n(o,i[1],e[1]);else{let l=Array(a),c=Array(a-1),h=Array(a-1),u=Array(a-1);for(let d=0;d<a-1;d++)h[d]=e[d+1]-e[d],u[d]=i[d+1]-i[d],c[d]=h[d]/u[d];l[0]=c[0];for(let d=1;d<a-1;d++)c[d]===0||c[d-1]===0||c[d-1]>0!=c[d]>0?l[d]=0:(l[d]=3*(u[d-1]+u[d])/((2*u[d]+u[d-1])/c[d-1]+(u[d]+2*u[d-1])/c[d]),isFinite(l[d])||(l[d]=0));l[a-1]=c[a-2];for(let d=0;d<a-1;d++)s(o,i[d]+u[d]/3,e[d]+l[d]*u[d]/3,i[d+1]-u[d]/3,e[d+1]-l[d+1]*u[d]/3,i[d+1],e[d+1])}return o}const Ih=new Set;function $f(){for(let i of Ih)i.syncRect(!0)}Yr&&(qs(hw,kr,$f),qs(uw,kr,$f,!0),qs(il,kr,()=>{Fn.pxRatio=wt}));const LE=tg(),DE=Qm();function qf(i,e,t,n){return(n?[i[0],i[1]].concat(i.slice(2)):[i[0]].concat(i.slice(1))).map((r,a)=>Uh(r,a,e,t))}function NE(i,e){return i.map((t,n)=>n==0?{}:pn({},e,t))}function Uh(i,e,t,n){return pn({},e==0?t:n,i)}function ng(i,e,t){return e==null?Wr:[e,t]}const IE=ng;function UE(i,e,t){return e==null?Wr:sl(e,t,hu,!0)}function ig(i,e,t,n){return e==null?Wr:ml(e,t,i.scales[n].log,!1)}const FE=ig;function sg(i,e,t,n){return e==null?Wr:cu(e,t,i.scales[n].log,!1)}const OE=sg;function kE(i,e,t,n,s){let r=Wn(Ef(i),Ef(e)),a=e-i,o=Ti(s/n*a,t);do{let l=t[o],c=n*l/a;if(c>=s&&r+(l<5?Ns.get(l):0)<=17)return[l,c]}while(++o<t.length);return[0,0]}function Yf(i){let e,t;return i=i.replace(/(\d+)px/,(n,s)=>(e=vn((t=+s)*wt))+"px"),[i,e,t]}function BE(i){i.show&&[i.font,i.labelFont].forEach(e=>{let t=Bt(e[2]*wt,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function Fn(i,e,t){const n={mode:Mt(i.mode,1)},s=n.mode;function r(v,E,D,F){let X=E.valToPct(v);return F+D*(E.dir==-1?1-X:X)}function a(v,E,D,F){let X=E.valToPct(v);return F+D*(E.dir==-1?X:1-X)}function o(v,E,D,F){return E.ori==0?r(v,E,D,F):a(v,E,D,F)}n.valToPosH=r,n.valToPosV=a;let l=!1;n.status=0;const c=n.root=hi($b);if(i.id!=null&&(c.id=i.id),ni(c,i.class),i.title){let v=hi(Kb,c);v.textContent=i.title}const h=Ei("canvas"),u=n.ctx=h.getContext("2d"),d=hi(Zb,c);qs("click",d,v=>{v.target===_&&(Xt!=or||Zt!=lr)&&Pn.click(n,v)},!0);const m=n.under=hi(Jb,d);d.appendChild(h);const _=n.over=hi(jb,d);i=Xr(i);const S=+Mt(i.pxAlign,1),p=Wf(S);(i.plugins||[]).forEach(v=>{v.opts&&(i=v.opts(n,i)||i)});const f=i.ms||.001,x=n.series=s==1?qf(i.series||[],Of,Gf,!1):NE(i.series||[null],Hf),R=n.axes=qf(i.axes||[],Ff,Bf,!0),y=n.scales={},A=n.bands=i.bands||[];A.forEach(v=>{v.fill=_t(v.fill||null),v.dir=Mt(v.dir,-1)});const w=s==2?x[1].facets[0].scale:x[0].scale,g={axes:es,series:ut},b=(i.drawOrder||["axes","series"]).map(v=>g[v]);function I(v){const E=v.distr==3?D=>us(D>0?D:v.clamp(n,D,v.min,v.max,v.key)):v.distr==4?D=>wc(D,v.asinh):v.distr==100?D=>v.fwd(D):D=>D;return D=>{let F=E(D),{_min:X,_max:j}=v,ce=j-X;return(F-X)/ce}}function N(v){let E=y[v];if(E==null){let D=(i.scales||Aa)[v]||Aa;if(D.from!=null){N(D.from);let F=pn({},y[D.from],D,{key:v});F.valToPct=I(F),y[v]=F}else{E=y[v]=pn({},v==w?$m:yE,D),E.key=v;let F=E.time,X=E.range,j=ws(X);if((v!=w||s==2&&!F)&&(j&&(X[0]==null||X[1]==null)&&(X={min:X[0]==null?Mf:{mode:1,hard:X[0],soft:X[0]},max:X[1]==null?Mf:{mode:1,hard:X[1],soft:X[1]}},j=!1),!j&&_l(X))){let ce=X;X=(me,we,Fe)=>we==null?Wr:sl(we,Fe,ce)}E.range=_t(X||(F?IE:v==w?E.distr==3?FE:E.distr==4?OE:ng:E.distr==3?ig:E.distr==4?sg:UE)),E.auto=_t(j?!1:E.auto),E.clamp=_t(E.clamp||SE),E._min=E._max=null,E.valToPct=I(E)}}}N("x"),N("y"),s==1&&x.forEach(v=>{N(v.scale)}),R.forEach(v=>{N(v.scale)});for(let v in i.scales)N(v);const P=y[w],B=P.distr;let V,U;P.ori==0?(ni(c,qb),V=r,U=a):(ni(c,Yb),V=a,U=r);const W={};for(let v in y){let E=y[v];(E.min!=null||E.max!=null)&&(W[v]={min:E.min,max:E.max},E.min=E.max=null)}const Z=i.tzDate||(v=>new Date(vn(v/f))),H=i.fmtDate||fu,he=f==1?qw(Z):Zw(Z),J=Nf(Z,Df(f==1?$w:Kw,H)),ee=Uf(Z,If(jw,H)),se=[],pe=n.legend=pn({},tE,i.legend),fe=n.cursor=pn({},oE,{drag:{y:s==2}},i.cursor),te=pe.show,_e=fe.show,xe=pe.markers;pe.idxs=se,xe.width=_t(xe.width),xe.dash=_t(xe.dash),xe.stroke=_t(xe.stroke),xe.fill=_t(xe.fill);let Pe,Me,q,oe=[],ve=[],Xe,Ze=!1,je={};if(pe.live){const v=x[1]?x[1].values:null;Ze=v!=null,Xe=Ze?v(n,1,0):{_:0};for(let E in Xe)je[E]=ou}if(te)if(Pe=Ei("table",sw,c),q=Ei("tbody",null,Pe),pe.mount(n,Pe),Ze){Me=Ei("thead",null,Pe,q);let v=Ei("tr",null,Me);Ei("th",null,v);for(var Ut in Xe)Ei("th",cf,v).textContent=Ut}else ni(Pe,aw),pe.live&&ni(Pe,rw);const At={show:!0},zt={show:!1};function xt(v,E){if(E==0&&(Ze||!pe.live||s==2))return Wr;let D=[],F=Ei("tr",ow,q,q.childNodes[E]);ni(F,v.class),v.show||ni(F,Xs);let X=Ei("th",null,F);if(xe.show){let me=hi(lw,X);if(E>0){let we=xe.width(n,E);we&&(me.style.border=we+"px "+xe.dash(n,E)+" "+xe.stroke(n,E)),me.style.background=xe.fill(n,E)}}let j=hi(cf,X);v.label instanceof HTMLElement?j.appendChild(v.label):j.textContent=v.label,E>0&&(xe.show||(j.style.color=v.width>0?xe.stroke(n,E):xe.fill(n,E)),dt("click",X,me=>{if(fe._lock)return;Qe(me);let we=x.indexOf(v);if((me.ctrlKey||me.metaKey)!=pe.isolate){let Fe=x.some((Oe,Be)=>Be>0&&Be!=we&&Oe.show);x.forEach((Oe,Be)=>{Be>0&&Ni(Be,Fe?Be==we?At:zt:At,!0,dn.setSeries)})}else Ni(we,{show:!v.show},!0,dn.setSeries)},!1),et&&dt(ff,X,me=>{fe._lock||(Qe(me),Ni(x.indexOf(v),hr,!0,dn.setSeries))},!1));for(var ce in Xe){let me=Ei("td",cw,F);me.textContent="--",D.push(me)}return[F,D]}const Jt=new Map;function dt(v,E,D,F=!0){const X=Jt.get(E)||{},j=fe.bind[v](n,E,D,F);j&&(qs(v,E,X[v]=j),Jt.set(E,X))}function Rt(v,E,D){const F=Jt.get(E)||{};for(let X in F)(v==null||X==v)&&(Ch(X,E,F[X]),delete F[X]);v==null&&Jt.delete(E)}let Vt=0,Kt=0,O=0,Le=0,qe=0,st=0,Te=qe,Ft=st,Ve=O,Ke=Le,C=0,M=0,$=0,de=0;n.bbox={};let le=!1,ye=!1,be=!1,ne=!1,re=!1,ge=!1;function k(v,E,D){(D||v!=n.width||E!=n.height)&&ae(v,E),ot(!1),be=!0,ye=!0,Dn()}function ae(v,E){n.width=Vt=O=v,n.height=Kt=Le=E,qe=st=0,Ee(),We();let D=n.bbox;C=D.left=Vs(qe*wt,.5),M=D.top=Vs(st*wt,.5),$=D.width=Vs(O*wt,.5),de=D.height=Vs(Le*wt,.5)}const ie=3;function Ae(){let v=!1,E=0;for(;!v;){E++;let D=sr(E),F=Di(E);v=E==ie||D&&F,v||(ae(n.width,n.height),ye=!0)}}function Se({width:v,height:E}){k(v,E)}n.setSize=Se;function Ee(){let v=!1,E=!1,D=!1,F=!1;R.forEach((X,j)=>{if(X.show&&X._show){let{side:ce,_size:me}=X,we=ce%2,Fe=X.label!=null?X.labelSize:0,Oe=me+Fe;Oe>0&&(we?(O-=Oe,ce==3?(qe+=Oe,F=!0):D=!0):(Le-=Oe,ce==0?(st+=Oe,v=!0):E=!0))}}),Pi[0]=v,Pi[1]=D,Pi[2]=E,Pi[3]=F,O-=vi[1]+vi[3],qe+=vi[3],Le-=vi[2]+vi[0],st+=vi[0]}function We(){let v=qe+O,E=st+Le,D=qe,F=st;function X(j,ce){switch(j){case 1:return v+=ce,v-ce;case 2:return E+=ce,E-ce;case 3:return D-=ce,D+ce;case 0:return F-=ce,F+ce}}R.forEach((j,ce)=>{if(j.show&&j._show){let me=j.side;j._pos=X(me,j._size),j.label!=null&&(j._lpos=X(me,j.labelSize))}})}if(fe.dataIdx==null){let v=fe.hover,E=v.skip=new Set(v.skip??[]);E.add(void 0);let D=v.prox=_t(v.prox),F=v.bias??=0;fe.dataIdx=(X,j,ce,me)=>{if(j==0)return ce;let we=ce,Fe=D(X,j,ce,me)??kt,Oe=Fe>=0&&Fe<kt,Be=P.ori==0?O:Le,it=fe.left,bt=e[0],yt=e[j];if(E.has(yt[ce])){we=null;let ft=null,Je=null,$e;if(F==0||F==-1)for($e=ce;ft==null&&$e-- >0;)E.has(yt[$e])||(ft=$e);if(F==0||F==1)for($e=ce;Je==null&&$e++<yt.length;)E.has(yt[$e])||(Je=$e);if(ft!=null||Je!=null)if(Oe){let qt=ft==null?-1/0:V(bt[ft],P,Be,0),tn=Je==null?1/0:V(bt[Je],P,Be,0),An=it-qt,It=tn-it;An<=It?An<=Fe&&(we=ft):It<=Fe&&(we=Je)}else we=Je==null?ft:ft==null?Je:ce-ft<=Je-ce?ft:Je}else Oe&&xn(it-V(bt[ce],P,Be,0))>Fe&&(we=null);return we}}const Qe=v=>{fe.event=v};fe.idxs=se,fe._lock=!1;let ue=fe.points;ue.show=_t(ue.show),ue.size=_t(ue.size),ue.stroke=_t(ue.stroke),ue.width=_t(ue.width),ue.fill=_t(ue.fill);const ze=n.focus=pn({},i.focus||{alpha:.3},fe.focus),et=ze.prox>=0,De=et&&ue.one;let at=[],Wt=[],On=[];function Jr(v,E){let D=ue.show(n,E);if(D instanceof HTMLElement)return ni(D,iw),ni(D,v.class),zi(D,-10,-10,O,Le),_.insertBefore(D,at[E]),D}function tr(v,E){if(s==1||E>0){let D=s==1&&y[v.scale].time,F=v.value;v.value=D?Rf(F)?Uf(Z,If(F,H)):F||ee:F||_E,v.label=v.label||(D?cE:lE)}if(De||E>0){v.width=v.width==null?1:v.width,v.paths=v.paths||LE||yw,v.fillTo=_t(v.fillTo||ME),v.pxAlign=+Mt(v.pxAlign,S),v.pxRound=Wf(v.pxAlign),v.stroke=_t(v.stroke||null),v.fill=_t(v.fill||null),v._stroke=v._fill=v._paths=v._focus=null;let D=vE(Wn(1,v.width),1),F=v.points=pn({},{size:D,width:Wn(1,D*.2),stroke:v.stroke,space:D*2,paths:DE,_stroke:null,_fill:null},v.points);F.show=_t(F.show),F.filter=_t(F.filter),F.fill=_t(F.fill),F.stroke=_t(F.stroke),F.paths=_t(F.paths),F.pxAlign=v.pxAlign}if(te){let D=xt(v,E);oe.splice(E,0,D[0]),ve.splice(E,0,D[1]),pe.values.push(null)}if(_e){se.splice(E,0,null);let D=null;De?E==0&&(D=Jr(v,E)):E>0&&(D=Jr(v,E)),at.splice(E,0,D),Wt.splice(E,0,0),On.splice(E,0,0)}Tn("addSeries",E)}function bl(v,E){E=E??x.length,v=s==1?Uh(v,E,Of,Gf):Uh(v,E,{},Hf),x.splice(E,0,v),tr(x[E],E)}n.addSeries=bl;function qa(v){if(x.splice(v,1),te){pe.values.splice(v,1),ve.splice(v,1);let E=oe.splice(v,1)[0];Rt(null,E.firstChild),E.remove()}_e&&(se.splice(v,1),at.splice(v,1)[0].remove(),Wt.splice(v,1),On.splice(v,1)),Tn("delSeries",v)}n.delSeries=qa;const Pi=[!1,!1,!1,!1];function Ji(v,E){if(v._show=v.show,v.show){let D=v.side%2,F=y[v.scale];F==null&&(v.scale=D?x[1].scale:w,F=y[v.scale]);let X=F.time;v.size=_t(v.size),v.space=_t(v.space),v.rotate=_t(v.rotate),ws(v.incrs)&&v.incrs.forEach(ce=>{!Ns.has(ce)&&Ns.set(ce,Am(ce))}),v.incrs=_t(v.incrs||(F.distr==2?Vw:X?f==1?Xw:Yw:Ws)),v.splits=_t(v.splits||(X&&F.distr==1?he:F.distr==3?Lh:F.distr==4?dE:uE)),v.stroke=_t(v.stroke),v.grid.stroke=_t(v.grid.stroke),v.ticks.stroke=_t(v.ticks.stroke),v.border.stroke=_t(v.border.stroke);let j=v.values;v.values=ws(j)&&!ws(j[0])?_t(j):X?ws(j)?Nf(Z,Df(j,H)):Rf(j)?Jw(Z,j):j||J:j||hE,v.filter=_t(v.filter||(F.distr>=3&&F.log==10?mE:F.distr==3&&F.log==2?gE:Em)),v.font=Yf(v.font),v.labelFont=Yf(v.labelFont),v._size=v.size(n,null,E,0),v._space=v._rotate=v._incrs=v._found=v._splits=v._values=null,v._size>0&&(Pi[E]=!0,v._el=hi(Qb,d))}}function ji(v,E,D,F){let[X,j,ce,me]=D,we=E%2,Fe=0;return we==0&&(me||j)&&(Fe=E==0&&!X||E==2&&!ce?vn(Ff.size/3):0),we==1&&(X||ce)&&(Fe=E==1&&!j||E==3&&!me?vn(Bf.size/2):0),Fe}const jr=n.padding=(i.padding||[ji,ji,ji,ji]).map(v=>_t(Mt(v,ji))),vi=n._padding=jr.map((v,E)=>v(n,E,Pi,0));let Qt,sn=null,rn=null;const Li=s==1?x[0].idxs:null;let Zn=null,fs=!1;function Qr(v,E){if(e=v??[],n.data=n._data=e,s==2){Qt=0;for(let D=1;D<x.length;D++)Qt+=e[D][0].length}else{e.length==0&&(n.data=n._data=e=[[]]),Zn=e[0],Qt=Zn.length;let D=e;if(B==2){D=e.slice();let F=D[0]=Array(Qt);for(let X=0;X<Qt;X++)F[X]=X}n._data=e=D}if(ot(!0),Tn("setData"),B==2&&(be=!0),E!==!1){let D=P;D.auto(n,fs)?ea():gs(w,D.min,D.max),ne=ne||fe.left>=0,ge=!0,Dn()}}n.setData=Qr;function ea(){fs=!0;let v,E;s==1&&(Qt>0?(sn=Li[0]=0,rn=Li[1]=Qt-1,v=e[0][sn],E=e[0][rn],B==2?(v=sn,E=rn):v==E&&(B==3?[v,E]=ml(v,v,P.log,!1):B==4?[v,E]=cu(v,v,P.log,!1):P.time?E=v+vn(86400/f):[v,E]=sl(v,E,hu,!0))):(sn=Li[0]=v=null,rn=Li[1]=E=null)),gs(w,v,E)}let nr,ps,ir,T,G,Q,Y,K,Re,Ne;function Ce(v,E,D,F,X,j){v??=uf,D??=du,F??="butt",X??=uf,j??="round",v!=nr&&(u.strokeStyle=nr=v),X!=ps&&(u.fillStyle=ps=X),E!=ir&&(u.lineWidth=ir=E),j!=G&&(u.lineJoin=G=j),F!=Q&&(u.lineCap=Q=F),D!=T&&u.setLineDash(T=D)}function Ie(v,E,D,F){E!=ps&&(u.fillStyle=ps=E),v!=Y&&(u.font=Y=v),D!=K&&(u.textAlign=K=D),F!=Re&&(u.textBaseline=Re=F)}function Ge(v,E,D,F,X=0){if(F.length>0&&v.auto(n,fs)&&(E==null||E.min==null)){let j=Mt(sn,0),ce=Mt(rn,F.length-1),me=D.min==null?mw(F,j,ce,X,v.distr==3):[D.min,D.max];v.min=Ri(v.min,D.min=me[0]),v.max=Wn(v.max,D.max=me[1])}}const nt={min:null,max:null};function ht(){for(let F in y){let X=y[F];W[F]==null&&(X.min==null||W[w]!=null&&X.auto(n,fs))&&(W[F]=nt)}for(let F in y){let X=y[F];W[F]==null&&X.from!=null&&W[X.from]!=null&&(W[F]=nt)}W[w]!=null&&ot(!0);let v={};for(let F in W){let X=W[F];if(X!=null){let j=v[F]=Xr(y[F],ww);if(X.min!=null)pn(j,X);else if(F!=w||s==2)if(Qt==0&&j.from==null){let ce=j.range(n,null,null,F);j.min=ce[0],j.max=ce[1]}else j.min=kt,j.max=-kt}}if(Qt>0){x.forEach((F,X)=>{if(s==1){let j=F.scale,ce=W[j];if(ce==null)return;let me=v[j];if(X==0){let we=me.range(n,me.min,me.max,j);me.min=we[0],me.max=we[1],sn=Ti(me.min,e[0]),rn=Ti(me.max,e[0]),rn-sn>1&&(e[0][sn]<me.min&&sn++,e[0][rn]>me.max&&rn--),F.min=Zn[sn],F.max=Zn[rn]}else F.show&&F.auto&&Ge(me,ce,F,e[X],F.sorted);F.idxs[0]=sn,F.idxs[1]=rn}else if(X>0&&F.show&&F.auto){let[j,ce]=F.facets,me=j.scale,we=ce.scale,[Fe,Oe]=e[X],Be=v[me],it=v[we];Be!=null&&Ge(Be,W[me],j,Fe,j.sorted),it!=null&&Ge(it,W[we],ce,Oe,ce.sorted),F.min=ce.min,F.max=ce.max}});for(let F in v){let X=v[F],j=W[F];if(X.from==null&&(j==null||j.min==null)){let ce=X.range(n,X.min==kt?null:X.min,X.max==-kt?null:X.max,F);X.min=ce[0],X.max=ce[1]}}}for(let F in v){let X=v[F];if(X.from!=null){let j=v[X.from];if(j.min==null)X.min=X.max=null;else{let ce=X.range(n,j.min,j.max,F);X.min=ce[0],X.max=ce[1]}}}let E={},D=!1;for(let F in v){let X=v[F],j=y[F];if(j.min!=X.min||j.max!=X.max){j.min=X.min,j.max=X.max;let ce=j.distr;j._min=ce==3?us(j.min):ce==4?wc(j.min,j.asinh):ce==100?j.fwd(j.min):j.min,j._max=ce==3?us(j.max):ce==4?wc(j.max,j.asinh):ce==100?j.fwd(j.max):j.max,E[F]=D=!0}}if(D){x.forEach((F,X)=>{s==2?X>0&&E.y&&(F._paths=null):E[F.scale]&&(F._paths=null)});for(let F in E)be=!0,Tn("setScale",F);_e&&fe.left>=0&&(ne=ge=!0)}for(let F in W)W[F]=null}function He(v){let E=Ph(sn-1,0,Qt-1),D=Ph(rn+1,0,Qt-1);for(;v[E]==null&&E>0;)E--;for(;v[D]==null&&D<Qt-1;)D++;return[E,D]}function ut(){if(Qt>0){let v=x.some(E=>E._focus)&&Ne!=ze.alpha;v&&(u.globalAlpha=Ne=ze.alpha),x.forEach((E,D)=>{if(D>0&&E.show&&(jt(D,!1),jt(D,!0),E._paths==null)){let F=Ne;Ne!=E.alpha&&(u.globalAlpha=Ne=E.alpha);let X=s==2?[0,e[D][0].length-1]:He(e[D]);E._paths=E.paths(n,D,X[0],X[1]),Ne!=F&&(u.globalAlpha=Ne=F)}}),x.forEach((E,D)=>{if(D>0&&E.show){let F=Ne;Ne!=E.alpha&&(u.globalAlpha=Ne=E.alpha),E._paths!=null&&Ct(D,!1);{let X=E._paths!=null?E._paths.gaps:null,j=E.points.show(n,D,sn,rn,X),ce=E.points.filter(n,D,j,X);(j||ce)&&(E.points._paths=E.points.paths(n,D,sn,rn,ce),Ct(D,!0))}Ne!=F&&(u.globalAlpha=Ne=F),Tn("drawSeries",D)}}),v&&(u.globalAlpha=Ne=1)}}function jt(v,E){let D=E?x[v].points:x[v];D._stroke=D.stroke(n,v),D._fill=D.fill(n,v)}function Ct(v,E){let D=E?x[v].points:x[v],{stroke:F,fill:X,clip:j,flags:ce,_stroke:me=D._stroke,_fill:we=D._fill,_width:Fe=D.width}=D._paths;Fe=Bt(Fe*wt,3);let Oe=null,Be=Fe%2/2;E&&we==null&&(we=Fe>0?"#fff":me);let it=D.pxAlign==1&&Be>0;if(it&&u.translate(Be,Be),!E){let bt=C-Fe/2,yt=M-Fe/2,ft=$+Fe,Je=de+Fe;Oe=new Path2D,Oe.rect(bt,yt,ft,Je)}E?ke(me,Fe,D.dash,D.cap,we,F,X,ce,j):Pt(v,me,Fe,D.dash,D.cap,we,F,X,ce,Oe,j),it&&u.translate(-Be,-Be)}function Pt(v,E,D,F,X,j,ce,me,we,Fe,Oe){let Be=!1;we!=0&&A.forEach((it,bt)=>{if(it.series[0]==v){let yt=x[it.series[1]],ft=e[it.series[1]],Je=(yt._paths||Aa).band;ws(Je)&&(Je=it.dir==1?Je[0]:Je[1]);let $e,qt=null;yt.show&&Je&&_w(ft,sn,rn)?(qt=it.fill(n,bt)||j,$e=yt._paths.clip):Je=null,ke(E,D,F,X,qt,ce,me,we,Fe,Oe,$e,Je),Be=!0}}),Be||ke(E,D,F,X,j,ce,me,we,Fe,Oe)}const mn=$r|Nh;function ke(v,E,D,F,X,j,ce,me,we,Fe,Oe,Be){Ce(v,E,D,F,X),(we||Fe||Be)&&(u.save(),we&&u.clip(we),Fe&&u.clip(Fe)),Be?(me&mn)==mn?(u.clip(Be),Oe&&u.clip(Oe),gt(X,ce),cn(v,j,E)):me&Nh?(gt(X,ce),u.clip(Be),cn(v,j,E)):me&$r&&(u.save(),u.clip(Be),Oe&&u.clip(Oe),gt(X,ce),u.restore(),cn(v,j,E)):(gt(X,ce),cn(v,j,E)),(we||Fe||Be)&&u.restore()}function cn(v,E,D){D>0&&(E instanceof Map?E.forEach((F,X)=>{u.strokeStyle=nr=X,u.stroke(F)}):E!=null&&v&&u.stroke(E))}function gt(v,E){E instanceof Map?E.forEach((D,F)=>{u.fillStyle=ps=F,u.fill(D)}):E!=null&&v&&u.fill(E)}function Qi(v,E,D,F){let X=R[v],j;if(F<=0)j=[0,0];else{let ce=X._space=X.space(n,v,E,D,F),me=X._incrs=X.incrs(n,v,E,D,F,ce);j=kE(E,D,me,F,ce)}return X._found=j}function hn(v,E,D,F,X,j,ce,me,we,Fe){let Oe=ce%2/2;S==1&&u.translate(Oe,Oe),Ce(me,ce,we,Fe,me),u.beginPath();let Be,it,bt,yt,ft=X+(F==0||F==3?-j:j);D==0?(it=X,yt=ft):(Be=X,bt=ft);for(let Je=0;Je<v.length;Je++)E[Je]!=null&&(D==0?Be=bt=v[Je]:it=yt=v[Je],u.moveTo(Be,it),u.lineTo(bt,yt));u.stroke(),S==1&&u.translate(-Oe,-Oe)}function sr(v){let E=!0;return R.forEach((D,F)=>{if(!D.show)return;let X=y[D.scale];if(X.min==null){D._show&&(E=!1,D._show=!1,ot(!1));return}else D._show||(E=!1,D._show=!0,ot(!1));let j=D.side,ce=j%2,{min:me,max:we}=X,[Fe,Oe]=Qi(F,me,we,ce==0?O:Le);if(Oe==0)return;let Be=X.distr==2,it=D._splits=D.splits(n,F,me,we,Fe,Oe,Be),bt=X.distr==2?it.map($e=>Zn[$e]):it,yt=X.distr==2?Zn[it[1]]-Zn[it[0]]:Fe,ft=D._values=D.values(n,D.filter(n,bt,F,Oe,yt),F,Oe,yt);D._rotate=j==2?D.rotate(n,ft,F,Oe):0;let Je=D._size;D._size=di(D.size(n,ft,F,v)),Je!=null&&D._size!=Je&&(E=!1)}),E}function Di(v){let E=!0;return jr.forEach((D,F)=>{let X=D(n,F,Pi,v);X!=vi[F]&&(E=!1),vi[F]=X}),E}function es(){for(let v=0;v<R.length;v++){let E=R[v];if(!E.show||!E._show)continue;let D=E.side,F=D%2,X,j,ce=E.stroke(n,v),me=D==0||D==3?-1:1,[we,Fe]=E._found;if(E.label!=null){let zn=E.labelGap*me,Qn=vn((E._lpos+zn)*wt);Ie(E.labelFont[0],ce,"center",D==2?pa:hf),u.save(),F==1?(X=j=0,u.translate(Qn,vn(M+de/2)),u.rotate((D==3?-Xo:Xo)/2)):(X=vn(C+$/2),j=Qn);let Os=bm(E.label)?E.label(n,v,we,Fe):E.label;u.fillText(Os,X,j),u.restore()}if(Fe==0)continue;let Oe=y[E.scale],Be=F==0?$:de,it=F==0?C:M,bt=E._splits,yt=Oe.distr==2?bt.map(zn=>Zn[zn]):bt,ft=Oe.distr==2?Zn[bt[1]]-Zn[bt[0]]:we,Je=E.ticks,$e=E.border,qt=Je.show?Je.size:0,tn=vn(qt*wt),An=vn((E.alignTo==2?E._size-qt-E.gap:E.gap)*wt),It=E._rotate*-Xo/180,nn=p(E._pos*wt),Jn=(tn+An)*me,Bn=nn+Jn;j=F==0?Bn:0,X=F==1?Bn:0;let ai=E.font[0],xi=E.align==1?Rr:E.align==2?yc:It>0?Rr:It<0?yc:F==0?"center":D==3?yc:Rr,Ui=It||F==1?"middle":D==2?pa:hf;Ie(ai,ce,xi,Ui);let jn=E.font[1]*E.lineGap,oi=bt.map(zn=>p(o(zn,Oe,Be,it))),Si=E._values;for(let zn=0;zn<Si.length;zn++){let Qn=Si[zn];if(Qn!=null){F==0?X=oi[zn]:j=oi[zn],Qn=""+Qn;let Os=Qn.indexOf(`
`)==-1?[Qn]:Qn.split(/\n/gm);for(let Hn=0;Hn<Os.length;Hn++){let zu=Os[Hn];It?(u.save(),u.translate(X,j+Hn*jn),u.rotate(It),u.fillText(zu,0,0),u.restore()):u.fillText(zu,X,j+Hn*jn)}}}Je.show&&hn(oi,Je.filter(n,yt,v,Fe,ft),F,D,nn,tn,Bt(Je.width*wt,3),Je.stroke(n,v),Je.dash,Je.cap);let Fi=E.grid;Fi.show&&hn(oi,Fi.filter(n,yt,v,Fe,ft),F,F==0?2:1,F==0?M:C,F==0?de:$,Bt(Fi.width*wt,3),Fi.stroke(n,v),Fi.dash,Fi.cap),$e.show&&hn([nn],[1],F==0?1:0,F==0?1:2,F==1?M:C,F==1?de:$,Bt($e.width*wt,3),$e.stroke(n,v),$e.dash,$e.cap)}Tn("drawAxes")}function ot(v){x.forEach((E,D)=>{D>0&&(E._paths=null,v&&(s==1?(E.min=null,E.max=null):E.facets.forEach(F=>{F.min=null,F.max=null})))})}let en=!1,kn=!1,Lt=[];function un(){kn=!1;for(let v=0;v<Lt.length;v++)Tn(...Lt[v]);Lt.length=0}function Dn(){en||(Lw(Mu),en=!0)}function Ya(v,E=!1){en=!0,kn=E,v(n),Mu(),E&&Lt.length>0&&queueMicrotask(un)}n.batch=Ya;function Mu(){if(le&&(ht(),le=!1),be&&(Ae(),be=!1),ye){if(Yt(m,Rr,qe),Yt(m,pa,st),Yt(m,xa,O),Yt(m,Sa,Le),Yt(_,Rr,qe),Yt(_,pa,st),Yt(_,xa,O),Yt(_,Sa,Le),Yt(d,xa,Vt),Yt(d,Sa,Kt),h.width=vn(Vt*wt),h.height=vn(Kt*wt),R.forEach(({_el:v,_show:E,_size:D,_pos:F,side:X})=>{if(v!=null)if(E){let j=X===3||X===0?D:0,ce=X%2==1;Yt(v,ce?"left":"top",F-j),Yt(v,ce?"width":"height",D),Yt(v,ce?"top":"left",ce?st:qe),Yt(v,ce?"height":"width",ce?Le:O),Rh(v,Xs)}else ni(v,Xs)}),nr=ps=ir=G=Q=Y=K=Re=T=null,Ne=1,ia(!0),qe!=Te||st!=Ft||O!=Ve||Le!=Ke){ot(!1);let v=O/Ve,E=Le/Ke;if(_e&&!ne&&fe.left>=0){fe.left*=v,fe.top*=E,rr&&zi(rr,vn(fe.left),0,O,Le),ar&&zi(ar,0,vn(fe.top),O,Le);for(let D=0;D<at.length;D++){let F=at[D];F!=null&&(Wt[D]*=v,On[D]*=E,zi(F,di(Wt[D]),di(On[D]),O,Le))}}if($t.show&&!re&&$t.left>=0&&$t.width>0){$t.left*=v,$t.width*=v,$t.top*=E,$t.height*=E;for(let D in Cl)Yt(cr,D,$t[D])}Te=qe,Ft=st,Ve=O,Ke=Le}Tn("setSize"),ye=!1}Vt>0&&Kt>0&&(u.clearRect(0,0,h.width,h.height),Tn("drawClear"),b.forEach(v=>v()),Tn("draw")),$t.show&&re&&(Ka($t),re=!1),_e&&ne&&(Fs(null,!0,!1),ne=!1),pe.show&&pe.live&&ge&&(Al(),ge=!1),l||(l=!0,n.status=1,Tn("ready")),fs=!1,en=!1}n.redraw=(v,E)=>{be=E||!1,v!==!1?gs(w,P.min,P.max):Dn()};function wl(v,E){let D=y[v];if(D.from==null){if(Qt==0){let F=D.range(n,E.min,E.max,v);E.min=F[0],E.max=F[1]}if(E.min>E.max){let F=E.min;E.min=E.max,E.max=F}if(Qt>1&&E.min!=null&&E.max!=null&&E.max-E.min<1e-16)return;v==w&&D.distr==2&&Qt>0&&(E.min=Ti(E.min,e[0]),E.max=Ti(E.max,e[0]),E.min==E.max&&E.max++),W[v]=E,le=!0,Dn()}}n.setScale=wl;let El,Tl,rr,ar,bu,wu,or,lr,Eu,Tu,Xt,Zt,ms=!1;const Pn=fe.drag;let wn=Pn.x,En=Pn.y;_e&&(fe.x&&(El=hi(tw,_)),fe.y&&(Tl=hi(nw,_)),P.ori==0?(rr=El,ar=Tl):(rr=Tl,ar=El),Xt=fe.left,Zt=fe.top);const $t=n.select=pn({show:!0,over:!0,left:0,width:0,top:0,height:0},i.select),cr=$t.show?hi(ew,$t.over?_:m):null;function Ka(v,E){if($t.show){for(let D in v)$t[D]=v[D],D in Cl&&Yt(cr,D,v[D]);E!==!1&&Tn("setSelect")}}n.setSelect=Ka;function cg(v){if(x[v].show)te&&Rh(oe[v],Xs);else if(te&&ni(oe[v],Xs),_e){let D=De?at[0]:at[v];D!=null&&zi(D,-10,-10,O,Le)}}function gs(v,E,D){wl(v,{min:E,max:D})}function Ni(v,E,D,F){E.focus!=null&&pg(v),E.show!=null&&x.forEach((X,j)=>{j>0&&(v==j||v==null)&&(X.show=E.show,cg(j),s==2?(gs(X.facets[0].scale,null,null),gs(X.facets[1].scale,null,null)):gs(X.scale,null,null),Dn())}),D!==!1&&Tn("setSeries",v,E),F&&sa("setSeries",n,v,E)}n.setSeries=Ni;function hg(v,E){pn(A[v],E)}function ug(v,E){v.fill=_t(v.fill||null),v.dir=Mt(v.dir,-1),E=E??A.length,A.splice(E,0,v)}function dg(v){v==null?A.length=0:A.splice(v,1)}n.addBand=ug,n.setBand=hg,n.delBand=dg;function fg(v,E){x[v].alpha=E,_e&&at[v]!=null&&(at[v].style.opacity=E),te&&oe[v]&&(oe[v].style.opacity=E)}let ts,_s,Us;const hr={focus:!0};function pg(v){if(v!=Us){let E=v==null,D=ze.alpha!=1;x.forEach((F,X)=>{if(s==1||X>0){let j=E||X==0||X==v;F._focus=E?null:j,D&&fg(X,j?1:ze.alpha)}}),Us=v,D&&Dn()}}te&&et&&dt(pf,Pe,v=>{fe._lock||(Qe(v),Us!=null&&Ni(null,hr,!0,dn.setSeries))});function Ii(v,E,D){let F=y[E];D&&(v=v/wt-(F.ori==1?st:qe));let X=O;F.ori==1&&(X=Le,v=X-v),F.dir==-1&&(v=X-v);let j=F._min,ce=F._max,me=v/X,we=j+(ce-j)*me,Fe=F.distr;return Fe==3?Vr(10,we):Fe==4?xw(we,F.asinh):Fe==100?F.bwd(we):we}function mg(v,E){let D=Ii(v,w,E);return Ti(D,e[0],sn,rn)}n.valToIdx=v=>Ti(v,e[0]),n.posToIdx=mg,n.posToVal=Ii,n.valToPos=(v,E,D)=>y[E].ori==0?r(v,y[E],D?$:O,D?C:0):a(v,y[E],D?de:Le,D?M:0),n.setCursor=(v,E,D)=>{Xt=v.left,Zt=v.top,Fs(null,E,D)};function Au(v,E){Yt(cr,Rr,$t.left=v),Yt(cr,xa,$t.width=E)}function Ru(v,E){Yt(cr,pa,$t.top=v),Yt(cr,Sa,$t.height=E)}let ta=P.ori==0?Au:Ru,na=P.ori==1?Au:Ru;function gg(){if(te&&pe.live)for(let v=s==2?1:0;v<x.length;v++){if(v==0&&Ze)continue;let E=pe.values[v],D=0;for(let F in E)ve[v][D++].firstChild.nodeValue=E[F]}}function Al(v,E){if(v!=null&&(v.idxs?v.idxs.forEach((D,F)=>{se[F]=D}):bw(v.idx)||se.fill(v.idx),pe.idx=se[0]),te&&pe.live){for(let D=0;D<x.length;D++)(D>0||s==1&&!Ze)&&_g(D,se[D]);gg()}ge=!1,E!==!1&&Tn("setLegend")}n.setLegend=Al;function _g(v,E){let D=x[v],F=v==0&&B==2?Zn:e[v],X;Ze?X=D.values(n,v,E)??je:(X=D.value(n,E==null?null:F[E],v,E),X=X==null?je:{_:X}),pe.values[v]=X}function Fs(v,E,D){Eu=Xt,Tu=Zt,[Xt,Zt]=fe.move(n,Xt,Zt),fe.left=Xt,fe.top=Zt,_e&&(rr&&zi(rr,vn(Xt),0,O,Le),ar&&zi(ar,0,vn(Zt),O,Le));let F,X=sn>rn;ts=kt,_s=null;let j=P.ori==0?O:Le,ce=P.ori==1?O:Le;if(Xt<0||Qt==0||X){F=fe.idx=null;for(let me=0;me<x.length;me++){let we=at[me];we!=null&&zi(we,-10,-10,O,Le)}et&&Ni(null,hr,!0,v==null&&dn.setSeries),pe.live&&(se.fill(F),ge=!0)}else{let me,we,Fe;s==1&&(me=P.ori==0?Xt:Zt,we=Ii(me,w),F=fe.idx=Ti(we,e[0],sn,rn),Fe=V(e[0][F],P,j,0));let Oe=-10,Be=-10,it=0,bt=0,yt=!0,ft="",Je="";for(let $e=s==2?1:0;$e<x.length;$e++){let qt=x[$e],tn=se[$e],An=tn==null?null:s==1?e[$e][tn]:e[$e][1][tn],It=fe.dataIdx(n,$e,F,we),nn=It==null?null:s==1?e[$e][It]:e[$e][1][It];if(ge=ge||nn!=An||It!=tn,se[$e]=It,$e>0&&qt.show){let Jn=It==null?-10:It==F?Fe:V(s==1?e[0][It]:e[$e][0][It],P,j,0),Bn=nn==null?-10:U(nn,s==1?y[qt.scale]:y[qt.facets[1].scale],ce,0);if(et&&nn!=null){let ai=P.ori==1?Xt:Zt,xi=xn(ze.dist(n,$e,It,Bn,ai));if(xi<ts){let Ui=ze.bias;if(Ui!=0){let jn=Ii(ai,qt.scale),oi=nn>=0?1:-1,Si=jn>=0?1:-1;Si==oi&&(Si==1?Ui==1?nn>=jn:nn<=jn:Ui==1?nn<=jn:nn>=jn)&&(ts=xi,_s=$e)}else ts=xi,_s=$e}}if(ge||De){let ai,xi;P.ori==0?(ai=Jn,xi=Bn):(ai=Bn,xi=Jn);let Ui,jn,oi,Si,Fi,zn,Qn=!0,Os=ue.bbox;if(Os!=null){Qn=!1;let Hn=Os(n,$e);oi=Hn.left,Si=Hn.top,Ui=Hn.width,jn=Hn.height}else oi=ai,Si=xi,Ui=jn=ue.size(n,$e);if(zn=ue.fill(n,$e),Fi=ue.stroke(n,$e),De)$e==_s&&ts<=ze.prox&&(Oe=oi,Be=Si,it=Ui,bt=jn,yt=Qn,ft=zn,Je=Fi);else{let Hn=at[$e];Hn!=null&&(Wt[$e]=oi,On[$e]=Si,yf(Hn,Ui,jn,Qn),xf(Hn,zn,Fi),zi(Hn,di(oi),di(Si),O,Le))}}}}if(De){let $e=ze.prox,qt=Us==null?ts<=$e:ts>$e||_s!=Us;if(ge||qt){let tn=at[0];tn!=null&&(Wt[0]=Oe,On[0]=Be,yf(tn,it,bt,yt),xf(tn,ft,Je),zi(tn,di(Oe),di(Be),O,Le))}}}if($t.show&&ms)if(v!=null){let[me,we]=dn.scales,[Fe,Oe]=dn.match,[Be,it]=v.cursor.sync.scales,bt=v.cursor.drag;if(wn=bt._x,En=bt._y,wn||En){let{left:yt,top:ft,width:Je,height:$e}=v.select,qt=v.scales[Be].ori,tn=v.posToVal,An,It,nn,Jn,Bn,ai=me!=null&&Fe(me,Be),xi=we!=null&&Oe(we,it);ai&&wn?(qt==0?(An=yt,It=Je):(An=ft,It=$e),nn=y[me],Jn=V(tn(An,Be),nn,j,0),Bn=V(tn(An+It,Be),nn,j,0),ta(Ri(Jn,Bn),xn(Bn-Jn))):ta(0,j),xi&&En?(qt==1?(An=yt,It=Je):(An=ft,It=$e),nn=y[we],Jn=U(tn(An,it),nn,ce,0),Bn=U(tn(An+It,it),nn,ce,0),na(Ri(Jn,Bn),xn(Bn-Jn))):na(0,ce)}else Pl()}else{let me=xn(Eu-bu),we=xn(Tu-wu);if(P.ori==1){let it=me;me=we,we=it}wn=Pn.x&&me>=Pn.dist,En=Pn.y&&we>=Pn.dist;let Fe=Pn.uni;Fe!=null?wn&&En&&(wn=me>=Fe,En=we>=Fe,!wn&&!En&&(we>me?En=!0:wn=!0)):Pn.x&&Pn.y&&(wn||En)&&(wn=En=!0);let Oe,Be;wn&&(P.ori==0?(Oe=or,Be=Xt):(Oe=lr,Be=Zt),ta(Ri(Oe,Be),xn(Be-Oe)),En||na(0,ce)),En&&(P.ori==1?(Oe=or,Be=Xt):(Oe=lr,Be=Zt),na(Ri(Oe,Be),xn(Be-Oe)),wn||ta(0,j)),!wn&&!En&&(ta(0,0),na(0,0))}if(Pn._x=wn,Pn._y=En,v==null){if(D){if(Bu!=null){let[me,we]=dn.scales;dn.values[0]=me!=null?Ii(P.ori==0?Xt:Zt,me):null,dn.values[1]=we!=null?Ii(P.ori==1?Xt:Zt,we):null}sa(Mc,n,Xt,Zt,O,Le,F)}if(et){let me=D&&dn.setSeries,we=ze.prox;Us==null?ts<=we&&Ni(_s,hr,!0,me):ts>we?Ni(null,hr,!0,me):_s!=Us&&Ni(_s,hr,!0,me)}}ge&&(pe.idx=F,Al()),E!==!1&&Tn("setCursor")}let vs=null;Object.defineProperty(n,"rect",{get(){return vs==null&&ia(!1),vs}});function ia(v=!1){v?vs=null:(vs=_.getBoundingClientRect(),Tn("syncRect",vs))}function Cu(v,E,D,F,X,j,ce){fe._lock||ms&&v!=null&&v.movementX==0&&v.movementY==0||(Rl(v,E,D,F,X,j,ce,!1,v!=null),v!=null?Fs(null,!0,!0):Fs(E,!0,!1))}function Rl(v,E,D,F,X,j,ce,me,we){if(vs==null&&ia(!1),Qe(v),v!=null)D=v.clientX-vs.left,F=v.clientY-vs.top;else{if(D<0||F<0){Xt=-10,Zt=-10;return}let[Fe,Oe]=dn.scales,Be=E.cursor.sync,[it,bt]=Be.values,[yt,ft]=Be.scales,[Je,$e]=dn.match,qt=E.axes[0].side%2==1,tn=P.ori==0?O:Le,An=P.ori==1?O:Le,It=qt?j:X,nn=qt?X:j,Jn=qt?F:D,Bn=qt?D:F;if(yt!=null?D=Je(Fe,yt)?o(it,y[Fe],tn,0):-10:D=tn*(Jn/It),ft!=null?F=$e(Oe,ft)?o(bt,y[Oe],An,0):-10:F=An*(Bn/nn),P.ori==1){let ai=D;D=F,F=ai}}we&&(E==null||E.cursor.event.type==Mc)&&((D<=1||D>=O-1)&&(D=Vs(D,O)),(F<=1||F>=Le-1)&&(F=Vs(F,Le))),me?(bu=D,wu=F,[or,lr]=fe.move(n,D,F)):(Xt=D,Zt=F)}const Cl={width:0,height:0,left:0,top:0};function Pl(){Ka(Cl,!1)}let Pu,Lu,Du,Nu;function Iu(v,E,D,F,X,j,ce){ms=!0,wn=En=Pn._x=Pn._y=!1,Rl(v,E,D,F,X,j,ce,!0,!1),v!=null&&(dt(bc,Th,Uu,!1),sa(df,n,or,lr,O,Le,null));let{left:me,top:we,width:Fe,height:Oe}=$t;Pu=me,Lu=we,Du=Fe,Nu=Oe}function Uu(v,E,D,F,X,j,ce){ms=Pn._x=Pn._y=!1,Rl(v,E,D,F,X,j,ce,!1,!0);let{left:me,top:we,width:Fe,height:Oe}=$t,Be=Fe>0||Oe>0,it=Pu!=me||Lu!=we||Du!=Fe||Nu!=Oe;if(Be&&it&&Ka($t),Pn.setScale&&Be&&it){let bt=me,yt=Fe,ft=we,Je=Oe;if(P.ori==1&&(bt=we,yt=Oe,ft=me,Je=Fe),wn&&gs(w,Ii(bt,w),Ii(bt+yt,w)),En)for(let $e in y){let qt=y[$e];$e!=w&&qt.from==null&&qt.min!=kt&&gs($e,Ii(ft+Je,$e),Ii(ft,$e))}Pl()}else fe.lock&&(fe._lock=!fe._lock,Fs(E,!0,v!=null));v!=null&&(Rt(bc,Th),sa(bc,n,Xt,Zt,O,Le,null))}function vg(v,E,D,F,X,j,ce){if(fe._lock)return;Qe(v);let me=ms;if(ms){let we=!0,Fe=!0,Oe=10,Be,it;P.ori==0?(Be=wn,it=En):(Be=En,it=wn),Be&&it&&(we=Xt<=Oe||Xt>=O-Oe,Fe=Zt<=Oe||Zt>=Le-Oe),Be&&we&&(Xt=Xt<or?0:O),it&&Fe&&(Zt=Zt<lr?0:Le),Fs(null,!0,!0),ms=!1}Xt=-10,Zt=-10,se.fill(null),Fs(null,!0,!0),me&&(ms=me)}function Fu(v,E,D,F,X,j,ce){fe._lock||(Qe(v),ea(),Pl(),v!=null&&sa(mf,n,Xt,Zt,O,Le,null))}function Ou(){R.forEach(BE),k(n.width,n.height,!0)}qs(il,kr,Ou);const ur={};ur.mousedown=Iu,ur.mousemove=Cu,ur.mouseup=Uu,ur.dblclick=Fu,ur.setSeries=(v,E,D,F)=>{let X=dn.match[2];D=X(n,E,D),D!=-1&&Ni(D,F,!0,!1)},_e&&(dt(df,_,Iu),dt(Mc,_,Cu),dt(ff,_,v=>{Qe(v),ia(!1)}),dt(pf,_,vg),dt(mf,_,Fu),Ih.add(n),n.syncRect=ia);const Za=n.hooks=i.hooks||{};function Tn(v,E,D){kn?Lt.push([v,E,D]):v in Za&&Za[v].forEach(F=>{F.call(null,n,E,D)})}(i.plugins||[]).forEach(v=>{for(let E in v.hooks)Za[E]=(Za[E]||[]).concat(v.hooks[E])});const ku=(v,E,D)=>D,dn=pn({key:null,setSeries:!1,filters:{pub:Tf,sub:Tf},scales:[w,x[1]?x[1].scale:null],match:[Af,Af,ku],values:[null,null]},fe.sync);dn.match.length==2&&dn.match.push(ku),fe.sync=dn;const Bu=dn.key,Ll=qm(Bu);function sa(v,E,D,F,X,j,ce){dn.filters.pub(v,E,D,F,X,j,ce)&&Ll.pub(v,E,D,F,X,j,ce)}Ll.sub(n);function xg(v,E,D,F,X,j,ce){dn.filters.sub(v,E,D,F,X,j,ce)&&ur[v](null,E,D,F,X,j,ce)}n.pub=xg;function Sg(){Ll.unsub(n),Ih.delete(n),Jt.clear(),Ch(il,kr,Ou),c.remove(),Pe?.remove(),Tn("destroy")}n.destroy=Sg;function Dl(){Tn("init",i,e),Qr(e||i.data,!1),W[w]?wl(w,W[w]):ea(),re=$t.show&&($t.width>0||$t.height>0),ne=ge=!0,k(i.width,i.height)}return x.forEach(tr),R.forEach(Ji),t?t instanceof HTMLElement?(t.appendChild(c),Dl()):t(n,Dl):Dl(),n}Fn.assign=pn;Fn.fmtNum=uu;Fn.rangeNum=sl;Fn.rangeLog=ml;Fn.rangeAsinh=cu;Fn.orient=er;Fn.pxRatio=wt;Fn.join=Pw;Fn.fmtDate=fu,Fn.tzDate=Hw;Fn.sync=qm;{Fn.addGap=bE,Fn.clipGaps=vl;let i=Fn.paths={points:Qm};i.linear=tg,i.stepped=TE,i.bars=AE,i.spline=CE}class Ml{shown=new Map;observer;constructor(){this.observer=typeof IntersectionObserver>"u"?null:new IntersectionObserver(e=>{for(const t of e)this.shown.set(t.target,t.isIntersecting)})}watch(e){this.shown.set(e,!0),this.observer?.observe(e)}visible(e){return this.shown.get(e)??!0}}const zE=1e-6,HE=1e-12,Su=2**-52;function Fh(i,e,t=.05){if(i===null||e===null||!Number.isFinite(i)||!Number.isFinite(e))return[-1,1];i>e&&([i,e]=[e,i]);const n=Math.max(zE*Math.max(Math.abs(i),Math.abs(e)),HE),s=e-i;if(s<n){const r=i/2+e/2;return[r-n/2,r+n/2]}return[i-t*s,e+t*s]}function GE(i,e){return!Number.isFinite(i)||!(e>0)?null:Math.max(Math.abs(i)/e,Su/10)}function VE(i,e){const t=Su/10,n=i!==null&&Number.isFinite(i)&&i>0?Math.min(i,t):t,s=e!==null&&Number.isFinite(e)&&e>0?Math.max(e,1e-12):1e-12;return[10**Math.floor(Math.log10(n)),10**Math.ceil(Math.log10(s)+1e-9)]}function WE(i,e,t,n,s){const r=Math.max(Math.abs(n),1);return{energy:Math.max(Math.abs(i),t*r*s),j3:Math.max(Math.abs(e),t*s*Math.sqrt(r*s))}}const Rc=[{title:"plot.dE",axis:"|ΔE|/E_s",key:"dE",color:"#ffb347",drift:"energy"},{title:"plot.dJ3",axis:"|ΔJ₃|/J_s",key:"dJ3",color:"#7dff8a",drift:"j3"},{title:"plot.z",axis:"z [m]",key:"z",color:"#59c3ff",events:!0},{title:"plot.tension",axis:"T [N]",key:"tension",color:"#ff5d73",events:!0}];function XE(i){if(i===null||!Number.isFinite(i))return"";if(i===0)return"0";const e=Math.abs(i);return e>=.001&&e<1e4?String(+i.toPrecision(4)):i.toExponential(0)}class $E{constructor(e,t=()=>{}){this.container=e;let n=0;const s={stroke:"#aab",grid:{stroke:"#2a2f3a"},ticks:{stroke:"#2a2f3a"},labelSize:16};for(const r of Rc){const a=document.createElement("div");a.className="plot",a.dataset.plot=r.key,e.appendChild(a),this.els.push(a),this.visibility.watch(a),this.shown.push({h:null,n:-1,t:NaN,ev:null});const o=[()=>t(performance.now()-n)];r.events&&o.push(c=>this.markEvents(c)),r.drift&&o.push(c=>this.markFloor(c));const l={title:L(r.title),width:this.width(),height:160,scales:{x:{time:!1,range:(c,h,u)=>Fh(h,u,0)},y:r.drift?{distr:3,log:10,range:(c,h,u)=>VE(h,u)}:{range:(c,h,u)=>Fh(h,u)}},legend:{show:!0,live:!1},hooks:{drawClear:[()=>{n=performance.now()}],draw:o},cursor:{show:!0,drag:{x:!1,y:!1}},series:[{label:"t [s]"},{label:r.axis,stroke:r.color,width:1.5}],axes:[{...s,label:L("plot.time")},{...s,label:r.axis,size:64,values:(c,h)=>h.map(XE)}]};this.charts.push(new Fn(l,[[],[]],a))}new ResizeObserver(()=>this.resize()).observe(e)}container;charts=[];els=[];visibility=new Ml;shown=[];events=[];width(){return Math.max(200,this.container.clientWidth-8)}resize(){for(const e of this.charts)e.setSize({width:this.width(),height:160})}markFloor(e){const{ctx:t,bbox:n}=e,s=Math.round(e.valToPos(Su,"y",!0))+.5;s>=n.top&&s<=n.top+n.height&&(t.save(),t.strokeStyle="#8a93a6",t.setLineDash([5,4]),t.beginPath(),t.moveTo(n.left,s),t.lineTo(n.left+n.width,s),t.stroke(),t.fillStyle="#8a93a6",t.font=`${Math.round(11*devicePixelRatio)}px system-ui, sans-serif`,t.textAlign="left",t.textBaseline="bottom",t.fillText(L("plot.floor"),n.left+4,s-3),t.restore())}markEvents(e){const[t,n]=[e.scales.x?.min,e.scales.x?.max];if(t===void 0||n===void 0||t===null||n===null)return;const{ctx:s,bbox:r}=e;s.save(),s.lineWidth=1,s.strokeStyle="#e0e0e0";for(const a of this.events){if(a.t<t||a.t>n)continue;const o=Math.round(e.valToPos(a.t,"x",!0))+.5;s.setLineDash(a.kind==="slack"?[4,3]:[]),s.beginPath(),s.moveTo(o,r.top),s.lineTo(o,r.top+r.height),s.stroke()}s.restore()}scales(){return Rc.map((e,t)=>{const n=this.charts[t]?.scales.y;return{key:e.key,distr:n?.distr??1,min:n?.min??null,max:n?.max??null}})}update(e,t=[],n={energy:1,j3:1}){this.events=t;const s=e.t.length,r=e.t[s-1]??NaN;Rc.forEach((a,o)=>{const l=this.charts[o],c=this.els[o],h=this.shown[o];if(l===void 0||c===void 0||h===void 0||!this.visibility.visible(c)||h.h===e&&h.n===s&&Object.is(h.t,r)&&h.ev===t)return;Object.assign(h,{h:e,n:s,t:r,ev:t});const u=e[a.key],d=a.drift;l.setData([e.t,d?u.map(m=>GE(m,n[d])):u])})}}function Ys(i,e=.1){let t=1/0,n=-1/0;for(const a of i)Number.isFinite(a)&&(a<t&&(t=a),a>n&&(n=a));if(t>n)return{lo:-1,hi:1};if(t===n)return{lo:t-Math.max(.5,Math.abs(t)*.1),hi:n+Math.max(.5,Math.abs(t)*.1)};const[s,r]=Fh(t,n,e);return{lo:s,hi:r}}function qE(i,e,t){const n=Math.max(e===null?0:e-i,.2*t);return{lo:i-.15*n,hi:i+2.2*n}}function Io(i,e=Math.abs(i)){if(i===0)return"0";const t=Math.abs(i),n=Math.min(12,Math.max(3,Math.ceil(Math.log10(t/Math.max(e,1e-300)))+2));return t>=.01&&t<1e4?String(+i.toPrecision(n)):i.toExponential(Math.max(1,n-2))}class Ra{constructor(e,t,n,s,r=150){this.xLabel=n,this.yLabel=s,this.height=r;const a=document.createElement("div");a.className="plot curve";const o=document.createElement("div");o.className="curve-title",o.textContent=t,a.appendChild(o),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("aria-label",t),a.appendChild(this.canvas),e.appendChild(a),this.ctx=this.canvas.getContext("2d")}xLabel;yLabel;height;canvas;ctx;draw(e,t,n,s,r={}){const a=this.ctx;if(a===null)return;const o=Math.min(window.devicePixelRatio||1,2),l=Math.max(100,e),c=this.height;this.canvas.width!==Math.round(l*o)&&(this.canvas.width=Math.round(l*o),this.canvas.height=Math.round(c*o),this.canvas.style.width=`${l}px`,this.canvas.style.height=`${c}px`),a.setTransform(o,0,0,o,0,0),a.clearRect(0,0,l,c);const h=56,u=c-20,d=6,m=l-8,_=x=>h+(x-n.lo)/(n.hi-n.lo)*(m-h),S=x=>u-(x-s.lo)/(s.hi-s.lo)*(u-d);a.strokeStyle="#2a2f3a",a.strokeRect(h,d,m-h,u-d),a.fillStyle="#aab",a.font="11px system-ui, sans-serif",a.fillText(Io(s.hi,s.hi-s.lo),4,d+10),a.fillText(Io(s.lo,s.hi-s.lo),4,u),a.fillText(this.yLabel,4,(d+u)/2),a.fillText(Io(n.lo,n.hi-n.lo),h,c-4);const p=Io(n.hi,n.hi-n.lo);a.fillText(p,m-a.measureText(p).width,c-4),a.fillText(this.xLabel,(h+m)/2-10,c-4),a.save(),a.beginPath(),a.rect(h,d,m-h,u-d),a.clip(),r.hLine!==void 0&&r.hLine!==null&&this.line(a,h,S(r.hLine),m,S(r.hLine),"#ffb347"),r.vLine!==void 0&&r.vLine!==null&&this.line(a,_(r.vLine),d,_(r.vLine),u,"#888");for(const x of t){a.strokeStyle=x.color,a.lineWidth=1.5,a.beginPath();let R=!1;for(let y=0;y<x.x.length;y++){const A=x.x[y],w=x.y[y];if(!Number.isFinite(A)||!Number.isFinite(w)){R=!1;continue}const g=Math.max(-1e4,Math.min(1e4,S(w)));R?a.lineTo(_(A),g):a.moveTo(_(A),g),R=!0}a.stroke()}r.dot&&(a.fillStyle="#ff8c42",a.beginPath(),a.arc(_(r.dot[0]),S(r.dot[1]),3.5,0,2*Math.PI),a.fill()),a.restore();let f=d+12;a.textAlign="right";for(const x of t)x.label&&(a.fillStyle=x.color,a.fillText(`— ${x.label}`,m-4,f),f+=13);a.textAlign="left"}line(e,t,n,s,r,a){e.strokeStyle=a,e.lineWidth=1,e.setLineDash([4,3]),e.beginPath(),e.moveTo(t,n),e.lineTo(s,r),e.stroke(),e.setLineDash([])}}function YE(i){return Math.atan2(Math.hypot(i[0],i[1]),-i[2])}class KE{constructor(e){this.container=e,this.phase=new Ra(e,L("portrait.phase"),"z [m]","ż [m/s]"),this.potential=new Ra(e,L("portrait.veff"),"θ [rad]","E [J]"),this.em=new Ra(e,L("portrait.em"),"J₃ [kg m²/s]","E [J]");for(const t of[this.phase,this.potential,this.em])this.visibility.watch(t.canvas);this.note=document.createElement("p"),this.note.className="note",this.note.dataset.note="portraits",e.appendChild(this.note)}container;phase;potential;em;note;visibility=new Ml;setModel(e){const t=Vh(e)??"";this.note.textContent!==t&&(this.note.textContent=t)}updateEM(e,t){if(!this.visibility.visible(this.em.canvas))return;const n=Math.max(200,this.container.clientWidth-8);if(e===null){this.em.draw(n,[],{lo:-1,hi:1},{lo:-1,hi:1});return}const s=e.top.energy,r=Ys([...e.boundary.j3.filter((o,l)=>(e.boundary.energy[l]??1/0)<2.6*s),t?.j3??0],.05),a={lo:e.bottom.energy-.15*s,hi:Math.max(2.6*s,(t?.energy??0)+.2*s)};this.em.draw(n,[{x:e.boundary.j3,y:e.boundary.energy,color:"#c9a0ff",label:L("portrait.emBoundary")}],r,a,{vLine:0,hLine:e.top.energy,dot:t?[t.j3,t.energy]:null})}update(e,t,n,s,r,a){const o=Math.max(200,this.container.clientWidth-8);if(this.visibility.visible(this.phase.canvas)){const c=t?[t.x[2],t.v[2]]:null,h=Ys(t?[...e.z,t.x[2]]:e.z),u=Ys(t?[...e.zdot,t.v[2]]:e.zdot);this.phase.draw(o,[{x:e.z,y:e.zdot,color:"#59c3ff",label:L("portrait.orbit")}],h,u,{dot:c})}if(!this.visibility.visible(this.potential.canvas))return;if(n===null||n.theta.length===0){this.potential.draw(o,[],{lo:0,hi:Math.PI},{lo:-1,hi:1});return}const l=qE(n.minimum.v_eff,t?.energy??null,s*Math.max(Math.abs(r),1)*a);this.potential.draw(o,[{x:n.theta,y:n.v_eff,color:"#7dff8a",label:"V_eff(θ)"}],{lo:0,hi:Math.PI},l,{hLine:t?.energy??null,vLine:t?YE(t.x):null})}}async function Oh(i,e){const t=await fetch(i,e),n=await t.json();if(!t.ok){const s=n.detail;throw new Error(typeof s=="string"?s:`${i}: HTTP ${t.status}`)}return n}class rg extends Error{}const ZE=1;let Cc=0;const Kf=[];async function Uo(i,e,t=()=>!1){Cc>=ZE&&await new Promise(n=>Kf.push(n)),Cc++;try{if(t())throw new rg(`${i}: no longer needed`);return await Oh(i,{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(e)})}finally{Cc--,Kf.shift()?.()}}const Pc=i=>e=>{e instanceof rg||i(e)},Fo=i=>i instanceof Error?i.message:String(i);class JE{constructor(e,t,n){this.store=e,this.reduced=t,this.explain=n}store;reduced;explain;veff=null;em=null;veffKey="";veffAt=-1/0;veffJ3=null;emKey="";exactEpoch=-1;reducedEpoch=-1;onFrames(){const e=this.store.status,t=this.store.trajectory[0],n=this.store.latest();if(!(e===null||t===void 0||n===null)){if(this.exactEpoch!==e.epoch&&this.fetchExact(e,t),this.reducedEpoch!==e.epoch&&this.fetchReduced(e,t),!kg(e.model)){[this.veff,this.em,this.veffKey,this.emKey]=[null,null,"",""];return}this.fetchEM(e,t),this.fetchPotential(e,n)}}fetchPotential(e,t){const n=e.params,s=`${e.epoch}:${n.length}:${n.mass}:${n.g}`,r=performance.now(),a=Math.abs(t.j3-(this.veffJ3??NaN))>.001*Math.max(Math.abs(t.j3),1e-9);s===this.veffKey&&!(a&&r-this.veffAt>1e3)||(s!==this.veffKey&&(this.veff=null),[this.veffKey,this.veffAt,this.veffJ3]=[s,r,t.j3],Uo("api/effective_potential",{length:n.length,mass:n.mass,g:n.g,j3:t.j3},()=>this.veffKey!==s).then(o=>{this.veffKey===s&&(this.veff=o)},Pc(o=>this.explain(`V_eff: ${Fo(o)}`))))}fetchEM(e,t){const n=e.params,s=`${n.length}:${n.mass}:${n.g}`;s!==this.emKey&&(this.emKey=s,this.em=null,n.g!==0&&Uo("api/em_map",{length:n.length,mass:n.mass,g:n.g,x:t.x,v:t.v},()=>this.emKey!==s).then(r=>{this.emKey===s&&(this.em=r)},Pc(r=>this.explain(`energy–momentum map: ${Fo(r)}`))))}fetchReduced(e,t){if(this.reducedEpoch=e.epoch,e.model!=="ideal"){this.reduced.setNote(Vh(e.model)??L("note.reducedIdeal",{model:e.model}));return}this.reduced.setNote(null);const n=e.params,s=()=>this.store.status?.epoch!==e.epoch;Uo("api/reduced",{length:n.length,mass:n.mass,g:n.g,x:t.x,v:t.v},s).then(r=>{s()||this.reduced.set(r)},Pc(r=>this.reduced.setNote(`reduced view: ${Fo(r)}`)))}fetchExact(e,t){if(this.exactEpoch=e.epoch,e.model!=="ideal")return;const n=e.params;Uo("api/exact",{length:n.length,mass:n.mass,g:n.g,x:t.x,v:t.v},()=>this.store.status?.epoch!==e.epoch).then(s=>{this.store.status?.epoch===e.epoch&&this.store.setExact(s)},s=>{this.store.status?.epoch===e.epoch&&this.store.setExact(null,Fo(s))})}}function jE(i,e){const t=e*e;return[i.x[2]/e,i.v[2]/e,(i.v[0]**2+i.v[1]**2+i.v[2]**2)/t]}function QE(i){const e=Math.max(...i.surface.sigma2.map(Math.abs),1e-9),t=Math.max(...i.orbit.sigma3,i.point[2],1e-9);return{s2:e,s3top:1.6*t+1e-9}}class yu{constructor(e,t){this.container=e;const n=document.createElement("div");n.className="curve-title",n.textContent=L("data.reduced"),e.appendChild(n),this.renderer=new um({antialias:t.antialias,preserveDrawingBuffer:!0}),this.renderer.localClippingEnabled=!0,this.renderer.setPixelRatio(t.pixelRatio),this.renderer.domElement.className="reduced-canvas",e.appendChild(this.renderer.domElement),this.note=document.createElement("p"),this.note.className="note",e.appendChild(this.note),this.scene.background=new ct(1448482),this.camera.up.set(0,0,1),this.camera.position.set(3.2,-3.6,2.2),this.controls=new fm(this.camera,this.renderer.domElement),this.point=new on(new ls(.05,16,12),new Rs({color:16747586,depthTest:!1,transparent:!0})),this.point.renderOrder=3,this.point.visible=!1,this.scene.add(this.group,this.point,new Qp(1.2)),this.resize(),new ResizeObserver(()=>this.resize()).observe(e),new IntersectionObserver(s=>{this.visible=s.some(r=>r.isIntersecting)}).observe(this.renderer.domElement),this.controls.addEventListener("change",()=>{this.dirty=!0})}container;renderer;camera=new qn(35,1,.01,100);controls;scene=new Op;group=new Xi;point;scales=null;note;visible=!1;lastDrawn=-1/0;dirty=!0;resize(){const e=Math.max(200,this.container.clientWidth-8),t=220;this.renderer.setSize(e,t,!1),this.renderer.domElement.style.width=`${e}px`,this.renderer.domElement.style.height=`${t}px`,this.camera.aspect=e/t,this.camera.updateProjectionMatrix()}setNote(e){this.note.textContent=e??"",e!==null&&this.set(null)}set(e){for(const w of[...this.group.children]){this.group.remove(w);const g=w;g.geometry?.dispose(),g.material?.dispose()}if(this.scales=e===null?null:QE(e),this.dirty=!0,e===null||this.scales===null)return;const{s2:t,s3top:n}=this.scales,s=(w,g,b)=>new z(w,g/t,2*b/n-1),r=[new Ai(new z(0,0,-1),1)],{sigma1:a,sigma2:o,sigma3:l}=e.surface,c=[];a.forEach((w,g)=>o.forEach((b,I)=>c.push(...s(w,b,l[g]?.[I]??NaN).toArray())));const h=[],u=o.length;for(let w=0;w+1<a.length;w++)for(let g=0;g+1<u;g++){const b=w*u+g;h.push(b,b+u,b+1,b+1,b+u,b+u+1)}const d=new Gt;d.setAttribute("position",new ln(c,3)),d.setIndex(h);const m={color:9417727,transparent:!0,opacity:.25,side:pi,clippingPlanes:r};this.group.add(new on(d,new Rs({...m,depthWrite:!1}))),this.group.add(new on(d.clone(),new Rs({...m,wireframe:!0,opacity:.25})));const{h:_,gamma:S}=e.plane,p=(w,g)=>s(w,g,2*(_-S*w)),f=new Gt().setFromPoints([p(-1,-t),p(1,-t),p(1,t),p(-1,t)]);f.setIndex([0,1,2,0,2,3]);const x=new Rs({color:16757575,transparent:!0,opacity:.22,side:pi,depthWrite:!1,clippingPlanes:[...r,new Ai(new z(0,0,1),1)]});this.group.add(new on(f,x));const R=e.orbit,y=new Gt().setFromPoints(R.sigma1.map((w,g)=>s(w,R.sigma2[g]??NaN,R.sigma3[g]??NaN))),A=new Zi(y,new _i({color:5882879,depthTest:!1,transparent:!0}));A.renderOrder=2,this.group.add(A),this.point.visible=!0}update(e,t){if(this.scales!==null&&e!==null){const[s,r,a]=jE(e,t);this.point.position.set(s,r/this.scales.s2,2*a/this.scales.s3top-1)}this.point.visible=this.scales!==null&&e!==null;const n=performance.now();!this.visible||!this.dirty&&n-this.lastDrawn<yu.MIN_INTERVAL||(this.lastDrawn=n,this.dirty=!1,this.controls.update(),this.renderer.render(this.scene,this.camera))}static MIN_INTERVAL=250}class eT{constructor(e){this.intervalMs=e}intervalMs;last=-1/0;due(e){return e-this.last<this.intervalMs?!1:(this.last=e,!0)}reset(){this.last=-1/0}}class tT{last=null;changed(e){const t=this.last;return t!==null&&t.length===e.length&&e.every((n,s)=>Object.is(n,t[s]))?!1:(this.last=[...e],!0)}}class nT{sums=new Map;add(e,t){const n=this.sums.get(e);n===void 0?this.sums.set(e,{ms:t,count:1}):(n.ms+=t,n.count++)}take(){const e={};for(const[t,n]of this.sums)e[t]={ms:n.ms/n.count,count:n.count};return this.sums.clear(),e}}function iT(i){const e={model:i.model,length:i.params.length,mass:i.params.mass,g:i.params.g,params:{...i.model_params},x:i.start.x,v:i.start.v,method:i.method,dt:i.dt,t0:i.t0,t_end:Math.max(i.t0+100,Math.ceil(i.t))},t=i.title??i.scenario;return t&&(e.title=`${t} (from the lab)`),e}const Ma=180/Math.PI;function sT(i,e){const t={};for(const[n,s]of Object.entries(i))n in e&&e[n]!==s&&(t[n]=s);return t}function ag(i){const e=t=>$n(Number((t*Ma).toPrecision(12)));return i.mode==="own"?`own:${$n(i.length)}:${$n(i.mass)}:${e(i.theta)}`:i.mode==="epsilon"?`eps:${e(i.epsilon)}`:i.mode==="method"?`method:${i.method}`:i.mode==="damped"?`damped:${$n(i.damping)}`:null}function $n(i){return Object.is(i,-0)?"-0":String(i)}function rT(i){const e=new URLSearchParams;i.scenario!==void 0&&e.set("s",i.scenario),i.model!==void 0&&e.set("model",i.model),i.modelParams!==void 0&&Object.keys(i.modelParams).length>0&&e.set("mp",Object.entries(i.modelParams).map(([n,s])=>`${n}:${$n(s)}`).join(",")),i.length!==void 0&&e.set("l",$n(i.length)),i.mass!==void 0&&e.set("m",$n(i.mass)),i.g!==void 0&&e.set("g",$n(i.g)),i.method!==void 0&&e.set("method",i.method),i.dt!==void 0&&e.set("dt",$n(i.dt)),i.timeScale!==void 0&&e.set("ts",$n(i.timeScale)),i.x!==void 0&&e.set("x",i.x.map($n).join(",")),i.v!==void 0&&e.set("v",i.v.map($n).join(",")),i.paused===!0&&e.set("paused","1"),i.at!==void 0&&i.at>0&&e.set("at",$n(i.at)),i.view!==void 0&&Object.keys(i.view).length>0&&e.set("view",Object.entries(i.view).map(([n,s])=>typeof s=="boolean"?s?n:`-${n}`:`${n}:${typeof s=="number"?$n(s):s}`).join(",")),i.plot!==void 0&&e.set("plot",i.plot.join(","));const t=i.twin===void 0?null:ag(i.twin);return t!==null&&e.set("twin",t),i.lang!==void 0&&e.set("lang",i.lang),e.toString()}const og=/^[A-Za-z0-9_.-]{1,100}$/;function ba(i){if(!/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(i.trim()))return null;const e=Number(i);return Number.isFinite(e)?e:null}function aT(i){const e=new URLSearchParams(i.startsWith("?")?i.slice(1):i),t={},n=[],s=new Set(["s","model","mp","l","m","g","method","dt","ts","x","v","paused","lang","at","view","plot","twin"]);for(const I of e.keys())s.has(I)||n.push(`unknown URL key ${I}`);const r=I=>{const N=e.get(I);if(N!==null){if(!og.test(N)){n.push(`${I} = ${JSON.stringify(N)} is not a name`);return}return N}},a=I=>{const N=e.get(I);if(N===null)return;const P=ba(N);return P===null&&n.push(`${I} = ${JSON.stringify(N)} is not a finite number`),P??void 0},o=I=>{const N=e.get(I);if(N===null)return;const P=N.split(",").map(ba);if(P.length!==3||P.some(B=>B===null)){n.push(`${I} = ${JSON.stringify(N)} is not three finite numbers`);return}return P},l=r("s");l!==void 0&&(t.scenario=l);const c=r("model");c!==void 0&&(t.model=c);const h=e.get("mp");if(h!==null){const I={};for(const N of h.split(",")){const[P,B,...V]=N.split(":"),U=B===void 0?null:ba(B);if(P===void 0||!/^[A-Za-z_][A-Za-z0-9_]{0,40}$/.test(P)||U===null||V.length>0){n.push(`mp: ${JSON.stringify(N)} is not name:number`);continue}I[P]=U}Object.keys(I).length>0&&(t.modelParams=I)}const u=a("l");u!==void 0&&(t.length=u);const d=a("m");d!==void 0&&(t.mass=d);const m=a("g");m!==void 0&&(t.g=m);const _=r("method");_!==void 0&&(t.method=_);const S=a("dt");S!==void 0&&(t.dt=S);const p=a("ts");p!==void 0&&(t.timeScale=p);const f=o("x"),x=o("v");f===void 0!=(x===void 0)&&n.length===0?n.push("the start needs both x and v"):f!==void 0&&x!==void 0&&(t.x=f,t.v=x);const R=e.get("paused");R!==null&&(t.paused=R==="1"||R==="true");const y=e.get("lang");y!==null&&/^[a-z]{2}$/.test(y)&&(t.lang=y);const A=a("at");A!==void 0&&(A>=0&&A<=1e6?t.at=A:n.push(`at = ${A} is not a time 0 … 1e6 s`));const w=e.get("view");if(w!==null){const I={};for(const N of w.split(",").filter(Boolean)){const P=/^(-?)([A-Za-z]{1,30})(?::([A-Za-z0-9 .+-]{1,30}))?$/.exec(N);if(P===null){n.push(`view: ${JSON.stringify(N)} is not a view option`);continue}const[,B,V,U]=P;U===void 0?I[V]=B!=="-":I[V]=ba(U)??U}t.view=I}const g=e.get("plot");if(g!==null){const I=g.split(",");I.length===2&&I.every(N=>/^[a-z0-9_]{1,20}$/i.test(N))?t.plot=[I[0],I[1]]:n.push(`plot = ${JSON.stringify(g)} is not two variable names`)}const b=e.get("twin");if(b!==null){const I=oT(b);I===null?n.push(`twin = ${JSON.stringify(b)} is not own:l:m:θ₀, eps:ε, method:name or damped:c`):t.twin=I}return{value:t,problems:n}}function oT(i){const e={mode:"off",epsilon:.01/Ma,method:"rk4",damping:.5,length:.5,mass:1,theta:10/Ma},[t,...n]=i.split(":"),s=n.map(ba);if(t==="own"&&s.length===3&&s.every(r=>r!==null)){const[r,a,o]=s;return r>0&&a>0&&o>=0&&o<=180?{...e,mode:"own",length:r,mass:a,theta:o/Ma}:null}return t==="eps"&&s.length===1&&s[0]!==null?{...e,mode:"epsilon",epsilon:s[0]/Ma}:t==="damped"&&s.length===1&&(s[0]??-1)>=0?{...e,mode:"damped",damping:s[0]}:t==="method"&&n.length===1&&og.test(n[0])?{...e,mode:"method",method:n[0]}:null}function Zf(i){const e={model:i.model,length:i.params.length,mass:i.params.mass,g:i.params.g,method:i.method,dt:i.dt,timeScale:i.time_scale,x:i.start.x,v:i.start.v};return i.scenario!==null&&(e.scenario=i.scenario),Object.keys(i.model_params).length>0&&(e.modelParams={...i.model_params}),i.paused&&(e.paused=!0),i.paused&&!i.adaptive&&i.t>i.t0&&(e.at=i.t-i.t0),e}function kh(i){const e=[];i.scenario!==void 0&&e.push({type:"load_scenario",name:i.scenario}),i.model!==void 0&&e.push({type:"set_model",model:i.model,params:{...i.modelParams}});const t={type:"set_params"};i.length!==void 0&&(t.length=i.length),i.mass!==void 0&&(t.mass=i.mass),i.g!==void 0&&(t.g=i.g),Object.keys(t).length>1&&e.push(t);const n={type:"set_method"};if(i.method!==void 0&&(n.method=i.method),i.dt!==void 0&&(n.dt=i.dt),Object.keys(n).length>1&&e.push(n),i.timeScale!==void 0&&e.push({type:"set_time_scale",time_scale:i.timeScale}),i.x!==void 0&&i.v!==void 0&&e.push({type:"set_state",x:i.x,v:i.v}),e.length>0&&e.push({type:"reset"}),i.paused===!0&&e.push({type:"pause"}),i.paused===!0&&i.at!==void 0&&i.at>0&&i.dt!==void 0&&i.dt>0){let s=Math.round(i.at/i.dt);for(s>1e7&&(s=0);s>0;){const r=Math.min(s,1e5);e.push({type:"step",n:r}),s-=r}}return e}function lT(i){const e=[L("link.scenario")];i.paused===!0&&e.push(i.at!==void 0&&i.at>0?L("link.pausedAt",{t:i.at.toFixed(3)}):L("link.paused"));const t=Object.entries(i.view??{}).map(([s,r])=>typeof r=="boolean"?r?s:`−${s}`:`${s} ${r}`);t.length>0&&e.push(L("link.view",{list:t.join(", ")})),i.plot!==void 0&&e.push(L("link.plot",{x:i.plot[0],y:i.plot[1]}));const n=i.twin===void 0?null:ag(i.twin);return n!==null&&e.push(L("link.twin",{what:n})),i.lang!==void 0&&e.push(L("link.lang",{lang:i.lang})),e.join("; ")}const Jf="(max-width: 700px), (max-aspect-ratio: 3/4)";function Cr(i,e,t,n=!1){const s=document.createElement("button");return s.type="button",s.dataset.action=i,s.textContent=e,s.title=t,s.setAttribute("aria-label",t),n&&s.classList.add("when-open"),s}class cT{constructor(e,t,n){this.panel=t,e.setAttribute("aria-label",L("toolbar.label")),this.toggle=Cr("panel","",L("toolbar.collapse")),this.toggle.setAttribute("aria-controls","panel-body"),this.toggle.addEventListener("click",()=>{this.setCollapsed(!t.classList.contains("collapsed")),n.collapsed(t.classList.contains("collapsed"))}),this.runButton=Cr("run",L("toolbar.pauseShort"),L("toolbar.pause")),this.runButton.addEventListener("click",()=>n.run());const s=Cr("reset",L("toolbar.resetShort"),L("toolbar.reset"));s.addEventListener("click",()=>n.reset());const r=Cr("step",L("toolbar.stepShort"),L("toolbar.step"));r.addEventListener("click",()=>n.step()),this.recordButton=Cr("record",L("toolbar.recordShort"),L("toolbar.record")),this.recordButton.setAttribute("aria-pressed","false"),this.recordButton.addEventListener("click",()=>n.record());const a=Cr("help","?",L("toolbar.help"));a.addEventListener("click",()=>n.help());const o=document.createElement("select");o.dataset.input="language",o.classList.add("when-open"),o.setAttribute("aria-label",L("toolbar.language"));for(const[l,c]of Object.entries(za)){const h=document.createElement("option");h.value=l,h.textContent=c.name,o.appendChild(h)}o.value=rp(),o.addEventListener("change",()=>n.language(o.value)),e.append(this.toggle,this.runButton,s,r,this.recordButton,a,o),this.setCollapsed(!1),window.matchMedia(Jf).addEventListener("change",()=>this.setCollapsed(t.classList.contains("collapsed")))}panel;runButton;recordButton;toggle;setCollapsed(e){this.panel.classList.toggle("collapsed",e),this.toggle.setAttribute("aria-expanded",String(!e));const t=window.matchMedia(Jf).matches;this.toggle.textContent=t?e?"▴":"▾":e?"◂":"▸",this.toggle.title=L(e?"toolbar.expand":"toolbar.collapse"),this.toggle.setAttribute("aria-label",this.toggle.title)}showRunning(e){const t=L(e?"toolbar.startShort":"toolbar.pauseShort");this.runButton.textContent!==t&&(this.runButton.textContent=t,this.runButton.title=L(e?"toolbar.start":"toolbar.pause"),this.runButton.setAttribute("aria-label",this.runButton.title))}showRecording(e){this.recordButton.setAttribute("aria-pressed",String(e)),this.recordButton.textContent=L(e?"toolbar.recordStopShort":"toolbar.recordShort"),this.recordButton.title=L(e?"toolbar.recordStop":"toolbar.record")}}const Bh=[["gravity.earth",9.81],["gravity.moon",1.62],["gravity.mars",3.71],["gravity.jupiter",24.79],["gravity.zero",0],["gravity.negative",-9.81]];function hT(i,e){return i===null?null:"damping"in(i.model_params??{})?{type:"set_params",params:{damping:e}}:i.model==="ideal"&&e>0?{type:"set_model",model:"damped",params:{damping:e}}:null}function uT(i,e,t){for(const[n,s]of[["θ₀",i],["φ₀",e],["φ̇₀",t]])if(!Number.isFinite(s))return L("start.notNumber",{name:n});return i<0||i>180?L("start.thetaRange",{value:i}):{type:"set_state",theta:i/Cn,phi:e/Cn,theta_dot:0,phi_dot:t/Cn}}function dT(i){let e=Math.round((2+18*i)*100)/100;for(const[,t]of Bh)Math.abs(e-t)<.3&&(e=Math.round((e+.6)*100)/100);return e}function Ot(i,e={},t=""){const n=document.createElement(i);for(const[s,r]of Object.entries(e))n.setAttribute(s,r);return t&&(n.textContent=t),n}function Pr(i,e,t){const n=Ot("section",{class:"tools","data-tool":t});return n.appendChild(Ot("h3",{},e)),i.appendChild(n),n}function Lc(i,e,t,n){const s=Ot("label");s.append(`${i} `);const r=Ot("input",{type:"number",step:n,name:e,"data-input":e});return r.value=String(t),r.style.width="5.5em",s.appendChild(r),[s,r]}class fT{constructor(e,t,n){this.store=t;const s=()=>this.now=t.playT??this.now,r=Pr(e,L("tools.start"),"start"),[a,o]=Lc("θ₀ [°]","theta0",30,"1"),[l,c]=Lc("φ₀ [°]","phi0",0,"1"),[h,u]=Lc("φ̇₀ [°/s]","phidot0",0,"10");o.title=L("tools.thetaHelp"),c.title=L("tools.phiHelp"),u.title=L("tools.phiDotHelp");const d=Ot("button",{type:"button","data-action":"set-start"},L("tools.setStart")),m=()=>{const I=uT(Number(o.value),Number(c.value),Number(u.value));typeof I=="string"?n.explain(I):n.send(I)};d.addEventListener("click",m);for(const I of[o,c,u])I.addEventListener("keydown",N=>N.key==="Enter"&&m());r.append(a,l,h,d);const _=Pr(e,L("tools.world"),"world"),S=Ot("label");S.append(`${L("tools.gravity")} `),this.gravity=Ot("select",{"data-input":"gravity-preset"}),this.gravity.appendChild(Ot("option",{value:""},L("gravity.custom")));for(const[I,N]of Bh)this.gravity.appendChild(Ot("option",{value:String(N)},`${L(I)} (${N} m/s²)`));this.gravity.appendChild(Ot("option",{value:"mystery"},L("tools.mystery")));const p=Ot("button",{type:"button","data-action":"reveal-g",hidden:""},L("tools.reveal"));this.reveal=p,this.gravity.addEventListener("change",()=>{this.gravity.value==="mystery"?(this.mysteryG=dT(Math.random()),document.body.classList.add("mystery"),p.hidden=!1,n.send({type:"set_params",g:this.mysteryG}),n.explain(L("tools.mysteryOn"),!0)):this.gravity.value!==""&&n.send({type:"set_params",g:Number(this.gravity.value)})}),p.addEventListener("click",()=>{n.explain(L("tools.revealed",{g:this.mysteryG??"?"}),!0),this.endMystery()}),S.append(this.gravity," ",p);const f=Ot("label");f.append(`${L("tools.friction")} `),this.friction=Ot("input",{type:"range",min:"0",max:"2",step:"0.01","data-input":"friction"}),this.friction.value="0",this.friction.title=L("tools.frictionHelp"),this.frictionValue=Ot("output"),this.friction.addEventListener("input",()=>{this.frictionValue.textContent=`${Number(this.friction.value).toFixed(2)} 1/s`}),this.friction.addEventListener("change",()=>{const I=hT(t.status,Number(this.friction.value));I!==null?n.send(I):Number(this.friction.value)>0&&n.explain(L("tools.noFriction",{model:t.status?.model??"?"}))}),f.append(this.friction," ",this.frictionValue),_.append(S,f);const x=Pr(e,L("tools.now"),"angles");this.angleText=Ot("div",{class:"big","data-readout":"angles","aria-live":"off"}),this.description=Ot("p",{class:"describe","data-readout":"describe","aria-live":"off","aria-atomic":"true"});const R=Ot("label");this.describeLive=Ot("input",{type:"checkbox","data-input":"describe"}),R.append(this.describeLive,` ${L("describe.toggle")}`),x.append(this.angleText,this.description,R);const y=Pr(e,L("tools.stopwatch"),"stopwatch");this.watchText=Ot("div",{class:"big","data-readout":"stopwatch"},"0.000 s"),this.watchButton=Ot("button",{type:"button","data-action":"stopwatch"},L("tools.swStart"));const A=Ot("button",{type:"button","data-action":"lap"},L("tools.swLap")),w=Ot("button",{type:"button","data-action":"stopwatch-reset"},L("tools.swReset"));this.lapList=Ot("ol",{class:"laps"}),this.watchButton.addEventListener("click",()=>{this.stopwatch.running?this.stopwatch.stop(s()):this.stopwatch.start(s()),this.watchButton.textContent=this.stopwatch.running?L("tools.swStop"):L("tools.swStart")}),A.addEventListener("click",()=>this.stopwatch.lap(s())),w.addEventListener("click",()=>{this.stopwatch.reset(),this.watchButton.textContent=L("tools.swStart")}),y.append(this.watchText,this.watchButton," ",A," ",w,this.lapList);const g=Pr(e,L("tools.period"),"period");g.title=L("tools.periodHelp"),this.periodTable=Ot("table",{"data-readout":"period"}),g.appendChild(this.periodTable);const b=Pr(e,L("tools.overlays"),"overlays");for(const I of["ruler","protractor"]){const N=Ot("label"),P=Ot("input",{type:"checkbox","data-input":I});P.addEventListener("change",()=>n.overlay(I,P.checked)),this.overlayBoxes[I]=P,N.append(P,` ${L(I==="ruler"?"tools.ruler":"tools.protractor")}`),b.appendChild(N)}}store;stopwatch=new ZM;angleText;watchText;lapList;watchButton;periodTable;friction;frictionValue;gravity;now=0;mysteryG=null;reveal;description;describeLive;describedAt=-1/0;spokenUntil=-1/0;endMystery(){this.mysteryG=null,document.body.classList.remove("mystery"),this.reveal.hidden=!0}describe(e,t,n=!1){const s=this.describeLive.checked;n&&(this.spokenUntil=t+3e3),this.description.setAttribute("aria-live",s||t<this.spokenUntil?"polite":"off"),!(!n&&s&&t-this.describedAt<5e3)&&(!n&&!s&&t-this.describedAt<1e3||(this.describedAt=t,this.description.textContent!==e?this.description.textContent=e:n&&(this.description.textContent="",requestAnimationFrame(()=>this.description.textContent=e))))}overlayBoxes={};showOverlay(e,t){const n=this.overlayBoxes[e];n&&(n.checked=t)}sync(e){const t=Bh.find(([,s])=>s===e.params.g);this.mysteryG!==null&&e.params.g!==this.mysteryG&&this.endMystery(),document.activeElement!==this.gravity&&(this.gravity.value=this.mysteryG!==null?"mystery":t?String(t[1]):"");const n=e.model_params?.damping;document.activeElement!==this.friction&&(this.friction.value=String(n??0),this.friction.disabled=n===void 0&&e.model!=="ideal",this.frictionValue.textContent=`${(n??0).toFixed(2)} 1/s`)}update(e,t){t!==null&&(this.now=t);const n=e===null?null:Fa(e),s=n===null?"—":`θ = ${(n.theta*Cn).toFixed(1)}°   φ = ${(n.phi*Cn).toFixed(1)}°`;this.angleText.textContent!==s&&(this.angleText.textContent=s);const r=`${this.stopwatch.reading(this.now).toFixed(3)} s`;this.watchText.textContent!==r&&(this.watchText.textContent=r);const a=this.stopwatch.laps.map(o=>`${o.toFixed(3)} s`).join("|");this.lapList.dataset.shown!==a&&(this.lapList.dataset.shown=a,this.lapList.replaceChildren(...this.stopwatch.laps.map(o=>Ot("li",{},`${o.toFixed(3)} s`)))),this.fillPeriod()}fillPeriod(){const e=this.store.periodTimer.reading(),t=e.kind==="swing"&&e.amplitude!==null?pT(this.store.status,e.amplitude):null,n=tb(e,this.store.exact,t),s=([u,d])=>u===null||d===null||d===0?"":`${((u-d)/d*100).toFixed(2)} %`,r=u=>u===null?"—":(u*Cn).toFixed(2),a=e.kind===null?L("tools.kindNone"):e.kind==="orbit"?L("tools.kindOrbit"):e.lowPerPeriod===1?L("tools.kindOver"):L("tools.kindSwing"),o=this.store.exact!==null?L("tools.exact"):L("tools.theory"),l=[["head","",L("tools.measured"),o,L("tools.difference")],["kind",L("tools.motion"),a,"",""]];n.swing?(l.push(["period",L("tools.periodSwing"),pt(n.period[0],5),pt(n.period[1],5),s(n.period)]),l.push(["amplitude",L("tools.amplitude"),r(e.amplitude),"",""])):(l.push(["period",L("tools.periodZ"),pt(n.period[0],5),pt(n.period[1],5),s(n.period)]),l.push(["advance",L("tools.advance"),r(n.advance[0]),r(n.advance[1]),s(n.advance)]),l.push(["precession",L("tools.precession"),r(n.precession[0]),r(n.precession[1]),""]),l.push(["band",L("tools.band"),e.thetaMin===null?"—":`${r(e.thetaMin)} … ${r(e.thetaMax)}`,"",""]));const c=this.periodTable;for(;c.rows.length>l.length;)c.deleteRow(-1);l.forEach(([u,...d],m)=>{const _=c.rows[m]??c.insertRow();for(_.dataset.row=u;_.cells.length<4;)_.insertCell();d.forEach((S,p)=>{const f=_.cells[p];f&&f.textContent!==S&&(f.textContent=S)})});const h=e.intervals===0?L("tools.periodWait"):L(n.swing?"tools.periodCount":"tools.periodCountZ",{n:e.intervals});c.caption?.textContent!==h&&(c.createCaption().textContent=h),c.dataset.period=e.period===null?"":String(e.period),c.dataset.kind=e.kind??""}}function pT(i,e){if(i===null)return null;const t=i.model_params??{},n=s=>(t[s]??0)===0;return i.model==="damped"&&!(n("drag")&&n("forcing_amplitude")&&n("gravity_x")&&n("gravity_y"))||i.model!=="ideal"&&i.model!=="damped"?null:QM(i.params.length,i.params.g,t.damping??0,e)}const mT={kinetic:"#7dff8a",potential:"#59c3ff",lost:"#ff5d73",total:"#e8e8e8"};class gT{canvas;ctx;scale=1;shown=null;constructor(e){const t=document.createElement("h3");t.textContent=L("energy.title"),e.appendChild(t),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("role","img"),this.canvas.setAttribute("aria-label",L("energy.title")),e.appendChild(this.canvas),this.ctx=this.canvas.getContext("2d")}rescale(){this.scale=1}draw(e,t){this.shown=e;const n=this.ctx;if(n===null)return;const s=Math.min(window.devicePixelRatio||1,2),r=Math.max(200,(this.canvas.parentElement?.clientWidth??300)-4),a=130;if(this.canvas.width!==Math.round(r*s)&&(this.canvas.width=Math.round(r*s),this.canvas.height=Math.round(a*s),this.canvas.style.width=`${r}px`,this.canvas.style.height=`${a}px`),n.setTransform(s,0,0,s,0,0),n.clearRect(0,0,r,a),e===null)return;const o=[["kinetic",L("energy.kinetic"),e.kinetic],["potential",L("energy.potential"),e.potential]];t&&o.push(["lost",L("energy.lost"),e.lost]),o.push(["total",L("energy.total"),e.total]);const l=Math.max(...o.map(([,,m])=>Math.abs(m)),1e-12);this.scale=l>this.scale?l:Math.max(l,.995*this.scale);const c=14,h=a-30,u=h,d=r/o.length;n.font="11px system-ui, sans-serif",n.textAlign="center",o.forEach(([m,_,S],p)=>{const f=d*p+d*.2,x=d*.6,R=Math.abs(S)/this.scale*(h-c);n.fillStyle=mT[m],S>=0?n.fillRect(f,u-R,x,R):(n.globalAlpha=.5,n.fillRect(f,u-R,x,R),n.globalAlpha=1),n.fillStyle="#dde3ee",n.fillText(_,f+x/2,a-16),n.fillText(`${S.toPrecision(4)} J`,f+x/2,a-3)}),n.strokeStyle="#555",n.beginPath(),n.moveTo(0,u+.5),n.lineTo(r,u+.5),n.stroke()}}const jf=(i,e)=>.5*e.mass*(i.v[0]**2+i.v[1]**2+i.v[2]**2),al=[{name:"t",label:"var.t",unit:"s",get:i=>i.t},{name:"theta",label:"var.theta",unit:"°",get:i=>Fa(i.x).theta*Cn},{name:"phi",label:"var.phi",unit:"°",get:i=>Fa(i.x).phi*Cn},{name:"x",label:"var.x",unit:"m",get:i=>i.x[0]},{name:"y",label:"var.y",unit:"m",get:i=>i.x[1]},{name:"z",label:"var.z",unit:"m",get:i=>i.x[2]},{name:"zdot",label:"var.zdot",unit:"m/s",get:i=>i.v[2]},{name:"speed",label:"var.speed",unit:"m/s",get:i=>Math.hypot(...i.v)},{name:"energy",label:"var.energy",unit:"J",get:i=>i.energy},{name:"kinetic",label:"var.kinetic",unit:"J",get:jf},{name:"potential",label:"var.potential",unit:"J",get:(i,e)=>i.energy-jf(i,e)},{name:"j3",label:"var.j3",unit:"kg m²/s",get:i=>i.j3},{name:"tension",label:"var.tension",unit:"N",get:i=>i.tension},{name:"power",label:"var.power",unit:"W",get:i=>i.power},{name:"radius",label:"var.radius",unit:"m",get:i=>Math.hypot(...i.x)}];function Ca(i){return al.find(e=>e.name===i)??al[0]}function Qf(i,e,t,n){const[s,r]=[Ca(e),Ca(t)];return{x:i.map(a=>s.get(a,n)),y:i.map(a=>r.get(a,n))}}class _T{constructor(e){this.container=e;const t=document.createElement("div");t.className="tools chosen",t.dataset.tool="chosen";const n=document.createElement("h3");n.textContent=L("chosen.title"),t.appendChild(n);for(const s of["y","x"]){const r=document.createElement("label");r.append(`${L(s==="x"?"chosen.xAxis":"chosen.yAxis")} `);const a=document.createElement("select");a.dataset.input=`chosen-${s}`;for(const o of al){const l=document.createElement("option");l.value=o.name,l.textContent=`${L(o.label)} [${o.unit}]`,a.appendChild(l)}a.value=this.choice[s],this.selects[s]=a,a.addEventListener("change",()=>{this.choice[s]=a.value,this.labels()}),r.appendChild(a),t.append(r," ")}e.appendChild(t),this.plot=new Ra(e,"","","",170),this.plot.canvas.dataset.plot="chosen",this.visibility.watch(this.plot.canvas),this.labels()}container;plot;visibility=new Ml;choice={x:"t",y:"theta"};selects={};choose(e,t){return[e,t].every(n=>al.some(s=>s.name===n))?(this.choice.x=e,this.choice.y=t,this.selects.x&&(this.selects.x.value=e),this.selects.y&&(this.selects.y.value=t),this.labels(),!0):!1}labels(){const[e,t]=[Ca(this.choice.x),Ca(this.choice.y)];this.plot.xLabel=`${L(e.label)} [${e.unit}]`,this.plot.yLabel=`${L(t.label)} [${t.unit}]`}update(e,t,n=null){if(!this.visibility.visible(this.plot.canvas))return;const r=[{...Qf(e,this.choice.x,this.choice.y,t),color:"#59c3ff",label:L(n?"twin.first":Ca(this.choice.y).label)}];n!==null&&r.push({...Qf(n,this.choice.x,this.choice.y,t),color:"#c8f560",label:L("twin.second")});const a=r.flatMap(l=>l.x),o=r.flatMap(l=>l.y);this.plot.draw(this.container.clientWidth-8,r,Ys(a,.02),Ys(o))}}function vT(i,e){const t=1.1*(i+e),n=Math.hypot(3.9,3.3);return[t*3.9/n,t*3.3/n,0]}function xT(i,e){const t=Math.hypot(...i),n=Math.atan2(Math.hypot(i[0],i[1]),-i[2])+e,s=Math.atan2(i[1],i[0]);return[t*Math.sin(n)*Math.cos(s),t*Math.sin(n)*Math.sin(s),-t*Math.cos(n)]}function ST(i,e){const t=[];i.scenario&&t.push({type:"load_scenario",name:i.scenario});const n=e.mode==="damped",s=e.mode==="own",r=n&&i.model==="ideal"?"damped":i.model,a={...i.model_params};if(n&&(a.damping=e.damping),t.push({type:"set_model",model:r,params:a}),t.push({type:"set_params",length:s?e.length:i.params.length,mass:s?e.mass:i.params.mass,g:i.params.g}),t.push({type:"set_method",method:e.mode==="method"?e.method:i.method,dt:i.dt}),s)t.push({type:"set_state",theta:e.theta,phi:0,theta_dot:0,phi_dot:0});else{const o=e.mode==="epsilon"?xT(i.start.x,e.epsilon):i.start.x;t.push({type:"set_state",x:o,v:i.start.v,project:!0})}return t.push({type:"set_time_scale",time_scale:i.time_scale}),t.push({type:"reset"}),t.push({type:i.paused?"pause":"resume"}),t}function yT(i,e){const t=i.length;if(t===0)return null;const n=i[0],s=i[t-1];if(e<n.t||e>s.t)return null;let r=0,a=t-1;for(;a-r>1;){const p=r+a>>1;i[p].t<=e?r=p:a=p}const o=i[r],l=i[a],c=l.t-o.t;if(!(c>0))return[o.x[0]+o.pivot[0],o.x[1]+o.pivot[1],o.x[2]+o.pivot[2]];const h=(e-o.t)/c,[u,d,m,_]=[2*h**3-3*h**2+1,h**3-2*h**2+h,-2*h**3+3*h**2,h**3-h**2],S=p=>u*o.x[p]+d*c*o.v[p]+m*l.x[p]+_*c*l.v[p]+(1-h)*o.pivot[p]+h*l.pivot[p];return[S(0),S(1),S(2)]}function ep(i,e){const t=[],n=[];for(const s of i){const r=yT(e,s.t);r!==null&&(t.push(s.t),n.push(Math.hypot(s.x[0]+s.pivot[0]-r[0],s.x[1]+s.pivot[1]-r[1],s.x[2]+s.pivot[2]-r[2])))}return{t,d:n}}class MT{constructor(e,t,n,s,r){this.first=t,this.socket=s,this.actions=r;const a=document.createElement("section");a.className="tools",a.dataset.tool="twin";const o=document.createElement("h3");o.textContent=L("twin.title"),a.appendChild(o);const l=document.createElement("label");l.append(`${L("twin.mode")} `);const c=document.createElement("select");c.dataset.input="twin-mode";const h=[["off",L("twin.off")],["own",L("twin.own")],["epsilon",L("twin.epsilon")],["method",L("twin.method")],["damped",L("twin.damped")]];for(const[b,I]of h){const N=document.createElement("option");N.value=b,N.textContent=I,c.appendChild(N)}l.appendChild(c);const u=document.createElement("label");u.append("ε [°] ");const d=document.createElement("input");d.type="number",d.step="0.01",d.value="0.01",d.dataset.input="twin-epsilon",d.style.width="5em",u.appendChild(d);const m=document.createElement("label");m.append(`${L("twin.methodPick")} `);const _=document.createElement("select");_.dataset.input="twin-method";for(const b of n){const I=document.createElement("option");I.value=b.name,I.textContent=$o(b.name,b.order),_.appendChild(I)}_.value=n.some(b=>b.name==="rk4")?"rk4":n[0]?.name??"",m.appendChild(_);const S=document.createElement("label");S.append(`${L("twin.damping")} `);const p=document.createElement("input");p.type="number",p.step="0.1",p.min="0",p.value="0.5",p.dataset.input="twin-damping",p.style.width="5em",S.appendChild(p);const f=document.createElement("span"),x=(b,I,N,P)=>{const B=document.createElement("label");B.append(`${b} `);const V=document.createElement("input");return V.type="number",V.step=P,V.value=N,V.dataset.input=I,V.style.width="4.5em",B.appendChild(V),f.appendChild(B),V},R=x(L("twin.length"),"twin-length","0.5","0.05"),y=x(L("twin.mass"),"twin-mass","1","0.1"),A=x(L("twin.theta"),"twin-theta","10","1"),w=document.createElement("button");w.type="button",w.dataset.action="twin-start",w.textContent=L("twin.start");const g=()=>{u.hidden=c.value!=="epsilon",m.hidden=c.value!=="method",S.hidden=c.value!=="damped",f.hidden=c.value!=="own",w.hidden=c.value==="off"};c.addEventListener("change",()=>{g(),c.value==="off"&&this.stop()}),w.addEventListener("click",()=>{if(this.options.mode=c.value,this.options.epsilon=Number(d.value)/Cn,this.options.method=_.value,this.options.damping=Number(p.value),this.options.length=Number(R.value),this.options.mass=Number(y.value),this.options.theta=Number(A.value)/Cn,!Number.isFinite(this.options.epsilon)||!(this.options.damping>=0)){r.explain(L("twin.bad"));return}const b=this.options;if(b.mode==="own"&&!(b.length>0&&b.mass>0&&b.theta>=0&&b.theta<=Math.PI)){r.explain(L("twin.badOwn"));return}this.start()}),g(),this.setInputs=b=>{c.value=b.mode,d.value=String(b.epsilon*Cn),_.value=b.method,p.value=String(b.damping),R.value=String(b.length),y.value=String(b.mass),A.value=String(b.theta*Cn),g()},this.periods=document.createElement("table"),this.periods.dataset.readout="twin-periods",this.periods.hidden=!0,a.append(l," ",u,m,S,f," ",w,this.periods),e.appendChild(a),this.plot=new Ra(e,L("twin.separation"),"t [s]","|r₁ − r₂| [m]",140),this.plot.canvas.dataset.plot="separation",this.plot.canvas.parentElement?.setAttribute("hidden",""),this.visibility.watch(this.plot.canvas)}first;socket;actions;store=new pm;options={mode:"off",epsilon:.01/Cn,method:"rk4",damping:.5,length:.5,mass:1,theta:10/Cn};periods;setInputs;conn=null;pending=[];plot;visibility=new Ml;get on(){return this.conn!==null}layout(){const[e,t]=[this.first.status,this.store.status];return this.conn===null||this.options.mode!=="own"||e===null||t===null?null:{offset:vT(e.params.length,t.params.length),length:t.params.length}}restore(e){Object.assign(this.options,e),this.setInputs(e),e.mode!=="off"&&this.start()}start(){const e=this.first.status;if(e===null)return this.actions.explain(L("msg.notConnected"));this.pending=ST(e,this.options),this.conn===null?this.conn=new sp(this.socket,{onOpen:()=>this.flush(),onClose:()=>this.store.setConnected(!1),onFrames:t=>this.store.onFrames(t),onNotice:t=>{t.type==="status"?this.store.onStatus(t):t.type==="event"?this.store.onEvent(t):this.actions.explain(`${L("twin.second")}: ${t.message}`)},onProtocolError:t=>this.actions.explain(`${L("twin.second")}: ${t}`)}):this.flush(),this.actions.send({type:"reset"}),this.plot.canvas.parentElement?.removeAttribute("hidden"),this.periods.hidden=!1}flush(){if(!(this.conn===null||!this.conn.isOpen)){for(const e of this.pending)this.conn.send(e);this.pending=[]}}stop(){this.conn?.close(),this.conn=null,this.store.clear(),this.store.status=null,this.plot.canvas.parentElement?.setAttribute("hidden",""),this.periods.hidden=!0}mirror(e){this.conn!==null&&(e.type==="pause"||e.type==="resume"||e.type==="reset"||e.type==="step")&&this.conn.send(e)}drawn(e,t){if(this.conn===null||e===null||this.store.frames.length===0)return null;const n=this.store.frames;this.store.playT=Math.min(Math.max(e,n[0].t),n[n.length-1].t);const{start:s,end:r}=this.store.trailRange(t);return{frame:this.store.displayed(),trail:{frames:this.store.trail,start:s,end:r}}}update(e){if(this.conn!==null&&this.fillPeriods(),this.conn===null||!this.visibility.visible(this.plot.canvas))return;const t=ep(this.first.history.frames,this.store.trajectory);this.plot.draw(e,[{x:t.t,y:t.d,color:"#c8f560",label:L("twin.separation")}],Ys(t.t,.02),Ys([0,...t.d]))}fillPeriods(){const e=(n,s)=>{const r=s.status,a=s.periodTimer.reading(),o=r===null?null:Math.atan2(Math.hypot(r.start.x[0],r.start.x[1]),-r.start.x[2])*Cn;return[n,r===null?"—":r.params.length.toPrecision(3),r===null?"—":r.params.mass.toPrecision(3),o===null?"—":o.toFixed(1),a.period===null?"—":`${a.period.toFixed(4)} (${a.intervals})`]};[["",L("twin.colLength"),L("twin.colMass"),L("twin.colTheta"),L("twin.colPeriod")],e(L("twin.first"),this.first),e(L("twin.second"),this.store)].forEach((n,s)=>{const r=this.periods.rows[s]??this.periods.insertRow();for(;r.cells.length<n.length;)r.insertCell();n.forEach((a,o)=>{const l=r.cells[o];l&&l.textContent!==a&&(l.textContent=a)})})}separationNow(){return ep(this.first.history.frames,this.store.trajectory)}}const bT=i=>`#${i.toString(16).padStart(6,"0")}`,wT={velocity:"vec.velocity",momentum:"vec.momentum",gravity:"vec.gravity",tension:"vec.tension",net:"vec.net",angularMomentum:"vec.angularMomentum",torque:"vec.torque"};class ET{constructor(e){this.el=e,e.setAttribute("aria-label",L("help.title"));const t=document.createElement("div");t.className="help-box";const n=document.createElement("h2");n.textContent=L("help.title");const s=document.createElement("table"),r=[["Space","help.space"],["R","help.r"],["S","help.s"],["← → ↑ ↓","help.arrows"],["Page ↑ / Page ↓","help.page"],["← → ↑ ↓ / + −","help.camera"],["Shift + ← →","help.bobKeys"],["D","help.describe"],["Tab","help.tab"],["?","help.help"],["Esc","help.esc"]];for(const[h,u]of r){const d=s.insertRow(),m=d.insertCell(),_=document.createElement("kbd");_.textContent=h,m.appendChild(_),d.insertCell().textContent=L(u)}const a=document.createElement("h3");a.textContent=L("help.colours");const o=document.createElement("ul");o.className="colour-key";const l=[["#ff8c42",L("help.bob")],["#59c3ff",L("help.trail")],["#c8f560",L("help.twin")],...Object.entries(wT).map(([h,u])=>[bT(ru[h]),L(u)]),["#e6d3a3",L("help.ruler")]];for(const[h,u]of l){const d=document.createElement("li"),m=document.createElement("span");m.className="swatch",m.style.background=h,d.append(m,` ${u}`),o.appendChild(d)}const c=document.createElement("button");c.type="button",c.dataset.action="help-close",c.textContent=L("help.close"),c.addEventListener("click",()=>this.toggle(!1)),t.append(n,s,a,o,c),e.appendChild(t),e.addEventListener("click",h=>h.target===e&&this.toggle(!1)),e.addEventListener("keydown",h=>{if(h.key!=="Tab")return;const u=[...e.querySelectorAll('button, [href], input, select, [tabindex]:not([tabindex="-1"])')],d=u[0],m=u[u.length-1];d===void 0||m===void 0||(h.shiftKey&&document.activeElement===d?(h.preventDefault(),m.focus()):!h.shiftKey&&document.activeElement===m&&(h.preventDefault(),d.focus()))}),document.addEventListener("focusin",h=>{this.open&&h.target instanceof Node&&!e.contains(h.target)&&this.el.querySelector("button")?.focus()})}el;returnFocus=null;get open(){return!this.el.hidden}toggle(e=!this.open){e!==this.open&&(e?(this.returnFocus=document.activeElement instanceof HTMLElement?document.activeElement:null,this.el.hidden=!1,this.el.querySelector("button")?.focus()):(this.el.hidden=!0,this.returnFocus?.focus()))}}const TT=300,AT=25e5;function RT(i){for(const e of["video/webm;codecs=vp9","video/webm;codecs=vp8","video/webm"])if(i(e))return e;return null}class CT{constructor(e,t){this.canvas=e,this.done=t}canvas;done;recorder=null;chunks=[];timer=null;get recording(){return this.recorder!==null}start(){if(this.recorder!==null)return null;if(typeof MediaRecorder>"u"||typeof this.canvas.captureStream!="function")return"no MediaRecorder";const e=RT(s=>MediaRecorder.isTypeSupported(s));if(e===null)return"no WebM";const t=this.canvas.captureStream(30),n=new MediaRecorder(t,{mimeType:e,videoBitsPerSecond:AT});return this.chunks=[],n.ondataavailable=s=>{s.data.size>0&&this.chunks.push(s.data)},n.onstop=()=>{for(const s of t.getTracks())s.stop();this.done(new Blob(this.chunks,{type:"video/webm"})),this.chunks=[]},n.start(1e3),this.recorder=n,this.timer=setTimeout(()=>this.stop(),TT*1e3),null}stop(){this.timer!==null&&clearTimeout(this.timer),this.timer=null;const e=this.recorder;this.recorder=null,e!==null&&e.state!=="inactive"&&e.stop()}}function PT(i,e){if(e)return null;switch(i){case" ":case"Spacebar":return"run";case"r":case"R":return"reset";case"s":case"S":return"step";case"?":return"help";case"Escape":return"close";default:return null}}function LT(i){switch(i){case"ArrowUp":case"ArrowRight":return 1;case"ArrowDown":case"ArrowLeft":return-1;case"PageUp":return 10;case"PageDown":return-10;case"Home":return-1/0;case"End":return 1/0;default:return null}}function tp(i,e=""){return typeof HTMLElement>"u"||!(i instanceof HTMLElement)?!1:e===" "&&(i instanceof HTMLButtonElement||i instanceof HTMLInputElement&&["checkbox","radio","button"].includes(i.type))||i.isContentEditable||i instanceof HTMLSelectElement||i instanceof HTMLTextAreaElement?!0:i instanceof HTMLInputElement?!["checkbox","radio","button"].includes(i.type):i.getAttribute("role")==="slider"}function np(i){for(const e of i.controllersRecursive()){const t=e.$slider;t!==void 0&&(t.setAttribute("aria-valuenow",String(e.getValue())),t.dataset.keys!=="1"&&(t.dataset.keys="1",t.tabIndex=0,t.setAttribute("role","slider"),t.setAttribute("aria-label",e.$name.textContent??""),e._min!==void 0&&t.setAttribute("aria-valuemin",String(e._min)),e._max!==void 0&&t.setAttribute("aria-valuemax",String(e._max)),t.addEventListener("keydown",n=>{const s=LT(n.key);if(s===null)return;n.preventDefault(),n.stopPropagation();const[r,a,o]=[e._min??-1/0,e._max??1/0,e._step??.01],l=Number(e.getValue()),c=s===1/0?a:s===-1/0?r:Math.min(a,Math.max(r,l+s*o));Number.isFinite(c)&&e.setValue(+c.toPrecision(12)),t.setAttribute("aria-valuenow",String(e.getValue()))})))}}function DT(i,e){const t=5*Math.PI/180;if(e&&i==="ArrowLeft")return{bob:-1};if(e&&i==="ArrowRight")return{bob:1};switch(i){case"ArrowLeft":return{orbit:[-t,0],zoom:1};case"ArrowRight":return{orbit:[t,0],zoom:1};case"ArrowUp":return{orbit:[0,t],zoom:1};case"ArrowDown":return{orbit:[0,-t],zoom:1};case"+":case"=":return{orbit:[0,0],zoom:1/1.1};case"-":return{orbit:[0,0],zoom:1.1};default:return null}}function ip(i,e,t=1e-6){if(i===null)return L("describe.none");const n=Fa(i.x).theta*Cn,s=Math.hypot(...i.v),r=i.v[2],a=s<t?L("describe.rest"):Math.abs(r)<.001*s?L("describe.turning"):r>0?L("describe.rising"):L("describe.falling");let o=L("describe.text",{theta:n.toFixed(0),dir:a,v:s.toFixed(2)});if(e!==null){const l=Math.abs(e.kinetic)+Math.abs(e.potential)+Math.abs(e.lost);if(l>0){const c=h=>Math.round(100*h/l);o+=L("describe.energy",{k:c(e.kinetic),u:c(e.potential)}),Math.abs(e.lost)>.005*l&&(o+=L("describe.lost",{p:c(e.lost)}))}}return o}const zh=2*2**20,NT=["damped","ideal","rotating","slewing","vibrating"];function IT(i,e,t,n,s){if(t>zh)return`${i}: ${(t/2**20).toFixed(1)} MiB; the lab fits files of at most ${zh/2**20} MiB (use pendulab fit for larger ones)`;if(e.trim()==="")return`${i}: the file is empty`;const r={csv:e,name:i,model:n},a=s.split(/[\s,]+/).filter(o=>o!=="");return a.length>0&&(r.fit=a),r}const lg=i=>typeof i=="number"&&Number.isFinite(i),UT=i=>Array.isArray(i)&&i.length===3&&i.every(lg);function FT(i){if(typeof i!="object"||i===null)return"the fit answer is not an object";const e=i;if(typeof e.report!="string"||typeof e.scenario_toml!="string")return"the fit answer has no report";const t=e.measured;if(t!=null){const n=t,s=n.t,r=n.x;if(!Array.isArray(s)||!Array.isArray(r)||s.length!==r.length||!s.every(lg)||!r.every(UT))return"the fit answer has a malformed measured path"}return{report:e.report,warnings:Array.isArray(e.warnings)?e.warnings.filter(n=>typeof n=="string"):[],params:e.params??{},converged:e.converged===!0,scenario_toml:e.scenario_toml,lab:e.lab??null,measured:t??null}}function OT(i){const e={model:i.model,modelParams:{...i.model_params},length:i.params.length,mass:i.params.mass,g:i.params.g,method:i.method,dt:i.dt,x:i.start.x,v:i.start.v};return kh(e)}function kT(i){return Object.entries(i).map(([e,t])=>{const n=t.determined&&t.stderr!==null?` ± ${t.stderr.toPrecision(2)}`:" (not determined by these data)",s=t.unit&&t.unit!=="1"?` ${t.unit}`:"";return`${e} = ${t.value.toPrecision(6)}${n}${s}`})}function ci(i,e={},t=""){const n=document.createElement(i);for(const[s,r]of Object.entries(e))n.setAttribute(s,r);return t&&(n.textContent=t),n}class BT{constructor(e,t){this.actions=t;const n=ci("section",{class:"tools","data-tool":"fit"});n.appendChild(ci("h3",{},L("fit.title")));const s=ci("label");s.append(`${L("fit.load")} `),this.input=ci("input",{type:"file",accept:".csv,.txt,.tsv,text/csv,text/plain","data-input":"fit-file"}),s.appendChild(this.input),s.title=L("fit.help");const r=ci("label");r.append(`${L("fit.model")} `),this.model=ci("select",{"data-input":"fit-model"});for(const o of NT)this.model.appendChild(ci("option",{value:o},o));r.appendChild(this.model);const a=ci("label");a.append(`${L("fit.params")} `),this.names=ci("input",{type:"text","data-input":"fit-params",placeholder:L("fit.paramsDefault")}),this.names.style.width="12em",a.appendChild(this.names),a.title=L("fit.paramsHelp"),this.clear=ci("button",{type:"button","data-action":"fit-clear"},L("fit.clear")),this.clear.disabled=!0,this.clear.addEventListener("click",()=>this.reset()),this.report=ci("pre",{class:"fit-report","data-output":"fit-report","aria-live":"polite"}),this.report.hidden=!0;for(const o of[s,r,a,this.clear]){const l=ci("p");l.appendChild(o),n.appendChild(l)}n.appendChild(this.report),e.appendChild(n),this.input.addEventListener("change",()=>{const o=this.input.files?.[0];o!==void 0&&this.send(o)})}actions;input;model;names;clear;report;busy=!1;reset(){this.report.hidden=!0,this.report.textContent="",this.clear.disabled=!0,this.input.value="",this.actions.cleared()}async send(e){if(this.busy)return;const t=e.size>zh?"":await e.text(),n=IT(e.name,t,e.size,this.model.value,this.names.value);if(typeof n=="string")return this.actions.explain(n);this.busy=!0,this.input.disabled=!0,this.report.hidden=!1,this.report.textContent=L("fit.running",{name:e.name});try{const s=await fetch("api/fit",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(n)}),r=await s.json().catch(()=>({detail:`HTTP ${s.status}`}));if(!s.ok){const l=r.detail;throw new Error(typeof l=="string"?l:`HTTP ${s.status}`)}const a=FT(r);if(typeof a=="string")throw new Error(a);const o=[a.report,"",...kT(a.params),...a.warnings.map(l=>`warning: ${l}`)];a.measured===null&&o.push(L("fit.noPath")),this.report.textContent=o.join(`
`),this.clear.disabled=!1,this.actions.loaded(a,e.name)}catch(s){const r=s instanceof Error?s.message:String(s);this.report.textContent=`${e.name}: ${r}`,this.actions.explain(L("fit.failed",{why:r}))}finally{this.busy=!1,this.input.disabled=!1}}}function Ht(i){const e=document.getElementById(i);if(e===null)throw new Error(`#${i} missing from index.html`);return e}function Oo(i,e){const t=document.createElement("a");t.href=e,t.download=i,document.body.appendChild(t),t.click(),t.remove()}async function zT(){const i=Ng(new URLSearchParams(window.location.search).get("lang"),window.localStorage?.getItem("pendulab.lang")??null,navigator.languages??[navigator.language]);Ig(i),document.documentElement.lang=i,document.title=L("page.title"),Ht("units").textContent=L("page.units"),Ht("scene").setAttribute("aria-label",L("page.scene")),Ht("panel").setAttribute("aria-label",L("page.panel"));const e=new pm,t=Ht("message");let n=null;const s=(q,oe=!1)=>{t.textContent=q,t.classList.toggle("info",oe),t.classList.add("shown"),n!==null&&clearTimeout(n),n=setTimeout(()=>t.classList.remove("shown"),6e3)},[r,a]=await Promise.all([Oh("api/schema"),Oh("api/scenarios")]);e.tickHz=r.tick_hz;const o=vb(xb(),window.devicePixelRatio);o.software&&(Ht("render").textContent=` · ${L("page.software")}`,Ht("render").title=L("page.softwareHelp",{renderer:o.renderer??""}));const l=new Hb(Ht("scene"),o);l.renderer.domElement.setAttribute("role","img"),l.renderer.domElement.setAttribute("aria-label",L("page.scene"));const c={...xc},h=new nT,u=new _T(Ht("plots")),d=new $E(Ht("plots"),q=>h.add("plots drawn (uPlot)",q)),m=new KE(Ht("portraits")),_=new yu(Ht("reduced"),o),S=new qg(Ht("data")),p=aT(window.location.search);for(const[q,oe]of Object.entries(p.value.view??{})){const ve=xc[q];ve!==void 0&&typeof ve==typeof oe&&(q!=="stereo"||vm.includes(oe))?c[q]=oe:p.problems.push(`view: ${q} = ${String(oe)} is not a view option`)}p.problems.length>0&&s(`link: ${p.problems.join("; ")}`);let f=kh(p.value),x=[];p.value.twin!==void 0&&(x=f.filter(q=>q.type==="step"),f=f.filter(q=>q.type!=="step"));let R=null,y=null;const A=q=>{R===null||!R.send(q)?s(L("msg.notConnected")):y?.mirror(q)},w=()=>A({type:e.status?.paused===!1?"pause":"resume"}),g=()=>A({type:"reset"}),b=()=>A({type:"step",n:1});let I=null;const N=new CT(l.renderer.domElement,q=>{q.slice(0,4).arrayBuffer().then(ve=>{I={size:q.size,head:[...new Uint8Array(ve)].map(Xe=>Xe.toString(16).padStart(2,"0")).join("")}});const oe=URL.createObjectURL(q);Oo(`pendulab-${e.status?.scenario??"lab"}.webm`,oe),setTimeout(()=>URL.revokeObjectURL(oe),1e4),s(L("msg.recorded",{mb:(q.size/1e6).toFixed(1)}),!0)}),P=new ET(Ht("help")),B=new cT(Ht("toolbar"),Ht("panel"),{run:w,reset:g,step:b,record:()=>{if(N.recording)N.stop();else{const q=N.start();q!==null?s(L("msg.noRecording",{why:q})):s(L("msg.recording"),!0)}B.showRecording(N.recording)},help:()=>P.toggle(),language:q=>{window.localStorage?.setItem("pendulab.lang",q),Il(()=>e.status?.commands,()=>R?.sent??0,2e3).then(()=>{const oe=new URLSearchParams(window.location.search);oe.set("lang",q),window.location.search=oe.toString()})},collapsed:()=>{}}),V=l.renderer.domElement;V.tabIndex=0,V.setAttribute("aria-label",`${L("page.scene")}. ${L("help.camera")}; Shift + ← →: ${L("help.bobKeys")}`),V.addEventListener("keydown",q=>{const oe=DT(q.key,q.shiftKey);if(!(oe===null||q.ctrlKey||q.metaKey||q.altKey))if(q.preventDefault(),"orbit"in oe)l.orbitBy(oe.orbit[0],oe.orbit[1],oe.zoom);else{const ve=e.status;if(ve===null)return;ve.paused||A({type:"pause"});const Xe=Fa(ve.start.x),Ze=Math.min(Math.max(Xe.theta+oe.bob/Cn,0),Math.PI);A({type:"set_state",theta:Ze,phi:Xe.phi,theta_dot:0,phi_dot:0}),s(L("describe.text",{theta:(Ze*Cn).toFixed(0),dir:L("describe.rest"),v:"0.00"}),!0)}}),document.addEventListener("keydown",q=>{if((q.key==="d"||q.key==="D")&&!q.ctrlKey&&!q.metaKey&&!q.altKey&&!tp(q.target,q.key)&&!P.open){const ve=e.latest();U.describe(ip(e.displayed(),ve?jd(ve,e.status?.params.mass??1,e.status?.params.g??9.81,e.status?.params.length??1,e.work):null),performance.now(),!0);return}const oe=PT(q.key,q.ctrlKey||q.metaKey||q.altKey);if(oe!==null){if(oe==="close"){P.open&&P.toggle(!1);return}tp(q.target,q.key)||P.open&&oe!=="help"||(q.preventDefault(),oe==="run"?w():oe==="reset"?g():oe==="step"?b():P.toggle())}});const U=new fT(Ht("tools"),e,{send:A,explain:s,overlay:(q,oe)=>{c[q]=oe}}),W=new gT(Ht("energy"));new BT(Ht("tools"),{loaded:(q,oe)=>{if(l.setMeasured(q.measured?.x??null),q.lab!==null)for(const ve of OT(q.lab))A(ve);s(L("fit.loaded",{name:oe}),!0)},cleared:()=>l.setMeasured(null),explain:s});const Z=new Wb(Ht("gui"),r,a,c,{send:A,explain:s,downloadCSV:()=>{const q=new Blob([e.toCSV()],{type:"text/csv"}),oe=URL.createObjectURL(q);Oo(`pendulab-${e.status?.scenario??"lab"}.csv`,oe),setTimeout(()=>URL.revokeObjectURL(oe),1e4)},downloadTOML:()=>{const q=e.status;if(q===null)return s(L("msg.notConnected"));fetch("api/scenario.toml",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(iT(q))}).then(async oe=>{if(!oe.ok)throw new Error((await oe.json()).detail??`HTTP ${oe.status}`);const ve=URL.createObjectURL(await oe.blob());Oo(`pendulab-${q.scenario??"lab"}.toml`,ve),setTimeout(()=>URL.revokeObjectURL(ve),1e4)}).catch(oe=>s(`scenario download: ${oe instanceof Error?oe.message:String(oe)}`))},screenshot:()=>Oo(`pendulab-${e.status?.scenario??"lab"}.png`,l.screenshot()),copyLink:()=>{he();const q=window.location.href,oe=lT(H());navigator.clipboard?.writeText(q).then(()=>s(L("msg.linkCopied",{what:oe}),!0),()=>s(`${q} — ${oe}`,!0))??s(`${q} — ${oe}`,!0)},viewChanged:(q,oe)=>{l.setTopView(oe),l.setStereo(q.stereo)}}),H=()=>{const q=e.status,oe=q===null?{}:Zf(q);return oe.view=sT(c,xc),(u.choice.x!=="t"||u.choice.y!=="theta")&&(oe.plot=[u.choice.x,u.choice.y]),y?.on&&y.options.mode!=="off"&&(oe.twin={...y.options}),oe.lang=rp(),oe},he=()=>{if(f.length>0||e.status===null)return;const q=`?${rT(H())}`;q!==window.location.search&&window.history.replaceState(null,"",q)};p.value.plot&&u.choose(...p.value.plot),U.showOverlay("ruler",c.ruler),U.showOverlay("protractor",c.protractor),l.setStereo(c.stereo);let J=p.value.twin??null;const ee=new JE(e,_,s);y=new MT(Ht("tools"),e,r.methods,Gu(window.location),{send:A,explain:s}),np(Z.gui);const se=q=>{const oe=e.status;e.onStatus(q),oe!==null&&(oe.scenario!==q.scenario||oe.model!==q.model)&&t.classList.contains("info")&&t.classList.remove("shown"),(oe===null||oe.epoch!==q.epoch)&&W.rescale(),Z.sync(q),np(Z.gui),U.sync(q),B.showRunning(q.paused),l.setLength(q.params.length),l.setModel(q.model),m.setModel(q.model),he()};R=new sp(Gu(window.location),{onOpen:()=>{e.setConnected(!0),Ht("conn").textContent=L("conn.connected"),Ht("offline").hidden=!0},onClose:()=>{e.setConnected(!1),Ht("conn").textContent=L("conn.retrying"),Ht("offline").textContent=L("conn.gone"),Ht("offline").hidden=!1,e.status!==null&&(f=kh(Zf(e.status)))},onFrames:q=>{const oe=performance.now();e.onFrames(q),ee.onFrames(),h.add("frames received",performance.now()-oe)},onNotice:q=>{if(q.type==="error"){e.onError(q),s(q.command?`${q.command}: ${q.message}`:q.message);return}if(q.type==="event"){e.onEvent(q),s(zg(q),!0);return}if(se(q),f.length>0){const oe=f;f=[];for(const ve of oe)A(ve)}if(J!==null){const oe=J;J=null,Il(()=>e.status?.commands,()=>R?.sent??0,5e3).then(()=>(y?.restore(oe),Il(()=>y?.store.status?.paused?1:void 0,()=>1,5e3))).then(()=>{for(const ve of x)A(ve);x=[]})}},onProtocolError:q=>s(`protocol: ${q}`)});let pe=0;const fe=Xh((q,oe)=>{A({type:"set_state",x:q,v:oe,project:!0})},50),te=()=>{e.status?.paused===!1&&A({type:"pause"})};l.enableDrag((q,oe)=>{oe==="start"&&te(),fe(q,[0,0,0]),oe==="end"&&s(L("msg.dragged"),!0)},(q,oe,ve)=>{if(ve==="start"){te(),s(L("msg.pull"),!0);return}if(oe===null)return;fe(q,oe.v);const Xe=oe.capped?L("msg.capped"):"";s(ve==="end"?L("msg.velocitySet",{v:oe.speed.toFixed(2),cap:Xe}):L("msg.velocity",{v:oe.speed.toFixed(2),cap:Xe}),!0)}),window.pendulab={store:e,drawn:()=>pe,send:A,screenshot:()=>l.screenshot(),bobOnScreen:()=>l.bobOnScreen(),handleOnScreen:()=>l.handleOnScreen(),quality:()=>o,frameCosts:()=>h.take(),twin:y.store,twinOnScreen:()=>l.twinOnScreen(),sphereOnScreen:()=>l.sphereOnScreen(),separation:()=>y?.separationNow()??{t:[],d:[]},energy:()=>W.shown,lastVideo:()=>I,plotScales:()=>d.scales(),measuredPoints:()=>l.measuredPoints()};let _e=performance.now();const xe=new eT(100),Pe=new tT,Me=q=>{const oe=(q-_e)/1e3;_e=q;let ve=performance.now();e.advancePlayhead(oe);const Xe=e.displayed(),Ze=e.status?.params,je=cb(e.status?.model_params),{start:Ut,end:At}=e.trailRange(c.trailSeconds),zt=Ze?.mass??1,xt=Ze?.g??9.81,Jt=y?.drawn(e.playT,c.trailSeconds)??null;l.setTwinLayout(y?.layout()??null);const dt=Pe.changed([Xe,e.trail,Ut,At,zt,xt,...je,...Object.values(c),Jt?.frame??null,Jt?.trail.end??0]);dt&&(l.update(Xe,{frames:e.trail,start:Ut,end:At},c,zt,xt,je),l.updateTwin(Jt?.frame??null,Jt?.trail??{frames:[],start:0,end:0}));let Rt=performance.now();if(h.add("scene update",Rt-ve),l.draw(dt)?(pe++,ve=performance.now(),h.add("scene render (submit)",ve-Rt)):ve=Rt,xe.due(q)){const Vt=e.reference,Kt=Ze?.length??1;d.update(e.history,e.events,WE(Vt?.energy??0,Vt?.j3??0,zt,xt,Kt));const O={mass:zt,g:xt,length:Kt};u.update(e.history.frames,O,y?.on?y.store.history.frames:null),y?.update(Ht("plots").clientWidth-8),U.update(Xe?.x??null,Xe?.t??null),he();const Le=e.latest(),qe=Le?jd(Le,zt,xt,Kt,e.work):null;W.draw(qe,e.status?.model!=="ideal"),U.describe(ip(Xe,qe),q),Rt=performance.now(),h.add("plots setData",Rt-ve),m.update(e.history,Xe,ee.veff,Ze?.mass??1,Ze?.g??9.81,Ze?.length??1),m.updateEM(ee.em,Xe),ve=performance.now(),h.add("portraits",ve-Rt),_.update(Xe,Ze?.length??1),Rt=performance.now(),h.add("reduced view",Rt-ve),S.update(Xe,e),h.add("data panel",performance.now()-Rt)}requestAnimationFrame(Me)};requestAnimationFrame(Me)}zT().catch(i=>{const e=document.getElementById("offline");e&&(e.textContent=`${L("conn.noStart")} ${i instanceof Error?i.message:String(i)}`,e.hidden=!1),console.error(i)});
