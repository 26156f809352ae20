(function(){const e=document.createElement("link").relList;if(e&&e.supports&&e.supports("modulepreload"))return;for(const s of document.querySelectorAll('link[rel="modulepreload"]'))n(s);new MutationObserver(s=>{for(const r of s)if(r.type==="childList")for(const a of r.addedNodes)a.tagName==="LINK"&&a.rel==="modulepreload"&&n(a)}).observe(document,{childList:!0,subtree:!0});function t(s){const r={};return s.integrity&&(r.integrity=s.integrity),s.referrerPolicy&&(r.referrerPolicy=s.referrerPolicy),s.crossOrigin==="use-credentials"?r.credentials="include":s.crossOrigin==="anonymous"?r.credentials="omit":r.credentials="same-origin",r}function n(s){if(s.ep)return;s.ep=!0;const r=t(s);fetch(s.href,r)}})();const og=["t","x1","x2","x3","v1","v2","v3","energy","j3","tension","power","a1","a2","a3","pivot1","pivot2","pivot3","taut","error_x"],lg={fields:og},Ih=lg.fields,cg=Ih.length,Ya=8*cg;function gn(i){const e=Ih.indexOf(i);if(e<0)throw new Error(`frame.json lacks the field ${i}`);return e}const Si={t:gn("t"),x:[gn("x1"),gn("x2"),gn("x3")],v:[gn("v1"),gn("v2"),gn("v3")],energy:gn("energy"),j3:gn("j3"),tension:gn("tension"),power:gn("power"),a:[gn("a1"),gn("a2"),gn("a3")],pivot:[gn("pivot1"),gn("pivot2"),gn("pivot3")],taut:gn("taut"),errorX:gn("error_x")};class di extends Error{}function hg(i){if(i.byteLength===0||i.byteLength%Ya!==0)throw new di(`a frame message has a multiple of ${Ya} bytes, got ${i.byteLength}`);const e=new DataView(i),t=i.byteLength/Ya,n=[];for(let s=0;s<t;s++){const r=s*Ya,a=l=>e.getFloat64(r+8*l,!0),o=l=>[a(l[0]),a(l[1]),a(l[2])];n.push({t:a(Si.t),x:o(Si.x),v:o(Si.v),energy:a(Si.energy),j3:a(Si.j3),tension:a(Si.tension),power:a(Si.power),a:o(Si.a),pivot:o(Si.pivot),taut:a(Si.taut)!==0,errorX:a(Si.errorX)})}return n}function Iu(i){return typeof i=="object"&&i!==null&&!Array.isArray(i)}function ug(i){let e;try{e=JSON.parse(i)}catch(t){throw new di(`notice is not JSON: ${String(t)}`)}if(!Iu(e))throw new di("notice is not a JSON object");if(e.type==="error"&&typeof e.message=="string"){const t=typeof e.command=="string"?e.command:null;return{type:"error",message:e.message,command:t}}if(e.type==="status"){const t=e.params;if(!Iu(t)||typeof e.epoch!="number"||typeof e.method!="string")throw new di("status notice lacks epoch, method or params");const n=e.frame_fields;if(Array.isArray(n)&&n.join(",")!==Ih.join(","))throw new di(`server frame layout ${n.join(",")} differs from the page's`);return e}if(e.type==="event")return dg(e);throw new di(`unknown notice type ${JSON.stringify(e.type)}`)}function Cl(i){return typeof i=="number"&&Number.isFinite(i)}function dg(i){const{kind:e,t,energy_lost:n,x:s,epoch:r}=i,a=i.skipped??0;if(e!=="slack"&&e!=="taut")throw new di(`event notice: kind ${JSON.stringify(e)} is not "slack" or "taut"`);if(!Cl(t))throw new di("event notice: t is not a finite number");if(!Cl(n)||n<0)throw new di("event notice: energy_lost is not a finite number ≥ 0");if(!Array.isArray(s)||s.length!==3||!s.every(Cl))throw new di("event notice: x is not 3 finite numbers");if(!Number.isInteger(r)||!Number.isInteger(a)||a<0)throw new di("event notice: epoch or skipped is not an integer");return{type:"event",kind:e,t,energy_lost:n,x:[s[0],s[1],s[2]],epoch:r,skipped:a}}function Uu(i){const e=i.protocol==="https:"?"wss:":"ws:",t=i.pathname.endsWith("/")?i.pathname:i.pathname.replace(/[^/]*$/,"");return`${e}//${i.host}${t}ws`}function fg(i,e,t,n=20){const s=Date.now()+t;return new Promise(r=>{const a=()=>{(i()??-1)>=e()?r(!0):Date.now()>=s?r(!1):setTimeout(a,n)};a()})}class Kf{constructor(e,t){this.url=e,this.handlers=t,this.open()}url;handlers;sent=0;ws=null;retryMs=500;closedByUs=!1;open(){const e=new WebSocket(this.url);e.binaryType="arraybuffer",e.onopen=()=>{this.retryMs=500,this.sent=0,this.handlers.onOpen()},e.onmessage=t=>{try{t.data instanceof ArrayBuffer?this.handlers.onFrames(hg(t.data)):typeof t.data=="string"&&this.handlers.onNotice(ug(t.data))}catch(n){if(n instanceof di)this.handlers.onProtocolError(n.message);else throw n}},e.onclose=()=>{this.ws=null,this.handlers.onClose(),this.closedByUs||(setTimeout(()=>this.open(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))},this.ws=e}get isOpen(){return this.ws!==null&&this.ws.readyState===WebSocket.OPEN}send(e){return!this.isOpen||this.ws===null?!1:(this.ws.send(JSON.stringify(e)),this.sent++,!0)}close(){this.closedByUs=!0,this.ws?.close()}}const il={"page.title":"Pendulab lab — the spherical pendulum","page.units":"SI units, z up","page.scene":"3-D view of the pendulum (drag to orbit, scroll to zoom)","page.panel":"controls and measurements","page.software":"software WebGL: no antialiasing","conn.connected":"connected","conn.retrying":"disconnected: retrying…","conn.gone":"The lab’s server is not answering: the pendulum has stopped. Is pendulab serve still running? Trying to reconnect …","conn.noStart":"The lab could not start:","toolbar.label":"run controls","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Reset","toolbar.stepShort":"Step","toolbar.recordShort":"● Record","toolbar.recordStopShort":"■ Stop","toolbar.start":"start (Space)","toolbar.pause":"pause (Space)","toolbar.reset":"reset to the start (R)","toolbar.step":"one step (S)","toolbar.record":"record a video (WebM)","toolbar.recordStop":"stop recording and download the video","toolbar.help":"keyboard shortcuts and colour key (?)","toolbar.language":"language","toolbar.collapse":"hide the panel","toolbar.expand":"show the panel","gui.title":"Pendulab lab","gui.pendulum":"Pendulum","gui.model":"model","gui.modelParams":"{model}: parameters","gui.paramHelp":"{help} — key {name} [{unit}]; allowed: {range}; default {default}","gui.integrator":"Integrator","gui.method":"method","gui.order":"order {n}","gui.symplectic":"symplectic","gui.adaptive":"adaptive","method.rk4":"Runge–Kutta, 4th order (classic; drifts off the sphere)","method.dop853":"Adaptive, very accurate (Dormand–Prince, 8th order)","method.rattle":"Symplectic (RATTLE, 2nd order; the default)","method.rattle4":"Symplectic (RATTLE, 4th order)","method.rattle6":"Symplectic (RATTLE, 6th order)","method.rattle8":"Symplectic (RATTLE, 8th order)","method.rkmk4":"Rotation steps on the sphere (Munthe-Kaas, 4th order)","method.rk4_angles":"Runge–Kutta 4 in angles (breaks down at the poles)","method.other":"{name} (order {n})","kind.generic":"goes round and round in a rosette","kind.conical":"circles at one height (conical pendulum)","kind.planar":"swings to and fro in a plane","kind.planar_rotating":"swings over the top in a plane","kind.separatrix":"creeps towards the top for ever","kind.rest":"at rest","kind.great_circle":"goes round a great circle (no gravity)","data.energy":"energy E","data.energyChange":"energy change E − E₀","data.spin":"angular momentum about the vertical J₃","data.spinChange":"its change J₃ − J₃(0)","data.height":"height z","data.turning":"lowest and highest height z₁, z₂","gui.dtRange":"dt must be between {min} and {max} s","gui.dtHelp":"step size of fixed-step methods; {min} … {max} s (dop853 chooses its own)","gui.run":"Run","gui.timeScale":"time scale [×]","gui.tsRange":"the time scale must be between {min} and {max}","gui.tsHelp":"simulated seconds per second (slow motion below 1); {min} … {max}","gui.stepN":"steps per step","gui.scenario":"scenario","gui.view":"View","gui.trail":"trail","gui.trailSeconds":"trail [s]","gui.sphere":"sphere of reach","gui.axes":"axes","gui.topView":"top view","gui.stereo":"stereo","gui.stereoHelp":"anaglyph: red–cyan glasses; side by side: a stereo viewer","stereo.off":"off","stereo.anaglyph":"anaglyph","stereo.sideBySide":"side by side","gui.vectors":"Vectors","gui.origin":"origin {axis} [m]","gui.originHelp":"origin of L and τ relative to the pivot (0: the pivot)","gui.export":"Share and export","gui.csv":"download trajectory (CSV)","gui.toml":"download scenario (TOML)","gui.tomlHelp":"the scenario as it stands (model, parameters, start, method) as a file for `pendulab run`","gui.png":"screenshot (PNG)","gui.link":"copy link to this scenario","vec.velocity":"velocity v","vec.velocityHelp":"v [m/s], drawn as 0.25 s of travel","vec.momentum":"momentum m v","vec.momentumHelp":"m v [kg m/s], 0.25 m per kg m/s","vec.gravity":"gravity m g","vec.gravityHelp":"the weight m g d [N] (d: the gravity direction); forces: m·max(|g|, 1) N ↔ 0.5 l","vec.tension":"rod force (tension)","vec.tensionHelp":"the rod force −T x/|x| [N], T from the server","vec.net":"net force m a","vec.netHelp":"m a [N]: a = ẍ computed by the server’s core (relative to the pivot)","vec.angularMomentum":"angular momentum L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] about the origin o, drawn from o","vec.torque":"torque τ","vec.torqueHelp":"τ = (x − o) × m a [N m] about the origin o, drawn from o; dL/dt = τ","data.now":"Now (from the server)","data.exact":"Exact solution of this orbit","data.tension":"tension","data.tensionMin":"tension min","data.tensionMax":"tension max","data.method":"method","data.state":"state","data.paused":"paused","data.running":"running","data.lagging":" (lagging: slower than asked)","data.model":"model","data.kind":"kind of motion","data.periodZ":"z-period T_z","data.swingPeriod":"swing period T","data.advance":"azimuthal advance Δφ per T_z","data.rotation":"rotation number W = Δφ/2π","data.reduced":"reduced view (σ₁, σ₂, σ₃): J₃ surface ∩ energy plane","portrait.phase":"phase portrait: vertical speed ż against height z","portrait.veff":"effective potential V_eff(θ); energy E dashed, θ now dotted","portrait.em":"energy–momentum map: E against J₃ (dot: now)","portrait.orbit":"orbit","portrait.emBoundary":"boundary (conical orbits)","note.spring":"the swinging spring leaves the sphere (its length varies): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.string":"the string goes slack (free flight inside the sphere): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.exactIdeal":"the exact solution exists for the ideal pendulum only; this is the {model} model","note.reducedIdeal":"the reduced view is the ideal pendulum’s; this is the {model} model","event.slack":"the string went slack (tension 0: free flight)","event.taut":"the string snapped taut, lost {lost} J","event.skippedOne":" ({n} earlier event of this moment not shown)","event.skippedMany":" ({n} earlier events of this moment not shown)","event.slackRow":"went slack","event.tautRow":"snapped taut","event.tautValue":"t = {t} s, lost {lost}","data.power":"power P = dE/dt","data.springForce":"spring force k(|r| − l₀)","data.springLength":"spring length |r|","data.stretch":"stretch |r| − l₀","data.string":"string","data.slackZero":"slack (0)","data.slack":"slack: free flight, |x| = {r} m","data.taut":"taut","data.events":"events","data.noEvents":"none yet (slack, snaps)","data.z3":"z₃ (outside)","data.dynamic":"Δφ dynamic","data.geometric":"Δφ geometric","data.error":"position error |Δx|","data.errorRel":"position error / l","data.errorHow":"error obtained by","data.errorPaused":"estimate paused (the server’s work budget is used up; it catches up when there is time)","data.errorNone":"no estimate","data.howExact":"the true error: against the exact solution (since t = {since} s)","data.howRichardson":"estimate: Richardson against a companion at dt/2 = {dt} s, order p = {p} (since t = {since} s)","data.howCompanion":"estimate: a companion run at rtol = {rtol} (since t = {since} s)","page.softwareHelp":"{renderer}: drawn without multisampling for the frame rate","tools.start":"Start angle","tools.thetaHelp":"θ₀: the angle from the downward vertical, in degrees (0 … 180)","tools.phiHelp":"φ₀: the azimuth around the vertical, in degrees","tools.phiDotHelp":"φ̇₀: how fast the bob starts going round, in degrees per second (0: a planar swing)","tools.setStart":"set start","tools.world":"Gravity and friction","tools.gravity":"gravity","tools.friction":"friction","tools.frictionHelp":"linear damping c [1/s]: the force −m c v; on the ideal pendulum it switches to the damped model","tools.noFriction":"the {model} model has no friction parameter","tools.now":"Angles now","tools.stopwatch":"Stopwatch (simulated time)","tools.swStart":"start","tools.swStop":"stop","tools.swLap":"lap","tools.swReset":"reset","tools.period":"Period timer","tools.periodHelp":"measured from the motion: the lowest points of the bob; a swing’s period ends when the bob passes the bottom again the same way. Compared with the exact value (ideal pendulum) or the theory (small-swing formula with friction)","tools.periodCount":"mean over {n} periods","tools.periodCountZ":"mean over {n} lowest-to-lowest times","tools.periodWait":"waiting for the bob to pass its lowest point twice","tools.motion":"motion","tools.kindNone":"—","tools.kindSwing":"swings to and fro","tools.kindOver":"swings over the top","tools.kindOrbit":"goes round (never through the bottom)","tools.periodSwing":"period T [s]","tools.periodZ":"lowest point to lowest point [s]","tools.advance":"turn between lowest points [°]","tools.precession":"pattern turns per round [°]","tools.amplitude":"amplitude (largest angle) [°]","tools.band":"angle from the vertical [°]","tools.theory":"theory","tools.measured":"measured","tools.exact":"exact","tools.difference":"difference","tools.overlays":"Ruler and protractor","tools.ruler":"ruler (metres)","tools.protractor":"protractor (θ in degrees)","start.notNumber":"{name} must be a number","start.thetaRange":"θ₀ = {value}° is not allowed: 0 … 180°","gravity.custom":"custom","gravity.earth":"Earth","gravity.moon":"Moon","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"zero","gravity.negative":"negative (upwards)","energy.title":"Energy","energy.kinetic":"kinetic","energy.potential":"potential","energy.lost":"lost","energy.total":"total","plot.dE":"energy drift |ΔE|/E_s (log)","plot.dJ3":"J₃ drift |ΔJ₃|/J_s (log)","plot.z":"height z(t)","plot.tension":"rod tension T(t)","plot.time":"time t [s]","plot.floor":"float64 roundoff 2.2e-16","chosen.title":"Plot any variables","chosen.xAxis":"across","chosen.yAxis":"up","var.t":"time t","var.theta":"angle θ","var.phi":"azimuth φ","var.x":"x","var.y":"y","var.z":"height z","var.zdot":"vertical speed ż","var.speed":"speed |v|","var.energy":"energy E","var.kinetic":"kinetic energy K","var.potential":"potential energy U","var.j3":"angular momentum J₃","var.tension":"tension T","var.power":"power P","var.radius":"distance |x|","twin.title":"Two pendulums","twin.mode":"second pendulum","twin.off":"off","twin.epsilon":"start differs by ε","twin.method":"another integrator","twin.damped":"damped beside this one","twin.own":"its own length, mass and start (side by side)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"the second pendulum needs a length > 0, a mass > 0 and a start angle 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"period T [s] (periods)","twin.methodPick":"integrator","twin.damping":"damping [1/s]","twin.start":"start both","twin.bad":"ε must be a number and the damping ≥ 0","twin.first":"pendulum 1","twin.second":"pendulum 2","twin.separation":"separation of the bobs |r₁ − r₂| [m]","help.title":"Keyboard shortcuts and colour key","help.space":"start / pause","help.r":"reset to the start","help.s":"one step (paused)","help.arrows":"on a focused slider: one step down / up","help.page":"on a focused slider: ten steps","help.tab":"move between controls","help.help":"this overlay","help.esc":"close this overlay","help.colours":"Colours","help.close":"close","help.bob":"bob","help.trail":"trail","help.twin":"second pendulum","help.ruler":"ruler and protractor","msg.notConnected":"not connected to the server","msg.linkCopied":"link copied: it reproduces this scenario","msg.dragged":"start set by dragging (at rest there): press start to release it","msg.pull":"pull the arrow to set the start velocity","msg.capped":" (capped: the most the arrow sets, 4√(g l))","msg.velocitySet":"start velocity set: |v| = {v} m/s{cap}; press start to run from it","msg.velocity":"start velocity |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} is not allowed: {allowed} ({range})","msg.recording":"recording the view…","msg.recorded":"video saved ({mb} MB, WebM)","msg.noRecording":"this browser cannot record the view ({why})","fit.title":"Measured data","fit.load":"Load measured data…","fit.help":"a CSV file of measurements in SI units (columns t, x, y, z or x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): the server fits the pendulum to it, loads the fitted motion and draws the measured path dotted beside it","fit.model":"model","fit.params":"fit","fit.paramsDefault":"what the data determine","fit.paramsHelp":"the parameters to fit, comma separated (e.g. length,g,damping,pivot); empty: what the data can determine","fit.clear":"clear measured path","fit.running":"fitting {name} …","fit.noPath":"(frame-free data: no measured path to draw)","fit.failed":"fit: {why}","fit.loaded":"fitted {name}: the fitted motion is loaded, the measured path dotted in gold"},pg={"page.title":"Pendulab-Labor — das Kugelpendel","page.units":"SI-Einheiten, z nach oben","page.scene":"3-D-Ansicht des Pendels (ziehen zum Drehen, scrollen zum Zoomen)","page.panel":"Steuerung und Messungen","page.software":"Software-WebGL: ohne Kantenglättung","conn.connected":"verbunden","conn.retrying":"getrennt: neuer Versuch…","conn.gone":"Der Server des Labors antwortet nicht: das Pendel steht. Läuft pendulab serve noch? Neuer Verbindungsversuch …","conn.noStart":"Das Labor konnte nicht starten:","toolbar.label":"Ablauf","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Zurück","toolbar.stepShort":"Schritt","toolbar.recordShort":"● Aufnahme","toolbar.recordStopShort":"■ Stopp","toolbar.start":"Start (Leertaste)","toolbar.pause":"Pause (Leertaste)","toolbar.reset":"zurück zum Start (R)","toolbar.step":"ein Schritt (S)","toolbar.record":"Video aufnehmen (WebM)","toolbar.recordStop":"Aufnahme beenden und Video speichern","toolbar.help":"Tastenkürzel und Farben (?)","toolbar.language":"Sprache","toolbar.collapse":"Leiste ausblenden","toolbar.expand":"Leiste einblenden","gui.title":"Pendulab-Labor","gui.pendulum":"Pendel","gui.model":"Modell","gui.modelParams":"{model}: Parameter","gui.paramHelp":"{help} — Schlüssel {name} [{unit}]; erlaubt: {range}; Vorgabe {default}","gui.integrator":"Integrator","gui.method":"Verfahren","gui.order":"Ordnung {n}","gui.symplectic":"symplektisch","gui.adaptive":"adaptiv","method.rk4":"Runge–Kutta, 4. Ordnung (klassisch; verlässt die Kugel)","method.dop853":"Adaptiv, sehr genau (Dormand–Prince, 8. Ordnung)","method.rattle":"Symplektisch (RATTLE, 2. Ordnung; Voreinstellung)","method.rattle4":"Symplektisch (RATTLE, 4. Ordnung)","method.rattle6":"Symplektisch (RATTLE, 6. Ordnung)","method.rattle8":"Symplektisch (RATTLE, 8. Ordnung)","method.rkmk4":"Drehschritte auf der Kugel (Munthe-Kaas, 4. Ordnung)","method.rk4_angles":"Runge–Kutta 4 in Winkeln (versagt an den Polen)","method.other":"{name} ({n}. Ordnung)","kind.generic":"kreist in einer Rosette","kind.conical":"kreist in einer Höhe (Kegelpendel)","kind.planar":"schwingt in einer Ebene hin und her","kind.planar_rotating":"schwingt in einer Ebene über den höchsten Punkt","kind.separatrix":"kriecht für immer auf den höchsten Punkt zu","kind.rest":"in Ruhe","kind.great_circle":"läuft auf einem Großkreis (ohne Schwerkraft)","data.energy":"Energie E","data.energyChange":"Energieänderung E − E₀","data.spin":"Drehimpuls um die Senkrechte J₃","data.spinChange":"seine Änderung J₃ − J₃(0)","data.height":"Höhe z","data.turning":"tiefste und höchste Höhe z₁, z₂","gui.dtRange":"dt muss zwischen {min} und {max} s liegen","gui.dtHelp":"Schrittweite der Verfahren mit festem Schritt; {min} … {max} s (dop853 wählt selbst)","gui.run":"Ablauf","gui.timeScale":"Zeitfaktor [×]","gui.tsRange":"der Zeitfaktor muss zwischen {min} und {max} liegen","gui.tsHelp":"simulierte Sekunden pro Sekunde (Zeitlupe unter 1); {min} … {max}","gui.stepN":"Schritte pro Schritt","gui.scenario":"Szenario","gui.view":"Ansicht","gui.trail":"Spur","gui.trailSeconds":"Spur [s]","gui.sphere":"Kugel der Reichweite","gui.axes":"Achsen","gui.topView":"Draufsicht","gui.stereo":"Stereo","gui.stereoHelp":"Anaglyphe: Rot-Cyan-Brille; nebeneinander: ein Stereobetrachter","stereo.off":"aus","stereo.anaglyph":"Anaglyphe (Rot–Cyan)","stereo.sideBySide":"nebeneinander","gui.vectors":"Vektoren","gui.origin":"Ursprung {axis} [m]","gui.originHelp":"Ursprung von L und τ relativ zum Aufhängepunkt (0: der Aufhängepunkt)","gui.export":"Teilen und exportieren","gui.csv":"Bahn herunterladen (CSV)","gui.toml":"Szenario herunterladen (TOML)","gui.tomlHelp":"das Szenario, wie es ist (Modell, Parameter, Start, Verfahren), als Datei für `pendulab run`","gui.png":"Bildschirmfoto (PNG)","gui.link":"Link zu diesem Szenario kopieren","vec.velocity":"Geschwindigkeit v","vec.velocityHelp":"v [m/s], gezeichnet als Weg in 0,25 s","vec.momentum":"Impuls m v","vec.momentumHelp":"m v [kg m/s], 0,25 m pro kg m/s","vec.gravity":"Gewichtskraft m g","vec.gravityHelp":"die Gewichtskraft m g d [N] (d: Richtung der Schwerkraft); Kräfte: m·max(|g|, 1) N ↔ 0,5 l","vec.tension":"Stangenkraft (Zugkraft)","vec.tensionHelp":"die Stangenkraft −T x/|x| [N], T vom Server","vec.net":"Gesamtkraft m a","vec.netHelp":"m a [N]: a = ẍ vom Kern des Servers berechnet (relativ zum Aufhängepunkt)","vec.angularMomentum":"Drehimpuls L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] um den Ursprung o, von o aus gezeichnet","vec.torque":"Drehmoment τ","vec.torqueHelp":"τ = (x − o) × m a [N m] um den Ursprung o, von o aus gezeichnet; dL/dt = τ","data.now":"Jetzt (vom Server)","data.exact":"Exakte Lösung dieser Bahn","data.tension":"Zugkraft","data.tensionMin":"Zugkraft min","data.tensionMax":"Zugkraft max","data.method":"Verfahren","data.state":"Zustand","data.paused":"angehalten","data.running":"läuft","data.lagging":" (hinkt nach: langsamer als verlangt)","data.model":"Modell","data.kind":"Art der Bewegung","data.periodZ":"z-Periode T_z","data.swingPeriod":"Schwingungsdauer T","data.advance":"Azimutvorschub Δφ pro T_z","data.rotation":"Umlaufzahl W = Δφ/2π","data.reduced":"reduzierte Ansicht (σ₁, σ₂, σ₃): J₃-Fläche ∩ Energieebene","portrait.phase":"Phasenporträt: Vertikalgeschwindigkeit ż gegen Höhe z","portrait.veff":"effektives Potential V_eff(θ); Energie E gestrichelt, θ jetzt gepunktet","portrait.em":"Energie-Impuls-Abbildung: E gegen J₃ (Punkt: jetzt)","portrait.orbit":"Bahn","portrait.emBoundary":"Rand (konische Bahnen)","note.spring":"die Schwingfeder verlässt die Kugel (ihre Länge ändert sich): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.string":"die Schnur wird schlaff (freier Flug in der Kugel): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.exactIdeal":"die exakte Lösung gibt es nur für das ideale Pendel; dies ist das Modell {model}","note.reducedIdeal":"die reduzierte Ansicht ist die des idealen Pendels; dies ist das Modell {model}","event.slack":"die Schnur wurde schlaff (Zugkraft 0: freier Flug)","event.taut":"die Schnur straffte sich ruckartig, verlor {lost} J","event.skippedOne":" ({n} früheres Ereignis dieses Moments nicht gezeigt)","event.skippedMany":" ({n} frühere Ereignisse dieses Moments nicht gezeigt)","event.slackRow":"schlaff geworden","event.tautRow":"gestrafft","event.tautValue":"t = {t} s, verlor {lost}","data.power":"Leistung P = dE/dt","data.springForce":"Federkraft k(|r| − l₀)","data.springLength":"Federlänge |r|","data.stretch":"Dehnung |r| − l₀","data.string":"Schnur","data.slackZero":"schlaff (0)","data.slack":"schlaff: freier Flug, |x| = {r} m","data.taut":"straff","data.events":"Ereignisse","data.noEvents":"noch keine (schlaff, Straffen)","data.z3":"z₃ (außerhalb)","data.dynamic":"Δφ dynamisch","data.geometric":"Δφ geometrisch","data.error":"Lagefehler |Δx|","data.errorRel":"Lagefehler / l","data.errorHow":"Fehler ermittelt durch","data.errorPaused":"Schätzung pausiert (das Rechenbudget des Servers ist aufgebraucht; sie holt auf, sobald Zeit ist)","data.errorNone":"keine Schätzung","data.howExact":"den wahren Fehler: gegen die exakte Lösung (seit t = {since} s)","data.howRichardson":"Schätzung: Richardson gegen einen Begleitlauf mit dt/2 = {dt} s, Ordnung p = {p} (seit t = {since} s)","data.howCompanion":"Schätzung: einen Begleitlauf mit rtol = {rtol} (seit t = {since} s)","page.softwareHelp":"{renderer}: ohne Multisampling gezeichnet, für die Bildrate","tools.start":"Startwinkel","tools.thetaHelp":"θ₀: der Winkel zur Senkrechten nach unten, in Grad (0 … 180)","tools.phiHelp":"φ₀: der Winkel um die Senkrechte, in Grad","tools.phiDotHelp":"φ̇₀: wie schnell die Kugel zu kreisen beginnt, in Grad pro Sekunde (0: ebene Schwingung)","tools.setStart":"Start setzen","tools.world":"Schwerkraft und Reibung","tools.gravity":"Schwerkraft","tools.friction":"Reibung","tools.frictionHelp":"lineare Dämpfung c [1/s]: die Kraft −m c v; beim idealen Pendel wird auf das gedämpfte Modell gewechselt","tools.noFriction":"das Modell {model} hat keinen Reibungsparameter","tools.now":"Winkel jetzt","tools.stopwatch":"Stoppuhr (simulierte Zeit)","tools.swStart":"Start","tools.swStop":"Stopp","tools.swLap":"Runde","tools.swReset":"Null","tools.period":"Periodenmessung","tools.periodHelp":"aus der Bewegung gemessen: den tiefsten Punkten der Kugel; eine Periode der Schwingung endet, wenn die Kugel den tiefsten Punkt wieder in derselben Richtung durchläuft. Verglichen mit dem exakten Wert (ideales Pendel) oder der Theorie (Formel für kleine Ausschläge mit Reibung)","tools.periodCount":"Mittel über {n} Perioden","tools.periodCountZ":"Mittel über {n} Zeiten von tiefstem zu tiefstem Punkt","tools.periodWait":"wartet, bis die Kugel zweimal den tiefsten Punkt durchlaufen hat","tools.motion":"Bewegung","tools.kindNone":"—","tools.kindSwing":"schwingt hin und her","tools.kindOver":"schwingt über den höchsten Punkt","tools.kindOrbit":"kreist (nie durch den tiefsten Punkt)","tools.periodSwing":"Periode T [s]","tools.periodZ":"tiefster bis tiefster Punkt [s]","tools.advance":"Drehung zwischen tiefsten Punkten [°]","tools.precession":"Bahn dreht sich pro Umlauf um [°]","tools.amplitude":"Amplitude (größter Winkel) [°]","tools.band":"Winkel zur Senkrechten [°]","tools.theory":"Theorie","tools.measured":"gemessen","tools.exact":"exakt","tools.difference":"Abweichung","tools.overlays":"Lineal und Winkelmesser","tools.ruler":"Lineal (Meter)","tools.protractor":"Winkelmesser (θ in Grad)","start.notNumber":"{name} muss eine Zahl sein","start.thetaRange":"θ₀ = {value}° ist nicht erlaubt: 0 … 180°","gravity.custom":"eigene","gravity.earth":"Erde","gravity.moon":"Mond","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"null","gravity.negative":"negativ (nach oben)","energy.title":"Energie","energy.kinetic":"kinetisch","energy.potential":"potentiell","energy.lost":"verloren","energy.total":"gesamt","plot.dE":"Energiedrift |ΔE|/E_s (log)","plot.dJ3":"J₃-Drift |ΔJ₃|/J_s (log)","plot.z":"Höhe z(t)","plot.tension":"Stangenkraft T(t)","plot.time":"Zeit t [s]","plot.floor":"float64-Rundung 2,2e-16","chosen.title":"Beliebige Größen zeichnen","chosen.xAxis":"waagerecht","chosen.yAxis":"senkrecht","var.t":"Zeit t","var.theta":"Winkel θ","var.phi":"Azimut φ","var.x":"x","var.y":"y","var.z":"Höhe z","var.zdot":"Vertikalgeschwindigkeit ż","var.speed":"Geschwindigkeit |v|","var.energy":"Energie E","var.kinetic":"kinetische Energie K","var.potential":"potentielle Energie U","var.j3":"Drehimpuls J₃","var.tension":"Zugkraft T","var.power":"Leistung P","var.radius":"Abstand |x|","twin.title":"Zwei Pendel","twin.mode":"zweites Pendel","twin.off":"aus","twin.epsilon":"Start um ε verschieden","twin.method":"anderer Integrator","twin.damped":"gedämpft daneben","twin.own":"eigene Länge, Masse und Start (nebeneinander)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"das zweite Pendel braucht eine Länge > 0, eine Masse > 0 und einen Startwinkel 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"Periode T [s] (Perioden)","twin.methodPick":"Integrator","twin.damping":"Dämpfung [1/s]","twin.start":"beide starten","twin.bad":"ε muss eine Zahl sein und die Dämpfung ≥ 0","twin.first":"Pendel 1","twin.second":"Pendel 2","twin.separation":"Abstand der Kugeln |r₁ − r₂| [m]","help.title":"Tastenkürzel und Farben","help.space":"Start / Pause","help.r":"zurück zum Start","help.s":"ein Schritt (angehalten)","help.arrows":"auf einem Schieberegler: einen Schritt runter / hoch","help.page":"auf einem Schieberegler: zehn Schritte","help.tab":"zwischen Bedienelementen wechseln","help.help":"diese Übersicht","help.esc":"diese Übersicht schließen","help.colours":"Farben","help.close":"schließen","help.bob":"Kugel","help.trail":"Spur","help.twin":"zweites Pendel","help.ruler":"Lineal und Winkelmesser","msg.notConnected":"keine Verbindung zum Server","msg.linkCopied":"Link kopiert: er stellt dieses Szenario wieder her","msg.dragged":"Start durch Ziehen gesetzt (dort in Ruhe): Start drücken, um loszulassen","msg.pull":"den Pfeil ziehen, um die Startgeschwindigkeit zu setzen","msg.capped":" (begrenzt: höchstens 4√(g l))","msg.velocitySet":"Startgeschwindigkeit gesetzt: |v| = {v} m/s{cap}; Start drücken","msg.velocity":"Startgeschwindigkeit |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} ist nicht erlaubt: {allowed} ({range})","msg.recording":"die Ansicht wird aufgenommen…","msg.recorded":"Video gespeichert ({mb} MB, WebM)","msg.noRecording":"dieser Browser kann die Ansicht nicht aufnehmen ({why})","fit.title":"Messdaten","fit.load":"Messdaten laden…","fit.help":"eine CSV-Datei mit Messwerten in SI-Einheiten (Spalten t, x, y, z oder x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): der Server passt das Pendel an, lädt die angepasste Bewegung und zeichnet die gemessene Bahn gepunktet daneben","fit.model":"Modell","fit.params":"anpassen","fit.paramsDefault":"was die Daten bestimmen","fit.paramsHelp":"die anzupassenden Parameter, durch Kommas getrennt (z. B. length,g,damping,pivot); leer: was die Daten bestimmen können","fit.clear":"gemessene Bahn löschen","fit.running":"{name} wird angepasst …","fit.noPath":"(Daten ohne Bezugssystem: keine Bahn zu zeichnen)","fit.failed":"Anpassung: {why}","fit.loaded":"{name} angepasst: die angepasste Bewegung ist geladen, die gemessene Bahn golden gepunktet"},mg={length:["Länge l","Länge der Stange vom Aufhängepunkt zur Kugel"],mass:["Masse m","Masse der Kugel"],g:["Schwerebeschleunigung g","Stärke der Schwerkraft (jedes Vorzeichen; 0 erlaubt)"],damping:["Reibung (lineare Dämpfung) c","Reibungskraft −m c v, proportional zur Geschwindigkeit"],drag:["Luftwiderstand c_q","Kraft −m c_q |v| v, quadratisch in der Geschwindigkeit"],forcing_amplitude:["Antrieb: Stärke A","periodische Kraft pro Masse A cos(ω t + ψ) in Richtung e"],forcing_omega:["Antrieb: Kreisfrequenz ω","wie schnell der Antrieb schwingt"],forcing_phase:["Antrieb: Phase ψ","Phase des Antriebs bei t = 0"],forcing_x:["Antriebsrichtung e: x","x-Komponente der Antriebsrichtung (wird normiert)"],forcing_y:["Antriebsrichtung e: y","y-Komponente der Antriebsrichtung"],forcing_z:["Antriebsrichtung e: z","z-Komponente der Antriebsrichtung"],gravity_x:["Schwerkraftrichtung d: x","x-Komponente der Richtung der Schwerkraft (wird normiert)"],gravity_y:["Schwerkraftrichtung d: y","y-Komponente der Richtung der Schwerkraft"],gravity_z:["Schwerkraftrichtung d: z","z-Komponente der Richtung der Schwerkraft"],frame_rate:["Drehrate des Bezugssystems |Ω|","wie schnell sich das Bezugssystem dreht (Erde: 7,292e-5)"],latitude:["geografische Breite λ","Breite des Ortes (Foucault-Pendel)"],radius:["Auslegerradius R","Abstand des Aufhängepunkts von der Drehachse des Krans"],rate:["Drehrate des Krans ω","wie schnell sich der Ausleger dreht"],height:["Höhe des Aufhängepunkts h","Höhe des Auslegers"],amplitude:["Rüttelamplitude A","Amplitude der senkrechten Schwingung des Aufhängepunkts"],frequency:["Rüttelfrequenz ν","Kreisfrequenz der Schwingung des Aufhängepunkts"],stiffness:["Federkonstante k","Steifigkeit der Feder; die Länge l ist die entspannte Länge"],restitution:["Stoßzahl e","wie elastisch die Schnur beim Straffen zurückfedert (0 … 1)"]},gg={ideal:"Ideales Pendel",damped:"Gedämpft und angetrieben",rotating:"Auf der drehenden Erde (Foucault)",slewing:"Drehkran",vibrating:"Gerüttelter Aufhängepunkt (Kapitza)",sampled_pivot:"Aufhängepunkt auf vorgegebener Bahn",spring:"Schwingfeder",string:"Pendel an einer Schnur"},_g={"page.title":"Laboratoire Pendulab — le pendule sphérique","page.units":"unités SI, z vers le haut","page.scene":"vue 3D du pendule (glisser pour tourner, molette pour zoomer)","page.panel":"commandes et mesures","page.software":"WebGL logiciel : sans anticrénelage","conn.connected":"connecté","conn.retrying":"déconnecté : nouvel essai…","conn.gone":"Le serveur du laboratoire ne répond pas : le pendule est arrêté. pendulab serve tourne-t-il encore ? Nouvel essai de connexion …","conn.noStart":"Le laboratoire n’a pas pu démarrer :","toolbar.label":"commandes de marche","toolbar.startShort":"▶ Démarrer","toolbar.pauseShort":"Pause","toolbar.resetShort":"Revenir","toolbar.stepShort":"Pas","toolbar.recordShort":"● Filmer","toolbar.recordStopShort":"■ Arrêter","toolbar.start":"démarrer (Espace)","toolbar.pause":"pause (Espace)","toolbar.reset":"revenir au départ (R)","toolbar.step":"un pas (S)","toolbar.record":"filmer la vue (WebM)","toolbar.recordStop":"arrêter de filmer et télécharger la vidéo","toolbar.help":"raccourcis clavier et légende des couleurs (?)","toolbar.language":"langue","toolbar.collapse":"masquer le panneau","toolbar.expand":"afficher le panneau","gui.title":"Laboratoire Pendulab","gui.pendulum":"Pendule","gui.model":"modèle","gui.modelParams":"{model} : paramètres","gui.paramHelp":"{help} — clé {name} [{unit}] ; permis : {range} ; par défaut {default}","gui.integrator":"Méthode de calcul","gui.method":"méthode","gui.order":"ordre {n}","gui.symplectic":"symplectique","gui.adaptive":"adaptative","method.rk4":"Runge–Kutta, ordre 4 (classique ; quitte la sphère)","method.dop853":"Adaptative, très précise (Dormand–Prince, ordre 8)","method.rattle":"Symplectique (RATTLE, ordre 2 ; par défaut)","method.rattle4":"Symplectique (RATTLE, ordre 4)","method.rattle6":"Symplectique (RATTLE, ordre 6)","method.rattle8":"Symplectique (RATTLE, ordre 8)","method.rkmk4":"Pas de rotation sur la sphère (Munthe-Kaas, ordre 4)","method.rk4_angles":"Runge–Kutta 4 en angles (échoue aux pôles)","method.other":"{name} (ordre {n})","kind.generic":"tourne en rosace","kind.conical":"tourne à hauteur constante (pendule conique)","kind.planar":"oscille dans un plan","kind.planar_rotating":"fait des tours complets dans un plan","kind.separatrix":"monte vers le sommet sans jamais l’atteindre","kind.rest":"au repos","kind.great_circle":"parcourt un grand cercle (sans pesanteur)","data.energy":"énergie E","data.energyChange":"variation de l’énergie E − E₀","data.spin":"moment cinétique autour de la verticale J₃","data.spinChange":"sa variation J₃ − J₃(0)","data.height":"hauteur z","data.turning":"hauteurs la plus basse et la plus haute z₁, z₂","gui.dtRange":"dt doit être entre {min} et {max} s","gui.dtHelp":"pas de temps des méthodes à pas fixe ; {min} … {max} s (dop853 choisit le sien)","gui.run":"Marche","gui.timeScale":"échelle de temps [×]","gui.tsRange":"l’échelle de temps doit être entre {min} et {max}","gui.tsHelp":"secondes simulées par seconde (ralenti en dessous de 1) ; {min} … {max}","gui.stepN":"pas par clic","gui.scenario":"scénario","gui.view":"Vue","gui.trail":"trace","gui.trailSeconds":"trace [s]","gui.sphere":"sphère atteignable","gui.axes":"axes","gui.topView":"vue de dessus","gui.stereo":"stéréo","gui.stereoHelp":"anaglyphe : lunettes rouge–cyan ; côte à côte : visionneuse stéréo","stereo.off":"non","stereo.anaglyph":"anaglyphe (rouge–cyan)","stereo.sideBySide":"côte à côte","gui.vectors":"Vecteurs","gui.origin":"origine {axis} [m]","gui.originHelp":"origine de L et τ par rapport au point de suspension (0 : le point de suspension)","gui.export":"Partager et exporter","gui.csv":"télécharger la trajectoire (CSV)","gui.toml":"télécharger le scénario (TOML)","gui.tomlHelp":"le scénario tel qu’il est (modèle, paramètres, départ, méthode) en fichier pour `pendulab run`","gui.png":"capture d’écran (PNG)","gui.link":"copier le lien vers ce scénario","vec.velocity":"vitesse v","vec.velocityHelp":"v [m/s], dessinée comme 0,25 s de trajet","vec.momentum":"quantité de mouvement m v","vec.momentumHelp":"m v [kg m/s], 0,25 m par kg m/s","vec.gravity":"poids m g","vec.gravityHelp":"le poids m g d [N] (d : direction de la pesanteur) ; forces : m·max(|g|, 1) N ↔ 0,5 l","vec.tension":"force de la tige (tension)","vec.tensionHelp":"la force de la tige −T x/|x| [N], T venant du serveur","vec.net":"force résultante m a","vec.netHelp":"m a [N] : a = ẍ calculée par le cœur du serveur (par rapport au point de suspension)","vec.angularMomentum":"moment cinétique L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] par rapport à l’origine o, dessiné depuis o","vec.torque":"moment de force τ","vec.torqueHelp":"τ = (x − o) × m a [N m] par rapport à l’origine o, dessiné depuis o ; dL/dt = τ","data.now":"Maintenant (du serveur)","data.exact":"Solution exacte de cette orbite","data.tension":"tension","data.tensionMin":"tension min","data.tensionMax":"tension max","data.method":"méthode","data.state":"état","data.paused":"en pause","data.running":"en marche","data.lagging":" (en retard : plus lent que demandé)","data.model":"modèle","data.kind":"type de mouvement","data.periodZ":"du point le plus bas au suivant T_z","data.swingPeriod":"période d’oscillation T","data.advance":"rotation entre deux points les plus bas Δφ","data.rotation":"nombre de rotation W = Δφ/2π","data.reduced":"vue réduite (σ₁, σ₂, σ₃) : surface J₃ ∩ plan d’énergie","portrait.phase":"portrait de phase : vitesse verticale ż selon la hauteur z","portrait.veff":"potentiel effectif V_eff(θ) ; énergie E en tirets, θ actuel en pointillés","portrait.em":"carte énergie–moment : E selon J₃ (point : maintenant)","portrait.orbit":"orbite","portrait.emBoundary":"bord (orbites coniques)","note.spring":"le ressort quitte la sphère (sa longueur varie) : V_eff, la carte énergie–moment, la vue réduite et la solution exacte sont celles du pendule à tige et ne sont pas affichées","note.string":"le fil se détend (vol libre dans la sphère) : V_eff, la carte énergie–moment, la vue réduite et la solution exacte sont celles du pendule à tige et ne sont pas affichées","note.exactIdeal":"la solution exacte n’existe que pour le pendule idéal ; ceci est le modèle {model}","note.reducedIdeal":"la vue réduite est celle du pendule idéal ; ceci est le modèle {model}","event.slack":"le fil s’est détendu (tension 0 : vol libre)","event.taut":"le fil s’est tendu d’un coup, {lost} J perdus","event.skippedOne":" ({n} événement antérieur de cet instant non affiché)","event.skippedMany":" ({n} événements antérieurs de cet instant non affichés)","event.slackRow":"détendu","event.tautRow":"tendu d’un coup","event.tautValue":"t = {t} s, perdu {lost}","data.power":"puissance P = dE/dt","data.springForce":"force du ressort k(|r| − l₀)","data.springLength":"longueur du ressort |r|","data.stretch":"allongement |r| − l₀","data.string":"fil","data.slackZero":"détendu (0)","data.slack":"détendu : vol libre, |x| = {r} m","data.taut":"tendu","data.events":"événements","data.noEvents":"aucun pour l’instant (détentes, à-coups)","data.z3":"z₃ (hors de la sphère)","data.dynamic":"Δφ dynamique","data.geometric":"Δφ géométrique","data.error":"erreur de position |Δx|","data.errorRel":"erreur de position / l","data.errorHow":"erreur obtenue par","data.errorPaused":"estimation en pause (le budget de calcul du serveur est épuisé ; elle rattrape quand il y a du temps)","data.errorNone":"pas d’estimation","data.howExact":"l’erreur vraie : comparée à la solution exacte (depuis t = {since} s)","data.howRichardson":"estimation : Richardson avec un calcul compagnon à dt/2 = {dt} s, ordre p = {p} (depuis t = {since} s)","data.howCompanion":"estimation : un calcul compagnon à rtol = {rtol} (depuis t = {since} s)","page.softwareHelp":"{renderer} : dessiné sans multiéchantillonnage pour la fluidité","tools.start":"Angle de départ","tools.thetaHelp":"θ₀ : l’angle avec la verticale vers le bas, en degrés (0 … 180)","tools.phiHelp":"φ₀ : l’azimut autour de la verticale, en degrés","tools.phiDotHelp":"φ̇₀ : à quelle vitesse la masse commence à tourner, en degrés par seconde (0 : une oscillation plane)","tools.setStart":"fixer le départ","tools.world":"Pesanteur et frottement","tools.gravity":"pesanteur","tools.friction":"frottement","tools.frictionHelp":"amortissement linéaire c [1/s] : la force −m c v ; sur le pendule idéal, passe au modèle amorti","tools.noFriction":"le modèle {model} n’a pas de paramètre de frottement","tools.now":"Angles maintenant","tools.stopwatch":"Chronomètre (temps simulé)","tools.swStart":"démarrer","tools.swStop":"arrêter","tools.swLap":"tour","tools.swReset":"remettre à zéro","tools.period":"Mesure de la période","tools.periodHelp":"mesurée sur le mouvement : les points les plus bas de la masse ; une période d’oscillation se termine quand la masse repasse en bas dans le même sens. Comparée à la valeur exacte (pendule idéal) ou à la théorie (formule des petites oscillations avec frottement)","tools.periodCount":"moyenne sur {n} périodes","tools.periodCountZ":"moyenne sur {n} passages d’un point le plus bas au suivant","tools.periodWait":"attend que la masse passe deux fois par son point le plus bas","tools.motion":"mouvement","tools.kindNone":"—","tools.kindSwing":"oscille d’avant en arrière","tools.kindOver":"fait des tours complets","tools.kindOrbit":"tourne (ne passe jamais par le bas)","tools.periodSwing":"période T [s]","tools.periodZ":"d’un point le plus bas au suivant [s]","tools.advance":"rotation entre deux points les plus bas [°]","tools.precession":"la figure tourne par tour de [°]","tools.amplitude":"amplitude (plus grand angle) [°]","tools.band":"angle avec la verticale [°]","tools.theory":"théorie","tools.measured":"mesuré","tools.exact":"exact","tools.difference":"écart","tools.overlays":"Règle et rapporteur","tools.ruler":"règle (mètres)","tools.protractor":"rapporteur (θ en degrés)","start.notNumber":"{name} doit être un nombre","start.thetaRange":"θ₀ = {value}° n’est pas permis : 0 … 180°","gravity.custom":"autre","gravity.earth":"Terre","gravity.moon":"Lune","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"nulle","gravity.negative":"négative (vers le haut)","energy.title":"Énergie","energy.kinetic":"cinétique","energy.potential":"potentielle","energy.lost":"perdue","energy.total":"totale","plot.dE":"dérive de l’énergie |ΔE|/E_s (log)","plot.dJ3":"dérive de J₃ |ΔJ₃|/J_s (log)","plot.z":"hauteur z(t)","plot.tension":"tension de la tige T(t)","plot.time":"temps t [s]","plot.floor":"arrondi float64 2,2e-16","chosen.title":"Tracer des grandeurs au choix","chosen.xAxis":"en abscisse","chosen.yAxis":"en ordonnée","var.t":"temps t","var.theta":"angle θ","var.phi":"azimut φ","var.x":"x","var.y":"y","var.z":"hauteur z","var.zdot":"vitesse verticale ż","var.speed":"vitesse |v|","var.energy":"énergie E","var.kinetic":"énergie cinétique K","var.potential":"énergie potentielle U","var.j3":"moment cinétique J₃","var.tension":"tension T","var.power":"puissance P","var.radius":"distance |x|","twin.title":"Deux pendules","twin.mode":"second pendule","twin.off":"aucun","twin.epsilon":"départ différent de ε","twin.method":"une autre méthode de calcul","twin.damped":"amorti à côté de celui-ci","twin.own":"sa propre longueur, masse et départ (côte à côte)","twin.length":"l₂ [m]","twin.mass":"m₂ [kg]","twin.theta":"θ₀₂ [°]","twin.badOwn":"le second pendule demande une longueur > 0, une masse > 0 et un angle de départ 0 … 180°","twin.colLength":"l [m]","twin.colMass":"m [kg]","twin.colTheta":"θ₀ [°]","twin.colPeriod":"période T [s] (périodes)","twin.methodPick":"méthode","twin.damping":"amortissement [1/s]","twin.start":"démarrer les deux","twin.bad":"ε doit être un nombre et l’amortissement ≥ 0","twin.first":"pendule 1","twin.second":"pendule 2","twin.separation":"distance entre les masses |r₁ − r₂| [m]","help.title":"Raccourcis clavier et légende des couleurs","help.space":"démarrer / pause","help.r":"revenir au départ","help.s":"un pas (en pause)","help.arrows":"sur un curseur sélectionné : un pas vers le bas / le haut","help.page":"sur un curseur sélectionné : dix pas","help.tab":"passer d’une commande à l’autre","help.help":"cette fenêtre","help.esc":"fermer cette fenêtre","help.colours":"Couleurs","help.close":"fermer","help.bob":"masse","help.trail":"trace","help.twin":"second pendule","help.ruler":"règle et rapporteur","msg.notConnected":"pas de connexion au serveur","msg.linkCopied":"lien copié : il reproduit ce scénario","msg.dragged":"départ fixé en glissant (au repos à cet endroit) : appuyer sur démarrer pour le lâcher","msg.pull":"tirer la flèche pour fixer la vitesse de départ","msg.capped":" (limitée : le maximum de la flèche, 4√(g l))","msg.velocitySet":"vitesse de départ fixée : |v| = {v} m/s{cap} ; appuyer sur démarrer pour partir de là","msg.velocity":"vitesse de départ |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} n’est pas permis : {allowed} ({range})","msg.recording":"la vue est filmée…","msg.recorded":"vidéo enregistrée ({mb} Mo, WebM)","msg.noRecording":"ce navigateur ne peut pas filmer la vue ({why})","fit.title":"Données mesurées","fit.load":"Charger des mesures…","fit.help":"un fichier CSV de mesures en unités SI (colonnes t, x, y, z ou x, z ; theta, phi ; angle ; specific_force ; angular_speed — docs/fit.md) : le serveur y ajuste le pendule, charge le mouvement ajusté et dessine le chemin mesuré en pointillés à côté","fit.model":"modèle","fit.params":"ajuster","fit.paramsDefault":"ce que les données déterminent","fit.paramsHelp":"les paramètres à ajuster, séparés par des virgules (p. ex. length,g,damping,pivot) ; vide : ce que les données peuvent déterminer","fit.clear":"effacer le chemin mesuré","fit.running":"ajustement de {name} …","fit.noPath":"(données sans repère : pas de chemin mesuré à dessiner)","fit.failed":"ajustement : {why}","fit.loaded":"{name} ajusté : le mouvement ajusté est chargé, le chemin mesuré en pointillés dorés"},vg={length:["longueur l","longueur de la tige du point de suspension à la masse"],mass:["masse m","masse de la boule"],g:["pesanteur g","intensité de la pesanteur (tout signe ; 0 permis)"],damping:["frottement (amortissement linéaire) c","force de frottement −m c v, proportionnelle à la vitesse"],drag:["résistance de l’air c_q","force −m c_q |v| v, quadratique en vitesse"],forcing_amplitude:["forçage : intensité A","force périodique par masse A cos(ω t + ψ) dans la direction e"],forcing_omega:["forçage : pulsation ω","à quelle vitesse le forçage oscille"],forcing_phase:["forçage : phase ψ","phase du forçage à t = 0"],forcing_x:["direction du forçage e : x","composante x de la direction du forçage (normalisée)"],forcing_y:["direction du forçage e : y","composante y de la direction du forçage"],forcing_z:["direction du forçage e : z","composante z de la direction du forçage"],gravity_x:["direction de la pesanteur d : x","composante x de la direction de la pesanteur (normalisée)"],gravity_y:["direction de la pesanteur d : y","composante y de la direction de la pesanteur"],gravity_z:["direction de la pesanteur d : z","composante z de la direction de la pesanteur"],frame_rate:["vitesse de rotation du référentiel |Ω|","à quelle vitesse tourne le référentiel (Terre : 7,292e-5)"],latitude:["latitude λ","latitude du lieu (pendule de Foucault)"],radius:["rayon de la flèche R","distance du point de suspension à l’axe de rotation de la grue"],rate:["vitesse de rotation de la grue ω","à quelle vitesse tourne la flèche"],height:["hauteur du point de suspension h","hauteur de la flèche"],amplitude:["amplitude de vibration A","amplitude de l’oscillation verticale du point de suspension"],frequency:["fréquence de vibration ν","pulsation de l’oscillation du point de suspension"],stiffness:["raideur du ressort k","raideur du ressort ; la longueur l est la longueur au repos"],restitution:["coefficient de restitution e","élasticité du fil quand il se tend d’un coup (0 … 1)"]},xg={ideal:"Pendule idéal",damped:"Amorti et forcé",rotating:"Sur la Terre qui tourne (Foucault)",slewing:"Grue pivotante",vibrating:"Point de suspension vibrant (Kapitza)",sampled_pivot:"Point de suspension sur un chemin donné",spring:"Ressort oscillant",string:"Pendule à fil"},Oa={en:{name:"English",words:il,params:{},models:{}},de:{name:"Deutsch",words:pg,params:mg,models:gg},fr:{name:"Français",words:_g,params:vg,models:xg}};let ka="en";function Pl(i){return typeof i=="string"&&Object.hasOwn(Oa,i)}function Sg(i,e,t){if(Pl(i))return i;if(Pl(e))return e;for(const n of t){const s=n.toLowerCase().split("-")[0];if(Pl(s))return s}return"en"}function Mg(i){ka=i}function yg(){return ka}function N(i,e={}){return(Oa[ka].words[i]??il[i]).replace(/\{(\w+)\}/g,(s,r)=>r in e?String(e[r]):s)}function bg(i,e,t){return Oa[ka].params[i]??[e,t]}function Uh(i,e){return Oa[ka].models[i]??e}function Go(i,e){const t=`method.${i}`;return Object.hasOwn(il,t)?N(t):N("method.other",{name:i,n:e})}function wg(i){const e=`kind.${i}`;return Object.hasOwn(il,e)?N(e):i}const Eg=["spring","string"];function Tg(i){return!Eg.includes(i??"ideal")}function Fh(i){return i==="spring"?N("note.spring"):i==="string"?N("note.string"):null}function Zf(i,e){return i==="spring"?"coil":i==="string"?e?"taut string":"slack string":"rod"}function pt(i,e=6){if(i==null||Number.isNaN(i))return"—";if(!Number.isFinite(i))return i>0?"∞":"−∞";if(i===0)return"0";const t=Math.abs(i);return t>=.001&&t<1e6?i.toPrecision(e):i.toExponential(e-1)}const Ag=5;function Rg(i){const e=i.kind==="slack"?N("event.slack"):N("event.taut",{lost:pt(i.energy_lost,3)}),t=i.skipped>0?N(i.skipped>1?"event.skippedMany":"event.skippedOne",{n:i.skipped}):"";return`t = ${i.t.toFixed(3)} s: ${e}${t}`}function Cg(i){return i.kind==="slack"?[N("event.slackRow"),`t = ${pt(i.t,6)} s`,""]:[N("event.tautRow"),N("event.tautValue",{t:pt(i.t,6),lost:pt(i.energy_lost,4)}),"J"]}function Pg(i,e,t,n=Ag){if(t===null||e.epoch!==t)return i;const s=[...i,e];return s.length>n?s.slice(s.length-n):s}function Lg(i,e){const t=e.reference,n=e.status,s=e.tensionExtremes,r=[["t",pt(i?.t,7),"s"],[N("data.energy"),pt(i?.energy,10),"J"],[N("data.energyChange"),i&&t?pt(i.energy-t.energy,3):"—","J"],[N("data.spin"),pt(i?.j3,10),"kg m²/s"],[N("data.spinChange"),i&&t?pt(i.j3-t.j3,3):"—","kg m²/s"],[N("data.tension"),pt(i?.tension,6),"N"],[N("data.tensionMin"),s?`${pt(s.min,6)} (t = ${pt(s.tMin,4)} s)`:"—","N"],[N("data.tensionMax"),s?`${pt(s.max,6)} (t = ${pt(s.tMax,4)} s)`:"—","N"],[N("data.height"),pt(i?.x[2],6),"m"],[N("data.method"),n?`${Go(n.method,0)}${n.adaptive?"":`, dt = ${n.dt} s`}`:"—",""],[N("data.state"),n?`${n.paused?N("data.paused"):N("data.running")}${n.lagging?N("data.lagging"):""}`:"—",""],...Dg(i,n)];n&&n.model!=="ideal"&&(r.splice(1,0,[N("data.model"),Uh(n.model,n.model),""]),r.splice(4,0,[N("data.power"),pt(i?.power,6),"W"]));const a=r.findIndex(l=>l[0]===N("data.tension")),o=Zf(n?.model,i?.taut??!0);if(o==="coil"&&n){const l=i?Math.hypot(...i.x):null;r[a]=[N("data.springForce"),pt(i?.tension,6),"N"],r.splice(a+1,0,[N("data.springLength"),pt(l,6),"m"],[N("data.stretch"),l===null?"—":pt(l-n.params.length,4),"m"])}else o==="slack string"?(r[a]=[N("data.tension"),N("data.slackZero"),"N"],r.splice(a+1,0,[N("data.string"),N("data.slack",{r:pt(i?Math.hypot(...i.x):null,5)}),""])):o==="taut string"&&r.splice(a+1,0,[N("data.string"),N("data.taut"),""]);if(n?.model==="string"){const l=[...e.events].reverse().map(Cg);r.push(...l.length>0?l:[[N("data.events"),N("data.noEvents"),""]])}return r}function Dg(i,e){const t=e?.error_estimate;if(!e||!t)return[];if(t.how===null)return[[N("data.errorHow"),t.note??N("data.errorNone"),""]];const n=pt(t.since,6),s=t.how==="exact"?N("data.howExact",{since:n}):t.how==="richardson"?N("data.howRichardson",{dt:pt(t.reference.dt,3),p:t.order??"?",since:n}):N("data.howCompanion",{rtol:pt(t.reference.rtol,3),since:n}),r=i?.errorX,a=r!==void 0&&r>=0;return[[N("data.error"),a?pt(r,3):r===void 0?"—":N("data.errorPaused"),a?"m":""],[N("data.errorRel"),a?pt(r/e.params.length,3):"—",""],[N("data.errorHow"),s,""]]}function Ng(i){const e=i.status,t=Fh(e?.model);return t!==null?t:e&&e.model!=="ideal"?N("note.exactIdeal",{model:e.model}):i.exactError??i.exact?.phases_note??""}function Ig(i){if(i===null)return[];const e=i.turning_heights,t=[[N("data.kind"),wg(i.kind),""],[N("data.turning"),`${pt(e[0])}, ${pt(e[1])}`,"m"]];return e.length>2&&t.push([N("data.z3"),pt(e[2]),"m"]),t.push([i.kind==="planar"?N("data.swingPeriod"):N("data.periodZ"),i.period_z_infinite?"∞":pt(i.period_z),"s"]),i.azimuth_advance!==null&&t.push([N("data.advance"),pt(i.azimuth_advance),"rad"]),i.rotation_number!==null&&t.push([N("data.rotation"),pt(i.rotation_number),""]),i.phases!==null&&(t.push([N("data.dynamic"),pt(i.phases.dynamic),"rad"]),t.push([N("data.geometric"),pt(i.phases.geometric),"rad"])),t}class Ug{live;exactTable;note;constructor(e){const t=n=>{const s=document.createElement("h3");s.textContent=n,e.appendChild(s)};t(N("data.now")),this.live=document.createElement("table"),e.appendChild(this.live),t(N("data.exact")),this.exactTable=document.createElement("table"),e.appendChild(this.exactTable),this.note=document.createElement("p"),this.note.className="note",e.appendChild(this.note)}fill(e,t){for(;e.rows.length>t.length;)e.deleteRow(-1);t.forEach(([n,s,r],a)=>{const o=e.rows[a]??e.insertRow();for(;o.cells.length<3;)o.insertCell();const[l,c,h]=[o.cells[0],o.cells[1],o.cells[2]];l&&l.textContent!==n&&(l.textContent=n),c&&c.textContent!==s&&(c.textContent=s),h&&h.textContent!==r&&(h.textContent=r)})}update(e,t){this.fill(this.live,Lg(e,t)),this.fill(this.exactTable,Ig(t.exact));const n=Ng(t);this.note.textContent!==n&&(this.note.textContent=n)}}class Xi{constructor(e,t,n,s,r="div"){this.parent=e,this.object=t,this.property=n,this._disabled=!1,this._hidden=!1,this.initialValue=this.getValue(),this.domElement=document.createElement(r),this.domElement.classList.add("lil-controller"),this.domElement.classList.add(s),this.$name=document.createElement("div"),this.$name.classList.add("lil-name"),Xi.nextNameID=Xi.nextNameID||0,this.$name.id=`lil-gui-name-${++Xi.nextNameID}`,this.$widget=document.createElement("div"),this.$widget.classList.add("lil-widget"),this.$disable=this.$widget,this.domElement.appendChild(this.$name),this.domElement.appendChild(this.$widget),this.domElement.addEventListener("keydown",a=>a.stopPropagation()),this.domElement.addEventListener("keyup",a=>a.stopPropagation()),this.parent.children.push(this),this.parent.controllers.push(this),this.parent.$children.appendChild(this.domElement),this._listenCallback=this._listenCallback.bind(this),this.name(n)}name(e){return this._name=e,this.$name.textContent=e,this}onChange(e){return this._onChange=e,this}_callOnChange(){this.parent._callOnChange(this),this._onChange!==void 0&&this._onChange.call(this,this.getValue()),this._changed=!0}onFinishChange(e){return this._onFinishChange=e,this}_callOnFinishChange(){this._changed&&(this.parent._callOnFinishChange(this),this._onFinishChange!==void 0&&this._onFinishChange.call(this,this.getValue())),this._changed=!1}reset(){return this.setValue(this.initialValue),this._callOnFinishChange(),this}enable(e=!0){return this.disable(!e)}disable(e=!0){return e===this._disabled?this:(this._disabled=e,this.domElement.classList.toggle("lil-disabled",e),this.$disable.toggleAttribute("disabled",e),this)}show(e=!0){return this._hidden=!e,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}options(e){const t=this.parent.add(this.object,this.property,e);return t.name(this._name),this.destroy(),t}min(e){return this}max(e){return this}step(e){return this}decimals(e){return this}listen(e=!0){return this._listening=e,this._listenCallbackID!==void 0&&(cancelAnimationFrame(this._listenCallbackID),this._listenCallbackID=void 0),this._listening&&this._listenCallback(),this}_listenCallback(){this._listenCallbackID=requestAnimationFrame(this._listenCallback);const e=this.save();e!==this._listenPrevValue&&this.updateDisplay(),this._listenPrevValue=e}getValue(){return this.object[this.property]}setValue(e){return this.getValue()!==e&&(this.object[this.property]=e,this._callOnChange(),this.updateDisplay()),this}updateDisplay(){return this}load(e){return this.setValue(e),this._callOnFinishChange(),this}save(){return this.getValue()}destroy(){this.listen(!1),this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.controllers.splice(this.parent.controllers.indexOf(this),1),this.parent.$children.removeChild(this.domElement)}}class Fg extends Xi{constructor(e,t,n){super(e,t,n,"lil-boolean","label"),this.$input=document.createElement("input"),this.$input.setAttribute("type","checkbox"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$widget.appendChild(this.$input),this.$input.addEventListener("change",()=>{this.setValue(this.$input.checked),this._callOnFinishChange()}),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.checked=this.getValue(),this}}function Ec(i){let e,t;return(e=i.match(/(#|0x)?([a-f0-9]{6})/i))?t=e[2]:(e=i.match(/rgb\(\s*(\d*)\s*,\s*(\d*)\s*,\s*(\d*)\s*\)/))?t=parseInt(e[1]).toString(16).padStart(2,0)+parseInt(e[2]).toString(16).padStart(2,0)+parseInt(e[3]).toString(16).padStart(2,0):(e=i.match(/^#?([a-f0-9])([a-f0-9])([a-f0-9])$/i))&&(t=e[1]+e[1]+e[2]+e[2]+e[3]+e[3]),t?"#"+t:!1}const Og={isPrimitive:!0,match:i=>typeof i=="string",fromHexString:Ec,toHexString:Ec},Ra={isPrimitive:!0,match:i=>typeof i=="number",fromHexString:i=>parseInt(i.substring(1),16),toHexString:i=>"#"+i.toString(16).padStart(6,0)},kg={isPrimitive:!1,match:i=>Array.isArray(i)||ArrayBuffer.isView(i),fromHexString(i,e,t=1){const n=Ra.fromHexString(i);e[0]=(n>>16&255)/255*t,e[1]=(n>>8&255)/255*t,e[2]=(n&255)/255*t},toHexString([i,e,t],n=1){n=255/n;const s=i*n<<16^e*n<<8^t*n<<0;return Ra.toHexString(s)}},Bg={isPrimitive:!1,match:i=>Object(i)===i,fromHexString(i,e,t=1){const n=Ra.fromHexString(i);e.r=(n>>16&255)/255*t,e.g=(n>>8&255)/255*t,e.b=(n&255)/255*t},toHexString({r:i,g:e,b:t},n=1){n=255/n;const s=i*n<<16^e*n<<8^t*n<<0;return Ra.toHexString(s)}},zg=[Og,Ra,kg,Bg];function Hg(i){return zg.find(e=>e.match(i))}class Vg extends Xi{constructor(e,t,n,s){super(e,t,n,"lil-color"),this.$input=document.createElement("input"),this.$input.setAttribute("type","color"),this.$input.setAttribute("tabindex",-1),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$text=document.createElement("input"),this.$text.setAttribute("type","text"),this.$text.setAttribute("spellcheck","false"),this.$text.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$display.appendChild(this.$input),this.$widget.appendChild(this.$display),this.$widget.appendChild(this.$text),this._format=Hg(this.initialValue),this._rgbScale=s,this._initialValueHexString=this.save(),this._textFocused=!1,this.$input.addEventListener("input",()=>{this._setValueFromHexString(this.$input.value)}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$text.addEventListener("input",()=>{const r=Ec(this.$text.value);r&&this._setValueFromHexString(r)}),this.$text.addEventListener("focus",()=>{this._textFocused=!0,this.$text.select()}),this.$text.addEventListener("blur",()=>{this._textFocused=!1,this.updateDisplay(),this._callOnFinishChange()}),this.$disable=this.$text,this.updateDisplay()}reset(){return this._setValueFromHexString(this._initialValueHexString),this}_setValueFromHexString(e){if(this._format.isPrimitive){const t=this._format.fromHexString(e);this.setValue(t)}else this._format.fromHexString(e,this.getValue(),this._rgbScale),this._callOnChange(),this.updateDisplay()}save(){return this._format.toHexString(this.getValue(),this._rgbScale)}load(e){return this._setValueFromHexString(e),this._callOnFinishChange(),this}updateDisplay(){return this.$input.value=this._format.toHexString(this.getValue(),this._rgbScale),this._textFocused||(this.$text.value=this.$input.value.substring(1)),this.$display.style.backgroundColor=this.$input.value,this}}class Ll extends Xi{constructor(e,t,n){super(e,t,n,"lil-function"),this.$button=document.createElement("button"),this.$button.appendChild(this.$name),this.$widget.appendChild(this.$button),this.$button.addEventListener("click",s=>{s.preventDefault(),this.getValue().call(this.object),this._callOnChange()}),this.$button.addEventListener("touchstart",()=>{},{passive:!0}),this.$disable=this.$button}}class Gg extends Xi{constructor(e,t,n,s,r,a){super(e,t,n,"lil-number"),this._initInput(),this.min(s),this.max(r);const o=a!==void 0;this.step(o?a:this._getImplicitStep(),o),this.updateDisplay()}decimals(e){return this._decimals=e,this.updateDisplay(),this}min(e){return this._min=e,this._onUpdateMinMax(),this}max(e){return this._max=e,this._onUpdateMinMax(),this}step(e,t=!0){return this._step=e,this._stepExplicit=t,this}updateDisplay(){const e=this.getValue();if(this._hasSlider){let t=(e-this._min)/(this._max-this._min);t=Math.max(0,Math.min(t,1)),this.$fill.style.width=t*100+"%"}return this._inputFocused||(this.$input.value=this._decimals===void 0?e:e.toFixed(this._decimals)),this}_initInput(){this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("aria-labelledby",this.$name.id),window.matchMedia("(pointer: coarse)").matches&&(this.$input.setAttribute("type","number"),this.$input.setAttribute("step","any")),this.$widget.appendChild(this.$input),this.$disable=this.$input;const t=()=>{let x=parseFloat(this.$input.value);isNaN(x)||(this._stepExplicit&&(x=this._snap(x)),this.setValue(this._clamp(x)))},n=x=>{const A=parseFloat(this.$input.value);isNaN(A)||(this._snapClampSetValue(A+x),this.$input.value=this.getValue())},s=x=>{x.key==="Enter"&&this.$input.blur(),x.code==="ArrowUp"&&(x.preventDefault(),n(this._step*this._arrowKeyMultiplier(x))),x.code==="ArrowDown"&&(x.preventDefault(),n(this._step*this._arrowKeyMultiplier(x)*-1))},r=x=>{this._inputFocused&&(x.preventDefault(),n(this._step*this._normalizeMouseWheel(x)))};let a=!1,o,l,c,h,u;const d=5,m=x=>{o=x.clientX,l=c=x.clientY,a=!0,h=this.getValue(),u=0,window.addEventListener("mousemove",_),window.addEventListener("mouseup",M)},_=x=>{if(a){const A=x.clientX-o,S=x.clientY-l;Math.abs(S)>d?(x.preventDefault(),this.$input.blur(),a=!1,this._setDraggingStyle(!0,"vertical")):Math.abs(A)>d&&M()}if(!a){const A=x.clientY-c;u-=A*this._step*this._arrowKeyMultiplier(x),h+u>this._max?u=this._max-h:h+u<this._min&&(u=this._min-h),this._snapClampSetValue(h+u)}c=x.clientY},M=()=>{this._setDraggingStyle(!1,"vertical"),this._callOnFinishChange(),window.removeEventListener("mousemove",_),window.removeEventListener("mouseup",M)},p=()=>{this._inputFocused=!0},f=()=>{this._inputFocused=!1,this.updateDisplay(),this._callOnFinishChange()};this.$input.addEventListener("input",t),this.$input.addEventListener("keydown",s),this.$input.addEventListener("wheel",r,{passive:!1}),this.$input.addEventListener("mousedown",m),this.$input.addEventListener("focus",p),this.$input.addEventListener("blur",f)}_initSlider(){this._hasSlider=!0,this.$slider=document.createElement("div"),this.$slider.classList.add("lil-slider"),this.$fill=document.createElement("div"),this.$fill.classList.add("lil-fill"),this.$slider.appendChild(this.$fill),this.$widget.insertBefore(this.$slider,this.$input),this.domElement.classList.add("lil-has-slider");const e=(f,x,A,S,R)=>(f-x)/(A-x)*(R-S)+S,t=f=>{const x=this.$slider.getBoundingClientRect();let A=e(f,x.left,x.right,this._min,this._max);this._snapClampSetValue(A)},n=f=>{this._setDraggingStyle(!0),t(f.clientX),window.addEventListener("mousemove",s),window.addEventListener("mouseup",r)},s=f=>{t(f.clientX)},r=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("mousemove",s),window.removeEventListener("mouseup",r)};let a=!1,o,l;const c=f=>{f.preventDefault(),this._setDraggingStyle(!0),t(f.touches[0].clientX),a=!1},h=f=>{f.touches.length>1||(this._hasScrollBar?(o=f.touches[0].clientX,l=f.touches[0].clientY,a=!0):c(f),window.addEventListener("touchmove",u,{passive:!1}),window.addEventListener("touchend",d))},u=f=>{if(a){const x=f.touches[0].clientX-o,A=f.touches[0].clientY-l;Math.abs(x)>Math.abs(A)?c(f):(window.removeEventListener("touchmove",u),window.removeEventListener("touchend",d))}else f.preventDefault(),t(f.touches[0].clientX)},d=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("touchmove",u),window.removeEventListener("touchend",d)},m=this._callOnFinishChange.bind(this),_=400;let M;const p=f=>{if(Math.abs(f.deltaX)<Math.abs(f.deltaY)&&this._hasScrollBar)return;f.preventDefault();const A=this._normalizeMouseWheel(f)*this._step;this._snapClampSetValue(this.getValue()+A),this.$input.value=this.getValue(),clearTimeout(M),M=setTimeout(m,_)};this.$slider.addEventListener("mousedown",n),this.$slider.addEventListener("touchstart",h,{passive:!1}),this.$slider.addEventListener("wheel",p,{passive:!1})}_setDraggingStyle(e,t="horizontal"){this.$slider&&this.$slider.classList.toggle("lil-active",e),document.body.classList.toggle("lil-dragging",e),document.body.classList.toggle(`lil-${t}`,e)}_getImplicitStep(){return this._hasMin&&this._hasMax?(this._max-this._min)/1e3:.1}_onUpdateMinMax(){!this._hasSlider&&this._hasMin&&this._hasMax&&(this._stepExplicit||this.step(this._getImplicitStep(),!1),this._initSlider(),this.updateDisplay())}_normalizeMouseWheel(e){let{deltaX:t,deltaY:n}=e;return Math.floor(e.deltaY)!==e.deltaY&&e.wheelDelta&&(t=0,n=-e.wheelDelta/120,n*=this._stepExplicit?1:10),t+-n}_arrowKeyMultiplier(e){let t=this._stepExplicit?1:10;return e.shiftKey?t*=10:e.altKey&&(t/=10),t}_snap(e){let t=0;return this._hasMin?t=this._min:this._hasMax&&(t=this._max),e-=t,e=Math.round(e/this._step)*this._step,e+=t,e=parseFloat(e.toPrecision(15)),e}_clamp(e){return e<this._min&&(e=this._min),e>this._max&&(e=this._max),e}_snapClampSetValue(e){this.setValue(this._clamp(this._snap(e)))}get _hasScrollBar(){const e=this.parent.root.$children;return e.scrollHeight>e.clientHeight}get _hasMin(){return this._min!==void 0}get _hasMax(){return this._max!==void 0}}class Wg extends Xi{constructor(e,t,n,s){super(e,t,n,"lil-option"),this.$select=document.createElement("select"),this.$select.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$select.addEventListener("change",()=>{this.setValue(this._values[this.$select.selectedIndex]),this._callOnFinishChange()}),this.$select.addEventListener("focus",()=>{this.$display.classList.add("lil-focus")}),this.$select.addEventListener("blur",()=>{this.$display.classList.remove("lil-focus")}),this.$widget.appendChild(this.$select),this.$widget.appendChild(this.$display),this.$disable=this.$select,this.options(s)}options(e){return this._values=Array.isArray(e)?e:Object.values(e),this._names=Array.isArray(e)?e:Object.keys(e),this.$select.replaceChildren(),this._names.forEach(t=>{const n=document.createElement("option");n.textContent=t,this.$select.appendChild(n)}),this.updateDisplay(),this}updateDisplay(){const e=this.getValue(),t=this._values.indexOf(e);return this.$select.selectedIndex=t,this.$display.textContent=t===-1?e:this._names[t],this}}class Xg extends Xi{constructor(e,t,n){super(e,t,n,"lil-string"),this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("spellcheck","false"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$input.addEventListener("input",()=>{this.setValue(this.$input.value)}),this.$input.addEventListener("keydown",s=>{s.code==="Enter"&&this.$input.blur()}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$widget.appendChild(this.$input),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.value=this.getValue(),this}}var $g=`.lil-gui {
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
}`;function qg(i){const e=document.createElement("style");e.innerHTML=i;const t=document.querySelector("head link[rel=stylesheet], head style");t?document.head.insertBefore(e,t):document.head.appendChild(e)}let Fu=!1;class Oh{constructor({parent:e,autoPlace:t=e===void 0,container:n,width:s,title:r="Controls",closeFolders:a=!1,injectStyles:o=!0,touchStyles:l=!0}={}){if(this.parent=e,this.root=e?e.root:this,this.children=[],this.controllers=[],this.folders=[],this._closed=!1,this._hidden=!1,this.domElement=document.createElement("div"),this.domElement.classList.add("lil-gui"),this.$title=document.createElement("button"),this.$title.classList.add("lil-title"),this.$title.setAttribute("aria-expanded",!0),this.$title.addEventListener("click",()=>this.openAnimated(this._closed)),this.$title.addEventListener("touchstart",()=>{},{passive:!0}),this.$children=document.createElement("div"),this.$children.classList.add("lil-children"),this.domElement.appendChild(this.$title),this.domElement.appendChild(this.$children),this.title(r),this.parent){this.parent.children.push(this),this.parent.folders.push(this),this.parent.$children.appendChild(this.domElement);return}this.domElement.classList.add("lil-root"),l&&this.domElement.classList.add("lil-allow-touch-styles"),!Fu&&o&&(qg($g),Fu=!0),n?n.appendChild(this.domElement):t&&(this.domElement.classList.add("lil-auto-place","autoPlace"),document.body.appendChild(this.domElement)),s&&this.domElement.style.setProperty("--width",s+"px"),this._closeFolders=a}add(e,t,n,s,r){if(Object(n)===n)return new Wg(this,e,t,n);const a=e[t];switch(typeof a){case"number":return new Gg(this,e,t,n,s,r);case"boolean":return new Fg(this,e,t);case"string":return new Xg(this,e,t);case"function":return new Ll(this,e,t)}console.error(`gui.add failed
	property:`,t,`
	object:`,e,`
	value:`,a)}addColor(e,t,n=1){return new Vg(this,e,t,n)}addFolder(e){const t=new Oh({parent:this,title:e});return this.root._closeFolders&&t.close(),t}load(e,t=!0){return e.controllers&&this.controllers.forEach(n=>{n instanceof Ll||n._name in e.controllers&&n.load(e.controllers[n._name])}),t&&e.folders&&this.folders.forEach(n=>{n._title in e.folders&&n.load(e.folders[n._title])}),this}save(e=!0){const t={controllers:{},folders:{}};return this.controllers.forEach(n=>{if(!(n instanceof Ll)){if(n._name in t.controllers)throw new Error(`Cannot save GUI with duplicate property "${n._name}"`);t.controllers[n._name]=n.save()}}),e&&this.folders.forEach(n=>{if(n._title in t.folders)throw new Error(`Cannot save GUI with duplicate folder "${n._title}"`);t.folders[n._title]=n.save()}),t}open(e=!0){return this._setClosed(!e),this.$title.setAttribute("aria-expanded",!this._closed),this.domElement.classList.toggle("lil-closed",this._closed),this}close(){return this.open(!1)}_setClosed(e){this._closed!==e&&(this._closed=e,this._callOnOpenClose(this))}show(e=!0){return this._hidden=!e,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}openAnimated(e=!0){return this._setClosed(!e),this.$title.setAttribute("aria-expanded",!this._closed),requestAnimationFrame(()=>{const t=this.$children.clientHeight;this.$children.style.height=t+"px",this.domElement.classList.add("lil-transition");const n=r=>{r.target===this.$children&&(this.$children.style.height="",this.domElement.classList.remove("lil-transition"),this.$children.removeEventListener("transitionend",n))};this.$children.addEventListener("transitionend",n);const s=e?this.$children.scrollHeight:0;this.domElement.classList.toggle("lil-closed",!e),requestAnimationFrame(()=>{this.$children.style.height=s+"px"})}),this}title(e){return this._title=e,this.$title.textContent=e,this}reset(e=!0){return(e?this.controllersRecursive():this.controllers).forEach(n=>n.reset()),this}onChange(e){return this._onChange=e,this}_callOnChange(e){this.parent&&this.parent._callOnChange(e),this._onChange!==void 0&&this._onChange.call(this,{object:e.object,property:e.property,value:e.getValue(),controller:e})}onFinishChange(e){return this._onFinishChange=e,this}_callOnFinishChange(e){this.parent&&this.parent._callOnFinishChange(e),this._onFinishChange!==void 0&&this._onFinishChange.call(this,{object:e.object,property:e.property,value:e.getValue(),controller:e})}onOpenClose(e){return this._onOpenClose=e,this}_callOnOpenClose(e){this.parent&&this.parent._callOnOpenClose(e),this._onOpenClose!==void 0&&this._onOpenClose.call(this,e)}destroy(){this.parent&&(this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.folders.splice(this.parent.folders.indexOf(this),1)),this.domElement.parentElement&&this.domElement.parentElement.removeChild(this.domElement),Array.from(this.children).forEach(e=>e.destroy())}controllersRecursive(){let e=Array.from(this.controllers);return this.folders.forEach(t=>{e=e.concat(t.controllersRecursive())}),e}foldersRecursive(){let e=Array.from(this.folders);return this.folders.forEach(t=>{e=e.concat(t.foldersRecursive())}),e}}function Jf(i){return i==="1"?"":i.replace("^2","²").replace("^3","³")}function jf(i){return bg(i.name,i.label??i.name,i.description)}function Yg(i){const e=Jf(i.unit),[t]=jf(i);return e?`${t} [${e}]`:t}function Tc(i){const e=Jf(i.unit),t=e?` ${e}`:"";return i.min!==null&&i.max!==null?`${i.min} … ${i.max}${t}`:i.min!==null?`≥ ${i.min}${t}`:i.max!==null?`≤ ${i.max}${t}`:"any finite number"}function Kg(i,e){return Number.isFinite(e)&&(i.min===null||e>=i.min)&&(i.max===null||e<=i.max)?null:N("msg.notAllowed",{name:i.name,value:e,allowed:i.allowed??Tc(i),range:Tc(i)})}function Qf(i,e,t,n,s){typeof e[t.name]!="number"&&(e[t.name]=t.default);const r=i.add(e,t.name,t.ui_min,t.ui_max).name(Yg(t)).onChange(l=>{const c=Kg(t,l);c!==null?s(c):n(l)}),[,a]=jf(t);r.domElement.title=N("gui.paramHelp",{help:a,name:t.name,unit:t.unit,range:Tc(t),default:t.default}),r.domElement.dataset.param=t.name,r.step(t.step,!1);const o=r;return typeof o._clamp=="function"&&(o._clamp=l=>l),r}function kh(i,e){let t=-1/0,n=null,s=null;return(...r)=>{s=r;const a=t+e-performance.now();a<=0&&n===null?(t=performance.now(),i(...r),s=null):n===null&&(n=setTimeout(()=>{n=null,t=performance.now(),s!==null&&i(...s),s=null},Math.max(0,a)))}}const Zg={damped:{damping:.3}};function Jg(i){const e=Zg[i];return e?{type:"set_model",model:i,params:{...e}}:{type:"set_model",model:i}}function jg(i){const e={};for(const t of i)e[t.label?`${Uh(t.name,t.label)} (${t.name})`:t.name]=t.name;return e}class Qg{constructor(e,t,n){this.parent=e,this.schema=t,this.actions=n,this.picker=e.add(this.state,"model",jg(t.models)).name(N("gui.model")).onChange(s=>n.send(Jg(s))),this.picker.domElement.dataset.control="model",this.picker.domElement.title=t.models.map(s=>`${s.name}: ${s.summary}`).join(`
`),this.sendParam=kh((s,r)=>{n.send({type:"set_params",params:{[s]:r}})},50)}parent;schema;actions;state={model:"ideal"};picker;paramsFolder=null;paramControls=[];values={};shown=null;sendParam;spec(e){return this.schema.models.find(t=>t.name===e)}rebuild(e){this.paramsFolder?.destroy(),this.paramsFolder=null,this.paramControls=[],this.values={},this.shown=e;const t=this.spec(e);if(t===void 0||t.params.length===0)return;const n=this.parent.addFolder(N("gui.modelParams",{model:Uh(e,t.label??e)}));for(const s of t.params){this.values[s.name]=s.default;const r=Qf(n,this.values,s,a=>this.sendParam(s.name,a),this.actions.explain);this.paramControls.push(r)}this.paramsFolder=n}sync(e){const t=e.model??"ideal";this.state.model=t,this.picker.updateDisplay(),this.shown!==t&&this.rebuild(t);for(const[n,s]of Object.entries(e.model_params??{}))this.values[n]=s;for(const n of this.paramControls)n.domElement.contains(document.activeElement)||n.updateDisplay()}}const Bh="187",Ir={ROTATE:0,DOLLY:1,PAN:2},Nr={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},e0=0,Ou=1,t0=2,Uo=1,n0=2,ga=3,Cs=0,Yn=1,fi=2,Ur=0,ya=1,ku=2,Bu=3,zu=4,i0=5,Lr=100,s0=101,r0=102,a0=103,o0=104,l0=200,c0=201,h0=202,u0=203,ep=204,tp=205,d0=206,f0=207,p0=208,m0=209,g0=210,_0=211,v0=212,x0=213,S0=214,Ac=0,Rc=1,Cc=2,Ca=3,Pc=4,Lc=5,Dc=6,Nc=7,np=0,M0=1,y0=2,ls=0,ip=1,sp=2,rp=3,ap=4,op=5,lp=6,cp=7,hp=300,Br=301,Pa=302,Dl=303,Nl=304,Ic=1e3,as=1001,Uc=1002,Pn=1003,b0=1004,Ka=1005,qn=1006,Il=1007,Ts=1008,ni=1009,up=1010,dp=1011,La=1012,zh=1013,qi=1014,Vi=1015,Yi=1016,Hh=1017,Vh=1018,zr=1020,fp=35902,pp=35899,mp=1021,gp=1022,Gi=1023,Ps=1026,As=1027,_p=1028,Gh=1029,Ks=1030,Wh=1031,Xh=1033,Fo=33776,Oo=33777,ko=33778,Bo=33779,Fc=35840,Oc=35841,kc=35842,Bc=35843,zc=36196,Hc=37492,Vc=37496,Gc=37488,Wc=37489,Wo=37490,Xc=37491,$c=37808,qc=37809,Yc=37810,Kc=37811,Zc=37812,Jc=37813,jc=37814,Qc=37815,eh=37816,th=37817,nh=37818,ih=37819,sh=37820,rh=37821,ah=36492,oh=36494,lh=36495,ch=36283,hh=36284,Xo=36285,uh=36286,w0=3200,dh=0,E0=1,Es="",hi="srgb",$o="srgb-linear",qo="linear",Lt="srgb",Ul=7680,T0=519,A0=512,R0=513,C0=514,vp=515,P0=516,L0=517,xp=518,Sp=519,Mp=35044,Hu="300 es",Ri=2e3,Da=2001;function D0(i){for(let e=i.length-1;e>=0;--e)if(i[e]>=65535)return!0;return!1}function Yo(i){return document.createElementNS("http://www.w3.org/1999/xhtml",i)}function N0(){const i=Yo("canvas");return i.style.display="block",i}const Vu={};function Ko(...i){const e="THREE."+i.shift();console.log(e,...i)}function yp(i){const e=i[0];if(typeof e=="string"&&e.startsWith("TSL:")){const t=i[1];t&&t.isStackTrace?i[0]+=" "+t.getLocation():i[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return i}function je(...i){i=yp(i);const e="THREE."+i.shift();{const t=i[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...i)}}function St(...i){i=yp(i);const e="THREE."+i.shift();{const t=i[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...i)}}function zo(...i){const e=i.join(" ");e in Vu||(Vu[e]=!0,je(...i))}function I0(i,e,t){return new Promise(function(n,s){function r(){switch(i.clientWaitSync(e,i.SYNC_FLUSH_COMMANDS_BIT,0)){case i.WAIT_FAILED:s();break;case i.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:n()}}setTimeout(r,t)})}const U0={[Ac]:Ac,[Cc]:Dc,[Pc]:Pc,[Ca]:Lc,[Rc]:Rc,[Dc]:Cc,[Nc]:Nc,[Lc]:Ca};class Is{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});const n=this._listeners;n[e]===void 0&&(n[e]=[]),n[e].indexOf(t)===-1&&n[e].push(t)}hasEventListener(e,t){const n=this._listeners;return n===void 0?!1:n[e]!==void 0&&n[e].indexOf(t)!==-1}removeEventListener(e,t){const n=this._listeners;if(n===void 0)return;const s=n[e];if(s!==void 0){const r=s.indexOf(t);r!==-1&&s.splice(r,1)}}dispatchEvent(e){const t=this._listeners;if(t===void 0)return;const n=t[e.type];if(n!==void 0){e.target=this;const s=n.slice(0);for(let r=0,a=s.length;r<a;r++)s[r].call(this,e);e.target=null}}}const Dn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],ba=Math.PI/180,fh=180/Math.PI;function js(){const i=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,n=Math.random()*4294967295|0;return(Dn[i&255]+Dn[i>>8&255]+Dn[i>>16&255]+Dn[i>>24&255]+"-"+Dn[e&255]+Dn[e>>8&255]+"-"+Dn[e>>16&15|64]+Dn[e>>24&255]+"-"+Dn[t&63|128]+Dn[t>>8&255]+"-"+Dn[t>>16&255]+Dn[t>>24&255]+Dn[n&255]+Dn[n>>8&255]+Dn[n>>16&255]+Dn[n>>24&255]).toLowerCase()}function mt(i,e,t){return Math.max(e,Math.min(t,i))}function F0(i,e){return(i%e+e)%e}function Fl(i,e,t){return(1-t)*i+t*e}function O0(i){return Math.pow(2,Math.floor(Math.log(i)/Math.LN2))}function sl(i){switch(i.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function bp(i,e){if(e.constructor===Float32Array)return i;const t=sl(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(i/t,-1)}function wp(i,e){if(e.constructor===Float32Array)return i;const t=sl(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(i*t)}const k0={DEG2RAD:ba};class Xe{static{this.prototype.isVector2=!0}constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){const t=this.x,n=this.y,s=e.elements;return this.x=s[0]*t+s[3]*n+s[6],this.y=s[1]*t+s[4]*n+s[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=mt(this.x,e.x,t.x),this.y=mt(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=mt(this.x,e,t),this.y=mt(this.y,e,t),this}clampLength(e,t){const n=this.length();return this.divideScalar(n||1).multiplyScalar(mt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const n=this.dot(e)/t;return Math.acos(mt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,n=this.y-e.y;return t*t+n*n}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){const n=Math.cos(t),s=Math.sin(t),r=this.x-e.x,a=this.y-e.y;return this.x=r*n-a*s+e.x,this.y=r*s+a*n+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}}class Ls{constructor(e=0,t=0,n=0,s=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=n,this._w=s}static slerpFlat(e,t,n,s,r,a,o){let l=n[s+0],c=n[s+1],h=n[s+2],u=n[s+3],d=r[a+0],m=r[a+1],_=r[a+2],M=r[a+3];if(u!==M||l!==d||c!==m||h!==_){let p=l*d+c*m+h*_+u*M;p<0&&(d=-d,m=-m,_=-_,M=-M,p=-p);let f=1-o;if(p<.9995){const x=Math.acos(p),A=Math.sin(x);f=Math.sin(f*x)/A,o=Math.sin(o*x)/A,l=l*f+d*o,c=c*f+m*o,h=h*f+_*o,u=u*f+M*o}else{l=l*f+d*o,c=c*f+m*o,h=h*f+_*o,u=u*f+M*o;const x=1/Math.sqrt(l*l+c*c+h*h+u*u);l*=x,c*=x,h*=x,u*=x}}e[t]=l,e[t+1]=c,e[t+2]=h,e[t+3]=u}static multiplyQuaternionsFlat(e,t,n,s,r,a){const o=n[s],l=n[s+1],c=n[s+2],h=n[s+3],u=r[a],d=r[a+1],m=r[a+2],_=r[a+3];return e[t]=o*_+h*u+l*m-c*d,e[t+1]=l*_+h*d+c*u-o*m,e[t+2]=c*_+h*m+o*d-l*u,e[t+3]=h*_-o*u-l*d-c*m,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,n,s){return this._x=e,this._y=t,this._z=n,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){const n=e._x,s=e._y,r=e._z,a=e._order,o=Math.cos,l=Math.sin,c=o(n/2),h=o(s/2),u=o(r/2),d=l(n/2),m=l(s/2),_=l(r/2);switch(a){case"XYZ":this._x=d*h*u+c*m*_,this._y=c*m*u-d*h*_,this._z=c*h*_+d*m*u,this._w=c*h*u-d*m*_;break;case"YXZ":this._x=d*h*u+c*m*_,this._y=c*m*u-d*h*_,this._z=c*h*_-d*m*u,this._w=c*h*u+d*m*_;break;case"ZXY":this._x=d*h*u-c*m*_,this._y=c*m*u+d*h*_,this._z=c*h*_+d*m*u,this._w=c*h*u-d*m*_;break;case"ZYX":this._x=d*h*u-c*m*_,this._y=c*m*u+d*h*_,this._z=c*h*_-d*m*u,this._w=c*h*u+d*m*_;break;case"YZX":this._x=d*h*u+c*m*_,this._y=c*m*u+d*h*_,this._z=c*h*_-d*m*u,this._w=c*h*u-d*m*_;break;case"XZY":this._x=d*h*u-c*m*_,this._y=c*m*u-d*h*_,this._z=c*h*_+d*m*u,this._w=c*h*u+d*m*_;break;default:je("Quaternion: .setFromEuler() encountered an unknown order: "+a)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){const n=t/2,s=Math.sin(n);return this._x=e.x*s,this._y=e.y*s,this._z=e.z*s,this._w=Math.cos(n),this._onChangeCallback(),this}setFromRotationMatrix(e){const t=e.elements,n=t[0],s=t[4],r=t[8],a=t[1],o=t[5],l=t[9],c=t[2],h=t[6],u=t[10],d=n+o+u;if(d>0){const m=.5/Math.sqrt(d+1);this._w=.25/m,this._x=(h-l)*m,this._y=(r-c)*m,this._z=(a-s)*m}else if(n>o&&n>u){const m=2*Math.sqrt(1+n-o-u);this._w=(h-l)/m,this._x=.25*m,this._y=(s+a)/m,this._z=(r+c)/m}else if(o>u){const m=2*Math.sqrt(1+o-n-u);this._w=(r-c)/m,this._x=(s+a)/m,this._y=.25*m,this._z=(l+h)/m}else{const m=2*Math.sqrt(1+u-n-o);this._w=(a-s)/m,this._x=(r+c)/m,this._y=(l+h)/m,this._z=.25*m}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let n=e.dot(t)+1;return n<1e-8?(n=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=n):(this._x=0,this._y=-e.z,this._z=e.y,this._w=n)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=n),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(mt(this.dot(e),-1,1)))}rotateTowards(e,t){const n=this.angleTo(e);if(n===0)return this;const s=Math.min(1,t/n);return this.slerp(e,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){const n=e._x,s=e._y,r=e._z,a=e._w,o=t._x,l=t._y,c=t._z,h=t._w;return this._x=n*h+a*o+s*c-r*l,this._y=s*h+a*l+r*o-n*c,this._z=r*h+a*c+n*l-s*o,this._w=a*h-n*o-s*l-r*c,this._onChangeCallback(),this}slerp(e,t){let n=e._x,s=e._y,r=e._z,a=e._w,o=this.dot(e);o<0&&(n=-n,s=-s,r=-r,a=-a,o=-o);let l=1-t;if(o<.9995){const c=Math.acos(o),h=Math.sin(c);l=Math.sin(l*c)/h,t=Math.sin(t*c)/h,this._x=this._x*l+n*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+a*t,this._onChangeCallback()}else this._x=this._x*l+n*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+a*t,this.normalize();return this}slerpQuaternions(e,t,n){return this.copy(e).slerp(t,n)}random(){const e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),n=Math.random(),s=Math.sqrt(1-n),r=Math.sqrt(n);return this.set(s*Math.sin(e),s*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}}class z{static{this.prototype.isVector3=!0}constructor(e=0,t=0,n=0){this.x=e,this.y=t,this.z=n}set(e,t,n){return n===void 0&&(n=this.z),this.x=e,this.y=t,this.z=n,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(Gu.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(Gu.setFromAxisAngle(e,t))}applyMatrix3(e){const t=this.x,n=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[3]*n+r[6]*s,this.y=r[1]*t+r[4]*n+r[7]*s,this.z=r[2]*t+r[5]*n+r[8]*s,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){const t=this.x,n=this.y,s=this.z,r=e.elements,a=1/(r[3]*t+r[7]*n+r[11]*s+r[15]);return this.x=(r[0]*t+r[4]*n+r[8]*s+r[12])*a,this.y=(r[1]*t+r[5]*n+r[9]*s+r[13])*a,this.z=(r[2]*t+r[6]*n+r[10]*s+r[14])*a,this}applyQuaternion(e){const t=this.x,n=this.y,s=this.z,r=e.x,a=e.y,o=e.z,l=e.w,c=2*(a*s-o*n),h=2*(o*t-r*s),u=2*(r*n-a*t);return this.x=t+l*c+a*u-o*h,this.y=n+l*h+o*c-r*u,this.z=s+l*u+r*h-a*c,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){const t=this.x,n=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[4]*n+r[8]*s,this.y=r[1]*t+r[5]*n+r[9]*s,this.z=r[2]*t+r[6]*n+r[10]*s,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=mt(this.x,e.x,t.x),this.y=mt(this.y,e.y,t.y),this.z=mt(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=mt(this.x,e,t),this.y=mt(this.y,e,t),this.z=mt(this.z,e,t),this}clampLength(e,t){const n=this.length();return this.divideScalar(n||1).multiplyScalar(mt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){const n=e.x,s=e.y,r=e.z,a=t.x,o=t.y,l=t.z;return this.x=s*l-r*o,this.y=r*a-n*l,this.z=n*o-s*a,this}projectOnVector(e){const t=e.lengthSq();if(t===0)return this.set(0,0,0);const n=e.dot(this)/t;return this.copy(e).multiplyScalar(n)}projectOnPlane(e){return Ol.copy(this).projectOnVector(e),this.sub(Ol)}reflect(e){return this.sub(Ol.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){const t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;const n=this.dot(e)/t;return Math.acos(mt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){const t=this.x-e.x,n=this.y-e.y,s=this.z-e.z;return t*t+n*n+s*s}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,n){const s=Math.sin(t)*e;return this.x=s*Math.sin(n),this.y=Math.cos(t)*e,this.z=s*Math.cos(n),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,n){return this.x=e*Math.sin(t),this.y=n,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){const t=this.setFromMatrixColumn(e,0).length(),n=this.setFromMatrixColumn(e,1).length(),s=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=n,this.z=s,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){const e=Math.random()*Math.PI*2,t=Math.random()*2-1,n=Math.sqrt(1-t*t);return this.x=n*Math.cos(e),this.y=t,this.z=n*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}}const Ol=new z,Gu=new Ls;class rt{static{this.prototype.isMatrix3=!0}constructor(e,t,n,s,r,a,o,l,c){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,n,s,r,a,o,l,c)}set(e,t,n,s,r,a,o,l,c){const h=this.elements;return h[0]=e,h[1]=s,h[2]=o,h[3]=t,h[4]=r,h[5]=l,h[6]=n,h[7]=a,h[8]=c,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){const t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],this}extractBasis(e,t,n){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),n.setFromMatrix3Column(this,2),this}setFromMatrix4(e){const t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const n=e.elements,s=t.elements,r=this.elements,a=n[0],o=n[3],l=n[6],c=n[1],h=n[4],u=n[7],d=n[2],m=n[5],_=n[8],M=s[0],p=s[3],f=s[6],x=s[1],A=s[4],S=s[7],R=s[2],y=s[5],g=s[8];return r[0]=a*M+o*x+l*R,r[3]=a*p+o*A+l*y,r[6]=a*f+o*S+l*g,r[1]=c*M+h*x+u*R,r[4]=c*p+h*A+u*y,r[7]=c*f+h*S+u*g,r[2]=d*M+m*x+_*R,r[5]=d*p+m*A+_*y,r[8]=d*f+m*S+_*g,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){const e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],h=e[8];return t*a*h-t*o*c-n*r*h+n*o*l+s*r*c-s*a*l}invert(){const e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],h=e[8],u=h*a-o*c,d=o*l-h*r,m=c*r-a*l,_=t*u+n*d+s*m;if(_===0)return this.set(0,0,0,0,0,0,0,0,0);const M=1/_;return e[0]=u*M,e[1]=(s*c-h*n)*M,e[2]=(o*n-s*a)*M,e[3]=d*M,e[4]=(h*t-s*l)*M,e[5]=(s*r-o*t)*M,e[6]=m*M,e[7]=(n*l-c*t)*M,e[8]=(a*t-n*r)*M,this}transpose(){let e;const t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){const t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,n,s,r,a,o){const l=Math.cos(r),c=Math.sin(r);return this.set(n*l,n*c,-n*(l*a+c*o)+a+e,-s*c,s*l,-s*(-c*a+l*o)+o+t,0,0,1),this}scale(e,t){return zo("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(kl.makeScale(e,t)),this}rotate(e){return zo("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(kl.makeRotation(-e)),this}translate(e,t){return zo("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(kl.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){const t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,n,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){const t=this.elements,n=e.elements;for(let s=0;s<9;s++)if(t[s]!==n[s])return!1;return!0}fromArray(e,t=0){for(let n=0;n<9;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){const n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e}clone(){return new this.constructor().fromArray(this.elements)}}const kl=new rt,Wu=new rt().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Xu=new rt().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function B0(){const i={enabled:!0,workingColorSpace:$o,spaces:{},convert:function(s,r,a){return this.enabled===!1||r===a||!r||!a||(this.spaces[r].transfer===Lt&&(s.r=cs(s.r),s.g=cs(s.g),s.b=cs(s.b)),this.spaces[r].primaries!==this.spaces[a].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[a].fromXYZ)),this.spaces[a].transfer===Lt&&(s.r=Fr(s.r),s.g=Fr(s.g),s.b=Fr(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===Es?qo:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,a){return s.copy(this.spaces[a].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],n=[.3127,.329];return i.define({[$o]:{primaries:e,whitePoint:n,transfer:qo,toXYZ:Wu,fromXYZ:Xu,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:hi},outputColorSpaceConfig:{drawingBufferColorSpace:hi}},[hi]:{primaries:e,whitePoint:n,transfer:Lt,toXYZ:Wu,fromXYZ:Xu,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:hi}}}),i}const xt=B0();function cs(i){return i<.04045?i*.0773993808:Math.pow(i*.9478672986+.0521327014,2.4)}function Fr(i){return i<.0031308?i*12.92:1.055*Math.pow(i,.41666)-.055}let dr;class z0{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let n;if(e instanceof HTMLCanvasElement)n=e;else{dr===void 0&&(dr=Yo("canvas")),dr.width=e.width,dr.height=e.height;const s=dr.getContext("2d");e instanceof ImageData?s.putImageData(e,0,0):s.drawImage(e,0,0,e.width,e.height),n=dr}return n.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){const t=Yo("canvas");t.width=e.width,t.height=e.height;const n=t.getContext("2d");n.drawImage(e,0,0,e.width,e.height);const s=n.getImageData(0,0,e.width,e.height),r=s.data;for(let a=0;a<r.length;a++)r[a]=cs(r[a]/255)*255;return n.putImageData(s,0,0),t}else if(e.data){const t=e.data.slice(0);for(let n=0;n<t.length;n++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[n]=Math.floor(cs(t[n]/255)*255):t[n]=cs(t[n]);return{data:t,width:e.width,height:e.height}}else return je("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}}let H0=0;class $h{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:H0++}),this.uuid=js(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){const t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];const n={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let a=0,o=s.length;a<o;a++)s[a].isDataTexture?r.push(Bl(s[a].image)):r.push(Bl(s[a]))}else r=Bl(s);n.url=r}return t||(e.images[this.uuid]=n),n}}function Bl(i){return typeof HTMLImageElement<"u"&&i instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&i instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&i instanceof ImageBitmap?z0.getDataURL(i):i.data?{data:Array.from(i.data),width:i.width,height:i.height,type:i.data.constructor.name}:(je("Texture: Unable to serialize Texture."),{})}let V0=0;const zl=new z;class In extends Is{constructor(e=In.DEFAULT_IMAGE,t=In.DEFAULT_MAPPING,n=as,s=as,r=qn,a=Ts,o=Gi,l=ni,c=In.DEFAULT_ANISOTROPY,h=Es){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:V0++}),this.uuid=js(),this.name="",this.source=new $h(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=n,this.wrapT=s,this.magFilter=r,this.minFilter=a,this.anisotropy=c,this.format=o,this.internalFormat=null,this.type=l,this.offset=new Xe(0,0),this.repeat=new Xe(1,1),this.center=new Xe(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new rt,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(zl).x}get height(){return this.source.getSize(zl).y}get depth(){return this.source.getSize(zl).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(const t in e){const n=e[t];if(n===void 0){je(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}const s=this[t];if(s===void 0){je(`Texture.setValues(): property '${t}' does not exist.`);continue}s&&n&&s.isVector2&&n.isVector2||s&&n&&s.isVector3&&n.isVector3||s&&n&&s.isMatrix3&&n.isMatrix3?s.copy(n):this[t]=n}}toJSON(e){const t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];const n={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(n.userData=this.userData),t||(e.textures[this.uuid]=n),n}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==hp)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case Ic:e.x=e.x-Math.floor(e.x);break;case as:e.x=e.x<0?0:1;break;case Uc:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case Ic:e.y=e.y-Math.floor(e.y);break;case as:e.y=e.y<0?0:1;break;case Uc:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}}In.DEFAULT_IMAGE=null;In.DEFAULT_MAPPING=hp;In.DEFAULT_ANISOTROPY=1;class nn{static{this.prototype.isVector4=!0}constructor(e=0,t=0,n=0,s=1){this.x=e,this.y=t,this.z=n,this.w=s}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,n,s){return this.x=e,this.y=t,this.z=n,this.w=s,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){const t=this.x,n=this.y,s=this.z,r=this.w,a=e.elements;return this.x=a[0]*t+a[4]*n+a[8]*s+a[12]*r,this.y=a[1]*t+a[5]*n+a[9]*s+a[13]*r,this.z=a[2]*t+a[6]*n+a[10]*s+a[14]*r,this.w=a[3]*t+a[7]*n+a[11]*s+a[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);const t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,n,s,r;const l=e.elements,c=l[0],h=l[4],u=l[8],d=l[1],m=l[5],_=l[9],M=l[2],p=l[6],f=l[10];if(Math.abs(h-d)<.01&&Math.abs(u-M)<.01&&Math.abs(_-p)<.01){if(Math.abs(h+d)<.1&&Math.abs(u+M)<.1&&Math.abs(_+p)<.1&&Math.abs(c+m+f-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;const A=(c+1)/2,S=(m+1)/2,R=(f+1)/2,y=(h+d)/4,g=(u+M)/4,b=(_+p)/4;return A>S&&A>R?A<.01?(n=0,s=.707106781,r=.707106781):(n=Math.sqrt(A),s=y/n,r=g/n):S>R?S<.01?(n=.707106781,s=0,r=.707106781):(s=Math.sqrt(S),n=y/s,r=b/s):R<.01?(n=.707106781,s=.707106781,r=0):(r=Math.sqrt(R),n=g/r,s=b/r),this.set(n,s,r,t),this}let x=Math.sqrt((p-_)*(p-_)+(u-M)*(u-M)+(d-h)*(d-h));return Math.abs(x)<.001&&(x=1),this.x=(p-_)/x,this.y=(u-M)/x,this.z=(d-h)/x,this.w=Math.acos((c+m+f-1)/2),this}setFromMatrixPosition(e){const t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=mt(this.x,e.x,t.x),this.y=mt(this.y,e.y,t.y),this.z=mt(this.z,e.z,t.z),this.w=mt(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=mt(this.x,e,t),this.y=mt(this.y,e,t),this.z=mt(this.z,e,t),this.w=mt(this.w,e,t),this}clampLength(e,t){const n=this.length();return this.divideScalar(n||1).multiplyScalar(mt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this.w=e.w+(t.w-e.w)*n,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}}class G0 extends Is{constructor(e=1,t=1,n={}){super(),n=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:qn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},n),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=n.depth,this.scissor=new nn(0,0,e,t),this.scissorTest=!1,this.viewport=new nn(0,0,e,t),this.textures=[];const s=n.count;for(let r=0;r<s;r++)this.textures[r]=new In({width:e,height:t,depth:n.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(n),this.depthBuffer=n.depthBuffer,this.stencilBuffer=n.stencilBuffer,this.resolveColorBuffer=n.resolveColorBuffer,this.resolveDepthBuffer=n.resolveDepthBuffer,this.resolveStencilBuffer=n.resolveStencilBuffer,this.storeMultisampledColorBuffer=n.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=n.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=n.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=n.depthTexture,this.samples=n.samples,this.multiview=n.multiview,this.useArrayDepthTexture=n.useArrayDepthTexture}_setTextureOptions(e={}){const t={minFilter:qn,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let n=0;n<this.textures.length;n++)this.textures[n].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,n=1){if(this.width!==e||this.height!==t||this.depth!==n){this.width=e,this.height=t,this.depth=n;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=e,this.textures[s].image.height=t,this.textures[s].image.depth=n,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,n=e.textures.length;t<n;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;const s=Object.assign({},e.textures[t].image);this.textures[t].source=new $h(s)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){const t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}}class $i extends G0{constructor(e=1,t=1,n={}){super(e,t,n),this.isWebGLRenderTarget=!0}}class Ep extends In{constructor(e=null,t=1,n=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:n,depth:s},this.magFilter=Pn,this.minFilter=Pn,this.wrapR=as,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}}class W0 extends In{constructor(e=null,t=1,n=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:n,depth:s},this.magFilter=Pn,this.minFilter=Pn,this.wrapR=as,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}}class Dt{static{this.prototype.isMatrix4=!0}constructor(e,t,n,s,r,a,o,l,c,h,u,d,m,_,M,p){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,n,s,r,a,o,l,c,h,u,d,m,_,M,p)}set(e,t,n,s,r,a,o,l,c,h,u,d,m,_,M,p){const f=this.elements;return f[0]=e,f[4]=t,f[8]=n,f[12]=s,f[1]=r,f[5]=a,f[9]=o,f[13]=l,f[2]=c,f[6]=h,f[10]=u,f[14]=d,f[3]=m,f[7]=_,f[11]=M,f[15]=p,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new Dt().fromArray(this.elements)}copy(e){const t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],t[9]=n[9],t[10]=n[10],t[11]=n[11],t[12]=n[12],t[13]=n[13],t[14]=n[14],t[15]=n[15],this}copyPosition(e){const t=this.elements,n=e.elements;return t[12]=n[12],t[13]=n[13],t[14]=n[14],this}setFromMatrix3(e){const t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,n){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),n.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),n.setFromMatrixColumn(this,2),this)}makeBasis(e,t,n){return this.set(e.x,t.x,n.x,0,e.y,t.y,n.y,0,e.z,t.z,n.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();const t=this.elements,n=e.elements,s=1/fr.setFromMatrixColumn(e,0).length(),r=1/fr.setFromMatrixColumn(e,1).length(),a=1/fr.setFromMatrixColumn(e,2).length();return t[0]=n[0]*s,t[1]=n[1]*s,t[2]=n[2]*s,t[3]=0,t[4]=n[4]*r,t[5]=n[5]*r,t[6]=n[6]*r,t[7]=0,t[8]=n[8]*a,t[9]=n[9]*a,t[10]=n[10]*a,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){const t=this.elements,n=e.x,s=e.y,r=e.z,a=Math.cos(n),o=Math.sin(n),l=Math.cos(s),c=Math.sin(s),h=Math.cos(r),u=Math.sin(r);if(e.order==="XYZ"){const d=a*h,m=a*u,_=o*h,M=o*u;t[0]=l*h,t[4]=-l*u,t[8]=c,t[1]=m+_*c,t[5]=d-M*c,t[9]=-o*l,t[2]=M-d*c,t[6]=_+m*c,t[10]=a*l}else if(e.order==="YXZ"){const d=l*h,m=l*u,_=c*h,M=c*u;t[0]=d+M*o,t[4]=_*o-m,t[8]=a*c,t[1]=a*u,t[5]=a*h,t[9]=-o,t[2]=m*o-_,t[6]=M+d*o,t[10]=a*l}else if(e.order==="ZXY"){const d=l*h,m=l*u,_=c*h,M=c*u;t[0]=d-M*o,t[4]=-a*u,t[8]=_+m*o,t[1]=m+_*o,t[5]=a*h,t[9]=M-d*o,t[2]=-a*c,t[6]=o,t[10]=a*l}else if(e.order==="ZYX"){const d=a*h,m=a*u,_=o*h,M=o*u;t[0]=l*h,t[4]=_*c-m,t[8]=d*c+M,t[1]=l*u,t[5]=M*c+d,t[9]=m*c-_,t[2]=-c,t[6]=o*l,t[10]=a*l}else if(e.order==="YZX"){const d=a*l,m=a*c,_=o*l,M=o*c;t[0]=l*h,t[4]=M-d*u,t[8]=_*u+m,t[1]=u,t[5]=a*h,t[9]=-o*h,t[2]=-c*h,t[6]=m*u+_,t[10]=d-M*u}else if(e.order==="XZY"){const d=a*l,m=a*c,_=o*l,M=o*c;t[0]=l*h,t[4]=-u,t[8]=c*h,t[1]=d*u+M,t[5]=a*h,t[9]=m*u-_,t[2]=_*u-m,t[6]=o*h,t[10]=M*u+d}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(X0,e,$0)}lookAt(e,t,n){const s=this.elements;return Qn.subVectors(e,t),Qn.lengthSq()===0&&(Qn.z=1),Qn.normalize(),vs.crossVectors(n,Qn),vs.lengthSq()===0&&(Math.abs(n.z)===1?Qn.x+=1e-4:Qn.z+=1e-4,Qn.normalize(),vs.crossVectors(n,Qn)),vs.normalize(),Za.crossVectors(Qn,vs),s[0]=vs.x,s[4]=Za.x,s[8]=Qn.x,s[1]=vs.y,s[5]=Za.y,s[9]=Qn.y,s[2]=vs.z,s[6]=Za.z,s[10]=Qn.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){const n=e.elements,s=t.elements,r=this.elements,a=n[0],o=n[4],l=n[8],c=n[12],h=n[1],u=n[5],d=n[9],m=n[13],_=n[2],M=n[6],p=n[10],f=n[14],x=n[3],A=n[7],S=n[11],R=n[15],y=s[0],g=s[4],b=s[8],k=s[12],I=s[1],L=s[5],G=s[9],W=s[13],U=s[2],X=s[6],J=s[10],H=s[14],ce=s[3],Z=s[7],ee=s[11],se=s[15];return r[0]=a*y+o*I+l*U+c*ce,r[4]=a*g+o*L+l*X+c*Z,r[8]=a*b+o*G+l*J+c*ee,r[12]=a*k+o*W+l*H+c*se,r[1]=h*y+u*I+d*U+m*ce,r[5]=h*g+u*L+d*X+m*Z,r[9]=h*b+u*G+d*J+m*ee,r[13]=h*k+u*W+d*H+m*se,r[2]=_*y+M*I+p*U+f*ce,r[6]=_*g+M*L+p*X+f*Z,r[10]=_*b+M*G+p*J+f*ee,r[14]=_*k+M*W+p*H+f*se,r[3]=x*y+A*I+S*U+R*ce,r[7]=x*g+A*L+S*X+R*Z,r[11]=x*b+A*G+S*J+R*ee,r[15]=x*k+A*W+S*H+R*se,this}multiplyScalar(e){const t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){const e=this.elements,t=e[0],n=e[4],s=e[8],r=e[12],a=e[1],o=e[5],l=e[9],c=e[13],h=e[2],u=e[6],d=e[10],m=e[14],_=e[3],M=e[7],p=e[11],f=e[15],x=l*m-c*d,A=o*m-c*u,S=o*d-l*u,R=a*m-c*h,y=a*d-l*h,g=a*u-o*h;return t*(M*x-p*A+f*S)-n*(_*x-p*R+f*y)+s*(_*A-M*R+f*g)-r*(_*S-M*y+p*g)}determinantAffine(){const e=this.elements,t=e[0],n=e[4],s=e[8],r=e[1],a=e[5],o=e[9],l=e[2],c=e[6],h=e[10];return t*(a*h-o*c)-n*(r*h-o*l)+s*(r*c-a*l)}transpose(){const e=this.elements;let t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,n){const s=this.elements;return e.isVector3?(s[12]=e.x,s[13]=e.y,s[14]=e.z):(s[12]=e,s[13]=t,s[14]=n),this}invert(){const e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],a=e[4],o=e[5],l=e[6],c=e[7],h=e[8],u=e[9],d=e[10],m=e[11],_=e[12],M=e[13],p=e[14],f=e[15],x=t*o-n*a,A=t*l-s*a,S=t*c-r*a,R=n*l-s*o,y=n*c-r*o,g=s*c-r*l,b=h*M-u*_,k=h*p-d*_,I=h*f-m*_,L=u*p-d*M,G=u*f-m*M,W=d*f-m*p,U=x*W-A*G+S*L+R*I-y*k+g*b;if(U===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);const X=1/U;return e[0]=(o*W-l*G+c*L)*X,e[1]=(s*G-n*W-r*L)*X,e[2]=(M*g-p*y+f*R)*X,e[3]=(d*y-u*g-m*R)*X,e[4]=(l*I-a*W-c*k)*X,e[5]=(t*W-s*I+r*k)*X,e[6]=(p*S-_*g-f*A)*X,e[7]=(h*g-d*S+m*A)*X,e[8]=(a*G-o*I+c*b)*X,e[9]=(n*I-t*G-r*b)*X,e[10]=(_*y-M*S+f*x)*X,e[11]=(u*S-h*y-m*x)*X,e[12]=(o*k-a*L-l*b)*X,e[13]=(t*L-n*k+s*b)*X,e[14]=(M*A-_*R-p*x)*X,e[15]=(h*R-u*A+d*x)*X,this}scale(e){const t=this.elements,n=e.x,s=e.y,r=e.z;return t[0]*=n,t[4]*=s,t[8]*=r,t[1]*=n,t[5]*=s,t[9]*=r,t[2]*=n,t[6]*=s,t[10]*=r,t[3]*=n,t[7]*=s,t[11]*=r,this}getMaxScaleOnAxis(){const e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],n=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],s=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,n,s))}makeTranslation(e,t,n){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,n,0,0,0,1),this}makeRotationX(e){const t=Math.cos(e),n=Math.sin(e);return this.set(1,0,0,0,0,t,-n,0,0,n,t,0,0,0,0,1),this}makeRotationY(e){const t=Math.cos(e),n=Math.sin(e);return this.set(t,0,n,0,0,1,0,0,-n,0,t,0,0,0,0,1),this}makeRotationZ(e){const t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,0,n,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){const n=Math.cos(t),s=Math.sin(t),r=1-n,a=e.x,o=e.y,l=e.z,c=r*a,h=r*o;return this.set(c*a+n,c*o-s*l,c*l+s*o,0,c*o+s*l,h*o+n,h*l-s*a,0,c*l-s*o,h*l+s*a,r*l*l+n,0,0,0,0,1),this}makeScale(e,t,n){return this.set(e,0,0,0,0,t,0,0,0,0,n,0,0,0,0,1),this}makeShear(e,t,n,s,r,a){return this.set(1,n,r,0,e,1,a,0,t,s,1,0,0,0,0,1),this}compose(e,t,n){const s=this.elements,r=t._x,a=t._y,o=t._z,l=t._w,c=r+r,h=a+a,u=o+o,d=r*c,m=r*h,_=r*u,M=a*h,p=a*u,f=o*u,x=l*c,A=l*h,S=l*u,R=n.x,y=n.y,g=n.z;return s[0]=(1-(M+f))*R,s[1]=(m+S)*R,s[2]=(_-A)*R,s[3]=0,s[4]=(m-S)*y,s[5]=(1-(d+f))*y,s[6]=(p+x)*y,s[7]=0,s[8]=(_+A)*g,s[9]=(p-x)*g,s[10]=(1-(d+M))*g,s[11]=0,s[12]=e.x,s[13]=e.y,s[14]=e.z,s[15]=1,this}decompose(e,t,n){const s=this.elements;e.x=s[12],e.y=s[13],e.z=s[14];const r=this.determinantAffine();if(r===0)return n.set(1,1,1),t.identity(),this;let a=fr.set(s[0],s[1],s[2]).length();const o=fr.set(s[4],s[5],s[6]).length(),l=fr.set(s[8],s[9],s[10]).length();r<0&&(a=-a),Mi.copy(this);const c=1/a,h=1/o,u=1/l;return Mi.elements[0]*=c,Mi.elements[1]*=c,Mi.elements[2]*=c,Mi.elements[4]*=h,Mi.elements[5]*=h,Mi.elements[6]*=h,Mi.elements[8]*=u,Mi.elements[9]*=u,Mi.elements[10]*=u,t.setFromRotationMatrix(Mi),n.x=a,n.y=o,n.z=l,this}makePerspective(e,t,n,s,r,a,o=Ri,l=!1){const c=this.elements,h=2*r/(t-e),u=2*r/(n-s),d=(t+e)/(t-e),m=(n+s)/(n-s);let _,M;if(l)_=r/(a-r),M=a*r/(a-r);else if(o===Ri)_=-(a+r)/(a-r),M=-2*a*r/(a-r);else if(o===Da)_=-a/(a-r),M=-a*r/(a-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return c[0]=h,c[4]=0,c[8]=d,c[12]=0,c[1]=0,c[5]=u,c[9]=m,c[13]=0,c[2]=0,c[6]=0,c[10]=_,c[14]=M,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(e,t,n,s,r,a,o=Ri,l=!1){const c=this.elements,h=2/(t-e),u=2/(n-s),d=-(t+e)/(t-e),m=-(n+s)/(n-s);let _,M;if(l)_=1/(a-r),M=a/(a-r);else if(o===Ri)_=-2/(a-r),M=-(a+r)/(a-r);else if(o===Da)_=-1/(a-r),M=-r/(a-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return c[0]=h,c[4]=0,c[8]=0,c[12]=d,c[1]=0,c[5]=u,c[9]=0,c[13]=m,c[2]=0,c[6]=0,c[10]=_,c[14]=M,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(e){const t=this.elements,n=e.elements;for(let s=0;s<16;s++)if(t[s]!==n[s])return!1;return!0}fromArray(e,t=0){for(let n=0;n<16;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){const n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e[t+9]=n[9],e[t+10]=n[10],e[t+11]=n[11],e[t+12]=n[12],e[t+13]=n[13],e[t+14]=n[14],e[t+15]=n[15],e}}const fr=new z,Mi=new Dt,X0=new z(0,0,0),$0=new z(1,1,1),vs=new z,Za=new z,Qn=new z,$u=new Dt,qu=new Ls;class Ds{constructor(e=0,t=0,n=0,s=Ds.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=n,this._order=s}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,n,s=this._order){return this._x=e,this._y=t,this._z=n,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,n=!0){const s=e.elements,r=s[0],a=s[4],o=s[8],l=s[1],c=s[5],h=s[9],u=s[2],d=s[6],m=s[10];switch(t){case"XYZ":this._y=Math.asin(mt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-h,m),this._z=Math.atan2(-a,r)):(this._x=Math.atan2(d,c),this._z=0);break;case"YXZ":this._x=Math.asin(-mt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(o,m),this._z=Math.atan2(l,c)):(this._y=Math.atan2(-u,r),this._z=0);break;case"ZXY":this._x=Math.asin(mt(d,-1,1)),Math.abs(d)<.9999999?(this._y=Math.atan2(-u,m),this._z=Math.atan2(-a,c)):(this._y=0,this._z=Math.atan2(l,r));break;case"ZYX":this._y=Math.asin(-mt(u,-1,1)),Math.abs(u)<.9999999?(this._x=Math.atan2(d,m),this._z=Math.atan2(l,r)):(this._x=0,this._z=Math.atan2(-a,c));break;case"YZX":this._z=Math.asin(mt(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-h,c),this._y=Math.atan2(-u,r)):(this._x=0,this._y=Math.atan2(o,m));break;case"XZY":this._z=Math.asin(-mt(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(d,c),this._y=Math.atan2(o,r)):(this._x=Math.atan2(-h,m),this._y=0);break;default:je("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,n===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,n){return $u.makeRotationFromQuaternion(e),this.setFromRotationMatrix($u,t,n)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return qu.setFromEuler(this),this.setFromQuaternion(qu,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}}Ds.DEFAULT_ORDER="XYZ";class qh{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}}let q0=0;const Yu=new z,pr=new Ls,ts=new Dt,Ja=new z,ra=new z,Y0=new z,K0=new Ls,Ku=new z(1,0,0),Zu=new z(0,1,0),Ju=new z(0,0,1),ju={type:"added"},Z0={type:"removed"},mr={type:"childadded",child:null},Hl={type:"childremoved",child:null};class Sn extends Is{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:q0++}),this.uuid=js(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=Sn.DEFAULT_UP.clone();const e=new z,t=new Ds,n=new Ls,s=new z(1,1,1);function r(){n.setFromEuler(t,!1)}function a(){t.setFromQuaternion(n,void 0,!1)}t._onChange(r),n._onChange(a),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:n},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new Dt},normalMatrix:{value:new rt}}),this.matrix=new Dt,this.matrixWorld=new Dt,this.matrixAutoUpdate=Sn.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=Sn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new qh,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return pr.setFromAxisAngle(e,t),this.quaternion.multiply(pr),this}rotateOnWorldAxis(e,t){return pr.setFromAxisAngle(e,t),this.quaternion.premultiply(pr),this}rotateX(e){return this.rotateOnAxis(Ku,e)}rotateY(e){return this.rotateOnAxis(Zu,e)}rotateZ(e){return this.rotateOnAxis(Ju,e)}translateOnAxis(e,t){return Yu.copy(e).applyQuaternion(this.quaternion),this.position.add(Yu.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(Ku,e)}translateY(e){return this.translateOnAxis(Zu,e)}translateZ(e){return this.translateOnAxis(Ju,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(ts.copy(this.matrixWorld).invert())}lookAt(e,t,n){e.isVector3?Ja.copy(e):Ja.set(e,t,n);const s=this.parent;this.updateWorldMatrix(!0,!1),ra.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?ts.lookAt(ra,Ja,this.up):ts.lookAt(Ja,ra,this.up),this.quaternion.setFromRotationMatrix(ts),s&&(ts.extractRotation(s.matrixWorld),pr.setFromRotationMatrix(ts),this.quaternion.premultiply(pr.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(St("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(ju),mr.child=e,this.dispatchEvent(mr),mr.child=null):St("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let n=0;n<arguments.length;n++)this.remove(arguments[n]);return this}const t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(Z0),Hl.child=e,this.dispatchEvent(Hl),Hl.child=null),this}removeFromParent(){const e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),ts.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),ts.multiply(e.parent.matrixWorld)),e.applyMatrix4(ts),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(ju),mr.child=e,this.dispatchEvent(mr),mr.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let n=0,s=this.children.length;n<s;n++){const a=this.children[n].getObjectByProperty(e,t);if(a!==void 0)return a}}getObjectsByProperty(e,t,n=[]){this[e]===t&&n.push(this);const s=this.children;for(let r=0,a=s.length;r<a;r++)s[r].getObjectsByProperty(e,t,n);return n}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ra,e,Y0),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ra,K0,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);const t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);const t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);const t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].traverseVisible(e)}traverseAncestors(e){const t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);const e=this.pivot;if(e!==null){const t=e.x,n=e.y,s=e.z,r=this.matrix.elements;r[12]+=t-r[0]*t-r[4]*n-r[8]*s,r[13]+=n-r[1]*t-r[5]*n-r[9]*s,r[14]+=s-r[2]*t-r[6]*n-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);const t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].updateMatrixWorld(e)}updateWorldMatrix(e,t,n=!1){const s=this.parent;if(e===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||n)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,n=!0),t===!0){const r=this.children;for(let a=0,o=r.length;a<o;a++)r[a].updateWorldMatrix(!1,!0,n)}}toJSON(e){const t=e===void 0||typeof e=="string",n={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},n.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});const s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(o=>({...o,boundingBox:o.boundingBox?o.boundingBox.toJSON():void 0,boundingSphere:o.boundingSphere?o.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(o=>({...o})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(e),s.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(o,l){return o[l.uuid]===void 0&&(o[l.uuid]=l.toJSON(e)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(e.geometries,this.geometry);const o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){const l=o.shapes;if(Array.isArray(l))for(let c=0,h=l.length;c<h;c++){const u=l[c];r(e.shapes,u)}else r(e.shapes,l)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){const o=[];for(let l=0,c=this.material.length;l<c;l++)o.push(r(e.materials,this.material[l]));s.material=o}else s.material=r(e.materials,this.material);if(this.children.length>0){s.children=[];for(let o=0;o<this.children.length;o++)s.children.push(this.children[o].toJSON(e).object)}if(this.animations.length>0){s.animations=[];for(let o=0;o<this.animations.length;o++){const l=this.animations[o];s.animations.push(r(e.animations,l))}}if(t){const o=a(e.geometries),l=a(e.materials),c=a(e.textures),h=a(e.images),u=a(e.shapes),d=a(e.skeletons),m=a(e.animations),_=a(e.nodes);o.length>0&&(n.geometries=o),l.length>0&&(n.materials=l),c.length>0&&(n.textures=c),h.length>0&&(n.images=h),u.length>0&&(n.shapes=u),d.length>0&&(n.skeletons=d),m.length>0&&(n.animations=m),_.length>0&&(n.nodes=_)}return n.object=s,n;function a(o){const l=[];for(const c in o){const h=o[c];delete h.metadata,l.push(h)}return l}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let n=0;n<e.children.length;n++){const s=e.children[n];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}}Sn.DEFAULT_UP=new z(0,1,0);Sn.DEFAULT_MATRIX_AUTO_UPDATE=!0;Sn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;class Wi extends Sn{constructor(){super(),this.isGroup=!0,this.type="Group"}}const J0={type:"move"};class Vl{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Wi,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Wi,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new z,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new z),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Wi,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new z,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new z,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){const t=this._hand;if(t)for(const n of e.hand.values())this._getHandJoint(t,n)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,n){let s=null,r=null,a=null;const o=this._targetRay,l=this._grip,c=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(c&&e.hand){a=!0;for(const M of e.hand.values()){const p=t.getJointPose(M,n),f=this._getHandJoint(c,M);p!==null&&(f.matrix.fromArray(p.transform.matrix),f.matrix.decompose(f.position,f.quaternion,f.scale),f.matrixWorldNeedsUpdate=!0,f.jointRadius=p.radius),f.visible=p!==null}const h=c.joints["index-finger-tip"],u=c.joints["thumb-tip"],d=h.position.distanceTo(u.position),m=.02,_=.005;c.inputState.pinching&&d>m+_?(c.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!c.inputState.pinching&&d<=m-_&&(c.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else l!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,n),r!==null&&(l.matrix.fromArray(r.transform.matrix),l.matrix.decompose(l.position,l.quaternion,l.scale),l.matrixWorldNeedsUpdate=!0,r.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(r.linearVelocity)):l.hasLinearVelocity=!1,r.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(r.angularVelocity)):l.hasAngularVelocity=!1,l.eventsEnabled&&l.dispatchEvent({type:"gripUpdated",data:e,target:this})));o!==null&&(s=t.getPose(e.targetRaySpace,n),s===null&&r!==null&&(s=r),s!==null&&(o.matrix.fromArray(s.transform.matrix),o.matrix.decompose(o.position,o.quaternion,o.scale),o.matrixWorldNeedsUpdate=!0,s.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(s.linearVelocity)):o.hasLinearVelocity=!1,s.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(s.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(J0)))}return o!==null&&(o.visible=s!==null),l!==null&&(l.visible=r!==null),c!==null&&(c.visible=a!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){const n=new Wi;n.matrixAutoUpdate=!1,n.visible=!1,e.joints[t.jointName]=n,e.add(n)}return e.joints[t.jointName]}}const Tp={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},xs={h:0,s:0,l:0},ja={h:0,s:0,l:0};function Gl(i,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?i+(e-i)*6*t:t<1/2?e:t<2/3?i+(e-i)*6*(2/3-t):i}class ct{constructor(e,t,n){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,n)}set(e,t,n){if(t===void 0&&n===void 0){const s=e;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(e,t,n);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=hi){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,xt.colorSpaceToWorking(this,t),this}setRGB(e,t,n,s=xt.workingColorSpace){return this.r=e,this.g=t,this.b=n,xt.colorSpaceToWorking(this,s),this}setHSL(e,t,n,s=xt.workingColorSpace){if(e=F0(e,1),t=mt(t,0,1),n=mt(n,0,1),t===0)this.r=this.g=this.b=n;else{const r=n<=.5?n*(1+t):n+t-n*t,a=2*n-r;this.r=Gl(a,r,e+1/3),this.g=Gl(a,r,e),this.b=Gl(a,r,e-1/3)}return xt.colorSpaceToWorking(this,s),this}setStyle(e,t=hi){function n(r){r!==void 0&&parseFloat(r)<1&&je("Color: Alpha component of "+e+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(e)){let r;const a=s[1],o=s[2];switch(a){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,t);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:je("Color: Unknown color model "+e)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(e)){const r=s[1],a=r.length;if(a===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(a===6)return this.setHex(parseInt(r,16),t);je("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=hi){const n=Tp[e.toLowerCase()];return n!==void 0?this.setHex(n,t):je("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=cs(e.r),this.g=cs(e.g),this.b=cs(e.b),this}copyLinearToSRGB(e){return this.r=Fr(e.r),this.g=Fr(e.g),this.b=Fr(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=hi){return xt.workingToColorSpace(Nn.copy(this),e),Math.round(mt(Nn.r*255,0,255))*65536+Math.round(mt(Nn.g*255,0,255))*256+Math.round(mt(Nn.b*255,0,255))}getHexString(e=hi){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=xt.workingColorSpace){xt.workingToColorSpace(Nn.copy(this),t);const n=Nn.r,s=Nn.g,r=Nn.b,a=Math.max(n,s,r),o=Math.min(n,s,r);let l,c;const h=(o+a)/2;if(o===a)l=0,c=0;else{const u=a-o;switch(c=h<=.5?u/(a+o):u/(2-a-o),a){case n:l=(s-r)/u+(s<r?6:0);break;case s:l=(r-n)/u+2;break;case r:l=(n-s)/u+4;break}l/=6}return e.h=l,e.s=c,e.l=h,e}getRGB(e,t=xt.workingColorSpace){return xt.workingToColorSpace(Nn.copy(this),t),e.r=Nn.r,e.g=Nn.g,e.b=Nn.b,e}getStyle(e=hi){xt.workingToColorSpace(Nn.copy(this),e);const t=Nn.r,n=Nn.g,s=Nn.b;return e!==hi?`color(${e} ${t.toFixed(3)} ${n.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(n*255)},${Math.round(s*255)})`}offsetHSL(e,t,n){return this.getHSL(xs),this.setHSL(xs.h+e,xs.s+t,xs.l+n)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,n){return this.r=e.r+(t.r-e.r)*n,this.g=e.g+(t.g-e.g)*n,this.b=e.b+(t.b-e.b)*n,this}lerpHSL(e,t){this.getHSL(xs),e.getHSL(ja);const n=Fl(xs.h,ja.h,t),s=Fl(xs.s,ja.s,t),r=Fl(xs.l,ja.l,t);return this.setHSL(n,s,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){const t=this.r,n=this.g,s=this.b,r=e.elements;return this.r=r[0]*t+r[3]*n+r[6]*s,this.g=r[1]*t+r[4]*n+r[7]*s,this.b=r[2]*t+r[5]*n+r[8]*s,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}}const Nn=new ct;ct.NAMES=Tp;class Ap extends Sn{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Ds,this.environmentIntensity=1,this.environmentRotation=new Ds,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){const t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}}const yi=new z,ns=new z,Wl=new z,is=new z,gr=new z,_r=new z,Qu=new z,Xl=new z,$l=new z,ql=new z,Yl=new nn,Kl=new nn,Zl=new nn;class pi{constructor(e=new z,t=new z,n=new z){this.a=e,this.b=t,this.c=n}static getNormal(e,t,n,s){s.subVectors(n,t),yi.subVectors(e,t),s.cross(yi);const r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(e,t,n,s,r){yi.subVectors(s,t),ns.subVectors(n,t),Wl.subVectors(e,t);const a=yi.dot(yi),o=yi.dot(ns),l=yi.dot(Wl),c=ns.dot(ns),h=ns.dot(Wl),u=a*c-o*o;if(u===0)return r.set(0,0,0),null;const d=1/u,m=(c*l-o*h)*d,_=(a*h-o*l)*d;return r.set(1-m-_,_,m)}static containsPoint(e,t,n,s){return this.getBarycoord(e,t,n,s,is)===null?!1:is.x>=0&&is.y>=0&&is.x+is.y<=1}static getInterpolation(e,t,n,s,r,a,o,l){return this.getBarycoord(e,t,n,s,is)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(r,is.x),l.addScaledVector(a,is.y),l.addScaledVector(o,is.z),l)}static getInterpolatedAttribute(e,t,n,s,r,a){return Yl.setScalar(0),Kl.setScalar(0),Zl.setScalar(0),Yl.fromBufferAttribute(e,t),Kl.fromBufferAttribute(e,n),Zl.fromBufferAttribute(e,s),a.setScalar(0),a.addScaledVector(Yl,r.x),a.addScaledVector(Kl,r.y),a.addScaledVector(Zl,r.z),a}static isFrontFacing(e,t,n,s){return yi.subVectors(n,t),ns.subVectors(e,t),yi.cross(ns).dot(s)<0}set(e,t,n){return this.a.copy(e),this.b.copy(t),this.c.copy(n),this}setFromPointsAndIndices(e,t,n,s){return this.a.copy(e[t]),this.b.copy(e[n]),this.c.copy(e[s]),this}setFromAttributeAndIndices(e,t,n,s){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,n),this.c.fromBufferAttribute(e,s),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return yi.subVectors(this.c,this.b),ns.subVectors(this.a,this.b),yi.cross(ns).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return pi.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return pi.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,n,s,r){return pi.getInterpolation(e,this.a,this.b,this.c,t,n,s,r)}containsPoint(e){return pi.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return pi.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){const n=this.a,s=this.b,r=this.c;let a,o;gr.subVectors(s,n),_r.subVectors(r,n),Xl.subVectors(e,n);const l=gr.dot(Xl),c=_r.dot(Xl);if(l<=0&&c<=0)return t.copy(n);$l.subVectors(e,s);const h=gr.dot($l),u=_r.dot($l);if(h>=0&&u<=h)return t.copy(s);const d=l*u-h*c;if(d<=0&&l>=0&&h<=0&&l-h>0)return a=l/(l-h),t.copy(n).addScaledVector(gr,a);ql.subVectors(e,r);const m=gr.dot(ql),_=_r.dot(ql);if(_>=0&&m<=_)return t.copy(r);const M=m*c-l*_;if(M<=0&&c>=0&&_<=0)return o=c/(c-_),t.copy(n).addScaledVector(_r,o);const p=h*_-m*u;if(p<=0&&u-h>=0&&m-_>=0)return Qu.subVectors(r,s),o=(u-h)/(u-h+(m-_)),t.copy(s).addScaledVector(Qu,o);const f=1/(p+M+d);return a=M*f,o=d*f,t.copy(n).addScaledVector(gr,a).addScaledVector(_r,o)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}}class Ba{constructor(e=new z(1/0,1/0,1/0),t=new z(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t+=3)this.expandByPoint(bi.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,n=e.count;t<n;t++)this.expandByPoint(bi.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){const n=bi.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(n),this.max.copy(e).add(n),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);const n=e.geometry;if(n!==void 0){const r=n.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let a=0,o=r.count;a<o;a++)e.isMesh===!0?e.getVertexPosition(a,bi):bi.fromBufferAttribute(r,a),bi.applyMatrix4(e.matrixWorld),this.expandByPoint(bi);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),Qa.copy(e.boundingBox)):(n.boundingBox===null&&n.computeBoundingBox(),Qa.copy(n.boundingBox)),Qa.applyMatrix4(e.matrixWorld),this.union(Qa)}const s=e.children;for(let r=0,a=s.length;r<a;r++)this.expandByObject(s[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,bi),bi.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,n;return e.normal.x>0?(t=e.normal.x*this.min.x,n=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,n=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,n+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,n+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,n+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,n+=e.normal.z*this.min.z),t<=-e.constant&&n>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(aa),eo.subVectors(this.max,aa),vr.subVectors(e.a,aa),xr.subVectors(e.b,aa),Sr.subVectors(e.c,aa),Ss.subVectors(xr,vr),Ms.subVectors(Sr,xr),ks.subVectors(vr,Sr);let t=[0,-Ss.z,Ss.y,0,-Ms.z,Ms.y,0,-ks.z,ks.y,Ss.z,0,-Ss.x,Ms.z,0,-Ms.x,ks.z,0,-ks.x,-Ss.y,Ss.x,0,-Ms.y,Ms.x,0,-ks.y,ks.x,0];return!Jl(t,vr,xr,Sr,eo)||(t=[1,0,0,0,1,0,0,0,1],!Jl(t,vr,xr,Sr,eo))?!1:(to.crossVectors(Ss,Ms),t=[to.x,to.y,to.z],Jl(t,vr,xr,Sr,eo))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,bi).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(bi).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(ss[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),ss[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),ss[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),ss[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),ss[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),ss[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),ss[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),ss[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(ss),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}}const ss=[new z,new z,new z,new z,new z,new z,new z,new z],bi=new z,Qa=new Ba,vr=new z,xr=new z,Sr=new z,Ss=new z,Ms=new z,ks=new z,aa=new z,eo=new z,to=new z,Bs=new z;function Jl(i,e,t,n,s){for(let r=0,a=i.length-3;r<=a;r+=3){Bs.fromArray(i,r);const o=s.x*Math.abs(Bs.x)+s.y*Math.abs(Bs.y)+s.z*Math.abs(Bs.z),l=e.dot(Bs),c=t.dot(Bs),h=n.dot(Bs);if(Math.max(-Math.max(l,c,h),Math.min(l,c,h))>o)return!1}return!0}const dn=new z,no=new Xe;let j0=0;class mi extends Is{constructor(e,t,n=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:j0++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=n,this.usage=Mp,this.updateRanges=[],this.gpuType=Vi,this.version=0,this._normalizationScale=e!==void 0?sl(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,n){e*=this.itemSize,n*=t.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[e+s]=t.array[n+s];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,n=this.count;t<n;t++)no.fromBufferAttribute(this,t),no.applyMatrix3(e),this.setXY(t,no.x,no.y);else if(this.itemSize===3)for(let t=0,n=this.count;t<n;t++)dn.fromBufferAttribute(this,t),dn.applyMatrix3(e),this.setXYZ(t,dn.x,dn.y,dn.z);return this}applyMatrix4(e){for(let t=0,n=this.count;t<n;t++)dn.fromBufferAttribute(this,t),dn.applyMatrix4(e),this.setXYZ(t,dn.x,dn.y,dn.z);return this}applyNormalMatrix(e){for(let t=0,n=this.count;t<n;t++)dn.fromBufferAttribute(this,t),dn.applyNormalMatrix(e),this.setXYZ(t,dn.x,dn.y,dn.z);return this}transformDirection(e){for(let t=0,n=this.count;t<n;t++)dn.fromBufferAttribute(this,t),dn.transformDirection(e),this.setXYZ(t,dn.x,dn.y,dn.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let n=this.array[e*this.itemSize+t];return this.normalized&&(n=this._denormalize(n)),n}setComponent(e,t,n){return this.normalized&&(n=this._normalize(n)),this.array[e*this.itemSize+t]=n,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,n){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n)),this.array[e+0]=t,this.array[e+1]=n,this}setXYZ(e,t,n,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=s,this}setXYZW(e,t,n,s,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=s,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){const e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){const t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):bp(e,this.array)}_normalize(e){const t=this._normalizationScale;return t!==void 0?Math.round(e*t):wp(e,this.array)}}class Rp extends mi{constructor(e,t,n){super(new Uint16Array(e),t,n)}}class Cp extends mi{constructor(e,t,n){super(new Uint32Array(e),t,n)}}class rn extends mi{constructor(e,t,n){super(new Float32Array(e),t,n)}}const Q0=new Ba,oa=new z,jl=new z;class za{constructor(e=new z,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){const n=this.center;t!==void 0?n.copy(t):Q0.setFromPoints(e).getCenter(n);let s=0;for(let r=0,a=e.length;r<a;r++)s=Math.max(s,n.distanceToSquared(e[r]));return this.radius=Math.sqrt(s),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){const t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){const n=this.center.distanceToSquared(e);return t.copy(e),n>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;oa.subVectors(e,this.center);const t=oa.lengthSq();if(t>this.radius*this.radius){const n=Math.sqrt(t),s=(n-this.radius)*.5;this.center.addScaledVector(oa,s/n),this.radius+=s}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(jl.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(oa.copy(e.center).add(jl)),this.expandByPoint(oa.copy(e.center).sub(jl))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}}let e_=0;const oi=new Dt,Ql=new Sn,Mr=new z,ei=new Ba,la=new Ba,Rn=new z;class Bt extends Is{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:e_++}),this.uuid=js(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(D0(e)?Cp:Rp)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,n=0){this.groups.push({start:e,count:t,materialIndex:n})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){const t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);const n=this.attributes.normal;if(n!==void 0){const r=new rt().getNormalMatrix(e);n.applyNormalMatrix(r),n.needsUpdate=!0}const s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(e),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return oi.makeRotationFromQuaternion(e),this.applyMatrix4(oi),this}rotateX(e){return oi.makeRotationX(e),this.applyMatrix4(oi),this}rotateY(e){return oi.makeRotationY(e),this.applyMatrix4(oi),this}rotateZ(e){return oi.makeRotationZ(e),this.applyMatrix4(oi),this}translate(e,t,n){return oi.makeTranslation(e,t,n),this.applyMatrix4(oi),this}scale(e,t,n){return oi.makeScale(e,t,n),this.applyMatrix4(oi),this}lookAt(e){return Ql.lookAt(e),Ql.updateMatrix(),this.applyMatrix4(Ql.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(Mr).negate(),this.translate(Mr.x,Mr.y,Mr.z),this}setFromPoints(e){const t=this.getAttribute("position");if(t===void 0){const n=[];for(let s=0,r=e.length;s<r;s++){const a=e[s];n.push(a.x,a.y,a.z||0)}this.setAttribute("position",new rn(n,3))}else{const n=Math.min(e.length,t.count);for(let s=0;s<n;s++){const r=e[s];t.setXYZ(s,r.x,r.y,r.z||0)}e.length>t.count&&je("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Ba);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){St("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new z(-1/0,-1/0,-1/0),new z(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let n=0,s=t.length;n<s;n++){const r=t[n];ei.setFromBufferAttribute(r),this.morphTargetsRelative?(Rn.addVectors(this.boundingBox.min,ei.min),this.boundingBox.expandByPoint(Rn),Rn.addVectors(this.boundingBox.max,ei.max),this.boundingBox.expandByPoint(Rn)):(this.boundingBox.expandByPoint(ei.min),this.boundingBox.expandByPoint(ei.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&St('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new za);const e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){St("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new z,1/0);return}if(e){const n=this.boundingSphere.center;if(ei.setFromBufferAttribute(e),t)for(let r=0,a=t.length;r<a;r++){const o=t[r];la.setFromBufferAttribute(o),this.morphTargetsRelative?(Rn.addVectors(ei.min,la.min),ei.expandByPoint(Rn),Rn.addVectors(ei.max,la.max),ei.expandByPoint(Rn)):(ei.expandByPoint(la.min),ei.expandByPoint(la.max))}ei.getCenter(n);let s=0;for(let r=0,a=e.count;r<a;r++)Rn.fromBufferAttribute(e,r),s=Math.max(s,n.distanceToSquared(Rn));if(t)for(let r=0,a=t.length;r<a;r++){const o=t[r],l=this.morphTargetsRelative;for(let c=0,h=o.count;c<h;c++)Rn.fromBufferAttribute(o,c),l&&(Mr.fromBufferAttribute(e,c),Rn.add(Mr)),s=Math.max(s,n.distanceToSquared(Rn))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&St('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){const e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){St("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}const n=t.position,s=t.normal,r=t.uv;let a=this.getAttribute("tangent");(a===void 0||a.count!==n.count)&&(a=new mi(new Float32Array(4*n.count),4),this.setAttribute("tangent",a));const o=[],l=[],c=new Uint8Array(n.count);for(let k=0;k<n.count;k++)o[k]=new z,l[k]=new z;const h=new z,u=new z,d=new z,m=new Xe,_=new Xe,M=new Xe,p=new z,f=new z;function x(k,I,L){c[k]=c[I]=c[L]=1,h.fromBufferAttribute(n,k),u.fromBufferAttribute(n,I),d.fromBufferAttribute(n,L),m.fromBufferAttribute(r,k),_.fromBufferAttribute(r,I),M.fromBufferAttribute(r,L),u.sub(h),d.sub(h),_.sub(m),M.sub(m);const G=1/(_.x*M.y-M.x*_.y);isFinite(G)&&(p.copy(u).multiplyScalar(M.y).addScaledVector(d,-_.y).multiplyScalar(G),f.copy(d).multiplyScalar(_.x).addScaledVector(u,-M.x).multiplyScalar(G),o[k].add(p),o[I].add(p),o[L].add(p),l[k].add(f),l[I].add(f),l[L].add(f))}let A=this.groups;A.length===0&&(A=[{start:0,count:e.count}]);for(let k=0,I=A.length;k<I;++k){const L=A[k],G=L.start,W=L.count;for(let U=G,X=G+W;U<X;U+=3)x(e.getX(U+0),e.getX(U+1),e.getX(U+2))}const S=new z,R=new z,y=new z,g=new z;function b(k){y.fromBufferAttribute(s,k),g.copy(y);const I=o[k];S.copy(I),S.sub(y.multiplyScalar(y.dot(I))).normalize(),R.crossVectors(g,I);const G=R.dot(l[k])<0?-1:1;a.setXYZW(k,S.x,S.y,S.z,G)}for(let k=0,I=n.count;k<I;++k)c[k]&&b(k);this._transformed=!0}computeVertexNormals(){const e=this.index,t=this.getAttribute("position");if(t!==void 0){let n=this.getAttribute("normal");if(n===void 0||n.count!==t.count)n=new mi(new Float32Array(t.count*3),3),this.setAttribute("normal",n);else for(let d=0,m=n.count;d<m;d++)n.setXYZ(d,0,0,0);const s=new z,r=new z,a=new z,o=new z,l=new z,c=new z,h=new z,u=new z;if(e)for(let d=0,m=e.count;d<m;d+=3){const _=e.getX(d+0),M=e.getX(d+1),p=e.getX(d+2);s.fromBufferAttribute(t,_),r.fromBufferAttribute(t,M),a.fromBufferAttribute(t,p),h.subVectors(a,r),u.subVectors(s,r),h.cross(u),o.fromBufferAttribute(n,_),l.fromBufferAttribute(n,M),c.fromBufferAttribute(n,p),o.add(h),l.add(h),c.add(h),n.setXYZ(_,o.x,o.y,o.z),n.setXYZ(M,l.x,l.y,l.z),n.setXYZ(p,c.x,c.y,c.z)}else for(let d=0,m=t.count;d<m;d+=3)s.fromBufferAttribute(t,d+0),r.fromBufferAttribute(t,d+1),a.fromBufferAttribute(t,d+2),h.subVectors(a,r),u.subVectors(s,r),h.cross(u),n.setXYZ(d+0,h.x,h.y,h.z),n.setXYZ(d+1,h.x,h.y,h.z),n.setXYZ(d+2,h.x,h.y,h.z);this.normalizeNormals(),n.needsUpdate=!0}}normalizeNormals(){const e=this.attributes.normal;for(let t=0,n=e.count;t<n;t++)Rn.fromBufferAttribute(e,t),Rn.normalize(),e.setXYZ(t,Rn.x,Rn.y,Rn.z)}toNonIndexed(){function e(o,l){const c=o.array,h=o.itemSize,u=o.normalized,d=new c.constructor(l.length*h);let m=0,_=0;for(let M=0,p=l.length;M<p;M++){o.isInterleavedBufferAttribute?m=l[M]*o.data.stride+o.offset:m=l[M]*h;for(let f=0;f<h;f++)d[_++]=c[m++]}return new mi(d,h,u)}if(this.index===null)return je("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;const t=new Bt,n=this.index.array,s=this.attributes;for(const o in s){const l=s[o],c=e(l,n);t.setAttribute(o,c)}const r=this.morphAttributes;for(const o in r){const l=[],c=r[o];for(let h=0,u=c.length;h<u;h++){const d=c[h],m=e(d,n);l.push(m)}t.morphAttributes[o]=l}t.morphTargetsRelative=this.morphTargetsRelative;const a=this.groups;for(let o=0,l=a.length;o<l;o++){const c=a[o];t.addGroup(c.start,c.count,c.materialIndex)}return t}toJSON(){const e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){const l=this.parameters;for(const c in l)l[c]!==void 0&&(e[c]=l[c]);return e}e.data={attributes:{}};const t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});const n=this.attributes;for(const l in n){const c=n[l];e.data.attributes[l]=c.toJSON(e.data)}const s={};let r=!1;for(const l in this.morphAttributes){const c=this.morphAttributes[l],h=[];for(let u=0,d=c.length;u<d;u++){const m=c[u];h.push(m.toJSON(e.data))}h.length>0&&(s[l]=h,r=!0)}r&&(e.data.morphAttributes=s,e.data.morphTargetsRelative=this.morphTargetsRelative);const a=this.groups;a.length>0&&(e.data.groups=JSON.parse(JSON.stringify(a)));const o=this.boundingSphere;return o!==null&&(e.data.boundingSphere=o.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;const t={};this.name=e.name;const n=e.index;n!==null&&this.setIndex(n.clone());const s=e.attributes;for(const c in s){const h=s[c];this.setAttribute(c,h.clone(t))}const r=e.morphAttributes;for(const c in r){const h=[],u=r[c];for(let d=0,m=u.length;d<m;d++)h.push(u[d].clone(t));this.morphAttributes[c]=h}this.morphTargetsRelative=e.morphTargetsRelative;const a=e.groups;for(let c=0,h=a.length;c<h;c++){const u=a[c];this.addGroup(u.start,u.count,u.materialIndex)}const o=e.boundingBox;o!==null&&(this.boundingBox=o.clone());const l=e.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}}class t_{constructor(e,t){this.isInterleavedBuffer=!0,this.array=e,this.stride=t,this.count=e!==void 0?e.length/t:0,this.usage=Mp,this.updateRanges=[],this.version=0,this.uuid=js()}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.array=new e.array.constructor(e.array),this.count=e.count,this.stride=e.stride,this.usage=e.usage,this}copyAt(e,t,n){e*=this.stride,n*=t.stride;for(let s=0,r=this.stride;s<r;s++)this.array[e+s]=t.array[n+s];return this}set(e,t=0){return this.array.set(e,t),this}clone(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});const t=ed(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=this.array.slice(0).buffer);const n=new this.array.constructor(e.arrayBuffers[t]),s=new this.constructor(n,this.stride);return s.setUsage(this.usage),s}onUpload(e){return this.onUploadCallback=e,this}toJSON(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});const t=ed(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=Array.from(new Uint32Array(this.array.slice(0).buffer)));const n={uuid:this.uuid,buffer:t,type:this.array.constructor.name,stride:this.stride};return n.usage=this.usage,n}}function ed(i){return i.buffer._uuid===void 0&&(i.buffer._uuid=js()),i.byteOffset===0&&i.byteLength===i.buffer.byteLength?i.buffer._uuid:i.buffer._uuid+":"+i.byteOffset+":"+i.byteLength}const Hn=new z;class Zo{constructor(e,t,n,s=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=e,this.itemSize=t,this.offset=n,this.normalized=s,this._normalizationScale=e!==void 0?sl(e.array):void 0}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(e){this.data.needsUpdate=e}applyMatrix4(e){for(let t=0,n=this.data.count;t<n;t++)Hn.fromBufferAttribute(this,t),Hn.applyMatrix4(e),this.setXYZ(t,Hn.x,Hn.y,Hn.z);return this}applyNormalMatrix(e){for(let t=0,n=this.count;t<n;t++)Hn.fromBufferAttribute(this,t),Hn.applyNormalMatrix(e),this.setXYZ(t,Hn.x,Hn.y,Hn.z);return this}transformDirection(e){for(let t=0,n=this.count;t<n;t++)Hn.fromBufferAttribute(this,t),Hn.transformDirection(e),this.setXYZ(t,Hn.x,Hn.y,Hn.z);return this}getComponent(e,t){let n=this.array[e*this.data.stride+this.offset+t];return this.normalized&&(n=this._denormalize(n)),n}setComponent(e,t,n){return this.normalized&&(n=this._normalize(n)),this.data.array[e*this.data.stride+this.offset+t]=n,this}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset]=t,this}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+1]=t,this}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+2]=t,this}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+3]=t,this}getX(e){let t=this.data.array[e*this.data.stride+this.offset];return this.normalized&&(t=this._denormalize(t)),t}getY(e){let t=this.data.array[e*this.data.stride+this.offset+1];return this.normalized&&(t=this._denormalize(t)),t}getZ(e){let t=this.data.array[e*this.data.stride+this.offset+2];return this.normalized&&(t=this._denormalize(t)),t}getW(e){let t=this.data.array[e*this.data.stride+this.offset+3];return this.normalized&&(t=this._denormalize(t)),t}setXY(e,t,n){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n)),this.data.array[e+0]=t,this.data.array[e+1]=n,this}setXYZ(e,t,n,s){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s)),this.data.array[e+0]=t,this.data.array[e+1]=n,this.data.array[e+2]=s,this}setXYZW(e,t,n,s,r){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.data.array[e+0]=t,this.data.array[e+1]=n,this.data.array[e+2]=s,this.data.array[e+3]=r,this}clone(e){if(e===void 0){Ko("InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let n=0;n<this.count;n++){const s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return new mi(new this.array.constructor(t),this.itemSize,this.normalized)}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.clone(e)),new Zo(e.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(e){if(e===void 0){Ko("InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");const t=[];for(let n=0;n<this.count;n++){const s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:t,normalized:this.normalized}}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.toJSON(e)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}_denormalize(e){const t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):bp(e,this.data.array)}_normalize(e){const t=this._normalizationScale;return t!==void 0?Math.round(e*t):wp(e,this.data.array)}}const ec=new z,n_=new z,i_=new rt;class Ti{constructor(e=new z(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,n,s){return this.normal.set(e,t,n),this.constant=s,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,n){const s=ec.subVectors(n,t).cross(n_.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(s,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){const e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,n=!0){const s=e.delta(ec),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;const a=-(e.start.dot(this.normal)+this.constant)/r;return n===!0&&(a<0||a>1)?null:t.copy(e.start).addScaledVector(s,a)}intersectsLine(e){const t=this.distanceToPoint(e.start),n=this.distanceToPoint(e.end);return t<0&&n>0||n<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){const n=t||i_.getNormalMatrix(e),s=this.coplanarPoint(ec).applyMatrix4(e),r=this.normal.applyMatrix3(n).normalize();return this.constant=-s.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}}let s_=0;class Qs extends Is{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:s_++}),this.uuid=js(),this.name="",this.type="Material",this.blending=ya,this.side=Cs,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=ep,this.blendDst=tp,this.blendEquation=Lr,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new ct(0,0,0),this.blendAlpha=0,this.depthFunc=Ca,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=T0,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=Ul,this.stencilZFail=Ul,this.stencilZPass=Ul,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(const t in e){const n=e[t];if(n===void 0){je(`Material: parameter '${t}' has value of undefined.`);continue}const s=this[t];if(s===void 0){je(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(n):s&&s.isVector2&&n&&n.isVector2||s&&s.isEuler&&n&&n.isEuler||s&&s.isVector3&&n&&n.isVector3?s.copy(n):this[t]=n}}toJSON(e){const t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});const n={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};n.uuid=this.uuid,n.type=this.type,n.blending=this.blending,n.side=this.side,n.shadowSide=this.shadowSide,n.vertexColors=this.vertexColors,n.opacity=this.opacity,n.transparent=this.transparent,n.blendSrc=this.blendSrc,n.blendDst=this.blendDst,n.blendEquation=this.blendEquation,n.blendSrcAlpha=this.blendSrcAlpha,n.blendDstAlpha=this.blendDstAlpha,n.blendEquationAlpha=this.blendEquationAlpha,n.blendColor=this.blendColor.getHex(),n.blendAlpha=this.blendAlpha,n.depthFunc=this.depthFunc,n.depthTest=this.depthTest,n.depthWrite=this.depthWrite,n.colorWrite=this.colorWrite,n.clipIntersection=this.clipIntersection,n.clipShadows=this.clipShadows,n.stencilWriteMask=this.stencilWriteMask,n.stencilFunc=this.stencilFunc,n.stencilRef=this.stencilRef,n.stencilFuncMask=this.stencilFuncMask,n.stencilFail=this.stencilFail,n.stencilZFail=this.stencilZFail,n.stencilZPass=this.stencilZPass,n.stencilWrite=this.stencilWrite,n.polygonOffset=this.polygonOffset,n.polygonOffsetFactor=this.polygonOffsetFactor,n.polygonOffsetUnits=this.polygonOffsetUnits,n.dithering=this.dithering,n.alphaTest=this.alphaTest,n.alphaHash=this.alphaHash,n.alphaToCoverage=this.alphaToCoverage,n.premultipliedAlpha=this.premultipliedAlpha,n.forceSinglePass=this.forceSinglePass,n.allowOverride=this.allowOverride,n.visible=this.visible,n.toneMapped=this.toneMapped,n.name=this.name,this.color&&this.color.isColor&&(n.color=this.color.getHex()),this.roughness!==void 0&&(n.roughness=this.roughness),this.metalness!==void 0&&(n.metalness=this.metalness),this.sheen!==void 0&&(n.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(n.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(n.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(n.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(n.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(n.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(n.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(n.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(n.shininess=this.shininess),this.clearcoat!==void 0&&(n.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(n.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(n.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(n.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(n.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(n.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(n.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,n.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(n.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(n.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(n.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(n.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(n.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(n.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(n.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(n.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(n.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(n.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(n.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(n.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(n.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(n.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(n.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(n.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(n.lightMap=this.lightMap.toJSON(e).uuid,n.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(n.aoMap=this.aoMap.toJSON(e).uuid,n.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(n.bumpMap=this.bumpMap.toJSON(e).uuid,n.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(n.normalMap=this.normalMap.toJSON(e).uuid,n.normalMapType=this.normalMapType,n.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(n.displacementMap=this.displacementMap.toJSON(e).uuid,n.displacementScale=this.displacementScale,n.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(n.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(n.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(n.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(n.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(n.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(n.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(n.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(n.combine=this.combine)),this.envMapRotation!==void 0&&(n.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(n.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(n.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(n.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(n.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(n.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(n.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(n.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(n.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(n.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(n.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(n.size=this.size),this.sizeAttenuation!==void 0&&(n.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(n.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(n.rotation=this.rotation),this.depthPacking!==void 0&&(n.depthPacking=this.depthPacking),this.linewidth!==void 0&&(n.linewidth=this.linewidth),this.linecap!==void 0&&(n.linecap=this.linecap),this.linejoin!==void 0&&(n.linejoin=this.linejoin),this.dashSize!==void 0&&(n.dashSize=this.dashSize),this.gapSize!==void 0&&(n.gapSize=this.gapSize),this.scale!==void 0&&(n.scale=this.scale),this.wireframe!==void 0&&(n.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(n.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(n.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(n.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(n.flatShading=this.flatShading),this.fog!==void 0&&(n.fog=this.fog),Object.keys(this.userData).length>0&&(n.userData=this.userData);function s(r){const a=[];for(const o in r){const l=r[o];delete l.metadata,a.push(l)}return a}if(t){const r=s(e.textures),a=s(e.images);r.length>0&&(n.textures=r),a.length>0&&(n.images=a)}return n}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new ct().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(n=>new Ti().fromJSON(n))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let n=e.normalScale;Array.isArray(n)===!1&&(n=[n,n]),this.normalScale=new Xe().fromArray(n)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new Xe().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;const t=e.clippingPlanes;let n=null;if(t!==null){const s=t.length;n=new Array(s);for(let r=0;r!==s;++r)n[r]=t[r].clone()}return this.clippingPlanes=n,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}}class Pp extends Qs{constructor(e){super(),this.isSpriteMaterial=!0,this.type="SpriteMaterial",this.color=new ct(16777215),this.map=null,this.alphaMap=null,this.rotation=0,this.sizeAttenuation=!0,this.transparent=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.rotation=e.rotation,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}}let yr;const ca=new z,br=new z,wr=new z,Er=new Xe,ha=new Xe,Lp=new Dt,io=new z,ua=new z,so=new z,td=new Xe,tc=new Xe,nd=new Xe;class Dp extends Sn{constructor(e=new Pp){if(super(),this.isSprite=!0,this.type="Sprite",yr===void 0){yr=new Bt;const t=new Float32Array([-.5,-.5,0,0,0,.5,-.5,0,1,0,.5,.5,0,1,1,-.5,.5,0,0,1]),n=new t_(t,5);yr.setIndex([0,1,2,0,2,3]),yr.setAttribute("position",new Zo(n,3,0,!1)),yr.setAttribute("uv",new Zo(n,2,3,!1))}this.geometry=yr,this.material=e,this.center=new Xe(.5,.5),this.count=1}intersectsFrustum(e){return e.intersectsSprite(this)}raycast(e,t){e.camera===null&&St('Sprite: "Raycaster.camera" needs to be set in order to raycast against sprites.'),br.setFromMatrixScale(this.matrixWorld),Lp.copy(e.camera.matrixWorld),this.modelViewMatrix.multiplyMatrices(e.camera.matrixWorldInverse,this.matrixWorld),wr.setFromMatrixPosition(this.modelViewMatrix),e.camera.isPerspectiveCamera&&this.material.sizeAttenuation===!1&&br.multiplyScalar(-wr.z);const n=this.material.rotation;let s,r;n!==0&&(r=Math.cos(n),s=Math.sin(n));const a=this.center;ro(io.set(-.5,-.5,0),wr,a,br,s,r),ro(ua.set(.5,-.5,0),wr,a,br,s,r),ro(so.set(.5,.5,0),wr,a,br,s,r),td.set(0,0),tc.set(1,0),nd.set(1,1);let o=e.ray.intersectTriangle(io,ua,so,!1,ca);if(o===null&&(ro(ua.set(-.5,.5,0),wr,a,br,s,r),tc.set(0,1),o=e.ray.intersectTriangle(io,so,ua,!1,ca),o===null))return;const l=e.ray.origin.distanceTo(ca);l<e.near||l>e.far||t.push({distance:l,point:ca.clone(),uv:pi.getInterpolation(ca,io,ua,so,td,tc,nd,new Xe),face:null,object:this})}copy(e,t){return super.copy(e,t),e.center!==void 0&&this.center.copy(e.center),this.material=e.material,this}toJSON(e){const t=super.toJSON(e);return t.object.center=this.center.toArray(),t}}function ro(i,e,t,n,s,r){Er.subVectors(i,t).addScalar(.5).multiply(n),s!==void 0?(ha.x=r*Er.x-s*Er.y,ha.y=s*Er.x+r*Er.y):ha.copy(Er),i.copy(e),i.x+=ha.x,i.y+=ha.y,i.applyMatrix4(Lp)}const rs=new z,nc=new z,ao=new z,oo=new z;class rl{constructor(e=new z,t=new z(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,rs)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);const n=t.dot(this.direction);return n<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,n)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){const t=rs.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(rs.copy(this.origin).addScaledVector(this.direction,t),rs.distanceToSquared(e))}distanceSqToSegment(e,t,n,s){nc.copy(e).add(t).multiplyScalar(.5),ao.copy(t).sub(e).normalize(),oo.copy(this.origin).sub(nc);const r=e.distanceTo(t)*.5,a=-this.direction.dot(ao),o=oo.dot(this.direction),l=-oo.dot(ao),c=oo.lengthSq(),h=Math.abs(1-a*a);let u,d,m,_;if(h>0)if(u=a*l-o,d=a*o-l,_=r*h,u>=0)if(d>=-_)if(d<=_){const M=1/h;u*=M,d*=M,m=u*(u+a*d+2*o)+d*(a*u+d+2*l)+c}else d=r,u=Math.max(0,-(a*d+o)),m=-u*u+d*(d+2*l)+c;else d=-r,u=Math.max(0,-(a*d+o)),m=-u*u+d*(d+2*l)+c;else d<=-_?(u=Math.max(0,-(-a*r+o)),d=u>0?-r:Math.min(Math.max(-r,-l),r),m=-u*u+d*(d+2*l)+c):d<=_?(u=0,d=Math.min(Math.max(-r,-l),r),m=d*(d+2*l)+c):(u=Math.max(0,-(a*r+o)),d=u>0?r:Math.min(Math.max(-r,-l),r),m=-u*u+d*(d+2*l)+c);else d=a>0?-r:r,u=Math.max(0,-(a*d+o)),m=-u*u+d*(d+2*l)+c;return n&&n.copy(this.origin).addScaledVector(this.direction,u),s&&s.copy(nc).addScaledVector(ao,d),m}intersectSphere(e,t){if(e.radius<0)return null;rs.subVectors(e.center,this.origin);const n=rs.dot(this.direction),s=rs.dot(rs)-n*n,r=e.radius*e.radius;if(s>r)return null;const a=Math.sqrt(r-s),o=n-a,l=n+a;return l<0?null:o<0?this.at(l,t):this.at(o,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){const t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;const n=-(this.origin.dot(e.normal)+e.constant)/t;return n>=0?n:null}intersectPlane(e,t){const n=this.distanceToPlane(e);return n===null?null:this.at(n,t)}intersectsPlane(e){const t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let n,s,r,a,o,l;const c=1/this.direction.x,h=1/this.direction.y,u=1/this.direction.z,d=this.origin;return c>=0?(n=(e.min.x-d.x)*c,s=(e.max.x-d.x)*c):(n=(e.max.x-d.x)*c,s=(e.min.x-d.x)*c),h>=0?(r=(e.min.y-d.y)*h,a=(e.max.y-d.y)*h):(r=(e.max.y-d.y)*h,a=(e.min.y-d.y)*h),n>a||r>s||((r>n||isNaN(n))&&(n=r),(a<s||isNaN(s))&&(s=a),u>=0?(o=(e.min.z-d.z)*u,l=(e.max.z-d.z)*u):(o=(e.max.z-d.z)*u,l=(e.min.z-d.z)*u),n>l||o>s)||((o>n||n!==n)&&(n=o),(l<s||s!==s)&&(s=l),s<0)?null:this.at(n>=0?n:s,t)}intersectsBox(e){return this.intersectBox(e,rs)!==null}intersectTriangle(e,t,n,s,r){const a=this.origin,o=this.direction,l=o.x,c=o.y,h=o.z,u=e.x-a.x,d=e.y-a.y,m=e.z-a.z,_=t.x-a.x,M=t.y-a.y,p=t.z-a.z,f=n.x-a.x,x=n.y-a.y,A=n.z-a.z,S=Math.abs(l),R=Math.abs(c),y=Math.abs(h);let g,b,k,I,L,G,W,U,X,J,H,ce;if(S>=R&&S>=y?(k=l,G=u,X=_,ce=f,l>=0?(g=c,b=h,I=d,L=m,W=M,U=p,J=x,H=A):(g=h,b=c,I=m,L=d,W=p,U=M,J=A,H=x)):R>=y?(k=c,G=d,X=M,ce=x,c>=0?(g=h,b=l,I=m,L=u,W=p,U=_,J=A,H=f):(g=l,b=h,I=u,L=m,W=_,U=p,J=f,H=A)):(k=h,G=m,X=p,ce=A,h>=0?(g=l,b=c,I=u,L=d,W=_,U=M,J=f,H=x):(g=c,b=l,I=d,L=u,W=M,U=_,J=x,H=f)),k===0)return null;const Z=g/k,ee=b/k,se=1/k,pe=I-Z*G,fe=L-ee*G,B=W-Z*X,te=U-ee*X,he=J-Z*ce,ge=H-ee*ce,ve=he*te-ge*B,Ve=pe*ge-fe*he,Qe=B*fe-te*pe;if(s){if(ve<0||Ve<0||Qe<0)return null}else if((ve<0||Ve<0||Qe<0)&&(ve>0||Ve>0||Qe>0))return null;const ze=ve+Ve+Qe;if(ze===0)return null;const nt=se*(ve*G+Ve*X+Qe*ce);return(ze>0?nt<0:nt>0)?null:this.at(nt/ze,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}}class Rs extends Qs{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new ct(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ds,this.combine=np,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}}const id=new Dt,zs=new rl,lo=new za,sd=new z,co=new z,ho=new z,uo=new z,ic=new z,fo=new z,rd=new z,po=new z;class sn extends Sn{constructor(e=new Bt,t=new Rs){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){const t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){const s=t[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}getVertexPosition(e,t){const n=this.geometry,s=n.attributes.position,r=n.morphAttributes.position,a=n.morphTargetsRelative;t.fromBufferAttribute(s,e);const o=this.morphTargetInfluences;if(r&&o){fo.set(0,0,0);for(let l=0,c=r.length;l<c;l++){const h=o[l],u=r[l];h!==0&&(ic.fromBufferAttribute(u,e),a?fo.addScaledVector(ic,h):fo.addScaledVector(ic.sub(t),h))}t.add(fo)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){const n=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(n.boundingSphere===null&&n.computeBoundingSphere(),lo.copy(n.boundingSphere),lo.applyMatrix4(r),zs.copy(e.ray).recast(e.near),!(lo.containsPoint(zs.origin)===!1&&(zs.intersectSphere(lo,sd)===null||zs.origin.distanceToSquared(sd)>(e.far-e.near)**2))&&(id.copy(r).invert(),zs.copy(e.ray).applyMatrix4(id),!(n.boundingBox!==null&&zs.intersectsBox(n.boundingBox)===!1)&&this._computeIntersections(e,t,zs)))}_computeIntersections(e,t,n){let s;const r=this.geometry,a=this.material,o=r.index,l=r.attributes.position,c=r.attributes.uv,h=r.attributes.uv1,u=r.attributes.normal,d=r.groups,m=r.drawRange;if(o!==null)if(Array.isArray(a))for(let _=0,M=d.length;_<M;_++){const p=d[_],f=a[p.materialIndex],x=Math.max(p.start,m.start),A=Math.min(o.count,Math.min(p.start+p.count,m.start+m.count));for(let S=x,R=A;S<R;S+=3){const y=o.getX(S),g=o.getX(S+1),b=o.getX(S+2);s=mo(this,f,e,n,c,h,u,y,g,b),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{const _=Math.max(0,m.start),M=Math.min(o.count,m.start+m.count);for(let p=_,f=M;p<f;p+=3){const x=o.getX(p),A=o.getX(p+1),S=o.getX(p+2);s=mo(this,a,e,n,c,h,u,x,A,S),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}else if(l!==void 0)if(Array.isArray(a))for(let _=0,M=d.length;_<M;_++){const p=d[_],f=a[p.materialIndex],x=Math.max(p.start,m.start),A=Math.min(l.count,Math.min(p.start+p.count,m.start+m.count));for(let S=x,R=A;S<R;S+=3){const y=S,g=S+1,b=S+2;s=mo(this,f,e,n,c,h,u,y,g,b),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{const _=Math.max(0,m.start),M=Math.min(l.count,m.start+m.count);for(let p=_,f=M;p<f;p+=3){const x=p,A=p+1,S=p+2;s=mo(this,a,e,n,c,h,u,x,A,S),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}}}function r_(i,e,t,n,s,r,a,o){let l;if(e.side===Yn?l=n.intersectTriangle(a,r,s,!0,o):l=n.intersectTriangle(s,r,a,e.side===Cs,o),l===null)return null;po.copy(o),po.applyMatrix4(i.matrixWorld);const c=t.ray.origin.distanceTo(po);return c<t.near||c>t.far?null:{distance:c,point:po.clone(),object:i}}function mo(i,e,t,n,s,r,a,o,l,c){i.getVertexPosition(o,co),i.getVertexPosition(l,ho),i.getVertexPosition(c,uo);const h=r_(i,e,t,n,co,ho,uo,rd);if(h){const u=new z;pi.getBarycoord(rd,co,ho,uo,u),s&&(h.uv=pi.getInterpolatedAttribute(s,o,l,c,u,new Xe)),r&&(h.uv1=pi.getInterpolatedAttribute(r,o,l,c,u,new Xe)),a&&(h.normal=pi.getInterpolatedAttribute(a,o,l,c,u,new z),h.normal.dot(n.direction)>0&&h.normal.multiplyScalar(-1));const d={a:o,b:l,c,normal:new z,materialIndex:0};pi.getNormal(co,ho,uo,d.normal),h.face=d,h.barycoord=u}return h}class a_ extends In{constructor(e=null,t=1,n=1,s,r,a,o,l,c=Pn,h=Pn,u,d){super(null,a,o,l,c,h,s,r,u,d),this.isDataTexture=!0,this.image={data:e,width:t,height:n},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}}const Hs=new za,o_=new Xe(.5,.5),go=new z;class Na{constructor(e=new Ti,t=new Ti,n=new Ti,s=new Ti,r=new Ti,a=new Ti){this.planes=[e,t,n,s,r,a]}set(e,t,n,s,r,a){const o=this.planes;return o[0].copy(e),o[1].copy(t),o[2].copy(n),o[3].copy(s),o[4].copy(r),o[5].copy(a),this}copy(e){const t=this.planes;for(let n=0;n<6;n++)t[n].copy(e.planes[n]);return this}setFromProjectionMatrix(e,t=Ri,n=!1){const s=this.planes,r=e.elements,a=r[0],o=r[1],l=r[2],c=r[3],h=r[4],u=r[5],d=r[6],m=r[7],_=r[8],M=r[9],p=r[10],f=r[11],x=r[12],A=r[13],S=r[14],R=r[15];if(s[0].setComponents(c-a,m-h,f-_,R-x).normalize(),s[1].setComponents(c+a,m+h,f+_,R+x).normalize(),s[2].setComponents(c+o,m+u,f+M,R+A).normalize(),s[3].setComponents(c-o,m-u,f-M,R-A).normalize(),n)s[4].setComponents(l,d,p,S).normalize(),s[5].setComponents(c-l,m-d,f-p,R-S).normalize();else if(s[4].setComponents(c-l,m-d,f-p,R-S).normalize(),t===Ri)s[5].setComponents(c+l,m+d,f+p,R+S).normalize();else if(t===Da)s[5].setComponents(l,d,p,S).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Hs.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{const t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Hs.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Hs)}intersectsSprite(e){Hs.center.set(0,0,0);const t=o_.distanceTo(e.center);return Hs.radius=.7071067811865476+t,Hs.applyMatrix4(e.matrixWorld),this.intersectsSphere(Hs)}intersectsSphere(e){const t=this.planes,n=e.center,s=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(n)<s)return!1;return!0}intersectsBox(e){const t=this.planes;for(let n=0;n<6;n++){const s=t[n];if(go.x=s.normal.x>0?e.max.x:e.min.x,go.y=s.normal.y>0?e.max.y:e.min.y,go.z=s.normal.z>0?e.max.z:e.min.z,s.distanceToPoint(go)<0)return!1}return!0}containsPoint(e){const t=this.planes;for(let n=0;n<6;n++)if(t[n].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}}const ad=new Dt;class Yh{constructor(){this.coordinateSystem=Ri,this._frustums=[],this._count=0}setFromArrayCamera(e){const t=e.cameras,n=this._frustums;for(let s=0;s<t.length;s++){const r=t[s];ad.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),n[s]===void 0&&(n[s]=new Na),n[s].setFromProjectionMatrix(ad,r.coordinateSystem,r.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsObject(e))return!0;return!1}intersectsSprite(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsSprite(e))return!0;return!1}intersectsSphere(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsSphere(e))return!0;return!1}intersectsBox(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsBox(e))return!0;return!1}containsPoint(e){const t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;const t=this._frustums,n=e._frustums;for(let s=0;s<e._count;s++)t[s]===void 0&&(t[s]=new Na),t[s].copy(n[s]);return this._count=e._count,this}clone(){return new Yh().copy(this)}}class gi extends Qs{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new ct(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}}const Jo=new z,jo=new z,od=new Dt,da=new rl,_o=new za,sc=new z,ld=new z;class Ki extends Sn{constructor(e=new Bt,t=new gi){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,n=[0];for(let s=1,r=t.count;s<r;s++)Jo.fromBufferAttribute(t,s-1),jo.fromBufferAttribute(t,s),n[s]=n[s-1],n[s]+=Jo.distanceTo(jo);e.setAttribute("lineDistance",new rn(n,1))}else je("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){const n=this.geometry,s=this.matrixWorld,r=e.params.Line.threshold,a=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),_o.copy(n.boundingSphere),_o.applyMatrix4(s),_o.radius+=r,e.ray.intersectsSphere(_o)===!1)return;od.copy(s).invert(),da.copy(e.ray).applyMatrix4(od);const o=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=o*o,c=this.isLineSegments?2:1,h=n.index,d=n.attributes.position;if(h!==null){const m=Math.max(0,a.start),_=Math.min(h.count,a.start+a.count);for(let M=m,p=_-1;M<p;M+=c){const f=h.getX(M),x=h.getX(M+1),A=vo(this,e,da,l,f,x,M);A&&t.push(A)}if(this.isLineLoop){const M=h.getX(_-1),p=h.getX(m),f=vo(this,e,da,l,M,p,_-1);f&&t.push(f)}}else{const m=Math.max(0,a.start),_=Math.min(d.count,a.start+a.count);for(let M=m,p=_-1;M<p;M+=c){const f=vo(this,e,da,l,M,M+1,M);f&&t.push(f)}if(this.isLineLoop){const M=vo(this,e,da,l,_-1,m,_-1);M&&t.push(M)}}}updateMorphTargets(){const t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){const s=t[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}}function vo(i,e,t,n,s,r,a){const o=i.geometry.attributes.position;if(Jo.fromBufferAttribute(o,s),jo.fromBufferAttribute(o,r),t.distanceSqToSegment(Jo,jo,sc,ld)>n)return;sc.applyMatrix4(i.matrixWorld);const c=e.ray.origin.distanceTo(sc);if(!(c<e.near||c>e.far))return{distance:c,point:ld.clone().applyMatrix4(i.matrixWorld),index:a,face:null,faceIndex:null,barycoord:null,object:i}}const cd=new z,hd=new z;class al extends Ki{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){const e=this.geometry;if(e.index===null){const t=e.attributes.position,n=[];for(let s=0,r=t.count;s<r;s+=2)cd.fromBufferAttribute(t,s),hd.fromBufferAttribute(t,s+1),n[s]=s===0?0:n[s-1],n[s+1]=n[s]+cd.distanceTo(hd);e.setAttribute("lineDistance",new rn(n,1))}else je("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}}class l_ extends Ki{constructor(e,t){super(e,t),this.isLineLoop=!0,this.type="LineLoop"}}class Np extends In{constructor(e=[],t=Br,n,s,r,a,o,l,c,h){super(e,t,n,s,r,a,o,l,c,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}}class c_ extends In{constructor(e,t,n,s,r,a,o,l,c){super(e,t,n,s,r,a,o,l,c),this.isCanvasTexture=!0,this.needsUpdate=!0}}class Hr extends In{constructor(e,t,n=qi,s,r,a,o=Pn,l=Pn,c,h=Ps,u=1){if(h!==Ps&&h!==As)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");const d={width:e,height:t,depth:u};super(d,s,r,a,o,l,h,n,c),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new $h(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){const t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}}class Ip extends Hr{constructor(e,t=qi,n=Br,s,r,a=Pn,o=Pn,l,c=Ps){const h={width:e,height:e,depth:1},u=[h,h,h,h,h,h];super(e,e,t,n,s,r,a,o,l,c),this.image=u,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}}class Up extends In{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}}class Ha extends Bt{constructor(e=1,t=1,n=1,s=1,r=1,a=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:n,widthSegments:s,heightSegments:r,depthSegments:a};const o=this;s=Math.floor(s),r=Math.floor(r),a=Math.floor(a);const l=[],c=[],h=[],u=[];let d=0,m=0;_("z","y","x",-1,-1,n,t,e,a,r,0),_("z","y","x",1,-1,n,t,-e,a,r,1),_("x","z","y",1,1,e,n,t,s,a,2),_("x","z","y",1,-1,e,n,-t,s,a,3),_("x","y","z",1,-1,e,t,n,s,r,4),_("x","y","z",-1,-1,e,t,-n,s,r,5),this.setIndex(l),this.setAttribute("position",new rn(c,3)),this.setAttribute("normal",new rn(h,3)),this.setAttribute("uv",new rn(u,2));function _(M,p,f,x,A,S,R,y,g,b,k){const I=S/g,L=R/b,G=S/2,W=R/2,U=y/2,X=g+1,J=b+1;let H=0,ce=0;const Z=new z;for(let ee=0;ee<J;ee++){const se=ee*L-W;for(let pe=0;pe<X;pe++){const fe=pe*I-G;Z[M]=fe*x,Z[p]=se*A,Z[f]=U,c.push(Z.x,Z.y,Z.z),Z[M]=0,Z[p]=0,Z[f]=y>0?1:-1,h.push(Z.x,Z.y,Z.z),u.push(pe/g),u.push(1-ee/b),H+=1}}for(let ee=0;ee<b;ee++)for(let se=0;se<g;se++){const pe=d+se+X*ee,fe=d+se+X*(ee+1),B=d+(se+1)+X*(ee+1),te=d+(se+1)+X*ee;l.push(pe,fe,te),l.push(fe,B,te),ce+=6}o.addGroup(m,ce,k),m+=ce,d+=H}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Ha(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}}class Va extends Bt{constructor(e=1,t=1,n=1,s=32,r=1,a=!1,o=0,l=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:e,radiusBottom:t,height:n,radialSegments:s,heightSegments:r,openEnded:a,thetaStart:o,thetaLength:l};const c=this;s=Math.floor(s),r=Math.floor(r);const h=[],u=[],d=[],m=[];let _=0;const M=[],p=n/2;let f=0;x(),a===!1&&(e>0&&A(!0),t>0&&A(!1)),this.setIndex(h),this.setAttribute("position",new rn(u,3)),this.setAttribute("normal",new rn(d,3)),this.setAttribute("uv",new rn(m,2));function x(){const S=new z,R=new z;let y=0;const g=(t-e)/n;for(let b=0;b<=r;b++){const k=[],I=b/r,L=I*(t-e)+e;for(let G=0;G<=s;G++){const W=G/s,U=W*l+o,X=Math.sin(U),J=Math.cos(U);R.x=L*X,R.y=-I*n+p,R.z=L*J,u.push(R.x,R.y,R.z),S.set(X,g,J).normalize(),d.push(S.x,S.y,S.z),m.push(W,1-I),k.push(_++)}M.push(k)}for(let b=0;b<s;b++)for(let k=0;k<r;k++){const I=M[k][b],L=M[k+1][b],G=M[k+1][b+1],W=M[k][b+1];(e>0||k!==0)&&(h.push(I,L,W),y+=3),(t>0||k!==r-1)&&(h.push(L,G,W),y+=3)}c.addGroup(f,y,0),f+=y}function A(S){const R=_,y=new Xe,g=new z;let b=0;const k=S===!0?e:t,I=S===!0?1:-1;for(let G=1;G<=s;G++)u.push(0,p*I,0),d.push(0,I,0),m.push(.5,.5),_++;const L=_;for(let G=0;G<=s;G++){const U=G/s*l+o,X=Math.cos(U),J=Math.sin(U);g.x=k*J,g.y=p*I,g.z=k*X,u.push(g.x,g.y,g.z),d.push(0,I,0),y.x=X*.5+.5,y.y=J*.5*I+.5,m.push(y.x,y.y),_++}for(let G=0;G<s;G++){const W=R+G,U=L+G;S===!0?h.push(U,U+1,W):h.push(U+1,U,W),b+=3}c.addGroup(f,b,S===!0?1:2),f+=b}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new Va(e.radiusTop,e.radiusBottom,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}}class Kh extends Va{constructor(e=1,t=1,n=32,s=1,r=!1,a=0,o=Math.PI*2){super(0,e,t,n,s,r,a,o),this.type="ConeGeometry",this.parameters={radius:e,height:t,radialSegments:n,heightSegments:s,openEnded:r,thetaStart:a,thetaLength:o}}static fromJSON(e){return new Kh(e.radius,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}}class ol extends Bt{constructor(e=1,t=1,n=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:n,heightSegments:s};const r=e/2,a=t/2,o=Math.floor(n),l=Math.floor(s),c=o+1,h=l+1,u=e/o,d=t/l,m=[],_=[],M=[],p=[];for(let f=0;f<h;f++){const x=f*d-a;for(let A=0;A<c;A++){const S=A*u-r;_.push(S,-x,0),M.push(0,0,1),p.push(A/o),p.push(1-f/l)}}for(let f=0;f<l;f++)for(let x=0;x<o;x++){const A=x+c*f,S=x+c*(f+1),R=x+1+c*(f+1),y=x+1+c*f;m.push(A,S,y),m.push(S,R,y)}this.setIndex(m),this.setAttribute("position",new rn(_,3)),this.setAttribute("normal",new rn(M,3)),this.setAttribute("uv",new rn(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new ol(e.width,e.height,e.widthSegments,e.heightSegments)}}class os extends Bt{constructor(e=1,t=32,n=16,s=0,r=Math.PI*2,a=0,o=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:e,widthSegments:t,heightSegments:n,phiStart:s,phiLength:r,thetaStart:a,thetaLength:o},t=Math.max(3,Math.floor(t)),n=Math.max(2,Math.floor(n));const l=Math.min(a+o,Math.PI);let c=0;const h=[],u=new z,d=new z,m=[],_=[],M=[],p=[];for(let f=0;f<=n;f++){const x=[],A=f/n,S=a+A*o,R=e*Math.cos(S),y=Math.sqrt(e*e-R*R);let g=0;f===0&&a===0?g=.5/t:f===n&&l===Math.PI&&(g=-.5/t);for(let b=0;b<=t;b++){const k=b/t,I=s+k*r;u.x=-y*Math.cos(I),u.y=R,u.z=y*Math.sin(I),_.push(u.x,u.y,u.z),d.copy(u).normalize(),M.push(d.x,d.y,d.z),p.push(k+g,1-A),x.push(c++)}h.push(x)}for(let f=0;f<n;f++)for(let x=0;x<t;x++){const A=h[f][x+1],S=h[f][x],R=h[f+1][x],y=h[f+1][x+1];(f!==0||a>0)&&m.push(A,S,y),(f!==n-1||l<Math.PI)&&m.push(S,R,y)}this.setIndex(m),this.setAttribute("position",new rn(_,3)),this.setAttribute("normal",new rn(M,3)),this.setAttribute("uv",new rn(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new os(e.radius,e.widthSegments,e.heightSegments,e.phiStart,e.phiLength,e.thetaStart,e.thetaLength)}}function Vr(i){const e={};for(const t in i){e[t]={};for(const n in i[t]){const s=i[t][n];if(ud(s))s.isRenderTargetTexture?(je("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][n]=null):e[t][n]=s.clone();else if(Array.isArray(s))if(ud(s[0])){const r=[];for(let a=0,o=s.length;a<o;a++)r[a]=s[a].clone();e[t][n]=r}else e[t][n]=s.slice();else e[t][n]=s}}return e}function Vn(i){const e={};for(let t=0;t<i.length;t++){const n=Vr(i[t]);for(const s in n)e[s]=n[s]}return e}function ud(i){return i&&(i.isColor||i.isMatrix3||i.isMatrix4||i.isVector2||i.isVector3||i.isVector4||i.isTexture||i.isQuaternion)}function h_(i){const e=[];for(let t=0;t<i.length;t++)e.push(i[t].clone());return e}function Fp(i){const e=i.getRenderTarget();return e===null?i.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:xt.workingColorSpace}const u_={clone:Vr,merge:Vn};var d_=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,f_=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`;class Zs extends Qs{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=d_,this.fragmentShader=f_,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=Vr(e.uniforms),this.uniformsGroups=h_(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){const t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(const s in this.uniforms){const a=this.uniforms[s].value;a&&a.isTexture?t.uniforms[s]={type:"t",value:a.toJSON(e).uuid}:a&&a.isColor?t.uniforms[s]={type:"c",value:a.getHex()}:a&&a.isVector2?t.uniforms[s]={type:"v2",value:a.toArray()}:a&&a.isVector3?t.uniforms[s]={type:"v3",value:a.toArray()}:a&&a.isVector4?t.uniforms[s]={type:"v4",value:a.toArray()}:a&&a.isMatrix3?t.uniforms[s]={type:"m3",value:a.toArray()}:a&&a.isMatrix4?t.uniforms[s]={type:"m4",value:a.toArray()}:t.uniforms[s]={value:a}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;const n={};for(const s in this.extensions)this.extensions[s]===!0&&(n[s]=!0);return Object.keys(n).length>0&&(t.extensions=n),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(const n in e.uniforms){const s=e.uniforms[n];switch(this.uniforms[n]={},s.type){case"t":this.uniforms[n].value=t[s.value]||null;break;case"c":this.uniforms[n].value=new ct().setHex(s.value);break;case"v2":this.uniforms[n].value=new Xe().fromArray(s.value);break;case"v3":this.uniforms[n].value=new z().fromArray(s.value);break;case"v4":this.uniforms[n].value=new nn().fromArray(s.value);break;case"m3":this.uniforms[n].value=new rt().fromArray(s.value);break;case"m4":this.uniforms[n].value=new Dt().fromArray(s.value);break;default:this.uniforms[n].value=s.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(const n in e.extensions)this.extensions[n]=e.extensions[n];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}}class p_ extends Zs{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}}class Or extends Qs{constructor(e){super(),this.isMeshStandardMaterial=!0,this.type="MeshStandardMaterial",this.defines={STANDARD:""},this.color=new ct(16777215),this.roughness=1,this.metalness=0,this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new ct(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=dh,this.normalScale=new Xe(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.roughnessMap=null,this.metalnessMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ds,this.envMapIntensity=1,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.defines={STANDARD:""},this.color.copy(e.color),this.roughness=e.roughness,this.metalness=e.metalness,this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.emissive.copy(e.emissive),this.emissiveMap=e.emissiveMap,this.emissiveIntensity=e.emissiveIntensity,this.bumpMap=e.bumpMap,this.bumpScale=e.bumpScale,this.normalMap=e.normalMap,this.normalMapType=e.normalMapType,this.normalScale.copy(e.normalScale),this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.roughnessMap=e.roughnessMap,this.metalnessMap=e.metalnessMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.envMapIntensity=e.envMapIntensity,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.flatShading=e.flatShading,this.fog=e.fog,this}}class m_ extends Qs{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=w0,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}}class g_ extends Qs{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}}class Op extends gi{constructor(e){super(),this.isLineDashedMaterial=!0,this.type="LineDashedMaterial",this.scale=1,this.dashSize=3,this.gapSize=1,this.setValues(e)}copy(e){return super.copy(e),this.scale=e.scale,this.dashSize=e.dashSize,this.gapSize=e.gapSize,this}}class kp extends Sn{static registerNode(e){this.prototype._lightNode=e}constructor(e,t=1){super(),this.isLight=!0,this.type="Light",this.color=new ct(e),this.intensity=t}copy(e,t){return super.copy(e,t),this.color.copy(e.color),this.intensity=e.intensity,this}toJSON(e){const t=super.toJSON(e);return t.object.color=this.color.getHex(),t.object.intensity=this.intensity,t}}const rc=new Dt,dd=new z,fd=new z;class __{constructor(e){this.camera=e,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new Xe(512,512),this.mapType=ni,this.map=null,this.mapPass=null,this.matrix=new Dt,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new Na,this._frameExtents=new Xe(1,1),this._viewportCount=1,this._viewports=[new nn(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(e){const t=this.camera;dd.setFromMatrixPosition(e.matrixWorld),t.position.copy(dd),fd.setFromMatrixPosition(e.target.matrixWorld),t.lookAt(fd),t.updateMatrixWorld(),this._updateMatrix(t,this.matrix,this._frustum)}_updateMatrix(e,t,n,s){rc.multiplyMatrices(e.projectionMatrix,e.matrixWorldInverse),n.setFromProjectionMatrix(rc,e.coordinateSystem,e.reversedDepth);const r=this._frameExtents,a=s?s.z/r.x:1,o=s?s.w/r.y:1,l=s?s.x/r.x:0,c=s?s.y/r.y:0;e.coordinateSystem===Da||e.reversedDepth?t.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,1,0,0,0,0,1):t.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,.5,.5,0,0,0,1),t.multiply(rc)}getViewport(e){return this._viewports[e]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(e){return this.camera=e.camera.clone(),this.intensity=e.intensity,this.bias=e.bias,this.radius=e.radius,this.autoUpdate=e.autoUpdate,this.needsUpdate=e.needsUpdate,this.normalBias=e.normalBias,this.blurSamples=e.blurSamples,this.mapSize.copy(e.mapSize),this.mapType=e.mapType,this.biasNode=e.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){const e={};return e.intensity=this.intensity,e.bias=this.bias,e.normalBias=this.normalBias,e.radius=this.radius,e.blurSamples=this.blurSamples,e.mapSize=this.mapSize.toArray(),e.mapType=this.mapType,e.camera=this.camera.toJSON(!1).object,delete e.camera.matrix,e}}const xo=new z,So=new Ls,Fi=new z;class Bp extends Sn{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new Dt,this.projectionMatrix=new Dt,this.projectionMatrixInverse=new Dt,this.coordinateSystem=Ri,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(xo,So,Fi),Fi.x===1&&Fi.y===1&&Fi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(xo,So,Fi.set(1,1,1)).invert()}updateWorldMatrix(e,t,n=!1){super.updateWorldMatrix(e,t,n),this.matrixWorld.decompose(xo,So,Fi),Fi.x===1&&Fi.y===1&&Fi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(xo,So,Fi.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}}const ys=new z,pd=new Xe,md=new Xe;class $n extends Bp{constructor(e=50,t=1,n=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=n,this.far=s,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){const t=.5*this.getFilmHeight()/e;this.fov=fh*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){const e=Math.tan(ba*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return fh*2*Math.atan(Math.tan(ba*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,n){ys.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(ys.x,ys.y).multiplyScalar(-e/ys.z),ys.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),n.set(ys.x,ys.y).multiplyScalar(-e/ys.z)}getViewSize(e,t){return this.getViewBounds(e,pd,md),t.subVectors(md,pd)}setViewOffset(e,t,n,s,r,a){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=this.near;let t=e*Math.tan(ba*.5*this.fov)/this.zoom,n=2*t,s=this.aspect*n,r=-.5*s;const a=this.view;if(this.view!==null&&this.view.enabled){const l=a.fullWidth,c=a.fullHeight;r+=a.offsetX*s/l,t-=a.offsetY*n/c,s*=a.width/l,n*=a.height/c}const o=this.filmOffset;o!==0&&(r+=e*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,t,t-n,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}}class zp extends Bp{constructor(e=-1,t=1,n=1,s=-1,r=.1,a=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=n,this.bottom=s,this.near=r,this.far=a,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,n,s,r,a){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),n=(this.right+this.left)/2,s=(this.top+this.bottom)/2;let r=n-e,a=n+e,o=s+t,l=s-t;if(this.view!==null&&this.view.enabled){const c=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=c*this.view.offsetX,a=r+c*this.view.width,o-=h*this.view.offsetY,l=o-h*this.view.height}this.projectionMatrix.makeOrthographic(r,a,o,l,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){const t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}}class v_ extends __{constructor(){super(new zp(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}}class x_ extends kp{constructor(e,t){super(e,t),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(Sn.DEFAULT_UP),this.updateMatrix(),this.target=new Sn,this.shadow=new v_}dispose(){super.dispose(),this.shadow.dispose()}copy(e){return super.copy(e),this.target=e.target.clone(),this.shadow=e.shadow.clone(),this}toJSON(e){const t=super.toJSON(e);return t.object.shadow=this.shadow.toJSON(),t.object.target=this.target.uuid,t}}class S_ extends kp{constructor(e,t){super(e,t),this.isAmbientLight=!0,this.type="AmbientLight"}}const gd=new Dt,_d=new Dt,Vs=new Dt;class Hp{constructor(){this.type="StereoCamera",this.aspect=1,this.eyeSep=.064,this.cameraL=new $n,this.cameraL.layers.enable(1),this.cameraL.matrixAutoUpdate=!1,this.cameraR=new $n,this.cameraR.layers.enable(2),this.cameraR.matrixAutoUpdate=!1,this._cache={focus:null,fov:null,aspect:null,near:null,far:null,zoom:null,eyeSep:null}}update(e){const t=this._cache;if(t.focus!==e.focus||t.fov!==e.fov||t.aspect!==e.aspect*this.aspect||t.near!==e.near||t.far!==e.far||t.zoom!==e.zoom||t.eyeSep!==this.eyeSep){t.focus=e.focus,t.fov=e.fov,t.aspect=e.aspect*this.aspect,t.near=e.near,t.far=e.far,t.zoom=e.zoom,t.eyeSep=this.eyeSep,Vs.copy(e.projectionMatrix);const s=t.eyeSep/2,r=s*t.near/t.focus,a=t.near*Math.tan(ba*t.fov*.5)/t.zoom;let o,l;_d.elements[12]=-s,gd.elements[12]=s,o=-a*t.aspect+r,l=a*t.aspect+r,Vs.elements[0]=2*t.near/(l-o),Vs.elements[8]=(l+o)/(l-o),this.cameraL.projectionMatrix.copy(Vs),o=-a*t.aspect-r,l=a*t.aspect-r,Vs.elements[0]=2*t.near/(l-o),Vs.elements[8]=(l+o)/(l-o),this.cameraR.projectionMatrix.copy(Vs)}this.cameraL.matrix.copy(e.matrixWorld).multiply(_d),this.cameraL.matrixWorldNeedsUpdate=!0,this.cameraR.matrix.copy(e.matrixWorld).multiply(gd),this.cameraR.matrixWorldNeedsUpdate=!0}}const Tr=-90,Ar=1;class ph extends Sn{constructor(e,t,n){super(),this.type="CubeCamera",this.renderTarget=n,this.coordinateSystem=null,this.activeMipmapLevel=0;const s=new $n(Tr,Ar,e,t);s.layers=this.layers,this.add(s);const r=new $n(Tr,Ar,e,t);r.layers=this.layers,this.add(r);const a=new $n(Tr,Ar,e,t);a.layers=this.layers,this.add(a);const o=new $n(Tr,Ar,e,t);o.layers=this.layers,this.add(o);const l=new $n(Tr,Ar,e,t);l.layers=this.layers,this.add(l);const c=new $n(Tr,Ar,e,t);c.layers=this.layers,this.add(c)}updateCoordinateSystem(){const e=this.coordinateSystem,t=this.children.concat(),[n,s,r,a,o,l]=t;for(const c of t)this.remove(c);if(e===Ri)n.up.set(0,1,0),n.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),a.up.set(0,0,1),a.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(e===Da)n.up.set(0,-1,0),n.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),a.up.set(0,0,-1),a.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(const c of t)this.add(c),c.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();const{renderTarget:n,activeMipmapLevel:s}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());const[r,a,o,l,c,h]=this.children,u=e.getRenderTarget(),d=e.getActiveCubeFace(),m=e.getActiveMipmapLevel(),_=e.xr.enabled;e.xr.enabled=!1;const M=n.texture.mipmapsAutoUpdate;n.texture.mipmapsAutoUpdate=!1;let p=!1;e.isWebGLRenderer===!0?p=e.state.buffers.depth.getReversed():p=e.reversedDepthBuffer,e.setRenderTarget(n,0,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,r),e.setRenderTarget(n,1,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(n,2,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(n,3,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),e.setRenderTarget(n,4,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),n.texture.mipmapsAutoUpdate=M,e.setRenderTarget(n,5,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,h),e.setRenderTarget(u,d,m),e.xr.enabled=_,n.texture.needsPMREMUpdate=!0}}class M_ extends $n{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}}const vd=new Dt;class Vp{constructor(e,t,n=0,s=1/0){this.ray=new rl(e,t),this.near=n,this.far=s,this.camera=null,this.layers=new qh,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(e,t){this.ray.set(e,t)}setFromCamera(e,t){t.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(e.x,e.y,.5).unproject(t).sub(this.ray.origin).normalize(),this.camera=t):t.isOrthographicCamera?(this.ray.origin.set(e.x,e.y,t.projectionMatrix.elements[14]).unproject(t),this.ray.direction.set(0,0,-1).transformDirection(t.matrixWorld),this.camera=t):St("Raycaster: Unsupported camera type: "+t.type)}setFromXRController(e){return vd.identity().extractRotation(e.matrixWorld),this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4(vd),this}intersectObject(e,t=!0,n=[]){return mh(e,this,n,t),n.sort(xd),n}intersectObjects(e,t=!0,n=[]){for(let s=0,r=e.length;s<r;s++)mh(e[s],this,n,t);return n.sort(xd),n}}function xd(i,e){return i.distance-e.distance}function mh(i,e,t,n){let s=!0;if(i.layers.test(e.layers)&&i.raycast(e,t)===!1&&(s=!1),s===!0&&n===!0){const r=i.children;for(let a=0,o=r.length;a<o;a++)mh(r[a],e,t,!0)}}class Sd{constructor(e=1,t=0,n=0){this.radius=e,this.phi=t,this.theta=n}set(e,t,n){return this.radius=e,this.phi=t,this.theta=n,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=mt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,n){return this.radius=Math.sqrt(e*e+t*t+n*n),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,n),this.phi=Math.acos(mt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}}const Md=new z;let Mo,ac;class y_ extends Sn{constructor(e=new z(0,0,1),t=new z(0,0,0),n=1,s=16776960,r=n*.2,a=r*.2){super(),this.type="ArrowHelper",Mo===void 0&&(Mo=new Bt,Mo.setAttribute("position",new rn([0,0,0,0,1,0],3)),ac=new Kh(.5,1,5,1),ac.translate(0,-.5,0)),this.position.copy(t),this.line=new Ki(Mo,new gi({color:s,toneMapped:!1})),this.line.matrixAutoUpdate=!1,this.add(this.line),this.cone=new sn(ac,new Rs({color:s,toneMapped:!1})),this.cone.matrixAutoUpdate=!1,this.add(this.cone),this.setDirection(e),this.setLength(n,r,a)}setDirection(e){if(e.y>.99999)this.quaternion.set(0,0,0,1);else if(e.y<-.99999)this.quaternion.set(1,0,0,0);else{Md.set(e.z,0,-e.x).normalize();const t=Math.acos(e.y);this.quaternion.setFromAxisAngle(Md,t)}}setLength(e,t=e*.2,n=t*.2){this.line.scale.set(1,Math.max(1e-4,e-t),1),this.line.updateMatrix(),this.cone.scale.set(n,t,n),this.cone.position.y=e,this.cone.updateMatrix()}setColor(e){this.line.material.color.set(e),this.cone.material.color.set(e)}copy(e){return super.copy(e,!1),this.line.copy(e.line),this.cone.copy(e.cone),this}dispose(){super.dispose(),this.line.geometry.dispose(),this.line.material.dispose(),this.cone.geometry.dispose(),this.cone.material.dispose()}}class Gp extends al{constructor(e=1){const t=[0,0,0,e,0,0,0,0,0,0,e,0,0,0,0,0,0,e],n=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new Bt;s.setAttribute("position",new rn(t,3)),s.setAttribute("color",new rn(n,3));const r=new gi({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(e,t,n){const s=new ct,r=this.geometry.attributes.color.array;return s.set(e),s.toArray(r,0),s.toArray(r,3),s.set(t),s.toArray(r,6),s.toArray(r,9),s.set(n),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}}let b_=class extends Is{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function yd(i,e,t,n){const s=w_(n);switch(t){case mp:return i*e;case _p:return i*e/s.components*s.byteLength;case Gh:return i*e/s.components*s.byteLength;case Ks:return i*e*2/s.components*s.byteLength;case Wh:return i*e*2/s.components*s.byteLength;case gp:return i*e*3/s.components*s.byteLength;case Gi:return i*e*4/s.components*s.byteLength;case Xh:return i*e*4/s.components*s.byteLength;case Fo:case Oo:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case ko:case Bo:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case Oc:case Bc:return Math.max(i,16)*Math.max(e,8)/4;case Fc:case kc:return Math.max(i,8)*Math.max(e,8)/2;case zc:case Hc:case Gc:case Wc:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case Vc:case Wo:case Xc:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case $c:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case qc:return Math.floor((i+4)/5)*Math.floor((e+3)/4)*16;case Yc:return Math.floor((i+4)/5)*Math.floor((e+4)/5)*16;case Kc:return Math.floor((i+5)/6)*Math.floor((e+4)/5)*16;case Zc:return Math.floor((i+5)/6)*Math.floor((e+5)/6)*16;case Jc:return Math.floor((i+7)/8)*Math.floor((e+4)/5)*16;case jc:return Math.floor((i+7)/8)*Math.floor((e+5)/6)*16;case Qc:return Math.floor((i+7)/8)*Math.floor((e+7)/8)*16;case eh:return Math.floor((i+9)/10)*Math.floor((e+4)/5)*16;case th:return Math.floor((i+9)/10)*Math.floor((e+5)/6)*16;case nh:return Math.floor((i+9)/10)*Math.floor((e+7)/8)*16;case ih:return Math.floor((i+9)/10)*Math.floor((e+9)/10)*16;case sh:return Math.floor((i+11)/12)*Math.floor((e+9)/10)*16;case rh:return Math.floor((i+11)/12)*Math.floor((e+11)/12)*16;case ah:case oh:case lh:return Math.ceil(i/4)*Math.ceil(e/4)*16;case ch:case hh:return Math.ceil(i/4)*Math.ceil(e/4)*8;case Xo:case uh:return Math.ceil(i/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function w_(i){switch(i){case ni:case up:return{byteLength:1,components:1};case La:case dp:case Yi:return{byteLength:2,components:1};case Hh:case Vh:return{byteLength:2,components:4};case qi:case zh:case Vi:return{byteLength:4,components:1};case fp:case pp:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${i}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:Bh}}));typeof window<"u"&&(window.__THREE__?je("WARNING: Multiple instances of Three.js being imported."):window.__THREE__=Bh);function Wp(){let i=null,e=!1,t=null,n=null;function s(r,a){n=i.requestAnimationFrame(s),t(r,a)}return{start:function(){e!==!0&&t!==null&&i!==null&&(n=i.requestAnimationFrame(s),e=!0)},stop:function(){i!==null&&i.cancelAnimationFrame(n),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){i=r}}}function E_(i){const e=new WeakMap;function t(o,l){const c=o.array,h=o.usage,u=c.byteLength,d=i.createBuffer();i.bindBuffer(l,d),i.bufferData(l,c,h),o.onUploadCallback();let m;if(c instanceof Float32Array)m=i.FLOAT;else if(typeof Float16Array<"u"&&c instanceof Float16Array)m=i.HALF_FLOAT;else if(c instanceof Uint16Array)o.isFloat16BufferAttribute?m=i.HALF_FLOAT:m=i.UNSIGNED_SHORT;else if(c instanceof Int16Array)m=i.SHORT;else if(c instanceof Uint32Array)m=i.UNSIGNED_INT;else if(c instanceof Int32Array)m=i.INT;else if(c instanceof Int8Array)m=i.BYTE;else if(c instanceof Uint8Array)m=i.UNSIGNED_BYTE;else if(c instanceof Uint8ClampedArray)m=i.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+c);return{buffer:d,type:m,bytesPerElement:c.BYTES_PER_ELEMENT,version:o.version,size:u}}function n(o,l,c){const h=l.array,u=l.updateRanges;if(i.bindBuffer(c,o),u.length===0)i.bufferSubData(c,0,h);else{u.sort((m,_)=>m.start-_.start);let d=0;for(let m=1;m<u.length;m++){const _=u[d],M=u[m];M.start<=_.start+_.count+1?_.count=Math.max(_.count,M.start+M.count-_.start):(++d,u[d]=M)}u.length=d+1;for(let m=0,_=u.length;m<_;m++){const M=u[m];i.bufferSubData(c,M.start*h.BYTES_PER_ELEMENT,h,M.start,M.count)}l.clearUpdateRanges()}l.onUploadCallback()}function s(o){return o.isInterleavedBufferAttribute&&(o=o.data),e.get(o)}function r(o){o.isInterleavedBufferAttribute&&(o=o.data);const l=e.get(o);l&&(i.deleteBuffer(l.buffer),e.delete(o))}function a(o,l){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){const h=e.get(o);(!h||h.version<o.version)&&e.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}const c=e.get(o);if(c===void 0)e.set(o,t(o,l));else if(c.version<o.version){if(c.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");n(c.buffer,o,l),c.version=o.version}}return{get:s,remove:r,update:a}}var T_=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,A_=`#ifdef USE_ALPHAHASH
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
#endif`,R_=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,C_=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,P_=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,L_=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,D_=`#ifdef USE_AOMAP
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
#endif`,N_=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,I_=`#ifdef USE_BATCHING
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
#endif`,U_=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,F_=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,O_=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,k_=`float G_BlinnPhong_Implicit( ) {
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
} // validated`,B_=`#ifdef USE_IRIDESCENCE
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
#endif`,z_=`#ifdef USE_BUMPMAP
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
#endif`,H_=`#if NUM_CLIPPING_PLANES > 0
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
#endif`,V_=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,G_=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,W_=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,X_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,$_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,q_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,Y_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
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
#endif`,K_=`#define PI 3.141592653589793
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
} // validated`,Z_=`vec3 transformedNormal = objectNormal;
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
#endif`,J_=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,j_=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,Q_=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,ev=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,tv="gl_FragColor = linearToOutputTexel( gl_FragColor );",nv=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,iv=`#ifdef USE_ENVMAP
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
#endif`,sv=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,rv=`#ifdef USE_ENVMAP
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
#endif`,av=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,ov=`#ifdef USE_ENVMAP
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
#endif`,lv=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,cv=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,hv=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,uv=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,dv=`#ifdef USE_GRADIENTMAP
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
}`,fv=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,pv=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,mv=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,gv=`uniform bool receiveShadow;
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
#include <lightprobes_pars_fragment>`,_v=`#ifdef USE_ENVMAP
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
#endif`,vv=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,xv=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,Sv=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,Mv=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,yv=`PhysicalMaterial material;
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
#endif`,bv=`uniform sampler2D dfgLUT;
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
}`,wv=`
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
#endif`,Ev=`#if defined( RE_IndirectDiffuse )
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
#endif`,Tv=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,Av=`#if NUM_LIGHT_PROBE_GRIDS > 0
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
#endif`,Rv=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,Cv=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Pv=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Lv=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,Dv=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,Nv=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,Iv=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
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
#endif`,Uv=`#if defined( USE_POINTS_UV )
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
#endif`,Fv=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,Ov=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,kv=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,Bv=`#if defined( USE_MORPHCOLORS )
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
#endif`,zv=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Hv=`#ifdef USE_MORPHTARGETS
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
#endif`,Vv=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Gv=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
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
vec3 nonPerturbedNormal = normal;`,Wv=`#ifdef USE_NORMALMAP_OBJECTSPACE
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
#endif`,Xv=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,$v=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,qv=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,Yv=`#ifdef USE_NORMALMAP
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
#endif`,Kv=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,Zv=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,Jv=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,jv=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,Qv=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,ex=`vec3 packNormalToRGB( const in vec3 normal ) {
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
}`,tx=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,nx=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,ix=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,sx=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,rx=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,ax=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,ox=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,lx=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,cx=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
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
#endif`,hx=`float getShadowMask() {
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
}`,ux=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,dx=`#ifdef USE_SKINNING
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
#endif`,fx=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,px=`#ifdef USE_SKINNING
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
#endif`,mx=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,gx=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,_x=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,vx=`#ifndef saturate
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
vec3 CustomToneMapping( vec3 color ) { return color; }`,xx=`#ifdef USE_TRANSMISSION
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
#endif`,Sx=`#ifdef USE_TRANSMISSION
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
#endif`,Mx=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,yx=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,bx=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,wx=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`;const Ex=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,Tx=`uniform sampler2D t2D;
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
}`,Ax=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Rx=`uniform float backgroundBlurriness;
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
}`,Cx=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Px=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Lx=`#include <common>
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
}`,Dx=`#if DEPTH_PACKING == 3200
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
}`,Nx=`#define DISTANCE
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
}`,Ix=`#define DISTANCE
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
}`,Ux=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,Fx=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Ox=`uniform float scale;
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
}`,kx=`uniform vec3 diffuse;
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
}`,Bx=`#include <common>
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
}`,zx=`uniform vec3 diffuse;
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
}`,Hx=`#define LAMBERT
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
}`,Vx=`#define LAMBERT
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
}`,Gx=`#define MATCAP
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
}`,Wx=`#define MATCAP
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
}`,Xx=`#define NORMAL
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
}`,$x=`#define NORMAL
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
}`,qx=`#define PHONG
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
}`,Yx=`#define PHONG
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
}`,Kx=`#define STANDARD
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
}`,Zx=`#define STANDARD
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
}`,Jx=`#define TOON
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
}`,jx=`#define TOON
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
}`,Qx=`uniform float size;
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
}`,eS=`uniform vec3 diffuse;
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
}`,tS=`#include <common>
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
}`,nS=`uniform vec3 color;
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
}`,iS=`uniform float rotation;
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
}`,sS=`uniform vec3 diffuse;
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
}`,lt={alphahash_fragment:T_,alphahash_pars_fragment:A_,alphamap_fragment:R_,alphamap_pars_fragment:C_,alphatest_fragment:P_,alphatest_pars_fragment:L_,aomap_fragment:D_,aomap_pars_fragment:N_,batching_pars_vertex:I_,batching_vertex:U_,begin_vertex:F_,beginnormal_vertex:O_,bsdfs:k_,iridescence_fragment:B_,bumpmap_pars_fragment:z_,clipping_planes_fragment:H_,clipping_planes_pars_fragment:V_,clipping_planes_pars_vertex:G_,clipping_planes_vertex:W_,color_fragment:X_,color_pars_fragment:$_,color_pars_vertex:q_,color_vertex:Y_,common:K_,defaultnormal_vertex:Z_,displacementmap_pars_vertex:J_,displacementmap_vertex:j_,emissivemap_fragment:Q_,emissivemap_pars_fragment:ev,colorspace_fragment:tv,colorspace_pars_fragment:nv,envmap_fragment:iv,envmap_common_pars_fragment:sv,envmap_pars_fragment:rv,envmap_pars_vertex:av,envmap_physical_pars_fragment:_v,envmap_vertex:ov,fog_vertex:lv,fog_pars_vertex:cv,fog_fragment:hv,fog_pars_fragment:uv,gradientmap_pars_fragment:dv,lightmap_pars_fragment:fv,lights_lambert_fragment:pv,lights_lambert_pars_fragment:mv,lights_pars_begin:gv,lights_toon_fragment:vv,lights_toon_pars_fragment:xv,lights_phong_fragment:Sv,lights_phong_pars_fragment:Mv,lights_physical_fragment:yv,lights_physical_pars_fragment:bv,lights_fragment_begin:wv,lights_fragment_maps:Ev,lights_fragment_end:Tv,lightprobes_pars_fragment:Av,logdepthbuf_fragment:Rv,logdepthbuf_pars_fragment:Cv,logdepthbuf_pars_vertex:Pv,logdepthbuf_vertex:Lv,map_fragment:Dv,map_pars_fragment:Nv,map_particle_fragment:Iv,map_particle_pars_fragment:Uv,metalnessmap_fragment:Fv,metalnessmap_pars_fragment:Ov,morphinstance_vertex:kv,morphcolor_vertex:Bv,morphnormal_vertex:zv,morphtarget_pars_vertex:Hv,morphtarget_vertex:Vv,normal_fragment_begin:Gv,normal_fragment_maps:Wv,normal_pars_fragment:Xv,normal_pars_vertex:$v,normal_vertex:qv,normalmap_pars_fragment:Yv,clearcoat_normal_fragment_begin:Kv,clearcoat_normal_fragment_maps:Zv,clearcoat_pars_fragment:Jv,iridescence_pars_fragment:jv,opaque_fragment:Qv,packing:ex,premultiplied_alpha_fragment:tx,project_vertex:nx,dithering_fragment:ix,dithering_pars_fragment:sx,roughnessmap_fragment:rx,roughnessmap_pars_fragment:ax,shadowmap_pars_fragment:ox,shadowmap_pars_vertex:lx,shadowmap_vertex:cx,shadowmask_pars_fragment:hx,skinbase_vertex:ux,skinning_pars_vertex:dx,skinning_vertex:fx,skinnormal_vertex:px,specularmap_fragment:mx,specularmap_pars_fragment:gx,tonemapping_fragment:_x,tonemapping_pars_fragment:vx,transmission_fragment:xx,transmission_pars_fragment:Sx,uv_pars_fragment:Mx,uv_pars_vertex:yx,uv_vertex:bx,worldpos_vertex:wx,background_vert:Ex,background_frag:Tx,backgroundCube_vert:Ax,backgroundCube_frag:Rx,cube_vert:Cx,cube_frag:Px,depth_vert:Lx,depth_frag:Dx,distance_vert:Nx,distance_frag:Ix,equirect_vert:Ux,equirect_frag:Fx,linedashed_vert:Ox,linedashed_frag:kx,meshbasic_vert:Bx,meshbasic_frag:zx,meshlambert_vert:Hx,meshlambert_frag:Vx,meshmatcap_vert:Gx,meshmatcap_frag:Wx,meshnormal_vert:Xx,meshnormal_frag:$x,meshphong_vert:qx,meshphong_frag:Yx,meshphysical_vert:Kx,meshphysical_frag:Zx,meshtoon_vert:Jx,meshtoon_frag:jx,points_vert:Qx,points_frag:eS,shadow_vert:tS,shadow_frag:nS,sprite_vert:iS,sprite_frag:sS},De={common:{diffuse:{value:new ct(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new rt},alphaMap:{value:null},alphaMapTransform:{value:new rt},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new rt}},envmap:{envMap:{value:null},envMapRotation:{value:new rt},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new rt}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new rt}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new rt},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new rt},normalScale:{value:new Xe(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new rt},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new rt}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new rt}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new rt}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new ct(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new ct(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new rt},alphaTest:{value:0},uvTransform:{value:new rt}},sprite:{diffuse:{value:new ct(16777215)},opacity:{value:1},center:{value:new Xe(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new rt},alphaMap:{value:null},alphaMapTransform:{value:new rt},alphaTest:{value:0}}},Hi={basic:{uniforms:Vn([De.common,De.specularmap,De.envmap,De.aomap,De.lightmap,De.fog]),vertexShader:lt.meshbasic_vert,fragmentShader:lt.meshbasic_frag},lambert:{uniforms:Vn([De.common,De.specularmap,De.envmap,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.fog,De.lights,{emissive:{value:new ct(0)},envMapIntensity:{value:1}}]),vertexShader:lt.meshlambert_vert,fragmentShader:lt.meshlambert_frag},phong:{uniforms:Vn([De.common,De.specularmap,De.envmap,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.fog,De.lights,{emissive:{value:new ct(0)},specular:{value:new ct(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:lt.meshphong_vert,fragmentShader:lt.meshphong_frag},standard:{uniforms:Vn([De.common,De.envmap,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.roughnessmap,De.metalnessmap,De.fog,De.lights,{emissive:{value:new ct(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:lt.meshphysical_vert,fragmentShader:lt.meshphysical_frag},toon:{uniforms:Vn([De.common,De.aomap,De.lightmap,De.emissivemap,De.bumpmap,De.normalmap,De.displacementmap,De.gradientmap,De.fog,De.lights,{emissive:{value:new ct(0)}}]),vertexShader:lt.meshtoon_vert,fragmentShader:lt.meshtoon_frag},matcap:{uniforms:Vn([De.common,De.bumpmap,De.normalmap,De.displacementmap,De.fog,{matcap:{value:null}}]),vertexShader:lt.meshmatcap_vert,fragmentShader:lt.meshmatcap_frag},points:{uniforms:Vn([De.points,De.fog]),vertexShader:lt.points_vert,fragmentShader:lt.points_frag},dashed:{uniforms:Vn([De.common,De.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:lt.linedashed_vert,fragmentShader:lt.linedashed_frag},depth:{uniforms:Vn([De.common,De.displacementmap]),vertexShader:lt.depth_vert,fragmentShader:lt.depth_frag},normal:{uniforms:Vn([De.common,De.bumpmap,De.normalmap,De.displacementmap,{opacity:{value:1}}]),vertexShader:lt.meshnormal_vert,fragmentShader:lt.meshnormal_frag},sprite:{uniforms:Vn([De.sprite,De.fog]),vertexShader:lt.sprite_vert,fragmentShader:lt.sprite_frag},background:{uniforms:{uvTransform:{value:new rt},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:lt.background_vert,fragmentShader:lt.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new rt}},vertexShader:lt.backgroundCube_vert,fragmentShader:lt.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:lt.cube_vert,fragmentShader:lt.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:lt.equirect_vert,fragmentShader:lt.equirect_frag},distance:{uniforms:Vn([De.common,De.displacementmap,{referencePosition:{value:new z},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:lt.distance_vert,fragmentShader:lt.distance_frag},shadow:{uniforms:Vn([De.lights,De.fog,{color:{value:new ct(0)},opacity:{value:1}}]),vertexShader:lt.shadow_vert,fragmentShader:lt.shadow_frag}};Hi.physical={uniforms:Vn([Hi.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new rt},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new rt},clearcoatNormalScale:{value:new Xe(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new rt},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new rt},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new rt},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new rt},sheen:{value:0},sheenColor:{value:new ct(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new rt},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new rt},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new rt},transmissionSamplerSize:{value:new Xe},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new rt},attenuationDistance:{value:0},attenuationColor:{value:new ct(0)},specularColor:{value:new ct(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new rt},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new rt},anisotropyVector:{value:new Xe},anisotropyMap:{value:null},anisotropyMapTransform:{value:new rt}}]),vertexShader:lt.meshphysical_vert,fragmentShader:lt.meshphysical_frag};const yo={r:0,b:0,g:0},rS=new Dt,Xp=new rt;Xp.set(-1,0,0,0,1,0,0,0,1);function aS(i,e,t,n,s,r){const a=new ct(0);let o=s===!0?0:1,l,c,h=null,u=0,d=null;function m(x){let A=x.isScene===!0?x.background:null;if(A&&A.isTexture){const S=x.backgroundBlurriness>0;A=e.get(A,S)}return A}function _(x){let A=!1;const S=m(x);S===null?p(a,o):S&&S.isColor&&(p(S,1),A=!0);const R=i.xr.getEnvironmentBlendMode();R==="additive"?t.buffers.color.setClear(0,0,0,1,r):R==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,r),(i.autoClear||A)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),i.clear(i.autoClearColor,i.autoClearDepth,i.autoClearStencil))}function M(x,A){const S=m(A);S&&S.isCubeTexture?(c===void 0&&(c=new sn(new Ha(1,1,1),new Zs({name:"BackgroundCubeMaterial",uniforms:Vr(Hi.backgroundCube.uniforms),vertexShader:Hi.backgroundCube.vertexShader,fragmentShader:Hi.backgroundCube.fragmentShader,side:Yn,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),c.geometry.deleteAttribute("uv"),c.onBeforeRender=function(R,y,g){this.matrixWorld.copyPosition(g.matrixWorld)},Object.defineProperty(c.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),n.update(c)),c.material.uniforms.envMap.value=S,c.material.uniforms.backgroundBlurriness.value=A.backgroundBlurriness,c.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,c.material.uniforms.backgroundRotation.value.setFromMatrix4(rS.makeRotationFromEuler(A.backgroundRotation)).transpose(),S.isRenderTargetTexture===!1&&c.material.uniforms.backgroundRotation.value.premultiply(Xp),c.material.toneMapped=xt.getTransfer(S.colorSpace)!==Lt,(h!==S||u!==S.version||d!==i.toneMapping)&&(c.material.needsUpdate=!0,h=S,u=S.version,d=i.toneMapping),c.layers.enableAll(),x.unshift(c,c.geometry,c.material,0,0,null)):S&&S.isTexture&&(l===void 0&&(l=new sn(new ol(2,2),new Zs({name:"BackgroundMaterial",uniforms:Vr(Hi.background.uniforms),vertexShader:Hi.background.vertexShader,fragmentShader:Hi.background.fragmentShader,side:Cs,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),n.update(l)),l.material.uniforms.t2D.value=S,l.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,l.material.toneMapped=xt.getTransfer(S.colorSpace)!==Lt,S.matrixAutoUpdate===!0&&S.updateMatrix(),l.material.uniforms.uvTransform.value.copy(S.matrix),(h!==S||u!==S.version||d!==i.toneMapping)&&(l.material.needsUpdate=!0,h=S,u=S.version,d=i.toneMapping),l.layers.enableAll(),x.unshift(l,l.geometry,l.material,0,0,null))}function p(x,A){x.getRGB(yo,Fp(i)),t.buffers.color.setClear(yo.r,yo.g,yo.b,A,r)}function f(){c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0),l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0)}return{getClearColor:function(){return a},setClearColor:function(x,A=1){a.set(x),o=A,p(a,o)},getClearAlpha:function(){return o},setClearAlpha:function(x){o=x,p(a,o)},render:_,addToRenderList:M,dispose:f}}function oS(i,e){const t=i.getParameter(i.MAX_VERTEX_ATTRIBS),n={},s=d(null);let r=s,a=!1;function o(L,G,W,U,X){let J=!1;const H=u(L,U,W,G);r!==H&&(r=H,c(r.object)),J=m(L,U,W,X),J&&_(L,U,W,X),X!==null&&e.update(X,i.ELEMENT_ARRAY_BUFFER),(J||a)&&(a=!1,S(L,G,W,U),X!==null&&i.bindBuffer(i.ELEMENT_ARRAY_BUFFER,e.get(X).buffer))}function l(){return i.createVertexArray()}function c(L){return i.bindVertexArray(L)}function h(L){return i.deleteVertexArray(L)}function u(L,G,W,U){const X=U.wireframe===!0;let J=n[G.id];J===void 0&&(J={},n[G.id]=J);const H=L.isInstancedMesh===!0?L.id:0;let ce=J[H];ce===void 0&&(ce={},J[H]=ce);let Z=ce[W.id];Z===void 0&&(Z={},ce[W.id]=Z);let ee=Z[X];return ee===void 0&&(ee=d(l()),Z[X]=ee),ee}function d(L){const G=[],W=[],U=[];for(let X=0;X<t;X++)G[X]=0,W[X]=0,U[X]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:G,enabledAttributes:W,attributeDivisors:U,object:L,attributes:{},index:null}}function m(L,G,W,U){const X=r.attributes,J=G.attributes;let H=0;const ce=W.getAttributes();for(const Z in ce)if(ce[Z].location>=0){const se=X[Z];let pe=J[Z];if(pe===void 0&&(Z==="instanceMatrix"&&L.instanceMatrix&&(pe=L.instanceMatrix),Z==="instanceColor"&&L.instanceColor&&(pe=L.instanceColor)),se===void 0||se.attribute!==pe||pe&&se.data!==pe.data)return!0;H++}return r.attributesNum!==H||r.index!==U}function _(L,G,W,U){const X={},J=G.attributes;let H=0;const ce=W.getAttributes();for(const Z in ce)if(ce[Z].location>=0){let se=J[Z];se===void 0&&(Z==="instanceMatrix"&&L.instanceMatrix&&(se=L.instanceMatrix),Z==="instanceColor"&&L.instanceColor&&(se=L.instanceColor));const pe={};pe.attribute=se,se&&se.data&&(pe.data=se.data),X[Z]=pe,H++}r.attributes=X,r.attributesNum=H,r.index=U}function M(){const L=r.newAttributes;for(let G=0,W=L.length;G<W;G++)L[G]=0}function p(L){f(L,0)}function f(L,G){const W=r.newAttributes,U=r.enabledAttributes,X=r.attributeDivisors;W[L]=1,U[L]===0&&(i.enableVertexAttribArray(L),U[L]=1),X[L]!==G&&(i.vertexAttribDivisor(L,G),X[L]=G)}function x(){const L=r.newAttributes,G=r.enabledAttributes;for(let W=0,U=G.length;W<U;W++)G[W]!==L[W]&&(i.disableVertexAttribArray(W),G[W]=0)}function A(L,G,W,U,X,J,H){H===!0?i.vertexAttribIPointer(L,G,W,X,J):i.vertexAttribPointer(L,G,W,U,X,J)}function S(L,G,W,U){M();const X=U.attributes,J=W.getAttributes(),H=G.defaultAttributeValues;for(const ce in J){const Z=J[ce];if(Z.location>=0){let ee=X[ce];if(ee===void 0&&(ce==="instanceMatrix"&&L.instanceMatrix&&(ee=L.instanceMatrix),ce==="instanceColor"&&L.instanceColor&&(ee=L.instanceColor)),ee!==void 0){const se=ee.normalized,pe=ee.itemSize,fe=e.get(ee);if(fe===void 0)continue;const B=fe.buffer,te=fe.type,he=fe.bytesPerElement,ge=te===i.INT||te===i.UNSIGNED_INT||ee.gpuType===zh;if(ee.isInterleavedBufferAttribute){const ve=ee.data,Ve=ve.isInterleavedBuffer===!0?ve.stride:ve.itemSize,Qe=ee.offset;if(ve.isInstancedInterleavedBuffer||ve.isInstancedBufferAttribute){for(let ze=0;ze<Z.locationSize;ze++)f(Z.location+ze,ve.meshPerAttribute);L.isInstancedMesh!==!0&&U._maxInstanceCount===void 0&&(U._maxInstanceCount=ve.meshPerAttribute*ve.count)}else for(let ze=0;ze<Z.locationSize;ze++)p(Z.location+ze);i.bindBuffer(i.ARRAY_BUFFER,B);for(let ze=0;ze<Z.locationSize;ze++)A(Z.location+ze,pe/Z.locationSize,te,se,Ve*he,(Qe+pe/Z.locationSize*ze)*he,ge)}else{if(ee.isInstancedBufferAttribute){for(let ve=0;ve<Z.locationSize;ve++)f(Z.location+ve,ee.meshPerAttribute);L.isInstancedMesh!==!0&&U._maxInstanceCount===void 0&&(U._maxInstanceCount=ee.meshPerAttribute*ee.count)}else for(let ve=0;ve<Z.locationSize;ve++)p(Z.location+ve);i.bindBuffer(i.ARRAY_BUFFER,B);for(let ve=0;ve<Z.locationSize;ve++)A(Z.location+ve,pe/Z.locationSize,te,se,pe*he,pe/Z.locationSize*ve*he,ge)}}else if(H!==void 0){const se=H[ce];if(se!==void 0)switch(se.length){case 2:i.vertexAttrib2fv(Z.location,se);break;case 3:i.vertexAttrib3fv(Z.location,se);break;case 4:i.vertexAttrib4fv(Z.location,se);break;default:i.vertexAttrib1fv(Z.location,se)}}}}x()}function R(){k();for(const L in n){const G=n[L];for(const W in G){const U=G[W];for(const X in U){const J=U[X];for(const H in J)h(J[H].object),delete J[H];delete U[X]}}delete n[L]}}function y(L){if(n[L.id]===void 0)return;const G=n[L.id];for(const W in G){const U=G[W];for(const X in U){const J=U[X];for(const H in J)h(J[H].object),delete J[H];delete U[X]}}delete n[L.id]}function g(L){for(const G in n){const W=n[G];for(const U in W){const X=W[U];if(X[L.id]===void 0)continue;const J=X[L.id];for(const H in J)h(J[H].object),delete J[H];delete X[L.id]}}}function b(L){for(const G in n){const W=n[G],U=L.isInstancedMesh===!0?L.id:0,X=W[U];if(X!==void 0){for(const J in X){const H=X[J];for(const ce in H)h(H[ce].object),delete H[ce];delete X[J]}delete W[U],Object.keys(W).length===0&&delete n[G]}}}function k(){I(),a=!0,r!==s&&(r=s,c(r.object))}function I(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:o,reset:k,resetDefaultState:I,dispose:R,releaseStatesOfGeometry:y,releaseStatesOfObject:b,releaseStatesOfProgram:g,initAttributes:M,enableAttribute:p,disableUnusedAttributes:x}}function lS(i,e,t){let n;function s(l){n=l}function r(l,c){i.drawArrays(n,l,c),t.update(c,n,1)}function a(l,c,h){h!==0&&(i.drawArraysInstanced(n,l,c,h),t.update(c,n,h))}function o(l,c,h){if(h===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(n,l,0,c,0,h);let d=0;for(let m=0;m<h;m++)d+=c[m];t.update(d,n,1)}this.setMode=s,this.render=r,this.renderInstances=a,this.renderMultiDraw=o}function cS(i,e,t,n){let s;function r(){if(s!==void 0)return s;if(e.has("EXT_texture_filter_anisotropic")===!0){const g=e.get("EXT_texture_filter_anisotropic");s=i.getParameter(g.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function a(g){return!(g!==Gi&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(g){const b=g===Yi&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(g!==ni&&g!==Vi&&!b&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_TYPE))}function l(g){if(g==="highp"){if(i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.HIGH_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.HIGH_FLOAT).precision>0)return"highp";g="mediump"}return g==="mediump"&&i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.MEDIUM_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let c=t.precision!==void 0?t.precision:"highp";const h=l(c);h!==c&&(je("WebGLRenderer:",c,"not supported, using",h,"instead."),c=h);const u=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),d=t.logarithmicDepthBuffer===!0&&u===!1;t.reversedDepthBuffer===!0&&u===!1&&je("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&u===!0&&je("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");const m=i.getParameter(i.MAX_TEXTURE_IMAGE_UNITS),_=i.getParameter(i.MAX_VERTEX_TEXTURE_IMAGE_UNITS),M=i.getParameter(i.MAX_TEXTURE_SIZE),p=i.getParameter(i.MAX_CUBE_MAP_TEXTURE_SIZE),f=i.getParameter(i.MAX_VERTEX_ATTRIBS),x=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),A=i.getParameter(i.MAX_VARYING_VECTORS),S=i.getParameter(i.MAX_FRAGMENT_UNIFORM_VECTORS),R=i.getParameter(i.MAX_SAMPLES),y=i.getParameter(i.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:l,textureFormatReadable:a,textureTypeReadable:o,precision:c,logarithmicDepthBuffer:d,reversedDepthBuffer:u,maxTextures:m,maxVertexTextures:_,maxTextureSize:M,maxCubemapSize:p,maxAttributes:f,maxVertexUniforms:x,maxVaryings:A,maxFragmentUniforms:S,maxSamples:R,samples:y}}function hS(i){const e=this;let t=null,n=0,s=!1,r=!1;const a=new Ti,o=new rt,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(u,d){const m=u.length!==0||d||n!==0||s;return s=d,n=u.length,m},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(u,d){t=h(u,d,0)},this.setState=function(u,d,m){const _=u.clippingPlanes,M=u.clipIntersection,p=u.clipShadows,f=i.get(u);if(!s||_===null||_.length===0||r&&!p)r?h(null):c();else{const x=r?0:n,A=x*4;let S=f.clippingState||null;l.value=S,S=h(_,d,A,m);for(let R=0;R!==A;++R)S[R]=t[R];f.clippingState=S,this.numIntersection=M?this.numPlanes:0,this.numPlanes+=x}};function c(){l.value!==t&&(l.value=t,l.needsUpdate=n>0),e.numPlanes=n,e.numIntersection=0}function h(u,d,m,_){const M=u!==null?u.length:0;let p=null;if(M!==0){if(p=l.value,_!==!0||p===null){const f=m+M*4,x=d.matrixWorldInverse;o.getNormalMatrix(x),(p===null||p.length<f)&&(p=new Float32Array(f));for(let A=0,S=m;A!==M;++A,S+=4)a.copy(u[A]).applyMatrix4(x,o),a.normal.toArray(p,S),p[S+3]=a.constant}l.value=p,l.needsUpdate=!0}return e.numPlanes=M,e.numIntersection=0,p}}class Zh extends $i{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;const n={width:e,height:e,depth:1},s=[n,n,n,n,n,n];this.texture=new Np(s),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;const n={uniforms:{tEquirect:{value:null}},vertexShader:`

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
			`},s=new Ha(5,5,5),r=new Zs({name:"CubemapFromEquirect",uniforms:Vr(n.uniforms),vertexShader:n.vertexShader,fragmentShader:n.fragmentShader,side:Yn,blending:Ur});r.uniforms.tEquirect.value=t;const a=new sn(s,r),o=t.minFilter;return t.minFilter===Ts&&(t.minFilter=qn),new ph(1,10,this).update(e,a),t.minFilter=o,a.geometry.dispose(),a.material.dispose(),this}clear(e,t=!0,n=!0,s=!0){const r=e.getRenderTarget();for(let a=0;a<6;a++)e.setRenderTarget(this,a),e.clear(t,n,s);e.setRenderTarget(r)}}const bd=256,uS=3,dS=20,$p=256,qp=16,fS=3,pS=new z,mS=new ct;class Qo{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new ph(1,10,null),this._boxMesh=new sn(new Ha(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,n=.1,s=100,r={}){const{size:a=256,position:o=pS}=r,l=this._renderer;this._setSize(a);const c=this._allocateTarget(),h=this._getSourceTarget(!0);t>0&&(h.texture.mipmapsAutoUpdate=!1);const u=l.autoClear,d=l.autoClearColor,m=l.autoClearDepth,_=l.autoClearStencil,M=e.background;l.autoClear=!0,l.autoClearColor=!0,l.autoClearDepth=!0,l.autoClearStencil=!0,M===null&&(e.background=l.getClearColor(mS));const p=new ph(n,s,h);return p.position.copy(o),p.update(l,e),l.autoClear=u,l.autoClearColor=d,l.autoClearDepth=m,l.autoClearStencil=_,e.background=M,t>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(c,t)),this._applyPMREM(c),c}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=Td(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Ed(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(bd,O0(e))}_fromTexture(e,t){e.mapping===Br||e.mapping===Pa?this._setSize(e.image.length===0?bd:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);const n=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(n),n}_allocateTarget(){const e=this._cubeSize,t=wd(e,!1,!1),n=Math.log2(e)-uS;for(let s=0;s<=n;s++)t.texture.mipmaps.push({width:e>>s,height:e>>s});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){const t=this._cubeSize,n=this._sourceTarget;return(n===null||n.width!==t||e&&n.depthBuffer===!1)&&(n!==null&&n.dispose(),this._sourceTarget=wd(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,n){const s=this._boxMesh,r=this._cubeCamera;s.material=n,r.renderTarget=e,r.activeMipmapLevel=t;const a=e.width>>t;e.viewport.set(0,0,a,a),r.update(this._renderer,s),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===Br||e.mapping===Pa?(this._cubemapMaterial===null&&(this._cubemapMaterial=Td()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Ed()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=gS(),this._integrationMaterial=_S());const t=this._cubeSize,n=e.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;const r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(t/qp);for(let a=0;a<=n;a++){const o=Qo.lodToRoughness(a,n);if(a>n-fS)r.roughness.value=o,this._renderCube(e,a,this._integrationMaterial);else{const l=o>0?Math.log2(t)+.5*Math.log2(6/($p*Math.pow(o,4)))+.5:0;s.roughness.value=o,s.lodBias.value=l,this._renderCube(e,a,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=vS());const n=this._blurMaterial,s=n.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(e,0,n),s.envMap.value=e.texture,this._renderCube(r,0,n)}}function wd(i,e,t){return new Zh(i,{minFilter:Ts,generateMipmaps:e,type:Yi,colorSpace:$o,depthBuffer:t})}function Ga(i,e,t){return new Zs({name:i,uniforms:e,vertexShader:lt.cube_vert,fragmentShader:t,side:Yn,blending:Ur,depthTest:!1,depthWrite:!1})}function gS(){return Ga("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${$p}u

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
	`)}function _S(){return Ga("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:qp}},`

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
	`)}function vS(){return Ga("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${dS}
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
	`)}function Ed(){return Ga("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

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
	`)}function Td(){return Ga("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function xS(i){let e=new WeakMap,t=new WeakMap,n=null;function s(d,m=!1){return d==null?null:m?a(d):r(d)}function r(d){if(d&&d.isTexture){const m=d.mapping;if(m===Dl||m===Nl)if(e.has(d)){const _=e.get(d).texture;return o(_,d.mapping)}else{const _=d.image;if(_&&_.height>0){const M=new Zh(_.height);return M.fromEquirectangularTexture(i,d),e.set(d,M),d.addEventListener("dispose",c),o(M.texture,d.mapping)}else return null}}return d}function a(d){if(d&&d.isTexture&&d.isPMREMTexture!==!0){const m=d.mapping,_=m===Dl||m===Nl,M=m===Br||m===Pa;if(_||M){let p=t.get(d);const f=p!==void 0?p.texture.pmremVersion:0;if(d.isRenderTargetTexture&&d.pmremVersion!==f)return n===null&&(n=new Qo(i)),p=_?n.fromEquirectangular(d,p):n.fromCubemap(d,p),p.texture.pmremVersion=d.pmremVersion,t.set(d,p),p.texture;if(p!==void 0)return p.texture;{const x=d.image;return _&&x&&x.height>0||M&&x&&l(x)?(n===null&&(n=new Qo(i)),p=_?n.fromEquirectangular(d):n.fromCubemap(d),p.texture.pmremVersion=d.pmremVersion,t.set(d,p),d.addEventListener("dispose",h),p.texture):null}}}return d}function o(d,m){return m===Dl?d.mapping=Br:m===Nl&&(d.mapping=Pa),d}function l(d){let m=0;const _=6;for(let M=0;M<_;M++)d[M]!==void 0&&m++;return m===_}function c(d){const m=d.target;m.removeEventListener("dispose",c);const _=e.get(m);_!==void 0&&(e.delete(m),_.dispose())}function h(d){const m=d.target;m.removeEventListener("dispose",h);const _=t.get(m);_!==void 0&&(t.delete(m),_.dispose())}function u(){e=new WeakMap,t=new WeakMap,n!==null&&(n.dispose(),n=null)}return{get:s,dispose:u}}function SS(i){const e={};function t(n){if(e[n]!==void 0)return e[n];const s=i.getExtension(n);return e[n]=s,s}return{has:function(n){return t(n)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(n){const s=t(n);return s===null&&zo("WebGLRenderer: "+n+" extension not supported."),s}}}function MS(i,e,t,n){const s={},r=new WeakMap,a=new FinalizationRegistry(_=>delete s[_]);function o(_){l(_.target)}function l(_){_.index!==null&&e.remove(_.index);for(const p in _.attributes)e.remove(_.attributes[p]);_.removeEventListener("dispose",o),delete s[_.id],a.unregister(_);const M=r.get(_);M&&(e.remove(M),r.delete(_)),n.releaseStatesOfGeometry(_),_.isInstancedBufferGeometry===!0&&delete _._maxInstanceCount,t.memory.geometries--}function c(_,M){return s[M.id]!==void 0||(M.addEventListener("dispose",o),s[M.id]=new WeakRef(M),a.register(M,M.id,M),t.memory.geometries++),M}function h(_){const M=_.attributes;for(const p in M)e.update(M[p],i.ARRAY_BUFFER)}function u(_){const M=_.index,p=_.attributes.position;let f=0;if(p===void 0)return;const x=M!==null?M.array.length:p.array.length/3-1,A=p.count>=65535?Cp:Rp,S=new A(Math.ceil(x/3)*6,1),R=S.array;if(M!==null){const g=M.array;f=M.version;for(let b=0,k=0;b<x;b+=3){const I=g[b+0],L=g[b+1],G=g[b+2];R[k++]=I,R[k++]=L,R[k++]=L,R[k++]=G,R[k++]=G,R[k++]=I}}else{f=p.version;for(let g=0,b=0;g<x;g+=3){const k=g+0,I=g+1,L=g+2;R[b++]=k,R[b++]=I,R[b++]=I,R[b++]=L,R[b++]=L,R[b++]=k}}S.version=f;const y=r.get(_);y&&e.remove(y),r.set(_,S)}function d(_){const M=r.get(_);if(M){const p=_.index;p!==null&&M.version<p.version&&u(_)}else u(_);return r.get(_)}function m(){for(const _ in s){const M=s[_].deref();M!==void 0&&l(M)}}return{get:c,update:h,getWireframeAttribute:d,dispose:m}}function yS(i,e,t){let n;function s(u){n=u}let r,a;function o(u){r=u.type,a=u.bytesPerElement}function l(u,d){i.drawElements(n,d,r,u*a),t.update(d,n,1)}function c(u,d,m){m!==0&&(i.drawElementsInstanced(n,d,r,u*a,m),t.update(d,n,m))}function h(u,d,m){if(m===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(n,d,0,r,u,0,m);let M=0;for(let p=0;p<m;p++)M+=d[p];t.update(M,n,1)}this.setMode=s,this.setIndex=o,this.render=l,this.renderInstances=c,this.renderMultiDraw=h}function bS(i){const e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function n(r,a,o){switch(t.calls++,a){case i.TRIANGLES:t.triangles+=o*(r/3);break;case i.LINES:t.lines+=o*(r/2);break;case i.LINE_STRIP:t.lines+=o*(r-1);break;case i.LINE_LOOP:t.lines+=o*r;break;case i.POINTS:t.points+=o*r;break;default:St("WebGLInfo: Unknown draw mode:",a);break}}function s(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:s,update:n}}function wS(i,e,t){const n=new WeakMap,s=new nn;function r(a,o,l){const c=a.morphTargetInfluences,h=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,u=h!==void 0?h.length:0;let d=n.get(o);if(d===void 0||d.count!==u){let I=function(){b.dispose(),n.delete(o),o.removeEventListener("dispose",I)};var m=I;d!==void 0&&d.texture.dispose();const _=o.morphAttributes.position!==void 0,M=o.morphAttributes.normal!==void 0,p=o.morphAttributes.color!==void 0,f=o.morphAttributes.position||[],x=o.morphAttributes.normal||[],A=o.morphAttributes.color||[];let S=0;_===!0&&(S=1),M===!0&&(S=2),p===!0&&(S=3);let R=o.attributes.position.count*S,y=1;R>e.maxTextureSize&&(y=Math.ceil(R/e.maxTextureSize),R=e.maxTextureSize);const g=new Float32Array(R*y*4*u),b=new Ep(g,R,y,u);b.type=Vi,b.needsUpdate=!0;const k=S*4;for(let L=0;L<u;L++){const G=f[L],W=x[L],U=A[L],X=R*y*4*L;for(let J=0;J<G.count;J++){const H=J*k;_===!0&&(s.fromBufferAttribute(G,J),g[X+H+0]=s.x,g[X+H+1]=s.y,g[X+H+2]=s.z,g[X+H+3]=0),M===!0&&(s.fromBufferAttribute(W,J),g[X+H+4]=s.x,g[X+H+5]=s.y,g[X+H+6]=s.z,g[X+H+7]=0),p===!0&&(s.fromBufferAttribute(U,J),g[X+H+8]=s.x,g[X+H+9]=s.y,g[X+H+10]=s.z,g[X+H+11]=U.itemSize===4?s.w:1)}}d={count:u,texture:b,size:new Xe(R,y)},n.set(o,d),o.addEventListener("dispose",I)}if(a.isInstancedMesh===!0&&a.morphTexture!==null)l.getUniforms().setValue(i,"morphTexture",a.morphTexture,t);else{let _=0;for(let p=0;p<c.length;p++)_+=c[p];const M=o.morphTargetsRelative?1:1-_;l.getUniforms().setValue(i,"morphTargetBaseInfluence",M),l.getUniforms().setValue(i,"morphTargetInfluences",c)}l.getUniforms().setValue(i,"morphTargetsTexture",d.texture,t),l.getUniforms().setValue(i,"morphTargetsTextureSize",d.size)}return{update:r}}function ES(i,e,t,n,s){let r=new WeakMap;function a(c){const h=s.render.frame,u=c.geometry,d=e.get(c,u);if(r.get(d)!==h&&(e.update(d),r.set(d,h)),c.isInstancedMesh&&(c.hasEventListener("dispose",l)===!1&&c.addEventListener("dispose",l),r.get(c)!==h&&(t.update(c.instanceMatrix,i.ARRAY_BUFFER),c.instanceColor!==null&&t.update(c.instanceColor,i.ARRAY_BUFFER),r.set(c,h))),c.isSkinnedMesh){const m=c.skeleton;r.get(m)!==h&&(m.update(),r.set(m,h))}return d}function o(){r=new WeakMap}function l(c){const h=c.target;h.removeEventListener("dispose",l),n.releaseStatesOfObject(h),t.remove(h.instanceMatrix),h.instanceColor!==null&&t.remove(h.instanceColor)}return{update:a,dispose:o}}const TS={[ip]:"LINEAR_TONE_MAPPING",[sp]:"REINHARD_TONE_MAPPING",[rp]:"CINEON_TONE_MAPPING",[ap]:"ACES_FILMIC_TONE_MAPPING",[lp]:"AGX_TONE_MAPPING",[cp]:"NEUTRAL_TONE_MAPPING",[op]:"CUSTOM_TONE_MAPPING"};function AS(i,e,t,n,s,r){const a=new $i(e,t,{type:i,depthBuffer:s,stencilBuffer:r,samples:n?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1});let o=null,l=null,c=null;const h=new Bt;h.setAttribute("position",new rn([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new rn([0,2,0,0,2,0],2));const u=new p_({uniforms:{tDiffuse:{value:null}},vertexShader:`
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
			}`,depthTest:!1,depthWrite:!1}),d=new sn(h,u),m=new zp(-1,1,1,-1,0,1);let _=null,M=null,p=!1,f,x=null,A=[],S=!1;this.setSize=function(R,y){a.setSize(R,y),o!==null&&o.setSize(R,y),l!==null&&l.setSize(R,y);for(let g=0;g<A.length;g++){const b=A[g];b.setSize&&b.setSize(R,y)}},this.setEffects=function(R){A=R,S=A.length>0&&A[0].isRenderPass===!0;const y=a.width,g=a.height;A.length>0&&o===null&&(o=new $i(y,g,{type:Yi,depthBuffer:!1,stencilBuffer:!1}),l=new $i(y,g,{type:Yi,depthBuffer:!1,stencilBuffer:!1}));const b=s===!0&&A.some(k=>k.needsDepthTexture===!0);b!==(a.depthTexture!==null)&&(b===!0&&c===null&&(c=new Hr(y,g),r===!0&&(c.format=As,c.type=zr)),a.dispose(),a.depthTexture=b?c:null,a.resolveDepthBuffer=b,a.storeMultisampledDepthBuffer=b);for(let k=0;k<A.length;k++){const I=A[k];I.setSize&&I.setSize(y,g),b&&I.needsDepthTexture===!0&&I.setDepthTexture&&I.setDepthTexture(c)}},this.begin=function(R,y){if(p||R.toneMapping===ls&&A.length===0)return!1;if(x=y,y!==null){const g=y.width,b=y.height;(a.width!==g||a.height!==b)&&this.setSize(g,b)}return S===!1&&R.setRenderTarget(a),f=R.toneMapping,R.toneMapping=ls,!0},this.hasRenderPass=function(){return S},this.end=function(R,y){R.toneMapping=f,p=!0;let g=a,b=o;for(let k=0;k<A.length;k++){const I=A[k];I.enabled!==!1&&(I.render(R,b,g,y),I.needsSwap!==!1&&(g=b,b=b===o?l:o))}if(_!==R.outputColorSpace||M!==R.toneMapping){_=R.outputColorSpace,M=R.toneMapping,u.defines={},xt.getTransfer(_)===Lt&&(u.defines.SRGB_TRANSFER="");const k=TS[M];k&&(u.defines[k]=""),u.needsUpdate=!0}u.uniforms.tDiffuse.value=g.texture,R.setRenderTarget(x),R.render(d,m),x=null,p=!1},this.isCompositing=function(){return p},this.dispose=function(){a.dispose(),o!==null&&o.dispose(),l!==null&&l.dispose(),h.dispose(),u.dispose()}}const Yp=new In,Kp=new Hr(1,1),Zp=new Ip(1),Jp=new Ep,jp=new W0,Qp=new Np,Ad=[],Rd=[],Cd=new Float32Array(16),Pd=new Float32Array(9),Ld=new Float32Array(4);function qr(i,e,t){const n=i[0];if(n<=0||n>0)return i;const s=e*t;let r=Ad[s];if(r===void 0&&(r=new Float32Array(s),Ad[s]=r),e!==0){n.toArray(r,0);for(let a=1,o=0;a!==e;++a)o+=t,i[a].toArray(r,o)}return r}function Mn(i,e){if(i.length!==e.length)return!1;for(let t=0,n=i.length;t<n;t++)if(i[t]!==e[t])return!1;return!0}function yn(i,e){for(let t=0,n=e.length;t<n;t++)i[t]=e[t]}function ll(i,e){let t=Rd[e];t===void 0&&(t=new Int32Array(e),Rd[e]=t);for(let n=0;n!==e;++n)t[n]=i.allocateTextureUnit();return t}function RS(i,e){const t=this.cache;t[0]!==e&&(i.uniform1f(this.addr,e),t[0]=e)}function CS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Mn(t,e))return;i.uniform2fv(this.addr,e),yn(t,e)}}function PS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(i.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(Mn(t,e))return;i.uniform3fv(this.addr,e),yn(t,e)}}function LS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Mn(t,e))return;i.uniform4fv(this.addr,e),yn(t,e)}}function DS(i,e){const t=this.cache,n=e.elements;if(n===void 0){if(Mn(t,e))return;i.uniformMatrix2fv(this.addr,!1,e),yn(t,e)}else{if(Mn(t,n))return;Ld.set(n),i.uniformMatrix2fv(this.addr,!1,Ld),yn(t,n)}}function NS(i,e){const t=this.cache,n=e.elements;if(n===void 0){if(Mn(t,e))return;i.uniformMatrix3fv(this.addr,!1,e),yn(t,e)}else{if(Mn(t,n))return;Pd.set(n),i.uniformMatrix3fv(this.addr,!1,Pd),yn(t,n)}}function IS(i,e){const t=this.cache,n=e.elements;if(n===void 0){if(Mn(t,e))return;i.uniformMatrix4fv(this.addr,!1,e),yn(t,e)}else{if(Mn(t,n))return;Cd.set(n),i.uniformMatrix4fv(this.addr,!1,Cd),yn(t,n)}}function US(i,e){const t=this.cache;t[0]!==e&&(i.uniform1i(this.addr,e),t[0]=e)}function FS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Mn(t,e))return;i.uniform2iv(this.addr,e),yn(t,e)}}function OS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(Mn(t,e))return;i.uniform3iv(this.addr,e),yn(t,e)}}function kS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Mn(t,e))return;i.uniform4iv(this.addr,e),yn(t,e)}}function BS(i,e){const t=this.cache;t[0]!==e&&(i.uniform1ui(this.addr,e),t[0]=e)}function zS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(Mn(t,e))return;i.uniform2uiv(this.addr,e),yn(t,e)}}function HS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(Mn(t,e))return;i.uniform3uiv(this.addr,e),yn(t,e)}}function VS(i,e){const t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(Mn(t,e))return;i.uniform4uiv(this.addr,e),yn(t,e)}}function cl(i){return i.version===0&&(i.compareFunction=Sp,i.needsUpdate=!0),i}function GS(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_2D_SHADOW?r=cl(Kp):r=Yp,t.setTexture2D(e||r,s)}function WS(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),t.setTexture3D(e||jp,s)}function XS(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_CUBE_SHADOW?r=cl(Zp):r=Qp,t.setTextureCube(e||r,s)}function $S(i,e,t){const n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),t.setTexture2DArray(e||Jp,s)}function qS(i){switch(i){case 5126:return RS;case 35664:return CS;case 35665:return PS;case 35666:return LS;case 35674:return DS;case 35675:return NS;case 35676:return IS;case 5124:case 35670:return US;case 35667:case 35671:return FS;case 35668:case 35672:return OS;case 35669:case 35673:return kS;case 5125:return BS;case 36294:return zS;case 36295:return HS;case 36296:return VS;case 35678:case 36198:case 36298:case 36306:case 35682:return GS;case 35679:case 36299:case 36307:return WS;case 35680:case 36300:case 36308:case 36293:return XS;case 36289:case 36303:case 36311:case 36292:return $S}}function YS(i,e){i.uniform1fv(this.addr,e)}function KS(i,e){const t=qr(e,this.size,2);i.uniform2fv(this.addr,t)}function ZS(i,e){const t=qr(e,this.size,3);i.uniform3fv(this.addr,t)}function JS(i,e){const t=qr(e,this.size,4);i.uniform4fv(this.addr,t)}function jS(i,e){const t=qr(e,this.size,4);i.uniformMatrix2fv(this.addr,!1,t)}function QS(i,e){const t=qr(e,this.size,9);i.uniformMatrix3fv(this.addr,!1,t)}function eM(i,e){const t=qr(e,this.size,16);i.uniformMatrix4fv(this.addr,!1,t)}function tM(i,e){i.uniform1iv(this.addr,e)}function nM(i,e){i.uniform2iv(this.addr,e)}function iM(i,e){i.uniform3iv(this.addr,e)}function sM(i,e){i.uniform4iv(this.addr,e)}function rM(i,e){i.uniform1uiv(this.addr,e)}function aM(i,e){i.uniform2uiv(this.addr,e)}function oM(i,e){i.uniform3uiv(this.addr,e)}function lM(i,e){i.uniform4uiv(this.addr,e)}function cM(i,e,t){const n=this.cache,s=e.length,r=ll(t,s);Mn(n,r)||(i.uniform1iv(this.addr,r),yn(n,r));let a;this.type===i.SAMPLER_2D_SHADOW?a=cl(Kp):a=Yp;for(let o=0;o!==s;++o)t.setTexture2D(e[o]||a,r[o])}function hM(i,e,t){const n=this.cache,s=e.length,r=ll(t,s);Mn(n,r)||(i.uniform1iv(this.addr,r),yn(n,r));for(let a=0;a!==s;++a)t.setTexture3D(e[a]||jp,r[a])}function uM(i,e,t){const n=this.cache,s=e.length,r=ll(t,s);Mn(n,r)||(i.uniform1iv(this.addr,r),yn(n,r));let a;this.type===i.SAMPLER_CUBE_SHADOW?a=cl(Zp):a=Qp;for(let o=0;o!==s;++o)t.setTextureCube(e[o]||a,r[o])}function dM(i,e,t){const n=this.cache,s=e.length,r=ll(t,s);Mn(n,r)||(i.uniform1iv(this.addr,r),yn(n,r));for(let a=0;a!==s;++a)t.setTexture2DArray(e[a]||Jp,r[a])}function fM(i){switch(i){case 5126:return YS;case 35664:return KS;case 35665:return ZS;case 35666:return JS;case 35674:return jS;case 35675:return QS;case 35676:return eM;case 5124:case 35670:return tM;case 35667:case 35671:return nM;case 35668:case 35672:return iM;case 35669:case 35673:return sM;case 5125:return rM;case 36294:return aM;case 36295:return oM;case 36296:return lM;case 35678:case 36198:case 36298:case 36306:case 35682:return cM;case 35679:case 36299:case 36307:return hM;case 35680:case 36300:case 36308:case 36293:return uM;case 36289:case 36303:case 36311:case 36292:return dM}}class pM{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.setValue=qS(t.type)}}class mM{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=fM(t.type)}}class gM{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,n){const s=this.seq;for(let r=0,a=s.length;r!==a;++r){const o=s[r];o.setValue(e,t[o.id],n)}}}const oc=/(\w+)(\])?(\[|\.)?/g;function Dd(i,e){i.seq.push(e),i.map[e.id]=e}function _M(i,e,t){const n=i.name,s=n.length;for(oc.lastIndex=0;;){const r=oc.exec(n),a=oc.lastIndex;let o=r[1];const l=r[2]==="]",c=r[3];if(l&&(o=o|0),c===void 0||c==="["&&a+2===s){Dd(t,c===void 0?new pM(o,i,e):new mM(o,i,e));break}else{let u=t.map[o];u===void 0&&(u=new gM(o),Dd(t,u)),t=u}}}class Ho{constructor(e,t){this.seq=[],this.map={};const n=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let a=0;a<n;++a){const o=e.getActiveUniform(t,a),l=e.getUniformLocation(t,o.name);_M(o,l,this)}const s=[],r=[];for(const a of this.seq)a.type===e.SAMPLER_2D_SHADOW||a.type===e.SAMPLER_CUBE_SHADOW||a.type===e.SAMPLER_2D_ARRAY_SHADOW?s.push(a):r.push(a);s.length>0&&(this.seq=s.concat(r))}setValue(e,t,n,s){const r=this.map[t];r!==void 0&&r.setValue(e,n,s)}setOptional(e,t,n){const s=t[n];s!==void 0&&this.setValue(e,n,s)}static upload(e,t,n,s){for(let r=0,a=t.length;r!==a;++r){const o=t[r],l=n[o.id];l.needsUpdate!==!1&&o.setValue(e,l.value,s)}}static seqWithValue(e,t){const n=[];for(let s=0,r=e.length;s!==r;++s){const a=e[s];a.id in t&&n.push(a)}return n}}function Nd(i,e,t){const n=i.createShader(e);return i.shaderSource(n,t),i.compileShader(n),n}const vM=37297;let xM=0;function SM(i,e){const t=i.split(`
`),n=[],s=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let a=s;a<r;a++){const o=a+1;n.push(`${o===e?">":" "} ${o}: ${t[a]}`)}return n.join(`
`)}const Id=new rt;function MM(i){xt._getMatrix(Id,xt.workingColorSpace,i);const e=`mat3( ${Id.elements.map(t=>t.toFixed(4))} )`;switch(xt.getTransfer(i)){case qo:return[e,"LinearTransferOETF"];case Lt:return[e,"sRGBTransferOETF"];default:return je("WebGLProgram: Unsupported color space: ",i),[e,"LinearTransferOETF"]}}function Ud(i,e,t){const n=i.getShaderParameter(e,i.COMPILE_STATUS),r=(i.getShaderInfoLog(e)||"").trim();if(n&&r==="")return"";const a=/ERROR: 0:(\d+)/.exec(r);if(a){const o=parseInt(a[1]);return t.toUpperCase()+`

`+r+`

`+SM(i.getShaderSource(e),o)}else return r}function yM(i,e){const t=MM(e);return[`vec4 ${i}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}const bM={[ip]:"Linear",[sp]:"Reinhard",[rp]:"Cineon",[ap]:"ACESFilmic",[lp]:"AgX",[cp]:"Neutral",[op]:"Custom"};function wM(i,e){const t=bM[e];return t===void 0?(je("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+i+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+i+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}const bo=new z;function EM(){xt.getLuminanceCoefficients(bo);const i=bo.x.toFixed(4),e=bo.y.toFixed(4),t=bo.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${i}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function TM(i){return[i.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",i.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(_a).join(`
`)}function AM(i){const e=[];for(const t in i){const n=i[t];n!==!1&&e.push("#define "+t+" "+n)}return e.join(`
`)}function RM(i,e){const t={},n=i.getProgramParameter(e,i.ACTIVE_ATTRIBUTES);for(let s=0;s<n;s++){const r=i.getActiveAttrib(e,s),a=r.name;let o=1;r.type===i.FLOAT_MAT2&&(o=2),r.type===i.FLOAT_MAT3&&(o=3),r.type===i.FLOAT_MAT4&&(o=4),t[a]={type:r.type,location:i.getAttribLocation(e,a),locationSize:o}}return t}function _a(i){return i!==""}function Fd(i,e){const t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return i.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function Od(i,e){return i.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}const CM=/^[ \t]*#include +<([\w\d./]+)>/gm;function gh(i){return i.replace(CM,PM)}function PM(i,e){const t=lt[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return gh(t)}const LM=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function kd(i){return i.replace(LM,DM)}function DM(i,e,t,n){let s="";for(let r=parseInt(e);r<parseInt(t);r++)s+=n.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function Bd(i){let e=`precision ${i.precision} float;
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
#define LOW_PRECISION`),e}const NM={[Uo]:"SHADOWMAP_TYPE_PCF",[ga]:"SHADOWMAP_TYPE_VSM"};function IM(i){return NM[i.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}const UM={[Pa]:"ENVMAP_MODE_REFRACTION"};function FM(i){return i.envMap===!1?"ENVMAP_MODE_REFLECTION":UM[i.envMapMode]||"ENVMAP_MODE_REFLECTION"}const OM={[np]:"ENVMAP_BLENDING_MULTIPLY",[M0]:"ENVMAP_BLENDING_MIX",[y0]:"ENVMAP_BLENDING_ADD"};function kM(i){return i.envMap===!1?"ENVMAP_BLENDING_NONE":OM[i.combine]||"ENVMAP_BLENDING_NONE"}function BM(i,e,t,n){const s=i.getContext(),r=t.defines;let a=t.vertexShader,o=t.fragmentShader;const l=IM(t),c=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=FM(t),u=kM(t),d=TM(t),m=AM(r),_=s.createProgram();let M,p,f=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(M=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(_a).join(`
`),M.length>0&&(M+=`
`),p=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(_a).join(`
`),p.length>0&&(p+=`
`)):(M=[Bd(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+h:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(_a).join(`
`),p=[Bd(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+c:"",t.envMap?"#define "+h:"",t.envMap?"#define "+u:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==ls?"#define TONE_MAPPING":"",t.toneMapping!==ls?lt.tonemapping_pars_fragment:"",t.toneMapping!==ls?wM("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",lt.colorspace_pars_fragment,yM("linearToOutputTexel",t.outputColorSpace),EM(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(_a).join(`
`)),a=gh(a),a=Fd(a,t),a=Od(a,t),o=gh(o),o=Fd(o,t),o=Od(o,t),a=kd(a),o=kd(o),t.isRawShaderMaterial!==!0&&(f=`#version 300 es
`,M=[d,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+M,p=["#define varying in",t.glslVersion===Hu?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===Hu?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+p);const x=f+M+a,A=f+p+o,S=Nd(s,s.VERTEX_SHADER,x),R=Nd(s,s.FRAGMENT_SHADER,A);s.attachShader(_,S),s.attachShader(_,R),t.index0AttributeName!==void 0?s.bindAttribLocation(_,0,t.index0AttributeName):t.hasPositionAttribute===!0&&s.bindAttribLocation(_,0,"position"),s.linkProgram(_);function y(I){if(i.debug.checkShaderErrors){const L=s.getProgramInfoLog(_)||"",G=s.getShaderInfoLog(S)||"",W=s.getShaderInfoLog(R)||"",U=L.trim(),X=G.trim(),J=W.trim();let H=!0,ce=!0;if(s.getProgramParameter(_,s.LINK_STATUS)===!1)if(H=!1,typeof i.debug.onShaderError=="function")i.debug.onShaderError(s,_,S,R);else{const Z=Ud(s,S,"vertex"),ee=Ud(s,R,"fragment");St("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(_,s.VALIDATE_STATUS)+`

Material Name: `+I.name+`
Material Type: `+I.type+`

Program Info Log: `+U+`
`+Z+`
`+ee)}else U!==""?je("WebGLProgram: Program Info Log:",U):(X===""||J==="")&&(ce=!1);ce&&(I.diagnostics={runnable:H,programLog:U,vertexShader:{log:X,prefix:M},fragmentShader:{log:J,prefix:p}})}s.deleteShader(S),s.deleteShader(R),g=new Ho(s,_),b=RM(s,_)}let g;this.getUniforms=function(){return g===void 0&&y(this),g};let b;this.getAttributes=function(){return b===void 0&&y(this),b};let k=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return k===!1&&(k=s.getProgramParameter(_,vM)),k},this.destroy=function(){n.releaseStatesOfProgram(this),s.deleteProgram(_),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=xM++,this.cacheKey=e,this.usedTimes=1,this.program=_,this.vertexShader=S,this.fragmentShader=R,this}let zM=0;class HM{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,n){const s=this._getShaderCacheForMaterial(e);return s.has(t)===!1&&(s.add(t),t.usedTimes++),s.has(n)===!1&&(s.add(n),n.usedTimes++),this}remove(e){const t=this.materialCache.get(e);for(const n of t)n.usedTimes--,n.usedTimes===0&&this.shaderCache.delete(n.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){const t=this.materialCache;let n=t.get(e);return n===void 0&&(n=new Set,t.set(e,n)),n}_getShaderStage(e){const t=this.shaderCache;let n=t.get(e);return n===void 0&&(n=new VM(e),t.set(e,n)),n}}class VM{constructor(e){this.id=zM++,this.code=e,this.usedTimes=0}}function GM(i){return i===Ks||i===Wo||i===Xo}function WM(i,e,t,n,s,r){const a=new qh,o=new HM,l=new Set,c=[],h=new Map,u=n.logarithmicDepthBuffer,d={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function m(g){return l.add(g),g===0?"uv":`uv${g}`}function _(g,b,k,I,L,G){const W=I.fog,U=L.geometry,X=g.isMeshStandardMaterial||g.isMeshLambertMaterial||g.isMeshPhongMaterial?I.environment:null,J=g.isMeshStandardMaterial||g.isMeshLambertMaterial&&!g.envMap||g.isMeshPhongMaterial&&!g.envMap,H=e.get(g.envMap||X,J),ce=d[g.type];let Z=n.precision;g.precision!==null&&(Z=n.getMaxPrecision(g.precision),Z!==g.precision&&je("WebGLProgram.getParameters:",g.precision,"not supported, using",Z,"instead."));const ee=U.morphAttributes.position||U.morphAttributes.normal||U.morphAttributes.color,se=ee!==void 0?ee.length:0;let pe=0;U.morphAttributes.position!==void 0&&(pe=1),U.morphAttributes.normal!==void 0&&(pe=2),U.morphAttributes.color!==void 0&&(pe=3);let fe,B,te,he;if(ce){const Re=Hi[ce];fe=Re.vertexShader,B=Re.fragmentShader}else{fe=g.vertexShader,B=g.fragmentShader;const Re=o.getVertexShaderStage(g),at=o.getFragmentShaderStage(g);o.update(g,Re,at),te=Re.id,he=at.id}const ge=i.getRenderTarget(),ve=i.state.buffers.depth.getReversed(),Ve=L.isInstancedMesh===!0,Qe=L.isBatchedMesh===!0,ze=!!g.map,nt=!!g.matcap,tt=!!H,Ye=tt&&H.isPMREMTexture===!0,It=!!g.aoMap,gt=!!g.lightMap,$t=!!g.bumpMap&&g.wireframe===!1,Mt=!!g.normalMap,an=!!g.displacementMap,dt=!!g.emissiveMap,pn=!!g.metalnessMap,Yt=!!g.roughnessMap,on=g.anisotropy>0,O=g.clearcoat>0,Ce=g.diffuseRoughness>0,qe=g.dispersion>0,st=g.retroreflectivity>0,we=g.iridescence>0,Ut=g.sheen>0,He=g.transmission>0,$e=on&&!!g.anisotropyMap,C=O&&!!g.clearcoatMap,w=O&&!!g.clearcoatNormalMap,q=O&&!!g.clearcoatRoughnessMap,de=Ce&&!!g.diffuseRoughnessMap,oe=we&&!!g.iridescenceMap,Se=we&&!!g.iridescenceThicknessMap,Me=Ut&&!!g.sheenColorMap,ne=Ut&&!!g.sheenRoughnessMap,re=!!g.specularMap,_e=!!g.specularColorMap,F=!!g.specularIntensityMap,ae=He&&!!g.transmissionMap,ie=He&&!!g.thicknessMap,Ee=!!g.gradientMap,xe=!!g.alphaMap,be=g.alphaTest>0,Ge=!!g.alphaHash,Ze=!!g.extensions;let ue=ls;g.toneMapped&&(ge===null||ge.isXRRenderTarget===!0)&&(ue=i.toneMapping);const Oe=Ye?H.isCompressedCubeTexture?H.image[0].mipmaps:H.mipmaps:null,Je={shaderID:ce,shaderType:g.type,shaderName:g.name,vertexShader:fe,fragmentShader:B,defines:g.defines,customVertexShaderID:te,customFragmentShaderID:he,isRawShaderMaterial:g.isRawShaderMaterial===!0,glslVersion:g.glslVersion,precision:Z,batching:Qe,batchingColor:Qe&&L._colorsTexture!==null,instancing:Ve,instancingColor:Ve&&L.instanceColor!==null,instancingMorph:Ve&&L.morphTexture!==null,outputColorSpace:ge===null?i.outputColorSpace:ge.isXRRenderTarget===!0?ge.texture.colorSpace:xt.workingColorSpace,alphaToCoverage:!!g.alphaToCoverage,map:ze,matcap:nt,envMap:tt,envMapMode:tt&&H.mapping,envMapPMREM:Ye,envMapMaxLod:Ye?Oe.length-1:null,envMapSize:Ye?Oe[0].width:null,aoMap:It,lightMap:gt,bumpMap:$t,normalMap:Mt,displacementMap:an,emissiveMap:dt,normalMapObjectSpace:Mt&&g.normalMapType===E0,normalMapTangentSpace:Mt&&g.normalMapType===dh,packedNormalMap:Mt&&g.normalMapType===dh&&GM(g.normalMap.format),metalnessMap:pn,roughnessMap:Yt,anisotropy:on,anisotropyMap:$e,clearcoat:O,clearcoatMap:C,clearcoatNormalMap:w,clearcoatRoughnessMap:q,diffuseRoughness:Ce,diffuseRoughnessMap:de,dispersion:qe,retroreflection:st,iridescence:we,iridescenceMap:oe,iridescenceThicknessMap:Se,sheen:Ut,sheenColorMap:Me,sheenRoughnessMap:ne,specularMap:re,specularColorMap:_e,specularIntensityMap:F,transmission:He,transmissionMap:ae,thicknessMap:ie,gradientMap:Ee,opaque:g.transparent===!1&&g.blending===ya&&g.alphaToCoverage===!1,alphaMap:xe,alphaTest:be,alphaHash:Ge,combine:g.combine,mapUv:ze&&m(g.map.channel),aoMapUv:It&&m(g.aoMap.channel),lightMapUv:gt&&m(g.lightMap.channel),bumpMapUv:$t&&m(g.bumpMap.channel),normalMapUv:Mt&&m(g.normalMap.channel),displacementMapUv:an&&m(g.displacementMap.channel),emissiveMapUv:dt&&m(g.emissiveMap.channel),metalnessMapUv:pn&&m(g.metalnessMap.channel),roughnessMapUv:Yt&&m(g.roughnessMap.channel),anisotropyMapUv:$e&&m(g.anisotropyMap.channel),clearcoatMapUv:C&&m(g.clearcoatMap.channel),clearcoatNormalMapUv:w&&m(g.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:q&&m(g.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:de&&m(g.diffuseRoughnessMap.channel),iridescenceMapUv:oe&&m(g.iridescenceMap.channel),iridescenceThicknessMapUv:Se&&m(g.iridescenceThicknessMap.channel),sheenColorMapUv:Me&&m(g.sheenColorMap.channel),sheenRoughnessMapUv:ne&&m(g.sheenRoughnessMap.channel),specularMapUv:re&&m(g.specularMap.channel),specularColorMapUv:_e&&m(g.specularColorMap.channel),specularIntensityMapUv:F&&m(g.specularIntensityMap.channel),transmissionMapUv:ae&&m(g.transmissionMap.channel),thicknessMapUv:ie&&m(g.thicknessMap.channel),alphaMapUv:xe&&m(g.alphaMap.channel),vertexTangents:!!U.attributes.tangent&&(Mt||on),vertexNormals:!!U.attributes.normal,vertexColors:g.vertexColors,vertexAlphas:g.vertexColors===!0&&!!U.attributes.color&&U.attributes.color.itemSize===4,pointsUvs:L.isPoints===!0&&!!U.attributes.uv&&(ze||xe),fog:!!W,useFog:g.fog===!0,fogExp2:!!W&&W.isFogExp2,flatShading:g.wireframe===!1&&(g.flatShading===!0||U.attributes.normal===void 0&&Mt===!1&&(g.isMeshLambertMaterial||g.isMeshPhongMaterial||g.isMeshStandardMaterial||g.isMeshPhysicalMaterial)),sizeAttenuation:g.sizeAttenuation===!0,logarithmicDepthBuffer:u,reversedDepthBuffer:ve,skinning:L.isSkinnedMesh===!0,hasPositionAttribute:U.attributes.position!==void 0,morphTargets:U.morphAttributes.position!==void 0,morphNormals:U.morphAttributes.normal!==void 0,morphColors:U.morphAttributes.color!==void 0,morphTargetsCount:se,morphTextureStride:pe,numSunLights:b.sun.length,numDirLights:b.directional.length,numPointLights:b.point.length,numSpotLights:b.spot.length,numSpotLightMaps:b.spotLightMap.length,numRectAreaLights:b.rectArea.length,numHemiLights:b.hemi.length,numSunLightShadows:b.sunShadowMap.length,numDirLightShadows:b.directionalShadowMap.length,numPointLightShadows:b.pointShadowMap.length,numSpotLightShadows:b.spotShadowMap.length,numSpotLightShadowsWithMaps:b.numSpotLightShadowsWithMaps,numLightProbes:b.numLightProbes,numLightProbeGrids:G.filter(Re=>Re.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:g.dithering,shadowMapEnabled:i.shadowMap.enabled&&k.length>0,shadowMapType:i.shadowMap.type,toneMapping:ue,decodeVideoTexture:ze&&g.map.isVideoTexture===!0&&xt.getTransfer(g.map.colorSpace)===Lt,decodeVideoTextureEmissive:dt&&g.emissiveMap.isVideoTexture===!0&&xt.getTransfer(g.emissiveMap.colorSpace)===Lt,premultipliedAlpha:g.premultipliedAlpha,doubleSided:g.side===fi,flipSided:g.side===Yn,useDepthPacking:g.depthPacking>=0,depthPacking:g.depthPacking||0,index0AttributeName:g.index0AttributeName,extensionClipCullDistance:Ze&&g.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Ze&&g.extensions.multiDraw===!0||Qe)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:g.customProgramCacheKey()};return Je.vertexUv1s=l.has(1),Je.vertexUv2s=l.has(2),Je.vertexUv3s=l.has(3),l.clear(),Je}function M(g){const b=[];if(g.shaderID?b.push(g.shaderID):(b.push(g.customVertexShaderID),b.push(g.customFragmentShaderID)),g.defines!==void 0)for(const k in g.defines)b.push(k),b.push(g.defines[k]);return g.isRawShaderMaterial===!1&&(p(b,g),f(b,g),b.push(i.outputColorSpace)),b.push(g.customProgramCacheKey),b.join()}function p(g,b){g.push(b.precision),g.push(b.outputColorSpace),g.push(b.envMapMode),g.push(b.envMapPMREM),g.push(b.envMapMaxLod),g.push(b.envMapSize),g.push(b.mapUv),g.push(b.alphaMapUv),g.push(b.lightMapUv),g.push(b.aoMapUv),g.push(b.bumpMapUv),g.push(b.normalMapUv),g.push(b.displacementMapUv),g.push(b.emissiveMapUv),g.push(b.metalnessMapUv),g.push(b.roughnessMapUv),g.push(b.anisotropyMapUv),g.push(b.clearcoatMapUv),g.push(b.clearcoatNormalMapUv),g.push(b.clearcoatRoughnessMapUv),g.push(b.diffuseRoughnessMapUv),g.push(b.iridescenceMapUv),g.push(b.iridescenceThicknessMapUv),g.push(b.sheenColorMapUv),g.push(b.sheenRoughnessMapUv),g.push(b.specularMapUv),g.push(b.specularColorMapUv),g.push(b.specularIntensityMapUv),g.push(b.transmissionMapUv),g.push(b.thicknessMapUv),g.push(b.combine),g.push(b.fogExp2),g.push(b.sizeAttenuation),g.push(b.morphTargetsCount),g.push(b.numSunLights),g.push(b.numDirLights),g.push(b.numPointLights),g.push(b.numSpotLights),g.push(b.numSpotLightMaps),g.push(b.numHemiLights),g.push(b.numRectAreaLights),g.push(b.numSunLightShadows),g.push(b.numDirLightShadows),g.push(b.numPointLightShadows),g.push(b.numSpotLightShadows),g.push(b.numSpotLightShadowsWithMaps),g.push(b.numLightProbes),g.push(b.numLightProbeGrids),g.push(b.shadowMapType),g.push(b.toneMapping),g.push(b.numClippingPlanes),g.push(b.numClipIntersection),g.push(b.depthPacking)}function f(g,b){a.disableAll(),b.instancing&&a.enable(0),b.instancingColor&&a.enable(1),b.instancingMorph&&a.enable(2),b.matcap&&a.enable(3),b.envMap&&a.enable(4),b.normalMapObjectSpace&&a.enable(5),b.normalMapTangentSpace&&a.enable(6),b.clearcoat&&a.enable(7),b.iridescence&&a.enable(8),b.alphaTest&&a.enable(9),b.vertexColors&&a.enable(10),b.vertexAlphas&&a.enable(11),b.vertexUv1s&&a.enable(12),b.vertexUv2s&&a.enable(13),b.vertexUv3s&&a.enable(14),b.vertexTangents&&a.enable(15),b.anisotropy&&a.enable(16),b.alphaHash&&a.enable(17),b.batching&&a.enable(18),b.dispersion&&a.enable(19),b.retroreflection&&a.enable(24),b.diffuseRoughness&&a.enable(25),b.batchingColor&&a.enable(20),b.gradientMap&&a.enable(21),b.packedNormalMap&&a.enable(22),b.vertexNormals&&a.enable(23),g.push(a.mask),a.disableAll(),b.fog&&a.enable(0),b.useFog&&a.enable(1),b.flatShading&&a.enable(2),b.logarithmicDepthBuffer&&a.enable(3),b.reversedDepthBuffer&&a.enable(4),b.skinning&&a.enable(5),b.morphTargets&&a.enable(6),b.morphNormals&&a.enable(7),b.morphColors&&a.enable(8),b.premultipliedAlpha&&a.enable(9),b.shadowMapEnabled&&a.enable(10),b.doubleSided&&a.enable(11),b.flipSided&&a.enable(12),b.useDepthPacking&&a.enable(13),b.dithering&&a.enable(14),b.transmission&&a.enable(15),b.sheen&&a.enable(16),b.opaque&&a.enable(17),b.pointsUvs&&a.enable(18),b.decodeVideoTexture&&a.enable(19),b.decodeVideoTextureEmissive&&a.enable(20),b.alphaToCoverage&&a.enable(21),b.numLightProbeGrids>0&&a.enable(22),b.hasPositionAttribute&&a.enable(23),g.push(a.mask)}function x(g){const b=d[g.type];let k;if(b){const I=Hi[b];k=u_.clone(I.uniforms)}else k=g.uniforms;return k}function A(g,b){let k=h.get(b);return k!==void 0?++k.usedTimes:(k=new BM(i,b,g,s),c.push(k),h.set(b,k)),k}function S(g){if(--g.usedTimes===0){const b=c.indexOf(g);c[b]=c[c.length-1],c.pop(),h.delete(g.cacheKey),g.destroy()}}function R(g){o.remove(g)}function y(){o.dispose()}return{getParameters:_,getProgramCacheKey:M,getUniforms:x,acquireProgram:A,releaseProgram:S,releaseShaderCache:R,programs:c,dispose:y}}function XM(){let i=new WeakMap;function e(a){return i.has(a)}function t(a){let o=i.get(a);return o===void 0&&(o={},i.set(a,o)),o}function n(a){i.delete(a)}function s(a,o,l){i.get(a)[o]=l}function r(){i=new WeakMap}return{has:e,get:t,remove:n,update:s,dispose:r}}function $M(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.material.id!==e.material.id?i.material.id-e.material.id:i.materialVariant!==e.materialVariant?i.materialVariant-e.materialVariant:i.z!==e.z?i.z-e.z:i.id-e.id}function zd(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.z!==e.z?e.z-i.z:i.id-e.id}function Hd(){const i=[];let e=0;const t=[],n=[],s=[];function r(){e=0,t.length=0,n.length=0,s.length=0}function a(d){let m=0;return d.isInstancedMesh&&(m+=2),d.isSkinnedMesh&&(m+=1),m}function o(d,m,_,M,p,f){let x=i[e];return x===void 0?(x={id:d.id,object:d,geometry:m,material:_,materialVariant:a(d),groupOrder:M,renderOrder:d.renderOrder,z:p,group:f},i[e]=x):(x.id=d.id,x.object=d,x.geometry=m,x.material=_,x.materialVariant=a(d),x.groupOrder=M,x.renderOrder=d.renderOrder,x.z=p,x.group=f),e++,x}function l(d,m,_,M,p,f,x){x.reversedDepth===!0&&(p=-p);const A=o(d,m,_,M,p,f);_.transmission>0?n.push(A):_.transparent===!0?s.push(A):t.push(A)}function c(d,m,_,M,p,f){const x=o(d,m,_,M,p,f);_.transmission>0?n.unshift(x):_.transparent===!0?s.unshift(x):t.unshift(x)}function h(d,m){t.length>1&&t.sort(d||$M),n.length>1&&n.sort(m||zd),s.length>1&&s.sort(m||zd)}function u(){for(let d=e,m=i.length;d<m;d++){const _=i[d];if(_.id===null)break;_.id=null,_.object=null,_.geometry=null,_.material=null,_.group=null}}return{opaque:t,transmissive:n,transparent:s,init:r,push:l,unshift:c,finish:u,sort:h}}function qM(){let i=new WeakMap;function e(n,s){const r=i.get(n);let a;return r===void 0?(a=new Hd,i.set(n,[a])):s>=r.length?(a=new Hd,r.push(a)):a=r[s],a}function t(){i=new WeakMap}return{get:e,dispose:t}}function YM(){const i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new z,color:new ct};break;case"SpotLight":t={position:new z,direction:new z,color:new ct,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new z,color:new ct,distance:0,decay:0};break;case"HemisphereLight":t={direction:new z,skyColor:new ct,groundColor:new ct};break;case"RectAreaLight":t={color:new ct,position:new z,halfWidth:new z,halfHeight:new z};break}return i[e.id]=t,t}}}function KM(){const i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Xe};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Xe};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Xe,shadowCameraNear:1,shadowCameraFar:1e3};break}return i[e.id]=t,t}}}let ZM=0;function JM(i,e){return(e.castShadow?2:0)-(i.castShadow?2:0)+(e.map?1:0)-(i.map?1:0)}function jM(i){const e=new YM,t=KM(),n={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let c=0;c<9;c++)n.probe.push(new z);const s=new z,r=new Dt,a=new Dt;function o(c){let h=0,u=0,d=0;for(let G=0;G<9;G++)n.probe[G].set(0,0,0);let m=0,_=0,M=0,p=0,f=0,x=0,A=0,S=0,R=0,y=0,g=0,b=0,k=0,I=0;c.sort(JM);for(let G=0,W=c.length;G<W;G++){const U=c[G],X=U.color,J=U.intensity,H=U.distance;let ce=null;if(U.shadow&&U.shadow.map&&(U.shadow.map.texture.format===Ks?ce=U.shadow.map.texture:ce=U.shadow.map.depthTexture||U.shadow.map.texture),U.isAmbientLight)h+=X.r*J,u+=X.g*J,d+=X.b*J;else if(U.isLightProbe){for(let Z=0;Z<9;Z++)n.probe[Z].addScaledVector(U.sh.coefficients[Z],J);I++}else if(U.isSunLight){const Z=e.get(U);if(Z.color.copy(U.color).multiplyScalar(U.intensity),U.castShadow){const ee=U.shadow,se=t.get(U);se.shadowIntensity=ee.intensity,se.shadowBias=ee.bias,se.shadowNormalBias=ee.normalBias,se.shadowRadius=ee.radius,se.shadowMapSize.copy(ee.mapSize).multiply(ee.getFrameExtents()),n.sunShadow[_]=se,n.sunShadowMap[_]=ce;const pe=ee.getViewportCount();for(let fe=0;fe<pe;fe++)n.sunShadowMatrix[M+fe]=ee.getMatrix(fe),n.sunShadowCascade[M+fe]=ee._cascadeData[fe];M+=pe,_++}n.sun[m]=Z,m++}else if(U.isDirectionalLight){const Z=e.get(U);if(Z.color.copy(U.color).multiplyScalar(U.intensity),U.castShadow){const ee=U.shadow,se=t.get(U);se.shadowIntensity=ee.intensity,se.shadowBias=ee.bias,se.shadowNormalBias=ee.normalBias,se.shadowRadius=ee.radius,se.shadowMapSize=ee.mapSize,n.directionalShadow[p]=se,n.directionalShadowMap[p]=ce,n.directionalShadowMatrix[p]=U.shadow.matrix,R++}n.directional[p]=Z,p++}else if(U.isSpotLight){const Z=e.get(U);Z.position.setFromMatrixPosition(U.matrixWorld),Z.color.copy(X).multiplyScalar(J),Z.distance=H,Z.coneCos=Math.cos(U.angle),Z.penumbraCos=Math.cos(U.angle*(1-U.penumbra)),Z.decay=U.decay,n.spot[x]=Z;const ee=U.shadow;if(U.map&&(n.spotLightMap[b]=U.map,b++,ee.updateMatrices(U),U.castShadow&&k++),n.spotLightMatrix[x]=ee.matrix,U.castShadow){const se=t.get(U);se.shadowIntensity=ee.intensity,se.shadowBias=ee.bias,se.shadowNormalBias=ee.normalBias,se.shadowRadius=ee.radius,se.shadowMapSize=ee.mapSize,n.spotShadow[x]=se,n.spotShadowMap[x]=ce,g++}x++}else if(U.isRectAreaLight){const Z=e.get(U);Z.color.copy(X).multiplyScalar(J),Z.halfWidth.set(U.width*.5,0,0),Z.halfHeight.set(0,U.height*.5,0),n.rectArea[A]=Z,A++}else if(U.isPointLight){const Z=e.get(U);if(Z.color.copy(U.color).multiplyScalar(U.intensity),Z.distance=U.distance,Z.decay=U.decay,U.castShadow){const ee=U.shadow,se=t.get(U);se.shadowIntensity=ee.intensity,se.shadowBias=ee.bias,se.shadowNormalBias=ee.normalBias,se.shadowRadius=ee.radius,se.shadowMapSize=ee.mapSize,se.shadowCameraNear=ee.camera.near,se.shadowCameraFar=ee.camera.far,n.pointShadow[f]=se,n.pointShadowMap[f]=ce,n.pointShadowMatrix[f]=U.shadow.matrix,y++}n.point[f]=Z,f++}else if(U.isHemisphereLight){const Z=e.get(U);Z.skyColor.copy(U.color).multiplyScalar(J),Z.groundColor.copy(U.groundColor).multiplyScalar(J),n.hemi[S]=Z,S++}}A>0&&(i.has("OES_texture_float_linear")===!0?(n.rectAreaLTC1=De.LTC_FLOAT_1,n.rectAreaLTC2=De.LTC_FLOAT_2):(n.rectAreaLTC1=De.LTC_HALF_1,n.rectAreaLTC2=De.LTC_HALF_2)),n.ambient[0]=h,n.ambient[1]=u,n.ambient[2]=d;const L=n.hash;(L.sunLength!==m||L.directionalLength!==p||L.pointLength!==f||L.spotLength!==x||L.rectAreaLength!==A||L.hemiLength!==S||L.numSunShadows!==_||L.numDirectionalShadows!==R||L.numPointShadows!==y||L.numSpotShadows!==g||L.numSpotMaps!==b||L.numLightProbes!==I)&&(n.sun.length=m,n.directional.length=p,n.spot.length=x,n.rectArea.length=A,n.point.length=f,n.hemi.length=S,n.sunShadow.length=_,n.sunShadowMap.length=_,n.sunShadowMatrix.length=M,n.sunShadowCascade.length=M,n.directionalShadow.length=R,n.directionalShadowMap.length=R,n.directionalShadowMatrix.length=R,n.pointShadow.length=y,n.pointShadowMap.length=y,n.pointShadowMatrix.length=y,n.spotShadow.length=g,n.spotShadowMap.length=g,n.spotLightMatrix.length=g+b-k,n.spotLightMap.length=b,n.numSpotLightShadowsWithMaps=k,n.numLightProbes=I,L.sunLength=m,L.directionalLength=p,L.pointLength=f,L.spotLength=x,L.rectAreaLength=A,L.hemiLength=S,L.numSunShadows=_,L.numDirectionalShadows=R,L.numPointShadows=y,L.numSpotShadows=g,L.numSpotMaps=b,L.numLightProbes=I,n.version=ZM++)}function l(c,h){let u=0,d=0,m=0,_=0,M=0,p=0;const f=h.matrixWorldInverse;for(let x=0,A=c.length;x<A;x++){const S=c[x];if(S.isSunLight){const R=n.sun[u];R.direction.setFromMatrixPosition(S.matrixWorld),R.direction.transformDirection(f),u++}else if(S.isDirectionalLight){const R=n.directional[d];R.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),R.direction.sub(s),R.direction.transformDirection(f),d++}else if(S.isSpotLight){const R=n.spot[_];R.position.setFromMatrixPosition(S.matrixWorld),R.position.applyMatrix4(f),R.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),R.direction.sub(s),R.direction.transformDirection(f),_++}else if(S.isRectAreaLight){const R=n.rectArea[M];R.position.setFromMatrixPosition(S.matrixWorld),R.position.applyMatrix4(f),a.identity(),r.copy(S.matrixWorld),r.premultiply(f),a.extractRotation(r),R.halfWidth.set(S.width*.5,0,0),R.halfHeight.set(0,S.height*.5,0),R.halfWidth.applyMatrix4(a),R.halfHeight.applyMatrix4(a),M++}else if(S.isPointLight){const R=n.point[m];R.position.setFromMatrixPosition(S.matrixWorld),R.position.applyMatrix4(f),m++}else if(S.isHemisphereLight){const R=n.hemi[p];R.direction.setFromMatrixPosition(S.matrixWorld),R.direction.transformDirection(f),p++}}}return{setup:o,setupView:l,state:n}}function Vd(i){const e=new jM(i),t=[],n=[],s=[];function r(u){h.camera=u,t.length=0,n.length=0,s.length=0}function a(u){u.isLightProbeGrid?s.push(u):t.push(u)}function o(u){n.push(u)}function l(){e.setup(t),s.sort((u,d)=>u.priority-d.priority||u.id-d.id)}function c(u){e.setupView(t,u)}const h={lightsArray:t,shadowsArray:n,lightProbeGridArray:s,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:h,setupLights:l,setupLightsView:c,pushLight:a,pushShadow:o}}function QM(i){let e=new WeakMap;function t(s,r=0){const a=e.get(s);let o;return a===void 0?(o=new Vd(i),e.set(s,[o])):r>=a.length?(o=new Vd(i),a.push(o)):o=a[r],o}function n(){e=new WeakMap}return{get:t,dispose:n}}const ey=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,ty=`uniform sampler2D shadow_pass;
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
}`,ny=[new z(1,0,0),new z(-1,0,0),new z(0,1,0),new z(0,-1,0),new z(0,0,1),new z(0,0,-1)],iy=[new z(0,-1,0),new z(0,-1,0),new z(0,0,1),new z(0,0,-1),new z(0,-1,0),new z(0,-1,0)],Gd=new Dt,fa=new z,lc=new z;function sy(i,e,t){let n=new Na;const s=new Xe,r=new Xe,a=new nn,o=new m_,l=new g_,c={},h=t.maxTextureSize,u={[Cs]:Yn,[Yn]:Cs,[fi]:fi},d=new Zs({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new Xe},radius:{value:4}},vertexShader:ey,fragmentShader:ty}),m=d.clone();m.defines.HORIZONTAL_PASS=1;const _=new Bt;_.setAttribute("position",new mi(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));const M=new sn(_,d),p=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Uo;let f=this.type;this.render=function(y,g,b){if(p.enabled===!1||p.autoUpdate===!1&&p.needsUpdate===!1||y.length===0)return;this.type===n0&&(je("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=Uo);const k=i.getRenderTarget(),I=i.getActiveCubeFace(),L=i.getActiveMipmapLevel(),G=i.state;G.setBlending(Ur),G.buffers.depth.getReversed()===!0?G.buffers.color.setClear(0,0,0,0):G.buffers.color.setClear(1,1,1,1),G.buffers.depth.setTest(!0),G.setScissorTest(!1);const W=f!==this.type;W&&g.traverse(function(U){U.material&&(Array.isArray(U.material)?U.material.forEach(X=>X.needsUpdate=!0):U.material.needsUpdate=!0)});for(let U=0,X=y.length;U<X;U++){const J=y[U],H=J.shadow;if(H===void 0){je("WebGLShadowMap:",J,"has no shadow.");continue}if(H.autoUpdate===!1&&H.needsUpdate===!1)continue;s.copy(H.mapSize);const ce=H.getFrameExtents();s.multiply(ce),r.copy(H.mapSize),(s.x>h||s.y>h)&&(s.x>h&&(r.x=Math.floor(h/ce.x),s.x=r.x*ce.x,H.mapSize.x=r.x),s.y>h&&(r.y=Math.floor(h/ce.y),s.y=r.y*ce.y,H.mapSize.y=r.y));const Z=i.state.buffers.depth.getReversed();if(H.camera._reversedDepth=Z,H.map===null||W===!0){if(H.map!==null&&(H.map.depthTexture!==null&&(H.map.depthTexture.dispose(),H.map.depthTexture=null),H.map.dispose()),this.type===ga){if(J.isPointLight){je("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}H.map=new $i(s.x,s.y,{format:Ks,type:Yi,minFilter:qn,magFilter:qn,generateMipmaps:!1}),H.map.texture.name=J.name+".shadowMap",H.map.depthTexture=new Hr(s.x,s.y,Vi),H.map.depthTexture.name=J.name+".shadowMapDepth",H.map.depthTexture.format=Ps,H.map.depthTexture.compareFunction=null,H.map.depthTexture.minFilter=Pn,H.map.depthTexture.magFilter=Pn}else J.isPointLight?(H.map=new Zh(s.x),H.map.depthTexture=new Ip(s.x,qi)):(H.map=new $i(s.x,s.y),H.map.depthTexture=new Hr(s.x,s.y,qi)),H.map.depthTexture.name=J.name+".shadowMap",H.map.depthTexture.format=Ps,this.type===Uo?(H.map.depthTexture.compareFunction=Z?xp:vp,H.map.depthTexture.minFilter=qn,H.map.depthTexture.magFilter=qn):(H.map.depthTexture.compareFunction=null,H.map.depthTexture.minFilter=Pn,H.map.depthTexture.magFilter=Pn);H.camera.updateProjectionMatrix()}H.map.isWebGLCubeRenderTarget!==!0&&(H.map.width!==s.x||H.map.height!==s.y)&&H.map.setSize(s.x,s.y);const ee=H.map.isWebGLCubeRenderTarget?6:H.getViewportCount();J.isPointLight!==!0&&H.updateMatrices(J,b);const se=(H.camera.layers.mask&4294967294)!==0?H.camera.layers:b.layers;for(let pe=0;pe<ee;pe++){const fe=H.getCamera(pe);if(J.isPointLight){const B=H.camera,te=H.matrix,he=J.distance||B.far;he!==B.far&&(B.far=he,B.updateProjectionMatrix()),fa.setFromMatrixPosition(J.matrixWorld),B.position.copy(fa),lc.copy(B.position),lc.add(ny[pe]),B.up.copy(iy[pe]),B.lookAt(lc),B.updateMatrixWorld(),te.makeTranslation(-fa.x,-fa.y,-fa.z),Gd.multiplyMatrices(B.projectionMatrix,B.matrixWorldInverse),H._frustum.setFromProjectionMatrix(Gd,B.coordinateSystem,B.reversedDepth)}if(H.map.isWebGLCubeRenderTarget)i.setRenderTarget(H.map,pe),i.clear();else{pe===0&&(i.setRenderTarget(H.map),i.clear());const B=H.getViewport(pe);a.set(r.x*B.x,r.y*B.y,r.x*B.z,r.y*B.w),G.viewport(a)}n=H.getFrustum(pe),S(g,b,fe,J,se,this.type)}H.isPointLightShadow!==!0&&this.type===ga&&x(H,b),H.needsUpdate=!1}f=this.type,p.needsUpdate=!1,i.setRenderTarget(k,I,L)};function x(y,g){const b=e.update(M);d.defines.VSM_SAMPLES!==y.blurSamples&&(d.defines.VSM_SAMPLES=y.blurSamples,m.defines.VSM_SAMPLES=y.blurSamples,d.needsUpdate=!0,m.needsUpdate=!0),y.mapPass===null?y.mapPass=new $i(s.x,s.y,{format:Ks,type:Yi}):(y.mapPass.width!==y.map.width||y.mapPass.height!==y.map.height)&&y.mapPass.setSize(y.map.width,y.map.height),d.uniforms.shadow_pass.value=y.map.depthTexture,d.uniforms.resolution.value.set(y.map.width,y.map.height),d.uniforms.radius.value=y.radius,i.setRenderTarget(y.mapPass),i.clear(),i.renderBufferDirect(g,null,b,d,M,null),m.uniforms.shadow_pass.value=y.mapPass.texture,m.uniforms.resolution.value.set(y.map.width,y.map.height),m.uniforms.radius.value=y.radius,i.setRenderTarget(y.map),i.clear(),i.renderBufferDirect(g,null,b,m,M,null)}function A(y,g,b,k){let I=null;const L=b.isPointLight===!0?y.customDistanceMaterial:y.customDepthMaterial;if(L!==void 0)I=L;else if(I=b.isPointLight===!0?l:o,i.localClippingEnabled&&g.clipShadows===!0&&Array.isArray(g.clippingPlanes)&&g.clippingPlanes.length!==0||g.displacementMap&&g.displacementScale!==0||g.alphaMap&&g.alphaTest>0||g.map&&g.alphaTest>0||g.alphaToCoverage===!0){const G=I.uuid,W=g.uuid;let U=c[G];U===void 0&&(U={},c[G]=U);let X=U[W];X===void 0&&(X=I.clone(),U[W]=X,g.addEventListener("dispose",R)),I=X}if(I.visible=g.visible,I.wireframe=g.wireframe,k===ga?I.side=g.shadowSide!==null?g.shadowSide:g.side:I.side=g.shadowSide!==null?g.shadowSide:u[g.side],I.alphaMap=g.alphaMap,I.alphaTest=g.alphaToCoverage===!0?.5:g.alphaTest,I.map=g.map,I.clipShadows=g.clipShadows,I.clippingPlanes=g.clippingPlanes,I.clipIntersection=g.clipIntersection,I.displacementMap=g.displacementMap,I.displacementScale=g.displacementScale,I.displacementBias=g.displacementBias,I.wireframeLinewidth=g.wireframeLinewidth,I.linewidth=g.linewidth,b.isPointLight===!0&&I.isMeshDistanceMaterial===!0){const G=i.properties.get(I);G.light=b}return I}function S(y,g,b,k,I,L){if(y.visible===!1)return;if(y.layers.test(I)&&(y.isMesh||y.isLine||y.isPoints)&&(y.castShadow||y.receiveShadow&&L===ga)&&(!y.frustumCulled||y.intersectsFrustum(n))){y.modelViewMatrix.multiplyMatrices(b.matrixWorldInverse,y.matrixWorld);const U=e.update(y),X=y.material;if(Array.isArray(X)){const J=U.groups;for(let H=0,ce=J.length;H<ce;H++){const Z=J[H],ee=X[Z.materialIndex];if(ee&&ee.visible){const se=A(y,ee,k,L);y.onBeforeShadow(i,y,g,b,U,se,Z),i.renderBufferDirect(b,null,U,se,y,Z),y.onAfterShadow(i,y,g,b,U,se,Z)}}}else if(X.visible){const J=A(y,X,k,L);y.onBeforeShadow(i,y,g,b,U,J,null),i.renderBufferDirect(b,null,U,J,y,null),y.onAfterShadow(i,y,g,b,U,J,null)}}const W=y.children;for(let U=0,X=W.length;U<X;U++)S(W[U],g,b,k,I,L)}function R(y){y.target.removeEventListener("dispose",R);for(const b in c){const k=c[b],I=y.target.uuid;I in k&&(k[I].dispose(),delete k[I])}}}function ry(i,e){function t(){let F=!1;const ae=new nn;let ie=null;const Ee=new nn(0,0,0,0);return{setMask:function(xe){ie!==xe&&!F&&(i.colorMask(xe,xe,xe,xe),ie=xe)},setLocked:function(xe){F=xe},setClear:function(xe,be,Ge,Ze,ue){ue===!0&&(xe*=Ze,be*=Ze,Ge*=Ze),ae.set(xe,be,Ge,Ze),Ee.equals(ae)===!1&&(i.clearColor(xe,be,Ge,Ze),Ee.copy(ae))},reset:function(){F=!1,ie=null,Ee.set(-1,0,0,0)}}}function n(){let F=!1,ae=!1,ie=null,Ee=null,xe=null;return{setReversed:function(be){if(ae!==be){const Ge=e.get("EXT_clip_control");be?Ge.clipControlEXT(Ge.LOWER_LEFT_EXT,Ge.ZERO_TO_ONE_EXT):Ge.clipControlEXT(Ge.LOWER_LEFT_EXT,Ge.NEGATIVE_ONE_TO_ONE_EXT),ae=be;const Ze=xe;xe=null,this.setClear(Ze)}},getReversed:function(){return ae},setTest:function(be){be?ve(i.DEPTH_TEST):Ve(i.DEPTH_TEST)},setMask:function(be){ie!==be&&!F&&(i.depthMask(be),ie=be)},setFunc:function(be){if(ae&&(be=U0[be]),Ee!==be){switch(be){case Ac:i.depthFunc(i.NEVER);break;case Rc:i.depthFunc(i.ALWAYS);break;case Cc:i.depthFunc(i.LESS);break;case Ca:i.depthFunc(i.LEQUAL);break;case Pc:i.depthFunc(i.EQUAL);break;case Lc:i.depthFunc(i.GEQUAL);break;case Dc:i.depthFunc(i.GREATER);break;case Nc:i.depthFunc(i.NOTEQUAL);break;default:i.depthFunc(i.LEQUAL)}Ee=be}},setLocked:function(be){F=be},setClear:function(be){xe!==be&&(xe=be,ae&&(be=1-be),i.clearDepth(be))},reset:function(){F=!1,ie=null,Ee=null,xe=null,ae=!1}}}function s(){let F=!1,ae=null,ie=null,Ee=null,xe=null,be=null,Ge=null,Ze=null,ue=null;return{setTest:function(Oe){F||(Oe?ve(i.STENCIL_TEST):Ve(i.STENCIL_TEST))},setMask:function(Oe){ae!==Oe&&!F&&(i.stencilMask(Oe),ae=Oe)},setFunc:function(Oe,Je,Re){(ie!==Oe||Ee!==Je||xe!==Re)&&(i.stencilFunc(Oe,Je,Re),ie=Oe,Ee=Je,xe=Re)},setOp:function(Oe,Je,Re){(be!==Oe||Ge!==Je||Ze!==Re)&&(i.stencilOp(Oe,Je,Re),be=Oe,Ge=Je,Ze=Re)},setLocked:function(Oe){F=Oe},setClear:function(Oe){ue!==Oe&&(i.clearStencil(Oe),ue=Oe)},reset:function(){F=!1,ae=null,ie=null,Ee=null,xe=null,be=null,Ge=null,Ze=null,ue=null}}}const r=new t,a=new n,o=new s;let l={};const c=new WeakMap;let h={},u={},d={},m=new WeakMap,_=[],M=null,p=!1,f=null,x=null,A=null,S=null,R=null,y=null,g=null,b=new ct(0,0,0),k=0,I=!1,L=null,G=null,W=null,U=null,X=null;const J=i.getParameter(i.MAX_COMBINED_TEXTURE_IMAGE_UNITS);let H=!1,ce=0;const Z=i.getParameter(i.VERSION);Z.indexOf("WebGL")!==-1?(ce=parseFloat(/^WebGL (\d)/.exec(Z)[1]),H=ce>=1):Z.indexOf("OpenGL ES")!==-1&&(ce=parseFloat(/^OpenGL ES (\d)/.exec(Z)[1]),H=ce>=2);let ee=null,se={};const pe=i.getParameter(i.SCISSOR_BOX),fe=i.getParameter(i.VIEWPORT),B=new nn().fromArray(pe),te=new nn().fromArray(fe);function he(F,ae,ie,Ee){const xe=new Uint8Array(4),be=i.createTexture();i.bindTexture(F,be),i.texParameteri(F,i.TEXTURE_MIN_FILTER,i.NEAREST),i.texParameteri(F,i.TEXTURE_MAG_FILTER,i.NEAREST);for(let Ge=0;Ge<ie;Ge++)F===i.TEXTURE_3D||F===i.TEXTURE_2D_ARRAY?i.texImage3D(ae,0,i.RGBA,1,1,Ee,0,i.RGBA,i.UNSIGNED_BYTE,xe):i.texImage2D(ae+Ge,0,i.RGBA,1,1,0,i.RGBA,i.UNSIGNED_BYTE,xe);return be}const ge={};ge[i.TEXTURE_2D]=he(i.TEXTURE_2D,i.TEXTURE_2D,1),ge[i.TEXTURE_CUBE_MAP]=he(i.TEXTURE_CUBE_MAP,i.TEXTURE_CUBE_MAP_POSITIVE_X,6),ge[i.TEXTURE_2D_ARRAY]=he(i.TEXTURE_2D_ARRAY,i.TEXTURE_2D_ARRAY,1,1),ge[i.TEXTURE_3D]=he(i.TEXTURE_3D,i.TEXTURE_3D,1,1),r.setClear(0,0,0,1),a.setClear(1),o.setClear(0),ve(i.DEPTH_TEST),a.setFunc(Ca),$t(!1),Mt(Ou),ve(i.CULL_FACE),It(Ur);function ve(F){h[F]!==!0&&(i.enable(F),h[F]=!0)}function Ve(F){h[F]!==!1&&(i.disable(F),h[F]=!1)}function Qe(F,ae){return d[F]!==ae?(i.bindFramebuffer(F,ae),d[F]=ae,F===i.DRAW_FRAMEBUFFER&&(d[i.FRAMEBUFFER]=ae),F===i.FRAMEBUFFER&&(d[i.DRAW_FRAMEBUFFER]=ae),!0):!1}function ze(F,ae){let ie=_,Ee=!1;if(F){ie=m.get(ae),ie===void 0&&(ie=[],m.set(ae,ie));const xe=F.textures;if(ie.length!==xe.length||ie[0]!==i.COLOR_ATTACHMENT0){for(let be=0,Ge=xe.length;be<Ge;be++)ie[be]=i.COLOR_ATTACHMENT0+be;ie.length=xe.length,Ee=!0}}else ie[0]!==i.BACK&&(ie[0]=i.BACK,Ee=!0);Ee&&i.drawBuffers(ie)}function nt(F){return M!==F?(i.useProgram(F),M=F,!0):!1}const tt={[Lr]:i.FUNC_ADD,[s0]:i.FUNC_SUBTRACT,[r0]:i.FUNC_REVERSE_SUBTRACT};tt[a0]=i.MIN,tt[o0]=i.MAX;const Ye={[l0]:i.ZERO,[c0]:i.ONE,[h0]:i.SRC_COLOR,[ep]:i.SRC_ALPHA,[g0]:i.SRC_ALPHA_SATURATE,[p0]:i.DST_COLOR,[d0]:i.DST_ALPHA,[u0]:i.ONE_MINUS_SRC_COLOR,[tp]:i.ONE_MINUS_SRC_ALPHA,[m0]:i.ONE_MINUS_DST_COLOR,[f0]:i.ONE_MINUS_DST_ALPHA,[_0]:i.CONSTANT_COLOR,[v0]:i.ONE_MINUS_CONSTANT_COLOR,[x0]:i.CONSTANT_ALPHA,[S0]:i.ONE_MINUS_CONSTANT_ALPHA};function It(F,ae,ie,Ee,xe,be,Ge,Ze,ue,Oe){if(F===Ur){p===!0&&(Ve(i.BLEND),p=!1);return}if(p===!1&&(ve(i.BLEND),p=!0),F!==i0){if(F!==f||Oe!==I){if((x!==Lr||R!==Lr)&&(i.blendEquation(i.FUNC_ADD),x=Lr,R=Lr),Oe)switch(F){case ya:i.blendFuncSeparate(i.ONE,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case ku:i.blendFunc(i.ONE,i.ONE);break;case Bu:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case zu:i.blendFuncSeparate(i.DST_COLOR,i.ONE_MINUS_SRC_ALPHA,i.ZERO,i.ONE);break;default:St("WebGLState: Invalid blending: ",F);break}else switch(F){case ya:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case ku:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE,i.ONE,i.ONE);break;case Bu:St("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case zu:St("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:St("WebGLState: Invalid blending: ",F);break}A=null,S=null,y=null,g=null,b.set(0,0,0),k=0,f=F,I=Oe}return}xe=xe||ae,be=be||ie,Ge=Ge||Ee,(ae!==x||xe!==R)&&(i.blendEquationSeparate(tt[ae],tt[xe]),x=ae,R=xe),(ie!==A||Ee!==S||be!==y||Ge!==g)&&(i.blendFuncSeparate(Ye[ie],Ye[Ee],Ye[be],Ye[Ge]),A=ie,S=Ee,y=be,g=Ge),(Ze.equals(b)===!1||ue!==k)&&(i.blendColor(Ze.r,Ze.g,Ze.b,ue),b.copy(Ze),k=ue),f=F,I=!1}function gt(F,ae){F.side===fi?Ve(i.CULL_FACE):ve(i.CULL_FACE);let ie=F.side===Yn;ae&&(ie=!ie),$t(ie),F.blending===ya&&F.transparent===!1?It(Ur):It(F.blending,F.blendEquation,F.blendSrc,F.blendDst,F.blendEquationAlpha,F.blendSrcAlpha,F.blendDstAlpha,F.blendColor,F.blendAlpha,F.premultipliedAlpha),a.setFunc(F.depthFunc),a.setTest(F.depthTest),a.setMask(F.depthWrite),r.setMask(F.colorWrite);const Ee=F.stencilWrite;o.setTest(Ee),Ee&&(o.setMask(F.stencilWriteMask),o.setFunc(F.stencilFunc,F.stencilRef,F.stencilFuncMask),o.setOp(F.stencilFail,F.stencilZFail,F.stencilZPass)),dt(F.polygonOffset,F.polygonOffsetFactor,F.polygonOffsetUnits),F.alphaToCoverage===!0?ve(i.SAMPLE_ALPHA_TO_COVERAGE):Ve(i.SAMPLE_ALPHA_TO_COVERAGE)}function $t(F){L!==F&&(F?i.frontFace(i.CW):i.frontFace(i.CCW),L=F)}function Mt(F){F!==e0?(ve(i.CULL_FACE),F!==G&&(F===Ou?i.cullFace(i.BACK):F===t0?i.cullFace(i.FRONT):i.cullFace(i.FRONT_AND_BACK))):Ve(i.CULL_FACE),G=F}function an(F){F!==W&&(H&&i.lineWidth(F),W=F)}function dt(F,ae,ie){F?(ve(i.POLYGON_OFFSET_FILL),(U!==ae||X!==ie)&&(U=ae,X=ie,a.getReversed()&&(ae=-ae,ie=-ie),i.polygonOffset(ae,ie))):Ve(i.POLYGON_OFFSET_FILL)}function pn(F){F?ve(i.SCISSOR_TEST):Ve(i.SCISSOR_TEST)}function Yt(F){F===void 0&&(F=i.TEXTURE0+J-1),ee!==F&&(i.activeTexture(F),ee=F)}function on(F,ae,ie){ie===void 0&&(ee===null?ie=i.TEXTURE0+J-1:ie=ee);let Ee=se[ie];Ee===void 0&&(Ee={type:void 0,texture:void 0},se[ie]=Ee),(Ee.type!==F||Ee.texture!==ae)&&(ee!==ie&&(i.activeTexture(ie),ee=ie),i.bindTexture(F,ae||ge[F]),Ee.type=F,Ee.texture=ae)}function O(){const F=se[ee];F!==void 0&&F.type!==void 0&&(i.bindTexture(F.type,null),F.type=void 0,F.texture=void 0)}function Ce(){try{i.compressedTexImage2D(...arguments)}catch(F){St("WebGLState:",F)}}function qe(){try{i.compressedTexImage3D(...arguments)}catch(F){St("WebGLState:",F)}}function st(){try{i.texSubImage2D(...arguments)}catch(F){St("WebGLState:",F)}}function we(){try{i.texSubImage3D(...arguments)}catch(F){St("WebGLState:",F)}}function Ut(){try{i.compressedTexSubImage2D(...arguments)}catch(F){St("WebGLState:",F)}}function He(){try{i.compressedTexSubImage3D(...arguments)}catch(F){St("WebGLState:",F)}}function $e(){try{i.texStorage2D(...arguments)}catch(F){St("WebGLState:",F)}}function C(){try{i.texStorage3D(...arguments)}catch(F){St("WebGLState:",F)}}function w(){try{i.texImage2D(...arguments)}catch(F){St("WebGLState:",F)}}function q(){try{i.texImage3D(...arguments)}catch(F){St("WebGLState:",F)}}function de(F){return u[F]!==void 0?u[F]:i.getParameter(F)}function oe(F,ae){u[F]!==ae&&(i.pixelStorei(F,ae),u[F]=ae)}function Se(F){B.equals(F)===!1&&(i.scissor(F.x,F.y,F.z,F.w),B.copy(F))}function Me(F){te.equals(F)===!1&&(i.viewport(F.x,F.y,F.z,F.w),te.copy(F))}function ne(F,ae){let ie=c.get(ae);ie===void 0&&(ie=new WeakMap,c.set(ae,ie));let Ee=ie.get(F);Ee===void 0&&(Ee=i.getUniformBlockIndex(ae,F.name),i.uniformBlockBinding(ae,Ee,Ee),ie.set(F,Ee))}function re(F,ae,ie){const xe=c.get(ae).get(F);l[xe]!==ie&&(i.bindBufferBase(i.UNIFORM_BUFFER,xe,ie),l[xe]=ie)}function _e(){i.disable(i.BLEND),i.disable(i.CULL_FACE),i.disable(i.DEPTH_TEST),i.disable(i.POLYGON_OFFSET_FILL),i.disable(i.SCISSOR_TEST),i.disable(i.STENCIL_TEST),i.disable(i.SAMPLE_ALPHA_TO_COVERAGE),i.blendEquation(i.FUNC_ADD),i.blendFunc(i.ONE,i.ZERO),i.blendFuncSeparate(i.ONE,i.ZERO,i.ONE,i.ZERO),i.blendColor(0,0,0,0),i.colorMask(!0,!0,!0,!0),i.clearColor(0,0,0,0),i.depthMask(!0),i.depthFunc(i.LESS),a.setReversed(!1),i.clearDepth(1),i.stencilMask(4294967295),i.stencilFunc(i.ALWAYS,0,4294967295),i.stencilOp(i.KEEP,i.KEEP,i.KEEP),i.clearStencil(0),i.cullFace(i.BACK),i.frontFace(i.CCW),i.polygonOffset(0,0),i.activeTexture(i.TEXTURE0),i.bindFramebuffer(i.FRAMEBUFFER,null),i.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),i.bindFramebuffer(i.READ_FRAMEBUFFER,null),i.useProgram(null),i.lineWidth(1),i.scissor(0,0,i.canvas.width,i.canvas.height),i.viewport(0,0,i.canvas.width,i.canvas.height),i.pixelStorei(i.PACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,!1),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,i.BROWSER_DEFAULT_WEBGL),i.pixelStorei(i.PACK_ROW_LENGTH,0),i.pixelStorei(i.PACK_SKIP_PIXELS,0),i.pixelStorei(i.PACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_ROW_LENGTH,0),i.pixelStorei(i.UNPACK_IMAGE_HEIGHT,0),i.pixelStorei(i.UNPACK_SKIP_PIXELS,0),i.pixelStorei(i.UNPACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_SKIP_IMAGES,0),h={},u={},ee=null,se={},d={},l={},m=new WeakMap,_=[],M=null,p=!1,f=null,x=null,A=null,S=null,R=null,y=null,g=null,b=new ct(0,0,0),k=0,I=!1,L=null,G=null,W=null,U=null,X=null,B.set(0,0,i.canvas.width,i.canvas.height),te.set(0,0,i.canvas.width,i.canvas.height),r.reset(),a.reset(),o.reset()}return{buffers:{color:r,depth:a,stencil:o},enable:ve,disable:Ve,bindFramebuffer:Qe,drawBuffers:ze,useProgram:nt,setBlending:It,setMaterial:gt,setFlipSided:$t,setCullFace:Mt,setLineWidth:an,setPolygonOffset:dt,setScissorTest:pn,activeTexture:Yt,bindTexture:on,unbindTexture:O,compressedTexImage2D:Ce,compressedTexImage3D:qe,texImage2D:w,texImage3D:q,pixelStorei:oe,getParameter:de,updateUBOMapping:ne,uniformBlockBinding:re,texStorage2D:$e,texStorage3D:C,texSubImage2D:st,texSubImage3D:we,compressedTexSubImage2D:Ut,compressedTexSubImage3D:He,scissor:Se,viewport:Me,reset:_e}}function ay(i,e,t,n,s,r,a){const o=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),c=new Xe,h=new WeakMap,u=new Set;let d;const m=new WeakMap,_=new Set,M=new FinalizationRegistry(C=>_.delete(C));let p=!1;try{p=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function f(C,w){return p?new OffscreenCanvas(C,w):Yo("canvas")}function x(C,w,q){let de=1;const oe=$e(C);if((oe.width>q||oe.height>q)&&(de=q/Math.max(oe.width,oe.height)),de<1)if(typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&C instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&C instanceof ImageBitmap||typeof VideoFrame<"u"&&C instanceof VideoFrame){const Se=Math.floor(de*oe.width),Me=Math.floor(de*oe.height);d===void 0&&(d=f(Se,Me));const ne=w?f(Se,Me):d;return ne.width=Se,ne.height=Me,ne.getContext("2d").drawImage(C,0,0,Se,Me),je("WebGLRenderer: Texture has been resized from ("+oe.width+"x"+oe.height+") to ("+Se+"x"+Me+")."),ne}else return"data"in C&&je("WebGLRenderer: Image in DataTexture is too big ("+oe.width+"x"+oe.height+")."),C;return C}function A(C){return C.generateMipmaps}function S(C){i.generateMipmap(C)}function R(C){return C.isWebGLCubeRenderTarget?i.TEXTURE_CUBE_MAP:C.isWebGL3DRenderTarget?i.TEXTURE_3D:C.isWebGLArrayRenderTarget||C.isCompressedArrayTexture?i.TEXTURE_2D_ARRAY:i.TEXTURE_2D}function y(C,w,q,de,oe,Se=!1){if(C!==null){if(i[C]!==void 0)return i[C];je("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+C+"'")}let Me;de&&(Me=e.get("EXT_texture_norm16"),Me||je("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let ne=w;if(w===i.RED&&(q===i.FLOAT&&(ne=i.R32F),q===i.HALF_FLOAT&&(ne=i.R16F),q===i.UNSIGNED_BYTE&&(ne=i.R8),q===i.UNSIGNED_SHORT&&Me&&(ne=Me.R16_EXT),q===i.SHORT&&Me&&(ne=Me.R16_SNORM_EXT)),w===i.RED_INTEGER&&(q===i.UNSIGNED_BYTE&&(ne=i.R8UI),q===i.UNSIGNED_SHORT&&(ne=i.R16UI),q===i.UNSIGNED_INT&&(ne=i.R32UI),q===i.BYTE&&(ne=i.R8I),q===i.SHORT&&(ne=i.R16I),q===i.INT&&(ne=i.R32I)),w===i.RG&&(q===i.FLOAT&&(ne=i.RG32F),q===i.HALF_FLOAT&&(ne=i.RG16F),q===i.UNSIGNED_BYTE&&(ne=i.RG8),q===i.UNSIGNED_SHORT&&Me&&(ne=Me.RG16_EXT),q===i.SHORT&&Me&&(ne=Me.RG16_SNORM_EXT)),w===i.RG_INTEGER&&(q===i.UNSIGNED_BYTE&&(ne=i.RG8UI),q===i.UNSIGNED_SHORT&&(ne=i.RG16UI),q===i.UNSIGNED_INT&&(ne=i.RG32UI),q===i.BYTE&&(ne=i.RG8I),q===i.SHORT&&(ne=i.RG16I),q===i.INT&&(ne=i.RG32I)),w===i.RGB_INTEGER&&(q===i.UNSIGNED_BYTE&&(ne=i.RGB8UI),q===i.UNSIGNED_SHORT&&(ne=i.RGB16UI),q===i.UNSIGNED_INT&&(ne=i.RGB32UI),q===i.BYTE&&(ne=i.RGB8I),q===i.SHORT&&(ne=i.RGB16I),q===i.INT&&(ne=i.RGB32I)),w===i.RGBA_INTEGER&&(q===i.UNSIGNED_BYTE&&(ne=i.RGBA8UI),q===i.UNSIGNED_SHORT&&(ne=i.RGBA16UI),q===i.UNSIGNED_INT&&(ne=i.RGBA32UI),q===i.BYTE&&(ne=i.RGBA8I),q===i.SHORT&&(ne=i.RGBA16I),q===i.INT&&(ne=i.RGBA32I)),w===i.RGB&&(q===i.UNSIGNED_SHORT&&Me&&(ne=Me.RGB16_EXT),q===i.SHORT&&Me&&(ne=Me.RGB16_SNORM_EXT),q===i.UNSIGNED_INT_5_9_9_9_REV&&(ne=i.RGB9_E5),q===i.UNSIGNED_INT_10F_11F_11F_REV&&(ne=i.R11F_G11F_B10F)),w===i.RGBA){const re=Se?qo:xt.getTransfer(oe);q===i.FLOAT&&(ne=i.RGBA32F),q===i.HALF_FLOAT&&(ne=i.RGBA16F),q===i.UNSIGNED_BYTE&&(ne=re===Lt?i.SRGB8_ALPHA8:i.RGBA8),q===i.UNSIGNED_SHORT&&Me&&(ne=Me.RGBA16_EXT),q===i.SHORT&&Me&&(ne=Me.RGBA16_SNORM_EXT),q===i.UNSIGNED_SHORT_4_4_4_4&&(ne=i.RGBA4),q===i.UNSIGNED_SHORT_5_5_5_1&&(ne=i.RGB5_A1)}return(ne===i.R16F||ne===i.R32F||ne===i.RG16F||ne===i.RG32F||ne===i.RGBA16F||ne===i.RGBA32F)&&e.get("EXT_color_buffer_float"),ne}function g(C,w){let q;return C?w===null||w===qi||w===zr?q=i.DEPTH24_STENCIL8:w===Vi?q=i.DEPTH32F_STENCIL8:w===La&&(q=i.DEPTH24_STENCIL8,je("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):w===null||w===qi||w===zr?q=i.DEPTH_COMPONENT24:w===Vi?q=i.DEPTH_COMPONENT32F:w===La&&(q=i.DEPTH_COMPONENT16),q}function b(C,w){return A(C)===!0||C.isFramebufferTexture&&C.minFilter!==Pn&&C.minFilter!==qn?Math.log2(Math.max(w.width,w.height))+1:C.mipmaps.length>0?C.mipmaps.length:C.isCompressedTexture&&Array.isArray(C.image)?w.mipmaps.length:1}function k(C){const w=new WeakRef(C);n.get(C).__ref=w,_.add(w),M.register(C,w,w)}function I(C){const w=n.get(C).__ref;w!==void 0&&(_.delete(w),M.unregister(w))}function L(C){W(C.target)}function G(C){U(C.target)}function W(C){C.removeEventListener("dispose",L),I(C),J(C),C.isVideoTexture&&h.delete(C),C.isHTMLTexture&&u.delete(C)}function U(C){C.removeEventListener("dispose",G),I(C),ce(C)}function X(){for(const C of _){const w=C.deref();w!==void 0&&(w.isRenderTarget===!0?U(w):W(w))}_.clear(),u.clear()}function J(C){const w=n.get(C);if(w.__webglInit===void 0)return;const q=C.source,de=m.get(q);if(de){const oe=de[w.__cacheKey];oe.usedTimes--,oe.usedTimes===0&&H(C),Object.keys(de).length===0&&m.delete(q)}n.remove(C)}function H(C){const w=n.get(C);i.deleteTexture(w.__webglTexture);const q=C.source,de=m.get(q);delete de[w.__cacheKey],a.memory.textures--}function ce(C){const w=n.get(C);w.__depthDisposeCallback&&w.__depthDisposeCallback();const q=C.depthTexture;if(q&&q.renderTarget===C&&W(q),C.isWebGLCubeRenderTarget)for(let oe=0;oe<6;oe++){if(Array.isArray(w.__webglFramebuffer[oe]))for(let Se=0;Se<w.__webglFramebuffer[oe].length;Se++)i.deleteFramebuffer(w.__webglFramebuffer[oe][Se]);else i.deleteFramebuffer(w.__webglFramebuffer[oe]);w.__webglDepthbuffer&&i.deleteRenderbuffer(w.__webglDepthbuffer[oe])}else{if(Array.isArray(w.__webglFramebuffer))for(let oe=0;oe<w.__webglFramebuffer.length;oe++)i.deleteFramebuffer(w.__webglFramebuffer[oe]);else i.deleteFramebuffer(w.__webglFramebuffer);if(w.__webglDepthbuffer&&i.deleteRenderbuffer(w.__webglDepthbuffer),w.__webglMultisampledFramebuffer&&i.deleteFramebuffer(w.__webglMultisampledFramebuffer),w.__webglColorRenderbuffer)for(let oe=0;oe<w.__webglColorRenderbuffer.length;oe++)w.__webglColorRenderbuffer[oe]&&i.deleteRenderbuffer(w.__webglColorRenderbuffer[oe]);w.__webglDepthRenderbuffer&&i.deleteRenderbuffer(w.__webglDepthRenderbuffer)}const de=C.textures;for(let oe=0,Se=de.length;oe<Se;oe++){const Me=n.get(de[oe]);Me.__webglTexture&&(i.deleteTexture(Me.__webglTexture),a.memory.textures--),n.remove(de[oe])}n.remove(C)}let Z=0;function ee(){Z=0}function se(){return Z}function pe(C){Z=C}function fe(){const C=Z;return C>=s.maxTextures&&je("WebGLTextures: Trying to use "+(C+1)+" texture units while this GPU supports only "+s.maxTextures),Z+=1,C}function B(C){const w=[];return w.push(C.wrapS),w.push(C.wrapT),w.push(C.wrapR||0),w.push(C.magFilter),w.push(C.minFilter),w.push(C.anisotropy),w.push(C.internalFormat),w.push(C.format),w.push(C.type),w.push(C.generateMipmaps),w.push(C.mipmapsAutoUpdate),w.push(C.premultiplyAlpha),w.push(C.flipY),w.push(C.unpackAlignment),w.push(C.colorSpace),w.join()}function te(C,w){const q=n.get(C);if(C.isVideoTexture&&Ut(C),C.isRenderTargetTexture===!1&&C.isExternalTexture!==!0&&C.version>0&&q.__version!==C.version){const de=C.image;if(de===null)je("WebGLRenderer: Texture marked for update but no image data found.");else if(de.complete===!1)je("WebGLRenderer: Texture marked for update but image is incomplete");else{gt(q,C,w);return}}else C.isExternalTexture&&(q.__webglTexture=C.sourceTexture?C.sourceTexture:null);t.bindTexture(i.TEXTURE_2D,q.__webglTexture,i.TEXTURE0+w)}function he(C,w){const q=n.get(C);if(C.isRenderTargetTexture===!1&&C.version>0&&q.__version!==C.version){gt(q,C,w);return}else C.isExternalTexture&&(q.__webglTexture=C.sourceTexture?C.sourceTexture:null);t.bindTexture(i.TEXTURE_2D_ARRAY,q.__webglTexture,i.TEXTURE0+w)}function ge(C,w){const q=n.get(C);if(C.isRenderTargetTexture===!1&&C.version>0&&q.__version!==C.version){gt(q,C,w);return}t.bindTexture(i.TEXTURE_3D,q.__webglTexture,i.TEXTURE0+w)}function ve(C,w){const q=n.get(C);if(C.version>0&&q.__version!==C.version){$t(q,C,w);return}t.bindTexture(i.TEXTURE_CUBE_MAP,q.__webglTexture,i.TEXTURE0+w)}const Ve={[Ic]:i.REPEAT,[as]:i.CLAMP_TO_EDGE,[Uc]:i.MIRRORED_REPEAT},Qe={[Pn]:i.NEAREST,[b0]:i.NEAREST_MIPMAP_NEAREST,[Ka]:i.NEAREST_MIPMAP_LINEAR,[qn]:i.LINEAR,[Il]:i.LINEAR_MIPMAP_NEAREST,[Ts]:i.LINEAR_MIPMAP_LINEAR},ze={[A0]:i.NEVER,[Sp]:i.ALWAYS,[R0]:i.LESS,[vp]:i.LEQUAL,[C0]:i.EQUAL,[xp]:i.GEQUAL,[P0]:i.GREATER,[L0]:i.NOTEQUAL};function nt(C,w){if(w.type===Vi&&e.has("OES_texture_float_linear")===!1&&(w.magFilter===qn||w.magFilter===Il||w.magFilter===Ka||w.magFilter===Ts||w.minFilter===qn||w.minFilter===Il||w.minFilter===Ka||w.minFilter===Ts)&&je("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),i.texParameteri(C,i.TEXTURE_WRAP_S,Ve[w.wrapS]),i.texParameteri(C,i.TEXTURE_WRAP_T,Ve[w.wrapT]),(C===i.TEXTURE_3D||C===i.TEXTURE_2D_ARRAY)&&i.texParameteri(C,i.TEXTURE_WRAP_R,Ve[w.wrapR]),i.texParameteri(C,i.TEXTURE_MAG_FILTER,Qe[w.magFilter]),i.texParameteri(C,i.TEXTURE_MIN_FILTER,Qe[w.minFilter]),w.compareFunction&&(i.texParameteri(C,i.TEXTURE_COMPARE_MODE,i.COMPARE_REF_TO_TEXTURE),i.texParameteri(C,i.TEXTURE_COMPARE_FUNC,ze[w.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(w.magFilter===Pn||w.minFilter!==Ka&&w.minFilter!==Ts||w.type===Vi&&e.has("OES_texture_float_linear")===!1)return;if(w.anisotropy>1||n.get(w).__currentAnisotropy){const q=e.get("EXT_texture_filter_anisotropic");i.texParameterf(C,q.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(w.anisotropy,s.getMaxAnisotropy())),n.get(w).__currentAnisotropy=w.anisotropy}}}function tt(C,w){let q=!1;C.__webglInit===void 0&&(C.__webglInit=!0,w.addEventListener("dispose",L),k(w));const de=w.source;let oe=m.get(de);oe===void 0&&(oe={},m.set(de,oe));const Se=B(w);if(Se!==C.__cacheKey){oe[Se]===void 0&&(oe[Se]={texture:i.createTexture(),usedTimes:0},a.memory.textures++,q=!0),oe[Se].usedTimes++;const Me=oe[C.__cacheKey];Me!==void 0&&(oe[C.__cacheKey].usedTimes--,Me.usedTimes===0&&H(w)),C.__cacheKey=Se,C.__webglTexture=oe[Se].texture}return q}function Ye(C,w,q){return Math.floor(Math.floor(C/q)/w)}function It(C,w,q,de){const Se=C.updateRanges;if(Se.length===0)t.texSubImage2D(i.TEXTURE_2D,0,0,0,w.width,w.height,q,de,w.data);else{Se.sort((F,ae)=>F.start-ae.start);let Me=0;for(let F=1;F<Se.length;F++){const ae=Se[Me],ie=Se[F],Ee=ae.start+ae.count,xe=Ye(ie.start,w.width,4),be=Ye(ae.start,w.width,4);ie.start<=Ee+1&&xe===be&&Ye(ie.start+ie.count-1,w.width,4)===xe?ae.count=Math.max(ae.count,ie.start+ie.count-ae.start):(++Me,Se[Me]=ie)}Se.length=Me+1;const ne=t.getParameter(i.UNPACK_ROW_LENGTH),re=t.getParameter(i.UNPACK_SKIP_PIXELS),_e=t.getParameter(i.UNPACK_SKIP_ROWS);t.pixelStorei(i.UNPACK_ROW_LENGTH,w.width);for(let F=0,ae=Se.length;F<ae;F++){const ie=Se[F],Ee=Math.floor(ie.start/4),xe=Math.ceil(ie.count/4),be=Ee%w.width,Ge=Math.floor(Ee/w.width),Ze=xe,ue=1;t.pixelStorei(i.UNPACK_SKIP_PIXELS,be),t.pixelStorei(i.UNPACK_SKIP_ROWS,Ge),t.texSubImage2D(i.TEXTURE_2D,0,be,Ge,Ze,ue,q,de,w.data)}C.clearUpdateRanges(),t.pixelStorei(i.UNPACK_ROW_LENGTH,ne),t.pixelStorei(i.UNPACK_SKIP_PIXELS,re),t.pixelStorei(i.UNPACK_SKIP_ROWS,_e)}}function gt(C,w,q){let de=i.TEXTURE_2D;(w.isDataArrayTexture||w.isCompressedArrayTexture)&&(de=i.TEXTURE_2D_ARRAY),w.isData3DTexture&&(de=i.TEXTURE_3D);const oe=tt(C,w),Se=w.source;t.bindTexture(de,C.__webglTexture,i.TEXTURE0+q);const Me=n.get(Se);if(Se.version!==Me.__version||oe===!0){if(t.activeTexture(i.TEXTURE0+q),(typeof ImageBitmap<"u"&&w.image instanceof ImageBitmap)===!1){const ue=xt.getPrimaries(xt.workingColorSpace),Oe=w.colorSpace===Es?null:xt.getPrimaries(w.colorSpace),Je=w.colorSpace===Es||ue===Oe?i.NONE:i.BROWSER_DEFAULT_WEBGL;t.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,w.flipY),t.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,w.premultiplyAlpha),t.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,Je)}t.pixelStorei(i.UNPACK_ALIGNMENT,w.unpackAlignment);let re=x(w.image,!1,s.maxTextureSize);re=He(w,re);const _e=r.convert(w.format,w.colorSpace),F=r.convert(w.type);let ae=y(w.internalFormat,_e,F,w.normalized,w.colorSpace,w.isVideoTexture);nt(de,w);let ie;const Ee=w.mipmaps,xe=w.isVideoTexture!==!0,be=Me.__version===void 0||oe===!0,Ge=Se.dataReady,Ze=b(w,re);if(w.isDepthTexture)ae=g(w.format===As,w.type),be&&(xe?t.texStorage2D(i.TEXTURE_2D,1,ae,re.width,re.height):t.texImage2D(i.TEXTURE_2D,0,ae,re.width,re.height,0,_e,F,null));else if(w.isDataTexture)if(Ee.length>0){xe&&be&&t.texStorage2D(i.TEXTURE_2D,Ze,ae,Ee[0].width,Ee[0].height);for(let ue=0,Oe=Ee.length;ue<Oe;ue++)ie=Ee[ue],xe?Ge&&t.texSubImage2D(i.TEXTURE_2D,ue,0,0,ie.width,ie.height,_e,F,ie.data):t.texImage2D(i.TEXTURE_2D,ue,ae,ie.width,ie.height,0,_e,F,ie.data);w.generateMipmaps=!1}else xe?(be&&t.texStorage2D(i.TEXTURE_2D,Ze,ae,re.width,re.height),Ge&&It(w,re,_e,F)):t.texImage2D(i.TEXTURE_2D,0,ae,re.width,re.height,0,_e,F,re.data);else if(w.isCompressedTexture)if(w.isCompressedArrayTexture){xe&&be&&t.texStorage3D(i.TEXTURE_2D_ARRAY,Ze,ae,Ee[0].width,Ee[0].height,re.depth);for(let ue=0,Oe=Ee.length;ue<Oe;ue++)if(ie=Ee[ue],w.format!==Gi)if(_e!==null)if(xe){if(Ge)if(w.layerUpdates.size>0){const Je=yd(ie.width,ie.height,w.format,w.type);for(const Re of w.layerUpdates){const at=ie.data.subarray(Re*Je/ie.data.BYTES_PER_ELEMENT,(Re+1)*Je/ie.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ue,0,0,Re,ie.width,ie.height,1,_e,at)}}else t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ue,0,0,0,ie.width,ie.height,re.depth,_e,ie.data)}else t.compressedTexImage3D(i.TEXTURE_2D_ARRAY,ue,ae,ie.width,ie.height,re.depth,0,ie.data,0,0);else je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else xe?Ge&&t.texSubImage3D(i.TEXTURE_2D_ARRAY,ue,0,0,0,ie.width,ie.height,re.depth,_e,F,ie.data):t.texImage3D(i.TEXTURE_2D_ARRAY,ue,ae,ie.width,ie.height,re.depth,0,_e,F,ie.data);w.layerUpdates.size>0&&w.clearLayerUpdates()}else{xe&&be&&t.texStorage2D(i.TEXTURE_2D,Ze,ae,Ee[0].width,Ee[0].height);for(let ue=0,Oe=Ee.length;ue<Oe;ue++)ie=Ee[ue],w.format!==Gi?_e!==null?xe?Ge&&t.compressedTexSubImage2D(i.TEXTURE_2D,ue,0,0,ie.width,ie.height,_e,ie.data):t.compressedTexImage2D(i.TEXTURE_2D,ue,ae,ie.width,ie.height,0,ie.data):je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):xe?Ge&&t.texSubImage2D(i.TEXTURE_2D,ue,0,0,ie.width,ie.height,_e,F,ie.data):t.texImage2D(i.TEXTURE_2D,ue,ae,ie.width,ie.height,0,_e,F,ie.data)}else if(w.isDataArrayTexture)if(xe){if(be&&t.texStorage3D(i.TEXTURE_2D_ARRAY,Ze,ae,re.width,re.height,re.depth),Ge)if(w.layerUpdates.size>0){const ue=yd(re.width,re.height,w.format,w.type);for(const Oe of w.layerUpdates){const Je=re.data.subarray(Oe*ue/re.data.BYTES_PER_ELEMENT,(Oe+1)*ue/re.data.BYTES_PER_ELEMENT);t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,Oe,re.width,re.height,1,_e,F,Je)}w.clearLayerUpdates()}else t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,0,re.width,re.height,re.depth,_e,F,re.data)}else t.texImage3D(i.TEXTURE_2D_ARRAY,0,ae,re.width,re.height,re.depth,0,_e,F,re.data);else if(w.isData3DTexture)xe?(be&&t.texStorage3D(i.TEXTURE_3D,Ze,ae,re.width,re.height,re.depth),Ge&&t.texSubImage3D(i.TEXTURE_3D,0,0,0,0,re.width,re.height,re.depth,_e,F,re.data)):t.texImage3D(i.TEXTURE_3D,0,ae,re.width,re.height,re.depth,0,_e,F,re.data);else if(w.isFramebufferTexture){if(be)if(xe)t.texStorage2D(i.TEXTURE_2D,Ze,ae,re.width,re.height);else{let ue=re.width,Oe=re.height;for(let Je=0;Je<Ze;Je++)t.texImage2D(i.TEXTURE_2D,Je,ae,ue,Oe,0,_e,F,null),ue>>=1,Oe>>=1}}else if(w.isHTMLTexture){if("texElementImage2D"in i){const ue=i.canvas;if(ue.hasAttribute("layoutsubtree")||ue.setAttribute("layoutsubtree","true"),re.parentNode!==ue){ue.appendChild(re),u.add(w),ue.onpaint=Oe=>{const Je=Oe.changedElements;for(const Re of u)Je.includes(Re.image)&&(Re.needsUpdate=!0)},ue.requestPaint();return}if(i.texElementImage2D.length===3)i.texElementImage2D(i.TEXTURE_2D,i.RGBA8,re);else{const Je=i.RGBA,Re=i.RGBA,at=i.UNSIGNED_BYTE;i.texElementImage2D(i.TEXTURE_2D,0,Je,Re,at,re)}i.texParameteri(i.TEXTURE_2D,i.TEXTURE_MIN_FILTER,i.LINEAR),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_S,i.CLAMP_TO_EDGE),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_T,i.CLAMP_TO_EDGE)}}else if(Ee.length>0){if(xe&&be){const ue=$e(Ee[0]);t.texStorage2D(i.TEXTURE_2D,Ze,ae,ue.width,ue.height)}for(let ue=0,Oe=Ee.length;ue<Oe;ue++)ie=Ee[ue],xe?Ge&&t.texSubImage2D(i.TEXTURE_2D,ue,0,0,_e,F,ie):t.texImage2D(i.TEXTURE_2D,ue,ae,_e,F,ie);w.generateMipmaps=!1}else if(xe){if(be){const ue=$e(re);t.texStorage2D(i.TEXTURE_2D,Ze,ae,ue.width,ue.height)}Ge&&t.texSubImage2D(i.TEXTURE_2D,0,0,0,_e,F,re)}else t.texImage2D(i.TEXTURE_2D,0,ae,_e,F,re);A(w)&&w.mipmapsAutoUpdate===!0&&S(de),Me.__version=Se.version,w.onUpdate&&w.onUpdate(w)}C.__version=w.version}function $t(C,w,q){if(w.image.length!==6)return;const de=tt(C,w),oe=w.source;t.bindTexture(i.TEXTURE_CUBE_MAP,C.__webglTexture,i.TEXTURE0+q);const Se=n.get(oe);if(oe.version!==Se.__version||de===!0){t.activeTexture(i.TEXTURE0+q);const Me=xt.getPrimaries(xt.workingColorSpace),ne=w.colorSpace===Es?null:xt.getPrimaries(w.colorSpace),re=w.colorSpace===Es||Me===ne?i.NONE:i.BROWSER_DEFAULT_WEBGL;t.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,w.flipY),t.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,w.premultiplyAlpha),t.pixelStorei(i.UNPACK_ALIGNMENT,w.unpackAlignment),t.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,re);const _e=w.isCompressedTexture||w.image[0].isCompressedTexture,F=w.image[0]&&w.image[0].isDataTexture,ae=[];for(let Re=0;Re<6;Re++)!_e&&!F?ae[Re]=x(w.image[Re],!0,s.maxCubemapSize):ae[Re]=F?w.image[Re].image:w.image[Re],ae[Re]=He(w,ae[Re]);const ie=ae[0],Ee=r.convert(w.format,w.colorSpace),xe=r.convert(w.type);let be=y(w.internalFormat,Ee,xe,w.normalized,w.colorSpace);const Ge=w.isVideoTexture!==!0,Ze=Se.__version===void 0||de===!0,ue=oe.dataReady;let Oe=b(w,ie);nt(i.TEXTURE_CUBE_MAP,w);let Je;if(w.isDepthTexture){if(be=g(w.format===As,w.type),Ze)if(Ge)t.texStorage2D(i.TEXTURE_CUBE_MAP,1,be,ie.width,ie.height);else for(let Re=0;Re<6;Re++)t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,be,ie.width,ie.height,0,Ee,xe,null)}else if(_e){Ge&&Ze&&t.texStorage2D(i.TEXTURE_CUBE_MAP,Oe,be,ie.width,ie.height);for(let Re=0;Re<6;Re++){Je=ae[Re].mipmaps;for(let at=0;at<Je.length;at++){const zt=Je[at];w.format!==Gi?Ee!==null?Ge?ue&&t.compressedTexSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,at,0,0,zt.width,zt.height,Ee,zt.data):t.compressedTexImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,at,be,zt.width,zt.height,0,zt.data):je("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,at,0,0,zt.width,zt.height,Ee,xe,zt.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,at,be,zt.width,zt.height,0,Ee,xe,zt.data)}}}else{if(Je=w.mipmaps,Ge&&Ze){Je.length>0&&Oe++;const Re=$e(ae[0]);t.texStorage2D(i.TEXTURE_CUBE_MAP,Oe,be,Re.width,Re.height)}for(let Re=0;Re<6;Re++)if(F){Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,0,0,ae[Re].width,ae[Re].height,Ee,xe,ae[Re].data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,be,ae[Re].width,ae[Re].height,0,Ee,xe,ae[Re].data);for(let at=0;at<Je.length;at++){const Fn=Je[at].image[Re].image;Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,at+1,0,0,Fn.width,Fn.height,Ee,xe,Fn.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,at+1,be,Fn.width,Fn.height,0,Ee,xe,Fn.data)}}else{Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,0,0,Ee,xe,ae[Re]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,be,Ee,xe,ae[Re]);for(let at=0;at<Je.length;at++){const zt=Je[at];Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,at+1,0,0,Ee,xe,zt.image[Re]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Re,at+1,be,Ee,xe,zt.image[Re])}}}A(w)&&w.mipmapsAutoUpdate===!0&&S(i.TEXTURE_CUBE_MAP),Se.__version=oe.version,w.onUpdate&&w.onUpdate(w)}C.__version=w.version}function Mt(C,w,q,de,oe,Se){const Me=r.convert(q.format,q.colorSpace),ne=r.convert(q.type),re=y(q.internalFormat,Me,ne,q.normalized,q.colorSpace),_e=n.get(w),F=n.get(q);if(F.__renderTarget=w,!_e.__hasExternalTextures){const ae=Math.max(1,w.width>>Se),ie=Math.max(1,w.height>>Se);oe===i.TEXTURE_3D||oe===i.TEXTURE_2D_ARRAY?t.texImage3D(oe,Se,re,ae,ie,w.depth,0,Me,ne,null):t.texImage2D(oe,Se,re,ae,ie,0,Me,ne,null)}t.bindFramebuffer(i.FRAMEBUFFER,C),we(w)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,de,oe,F.__webglTexture,0,st(w)):(oe===i.TEXTURE_2D||oe>=i.TEXTURE_CUBE_MAP_POSITIVE_X&&oe<=i.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&i.framebufferTexture2D(i.FRAMEBUFFER,de,oe,F.__webglTexture,Se),t.bindFramebuffer(i.FRAMEBUFFER,null)}function an(C,w,q){if(i.bindRenderbuffer(i.RENDERBUFFER,C),w.depthBuffer){const de=w.depthTexture,oe=de&&de.isDepthTexture?de.type:null,Se=g(w.stencilBuffer,oe),Me=w.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;we(w)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,st(w),Se,w.width,w.height):q?i.renderbufferStorageMultisample(i.RENDERBUFFER,st(w),Se,w.width,w.height):i.renderbufferStorage(i.RENDERBUFFER,Se,w.width,w.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,Me,i.RENDERBUFFER,C)}else{const de=w.textures;for(let oe=0;oe<de.length;oe++){const Se=de[oe],Me=r.convert(Se.format,Se.colorSpace),ne=r.convert(Se.type),re=y(Se.internalFormat,Me,ne,Se.normalized,Se.colorSpace);we(w)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,st(w),re,w.width,w.height):q?i.renderbufferStorageMultisample(i.RENDERBUFFER,st(w),re,w.width,w.height):i.renderbufferStorage(i.RENDERBUFFER,re,w.width,w.height)}}i.bindRenderbuffer(i.RENDERBUFFER,null)}function dt(C,w,q){const de=w.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(i.FRAMEBUFFER,C),!(w.depthTexture&&w.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");const oe=n.get(w.depthTexture);oe.__renderTarget=w;const Se=de?w.depthTexture.image[0]:w.depthTexture.image;(!oe.__webglTexture||Se.width!==w.width||Se.height!==w.height)&&(Se.width=w.width,Se.height=w.height,w.depthTexture.needsUpdate=!0),de?ve(w.depthTexture,0):te(w.depthTexture,0);const Me=oe.__webglTexture,ne=st(w),re=de?i.TEXTURE_CUBE_MAP_POSITIVE_X+q:i.TEXTURE_2D,_e=w.depthTexture.format===As?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;if(w.depthTexture.format===Ps)we(w)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,_e,re,Me,0,ne):i.framebufferTexture2D(i.FRAMEBUFFER,_e,re,Me,0);else if(w.depthTexture.format===As)we(w)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,_e,re,Me,0,ne):i.framebufferTexture2D(i.FRAMEBUFFER,_e,re,Me,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function pn(C){const w=n.get(C),q=C.isWebGLCubeRenderTarget===!0;if(w.__boundDepthTexture!==C.depthTexture){const de=C.depthTexture;if(w.__depthDisposeCallback&&w.__depthDisposeCallback(),de){const oe=()=>{delete w.__boundDepthTexture,delete w.__depthDisposeCallback,de.removeEventListener("dispose",oe)};de.addEventListener("dispose",oe),w.__depthDisposeCallback=oe}w.__boundDepthTexture=de}if(C.depthTexture&&!w.__autoAllocateDepthBuffer)if(q)for(let de=0;de<6;de++)dt(w.__webglFramebuffer[de],C,de);else C.texture.mipmaps.length>0?dt(w.__webglFramebuffer[0],C,0):dt(w.__webglFramebuffer,C,0);else if(q){w.__webglDepthbuffer=[];for(let de=0;de<6;de++)if(t.bindFramebuffer(i.FRAMEBUFFER,w.__webglFramebuffer[de]),w.__webglDepthbuffer[de]===void 0)w.__webglDepthbuffer[de]=i.createRenderbuffer(),an(w.__webglDepthbuffer[de],C,!1);else{const oe=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,Se=w.__webglDepthbuffer[de];i.bindRenderbuffer(i.RENDERBUFFER,Se),i.framebufferRenderbuffer(i.FRAMEBUFFER,oe,i.RENDERBUFFER,Se)}}else if(C.texture.mipmaps.length>0?t.bindFramebuffer(i.FRAMEBUFFER,w.__webglFramebuffer[0]):t.bindFramebuffer(i.FRAMEBUFFER,w.__webglFramebuffer),w.__webglDepthbuffer===void 0)w.__webglDepthbuffer=i.createRenderbuffer(),an(w.__webglDepthbuffer,C,!1);else{const oe=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,Se=w.__webglDepthbuffer;i.bindRenderbuffer(i.RENDERBUFFER,Se),i.framebufferRenderbuffer(i.FRAMEBUFFER,oe,i.RENDERBUFFER,Se)}t.bindFramebuffer(i.FRAMEBUFFER,null)}function Yt(C,w,q){const de=n.get(C);w!==void 0&&Mt(de.__webglFramebuffer,C,C.texture,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,0),q!==void 0&&pn(C)}function on(C){const w=C.texture,q=n.get(C),de=n.get(w);C.addEventListener("dispose",G),k(C);const oe=C.textures,Se=C.isWebGLCubeRenderTarget===!0,Me=oe.length>1;if(Me||(de.__webglTexture===void 0&&(de.__webglTexture=i.createTexture()),de.__version=w.version,a.memory.textures++),Se){q.__webglFramebuffer=[];for(let ne=0;ne<6;ne++)if(w.mipmaps.length>0){q.__webglFramebuffer[ne]=[];for(let re=0;re<w.mipmaps.length;re++)q.__webglFramebuffer[ne][re]=i.createFramebuffer()}else q.__webglFramebuffer[ne]=i.createFramebuffer()}else{if(w.mipmaps.length>0){q.__webglFramebuffer=[];for(let ne=0;ne<w.mipmaps.length;ne++)q.__webglFramebuffer[ne]=i.createFramebuffer()}else q.__webglFramebuffer=i.createFramebuffer();if(Me)for(let ne=0,re=oe.length;ne<re;ne++){const _e=n.get(oe[ne]);_e.__webglTexture===void 0&&(_e.__webglTexture=i.createTexture(),a.memory.textures++)}if(C.samples>0&&we(C)===!1){q.__webglMultisampledFramebuffer=i.createFramebuffer(),q.__webglColorRenderbuffer=[],t.bindFramebuffer(i.FRAMEBUFFER,q.__webglMultisampledFramebuffer);for(let ne=0;ne<oe.length;ne++){const re=oe[ne];q.__webglColorRenderbuffer[ne]=i.createRenderbuffer(),i.bindRenderbuffer(i.RENDERBUFFER,q.__webglColorRenderbuffer[ne]);const _e=r.convert(re.format,re.colorSpace),F=r.convert(re.type),ae=y(re.internalFormat,_e,F,re.normalized,re.colorSpace,C.isXRRenderTarget===!0),ie=st(C);i.renderbufferStorageMultisample(i.RENDERBUFFER,ie,ae,C.width,C.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ne,i.RENDERBUFFER,q.__webglColorRenderbuffer[ne])}i.bindRenderbuffer(i.RENDERBUFFER,null),C.depthBuffer&&(q.__webglDepthRenderbuffer=i.createRenderbuffer(),an(q.__webglDepthRenderbuffer,C,!0)),t.bindFramebuffer(i.FRAMEBUFFER,null)}}if(Se){t.bindTexture(i.TEXTURE_CUBE_MAP,de.__webglTexture),nt(i.TEXTURE_CUBE_MAP,w);for(let ne=0;ne<6;ne++)if(w.mipmaps.length>0)for(let re=0;re<w.mipmaps.length;re++)Mt(q.__webglFramebuffer[ne][re],C,w,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+ne,re);else Mt(q.__webglFramebuffer[ne],C,w,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+ne,0);A(w)?S(i.TEXTURE_CUBE_MAP):w.mipmaps.length>0&&i.texParameteri(i.TEXTURE_CUBE_MAP,i.TEXTURE_MAX_LEVEL,w.mipmaps.length-1),t.unbindTexture()}else if(Me){for(let ne=0,re=oe.length;ne<re;ne++){const _e=oe[ne],F=n.get(_e);let ae=i.TEXTURE_2D;(C.isWebGL3DRenderTarget||C.isWebGLArrayRenderTarget)&&(ae=C.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),t.bindTexture(ae,F.__webglTexture),nt(ae,_e),Mt(q.__webglFramebuffer,C,_e,i.COLOR_ATTACHMENT0+ne,ae,0),A(_e)&&S(ae)}t.unbindTexture()}else{let ne=i.TEXTURE_2D;if((C.isWebGL3DRenderTarget||C.isWebGLArrayRenderTarget)&&(ne=C.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),t.bindTexture(ne,de.__webglTexture),nt(ne,w),w.mipmaps.length>0)for(let re=0;re<w.mipmaps.length;re++)Mt(q.__webglFramebuffer[re],C,w,i.COLOR_ATTACHMENT0,ne,re);else Mt(q.__webglFramebuffer,C,w,i.COLOR_ATTACHMENT0,ne,0);A(w)?S(ne):w.mipmaps.length>0&&i.texParameteri(ne,i.TEXTURE_MAX_LEVEL,w.mipmaps.length-1),t.unbindTexture()}C.depthBuffer&&pn(C)}function O(C){const w=C.textures;for(let q=0,de=w.length;q<de;q++){const oe=w[q];if(A(oe)&&oe.mipmapsAutoUpdate===!0){const Se=R(C),Me=n.get(oe).__webglTexture;t.bindTexture(Se,Me),S(Se),t.unbindTexture()}}}const Ce=[];function qe(C){if(C.samples>0){if(we(C)===!1){const w=C.textures,q=C.width,de=C.height;let oe=i.COLOR_BUFFER_BIT;const Se=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,Me=n.get(C),ne=w.length>1;if(ne)for(let _e=0;_e<w.length;_e++)t.bindFramebuffer(i.FRAMEBUFFER,Me.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+_e,i.RENDERBUFFER,null),t.bindFramebuffer(i.FRAMEBUFFER,Me.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+_e,i.TEXTURE_2D,null,0);t.bindFramebuffer(i.READ_FRAMEBUFFER,Me.__webglMultisampledFramebuffer),C.texture.mipmaps.length>0?t.bindFramebuffer(i.DRAW_FRAMEBUFFER,Me.__webglFramebuffer[0]):t.bindFramebuffer(i.DRAW_FRAMEBUFFER,Me.__webglFramebuffer);for(let _e=0;_e<w.length;_e++){if(C.resolveDepthBuffer&&(C.depthBuffer&&(oe|=i.DEPTH_BUFFER_BIT),C.stencilBuffer&&C.resolveStencilBuffer&&(oe|=i.STENCIL_BUFFER_BIT)),ne){i.framebufferRenderbuffer(i.READ_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.RENDERBUFFER,Me.__webglColorRenderbuffer[_e]);const F=n.get(w[_e]).__webglTexture;i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,F,0)}i.blitFramebuffer(0,0,q,de,0,0,q,de,oe,i.NEAREST),l===!0&&(Ce.length=0,Ce.push(i.COLOR_ATTACHMENT0+_e),C.depthBuffer&&C.storeMultisampledDepthBuffer===!1&&Ce.push(Se),i.invalidateFramebuffer(i.READ_FRAMEBUFFER,Ce))}if(t.bindFramebuffer(i.READ_FRAMEBUFFER,null),t.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),ne)for(let _e=0;_e<w.length;_e++){t.bindFramebuffer(i.FRAMEBUFFER,Me.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+_e,i.RENDERBUFFER,Me.__webglColorRenderbuffer[_e]);const F=n.get(w[_e]).__webglTexture;t.bindFramebuffer(i.FRAMEBUFFER,Me.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+_e,i.TEXTURE_2D,F,0)}t.bindFramebuffer(i.DRAW_FRAMEBUFFER,Me.__webglMultisampledFramebuffer)}else if(C.depthBuffer&&C.storeMultisampledDepthBuffer===!1&&l){const w=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,[w])}}}function st(C){return Math.min(s.maxSamples,C.samples)}function we(C){const w=n.get(C);return C.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&w.__useRenderToTexture!==!1}function Ut(C){const w=a.render.frame;h.get(C)!==w&&(h.set(C,w),C.update())}function He(C,w){const q=C.colorSpace,de=C.format,oe=C.type;return C.isCompressedTexture===!0||C.isVideoTexture===!0||q!==$o&&q!==Es&&(xt.getTransfer(q)===Lt?(de!==Gi||oe!==ni)&&je("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):St("WebGLTextures: Unsupported texture color space:",q)),w}function $e(C){return typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement?(c.width=C.naturalWidth||C.width,c.height=C.naturalHeight||C.height):typeof VideoFrame<"u"&&C instanceof VideoFrame?(c.width=C.displayWidth,c.height=C.displayHeight):(c.width=C.width,c.height=C.height),c}this.allocateTextureUnit=fe,this.resetTextureUnits=ee,this.getTextureUnits=se,this.setTextureUnits=pe,this.setTexture2D=te,this.setTexture2DArray=he,this.setTexture3D=ge,this.setTextureCube=ve,this.rebindTextures=Yt,this.setupRenderTarget=on,this.updateRenderTargetMipmap=O,this.updateMultisampleRenderTarget=qe,this.setupDepthRenderbuffer=pn,this.setupFrameBufferTexture=Mt,this.useMultisampledRTT=we,this.dispose=X}function oy(i,e){function t(n,s=Es){let r;const a=xt.getTransfer(s);if(n===ni)return i.UNSIGNED_BYTE;if(n===Hh)return i.UNSIGNED_SHORT_4_4_4_4;if(n===Vh)return i.UNSIGNED_SHORT_5_5_5_1;if(n===fp)return i.UNSIGNED_INT_5_9_9_9_REV;if(n===pp)return i.UNSIGNED_INT_10F_11F_11F_REV;if(n===up)return i.BYTE;if(n===dp)return i.SHORT;if(n===La)return i.UNSIGNED_SHORT;if(n===zh)return i.INT;if(n===qi)return i.UNSIGNED_INT;if(n===Vi)return i.FLOAT;if(n===Yi)return i.HALF_FLOAT;if(n===mp)return i.ALPHA;if(n===gp)return i.RGB;if(n===Gi)return i.RGBA;if(n===Ps)return i.DEPTH_COMPONENT;if(n===As)return i.DEPTH_STENCIL;if(n===_p)return i.RED;if(n===Gh)return i.RED_INTEGER;if(n===Ks)return i.RG;if(n===Wh)return i.RG_INTEGER;if(n===Xh)return i.RGBA_INTEGER;if(n===Fo||n===Oo||n===ko||n===Bo)if(a===Lt)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(n===Fo)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(n===Oo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(n===ko)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(n===Bo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(n===Fo)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(n===Oo)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(n===ko)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(n===Bo)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(n===Fc||n===Oc||n===kc||n===Bc)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(n===Fc)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(n===Oc)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(n===kc)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(n===Bc)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(n===zc||n===Hc||n===Vc||n===Gc||n===Wc||n===Wo||n===Xc)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(n===zc||n===Hc)return a===Lt?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(n===Vc)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(n===Gc)return r.COMPRESSED_R11_EAC;if(n===Wc)return r.COMPRESSED_SIGNED_R11_EAC;if(n===Wo)return r.COMPRESSED_RG11_EAC;if(n===Xc)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(n===$c||n===qc||n===Yc||n===Kc||n===Zc||n===Jc||n===jc||n===Qc||n===eh||n===th||n===nh||n===ih||n===sh||n===rh)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(n===$c)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(n===qc)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(n===Yc)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(n===Kc)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(n===Zc)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(n===Jc)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(n===jc)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(n===Qc)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(n===eh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(n===th)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(n===nh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(n===ih)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(n===sh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(n===rh)return a===Lt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(n===ah||n===oh||n===lh)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(n===ah)return a===Lt?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(n===oh)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(n===lh)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(n===ch||n===hh||n===Xo||n===uh)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(n===ch)return r.COMPRESSED_RED_RGTC1_EXT;if(n===hh)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(n===Xo)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(n===uh)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return n===zr?i.UNSIGNED_INT_24_8:i[n]!==void 0?i[n]:null}return{convert:t}}const ly=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,cy=`
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

}`;class hy{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){const n=new Up(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=n}}getMesh(e){if(this.texture!==null&&this.mesh===null){const t=e.cameras[0].viewport,n=new Zs({vertexShader:ly,fragmentShader:cy,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new sn(new ol(20,20),n)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}}class uy extends Is{constructor(e,t){super();const n=this;let s=null,r=1,a=null,o="local-floor",l=1,c=null,h=null,u=null,d=null,m=null,_=null;const M=typeof XRWebGLBinding<"u",p=new hy,f={},x=t.getContextAttributes();let A=null,S=null;const R=[],y=[],g=new Xe;let b=null,k=null;const I=new $n;I.viewport=new nn;const L=new $n;L.viewport=new nn;const G=[I,L],W=new M_;let U=null,X=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(B){let te=R[B];return te===void 0&&(te=new Vl,R[B]=te),te.getTargetRaySpace()},this.getControllerGrip=function(B){let te=R[B];return te===void 0&&(te=new Vl,R[B]=te),te.getGripSpace()},this.getHand=function(B){let te=R[B];return te===void 0&&(te=new Vl,R[B]=te),te.getHandSpace()};function J(B){const te=y.indexOf(B.inputSource);if(te===-1)return;const he=R[te];he!==void 0&&(he.update(B.inputSource,B.frame,c||a),he.dispatchEvent({type:B.type,data:B.inputSource}))}function H(){s.removeEventListener("select",J),s.removeEventListener("selectstart",J),s.removeEventListener("selectend",J),s.removeEventListener("squeeze",J),s.removeEventListener("squeezestart",J),s.removeEventListener("squeezeend",J),s.removeEventListener("end",H),s.removeEventListener("inputsourceschange",ce);for(let B=0;B<R.length;B++){const te=y[B];te!==null&&(y[B]=null,R[B].disconnect(te))}U=null,X=null,p.reset();for(const B in f)delete f[B];if(e.setRenderTarget(A),m=null,d=null,u=null,s=null,S=null,fe.stop(),n.isPresenting=!1,e.setPixelRatio(b),e.setSize(g.width,g.height,!1),k!==null){const B=k.camera;B.fov=k.fov,B.zoom=k.zoom,B.updateProjectionMatrix(),k=null}n.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(B){r=B,n.isPresenting===!0&&je("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(B){o=B,n.isPresenting===!0&&je("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return c||a},this.setReferenceSpace=function(B){c=B},this.getBaseLayer=function(){return d!==null?d:m},this.getBinding=function(){return u===null&&M&&(u=new XRWebGLBinding(s,t)),u},this.getFrame=function(){return _},this.getSession=function(){return s},this.setSession=async function(B){if(s=B,s!==null){if(A=e.getRenderTarget(),s.addEventListener("select",J),s.addEventListener("selectstart",J),s.addEventListener("selectend",J),s.addEventListener("squeeze",J),s.addEventListener("squeezestart",J),s.addEventListener("squeezeend",J),s.addEventListener("end",H),s.addEventListener("inputsourceschange",ce),x.xrCompatible!==!0&&await t.makeXRCompatible(),b=e.getPixelRatio(),e.getSize(g),M&&"createProjectionLayer"in XRWebGLBinding.prototype){let he=null,ge=null,ve=null;x.depth&&(ve=x.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,he=x.stencil?As:Ps,ge=x.stencil?zr:qi);const Ve={colorFormat:t.RGBA8,depthFormat:ve,scaleFactor:r};u=this.getBinding(),d=u.createProjectionLayer(Ve),s.updateRenderState({layers:[d]}),e.setPixelRatio(1),e.setSize(d.textureWidth,d.textureHeight,!1),S=new $i(d.textureWidth,d.textureHeight,{format:Gi,type:ni,depthTexture:new Hr(d.textureWidth,d.textureHeight,ge,void 0,void 0,void 0,void 0,void 0,void 0,he),stencilBuffer:x.stencil,colorSpace:e.outputColorSpace,samples:x.antialias?4:0,resolveDepthBuffer:d.ignoreDepthValues===!1,resolveStencilBuffer:d.ignoreDepthValues===!1,storeMultisampledDepthBuffer:d.ignoreDepthValues===!1,storeMultisampledStencilBuffer:d.ignoreDepthValues===!1})}else{const he={antialias:x.antialias,alpha:!0,depth:x.depth,stencil:x.stencil,framebufferScaleFactor:r};m=new XRWebGLLayer(s,t,he),s.updateRenderState({baseLayer:m}),e.setPixelRatio(1),e.setSize(m.framebufferWidth,m.framebufferHeight,!1),S=new $i(m.framebufferWidth,m.framebufferHeight,{format:Gi,type:ni,colorSpace:e.outputColorSpace,stencilBuffer:x.stencil,resolveDepthBuffer:m.ignoreDepthValues===!1,resolveStencilBuffer:m.ignoreDepthValues===!1,storeMultisampledDepthBuffer:m.ignoreDepthValues===!1,storeMultisampledStencilBuffer:m.ignoreDepthValues===!1})}S.isXRRenderTarget=!0,this.setFoveation(l),c=null,a=await s.requestReferenceSpace(o),fe.setContext(s),fe.start(),n.isPresenting=!0,n.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return p.getDepthTexture()};function ce(B){for(let te=0;te<B.removed.length;te++){const he=B.removed[te],ge=y.indexOf(he);ge>=0&&(y[ge]=null,R[ge].disconnect(he))}for(let te=0;te<B.added.length;te++){const he=B.added[te];let ge=y.indexOf(he);if(ge===-1){for(let Ve=0;Ve<R.length;Ve++)if(Ve>=y.length){y.push(he),ge=Ve;break}else if(y[Ve]===null){y[Ve]=he,ge=Ve;break}if(ge===-1)break}const ve=R[ge];ve&&ve.connect(he)}}function Z(B,te){te===null?B.matrixWorld.copy(B.matrix):B.matrixWorld.multiplyMatrices(te.matrixWorld,B.matrix),B.matrixWorldInverse.copy(B.matrixWorld).invert()}this.updateCamera=function(B){if(s===null)return;let te=B.near,he=B.far;p.texture!==null&&(p.depthNear>0&&(te=p.depthNear),p.depthFar>0&&(he=p.depthFar)),W.near=L.near=I.near=te,W.far=L.far=I.far=he,(U!==W.near||X!==W.far)&&(s.updateRenderState({depthNear:W.near,depthFar:W.far}),U=W.near,X=W.far),W.layers.mask=B.layers.mask|6,I.layers.mask=W.layers.mask&-5,L.layers.mask=W.layers.mask&-3;const ge=B.parent,ve=W.cameras;Z(W,ge);for(let Ve=0;Ve<ve.length;Ve++)Z(ve[Ve],ge);W.projectionMatrix.copy(I.projectionMatrix),W.projectionMatrixInverse.copy(I.projectionMatrixInverse),k===null&&B.isPerspectiveCamera&&(k={camera:B,fov:B.fov,zoom:B.zoom}),ee(B,W,ge)};function ee(B,te,he){he===null?B.matrix.copy(te.matrixWorld):(B.matrix.copy(he.matrixWorld),B.matrix.invert(),B.matrix.multiply(te.matrixWorld)),B.matrix.decompose(B.position,B.quaternion,B.scale),B.updateMatrixWorld(!0),B.projectionMatrix.copy(te.projectionMatrix),B.projectionMatrixInverse.copy(te.projectionMatrixInverse),B.isPerspectiveCamera&&(B.fov=fh*2*Math.atan(1/B.projectionMatrix.elements[5]),B.zoom=1)}this.getCamera=function(){return W},this.getFoveation=function(){if(!(d===null&&m===null))return l},this.setFoveation=function(B){l=B,d!==null&&(d.fixedFoveation=B),m!==null&&m.fixedFoveation!==void 0&&(m.fixedFoveation=B)},this.hasDepthSensing=function(){return p.texture!==null},this.getDepthSensingMesh=function(){return p.getMesh(W)},this.getCameraTexture=function(B){return f[B]};let se=null;function pe(B,te){if(h=te.getViewerPose(c||a),_=te,h!==null){const he=h.views;m!==null&&(e.setRenderTargetFramebuffer(S,m.framebuffer),e.setRenderTarget(S));let ge=!1;he.length!==W.cameras.length&&(W.cameras.length=0,ge=!0);for(let ze=0;ze<he.length;ze++){const nt=he[ze];let tt=null;if(m!==null)tt=m.getViewport(nt);else{const It=u.getViewSubImage(d,nt);tt=It.viewport,ze===0&&(e.setRenderTargetTextures(S,It.colorTexture,It.depthStencilTexture),e.setRenderTarget(S))}let Ye=G[ze];Ye===void 0&&(Ye=new $n,Ye.layers.enable(ze),Ye.viewport=new nn,G[ze]=Ye),Ye.matrix.fromArray(nt.transform.matrix),Ye.matrix.decompose(Ye.position,Ye.quaternion,Ye.scale),Ye.projectionMatrix.fromArray(nt.projectionMatrix),Ye.projectionMatrixInverse.copy(Ye.projectionMatrix).invert(),Ye.viewport.set(tt.x,tt.y,tt.width,tt.height),ze===0&&(W.matrix.copy(Ye.matrix),W.matrix.decompose(W.position,W.quaternion,W.scale)),ge===!0&&W.cameras.push(Ye)}const ve=s.enabledFeatures;if(ve&&ve.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&M){u=n.getBinding();const ze=u.getDepthInformation(he[0]);ze&&ze.isValid&&ze.texture&&p.init(ze,s.renderState)}if(ve&&ve.includes("camera-access")&&M){e.state.unbindTexture(),u=n.getBinding();for(let ze=0;ze<he.length;ze++){const nt=he[ze].camera;if(nt){let tt=f[nt];tt||(tt=new Up,f[nt]=tt);const Ye=u.getCameraImage(nt);tt.sourceTexture=Ye}}}}for(let he=0;he<R.length;he++){const ge=y[he],ve=R[he];ge!==null&&ve!==void 0&&ve.update(ge,te,c||a)}se&&se(B,te),te.detectedPlanes&&n.dispatchEvent({type:"planesdetected",data:te}),_=null}const fe=new Wp;fe.setAnimationLoop(pe),this.setAnimationLoop=function(B){se=B},this.dispose=function(){}}}const dy=new Dt,em=new rt;em.set(-1,0,0,0,1,0,0,0,1);function fy(i,e){function t(p,f){p.matrixAutoUpdate===!0&&p.updateMatrix(),f.value.copy(p.matrix)}function n(p,f){f.color.getRGB(p.fogColor.value,Fp(i)),f.isFog?(p.fogNear.value=f.near,p.fogFar.value=f.far):f.isFogExp2&&(p.fogDensity.value=f.density)}function s(p,f,x,A,S){f.isNodeMaterial?f.uniformsNeedUpdate=!1:f.isMeshBasicMaterial?r(p,f):f.isMeshLambertMaterial?(r(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshToonMaterial?(r(p,f),u(p,f)):f.isMeshPhongMaterial?(r(p,f),h(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshStandardMaterial?(r(p,f),d(p,f),f.isMeshPhysicalMaterial&&m(p,f,S)):f.isMeshMatcapMaterial?(r(p,f),_(p,f)):f.isMeshDepthMaterial?r(p,f):f.isMeshDistanceMaterial?(r(p,f),M(p,f)):f.isMeshNormalMaterial?r(p,f):f.isLineBasicMaterial?(a(p,f),f.isLineDashedMaterial&&o(p,f)):f.isPointsMaterial?l(p,f,x,A):f.isSpriteMaterial?c(p,f):f.isShadowMaterial?(p.color.value.copy(f.color),p.opacity.value=f.opacity):f.isShaderMaterial&&(f.uniformsNeedUpdate=!1)}function r(p,f){p.opacity.value=f.opacity,f.color&&p.diffuse.value.copy(f.color),f.emissive&&p.emissive.value.copy(f.emissive).multiplyScalar(f.emissiveIntensity),f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.bumpMap&&(p.bumpMap.value=f.bumpMap,t(f.bumpMap,p.bumpMapTransform),p.bumpScale.value=f.bumpScale,f.side===Yn&&(p.bumpScale.value*=-1)),f.normalMap&&(p.normalMap.value=f.normalMap,t(f.normalMap,p.normalMapTransform),p.normalScale.value.copy(f.normalScale),f.side===Yn&&p.normalScale.value.negate()),f.displacementMap&&(p.displacementMap.value=f.displacementMap,t(f.displacementMap,p.displacementMapTransform),p.displacementScale.value=f.displacementScale,p.displacementBias.value=f.displacementBias),f.emissiveMap&&(p.emissiveMap.value=f.emissiveMap,t(f.emissiveMap,p.emissiveMapTransform)),f.specularMap&&(p.specularMap.value=f.specularMap,t(f.specularMap,p.specularMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest);const x=e.get(f),A=x.envMap,S=x.envMapRotation;A&&(p.envMap.value=A,p.envMapRotation.value.setFromMatrix4(dy.makeRotationFromEuler(S)).transpose(),A.isCubeTexture&&A.isRenderTargetTexture===!1&&p.envMapRotation.value.premultiply(em),p.reflectivity.value=f.reflectivity,p.ior.value=f.ior,p.refractionRatio.value=f.refractionRatio),f.lightMap&&(p.lightMap.value=f.lightMap,p.lightMapIntensity.value=f.lightMapIntensity,t(f.lightMap,p.lightMapTransform)),f.aoMap&&(p.aoMap.value=f.aoMap,p.aoMapIntensity.value=f.aoMapIntensity,t(f.aoMap,p.aoMapTransform))}function a(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform))}function o(p,f){p.dashSize.value=f.dashSize,p.totalSize.value=f.dashSize+f.gapSize,p.scale.value=f.scale}function l(p,f,x,A){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.size.value=f.size*x,p.scale.value=A*.5,f.map&&(p.map.value=f.map,t(f.map,p.uvTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function c(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.rotation.value=f.rotation,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function h(p,f){p.specular.value.copy(f.specular),p.shininess.value=Math.max(f.shininess,1e-4)}function u(p,f){f.gradientMap&&(p.gradientMap.value=f.gradientMap)}function d(p,f){p.metalness.value=f.metalness,f.metalnessMap&&(p.metalnessMap.value=f.metalnessMap,t(f.metalnessMap,p.metalnessMapTransform)),p.roughness.value=f.roughness,f.roughnessMap&&(p.roughnessMap.value=f.roughnessMap,t(f.roughnessMap,p.roughnessMapTransform)),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)}function m(p,f,x){p.ior.value=f.ior,f.diffuseRoughness>0&&(p.diffuseRoughness.value=f.diffuseRoughness,f.diffuseRoughnessMap&&(p.diffuseRoughnessMap.value=f.diffuseRoughnessMap,t(f.diffuseRoughnessMap,p.diffuseRoughnessMapTransform))),f.sheen>0&&(p.sheenColor.value.copy(f.sheenColor).multiplyScalar(f.sheen),p.sheenRoughness.value=f.sheenRoughness,f.sheenColorMap&&(p.sheenColorMap.value=f.sheenColorMap,t(f.sheenColorMap,p.sheenColorMapTransform)),f.sheenRoughnessMap&&(p.sheenRoughnessMap.value=f.sheenRoughnessMap,t(f.sheenRoughnessMap,p.sheenRoughnessMapTransform))),f.clearcoat>0&&(p.clearcoat.value=f.clearcoat,p.clearcoatRoughness.value=f.clearcoatRoughness,f.clearcoatMap&&(p.clearcoatMap.value=f.clearcoatMap,t(f.clearcoatMap,p.clearcoatMapTransform)),f.clearcoatRoughnessMap&&(p.clearcoatRoughnessMap.value=f.clearcoatRoughnessMap,t(f.clearcoatRoughnessMap,p.clearcoatRoughnessMapTransform)),f.clearcoatNormalMap&&(p.clearcoatNormalMap.value=f.clearcoatNormalMap,t(f.clearcoatNormalMap,p.clearcoatNormalMapTransform),p.clearcoatNormalScale.value.copy(f.clearcoatNormalScale),f.side===Yn&&p.clearcoatNormalScale.value.negate())),f.dispersion>0&&(p.dispersion.value=f.dispersion),f.retroreflectivity>0&&(p.retroreflectivity.value=f.retroreflectivity),f.iridescence>0&&(p.iridescence.value=f.iridescence,p.iridescenceIOR.value=f.iridescenceIOR,p.iridescenceThicknessMinimum.value=f.iridescenceThicknessMinimum,p.iridescenceThicknessMaximum.value=f.iridescenceThicknessMaximum,f.iridescenceMap&&(p.iridescenceMap.value=f.iridescenceMap,t(f.iridescenceMap,p.iridescenceMapTransform)),f.iridescenceThicknessMap&&(p.iridescenceThicknessMap.value=f.iridescenceThicknessMap,t(f.iridescenceThicknessMap,p.iridescenceThicknessMapTransform))),f.transmission>0&&(p.transmission.value=f.transmission,p.transmissionSamplerMap.value=x.texture,p.transmissionSamplerSize.value.set(x.width,x.height),f.transmissionMap&&(p.transmissionMap.value=f.transmissionMap,t(f.transmissionMap,p.transmissionMapTransform)),p.thickness.value=f.thickness,f.thicknessMap&&(p.thicknessMap.value=f.thicknessMap,t(f.thicknessMap,p.thicknessMapTransform)),p.attenuationDistance.value=f.attenuationDistance,p.attenuationColor.value.copy(f.attenuationColor)),f.anisotropy>0&&(p.anisotropyVector.value.set(f.anisotropy*Math.cos(f.anisotropyRotation),f.anisotropy*Math.sin(f.anisotropyRotation)),f.anisotropyMap&&(p.anisotropyMap.value=f.anisotropyMap,t(f.anisotropyMap,p.anisotropyMapTransform))),p.specularIntensity.value=f.specularIntensity,p.specularColor.value.copy(f.specularColor),f.specularColorMap&&(p.specularColorMap.value=f.specularColorMap,t(f.specularColorMap,p.specularColorMapTransform)),f.specularIntensityMap&&(p.specularIntensityMap.value=f.specularIntensityMap,t(f.specularIntensityMap,p.specularIntensityMapTransform))}function _(p,f){f.matcap&&(p.matcap.value=f.matcap)}function M(p,f){const x=e.get(f).light;p.referencePosition.value.setFromMatrixPosition(x.matrixWorld),p.nearDistance.value=x.shadow.camera.near,p.farDistance.value=x.shadow.camera.far}return{refreshFogUniforms:n,refreshMaterialUniforms:s}}function py(i,e,t,n){let s={},r={};function a(x,A){const S=A.program;n.uniformBlockBinding(x,S,s[x.id])}function o(x,A){let S=s[x.id];S===void 0&&(_(x),S=l(x),s[x.id]=S,x.addEventListener("dispose",p));const R=A.program;n.updateUBOMapping(x,R);const y=e.render.frame;r[x.id]!==y&&(c(x),r[x.id]=y)}function l(x){const A=i.createBuffer(),S=x.__size,R=x.usage;return i.bindBuffer(i.UNIFORM_BUFFER,A),i.bufferData(i.UNIFORM_BUFFER,S,R),i.bindBuffer(i.UNIFORM_BUFFER,null),A}function c(x){const A=s[x.id],S=x.uniforms,R=x.__cache;i.bindBuffer(i.UNIFORM_BUFFER,A);for(let y=0,g=S.length;y<g;y++){const b=S[y];if(Array.isArray(b))for(let k=0,I=b.length;k<I;k++)h(b[k],y,k,R);else h(b,y,0,R)}i.bindBuffer(i.UNIFORM_BUFFER,null)}function h(x,A,S,R){if(d(x,A,S,R)===!0){const y=x.__offset,g=x.value;if(Array.isArray(g)){let b=0;for(let k=0;k<g.length;k++){const I=g[k],L=M(I,!0);u(I,x.__data,b),b+=L.storage/Float32Array.BYTES_PER_ELEMENT}}else u(g,x.__data,0);i.bufferSubData(i.UNIFORM_BUFFER,y,x.__data)}}function u(x,A,S){typeof x=="number"||typeof x=="boolean"?A[S]=x:x.isMatrix3?(A[S]=x.elements[0],A[S+1]=x.elements[1],A[S+2]=x.elements[2],A[S+3]=0,A[S+4]=x.elements[3],A[S+5]=x.elements[4],A[S+6]=x.elements[5],A[S+7]=0,A[S+8]=x.elements[6],A[S+9]=x.elements[7],A[S+10]=x.elements[8],A[S+11]=0):ArrayBuffer.isView(x)?A.set(x.subarray(0,A.length-S),S):x.toArray(A,S)}function d(x,A,S,R){const y=x.value,g=A+"_"+S;if(Array.isArray(y)){R[g]===void 0&&(R[g]=[]);const b=R[g];let k=!1;for(let I=0;I<y.length;I++)m(y[I],b,I)===!0&&(k=!0);return k}return m(y,R,g)}function m(x,A,S){if(A[S]===void 0)return typeof x=="number"||typeof x=="boolean"?A[S]=x:ArrayBuffer.isView(x)?A[S]=x.slice():A[S]=x.clone(),!0;{const R=A[S];if(typeof x=="number"||typeof x=="boolean"){if(R!==x)return A[S]=x,!0}else{if(ArrayBuffer.isView(x))return!0;if(R.equals(x)===!1)return R.copy(x),!0}}return!1}function _(x){const A=x.uniforms;let S=0;const R=16;for(let g=0,b=A.length;g<b;g++){const k=Array.isArray(A[g])?A[g]:[A[g]];for(let I=0,L=k.length;I<L;I++){const G=k[I],W=Array.isArray(G.value)?G.value:[G.value],U=Array.isArray(A[g])||Array.isArray(G.value);let X=S;for(let H=0,ce=W.length;H<ce;H++){const Z=W[H],ee=M(Z,U),se=S%R,pe=se%ee.boundary,fe=se+pe;S+=pe,fe!==0&&R-fe<ee.storage&&(S+=R-fe),H===0&&(X=S),S+=ee.storage}const J=G.type==="int"?Int32Array:G.type==="uint"?Uint32Array:Float32Array;G.__data=new J((S-X)/Float32Array.BYTES_PER_ELEMENT),G.__offset=X}}const y=S%R;return y>0&&(S+=R-y),x.__size=S,x.__cache={},this}function M(x,A){const S={boundary:0,storage:0};return typeof x=="number"||typeof x=="boolean"?(S.boundary=4,S.storage=4):x.isVector2?(S.boundary=8,S.storage=8):x.isVector3||x.isColor?(S.boundary=16,S.storage=12):x.isVector4?(S.boundary=16,S.storage=16):x.isMatrix3?(S.boundary=16,S.storage=48):x.isMatrix4?(S.boundary=16,S.storage=64):x.isTexture?je("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(x)?(S.boundary=16,S.storage=x.byteLength):je("WebGLRenderer: Unsupported uniform value type.",x),A===!0&&(S.boundary=16,S.storage=Math.ceil(S.storage/16)*16),S}function p(x){const A=x.target;A.removeEventListener("dispose",p),i.deleteBuffer(s[A.id]),delete s[A.id],delete r[A.id]}function f(){for(const x in s)i.deleteBuffer(s[x]);s={},r={}}return{bind:a,update:o,dispose:f}}const my=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]);let Oi=null;function gy(){return Oi===null&&(Oi=new a_(my,16,16,Ks,Yi),Oi.name="DFG_LUT",Oi.minFilter=qn,Oi.magFilter=qn,Oi.wrapS=as,Oi.wrapT=as,Oi.generateMipmaps=!1,Oi.needsUpdate=!0),Oi}class tm{constructor(e={}){const{canvas:t=N0(),context:n=null,depth:s=!0,stencil:r=!1,alpha:a=!1,antialias:o=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:c=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:u=!1,reversedDepthBuffer:d=!1,outputBufferType:m=ni}=e;this.isWebGLRenderer=!0;let _;if(n!==null){if(typeof WebGLRenderingContext<"u"&&n instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");_=n.getContextAttributes().alpha}else _=a;const M=m,p=new Set([Xh,Wh,Gh]),f=new Set([ni,qi,La,zr,Hh,Vh]),x=new Uint32Array(4),A=new Int32Array(4),S={textures:[],min:[],max:[],resolution:[]};let R=null,y=null;const g=[],b=[];let k=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=ls,this.toneMappingExposure=1,this.transmissionResolutionScale=1;const I=this;let L=!1,G=null,W=null,U=null,X=null;this._outputColorSpace=hi;let J=0,H=0,ce=null,Z=-1,ee=null;const se=new nn,pe=new nn;let fe=null;const B=new ct(0);let te=0,he=t.width,ge=t.height,ve=1,Ve=null,Qe=null;const ze=new nn(0,0,he,ge),nt=new nn(0,0,he,ge);let tt=!1;const Ye=new Na,It=new Yh;let gt=!1,$t=!1;const Mt=new Dt,an=new z,dt=new nn,pn={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0};let Yt=!1;function on(){return ce===null?ve:1}let O=n;function Ce(T,V){return t.getContext(T,V)}let qe,st,we,Ut,He,$e,C,w,q,de,oe,Se,Me,ne,re,_e,F,ae,ie,Ee,xe,be,Ge;try{const T={alpha:!0,depth:s,stencil:r,antialias:o,premultipliedAlpha:l,preserveDrawingBuffer:c,powerPreference:h,failIfMajorPerformanceCaveat:u};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${Bh}`),t.addEventListener("webglcontextlost",Oe,!1),t.addEventListener("webglcontextrestored",Je,!1),t.addEventListener("webglcontextcreationerror",Re,!1),O===null){const V="webgl2";if(O=Ce(V,T),O===null)throw Ce(V)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}Ze()}catch(T){throw t.removeEventListener("webglcontextlost",Oe,!1),t.removeEventListener("webglcontextrestored",Je,!1),t.removeEventListener("webglcontextcreationerror",Re,!1),St("WebGLRenderer: "+T.message),T}function Ze(){qe=new SS(O),qe.init(),xe=new oy(O,qe),st=new cS(O,qe,e,xe),we=new ry(O,qe),st.reversedDepthBuffer&&d&&we.buffers.depth.setReversed(!0),W=O.createFramebuffer(),U=O.createFramebuffer(),X=O.createFramebuffer(),Ut=new bS(O),He=new XM,$e=new ay(O,qe,we,He,st,xe,Ut),C=new xS(I),w=new E_(O),be=new oS(O,w),q=new MS(O,w,Ut,be),de=new ES(O,q,w,be,Ut),ae=new wS(O,st,$e),re=new hS(He),oe=new WM(I,C,qe,st,be,re),Se=new fy(I,He),Me=new qM,ne=new QM(qe),F=new aS(I,C,we,de,_,l),_e=new sy(I,de,st),Ge=new py(O,Ut,st,we),ie=new lS(O,qe,Ut),Ee=new yS(O,qe,Ut),Ut.programs=oe.programs,I.capabilities=st,I.extensions=qe,I.properties=He,I.renderLists=Me,I.shadowMap=_e,I.state=we,I.info=Ut}M!==ni&&(k=new AS(M,t.width,t.height,o,s,r));const ue=new uy(I,O);this.xr=ue,this.getContext=function(){return O},this.getContextAttributes=function(){return O.getContextAttributes()},this.forceContextLoss=function(){const T=qe.get("WEBGL_lose_context");T&&T.loseContext()},this.forceContextRestore=function(){const T=qe.get("WEBGL_lose_context");T&&T.restoreContext()},this.getPixelRatio=function(){return ve},this.setPixelRatio=function(T){T!==void 0&&(ve=T,this.setSize(he,ge,!1))},this.getSize=function(T){return T.set(he,ge)},this.setSize=function(T,V,Q=!0){if(ue.isPresenting){je("WebGLRenderer: Can't change size while VR device is presenting.");return}he=T,ge=V,t.width=Math.floor(T*ve),t.height=Math.floor(V*ve),Q===!0&&(t.style.width=T+"px",t.style.height=V+"px"),k!==null&&k.setSize(t.width,t.height),this.setViewport(0,0,T,V)},this.getDrawingBufferSize=function(T){return T.set(he*ve,ge*ve).floor()},this.setDrawingBufferSize=function(T,V,Q){he=T,ge=V,ve=Q,t.width=Math.floor(T*Q),t.height=Math.floor(V*Q),this.setViewport(0,0,T,V)},this.setEffects=function(T){if(M===ni){St("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(T){for(let V=0;V<T.length;V++)if(T[V].isOutputPass===!0){je("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}k.setEffects(T||[])},this.getCurrentViewport=function(T){return T.copy(se)},this.getViewport=function(T){return T.copy(ze)},this.setViewport=function(T,V,Q,Y){T.isVector4?ze.set(T.x,T.y,T.z,T.w):ze.set(T,V,Q,Y),we.viewport(se.copy(ze).multiplyScalar(on()).round())},this.getScissor=function(T){return T.copy(nt)},this.setScissor=function(T,V,Q,Y){T.isVector4?nt.set(T.x,T.y,T.z,T.w):nt.set(T,V,Q,Y),we.scissor(pe.copy(nt).multiplyScalar(on()).round())},this.getScissorTest=function(){return tt},this.setScissorTest=function(T){we.setScissorTest(tt=T)},this.setOpaqueSort=function(T){Ve=T},this.setTransparentSort=function(T){Qe=T},this.getClearColor=function(T){return T.copy(F.getClearColor())},this.setClearColor=function(){F.setClearColor(...arguments)},this.getClearAlpha=function(){return F.getClearAlpha()},this.setClearAlpha=function(){F.setClearAlpha(...arguments)},this.clear=function(T=!0,V=!0,Q=!0){let Y=0;if(T){let K=!1;if(ce!==null){const Te=ce.texture.format;K=p.has(Te)}if(K){const Te=ce.texture.type,Pe=f.has(Te),Ae=F.getClearColor(),Le=F.getClearAlpha(),Be=Ae.r,et=Ae.g,ht=Ae.b;Pe?(x[0]=Be,x[1]=et,x[2]=ht,x[3]=Le,O.clearBufferuiv(O.COLOR,0,x)):(A[0]=Be,A[1]=et,A[2]=ht,A[3]=Le,O.clearBufferiv(O.COLOR,0,A))}else Y|=O.COLOR_BUFFER_BIT}V&&(Y|=O.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),Q&&(Y|=O.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),Y!==0&&O.clear(Y)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(T){T.setRenderer(this),G=T},this.dispose=function(){t.removeEventListener("webglcontextlost",Oe,!1),t.removeEventListener("webglcontextrestored",Je,!1),t.removeEventListener("webglcontextcreationerror",Re,!1),F.dispose(),Me.dispose(),ne.dispose(),$e.dispose(),He.dispose(),C.dispose(),de.dispose(),q.dispose(),be.dispose(),Ge.dispose(),oe.dispose(),ue.dispose(),ue.removeEventListener("sessionstart",Wa),ue.removeEventListener("sessionend",Ci),Zi.stop()};function Oe(T){T.preventDefault(),Ko("WebGLRenderer: Context Lost."),L=!0}function Je(){Ko("WebGLRenderer: Context Restored."),L=!1;const T=Ut.autoReset,V=_e.enabled,Q=_e.autoUpdate,Y=_e.needsUpdate,K=_e.type;Ze(),Ut.autoReset=T,_e.enabled=V,_e.autoUpdate=Q,_e.needsUpdate=Y,_e.type=K}function Re(T){St("WebGLRenderer: A WebGL context could not be created. Reason: ",T.statusMessage)}function at(T){const V=T.target;V.removeEventListener("dispose",at),zt(V)}function zt(T){Fn(T),He.remove(T)}function Fn(T){const V=He.get(T).programs;V!==void 0&&(V.forEach(function(Q){oe.releaseProgram(Q)}),T.isShaderMaterial&&oe.releaseShaderCache(T))}this.renderBufferDirect=function(T,V,Q,Y,K,Te){V===null&&(V=pn);const Pe=K.isMesh&&K.matrixWorld.determinantAffine()<0,Ae=ea(T,V,Q,Y,K);we.setMaterial(Y,Pe);let Le=Q.index,Be=1;if(Y.wireframe===!0){if(Le=q.getWireframeAttribute(Q),Le===void 0)return;Be=2}const et=Q.drawRange,ht=Q.attributes.position;let ke=et.start*Be,ut=(et.start+et.count)*Be;Te!==null&&(ke=Math.max(ke,Te.start*Be),ut=Math.min(ut,(Te.start+Te.count)*Be)),Le!==null?(ke=Math.max(ke,0),ut=Math.min(ut,Le.count)):ht!=null&&(ke=Math.max(ke,0),ut=Math.min(ut,ht.count));const qt=ut-ke;if(qt<0||qt===1/0)return;be.setup(K,Y,Ae,Q,Le);let Rt,Ct=ie;if(Le!==null&&(Rt=w.get(Le),Ct=Ee,Ct.setIndex(Rt)),K.isMesh)Y.wireframe===!0?(we.setLineWidth(Y.wireframeLinewidth*on()),Ct.setMode(O.LINES)):Ct.setMode(O.TRIANGLES);else if(K.isLine){let mn=Y.linewidth;mn===void 0&&(mn=1),we.setLineWidth(mn*on()),K.isLineSegments?Ct.setMode(O.LINES):K.isLineLoop?Ct.setMode(O.LINE_LOOP):Ct.setMode(O.LINE_STRIP)}else K.isPoints?Ct.setMode(O.POINTS):K.isSprite&&Ct.setMode(O.TRIANGLES);if(K.isBatchedMesh)if(qe.get("WEBGL_multi_draw"))Ct.renderMultiDraw(K._multiDrawStarts,K._multiDrawCounts,K._multiDrawCount);else{const mn=K._multiDrawStarts,Ue=K._multiDrawCounts,ln=K._multiDrawCount,_t=Le?w.get(Le).bytesPerElement:1,ji=He.get(Y).currentProgram.getUniforms();for(let cn=0;cn<ln;cn++)ji.setValue(O,"_gl_DrawID",cn),Ct.render(mn[cn]/_t,Ue[cn])}else if(K.isInstancedMesh)Ct.renderInstances(ke,qt,K.count);else if(Q.isInstancedBufferGeometry){const mn=Q._maxInstanceCount!==void 0?Q._maxInstanceCount:1/0,Ue=Math.min(Q.instanceCount,mn);Ct.renderInstances(ke,qt,Ue)}else Ct.render(ke,qt)};function Jr(T,V,Q,Y){G!==null&&T.isNodeMaterial&&G.setObject(Y,T),gt===!0&&re.setState(T,Q,!1),T.transparent===!0&&T.side===fi&&T.forceSinglePass===!1?(T.side=Yn,T.needsUpdate=!0,Pi(T,V,Y),T.side=Cs,T.needsUpdate=!0,Pi(T,V,Y),T.side=fi):Pi(T,V,Y)}this.compile=function(T,V,Q=null){Q===null&&(Q=T),G!==null&&G.renderStart(T,V,Q),y=ne.get(Q),y.init(V),b.push(y),Q.traverseVisible(function(K){K.isLight&&K.layers.test(V.layers)&&(y.pushLight(K),K.castShadow&&y.pushShadow(K))}),T!==Q&&T.traverseVisible(function(K){K.isLight&&K.layers.test(V.layers)&&(y.pushLight(K),K.castShadow&&y.pushShadow(K))}),y.setupLights(),G!==null&&G.updateLights(y.state.lightsArray),$t=this.localClippingEnabled,gt=re.init(this.clippingPlanes,$t),gt===!0&&re.setGlobalState(this.clippingPlanes,V),G!==null&&_e.render(y.state.shadowsArray,Q,V);const Y=new Set;return T.traverse(function(K){if(!(K.isMesh||K.isPoints||K.isLine||K.isSprite))return;const Te=K.material;if(Te)if(Array.isArray(Te))for(let Pe=0;Pe<Te.length;Pe++){const Ae=Te[Pe];Jr(Ae,Q,V,K),Y.add(Ae)}else Jr(Te,Q,V,K),Y.add(Te)}),y=b.pop(),G!==null&&G.renderEnd(),Y},this.compileAsync=function(T,V,Q=null){const Y=this.compile(T,V,Q);return new Promise(K=>{function Te(){if(Y.forEach(function(Pe){const Le=He.get(Pe).currentProgram;(Le===void 0||Le.isReady())&&Y.delete(Pe)}),Y.size===0){K(T);return}setTimeout(Te,10)}qe.get("KHR_parallel_shader_compile")!==null?Te():setTimeout(Te,10)})};let tr=null;function xl(T){tr&&tr(T)}function Wa(){Zi.stop()}function Ci(){Zi.start()}const Zi=new Wp;Zi.setAnimationLoop(xl),typeof self<"u"&&Zi.setContext(self),this.setAnimationLoop=function(T){tr=T,ue.setAnimationLoop(T),T===null?Zi.stop():Zi.start()},ue.addEventListener("sessionstart",Wa),ue.addEventListener("sessionend",Ci),this.render=function(T,V){if(V!==void 0&&V.isCamera!==!0){St("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(L===!0)return;G!==null&&G.renderStart(T,V);const Q=ue.enabled===!0&&ue.isPresenting===!0,Y=k!==null&&(ce===null||Q)&&k.begin(I,ce);if(T.matrixWorldAutoUpdate===!0&&T.updateMatrixWorld(),V.parent===null&&V.matrixWorldAutoUpdate===!0&&V.updateMatrixWorld(),ue.enabled===!0&&ue.isPresenting===!0&&(k===null||k.isCompositing()===!1)&&(ue.cameraAutoUpdate===!0&&ue.updateCamera(V),V=ue.getCamera()),T.isScene===!0&&T.onBeforeRender(I,T,V,ce),y=ne.get(T,b.length),y.init(V),y.state.textureUnits=$e.getTextureUnits(),b.push(y),Mt.multiplyMatrices(V.projectionMatrix,V.matrixWorldInverse),V.isArrayCamera?It.setFromArrayCamera(V):Ye.setFromProjectionMatrix(Mt,Ri,V.reversedDepth),$t=this.localClippingEnabled,gt=re.init(this.clippingPlanes,$t),R=Me.get(T,g.length),R.init(),g.push(R),this.info.render.frame++,ue.enabled===!0&&ue.isPresenting===!0){const Pe=I.xr.getDepthSensingMesh();Pe!==null&&Ji(Pe,V,-1/0,I.sortObjects)}Ji(T,V,0,I.sortObjects),R.finish(),G!==null&&G.updateLights(y.state.lightsArray),I.sortObjects===!0&&R.sort(Ve,Qe),Yt=ue.enabled===!1||ue.isPresenting===!1||ue.hasDepthSensing()===!1,Yt&&F.addToRenderList(R,T),this.info.autoReset===!0&&this.info.reset(),gt===!0&&re.beginShadows();const K=y.state.shadowsArray;if(_e.render(K,T,V),gt===!0&&re.endShadows(),(Y&&k.hasRenderPass())===!1){const Pe=R.opaque,Ae=R.transmissive;if(y.setupLights(),V.isArrayCamera){const Le=V.cameras;if(Ae.length>0)for(let Be=0,et=Le.length;Be<et;Be++){const ht=Le[Be];_i(Pe,Ae,T,ht)}Yt&&F.render(T);for(let Be=0,et=Le.length;Be<et;Be++){const ht=Le[Be];jr(R,T,ht,ht.viewport)}}else Ae.length>0&&_i(Pe,Ae,T,V),Yt&&F.render(T),jr(R,T,V)}ce!==null&&H===0&&($e.updateMultisampleRenderTarget(ce),$e.updateRenderTargetMipmap(ce)),Y&&k.end(I),T.isScene===!0&&T.onAfterRender(I,T,V),be.resetDefaultState(),Z=-1,ee=null,b.pop(),b.length>0?(y=b[b.length-1],$e.setTextureUnits(y.state.textureUnits),gt===!0&&re.setGlobalState(I.clippingPlanes,y.state.camera)):y=null,g.pop(),g.length>0?R=g[g.length-1]:R=null,G!==null&&G.renderEnd()};function Ji(T,V,Q,Y){if(T.visible===!1)return;if(T.layers.test(V.layers)){if(T.isGroup)Q=T.renderOrder;else if(T.isLOD)T.autoUpdate===!0&&T.update(V);else if(T.isLight)y.pushLight(T),T.castShadow&&y.pushShadow(T);else if(T.isSprite){const Pe=V.isArrayCamera?It:Ye;if(!T.frustumCulled||T.intersectsFrustum(Pe)){Y&&dt.setFromMatrixPosition(T.matrixWorld).applyMatrix4(Mt);const Ae=de.update(T),Le=T.material;Le.visible&&R.push(T,Ae,Le,Q,dt.z,null,V)}}else if(T.isMesh||T.isLine||T.isPoints){const Pe=V.isArrayCamera?It:Ye;if(!T.frustumCulled||T.intersectsFrustum(Pe)){const Ae=de.update(T),Le=T.material;if(Y&&(T.boundingSphere!==void 0?(T.boundingSphere===null&&T.computeBoundingSphere(),dt.copy(T.boundingSphere.center)):(Ae.boundingSphere===null&&Ae.computeBoundingSphere(),dt.copy(Ae.boundingSphere.center)),dt.applyMatrix4(T.matrixWorld).applyMatrix4(Mt)),Array.isArray(Le)){const Be=Ae.groups;for(let et=0,ht=Be.length;et<ht;et++){const ke=Be[et],ut=Le[ke.materialIndex];ut&&ut.visible&&R.push(T,Ae,ut,Q,dt.z,ke,V)}}else Le.visible&&R.push(T,Ae,Le,Q,dt.z,null,V)}}}const Te=T.children;for(let Pe=0,Ae=Te.length;Pe<Ae;Pe++)Ji(Te[Pe],V,Q,Y)}function jr(T,V,Q,Y){const{opaque:K,transmissive:Te,transparent:Pe}=T;y.setupLightsView(Q),gt===!0&&re.setGlobalState(I.clippingPlanes,Q),Y&&we.viewport(se.copy(Y)),K.length>0&&Kt(K,V,Q),Te.length>0&&Kt(Te,V,Q),Pe.length>0&&Kt(Pe,V,Q),we.buffers.depth.setTest(!0),we.buffers.depth.setMask(!0),we.buffers.color.setMask(!0),we.setPolygonOffset(!1)}function _i(T,V,Q,Y){if((Q.isScene===!0?Q.overrideMaterial:null)!==null)return;if(y.state.transmissionRenderTarget[Y.id]===void 0){const ke=qe.has("EXT_color_buffer_half_float")||qe.has("EXT_color_buffer_float");y.state.transmissionRenderTarget[Y.id]=new $i(1,1,{generateMipmaps:!0,type:ke?Yi:ni,minFilter:Ts,samples:Math.max(4,st.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:xt.workingColorSpace})}const Te=y.state.transmissionRenderTarget[Y.id],Pe=Y.viewport||se;Te.setSize(Pe.z*I.transmissionResolutionScale,Pe.w*I.transmissionResolutionScale);const Ae=I.getRenderTarget(),Le=I.getActiveCubeFace(),Be=I.getActiveMipmapLevel();I.setRenderTarget(Te),I.getClearColor(B),te=I.getClearAlpha(),te<1&&I.setClearColor(16777215,.5),I.clear(),Yt&&F.render(Q);const et=I.toneMapping;I.toneMapping=ls;const ht=Y.viewport;if(Y.viewport!==void 0&&(Y.viewport=void 0),y.setupLightsView(Y),gt===!0&&re.setGlobalState(I.clippingPlanes,Y),Kt(T,Q,Y),$e.updateMultisampleRenderTarget(Te),$e.updateRenderTargetMipmap(Te),qe.has("WEBGL_multisampled_render_to_texture")===!1){let ke=!1;for(let ut=0,qt=V.length;ut<qt;ut++){const Rt=V[ut],{object:Ct,geometry:mn,material:Ue,group:ln}=Rt;if(Ue.side===fi&&Ct.layers.test(Y.layers)){const _t=Ue.side;Ue.side=Yn,Ue.needsUpdate=!0,en(Ct,Q,Y,mn,Ue,ln),Ue.side=_t,Ue.needsUpdate=!0,ke=!0}}ke===!0&&($e.updateMultisampleRenderTarget(Te),$e.updateRenderTargetMipmap(Te))}I.setRenderTarget(Ae,Le,Be),I.setClearColor(B,te),ht!==void 0&&(Y.viewport=ht),I.toneMapping=et}function Kt(T,V,Q){const Y=V.isScene===!0?V.overrideMaterial:null;for(let K=0,Te=T.length;K<Te;K++){const Pe=T[K],{object:Ae,geometry:Le,group:Be}=Pe;let et=Pe.material;et.allowOverride===!0&&Y!==null&&(et=Y),Ae.layers.test(Q.layers)&&en(Ae,V,Q,Le,et,Be)}}function en(T,V,Q,Y,K,Te){G!==null&&K.isNodeMaterial&&G.setObject(T,K),T.onBeforeRender(I,V,Q,Y,K,Te),T.modelViewMatrix.multiplyMatrices(Q.matrixWorldInverse,T.matrixWorld),T.normalMatrix.getNormalMatrix(T.modelViewMatrix),K.onBeforeRender(I,V,Q,Y,T,Te),K.transparent===!0&&K.side===fi&&K.forceSinglePass===!1?(K.side=Yn,K.needsUpdate=!0,I.renderBufferDirect(Q,V,Y,K,T,Te),K.side=Cs,K.needsUpdate=!0,I.renderBufferDirect(Q,V,Y,K,T,Te),K.side=fi):I.renderBufferDirect(Q,V,Y,K,T,Te),T.onAfterRender(I,V,Q,Y,K,Te)}function tn(T){let V=0;for(const Q of T)Q.texture!==null&&V++;return V}function Pi(T,V,Q){V.isScene!==!0&&(V=pn);const Y=He.get(T),K=y.state.lights,Te=y.state.shadowsArray,Pe=K.state.version,Ae=oe.getParameters(T,K.state,Te,V,Q,y.state.lightProbeGridArray),Le=oe.getProgramCacheKey(Ae);let Be=Y.programs;Y.environment=T.isMeshStandardMaterial||T.isMeshLambertMaterial||T.isMeshPhongMaterial?V.environment:null,Y.fog=V.fog;const et=T.isMeshStandardMaterial||T.isMeshLambertMaterial&&!T.envMap||T.isMeshPhongMaterial&&!T.envMap;Y.envMap=C.get(T.envMap||Y.environment,et),Y.envMapRotation=Y.environment!==null&&T.envMap===null?V.environmentRotation:T.envMapRotation,Be===void 0&&(T.addEventListener("dispose",at),Be=new Map,Y.programs=Be,Y.programVariants=new Map);let ht=Be.get(Le);if(ht!==void 0){if(Y.currentProgram===ht&&Y.lightsStateVersion===Pe)return Qr(T,Ae),ht}else Ae.uniforms=oe.getUniforms(T),G!==null&&T.isNodeMaterial&&G.build(T,Q,Ae),T.onBeforeCompile(Ae,I),ht=oe.acquireProgram(Ae,Le),Be.set(Le,ht),Y.uniforms=Ae.uniforms;const ke=Y.uniforms;return(!T.isShaderMaterial&&!T.isRawShaderMaterial||T.clipping===!0)&&(ke.clippingPlanes=re.uniform),Qr(T,Ae),Y.needsLights=fs(T),Y.lightsStateVersion=Pe,Y.needsLights&&(ke.ambientLightColor.value=K.state.ambient,ke.lightProbe.value=K.state.probe,ke.sunLights.value=K.state.sun,ke.sunLightShadows.value=K.state.sunShadow,ke.directionalLights.value=K.state.directional,ke.directionalLightShadows.value=K.state.directionalShadow,ke.spotLights.value=K.state.spot,ke.spotLightShadows.value=K.state.spotShadow,ke.rectAreaLights.value=K.state.rectArea,ke.ltc_1.value=K.state.rectAreaLTC1,ke.ltc_2.value=K.state.rectAreaLTC2,ke.pointLights.value=K.state.point,ke.pointLightShadows.value=K.state.pointShadow,ke.hemisphereLights.value=K.state.hemi,ke.sunShadowMatrix.value=K.state.sunShadowMatrix,ke.sunShadowCascade.value=K.state.sunShadowCascade,ke.directionalShadowMatrix.value=K.state.directionalShadowMatrix,ke.spotLightMatrix.value=K.state.spotLightMatrix,ke.spotLightMap.value=K.state.spotLightMap,ke.pointShadowMatrix.value=K.state.pointShadowMatrix),Y.numLightProbeGrids=tn(y.state.lightProbeGridArray),Y.currentProgram=ht,Y.uniformsList=null,ht}function Kn(T,V,Q,Y,K){const Te=He.get(T),Pe=Te.currentProgram.id+","+Y+","+K;let Ae=Te.programVariants.get(Pe);return Ae===void 0?(Ae=Pi(T,V,Q),Te.programVariants.set(Pe,Ae)):(Te.currentProgram=Ae,Te.uniformsList=null,Te.outputColorSpace=Y,Te.toneMapping=K),Ae}function ds(T){if(T.uniformsList===null){const V=T.currentProgram.getUniforms();T.uniformsList=Ho.seqWithValue(V.seq,T.uniforms)}return T.uniformsList}function Qr(T,V){const Q=He.get(T);Q.outputColorSpace=V.outputColorSpace,Q.batching=V.batching,Q.batchingColor=V.batchingColor,Q.instancing=V.instancing,Q.instancingColor=V.instancingColor,Q.instancingMorph=V.instancingMorph,Q.skinning=V.skinning,Q.morphTargets=V.morphTargets,Q.morphNormals=V.morphNormals,Q.morphColors=V.morphColors,Q.morphTargetsCount=V.morphTargetsCount,Q.numClippingPlanes=V.numClippingPlanes,Q.numIntersection=V.numClipIntersection,Q.vertexAlphas=V.vertexAlphas,Q.vertexTangents=V.vertexTangents,Q.toneMapping=V.toneMapping}function ea(T,V,Q,Y,K){V.isScene!==!0&&(V=pn),$e.resetTextureUnits();const Te=V.fog,Pe=Y.isMeshStandardMaterial||Y.isMeshLambertMaterial||Y.isMeshPhongMaterial?V.environment:null,Ae=ce===null?I.outputColorSpace:ce.isXRRenderTarget===!0?ce.texture.colorSpace:xt.workingColorSpace,Le=Y.isMeshStandardMaterial||Y.isMeshLambertMaterial&&!Y.envMap||Y.isMeshPhongMaterial&&!Y.envMap,Be=C.get(Y.envMap||Pe,Le),et=Y.vertexColors===!0&&!!Q.attributes.color&&Q.attributes.color.itemSize===4,ht=!!Q.attributes.tangent&&(!!Y.normalMap||Y.anisotropy>0),ke=!!Q.morphAttributes.position,ut=!!Q.morphAttributes.normal,qt=!!Q.morphAttributes.color;let Rt=ls;Y.toneMapped&&(ce===null||ce.isXRRenderTarget===!0)&&(Rt=I.toneMapping);const Ct=Q.morphAttributes.position||Q.morphAttributes.normal||Q.morphAttributes.color,mn=Ct!==void 0?Ct.length:0,Ue=He.get(Y),ln=y.state.lights;if(gt===!0&&($t===!0||T!==ee)){const Pt=T===ee&&Y.id===Z;re.setState(Y,T,Pt)}let _t=!1,ji=!1;Y.version===Ue.__version?Ue.needsLights&&Ue.lightsStateVersion!==ln.state.version||K.isBatchedMesh&&Ue.batching===!1||!K.isBatchedMesh&&Ue.batching===!0||K.isBatchedMesh&&Ue.batchingColor===!0&&K._colorsTexture===null||K.isBatchedMesh&&Ue.batchingColor===!1&&K._colorsTexture!==null||K.isInstancedMesh&&Ue.instancing===!1||!K.isInstancedMesh&&Ue.instancing===!0||K.isSkinnedMesh&&Ue.skinning===!1||!K.isSkinnedMesh&&Ue.skinning===!0||K.isInstancedMesh&&Ue.instancingColor===!0&&K.instanceColor===null||K.isInstancedMesh&&Ue.instancingColor===!1&&K.instanceColor!==null||K.isInstancedMesh&&Ue.instancingMorph===!0&&K.morphTexture===null||K.isInstancedMesh&&Ue.instancingMorph===!1&&K.morphTexture!==null||Ue.envMap!==Be||Y.fog===!0&&Ue.fog!==Te||Ue.numClippingPlanes!==void 0&&(Ue.numClippingPlanes!==re.numPlanes||Ue.numIntersection!==re.numIntersection)||Ue.vertexAlphas!==et||Ue.vertexTangents!==ht||Ue.morphTargets!==ke||Ue.morphNormals!==ut||Ue.morphColors!==qt||Ue.morphTargetsCount!==mn||Ue.numLightProbeGrids!==tn(y.state.lightProbeGridArray)?_t=!0:(Ue.outputColorSpace!==Ae||Ue.toneMapping!==Rt)&&(ji=!0):(_t=!0,Ue.__version=Y.version);let cn=Ue.currentProgram;(_t===!0||ji===!0)&&(cn=ji===!0?Kn(Y,V,K,Ae,Rt):Pi(Y,V,K),G&&Y.isNodeMaterial&&G.onUpdateProgram(Y,cn,Ue));let sr=!1,Li=!1,Qi=!1;const ot=cn.getUniforms(),Zt=Ue.uniforms;if(we.useProgram(cn.program)&&(sr=!0,Li=!0,Qi=!0),Y.id!==Z&&(Z=Y.id,Li=!0),sr||ee!==T){we.buffers.depth.getReversed()&&T.reversedDepth!==!0&&(T._reversedDepth=!0,T.updateProjectionMatrix()),ot.setValue(O,"projectionMatrix",T.projectionMatrix),ot.setValue(O,"viewMatrix",T.matrixWorldInverse);const hn=ot.map.cameraPosition;hn!==void 0&&hn.setValue(O,an.setFromMatrixPosition(T.matrixWorld)),st.logarithmicDepthBuffer&&ot.setValue(O,"logDepthBufFC",2/(Math.log(T.far+1)/Math.LN2)),(Y.isMeshPhongMaterial||Y.isMeshToonMaterial||Y.isMeshLambertMaterial||Y.isMeshBasicMaterial||Y.isMeshStandardMaterial||Y.isShaderMaterial)&&ot.setValue(O,"isOrthographic",T.isOrthographicCamera===!0),ee!==T&&(ee=T,Li=!0,Qi=!0)}if(Ue.needsLights&&(ln.state.sunShadowMap.length>0&&ot.setValue(O,"sunShadowMap",ln.state.sunShadowMap,$e),ln.state.directionalShadowMap.length>0&&ot.setValue(O,"directionalShadowMap",ln.state.directionalShadowMap,$e),ln.state.spotShadowMap.length>0&&ot.setValue(O,"spotShadowMap",ln.state.spotShadowMap,$e),ln.state.pointShadowMap.length>0&&ot.setValue(O,"pointShadowMap",ln.state.pointShadowMap,$e)),K.isSkinnedMesh){ot.setOptional(O,K,"bindMatrix"),ot.setOptional(O,K,"bindMatrixInverse");const Pt=K.skeleton;Pt&&(Pt.boneTexture===null&&Pt.computeBoneTexture(),ot.setValue(O,"boneTexture",Pt.boneTexture,$e))}K.isBatchedMesh&&(ot.setOptional(O,K,"batchingTexture"),ot.setValue(O,"batchingTexture",K._matricesTexture,$e),ot.setOptional(O,K,"batchingIdTexture"),ot.setValue(O,"batchingIdTexture",K._indirectTexture,$e),ot.setOptional(O,K,"batchingColorTexture"),K._colorsTexture!==null&&ot.setValue(O,"batchingColorTexture",K._colorsTexture,$e));const On=Q.morphAttributes;if((On.position!==void 0||On.normal!==void 0||On.color!==void 0)&&ae.update(K,Q,cn),(Li||Ue.receiveShadow!==K.receiveShadow)&&(Ue.receiveShadow=K.receiveShadow,ot.setValue(O,"receiveShadow",K.receiveShadow)),(Y.isMeshStandardMaterial||Y.isMeshLambertMaterial||Y.isMeshPhongMaterial)&&Y.envMap===null&&V.environment!==null&&(Zt.envMapIntensity.value=V.environmentIntensity),Zt.dfgLUT!==void 0&&(Zt.dfgLUT.value=gy()),Li){if(ot.setValue(O,"toneMappingExposure",I.toneMappingExposure),Ue.needsLights&&nr(Zt,Qi),Te&&Y.fog===!0&&Se.refreshFogUniforms(Zt,Te),Se.refreshMaterialUniforms(Zt,Y,ve,ge,y.state.transmissionRenderTarget[T.id]),Ue.needsLights&&Ue.numLightProbeGrids>0){const Pt=S;let hn=0;for(const Ln of y.state.lightProbeGridArray)Ln.texture!==null&&(Pt.textures[hn]=Ln.texture,Pt.min[hn]=Ln.boundingBox.min,Pt.max[hn]=Ln.boundingBox.max,Pt.resolution[hn]=Ln.resolution,hn++);for(const Ln in Pt)Pt[Ln].length=hn;Zt.probesSH.value=Pt.textures,Zt.probesMin.value=Pt.min,Zt.probesMax.value=Pt.max,Zt.probesResolution.value=Pt.resolution}Ho.upload(O,ds(Ue),Zt,$e)}if(Y.isShaderMaterial&&Y.uniformsNeedUpdate===!0&&(Ho.upload(O,ds(Ue),Zt,$e),Y.uniformsNeedUpdate=!1),Y.isSpriteMaterial&&ot.setValue(O,"center",K.center),ot.setValue(O,"modelViewMatrix",K.modelViewMatrix),ot.setValue(O,"normalMatrix",K.normalMatrix),ot.setValue(O,"modelMatrix",K.matrixWorld),Y.uniformsGroups!==void 0){const Pt=Y.uniformsGroups;for(let hn=0,Ln=Pt.length;hn<Ln;hn++){const Xa=Pt[hn];Ge.update(Xa,cn),Ge.bind(Xa,cn)}}return cn}function nr(T,V){T.ambientLightColor.needsUpdate=V,T.lightProbe.needsUpdate=V,T.sunLights.needsUpdate=V,T.sunLightShadows.needsUpdate=V,T.directionalLights.needsUpdate=V,T.directionalLightShadows.needsUpdate=V,T.pointLights.needsUpdate=V,T.pointLightShadows.needsUpdate=V,T.spotLights.needsUpdate=V,T.spotLightShadows.needsUpdate=V,T.rectAreaLights.needsUpdate=V,T.hemisphereLights.needsUpdate=V}function fs(T){return T.isMeshLambertMaterial||T.isMeshToonMaterial||T.isMeshPhongMaterial||T.isMeshStandardMaterial||T.isShadowMaterial||T.isShaderMaterial&&T.lights===!0}this.getActiveCubeFace=function(){return J},this.getActiveMipmapLevel=function(){return H},this.getRenderTarget=function(){return ce},this.setRenderTargetTextures=function(T,V,Q){const Y=He.get(T);Y.__autoAllocateDepthBuffer=T.resolveDepthBuffer===!1,Y.__autoAllocateDepthBuffer===!1&&(Y.__useRenderToTexture=!1),He.get(T.texture).__webglTexture=V,He.get(T.depthTexture).__webglTexture=Y.__autoAllocateDepthBuffer?void 0:Q,Y.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(T,V){const Q=He.get(T);Q.__webglFramebuffer=V,Q.__useDefaultFramebuffer=V===void 0},this.setRenderTarget=function(T,V=0,Q=0){ce=T,J=V,H=Q;let Y=null,K=!1,Te=!1;if(T){const Ae=He.get(T);if(Ae.__useDefaultFramebuffer!==void 0){we.bindFramebuffer(O.FRAMEBUFFER,Ae.__webglFramebuffer),se.copy(T.viewport),pe.copy(T.scissor),fe=T.scissorTest,we.viewport(se),we.scissor(pe),we.setScissorTest(fe),Z=-1;return}else if(Ae.__webglFramebuffer===void 0)$e.setupRenderTarget(T);else if(Ae.__hasExternalTextures)$e.rebindTextures(T,He.get(T.texture).__webglTexture,He.get(T.depthTexture).__webglTexture);else if(T.depthBuffer){const et=T.depthTexture;if(Ae.__boundDepthTexture!==et){if(et!==null&&He.has(et)&&(T.width!==et.image.width||T.height!==et.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");$e.setupDepthRenderbuffer(T)}}const Le=T.texture;(Le.isData3DTexture||Le.isDataArrayTexture||Le.isCompressedArrayTexture)&&(Te=!0);const Be=He.get(T).__webglFramebuffer;T.isWebGLCubeRenderTarget?(Array.isArray(Be[V])?Y=Be[V][Q]:Y=Be[V],K=!0):T.samples>0&&$e.useMultisampledRTT(T)===!1?Y=He.get(T).__webglMultisampledFramebuffer:Array.isArray(Be)?Y=Be[Q]:Y=Be,se.copy(T.viewport),pe.copy(T.scissor),fe=T.scissorTest}else se.copy(ze).multiplyScalar(ve).floor(),pe.copy(nt).multiplyScalar(ve).floor(),fe=tt;if(Q!==0&&(Y=W),we.bindFramebuffer(O.FRAMEBUFFER,Y)&&we.drawBuffers(T,Y),we.viewport(se),we.scissor(pe),we.setScissorTest(fe),K){const Ae=He.get(T.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_CUBE_MAP_POSITIVE_X+V,Ae.__webglTexture,Q)}else if(Te){const Ae=V;for(let Le=0;Le<T.textures.length;Le++){const Be=He.get(T.textures[Le]);O.framebufferTextureLayer(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0+Le,Be.__webglTexture,Q,Ae)}}else if(T!==null&&Q!==0){const Ae=He.get(T.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,Ae.__webglTexture,Q)}Z=-1};function ir(T){const V=He.get(T);return(V.__readFormat!==T.format||V.__readType!==T.type)&&(V.__readFormat=T.format,V.__readType=T.type,V.__formatReadable=st.textureFormatReadable(T.format),V.__typeReadable=st.textureTypeReadable(T.type)),V}this.readRenderTargetPixels=function(T,V,Q,Y,K,Te,Pe,Ae=0){if(!(T&&T.isWebGLRenderTarget)){St("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Le=He.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Pe!==void 0&&(Le=Le[Pe],Array.isArray(Le)&&(Le=Le[0])),Le){we.bindFramebuffer(O.FRAMEBUFFER,Le);try{const Be=T.textures[Ae],et=Be.format,ht=Be.type;T.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Ae);const ke=ir(Be);if(ke.__formatReadable===!1){St("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(ke.__typeReadable===!1){St("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}V>=0&&V<=T.width-Y&&Q>=0&&Q<=T.height-K&&O.readPixels(V,Q,Y,K,xe.convert(et),xe.convert(ht),Te)}finally{const Be=ce!==null?He.get(ce).__webglFramebuffer:null;we.bindFramebuffer(O.FRAMEBUFFER,Be)}}},this.readRenderTargetPixelsAsync=async function(T,V,Q,Y,K,Te,Pe,Ae=0){if(!(T&&T.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Le=He.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Pe!==void 0&&(Le=Le[Pe],Array.isArray(Le)&&(Le=Le[0])),Le)if(V>=0&&V<=T.width-Y&&Q>=0&&Q<=T.height-K){we.bindFramebuffer(O.FRAMEBUFFER,Le);const Be=T.textures[Ae],et=Be.format,ht=Be.type;T.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Ae);const ke=ir(Be);if(ke.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(ke.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");const ut=O.createBuffer();O.bindBuffer(O.PIXEL_PACK_BUFFER,ut),O.bufferData(O.PIXEL_PACK_BUFFER,Te.byteLength,O.STREAM_READ),O.readPixels(V,Q,Y,K,xe.convert(et),xe.convert(ht),0),O.bindBuffer(O.PIXEL_PACK_BUFFER,null);const qt=ce!==null?He.get(ce).__webglFramebuffer:null;we.bindFramebuffer(O.FRAMEBUFFER,qt);const Rt=O.fenceSync(O.SYNC_GPU_COMMANDS_COMPLETE,0);return O.flush(),await I0(O,Rt,4),O.bindBuffer(O.PIXEL_PACK_BUFFER,ut),O.getBufferSubData(O.PIXEL_PACK_BUFFER,0,Te),O.bindBuffer(O.PIXEL_PACK_BUFFER,null),O.deleteBuffer(ut),O.deleteSync(Rt),Te}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(T,V=null,Q=0){const Y=Math.pow(2,-Q),K=Math.floor(T.image.width*Y),Te=Math.floor(T.image.height*Y),Pe=V!==null?V.x:0,Ae=V!==null?V.y:0;$e.setTexture2D(T,0),O.copyTexSubImage2D(O.TEXTURE_2D,Q,0,0,Pe,Ae,K,Te),we.unbindTexture()},this.copyTextureToTexture=function(T,V,Q=null,Y=null,K=0,Te=0){let Pe,Ae,Le,Be,et,ht,ke,ut,qt;const Rt=T.isCompressedTexture?T.mipmaps[Te]:T.image;if(Q!==null)Pe=Q.max.x-Q.min.x,Ae=Q.max.y-Q.min.y,Le=Q.isBox3?Q.max.z-Q.min.z:1,Be=Q.min.x,et=Q.min.y,ht=Q.isBox3?Q.min.z:0;else{const ot=Math.pow(2,-K);Pe=Math.floor(Rt.width*ot),Ae=Math.floor(Rt.height*ot),T.isDataArrayTexture?Le=Rt.depth:T.isData3DTexture?Le=Math.floor(Rt.depth*ot):Le=1,Be=0,et=0,ht=0}Y!==null?(ke=Y.x,ut=Y.y,qt=Y.z):(ke=0,ut=0,qt=0);const Ct=xe.convert(V.format),mn=xe.convert(V.type);let Ue;V.isData3DTexture?($e.setTexture3D(V,0),Ue=O.TEXTURE_3D):V.isDataArrayTexture||V.isCompressedArrayTexture?($e.setTexture2DArray(V,0),Ue=O.TEXTURE_2D_ARRAY):($e.setTexture2D(V,0),Ue=O.TEXTURE_2D),we.activeTexture(O.TEXTURE0),we.pixelStorei(O.UNPACK_FLIP_Y_WEBGL,V.flipY),we.pixelStorei(O.UNPACK_PREMULTIPLY_ALPHA_WEBGL,V.premultiplyAlpha),we.pixelStorei(O.UNPACK_ALIGNMENT,V.unpackAlignment);const ln=we.getParameter(O.UNPACK_ROW_LENGTH),_t=we.getParameter(O.UNPACK_IMAGE_HEIGHT),ji=we.getParameter(O.UNPACK_SKIP_PIXELS),cn=we.getParameter(O.UNPACK_SKIP_ROWS),sr=we.getParameter(O.UNPACK_SKIP_IMAGES);we.pixelStorei(O.UNPACK_ROW_LENGTH,Rt.width),we.pixelStorei(O.UNPACK_IMAGE_HEIGHT,Rt.height),we.pixelStorei(O.UNPACK_SKIP_PIXELS,Be),we.pixelStorei(O.UNPACK_SKIP_ROWS,et),we.pixelStorei(O.UNPACK_SKIP_IMAGES,ht);const Li=T.isDataArrayTexture||T.isData3DTexture,Qi=V.isDataArrayTexture||V.isData3DTexture;if(T.isDepthTexture){const ot=He.get(T),Zt=He.get(V),On=He.get(ot.__renderTarget),Pt=He.get(Zt.__renderTarget);we.bindFramebuffer(O.READ_FRAMEBUFFER,On.__webglFramebuffer),we.bindFramebuffer(O.DRAW_FRAMEBUFFER,Pt.__webglFramebuffer);for(let hn=0;hn<Le;hn++)Li&&(O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,He.get(T).__webglTexture,K,ht+hn),O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,He.get(V).__webglTexture,Te,qt+hn)),O.blitFramebuffer(Be,et,Be+Pe,et+Ae,ke,ut,ke+Pe,ut+Ae,O.DEPTH_BUFFER_BIT,O.NEAREST);we.bindFramebuffer(O.READ_FRAMEBUFFER,null),we.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else if(K!==0||T.isRenderTargetTexture||He.has(T)){const ot=He.get(T),Zt=He.get(V);we.bindFramebuffer(O.READ_FRAMEBUFFER,U),we.bindFramebuffer(O.DRAW_FRAMEBUFFER,X);for(let On=0;On<Le;On++)Li?O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,ot.__webglTexture,K,ht+On):O.framebufferTexture2D(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,ot.__webglTexture,K),Qi?O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Zt.__webglTexture,Te,qt+On):O.framebufferTexture2D(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,Zt.__webglTexture,Te),K!==0?O.blitFramebuffer(Be,et,Be+Pe,et+Ae,ke,ut,ke+Pe,ut+Ae,O.COLOR_BUFFER_BIT,O.NEAREST):Qi?O.copyTexSubImage3D(Ue,Te,ke,ut,qt+On,Be,et,Pe,Ae):O.copyTexSubImage2D(Ue,Te,ke,ut,Be,et,Pe,Ae);we.bindFramebuffer(O.READ_FRAMEBUFFER,null),we.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else Qi?T.isDataTexture||T.isData3DTexture?O.texSubImage3D(Ue,Te,ke,ut,qt,Pe,Ae,Le,Ct,mn,Rt.data):V.isCompressedArrayTexture?O.compressedTexSubImage3D(Ue,Te,ke,ut,qt,Pe,Ae,Le,Ct,Rt.data):O.texSubImage3D(Ue,Te,ke,ut,qt,Pe,Ae,Le,Ct,mn,Rt):T.isDataTexture?O.texSubImage2D(O.TEXTURE_2D,Te,ke,ut,Pe,Ae,Ct,mn,Rt.data):T.isCompressedTexture?O.compressedTexSubImage2D(O.TEXTURE_2D,Te,ke,ut,Rt.width,Rt.height,Ct,Rt.data):O.texSubImage2D(O.TEXTURE_2D,Te,ke,ut,Pe,Ae,Ct,mn,Rt);we.pixelStorei(O.UNPACK_ROW_LENGTH,ln),we.pixelStorei(O.UNPACK_IMAGE_HEIGHT,_t),we.pixelStorei(O.UNPACK_SKIP_PIXELS,ji),we.pixelStorei(O.UNPACK_SKIP_ROWS,cn),we.pixelStorei(O.UNPACK_SKIP_IMAGES,sr),Te===0&&V.generateMipmaps===!0&&V.mipmapsAutoUpdate===!0&&O.generateMipmap(Ue),we.unbindTexture()},this.initRenderTarget=function(T){He.get(T).__webglFramebuffer===void 0&&$e.setupRenderTarget(T)},this.initTexture=function(T){T.isCubeTexture?$e.setTextureCube(T,0):T.isData3DTexture?$e.setTexture3D(T,0):T.isDataArrayTexture||T.isCompressedArrayTexture?$e.setTexture2DArray(T,0):$e.setTexture2D(T,0),we.unbindTexture()},this.resetState=function(){J=0,H=0,ce=null,we.reset(),be.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Ri}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;const t=this.getContext();t.drawingBufferColorSpace=xt._getDrawingBufferColorSpace(e),t.unpackColorSpace=xt._getUnpackColorSpace()}}const Wd={type:"change"},Jh={type:"start"},nm={type:"end"},wo=new rl,Xd=new Ti,_y=Math.cos(70*k0.DEG2RAD),_n=new z,Xn=2*Math.PI,Tt={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},cc=1e-6;class im extends b_{constructor(e,t=null){super(e,t),this.state=Tt.NONE,this.target=new z,this.cursor=new z,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:Ir.ROTATE,MIDDLE:Ir.DOLLY,RIGHT:Ir.PAN},this.touches={ONE:Nr.ROTATE,TWO:Nr.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new z,this._lastQuaternion=new Ls,this._lastTargetPosition=new z,this._quat=new Ls().setFromUnitVectors(e.up,new z(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new Sd,this._sphericalDelta=new Sd,this._scale=1,this._panOffset=new z,this._rotateStart=new Xe,this._rotateEnd=new Xe,this._rotateDelta=new Xe,this._panStart=new Xe,this._panEnd=new Xe,this._panDelta=new Xe,this._dollyStart=new Xe,this._dollyEnd=new Xe,this._dollyDelta=new Xe,this._dollyDirection=new z,this._mouse=new Xe,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=xy.bind(this),this._onPointerDown=vy.bind(this),this._onPointerUp=Sy.bind(this),this._onContextMenu=Ay.bind(this),this._onMouseWheel=by.bind(this),this._onKeyDown=wy.bind(this),this._onTouchStart=Ey.bind(this),this._onTouchMove=Ty.bind(this),this._onMouseDown=My.bind(this),this._onMouseMove=yy.bind(this),this._interceptControlDown=Ry.bind(this),this._interceptControlUp=Cy.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Tt.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(Wd),this.update(),this.state=Tt.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){const t=this.object.position;_n.copy(t).sub(this.target),_n.applyQuaternion(this._quat),this._spherical.setFromVector3(_n),this.autoRotate&&this.state===Tt.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let n=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(n)&&isFinite(s)&&(n<-Math.PI?n+=Xn:n>Math.PI&&(n-=Xn),s<-Math.PI?s+=Xn:s>Math.PI&&(s-=Xn),n<=s?this._spherical.theta=Math.max(n,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(n+s)/2?Math.max(n,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{const a=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=a!=this._spherical.radius}if(_n.setFromSpherical(this._spherical),_n.applyQuaternion(this._quatInverse),t.copy(this.target).add(_n),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let a=null;if(this.object.isPerspectiveCamera){const o=_n.length();a=this._clampDistance(o*this._scale);const l=o-a;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),r=!!l}else if(this.object.isOrthographicCamera){const o=new z(this._mouse.x,this._mouse.y,0);o.unproject(this.object);const l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=l!==this.object.zoom;const c=new z(this._mouse.x,this._mouse.y,0);c.unproject(this.object),this.object.position.sub(c).add(o),this.object.updateMatrixWorld(),a=_n.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;a!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(a).add(this.object.position):(wo.origin.copy(this.object.position),wo.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(wo.direction))<_y?this.object.lookAt(this.target):(Xd.setFromNormalAndCoplanarPoint(this.object.up,this.target),wo.intersectPlane(Xd,this.target))))}else if(this.object.isOrthographicCamera){const a=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),a!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>cc||8*(1-this._lastQuaternion.dot(this.object.quaternion))>cc||this._lastTargetPosition.distanceToSquared(this.target)>cc?(this.dispatchEvent(Wd),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?Xn/60*this.autoRotateSpeed*e:Xn/60/60*this.autoRotateSpeed}_getZoomScale(e){const t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){_n.setFromMatrixColumn(t,0),_n.multiplyScalar(-e),this._panOffset.add(_n)}_panUp(e,t){this.screenSpacePanning===!0?_n.setFromMatrixColumn(t,1):(_n.setFromMatrixColumn(t,0),_n.crossVectors(this.object.up,_n)),_n.multiplyScalar(e),this._panOffset.add(_n)}_pan(e,t){const n=this.domElement;if(this.object.isPerspectiveCamera){const s=this.object.position;_n.copy(s).sub(this.target);let r=_n.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/n.clientHeight,this.object.matrix),this._panUp(2*t*r/n.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/n.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/n.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;const n=this.domElement.getBoundingClientRect(),s=e-n.left,r=t-n.top,a=n.width,o=n.height;this._mouse.x=s/a*2-1,this._mouse.y=-(r/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(Xn*this._rotateDelta.x/t.clientHeight),this._rotateUp(Xn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(Xn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-Xn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(Xn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-Xn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._rotateStart.set(n,s)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panStart.set(n,s)}}_handleTouchStartDolly(e){const t=this._getSecondPointerPosition(e),n=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(n*n+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{const n=this._getSecondPointerPosition(e),s=.5*(e.pageX+n.x),r=.5*(e.pageY+n.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const t=this.domElement;this._rotateLeft(Xn*this._rotateDelta.x/t.clientHeight),this._rotateUp(Xn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{const t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panEnd.set(n,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){const t=this._getSecondPointerPosition(e),n=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(n*n+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);const a=(e.pageX+t.x)*.5,o=(e.pageY+t.y)*.5;this._updateZoomParameters(a,o)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new Xe,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){const t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){const t=e.deltaMode,n={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:n.deltaY*=16;break;case 2:n.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(n.deltaY*=10),n}}function vy(i){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(i.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(i)&&(this._addPointer(i),i.pointerType==="touch"?this._onTouchStart(i):this._onMouseDown(i),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function xy(i){this.enabled!==!1&&(i.pointerType==="touch"?this._onTouchMove(i):this._onMouseMove(i))}function Sy(i){switch(this._removePointer(i),this._pointers.length){case 0:this.domElement.releasePointerCapture(i.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(nm),this.state=Tt.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:const e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function My(i){let e;switch(i.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case Ir.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(i),this.state=Tt.DOLLY;break;case Ir.ROTATE:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Tt.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Tt.ROTATE}break;case Ir.PAN:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Tt.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Tt.PAN}break;default:this.state=Tt.NONE}this.state!==Tt.NONE&&this.dispatchEvent(Jh)}function yy(i){switch(this.state){case Tt.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(i);break;case Tt.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(i);break;case Tt.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(i);break}}function by(i){this.enabled===!1||this.enableZoom===!1||this.state!==Tt.NONE||(i.preventDefault(),this.dispatchEvent(Jh),this._handleMouseWheel(this._customWheelEvent(i)),this.dispatchEvent(nm))}function wy(i){this.enabled!==!1&&this._handleKeyDown(i)}function Ey(i){switch(this._trackPointer(i),this._pointers.length){case 1:switch(this.touches.ONE){case Nr.ROTATE:if(this.enableRotate===!1){this.state=Tt.NONE;break}this._handleTouchStartRotate(i),this.state=Tt.TOUCH_ROTATE;break;case Nr.PAN:if(this.enablePan===!1){this.state=Tt.NONE;break}this._handleTouchStartPan(i),this.state=Tt.TOUCH_PAN;break;default:this.state=Tt.NONE}break;case 2:switch(this.touches.TWO){case Nr.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(i),this.state=Tt.TOUCH_DOLLY_PAN;break;case Nr.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(i),this.state=Tt.TOUCH_DOLLY_ROTATE;break;default:this.state=Tt.NONE}break;default:this.state=Tt.NONE}this.state!==Tt.NONE&&this.dispatchEvent(Jh)}function Ty(i){switch(this._trackPointer(i),this.state){case Tt.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(i),this.update();break;case Tt.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(i),this.update();break;case Tt.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(i),this.update();break;case Tt.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(i),this.update();break;default:this.state=Tt.NONE}}function Ay(i){this.enabled!==!1&&i.preventDefault()}function Ry(i){i.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function Cy(i){i.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}class Py{constructor(e){const t=new Hp;t.aspect=.5;const n=new Xe;this.setEyeSeparation=function(s){t.eyeSep=s},this.setSize=function(s,r){e.setSize(s,r)},this.render=function(s,r){s.matrixWorldAutoUpdate===!0&&s.updateMatrixWorld(),r.parent===null&&r.matrixWorldAutoUpdate===!0&&r.updateMatrixWorld(),t.update(r);const a=e.autoClear;e.getSize(n),e.autoClear=!1,e.clear(),e.setScissorTest(!0),e.setScissor(0,0,n.width/2,n.height),e.setViewport(0,0,n.width/2,n.height),e.render(s,t.cameraL),e.setScissor(n.width/2,0,n.width/2,n.height),e.setViewport(n.width/2,0,n.width/2,n.height),e.render(s,t.cameraR),e.setScissorTest(!1),e.autoClear=a}}}const Eo=(i,e)=>i[0]*e[0]+i[1]*e[1]+i[2]*e[2],hc=(i,e)=>[i[0]+e[0],i[1]+e[1],i[2]+e[2]],uc=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]],zi=(i,e)=>[i[0]*e,i[1]*e,i[2]*e];function Ly(i,e){return 4*Math.sqrt(Math.max(Math.abs(e),1)*Math.max(i,0))}function Dy(i,e,t,n,s){const r=Math.hypot(...t),a=Math.hypot(...i.direction);if(!(r>0)||!(a>0)||!(n>0)||!Number.isFinite(r)||!Number.isFinite(a)||![...e,...i.origin].every(Number.isFinite))return null;const o=zi(t,1/r),l=zi(i.direction,1/a),c=hc(e,t),h=uc(c,i.origin),u=Eo(o,l),d=Math.abs(u)>1e-9?Eo(o,h)/u:-1,m=d>0?hc(i.origin,zi(l,d)):hc(i.origin,zi(l,Math.max(Eo(h,l),0)));let _=uc(m,c);_=uc(_,zi(o,Eo(_,o)));let M=zi(_,1/n);const p=Math.hypot(...M);if(!Number.isFinite(p))return null;const f=Math.max(s,0);return p>f?(M=p>0?zi(M,f/p):[0,0,0],{v:M,speed:f,capped:!0}):{v:M,speed:p,capped:!1}}function Ny(i,e,t,n){const s=zi(e,t),r=Math.hypot(...s);if(r>=n)return s;if(r>1e-12*n)return zi(s,n/r);const a=[-i[1],i[0],0],o=Math.hypot(...a);return o>1e-12*Math.hypot(...i)&&o>0?zi(a,n/o):[n,0,0]}function Iy(i,e,t){const n=i.intersectSphere(new za(e,t),new z);if(n!==null)return n.sub(e);const s=i.closestPointToPoint(e,new z).sub(e),r=s.length();return r>0?s.multiplyScalar(t/r):new z(0,0,-t)}class Uy{constructor(e,t,n,s,r,a){this.canvas=e,this.camera=t,this.controls=n,this.bob=s,this.onDrag=r,this.sphere=a,e.addEventListener("pointerdown",o=>this.down(o),{capture:!0}),e.addEventListener("pointermove",o=>this.move(o)),e.addEventListener("pointerup",o=>this.up(o)),e.addEventListener("pointercancel",o=>this.up(o))}canvas;camera;controls;bob;onDrag;sphere;dragging=!1;raycaster=new Vp;get active(){return this.dragging}ray(e){const t=this.canvas.getBoundingClientRect(),n=new Xe((e.clientX-t.left)/t.width*2-1,-((e.clientY-t.top)/t.height)*2+1);return this.raycaster.setFromCamera(n,this.camera),this.raycaster.ray}position(e){const{pivot:t,length:n}=this.sphere(),s=Iy(this.ray(e),t,n);return[s.x,s.y,s.z]}down(e){e.button!==0||!this.bob.visible||(this.ray(e),this.raycaster.intersectObject(this.bob,!1).length!==0&&(this.dragging=!0,this.controls.enabled=!1,this.canvas.setPointerCapture?.(e.pointerId),e.stopImmediatePropagation(),this.onDrag(this.position(e),"start")))}move(e){this.dragging&&this.onDrag(this.position(e),"move")}up(e){this.dragging&&(this.dragging=!1,this.controls.enabled=!0,this.onDrag(this.position(e),"end"))}}class Fy{constructor(e,t,n,s,r,a,o,l){this.canvas=e,this.camera=t,this.controls=n,this.handle=s,this.occluder=r,this.grabRadius=a,this.pullBasis=o,this.onPull=l,e.addEventListener("pointerdown",c=>this.down(c),{capture:!0}),e.addEventListener("pointermove",c=>this.move(c)),e.addEventListener("pointerup",c=>this.up(c)),e.addEventListener("pointercancel",c=>this.up(c))}canvas;camera;controls;handle;occluder;grabRadius;pullBasis;onPull;basis=null;moved=!1;raycaster=new Vp;tmp=new z;get active(){return this.basis!==null}ray(e){const t=this.canvas.getBoundingClientRect(),n=new Xe((e.clientX-t.left)/t.width*2-1,-((e.clientY-t.top)/t.height)*2+1);return this.raycaster.setFromCamera(n,this.camera),this.raycaster.ray}pulled(e){if(this.basis===null)return null;const t=this.ray(e),{pivot:n,x:s,arrowScale:r,vmax:a}=this.basis;return Dy({origin:[t.origin.x,t.origin.y,t.origin.z],direction:[t.direction.x,t.direction.y,t.direction.z]},n,s,r,a)}down(e){if(e.button!==0||!this.handle.visible)return;const t=this.ray(e),n=this.handle.getWorldPosition(this.tmp),s=this.grabRadius();if(t.distanceToPoint(n)>s)return;const r=this.raycaster.intersectObject(this.occluder,!1)[0];if(r!==void 0&&r.distance<n.sub(t.origin).dot(t.direction)-s)return;const a=this.pullBasis();a!==null&&(this.basis=a,this.moved=!1,this.controls.enabled=!1,this.canvas.setPointerCapture?.(e.pointerId),e.stopImmediatePropagation(),this.onPull(a.x,null,"start"))}move(e){this.basis!==null&&(this.moved=!0,this.onPull(this.basis.x,this.pulled(e),"move"))}up(e){if(this.basis===null)return;const t=this.moved?this.pulled(e):null,n=this.basis.x;this.basis=null,this.controls.enabled=!0,this.onPull(n,t,"end")}}const Gn=180/Math.PI;function _h(i){return{theta:Math.atan2(Math.hypot(i[0],i[1]),-i[2]),phi:Math.atan2(i[1],i[0])}}function Oy(i){let e=i%(2*Math.PI);return e<=-Math.PI&&(e+=2*Math.PI),e>Math.PI&&(e-=2*Math.PI),e}class ky{constructor(e=8){this.maxLaps=e}maxLaps;acc=0;since=null;laps=[];get running(){return this.since!==null}reading(e){return this.acc+(this.since===null?0:Math.max(0,e-this.since))}start(e){this.since===null&&(this.since=e)}stop(e){this.since!==null&&(this.acc=this.reading(e),this.since=null)}lap(e){this.laps.push(this.reading(e)),this.laps.length>this.maxLaps&&this.laps.shift()}reset(){[this.acc,this.since,this.laps]=[0,null,[]]}}const To={kind:null,period:null,advance:null,precession:null,lowPerPeriod:1,intervals:0,amplitude:null,thetaMin:null,thetaMax:null,from:null,to:null};class By{constructor(e=1e-7,t=10,n=.02){this.minRise=e,this.keep=t,this.planarRatio=n}minRise;keep;planarRatio;prev=null;phi=0;lows=[];zLow=1/0;zHigh=-1/0;rMax=0;thMax=0;thMin=1/0;reset(){this.prev=null,this.phi=0,this.lows=[],this.zLow=1/0,this.zHigh=-1/0,this.rMax=0,this.thMax=0,this.thMin=1/0}push(e){const t=this.prev;if(t!==null&&e.t<=t.t)return;const n=Math.atan2(e.x[1],e.x[0]),s=Math.hypot(e.x[0],e.x[1]),r=Math.atan2(s,-e.x[2]);if(t===null){this.phi=n,this.prev=e,this.zLow=this.zHigh=e.x[2],[this.rMax,this.thMax,this.thMin]=[s,r,r];return}const a=this.phi;this.phi=a+Oy(n-Math.atan2(t.x[1],t.x[0])),this.zLow=Math.min(this.zLow,e.x[2]),this.zHigh=Math.max(this.zHigh,e.x[2]);const[o,l]=[t.v[2],e.v[2]];if(o<0&&l>=0){const c=o===l?0:-o/(l-o),h=t.t+c*(e.t-t.t),u=a+c*(this.phi-a);if(this.lows.length===0||this.zHigh-this.zLow>this.minRise){const d=(S,R)=>S+c*(R-S),m=d(t.x[0],e.x[0]),_=d(t.x[1],e.x[1]),M=d(t.v[0],e.v[0]),p=d(t.v[1],e.v[1]),f=Math.hypot(M,p)||1,x=Math.hypot(m,_),A=Math.max(this.rMax,x);this.lows.push({t:h,phi:u,dir:[M/f,p/f],through:A>0&&x<=this.planarRatio*A,thetaMax:this.thMax,thetaMin:Math.min(this.thMin,r)}),this.lows.length>2*this.keep+1&&this.lows.shift()}this.zLow=this.zHigh=e.x[2],[this.rMax,this.thMax,this.thMin]=[s,r,r],this.prev=e;return}this.rMax=Math.max(this.rMax,s),this.thMax=Math.max(this.thMax,r),this.thMin=Math.min(this.thMin,r),this.prev=e}reading(){const e=this.lows,t=e[e.length-1];if(t===void 0||e.length<2)return{...To};const n={thetaMin:Math.min(t.thetaMin,this.thMin),thetaMax:Math.max(t.thetaMax,this.thMax)};if(t.through){const l=[];let c=0;for(let p=e.length-1;p>=0&&l.length<=this.keep;p--){const f=e[p];if(!f.through)break;f.dir[0]*t.dir[0]+f.dir[1]*t.dir[1]>0&&l.push(f),c=p}const h=l.length-1,u=l[h],d=e[e.length-2],m=d.dir[0]*t.dir[0]+d.dir[1]*t.dir[1]>0?1:2,_=e.slice(Math.max(c,e.indexOf(u))+1),M=_.length>0?Math.sqrt(_.reduce((p,f)=>p+f.thetaMax**2,0)/_.length):t.thetaMax;return{...To,kind:"swing",period:h<1?null:(t.t-u.t)/h,lowPerPeriod:m,intervals:Math.max(h,0),amplitude:M,...n,from:h<1?null:u.t,to:t.t}}let s=e.length-1;for(;s>0&&e.length-1-s<this.keep&&!e[s-1].through;)s--;const r=e[s],a=e.length-1-s;if(a<1)return{...To,kind:"orbit",...n};const o=(t.phi-r.phi)/a;return{...To,kind:"orbit",period:(t.t-r.t)/a,advance:o,precession:Math.sign(o)*(2*Math.abs(o)-2*Math.PI),intervals:a,...n,from:r.t,to:t.t}}}function zy(i){let[e,t]=[1,Math.sqrt(1-i)];for(let n=0;n<40&&Math.abs(e-t)>1e-16*e;n++)[e,t]=[(e+t)/2,Math.sqrt(e*t)];return Math.PI/(2*e)}function Hy(i,e,t,n){if(!(e>0)||!(i>0)||!(n>=0)||n>=Math.PI)return null;const s=e/i,r=Math.sqrt(s-t**2/4);return r>0?4*zy(Math.sin(n/2)**2)/r:null}function Vy(i,e,t,n,s){const r=.5*e*(i.v[0]**2+i.v[1]**2+i.v[2]**2),a=i.energy-r+e*Math.abs(t)*n,o=-s;return{kinetic:r,potential:a,lost:o,total:r+a+o}}function Gy(i,e){return .5*(i.power+e.power)*(e.t-i.t)}function Wy(i,e,t=null){const n=i.kind===null?e?.kind==="planar":i.kind==="swing",s=e===null||e.period_z_infinite||e.period_z===null?null:e.period_z;let r=s;n&&s!==null&&e?.kind!=="planar"&&(r=i.lowPerPeriod*s),e===null&&(r=t);const a=e?.azimuth_advance??null,o=l=>l===null?null:Math.sign(l)*(2*Math.abs(l)-2*Math.PI);return{swing:n,period:[i.period,r],advance:[n?null:i.advance,n?null:a],precession:[n?null:i.precession,n?null:o(a)]}}const $d=512,$s=4e3,Xy=4e3,$y=2e5,qy=3,Yy=["t [s]","x1 [m]","x2 [m]","x3 [m]","v1 [m/s]","v2 [m/s]","v3 [m/s]","energy [J]","j3 [kg m^2/s]","tension [N]","power [W]","a1 [m/s^2]","a2 [m/s^2]","a3 [m/s^2]","pivot1 [m]","pivot2 [m]","pivot3 [m]","taut [1]","error_x [m]"];function qd(){return{t:[],dE:[],dJ3:[],z:[],zdot:[],tension:[],frames:[]}}function ki(i,e,t){return i+(e-i)*t}function Ky(i,e,t){const n=(o,l)=>[ki(o[0],l[0],t),ki(o[1],l[1],t),ki(o[2],l[2],t)],s=n(i.x,e.x),r=ki(Math.hypot(...i.x),Math.hypot(...e.x),t),a=Math.hypot(...s);if(a>0)for(let o=0;o<3;o++)s[o]=s[o]*(r/a);return{t:ki(i.t,e.t,t),x:s,v:n(i.v,e.v),energy:ki(i.energy,e.energy,t),j3:ki(i.j3,e.j3,t),tension:ki(i.tension,e.tension,t),power:ki(i.power,e.power,t),a:n(i.a,e.a),pivot:n(i.pivot,e.pivot),taut:i.taut&&e.taut,errorX:i.errorX<0||e.errorX<0?-1:ki(i.errorX,e.errorX,t)}}function Zy(i,e,t){return i===null||e.epoch!==i.epoch||t!==null&&e.t<t}function Yd(i,e,t){let n=0,s=i.length;for(;n<s;){const r=n+s>>1,a=i[r].t;(t?a<e:a<=e)?n=r+1:s=r}return n}class sm{status=null;frames=[];trail=[];history=qd();trajectory=[];trajectoryTruncated=!1;reference=null;tensionExtremes=null;playT=null;exact=null;exactError=null;errors=[];events=[];connected=!1;tickHz=60;work=0;periodTimer=new By;historyStride=1;historyCount=0;disconnected=!1;listeners=new Set;subscribe(e){return this.listeners.add(e),()=>this.listeners.delete(e)}emit(){for(const e of this.listeners)e()}onStatus(e){const t=this.disconnected||Zy(this.status,e,this.latest()?.t??null);this.disconnected=!1,this.status=e,t&&this.clear(),this.emit()}clear(){this.frames=[],this.trail=[],this.history=qd(),this.trajectory=[],this.trajectoryTruncated=!1,this.reference=null,this.tensionExtremes=null,this.playT=null,this.exact=null,this.exactError=null,this.events=[],this.work=0,this.periodTimer.reset(),this.historyStride=1,this.historyCount=0}onError(e){this.errors.push(e),this.errors.length>20&&this.errors.shift(),this.emit()}onEvent(e){const t=this.events;this.events=Pg(t,e,this.status?.epoch??null),this.events!==t&&(this.work-=e.energy_lost,this.emit())}setConnected(e){this.connected=e,e||(this.disconnected=!0),this.emit()}setExact(e,t=null){this.exact=e,this.exactError=t,this.emit()}onFrames(e){for(const t of e){const n=this.frames[this.frames.length-1];if(n!==void 0&&t.t<n.t)continue;n!==void 0&&t.t===n.t?this.frames.pop():n!==void 0&&(this.work+=Gy(n,t)),this.frames.push(t),this.periodTimer.push(t),this.reference===null&&(this.reference={energy:t.energy,j3:t.j3});const s=this.tensionExtremes;s===null?this.tensionExtremes={min:t.tension,tMin:t.t,max:t.tension,tMax:t.t}:(t.tension<s.min&&([s.min,s.tMin]=[t.tension,t.t]),t.tension>s.max&&([s.max,s.tMax]=[t.tension,t.t])),this.pushTrail(t),this.pushHistory(t),this.trajectory.length<$y?this.trajectory.push(t):this.trajectoryTruncated=!0,this.playT===null&&(this.playT=t.t)}this.frames.length>$d&&this.frames.splice(0,this.frames.length-$d)}pushTrail(e){const t=this.trail[this.trail.length-1];t!==void 0&&t.t===e.t&&this.trail.pop(),this.trail.push(e),this.trail.length>$s&&this.trail.splice(0,this.trail.length-$s)}pushHistory(e){const t=this.reference;if(t===null)return;const n=this.history;if(!(n.t.length>0&&e.t<=n.t[n.t.length-1])&&this.historyCount++%this.historyStride===0&&(n.t.push(e.t),n.dE.push(e.energy-t.energy),n.dJ3.push(e.j3-t.j3),n.z.push(e.x[2]),n.zdot.push(e.v[2]),n.tension.push(e.tension),n.frames.push(e),n.t.length>Xy)){const s=r=>r.filter((a,o)=>o%2===0);this.history={t:s(n.t),dE:s(n.dE),dJ3:s(n.dJ3),z:s(n.z),zdot:s(n.zdot),tension:s(n.tension),frames:s(n.frames)},this.historyStride*=2,this.historyCount=1}}latest(){return this.frames[this.frames.length-1]??null}advancePlayhead(e){const t=this.latest(),n=this.frames[0];if(t==null||n===void 0)return this.playT=null;const s=this.status;if(s===null||s.paused||this.playT===null)return this.playT=t.t,this.playT;const r=qy*s.time_scale/this.tickHz;let a=this.playT+Math.max(0,e)*s.time_scale;return a=Math.min(a,t.t),a=Math.max(a,t.t-r,n.t),this.playT=a,a}displayed(){const e=this.playT,t=this.frames;if(e===null||t.length===0)return null;const n=t[t.length-1];if(e>=n.t)return n;let s=0,r=t.length-1;if(e<=t[0].t)return t[0];for(;r-s>1;){const c=s+r>>1;t[c].t<=e?s=c:r=c}const a=t[s],o=t[r],l=o.t-a.t;return Ky(a,o,l>0?(e-a.t)/l:1)}trailRange(e){const t=this.playT;if(t===null)return{start:0,end:0};const n=Yd(this.trail,t,!1),s=Yd(this.trail,t-e,!0);return{start:Math.min(s,n),end:n}}trailWindow(e){const{start:t,end:n}=this.trailRange(e);return this.trail.slice(t,n)}toCSV(){const e=this.status,t={source:"pendulab lab",scenario:e?.scenario??null,params:e?.params??null,model:e?.model??null,model_params:e?.model_params??null,method:e?.method??null,dt:e?.dt??null,truncated:this.trajectoryTruncated},n=Yy.join(","),s=this.trajectory.map(r=>[r.t,...r.x,...r.v,r.energy,r.j3,r.tension,r.power,...r.a,...r.pivot,r.taut?1:0,r.errorX].map(a=>String(a)).join(","));return[`# ${JSON.stringify(t)}`,n,...s].join(`
`)+`
`}}const Kd=(i,e)=>[i[1]*e[2]-i[2]*e[1],i[2]*e[0]-i[0]*e[2],i[0]*e[1]-i[1]*e[0]],va=(i,e)=>[i[0]*e,i[1]*e,i[2]*e],Jy=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]];function jy(i){const e=[i?.gravity_x??0,i?.gravity_y??0,i?.gravity_z??-1],t=Math.hypot(...e);return t>0?va(e,1/t):[0,0,-1]}function Qy(i,e,t,n,s){const r=Math.hypot(...i.x),a=va(i.v,e),o=va(i.a,e),l=Jy(i.x,s);return{velocity:i.v,momentum:a,gravity:va(n,e*t),tension:r>0?va(i.x,-i.tension/r):[0,0,0],net:o,angularMomentum:Kd(l,a),torque:Kd(l,o)}}function dc(i,e,t){const n=Math.max(Math.abs(t),1),s=.5*i/(e*n),r=Math.sqrt(n/i);return{velocity:.25,momentum:.25,gravity:s,tension:s,net:s,angularMomentum:.5*i/(e*i*i*r),torque:s/i}}const rm=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]],Ia=i=>Math.hypot(i[0],i[1],i[2]),Ua=(i,e)=>[i[0]*e,i[1]*e,i[2]*e],vh=(i,e)=>[i[1]*e[2]-i[2]*e[1],i[2]*e[0]-i[0]*e[2],i[0]*e[1]-i[1]*e[0]];function am(i,e){const t=e[0]*i[0]+e[1]*i[1]+e[2]*i[2];let n=rm(e,Ua(i,t));return Ia(n)<1e-9&&(n=Math.abs(i[0])<.9?vh(i,[1,0,0]):vh(i,[0,1,0])),Ua(n,1/Ia(n))}function eb(i,e,t,n){const s=Ia(i);if(!(s>0))return[[0,0,0],[...i]];const r=Ua(i,1/s),a=am(r,[0,0,1]),o=vh(r,a),l=[];for(let c=0;c<=n;c++){const h=c/n,u=t*Math.min(1,h/.05,(1-h)/.05),d=2*Math.PI*e*h,[m,_]=[Math.cos(d)*u,Math.sin(d)*u];l.push([i[0]*h+a[0]*m+o[0]*_,i[1]*h+a[1]*m+o[1]*_,i[2]*h+a[2]*m+o[2]*_])}return l}function tb(i){let e=0;for(let t=1;t<i.length;t++)e+=Ia(rm(i[t],i[t-1]));return e}function Zd(i,e,t){const n=[];for(let s=0;s<=t;s++){const r=s/t,[a,o]=[2*r*(1-r),r*r];n.push([e[0]*a+i[0]*o,e[1]*a+i[1]*o,e[2]*a+i[2]*o])}return n}function nb(i,e,t,n=[0,0,-1]){const s=Ia(i),r=Ua(i,.5);if(!(s>0)||s>=e)return Zd(i,r,t);const a=am(Ua(i,1/s),n),o=h=>Zd(i,[r[0]+a[0]*h,r[1]+a[1]*h,r[2]+a[2]*h],t);let[l,c]=[0,e];for(let h=0;h<40&&c-l>1e-4*e;h++){const u=.5*(l+c);tb(o(u))<e?l=u:c=u}return o(.5*(l+c))}const Jd=400,jd=48;class ib{group=new Wi;coil;slack;constructor(){this.coil=new Ki(new Bt().setFromPoints(Array.from({length:Jd+1},()=>new z)),new gi({color:14211288})),this.slack=new Ki(new Bt().setFromPoints(Array.from({length:jd+1},()=>new z)),new Op({color:15918793,dashSize:.04,gapSize:.03}));for(const e of[this.coil,this.slack])e.frustumCulled=!1,e.visible=!1;this.group.add(this.coil,this.slack)}update(e,t,n,s,r){if(this.coil.visible=e==="coil",this.slack.visible=e==="slack string",this.group.position.set(...n),e==="coil"&&this.fill(this.coil,eb(t,14,.035*s,Jd)),e==="slack string"){this.fill(this.slack,nb(t,s,jd,r));const a=this.slack.material;a.dashSize=.04*s,a.gapSize=.03*s,this.slack.computeLineDistances()}}fill(e,t){const n=e.geometry.getAttribute("position");t.forEach((s,r)=>n.setXYZ(r,s[0],s[1],s[2])),n.needsUpdate=!0}}const sb=/swiftshader|llvmpipe|softpipe|software|basic render driver|lavapipe/i;function rb(i){return i!==null&&sb.test(i)}function ab(i,e){return 1-(1-i)**e}function ob(i,e){const t=rb(i),n=Number.isFinite(e)&&e>0?e:1;return{renderer:i,software:t,antialias:!t,pixelRatio:Math.min(n,t?1:2),reachLayers:t?1:2}}function lb(){const i=document.createElement("canvas"),e=i.getContext("webgl2")??i.getContext("webgl");if(e===null)return null;let t=e.getParameter(e.RENDERER);if(typeof t!="string"||t===""||/^webkit webgl$/i.test(t)){const n=e.getExtension("WEBGL_debug_renderer_info");n!==null&&(t=e.getParameter(n.UNMASKED_RENDERER_WEBGL))}return e.getExtension("WEBGL_lose_context")?.loseContext(),typeof t=="string"&&t!==""&&!/^webkit webgl$/i.test(t)?t:null}const om=15127459;function cb(i){const e=i/20,t=10**Math.floor(Math.log10(e)),n=e/t;return(n<1.5?1:n<3.5?2:5)*t}class fc{sprite;canvas=document.createElement("canvas");texture;text="";constructor(e,t){this.canvas.width=256,this.canvas.height=64,this.texture=new c_(this.canvas),this.sprite=new Dp(new Pp({map:this.texture,depthTest:!1,transparent:!0})),this.sprite.scale.set(4*t,t,1),this.set(e)}set(e){if(e===this.text)return;this.text=e;const t=this.canvas.getContext("2d");t!==null&&(t.clearRect(0,0,256,64),t.font="bold 44px system-ui, sans-serif",t.fillStyle=`#${om.toString(16)}`,t.textAlign="center",t.textBaseline="middle",t.fillText(e,128,32),this.texture.needsUpdate=!0)}}function Qd(i){const e=new Bt().setFromPoints(i);return new al(e,new gi({color:om}))}class hb{ruler=new Wi;protractor=new Wi;dial=new Wi;thetaLabel=new fc("",.1);built=-1;constructor(){this.ruler.visible=!1,this.protractor.visible=!1,this.protractor.add(this.dial,this.thetaLabel.sprite)}build(e){if(e===this.built)return;this.built=e;for(const l of[this.ruler,this.dial])for(const c of[...l.children])l.remove(c),(c instanceof sn||c instanceof al||c instanceof Dp)&&(c.geometry.dispose(),c.material.dispose());const t=cb(2*e),n=1.1*e,s=[new z(n,0,-e),new z(n,0,e)],r=Math.floor(e/t+1e-9);for(let l=-r;l<=r;l++){const c=l*t,h=l%5===0;if(s.push(new z(n,0,c),new z(n-(h?.08:.04)*e,0,c)),h){const u=new fc(`${+c.toPrecision(6)} m`,.07*e);u.sprite.position.set(n+.16*e,0,c),this.ruler.add(u.sprite)}}this.ruler.add(Qd(s));const a=.4*e,o=[];for(let l=0;l<360;l+=2){const c=l*Math.PI/180,h=(l+2)*Math.PI/180;o.push(new z(a*Math.sin(c),0,-a*Math.cos(c)),new z(a*Math.sin(h),0,-a*Math.cos(h)))}for(let l=0;l<360;l+=10){const c=l*Math.PI/180,h=l%30===0?.85:.92;if(o.push(new z(a*Math.sin(c),0,-a*Math.cos(c)),new z(h*a*Math.sin(c),0,-h*a*Math.cos(c))),l%30===0&&l<=180){const u=new fc(`${l}°`,.06*e);u.sprite.position.set(1.2*a*Math.sin(c),0,-1.2*a*Math.cos(c)),this.dial.add(u.sprite)}}o.push(new z(0,0,-a),new z(0,0,a)),this.dial.add(Qd(o))}face(e){const t=this.ruler.position;this.ruler.rotation.set(0,0,Math.atan2(e.x-t.x,-(e.y-t.y)))}update(e,t,n,s,r,a){if(this.ruler.visible=s,this.protractor.visible=r,!s&&!r)return;this.build(n),this.ruler.position.copy(e),this.face(a),this.protractor.position.copy(e);const o=Math.atan2(t[1],t[0]),l=Math.atan2(Math.hypot(t[0],t[1]),-t[2]);this.dial.rotation.set(0,0,Number.isFinite(o)?o:0);const c=.55*n,h=l/2;this.thetaLabel.sprite.position.set(c*Math.sin(h)*Math.cos(o),c*Math.sin(h)*Math.sin(o),-c*Math.cos(h)),this.thetaLabel.sprite.scale.set(.4*n,.1*n,1),this.thetaLabel.set(`θ = ${(l*180/Math.PI).toFixed(1)}°`)}}class ub{constructor(e){this.renderer=e,this.stereo.aspect=1}renderer;stereo=new Hp;render(e,t,n,s,r){const a=this.renderer,o=a.getContext();t.focus=s,t.updateMatrixWorld(),this.stereo.eyeSep=n,this.stereo.update(t);const l=a.autoClear,c=e.background;a.autoClear=!1,e.background=null,a.setClearColor(r,1),a.clear();try{o.colorMask(!0,!1,!1,!0),a.render(e,this.stereo.cameraL),a.clearDepth(),o.colorMask(!1,!0,!0,!0),a.render(e,this.stereo.cameraR)}finally{o.colorMask(!0,!0,!0,!0),e.background=c,a.autoClear=l}}}function db(i,e,t,n=.9){const s=e*Math.PI/360,r=Math.atan(Math.tan(s)*Math.max(t,.001)),a=Math.min(s,r);return i/Math.sin(a*n)}function fb(i,e){const t=[],s=a=>{for(let o=0;o<96;o++)t.push(a(2*Math.PI*o/96),a(2*Math.PI*(o+1)/96))};for(let a=0;a<6;a++){const o=a*Math.PI/6;s(l=>new z(Math.sin(l)*Math.cos(o),Math.sin(l)*Math.sin(o),Math.cos(l)))}for(const a of[-.75,-.5,-.25,.25,.5,.75]){const o=Math.sqrt(1-a*a);s(l=>new z(o*Math.cos(l),o*Math.sin(l),a))}const r=new al(new Bt().setFromPoints(t),new gi({color:i,transparent:!0,opacity:e}));return r.visible=!1,r}function pb(i,e,t,n){const s=t.position.clone().sub(i).normalize(),r=new z().crossVectors(s,new z(0,0,1));r.lengthSq()<1e-12&&r.set(1,0,0),r.normalize();const a=new z().crossVectors(s,r).normalize(),o=t.position.distanceTo(i),l=e*Math.sqrt(Math.max(0,1-e*e/(o*o))),c=i.clone().addScaledVector(s,e*e/o),h=n.getBoundingClientRect(),u={left:1/0,right:-1/0,top:1/0,bottom:-1/0};for(let d=0;d<64;d++){const m=2*Math.PI*d/64,_=c.clone().addScaledVector(r,l*Math.cos(m)).addScaledVector(a,l*Math.sin(m)).project(t),M=h.left+(_.x+1)/2*h.width,p=h.top+(1-_.y)/2*h.height;u.left=Math.min(u.left,M),u.right=Math.max(u.right,M),u.top=Math.min(u.top,p),u.bottom=Math.max(u.bottom,p)}return u}const Ao=13170016,mb=new z(0,1,0);class gb{group=new Wi;bob;rod;pivotMark;trail;positions=new Float32Array(3*($s+1));tmpX=new z;tmpPivot=new z;tmpDir=new z;length=1;offset=new z;constructor(){this.bob=new sn(new os(1,24,16),new Or({color:Ao,roughness:.4})),this.rod=new sn(new Va(1,1,1,8),new Or({color:Ao,metalness:.3,roughness:.5}));const e=new Bt;e.setAttribute("position",new mi(this.positions,3)),e.setDrawRange(0,0),this.trail=new Ki(e,new gi({color:Ao,transparent:!0,opacity:.6})),this.trail.frustumCulled=!1,this.pivotMark=new sn(new os(1,12,8),new Or({color:Ao})),this.pivotMark.visible=!1,this.group.add(this.bob,this.rod,this.trail,this.pivotMark),this.group.visible=!1}setLength(e){this.length=e,this.bob.scale.setScalar(.045*e)}setOffset(e){e===null?this.offset.set(0,0,0):this.offset.fromArray(e),this.pivotMark.visible=e!==null,this.pivotMark.position.copy(this.offset),this.pivotMark.scale.setScalar(.03*this.length)}update(e,t){if(this.group.visible=e!==null,e===null)return;const n=this.tmpX.fromArray(e.x),s=this.tmpPivot.fromArray(e.pivot).add(this.offset);this.bob.position.copy(n).add(s);const r=n.length();r>0&&(this.rod.position.copy(n).multiplyScalar(.5).add(s),this.rod.quaternion.setFromUnitVectors(mb,this.tmpDir.copy(n).divideScalar(r)),this.rod.scale.set(.005*this.length,r,.005*this.length));const a=Math.max(0,Math.min(t.end-t.start,$s)),o=this.positions;for(let h=0;h<a;h++){const u=t.frames[t.end-a+h];o[3*h]=u.x[0]+u.pivot[0]+this.offset.x,o[3*h+1]=u.x[1]+u.pivot[1]+this.offset.y,o[3*h+2]=u.x[2]+u.pivot[2]+this.offset.z}const l=this.trail.geometry;l.setDrawRange(0,a);const c=l.getAttribute("position");c.clearUpdateRanges(),c.addUpdateRange(0,3*Math.max(a,1)),c.needsUpdate=!0}}const _b=16766720,vb=4e3;function xb(i,e=[0,0,0]){const t=i.filter(s=>s.every(Number.isFinite)).slice(0,vb),n=new Float32Array(3*t.length);return t.forEach((s,r)=>{n[3*r]=s[0]+e[0],n[3*r+1]=s[1]+e[1],n[3*r+2]=s[2]+e[2]}),n}function Sb(i,e){const t=e>1?i/(e-1):0,n=Math.max(t/3,1e-4);return{dash:n,gap:Math.max(2*n,1e-4)}}class Mb{line;material=new Op({color:_b,dashSize:.01,gapSize:.02});constructor(){this.line=new Ki(new Bt,this.material),this.line.frustumCulled=!1,this.line.visible=!1,this.line.name="measured-path"}set(e){this.line.geometry.dispose();const t=new Bt,n=xb(e??[]);t.setAttribute("position",new mi(n,3)),this.line.geometry=t;const s=n.length/3;if(this.line.visible=s>1,s<2)return;this.line.computeLineDistances();const r=t.getAttribute("lineDistance"),{dash:a,gap:o}=Sb(r.getX(s-1),s);this.material.dashSize=a,this.material.gapSize=o}get points(){return this.line.visible?this.line.geometry.getAttribute("position").count:0}}const yb=["off","anaglyph","side by side"],bb={trail:!0,trailSeconds:10,sphere:!0,axes:!0,velocity:!0,momentum:!1,gravity:!1,tension:!1,net:!1,angularMomentum:!1,torque:!1,originX:0,originY:0,originZ:0,stereo:"off",ruler:!1,protractor:!1},jh={velocity:14711807,momentum:10194175,gravity:16757575,tension:16735603,net:16777215,angularMomentum:5102016,torque:16769357},wb=["angularMomentum","torque"],pc=new ct(1119259),ef=.06,Eb=new ct(5882879),Tb=new z(0,1,0),Ab=.025,Rb=.06,Cb=.085,Pb={frames:[],start:0,end:0};function Lb(i){const e=new y_(new z(1,0,0),new z,1,i);return e.visible=!1,e}class Db{constructor(e,t){this.container=e,this.renderer=new tm({antialias:t.antialias}),this.renderer.setPixelRatio(t.pixelRatio),this.renderer.domElement.id="scene-canvas",e.appendChild(this.renderer.domElement),this.scene.background=pc,this.camera=new $n(40,1,.01,1e3),this.camera.up.set(0,0,1),this.controls=new im(this.camera,this.renderer.domElement),this.controls.enableDamping=!0,this.scene.add(new S_(16777215,.6));const n=new x_(16777215,1.6);n.position.set(2,-3,4),this.scene.add(n),this.sphere=new sn(new os(1,48,32),new Rs({color:9417727,transparent:!0,opacity:t.reachLayers===1?ab(ef,2):ef,depthWrite:!1,side:t.reachLayers===2?fi:Cs}));const s=new Bt().setFromPoints(Array.from({length:128},(a,o)=>{const l=2*Math.PI*o/128;return new z(Math.cos(l),Math.sin(l),0)}));this.equator=new l_(s,new gi({color:9417727,transparent:!0,opacity:.25})),this.pivot=new sn(new os(.02,16,12),new Or({color:13421772})),this.rod=new sn(new Va(1,1,1,12),new Or({color:14211288,metalness:.6,roughness:.3})),this.bob=new sn(new os(1,32,24),new Or({color:16747586,roughness:.35})),this.axes=new Gp(1.3),this.handle=new sn(new os(1,16,12),new Rs({color:15911167})),this.handle.name="velocity handle",this.handle.visible=!1,this.trailPositions=new Float32Array(3*($s+1)),this.trailColors=new Float32Array(3*($s+1));const r=new Bt;r.setAttribute("position",new mi(this.trailPositions,3)),r.setAttribute("color",new mi(this.trailColors,3)),r.setDrawRange(0,0),this.trail=new Ki(r,new gi({vertexColors:!0})),this.trail.frustumCulled=!1,this.boom=new Ki(new Bt().setFromPoints([new z,new z]),new gi({color:10134712})),this.boom.visible=!1,this.boom.frustumCulled=!1,this.scene.add(this.sphere,this.equator,this.reachLines,this.pivot,this.rod,this.bob,this.axes,this.trail,this.tether.group,this.handle,this.boom,this.twin.group,this.measured.line,this.instruments.ruler,this.instruments.protractor,...Object.values(this.arrows)),this.setLength(1),this.resetCamera(),new ResizeObserver(()=>this.resize()).observe(e),this.resize()}container;renderer;camera;controls;scene=new Ap;sphere;equator;reachLines=fb(9417727,.18);rod;bob;pivot;axes;trail;trailPositions;trailColors;trailColored=-1;tmpX=new z;tmpBob=new z;tmpDir=new z;tmpVec=new z;tmpOrigin=new z;arrows=Object.fromEntries(Object.entries(jh).map(([e,t])=>[e,Lb(t)]));length=1;extent=1;stereo="off";anaglyph=null;instruments=new hb;boom;twin=new gb;measured=new Mb;follow=!1;followAt=null;reach=1;twinLayoutKey="";twinLayout=null;sideBySide=null;drag=null;pull=null;handle;drawn=null;velocityScale=dc(1,1,9.81).velocity;gNow=9.81;tmpHandle=new z;pivotNow=new z;topView=!1;tether=new ib;model="ideal";invalid=!0;setLength(e){if(!(e>0))return;const t=Math.abs(e-this.length)>1e-12*e;this.length=e,t&&(this.extent=this.reach=e),this.sphere.scale.setScalar(e),this.equator.scale.setScalar(e),this.reachLines.scale.setScalar(e),this.pivot.scale.setScalar(e),this.bob.scale.setScalar(.05*e),this.twin.setLength(this.twinLayout?.length??e),this.handle.scale.setScalar(Ab*e),this.axes.scale.setScalar(e),t&&this.resetCamera(),this.invalid=!0}fit(e){Math.abs(e-this.extent)<=.2*this.extent||(this.extent=e,this.resetCamera())}resetCamera(){const e=this.twinLayout,t=e===null?0:.5*Math.hypot(...e.offset),n=e===null?this.extent:t+Math.max(this.extent,e.length),s=1.1*n,r=this.stereo==="side by side"?this.camera.aspect/2:this.camera.aspect,a=db(s,this.camera.fov,r),o=this.follow&&this.followAt!==null?this.followAt.clone():new z;e!==null&&o.add(new z(...e.offset).multiplyScalar(.5)),this.topView?this.camera.position.set(0,-1e-4*a,a).add(o):this.camera.position.set(3.3,-3.9,1.5).normalize().multiplyScalar(a).add(o),this.controls.target.copy(o),this.camera.near=.01*this.length,this.camera.far=100*n,this.camera.updateProjectionMatrix(),this.controls.update(),this.invalid=!0}setModel(e){e!==this.model&&(this.invalid=!0,this.model=e,this.follow=e==="slewing",this.followAt=null,this.extent=this.reach=this.length,this.resetCamera())}setTopView(e){this.topView=e,this.resetCamera()}enableDrag(e,t){const n=this.renderer.domElement;this.pull=new Fy(n,this.camera,this.controls,this.handle,this.bob,()=>Rb*this.length,()=>this.pullBasis(),t),this.drag=new Uy(n,this.camera,this.controls,this.bob,e,()=>({pivot:this.pivotNow,length:this.length}))}pullBasis(){const e=this.drawn;return e===null?null:{pivot:[...e.pivot],x:[...e.x],arrowScale:this.velocityScale,vmax:Ly(this.length,this.gNow)}}onScreen(e){if(!e.visible)return null;const t=e.position.clone().project(this.camera),n=this.renderer.domElement.getBoundingClientRect();return{x:n.left+(t.x+1)/2*n.width,y:n.top+(1-t.y)/2*n.height}}bobOnScreen(){return this.onScreen(this.bob)}handleOnScreen(){return this.onScreen(this.handle)}setStereo(e){this.stereo=e,e==="anaglyph"&&this.anaglyph===null&&(this.anaglyph=new ub(this.renderer)),e==="side by side"&&this.sideBySide===null&&(this.sideBySide=new Py(this.renderer)),this.resize(),this.resetCamera()}resize(){const e=Math.max(1,this.container.clientWidth),t=Math.max(1,this.container.clientHeight);this.renderer.setSize(e,t,!1),this.stereo==="side by side"&&this.sideBySide?.setSize(e,t),this.renderer.domElement.style.width="",this.renderer.domElement.style.height="",this.camera.aspect=e/t,this.camera.updateProjectionMatrix(),this.resetCamera(),this.invalid=!0}update(e,t,n,s,r,a){const o=this.stereo==="anaglyph";this.sphere.visible=n.sphere&&!o,this.reachLines.visible=n.sphere&&o,this.equator.visible=n.sphere,this.axes.visible=n.axes;const l=e!==null,c=Zf(this.model,e?.taut??!0);if(this.rod.visible=l&&(c==="rod"||c==="taut string"),this.bob.visible=l,this.drawn=e,this.gNow=r,this.velocityScale=dc(this.length,s,r).velocity,this.handle.visible=l&&n.velocity,e===null){this.tether.update("rod",[0,0,0],[0,0,0],this.length,a),this.trail.geometry.setDrawRange(0,0);for(const R of Object.values(this.arrows))R.visible=!1;return}const h=this.pivotNow.fromArray(e.pivot);this.followPivot(h),this.reach=Math.max(this.reach,Math.hypot(...e.x)),this.fit(this.reach+(this.follow?0:h.length())),this.instruments.update(h,e.x,this.length,n.ruler,n.protractor,this.camera.position);const u=Math.hypot(h.x,h.y);if(this.boom.visible=u>1e-9*this.length,this.boom.visible){const R=this.boom.geometry.getAttribute("position");R.setXYZ(0,0,0,h.z),R.setXYZ(1,h.x,h.y,h.z),R.needsUpdate=!0}for(const R of[this.sphere,this.equator,this.reachLines,this.pivot])R.position.copy(h);const d=this.tmpX.fromArray(e.x),m=d.length(),_=this.tmpBob.copy(d).add(h);if(this.bob.position.copy(_),m>0){this.rod.position.copy(d).multiplyScalar(.5).add(h),this.rod.quaternion.setFromUnitVectors(Tb,this.tmpDir.copy(d).divideScalar(m));const R=c==="taut string"?.003:.008;this.rod.scale.set(R*this.length,m,R*this.length)}const M=r<0?[-a[0],-a[1],-a[2]]:a;if(this.tether.update(c,e.x,e.pivot,this.length,M),this.updateTrail(n.trail?t:Pb,e),this.handle.visible){const R=Ny(e.x,e.v,this.velocityScale,Cb*this.length);this.handle.position.copy(this.tmpHandle.fromArray(R).add(_))}const p=Object.keys(this.arrows);if(!p.some(R=>n[R])){for(const R of p)this.arrows[R].visible=!1;return}const f=[n.originX,n.originY,n.originZ],x=Qy(e,s,r,a,f),A=dc(this.length,s,r),S=this.tmpOrigin.fromArray(f).add(h);for(const R of p){const y=wb.includes(R)?S:_,g=this.tmpVec.fromArray(x[R]).multiplyScalar(A[R]);this.setArrow(this.arrows[R],n[R],y,g)}}followPivot(e){if(!this.follow)return;if(this.followAt===null){this.followAt=e.clone(),this.resetCamera();return}const t=this.tmpVec.copy(e).sub(this.followAt);t.lengthSq()!==0&&(this.camera.position.add(t),this.controls.target.add(t),this.followAt.copy(e))}setTwinLayout(e){const t=e===null?"":`${e.offset.join(",")}|${e.length}`;t!==this.twinLayoutKey&&(this.twinLayoutKey=t,this.twinLayout=e,this.twin.setLength(e?.length??this.length),this.twin.setOffset(e?.offset??null),this.resetCamera())}updateTwin(e,t){this.twin.update(e,t),this.invalid=!0}setMeasured(e){this.measured.set(e),this.invalid=!0}measuredPoints(){return this.measured.points}sphereOnScreen(){return pb(this.sphere.position,this.sphere.scale.x,this.camera,this.renderer.domElement)}twinOnScreen(){return this.twin.group.visible?this.onScreen(this.twin.bob):null}setArrow(e,t,n,s){const r=s.length();if(e.visible=t&&r>1e-6*this.length,!e.visible)return;e.position.copy(n),e.setDirection(s.divideScalar(r));const a=Math.min(.25*r,.08*this.length);e.setLength(r,a,.5*a)}updateTrail(e,t){const n=Math.min(e.end-e.start,$s),s=this.trail.geometry;if(n<=0){s.setDrawRange(0,0);return}const r=e.end-n,a=this.trailPositions,o=n+1;for(let c=0;c<o;c++){const h=c<n?e.frames[r+c]:t;a[3*c]=h.x[0]+h.pivot[0],a[3*c+1]=h.x[1]+h.pivot[1],a[3*c+2]=h.x[2]+h.pivot[2]}s.setDrawRange(0,o);const l=s.getAttribute("position");if(l.clearUpdateRanges(),l.addUpdateRange(0,3*o),l.needsUpdate=!0,o!==this.trailColored){this.trailColored=o;const c=this.trailColors,h=new ct;for(let d=0;d<o;d++)h.copy(pc).lerp(Eb,(d+1)/o),c[3*d]=h.r,c[3*d+1]=h.g,c[3*d+2]=h.b;const u=s.getAttribute("color");u.clearUpdateRanges(),u.addUpdateRange(0,3*o),u.needsUpdate=!0}}draw(e){const t=this.controls.update();return t&&this.instruments.ruler.visible&&this.instruments.face(this.camera.position),!e&&!t&&!this.invalid?!1:(this.invalid=!1,this.render(),!0)}render(){const e=this.camera.position.distanceTo(this.controls.target);this.stereo==="anaglyph"&&this.anaglyph!==null?this.anaglyph.render(this.scene,this.camera,e/30,e,pc):this.stereo==="side by side"&&this.sideBySide!==null?(this.camera.focus=e,this.sideBySide.setEyeSeparation(e/30),this.sideBySide.render(this.scene,this.camera)):this.renderer.render(this.scene,this.camera)}screenshot(){return this.render(),this.renderer.domElement.toDataURL("image/png")}}const Nb={velocity:["vec.velocity","vec.velocityHelp"],momentum:["vec.momentum","vec.momentumHelp"],gravity:["vec.gravity","vec.gravityHelp"],tension:["vec.tension","vec.tensionHelp"],net:["vec.net","vec.netHelp"],angularMomentum:["vec.angularMomentum","vec.angularMomentumHelp"],torque:["vec.torque","vec.torqueHelp"]};function Ib(i,e,t,n){const s=i.addFolder(N("gui.view"));s.add(e,"trail").name(N("gui.trail")).onChange(t),s.add(e,"trailSeconds",1,120,1).name(N("gui.trailSeconds")).onChange(t),s.add(e,"sphere").name(N("gui.sphere")).onChange(t),s.add(e,"axes").name(N("gui.axes")).onChange(t);const r={topView:!1};s.add(r,"topView").name(N("gui.topView")).onChange(h=>{n(h),t()});const a={off:"stereo.off",anaglyph:"stereo.anaglyph","side by side":"stereo.sideBySide"},o=Object.fromEntries(yb.map(h=>[a[h]?N(a[h]):h,h])),l=s.add(e,"stereo",o).name(N("gui.stereo")).onChange(t);l.domElement.title=N("gui.stereoHelp"),l.domElement.dataset.control="stereo",s.close();const c=i.addFolder(N("gui.vectors"));for(const[h,[u,d]]of Object.entries(Nb)){const m=c.add(e,h).name(N(u)).onChange(t);m.domElement.title=N(d),m.domElement.dataset.vector=h,m.$name.style.borderLeft=`10px solid #${jh[h].toString(16).padStart(6,"0")}`,m.$name.style.paddingLeft="4px"}for(const h of["X","Y","Z"]){const u=`origin${h}`;c.add(e,u,-5,5,.01).name(N("gui.origin",{axis:h.toLowerCase()})).onChange(t).domElement.title=N("gui.originHelp")}return c.close(),s}class Ub{constructor(e,t,n,s,r){this.view=s,this.gui=new Oh({container:e,title:N("gui.title"),width:270});const a={};this.model=a;const o=this.gui.addFolder(N("gui.pendulum")),l=kh((y,g)=>{r.send({type:"set_params",[y]:g})},50);for(const y of t.model.params){const g=b=>l(y.name,b);this.synced.push(Qf(o,a,y,g,r.explain))}this.modelControls=new Qg(o,t,r);const c=this.gui.addFolder(N("gui.integrator")).close(),h={};for(const y of t.methods)h[Go(y.name,y.order)]=y.name;a.method=t.methods.find(y=>y.default)?.name??t.methods[0]?.name??"rattle";const u=c.add(a,"method",h).name(N("gui.method")).onChange(y=>r.send({type:"set_method",method:y}));u.domElement.title=t.methods.map(y=>`${Go(y.name,y.order)} — ${y.name}: ${y.summary}`).join(`
`),this.synced.push(u);const d=t.controls.dt;a.dt=d.default??.001;const m=c.add(a,"dt").name("dt [s]").decimals(6).onFinishChange(y=>{if(!(y>=d.min&&y<=d.max)){r.explain(N("gui.dtRange",{min:d.min,max:d.max}));return}r.send({type:"set_method",dt:y})});m.domElement.title=N("gui.dtHelp",{min:d.min,max:d.max}),this.synced.push(m);const _=this.gui.addFolder(N("gui.run")),M=t.controls.time_scale;a.time_scale=M.default??1;const p=_.add(a,"time_scale").name(N("gui.timeScale")).decimals(3).onFinishChange(y=>{if(!(y>=M.min&&y<=M.max)){r.explain(N("gui.tsRange",{min:M.min,max:M.max}));return}r.send({type:"set_time_scale",time_scale:y})});p.domElement.title=N("gui.tsHelp",{min:M.min,max:M.max}),this.synced.push(p),a.paused=!1,a.run=()=>r.send({type:a.paused===!0?"resume":"pause"}),this.runButton=_.add(a,"run").name(N("toolbar.pause")),a.stepN=1;const f=t.controls.step_n;_.add(a,"stepN",f.min,Math.min(f.max,1e3),1).name(N("gui.stepN")),a.step=()=>r.send({type:"step",n:Math.round(Number(a.stepN))}),_.add(a,"step").name(N("toolbar.step")),a.reset=()=>r.send({type:"reset"}),_.add(a,"reset").name(N("toolbar.reset"));const x={};for(const y of n)y.error===void 0&&(x[y.title?`${y.title}`:y.name]=y.name);a.scenario="";const A=_.add(a,"scenario",x).name(N("gui.scenario")).onChange(y=>r.send({type:"load_scenario",name:y}));A.domElement.title=n.filter(y=>y.error===void 0).map(y=>`${y.name}: ${y.title??""}`).join(`
`),this.synced.push(A),Ib(this.gui,s,()=>r.viewChanged(this.view,this.topView),y=>{this.topView=y});const S=this.gui.addFolder(N("gui.export")).close();a.csv=()=>r.downloadCSV(),S.add(a,"csv").name(N("gui.csv")),a.toml=()=>r.downloadTOML();const R=S.add(a,"toml").name(N("gui.toml"));R.domElement.dataset.control="toml",R.domElement.title=N("gui.tomlHelp"),a.png=()=>r.screenshot(),S.add(a,"png").name(N("gui.png")),a.link=()=>r.copyLink(),S.add(a,"link").name(N("gui.link"))}view;gui;model;synced=[];runButton;modelControls;topView=!1;sync(e){const t=this.model;t.length=e.params.length,t.mass=e.params.mass,t.g=e.params.g,t.method=e.method,t.dt=e.dt,t.time_scale=e.time_scale,t.paused=e.paused,t.scenario=e.scenario??"";for(const n of this.synced)n.domElement.contains(document.activeElement)||n.updateDisplay();this.runButton.name(e.paused?N("toolbar.start"):N("toolbar.pause")),this.modelControls.sync(e)}}const Fb=!0,bn="u-",Ob="uplot",kb=bn+"hz",Bb=bn+"vt",zb=bn+"title",Hb=bn+"wrap",Vb=bn+"under",Gb=bn+"over",Wb=bn+"axis",Xs=bn+"off",Xb=bn+"select",$b=bn+"cursor-x",qb=bn+"cursor-y",Yb=bn+"cursor-pt",Kb=bn+"legend",Zb=bn+"live",Jb=bn+"inline",jb=bn+"series",Qb=bn+"marker",tf=bn+"label",ew=bn+"value",xa="width",Sa="height",pa="top",nf="bottom",Rr="left",mc="right",Qh="#000",sf=Qh+"0",gc="mousemove",rf="mousedown",_c="mouseup",af="mouseenter",of="mouseleave",lf="dblclick",tw="resize",nw="scroll",cf="change",el="dppxchange",eu="--",Yr=typeof window<"u",xh=Yr?document:null,kr=Yr?window:null,iw=Yr?navigator:null;let Et,Ro;function Sh(){let i=devicePixelRatio;Et!=i&&(Et=i,Ro&&yh(cf,Ro,Sh),Ro=matchMedia(`(min-resolution: ${Et-.001}dppx) and (max-resolution: ${Et+.001}dppx)`),qs(cf,Ro,Sh),kr.dispatchEvent(new CustomEvent(el)))}function ti(i,e){if(e!=null){let t=i.classList;!t.contains(e)&&t.add(e)}}function Mh(i,e){let t=i.classList;t.contains(e)&&t.remove(e)}function Wt(i,e,t){i.style[e]=t+"px"}function wi(i,e,t,n){let s=xh.createElement(i);return e!=null&&ti(s,e),t?.insertBefore(s,n),s}function ci(i,e){return wi("div",i,e)}const hf=new WeakMap;function Bi(i,e,t,n,s){let r="translate("+e+"px,"+t+"px)",a=hf.get(i);r!=a&&(i.style.transform=r,hf.set(i,r),e<0||t<0||e>n||t>s?ti(i,Xs):Mh(i,Xs))}const uf=new WeakMap;function df(i,e,t){let n=e+t,s=uf.get(i);n!=s&&(uf.set(i,n),i.style.background=e,i.style.borderColor=t)}const ff=new WeakMap;function pf(i,e,t,n){let s=e+""+t,r=ff.get(i);s!=r&&(ff.set(i,s),i.style.height=t+"px",i.style.width=e+"px",i.style.marginLeft=n?-e/2+"px":0,i.style.marginTop=n?-t/2+"px":0)}const tu={passive:!0},sw={...tu,capture:!0};function qs(i,e,t,n){e.addEventListener(i,t,n?sw:tu)}function yh(i,e,t,n){e.removeEventListener(i,t,tu)}Yr&&Sh();function Ei(i,e,t,n){let s;t=t||0,n=n||e.length-1;let r=n<=2147483647;for(;n-t>1;)s=r?t+n>>1:ii((t+n)/2),e[s]<i?t=s:n=s;return i-e[t]<=e[n]-i?t:n}function lm(i){return(t,n,s)=>{let r=-1,a=-1;for(let o=n;o<=s;o++)if(i(t[o])){r=o;break}for(let o=s;o>=n;o--)if(i(t[o])){a=o;break}return[r,a]}}const cm=i=>i!=null,hm=i=>i!=null&&i>0,hl=lm(cm),rw=lm(hm);function aw(i,e,t,n=0,s=!1){let r=s?rw:hl,a=s?hm:cm;[e,t]=r(i,e,t);let o=i[e],l=i[e];if(e>-1)if(n==1)o=i[e],l=i[t];else if(n==-1)o=i[t],l=i[e];else for(let c=e;c<=t;c++){let h=i[c];a(h)&&(h<o?o=h:h>l&&(l=h))}return[o??Ft,l??-Ft]}function ul(i,e,t,n){let s=_f(i),r=_f(e);i==e&&(s==-1?(i*=t,e/=t):(i/=t,e*=t));let a=t==10?hs:um,o=s==1?ii:ui,l=r==1?ui:ii,c=o(a(xn(i))),h=l(a(xn(e))),u=Gr(t,c),d=Gr(t,h);return t==10&&(c<0&&(u=Ot(u,-c)),h<0&&(d=Ot(d,-h))),n||t==2?(i=u*s,e=d*r):(i=mm(i,u),e=dl(e,d)),[i,e]}function nu(i,e,t,n){let s=ul(i,e,t,n);return i==0&&(s[0]=0),e==0&&(s[1]=0),s}const iu=.1,mf={mode:3,pad:iu},wa={pad:0,soft:null,mode:0},ow={min:wa,max:wa};function tl(i,e,t,n){return fl(t)?gf(i,e,t):(wa.pad=t,wa.soft=n?0:null,wa.mode=n?3:0,gf(i,e,ow))}function bt(i,e){return i??e}function lw(i,e,t){for(e=bt(e,0),t=bt(t,i.length-1);e<=t;){if(i[e]!=null)return!0;e++}return!1}function gf(i,e,t){let n=t.min,s=t.max,r=bt(n.pad,0),a=bt(s.pad,0),o=bt(n.hard,-Ft),l=bt(s.hard,Ft),c=bt(n.soft,Ft),h=bt(s.soft,-Ft),u=bt(n.mode,0),d=bt(s.mode,0),m=e-i,_=hs(m),M=Wn(xn(i),xn(e)),p=hs(M),f=xn(p-_);(m<1e-24||f>10)&&(m=0,(i==0||e==0)&&(m=1e-24,u==2&&c!=Ft&&(r=0),d==2&&h!=-Ft&&(a=0)));let x=m||M||1e3,A=hs(x),S=Gr(10,ii(A)),R=x*(m==0?i==0?.1:1:r),y=Ot(mm(i-R,S/10),24),g=i>=c&&(u==1||u==3&&y<=c||u==2&&y>=c)?c:Ft,b=Wn(o,y<g&&i>=g?g:Ai(g,y)),k=x*(m==0?e==0?.1:1:a),I=Ot(dl(e+k,S/10),24),L=e<=h&&(d==1||d==3&&I>=h||d==2&&I<=h)?h:-Ft,G=Ai(l,I>L&&e<=L?L:Wn(L,I));return b==G&&b==0&&(G=100),[b,G]}const cw=new Intl.NumberFormat(Yr?iw.language:"en-US"),su=i=>cw.format(i),si=Math,Vo=si.PI,xn=si.abs,ii=si.floor,vn=si.round,ui=si.ceil,Ai=si.min,Wn=si.max,Gr=si.pow,_f=si.sign,hs=si.log10,um=si.log2,hw=(i,e=1)=>si.sinh(i)*e,vc=(i,e=1)=>si.asinh(i/e),Ft=1/0;function vf(i){return(hs((i^i>>31)-(i>>31))|0)+1}function bh(i,e,t){return Ai(Wn(i,e),t)}function dm(i){return typeof i=="function"}function vt(i){return dm(i)?i:()=>i}const uw=()=>{},fm=i=>i,pm=(i,e)=>e,dw=i=>null,xf=i=>!0,Sf=(i,e)=>i==e,fw=/\.\d*?(?=9{6,}|0{6,})/gm,Js=i=>{if(_m(i)||Ns.has(i))return i;const e=`${i}`,t=e.match(fw);if(t==null)return i;let n=t[0].length-1;if(e.indexOf("e-")!=-1){let[s,r]=e.split("e");return+`${Js(s)}e${r}`}return Ot(i,n)};function Gs(i,e){return Js(Ot(Js(i/e))*e)}function dl(i,e){return Js(ui(Js(i/e))*e)}function mm(i,e){return Js(ii(Js(i/e))*e)}function Ot(i,e=0){if(_m(i))return i;let t=10**e,n=i*t*(1+Number.EPSILON);return vn(n)/t}const Ns=new Map;function gm(i){return((""+i).split(".")[1]||"").length}function Fa(i,e,t,n){let s=[],r=n.map(gm);for(let a=e;a<t;a++){let o=xn(a),l=Ot(Gr(i,a),o);for(let c=0;c<n.length;c++){let h=i==10?+`${n[c]}e${a}`:n[c]*l,u=(a>=0?0:o)+(a>=r[c]?0:r[c]),d=i==10?h:Ot(h,u);s.push(d),Ns.set(d,u)}}return s}const Ea={},ru=[],Wr=[null,null],ws=Array.isArray,_m=Number.isInteger,pw=i=>i===void 0;function Mf(i){return typeof i=="string"}function fl(i){let e=!1;if(i!=null){let t=i.constructor;e=t==null||t==Object}return e}function mw(i){return i!=null&&typeof i=="object"}const gw=Object.getPrototypeOf(Uint8Array),vm="__proto__";function Xr(i,e=fl){let t;if(ws(i)){let n=i.find(s=>s!=null);if(ws(n)||e(n)){t=Array(i.length);for(let s=0;s<i.length;s++)t[s]=Xr(i[s],e)}else t=i.slice()}else if(i instanceof gw)t=i.slice();else if(e(i)){t={};for(let n in i)n!=vm&&(t[n]=Xr(i[n],e))}else t=i;return t}function fn(i){let e=arguments;for(let t=1;t<e.length;t++){let n=e[t];for(let s in n)s!=vm&&(fl(i[s])?fn(i[s],Xr(n[s])):i[s]=Xr(n[s]))}return i}const _w=0,vw=1,xw=2;function Sw(i,e,t){for(let n=0,s,r=-1;n<e.length;n++){let a=e[n];if(a>r){for(s=a-1;s>=0&&i[s]==null;)i[s--]=null;for(s=a+1;s<t&&i[s]==null;)i[r=s++]=null}}}function Mw(i,e){if(ww(i)){let a=i[0].slice();for(let o=1;o<i.length;o++)a.push(...i[o].slice(1));return Ew(a[0])||(a=bw(a)),a}let t=new Set;for(let a=0;a<i.length;a++){let l=i[a][0],c=l.length;for(let h=0;h<c;h++)t.add(l[h])}let n=[Array.from(t).sort((a,o)=>a-o)],s=n[0].length,r=new Map;for(let a=0;a<s;a++)r.set(n[0][a],a);for(let a=0;a<i.length;a++){let o=i[a],l=o[0];for(let c=1;c<o.length;c++){let h=o[c],u=Array(s).fill(void 0),d=e?e[a][c]:vw,m=[];for(let _=0;_<h.length;_++){let M=h[_],p=r.get(l[_]);M===null?d!=_w&&(u[p]=M,d==xw&&m.push(p)):u[p]=M}Sw(u,m,s),n.push(u)}}return n}const yw=typeof queueMicrotask>"u"?i=>Promise.resolve().then(i):queueMicrotask;function bw(i){let e=i[0],t=e.length,n=Array(t);for(let r=0;r<n.length;r++)n[r]=r;n.sort((r,a)=>e[r]-e[a]);let s=[];for(let r=0;r<i.length;r++){let a=i[r],o=Array(t);for(let l=0;l<t;l++)o[l]=a[n[l]];s.push(o)}return s}function ww(i){let e=i[0][0],t=e.length;for(let n=1;n<i.length;n++){let s=i[n][0];if(s.length!=t)return!1;if(s!=e){for(let r=0;r<t;r++)if(s[r]!=e[r])return!1}}return!0}function Ew(i,e=100){const t=i.length;if(t<=1)return!0;let n=0,s=t-1;for(;n<=s&&i[n]==null;)n++;for(;s>=n&&i[s]==null;)s--;if(s<=n)return!0;const r=Wn(1,ii((s-n+1)/e));for(let a=i[n],o=n+r;o<=s;o+=r){const l=i[o];if(l!=null){if(l<=a)return!1;a=l}}return!0}const xm=["January","February","March","April","May","June","July","August","September","October","November","December"],Sm=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function Mm(i){return i.slice(0,3)}const Tw=Sm.map(Mm),Aw=xm.map(Mm),Rw={MMMM:xm,MMM:Aw,WWWW:Sm,WWW:Tw};function ma(i){return(i<10?"0":"")+i}function Cw(i){return(i<10?"00":i<100?"0":"")+i}const Pw={YYYY:i=>i.getFullYear(),YY:i=>(i.getFullYear()+"").slice(2),MMMM:(i,e)=>e.MMMM[i.getMonth()],MMM:(i,e)=>e.MMM[i.getMonth()],MM:i=>ma(i.getMonth()+1),M:i=>i.getMonth()+1,DD:i=>ma(i.getDate()),D:i=>i.getDate(),WWWW:(i,e)=>e.WWWW[i.getDay()],WWW:(i,e)=>e.WWW[i.getDay()],HH:i=>ma(i.getHours()),H:i=>i.getHours(),h:i=>{let e=i.getHours();return e==0?12:e>12?e-12:e},AA:i=>i.getHours()>=12?"PM":"AM",aa:i=>i.getHours()>=12?"pm":"am",a:i=>i.getHours()>=12?"p":"a",mm:i=>ma(i.getMinutes()),m:i=>i.getMinutes(),ss:i=>ma(i.getSeconds()),s:i=>i.getSeconds(),fff:i=>Cw(i.getMilliseconds())};function au(i,e){e=e||Rw;let t=[],n=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=n.exec(i);)t.push(s[0][0]=="{"?Pw[s[1]]:s[0]);return r=>{let a="";for(let o=0;o<t.length;o++)a+=typeof t[o]=="string"?t[o]:t[o](r,e);return a}}const Lw=new Intl.DateTimeFormat().resolvedOptions().timeZone;function Dw(i,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+i+i.getTimezoneOffset()*6e4):e==Lw?t=i:(t=new Date(i.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(i.getMilliseconds())),t}const ym=i=>i%1==0,nl=[1,2,2.5,5],Nw=Fa(10,-32,0,nl),bm=Fa(10,0,32,nl),Iw=bm.filter(ym),Ws=Nw.concat(bm),ou=`
`,wm="{YYYY}",yf=ou+wm,Em="{M}/{D}",Ma=ou+Em,Co=Ma+"/{YY}",Tm="{aa}",Uw="{h}:{mm}",Dr=Uw+Tm,bf=ou+Dr,wf=":{ss}",At=null;function Am(i){let e=i*1e3,t=e*60,n=t*60,s=n*24,r=s*30,a=s*365,l=(i==1?Fa(10,0,3,nl).filter(ym):Fa(10,-3,0,nl)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,n,n*2,n*3,n*4,n*6,n*8,n*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,a,a*2,a*5,a*10,a*25,a*50,a*100]);const c=[[a,wm,At,At,At,At,At,At,1],[s*28,"{MMM}",yf,At,At,At,At,At,1],[s,Em,yf,At,At,At,At,At,1],[n,"{h}"+Tm,Co,At,Ma,At,At,At,1],[t,Dr,Co,At,Ma,At,At,At,1],[e,wf,Co+" "+Dr,At,Ma+" "+Dr,At,bf,At,1],[i,wf+".{fff}",Co+" "+Dr,At,Ma+" "+Dr,At,bf,At,1]];function h(u){return(d,m,_,M,p,f)=>{let x=[],A=p>=a,S=p>=r&&p<a,R=u(_),y=Ot(R*i,3),g=xc(R.getFullYear(),A?0:R.getMonth(),S||A?1:R.getDate()),b=Ot(g*i,3);if(S||A){let k=S?p/r:0,I=A?p/a:0,L=y==b?y:Ot(xc(g.getFullYear()+I,g.getMonth()+k,1)*i,3),G=new Date(vn(L/i)),W=G.getFullYear(),U=G.getMonth();for(let X=0;L<=M;X++){let J=xc(W+I*X,U+k*X,1),H=J-u(Ot(J*i,3));L=Ot((+J+H)*i,3),L<=M&&x.push(L)}}else{let k=p>=s?s:p,I=ii(_)-ii(y),L=b+I+dl(y-b,k);x.push(L);let G=u(L),W=G.getHours()+G.getMinutes()/t+G.getSeconds()/n,U=p/n,X=d.axes[m]._space,J=f/X;for(;L=Ot(L+p,i==1?0:3),!(L>M);)if(U>1){let H=ii(Ot(W+U,6))%24,ee=u(L).getHours()-H;ee>1&&(ee=-1),L-=ee*n,W=(W+U)%24;let se=x[x.length-1];Ot((L-se)/p,3)*J>=.7&&x.push(L)}else x.push(L)}return x}}return[l,c,h]}const[Fw,Ow,kw]=Am(1),[Bw,zw,Hw]=Am(.001);Fa(2,-53,53,[1]);function Ef(i,e){return i.map(t=>t.map((n,s)=>s==0||s==8||n==null?n:e(s==1||t[8]==0?n:t[1]+n)))}function Tf(i,e){return(t,n,s,r,a)=>{let o=e.find(_=>a>=_[0])||e[e.length-1],l,c,h,u,d,m;return n.map(_=>{let M=i(_),p=M.getFullYear(),f=M.getMonth(),x=M.getDate(),A=M.getHours(),S=M.getMinutes(),R=M.getSeconds(),y=p!=l&&o[2]||f!=c&&o[3]||x!=h&&o[4]||A!=u&&o[5]||S!=d&&o[6]||R!=m&&o[7]||o[1];return l=p,c=f,h=x,u=A,d=S,m=R,y(M)})}}function Vw(i,e){let t=au(e);return(n,s,r,a,o)=>s.map(l=>t(i(l)))}function xc(i,e,t){return new Date(i,e,t)}function Af(i,e){return e(i)}const Gw="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function Rf(i,e){return(t,n,s,r)=>r==null?eu:e(i(n))}function Ww(i,e){let t=i.series[e];return t.width?t.stroke(i,e):t.points.width?t.points.stroke(i,e):null}function Xw(i,e){return i.series[e].fill(i,e)}const $w={show:!0,live:!0,isolate:!1,mount:uw,markers:{show:!0,width:2,stroke:Ww,fill:Xw,dash:"solid"},idx:null,idxs:null,values:[]};function qw(i,e){let t=i.cursor.points,n=ci(),s=t.size(i,e);Wt(n,xa,s),Wt(n,Sa,s);let r=s/-2;Wt(n,"marginLeft",r),Wt(n,"marginTop",r);let a=t.width(i,e,s);return a&&Wt(n,"borderWidth",a),n}function Yw(i,e){let t=i.series[e].points;return t._fill||t._stroke}function Kw(i,e){let t=i.series[e].points;return t._stroke||t._fill}function Zw(i,e){return i.series[e].points.size}const Sc=[0,0];function Jw(i,e,t){return Sc[0]=e,Sc[1]=t,Sc}function Po(i,e,t,n=!0){return s=>{s.button==0&&(!n||s.target==e)&&t(s)}}function Mc(i,e,t,n=!0){return s=>{(!n||s.target==e)&&t(s)}}const jw={show:!0,x:!0,y:!0,lock:!1,move:Jw,points:{one:!1,show:qw,size:Zw,width:0,stroke:Kw,fill:Yw},bind:{mousedown:Po,mouseup:Po,click:Po,dblclick:Po,mousemove:Mc,mouseleave:Mc,mouseenter:Mc},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(i,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(i,e,t,n,s)=>n-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},Rm={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},lu=fn({},Rm,{filter:pm}),Cm=fn({},lu,{size:10}),Pm=fn({},Rm,{show:!1}),cu='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',Lm="bold "+cu,Dm=1.5,Cf={show:!0,scale:"x",stroke:Qh,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Lm,side:2,grid:lu,ticks:Cm,border:Pm,font:cu,lineGap:Dm,rotate:0},Qw="Value",eE="Time",Pf={show:!0,scale:"x",auto:!1,sorted:1,min:Ft,max:-Ft,idxs:[]};function tE(i,e,t,n,s){return e.map(r=>r==null?"":su(r))}function nE(i,e,t,n,s,r,a){let o=[],l=Ns.get(s)||0;t=a?t:Ot(dl(t,s),l);for(let c=t;c<=n;c=Ot(c+s,l))o.push(Object.is(c,-0)?0:c);return o}function wh(i,e,t,n,s,r,a){const o=[],l=i.scales[i.axes[e].scale].log,c=l==10?hs:um,h=ii(c(t));s=Gr(l,h),l==10&&(s=Ws[Ei(s,Ws)]);let u=t,d=s*l;l==10&&(d=Ws[Ei(d,Ws)]);do o.push(u),u=u+s,l==10&&!Ns.has(u)&&(u=Ot(u,Ns.get(s))),u>=d&&(s=u,d=s*l,l==10&&(d=Ws[Ei(d,Ws)]));while(u<=n);return o}function iE(i,e,t,n,s,r,a){let l=i.scales[i.axes[e].scale].asinh,c=n>l?wh(i,e,Wn(l,t),n,s):[l],h=n>=0&&t<=0?[0]:[];return(t<-l?wh(i,e,Wn(l,-n),-t,s):[l]).reverse().map(d=>-d).concat(h,c)}const Nm=/./,sE=/[12357]/,rE=/[125]/,Lf=/1/,Eh=(i,e,t,n)=>i.map((s,r)=>e==4&&s==0||r%n==0&&t.test(s.toExponential()[s<0?1:0])?s:null);function aE(i,e,t,n,s){let r=i.axes[t],a=r.scale,o=i.scales[a],l=i.valToPos,c=r._space,h=l(10,a),u=l(9,a)-h>=c?Nm:l(7,a)-h>=c?sE:l(5,a)-h>=c?rE:Lf;if(u==Lf){let d=xn(l(1,a)-h);if(d<c)return Eh(e.slice().reverse(),o.distr,u,ui(c/d)).reverse()}return Eh(e,o.distr,u,1)}function oE(i,e,t,n,s){let r=i.axes[t],a=r.scale,o=r._space,l=i.valToPos,c=xn(l(1,a)-l(2,a));return c<o?Eh(e.slice().reverse(),3,Nm,ui(o/c)).reverse():e}function lE(i,e,t,n){return n==null?eu:e==null?"":su(e)}const Df={show:!0,scale:"y",stroke:Qh,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Lm,side:3,grid:lu,ticks:Cm,border:Pm,font:cu,lineGap:Dm,rotate:0};function cE(i,e){let t=3+(i||1)*2;return Ot(t*e,3)}function hE(i,e){let{scale:t,idxs:n}=i.series[0],s=i._data[0],r=i.valToPos(s[n[0]],t,!0),a=i.valToPos(s[n[1]],t,!0),o=xn(a-r),l=i.series[e],c=o/(l.points.space*Et);return n[1]-n[0]<=c}const Nf={scale:null,auto:!0,sorted:0,min:Ft,max:-Ft},Im=(i,e,t,n,s)=>s,If={show:!0,auto:!0,sorted:0,gaps:Im,alpha:1,facets:[fn({},Nf,{scale:"x"}),fn({},Nf,{scale:"y"})]},Uf={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:Im,alpha:1,points:{show:hE,filter:null},values:null,min:Ft,max:-Ft,idxs:[],path:null,clip:null};function uE(i,e,t,n,s){return t/10}const Um={time:Fb,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},dE=fn({},Um,{time:!1,ori:1}),Ff={};function Fm(i,e){let t=Ff[i];return t||(t={key:i,plots:[],sub(n){t.plots.push(n)},unsub(n){t.plots=t.plots.filter(s=>s!=n)},pub(n,s,r,a,o,l,c){for(let h=0;h<t.plots.length;h++)t.plots[h]!=s&&t.plots[h].pub(n,s,r,a,o,l,c)}},i!=null&&(Ff[i]=t)),t}const $r=1,Th=2;function er(i,e,t){const n=i.mode,s=i.series[e],r=n==2?i._data[e]:i._data,a=i.scales,o=i.bbox;let l=r[0],c=n==2?r[1]:r[e],h=n==2?a[s.facets[0].scale]:a[i.series[0].scale],u=n==2?a[s.facets[1].scale]:a[s.scale],d=o.left,m=o.top,_=o.width,M=o.height,p=i.valToPosH,f=i.valToPosV;return h.ori==0?t(s,l,c,h,u,p,f,d,m,_,M,ml,Kr,_l,km,zm):t(s,l,c,h,u,f,p,m,d,M,_,gl,Zr,du,Bm,Hm)}function hu(i,e){let t=0,n=0,s=bt(i.bands,ru);for(let r=0;r<s.length;r++){let a=s[r];a.series[0]==e?t=a.dir:a.series[1]==e&&(a.dir==1?n|=1:n|=2)}return[t,n==1?-1:n==2?1:n==3?2:0]}function fE(i,e,t,n,s){let r=i.mode,a=i.series[e],o=r==2?a.facets[1].scale:a.scale,l=i.scales[o];return s==-1?l.min:s==1?l.max:l.distr==3?l.dir==1?l.min:l.max:0}function us(i,e,t,n,s,r){return er(i,e,(a,o,l,c,h,u,d,m,_,M,p)=>{let f=a.pxRound;const x=c.dir*(c.ori==0?1:-1),A=c.ori==0?Kr:Zr;let S,R;x==1?(S=t,R=n):(S=n,R=t);let y=f(u(o[S],c,M,m)),g=f(d(l[S],h,p,_)),b=f(u(o[R],c,M,m)),k=f(d(r==1?h.max:h.min,h,p,_)),I=new Path2D(s);return A(I,b,k),A(I,y,k),A(I,y,g),I})}function pl(i,e,t,n,s,r){let a=null;if(i.length>0){a=new Path2D;const o=e==0?_l:du;let l=t;for(let u=0;u<i.length;u++){let d=i[u];if(d[1]>d[0]){let m=d[0]-l;m>0&&o(a,l,n,m,n+r),l=d[1]}}let c=t+s-l,h=10;c>0&&o(a,l,n-h/2,c,n+r+h)}return a}function pE(i,e,t){let n=i[i.length-1];n&&n[0]==e?n[1]=t:i.push([e,t])}function uu(i,e,t,n,s,r,a){let o=[],l=i.length;for(let c=s==1?t:n;c>=t&&c<=n;c+=s)if(e[c]===null){let u=c,d=c;if(s==1)for(;++c<=n&&e[c]===null;)d=c;else for(;--c>=t&&e[c]===null;)d=c;let m=r(i[u]),_=d==u?m:r(i[d]),M=u-s;m=a<=0&&M>=0&&M<l?r(i[M]):m;let f=d+s;_=a>=0&&f>=0&&f<l?r(i[f]):_,_>=m&&o.push([m,_])}return o}function Of(i){return i==0?fm:i==1?vn:e=>Gs(e,i)}function Om(i){let e=i==0?ml:gl,t=i==0?(s,r,a,o,l,c)=>{s.arcTo(r,a,o,l,c)}:(s,r,a,o,l,c)=>{s.arcTo(a,r,l,o,c)},n=i==0?(s,r,a,o,l)=>{s.rect(r,a,o,l)}:(s,r,a,o,l)=>{s.rect(a,r,l,o)};return(s,r,a,o,l,c=0,h=0)=>{c==0&&h==0?n(s,r,a,o,l):(c=Ai(c,o/2,l/2),h=Ai(h,o/2,l/2),e(s,r+c,a),t(s,r+o,a,r+o,a+l,c),t(s,r+o,a+l,r,a+l,h),t(s,r,a+l,r,a,h),t(s,r,a,r+o,a,c),s.closePath())}}const ml=(i,e,t)=>{i.moveTo(e,t)},gl=(i,e,t)=>{i.moveTo(t,e)},Kr=(i,e,t)=>{i.lineTo(e,t)},Zr=(i,e,t)=>{i.lineTo(t,e)},_l=Om(0),du=Om(1),km=(i,e,t,n,s,r)=>{i.arc(e,t,n,s,r)},Bm=(i,e,t,n,s,r)=>{i.arc(t,e,n,s,r)},zm=(i,e,t,n,s,r,a)=>{i.bezierCurveTo(e,t,n,s,r,a)},Hm=(i,e,t,n,s,r,a)=>{i.bezierCurveTo(t,e,s,n,a,r)};function Vm(i){return(e,t,n,s,r)=>er(e,t,(a,o,l,c,h,u,d,m,_,M,p)=>{let{pxRound:f,points:x}=a,A,S;c.ori==0?(A=ml,S=km):(A=gl,S=Bm);const R=Ot(x.width*Et,3);let y=(x.size-x.width)/2*Et,g=Ot(y*2,3),b=new Path2D,k=new Path2D,{left:I,top:L,width:G,height:W}=e.bbox;_l(k,I-g,L-g,G+g*2,W+g*2);const U=X=>{if(l[X]!=null){let J=f(u(o[X],c,M,m)),H=f(d(l[X],h,p,_));A(b,J+y,H),S(b,J,H,y,0,Vo*2)}};if(r)r.forEach(U);else for(let X=n;X<=s;X++)U(X);return{stroke:R>0?b:null,fill:b,clip:k,flags:$r|Th}})}function Gm(i){return(e,t,n,s,r,a)=>{n!=s&&(r!=n&&a!=n&&i(e,t,n),r!=s&&a!=s&&i(e,t,s),i(e,t,a))}}const mE=Gm(Kr),gE=Gm(Zr);function Wm(i){const e=bt(i?.alignGaps,0);return(t,n,s,r)=>er(t,n,(a,o,l,c,h,u,d,m,_,M,p)=>{[s,r]=hl(l,s,r);let f=a.pxRound,x=W=>f(u(W,c,M,m)),A=W=>f(d(W,h,p,_)),S,R;c.ori==0?(S=Kr,R=mE):(S=Zr,R=gE);const y=c.dir*(c.ori==0?1:-1),g={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:$r},b=g.stroke;let k=!1;if(r-s>=M*4){let W=fe=>t.posToVal(fe,c.key,!0),U=null,X=null,J,H,ce,Z=x(o[y==1?s:r]),ee=x(o[s]),se=x(o[r]),pe=W(y==1?ee+1:se-1);for(let fe=y==1?s:r;fe>=s&&fe<=r;fe+=y){let B=o[fe],he=(y==1?B<pe:B>pe)?Z:x(B),ge=l[fe];he==Z?ge!=null?(H=ge,U==null?(S(b,he,A(H)),J=U=X=H):H<U?U=H:H>X&&(X=H)):ge===null&&(k=!0):(U!=null&&R(b,Z,A(U),A(X),A(J),A(H)),ge!=null?(H=ge,S(b,he,A(H)),U=X=J=H):(U=X=null,ge===null&&(k=!0)),Z=he,pe=W(Z+y))}U!=null&&U!=X&&ce!=Z&&R(b,Z,A(U),A(X),A(J),A(H))}else for(let W=y==1?s:r;W>=s&&W<=r;W+=y){let U=l[W];U===null?k=!0:U!=null&&S(b,x(o[W]),A(U))}let[L,G]=hu(t,n);if(a.fill!=null||L!=0){let W=g.fill=new Path2D(b),U=a.fillTo(t,n,a.min,a.max,L),X=A(U),J=x(o[s]),H=x(o[r]);y==-1&&([H,J]=[J,H]),S(W,H,X),S(W,J,X)}if(!a.spanGaps){let W=[];k&&W.push(...uu(o,l,s,r,y,x,e)),g.gaps=W=a.gaps(t,n,s,r,W),g.clip=pl(W,c.ori,m,_,M,p)}return G!=0&&(g.band=G==2?[us(t,n,s,r,b,-1),us(t,n,s,r,b,1)]:us(t,n,s,r,b,G)),g})}function _E(i){const e=bt(i.align,1),t=bt(i.ascDesc,!1),n=bt(i.alignGaps,0),s=bt(i.extend,!1);return(r,a,o,l)=>er(r,a,(c,h,u,d,m,_,M,p,f,x,A)=>{[o,l]=hl(u,o,l);let S=c.pxRound,{left:R,width:y}=r.bbox,g=ee=>S(_(ee,d,x,p)),b=ee=>S(M(ee,m,A,f)),k=d.ori==0?Kr:Zr;const I={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:$r},L=I.stroke,G=d.dir*(d.ori==0?1:-1);let W=b(u[G==1?o:l]),U=g(h[G==1?o:l]),X=U,J=U;s&&e==-1&&(J=R,k(L,J,W)),k(L,U,W);for(let ee=G==1?o:l;ee>=o&&ee<=l;ee+=G){let se=u[ee];if(se==null)continue;let pe=g(h[ee]),fe=b(se);e==1?k(L,pe,W):k(L,X,fe),k(L,pe,fe),W=fe,X=pe}let H=X;s&&e==1&&(H=R+y,k(L,H,W));let[ce,Z]=hu(r,a);if(c.fill!=null||ce!=0){let ee=I.fill=new Path2D(L),se=c.fillTo(r,a,c.min,c.max,ce),pe=b(se);k(ee,H,pe),k(ee,J,pe)}if(!c.spanGaps){let ee=[];ee.push(...uu(h,u,o,l,G,g,n));let se=c.width*Et/2,pe=t||e==1?se:-se,fe=t||e==-1?-se:se;ee.forEach(B=>{B[0]+=pe,B[1]+=fe}),I.gaps=ee=c.gaps(r,a,o,l,ee),I.clip=pl(ee,d.ori,p,f,x,A)}return Z!=0&&(I.band=Z==2?[us(r,a,o,l,L,-1),us(r,a,o,l,L,1)]:us(r,a,o,l,L,Z)),I})}function kf(i,e,t,n,s,r,a=Ft){if(i.length>1){let o=null;for(let l=0,c=1/0;l<i.length;l++)if(e[l]!==void 0){if(o!=null){let h=xn(i[l]-i[o]);h<c&&(c=h,a=xn(t(i[l],n,s,r)-t(i[o],n,s,r)))}o=l}}return a}function vE(i){i=i||Ea;const e=bt(i.size,[.6,Ft,1]),t=i.align||0,n=i.gap||0;let s=i.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;const r=vt(s),a=1-e[0],o=bt(e[1],Ft),l=bt(e[2],1),c=bt(i.disp,Ea),h=bt(i.each,m=>{}),{fill:u,stroke:d}=c;return(m,_,M,p)=>er(m,_,(f,x,A,S,R,y,g,b,k,I,L)=>{let G=f.pxRound,W=t,U=n*Et,X=o*Et,J=l*Et,H,ce;S.ori==0?[H,ce]=r(m,_):[ce,H]=r(m,_);const Z=S.dir*(S.ori==0?1:-1);let ee=S.ori==0?_l:du,se=S.ori==0?h:(Ce,qe,st,we,Ut,He,$e)=>{h(Ce,qe,st,Ut,we,$e,He)},pe=bt(m.bands,ru).find(Ce=>Ce.series[0]==_),fe=pe!=null?pe.dir:0,B=f.fillTo(m,_,f.min,f.max,fe),te=G(g(B,R,L,k)),he,ge,ve,Ve=I,Qe=G(f.width*Et),ze=!1,nt=null,tt=null,Ye=null,It=null;u!=null&&(Qe==0||d!=null)&&(ze=!0,nt=u.values(m,_,M,p),tt=new Map,new Set(nt).forEach(Ce=>{Ce!=null&&tt.set(Ce,new Path2D)}),Qe>0&&(Ye=d.values(m,_,M,p),It=new Map,new Set(Ye).forEach(Ce=>{Ce!=null&&It.set(Ce,new Path2D)})));let{x0:gt,size:$t}=c;if(gt!=null&&$t!=null){W=1,x=gt.values(m,_,M,p),gt.unit==2&&(x=x.map(st=>m.posToVal(b+st*I,S.key,!0)));let Ce=$t.values(m,_,M,p);$t.unit==2?ge=Ce[0]*I:ge=y(Ce[0],S,I,b)-y(0,S,I,b),Ve=kf(x,A,y,S,I,b,Ve),ve=Ve-ge+U}else Ve=kf(x,A,y,S,I,b,Ve),ve=Ve*a+U,ge=Ve-ve;ve<1&&(ve=0),Qe>=ge/2&&(Qe=0),ve<5&&(G=fm);let Mt=ve>0,an=Ve-ve-(Mt?Qe:0);ge=G(bh(an,J,X)),he=(W==0?ge/2:W==Z?0:ge)-W*Z*((W==0?U/2:0)+(Mt?Qe/2:0));const dt={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},pn=ze?null:new Path2D;let Yt=null;if(pe!=null)Yt=m.data[pe.series[1]];else{let{y0:Ce,y1:qe}=c;Ce!=null&&qe!=null&&(A=qe.values(m,_,M,p),Yt=Ce.values(m,_,M,p))}let on=H*ge,O=ce*ge;for(let Ce=Z==1?M:p;Ce>=M&&Ce<=p;Ce+=Z){let qe=A[Ce];if(qe==null)continue;if(Yt!=null){let q=Yt[Ce]??0;if(qe-q==0)continue;te=g(q,R,L,k)}let st=S.distr!=2||c!=null?x[Ce]:Ce,we=y(st,S,I,b),Ut=g(bt(qe,B),R,L,k),He=G(we-he),$e=G(Wn(Ut,te)),C=G(Ai(Ut,te)),w=$e-C;if(qe!=null){let q=qe<0?O:on,de=qe<0?on:O;ze?(Qe>0&&Ye[Ce]!=null&&ee(It.get(Ye[Ce]),He,C+ii(Qe/2),ge,Wn(0,w-Qe),q,de),nt[Ce]!=null&&ee(tt.get(nt[Ce]),He,C+ii(Qe/2),ge,Wn(0,w-Qe),q,de)):ee(pn,He,C+ii(Qe/2),ge,Wn(0,w-Qe),q,de),se(m,_,Ce,He-Qe/2,C,ge+Qe,w)}}return Qe>0?dt.stroke=ze?It:pn:ze||(dt._fill=f.width==0?f._fill:f._stroke??f._fill,dt.width=0),dt.fill=ze?tt:pn,dt})}function xE(i,e){const t=bt(e?.alignGaps,0);return(n,s,r,a)=>er(n,s,(o,l,c,h,u,d,m,_,M,p,f)=>{[r,a]=hl(c,r,a);let x=o.pxRound,A=H=>x(d(H,h,p,_)),S=H=>x(m(H,u,f,M)),R,y,g;h.ori==0?(R=ml,g=Kr,y=zm):(R=gl,g=Zr,y=Hm);const b=h.dir*(h.ori==0?1:-1);let k=A(l[b==1?r:a]),I=k,L=[],G=[];for(let H=b==1?r:a;H>=r&&H<=a;H+=b)if(c[H]!=null){let Z=l[H],ee=A(Z);L.push(I=ee),G.push(S(c[H]))}const W={stroke:i(L,G,R,g,y,x),fill:null,clip:null,band:null,gaps:null,flags:$r},U=W.stroke;let[X,J]=hu(n,s);if(o.fill!=null||X!=0){let H=W.fill=new Path2D(U),ce=o.fillTo(n,s,o.min,o.max,X),Z=S(ce);g(H,I,Z),g(H,k,Z)}if(!o.spanGaps){let H=[];H.push(...uu(l,c,r,a,b,A,t)),W.gaps=H=o.gaps(n,s,r,a,H),W.clip=pl(H,h.ori,_,M,p,f)}return J!=0&&(W.band=J==2?[us(n,s,r,a,U,-1),us(n,s,r,a,U,1)]:us(n,s,r,a,U,J)),W})}function SE(i){return xE(ME,i)}function ME(i,e,t,n,s,r){const a=i.length;if(a<2)return null;const o=new Path2D;if(t(o,i[0],e[0]),a==2)n(o,i[1],e[1]);else{let l=Array(a),c=Array(a-1),h=Array(a-1),u=Array(a-1);for(let d=0;d<a-1;d++)h[d]=e[d+1]-e[d],u[d]=i[d+1]-i[d],c[d]=h[d]/u[d];l[0]=c[0];for(let d=1;d<a-1;d++)c[d]===0||c[d-1]===0||c[d-1]>0!=c[d]>0?l[d]=0:(l[d]=3*(u[d-1]+u[d])/((2*u[d]+u[d-1])/c[d-1]+(u[d]+2*u[d-1])/c[d]),isFinite(l[d])||(l[d]=0));l[a-1]=c[a-2];for(let d=0;d<a-1;d++)s(o,i[d]+u[d]/3,e[d]+l[d]*u[d]/3,i[d+1]-u[d]/3,e[d+1]-l[d+1]*u[d]/3,i[d+1],e[d+1])}return o}const Ah=new Set;function Bf(){for(let i of Ah)i.syncRect(!0)}Yr&&(qs(tw,kr,Bf),qs(nw,kr,Bf,!0),qs(el,kr,()=>{Un.pxRatio=Et}));const yE=Wm(),bE=Vm();function zf(i,e,t,n){return(n?[i[0],i[1]].concat(i.slice(2)):[i[0]].concat(i.slice(1))).map((r,a)=>Rh(r,a,e,t))}function wE(i,e){return i.map((t,n)=>n==0?{}:fn({},e,t))}function Rh(i,e,t,n){return fn({},e==0?t:n,i)}function Xm(i,e,t){return e==null?Wr:[e,t]}const EE=Xm;function TE(i,e,t){return e==null?Wr:tl(e,t,iu,!0)}function $m(i,e,t,n){return e==null?Wr:ul(e,t,i.scales[n].log,!1)}const AE=$m;function qm(i,e,t,n){return e==null?Wr:nu(e,t,i.scales[n].log,!1)}const RE=qm;function CE(i,e,t,n,s){let r=Wn(vf(i),vf(e)),a=e-i,o=Ei(s/n*a,t);do{let l=t[o],c=n*l/a;if(c>=s&&r+(l<5?Ns.get(l):0)<=17)return[l,c]}while(++o<t.length);return[0,0]}function Hf(i){let e,t;return i=i.replace(/(\d+)px/,(n,s)=>(e=vn((t=+s)*Et))+"px"),[i,e,t]}function PE(i){i.show&&[i.font,i.labelFont].forEach(e=>{let t=Ot(e[2]*Et,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function Un(i,e,t){const n={mode:bt(i.mode,1)},s=n.mode;function r(v,E,P,D){let $=E.valToPct(v);return D+P*(E.dir==-1?1-$:$)}function a(v,E,P,D){let $=E.valToPct(v);return D+P*(E.dir==-1?$:1-$)}function o(v,E,P,D){return E.ori==0?r(v,E,P,D):a(v,E,P,D)}n.valToPosH=r,n.valToPosV=a;let l=!1;n.status=0;const c=n.root=ci(Ob);if(i.id!=null&&(c.id=i.id),ti(c,i.class),i.title){let v=ci(zb,c);v.textContent=i.title}const h=wi("canvas"),u=n.ctx=h.getContext("2d"),d=ci(Hb,c);qs("click",d,v=>{v.target===_&&(Ht!=or||Xt!=lr)&&Cn.click(n,v)},!0);const m=n.under=ci(Vb,d);d.appendChild(h);const _=n.over=ci(Gb,d);i=Xr(i);const M=+bt(i.pxAlign,1),p=Of(M);(i.plugins||[]).forEach(v=>{v.opts&&(i=v.opts(n,i)||i)});const f=i.ms||.001,x=n.series=s==1?zf(i.series||[],Pf,Uf,!1):wE(i.series||[null],If),A=n.axes=zf(i.axes||[],Cf,Df,!0),S=n.scales={},R=n.bands=i.bands||[];R.forEach(v=>{v.fill=vt(v.fill||null),v.dir=bt(v.dir,-1)});const y=s==2?x[1].facets[0].scale:x[0].scale,g={axes:Qi,series:ut},b=(i.drawOrder||["axes","series"]).map(v=>g[v]);function k(v){const E=v.distr==3?P=>hs(P>0?P:v.clamp(n,P,v.min,v.max,v.key)):v.distr==4?P=>vc(P,v.asinh):v.distr==100?P=>v.fwd(P):P=>P;return P=>{let D=E(P),{_min:$,_max:j}=v,le=j-$;return(D-$)/le}}function I(v){let E=S[v];if(E==null){let P=(i.scales||Ea)[v]||Ea;if(P.from!=null){I(P.from);let D=fn({},S[P.from],P,{key:v});D.valToPct=k(D),S[v]=D}else{E=S[v]=fn({},v==y?Um:dE,P),E.key=v;let D=E.time,$=E.range,j=ws($);if((v!=y||s==2&&!D)&&(j&&($[0]==null||$[1]==null)&&($={min:$[0]==null?mf:{mode:1,hard:$[0],soft:$[0]},max:$[1]==null?mf:{mode:1,hard:$[1],soft:$[1]}},j=!1),!j&&fl($))){let le=$;$=(me,ye,Ne)=>ye==null?Wr:tl(ye,Ne,le)}E.range=vt($||(D?EE:v==y?E.distr==3?AE:E.distr==4?RE:Xm:E.distr==3?$m:E.distr==4?qm:TE)),E.auto=vt(j?!1:E.auto),E.clamp=vt(E.clamp||uE),E._min=E._max=null,E.valToPct=k(E)}}}I("x"),I("y"),s==1&&x.forEach(v=>{I(v.scale)}),A.forEach(v=>{I(v.scale)});for(let v in i.scales)I(v);const L=S[y],G=L.distr;let W,U;L.ori==0?(ti(c,kb),W=r,U=a):(ti(c,Bb),W=a,U=r);const X={};for(let v in S){let E=S[v];(E.min!=null||E.max!=null)&&(X[v]={min:E.min,max:E.max},E.min=E.max=null)}const J=i.tzDate||(v=>new Date(vn(v/f))),H=i.fmtDate||au,ce=f==1?kw(J):Hw(J),Z=Tf(J,Ef(f==1?Ow:zw,H)),ee=Rf(J,Af(Gw,H)),se=[],pe=n.legend=fn({},$w,i.legend),fe=n.cursor=fn({},jw,{drag:{y:s==2}},i.cursor),B=pe.show,te=fe.show,he=pe.markers;pe.idxs=se,he.width=vt(he.width),he.dash=vt(he.dash),he.stroke=vt(he.stroke),he.fill=vt(he.fill);let ge,ve,Ve,Qe=[],ze=[],nt,tt=!1,Ye={};if(pe.live){const v=x[1]?x[1].values:null;tt=v!=null,nt=tt?v(n,1,0):{_:0};for(let E in nt)Ye[E]=eu}if(B)if(ge=wi("table",Kb,c),Ve=wi("tbody",null,ge),pe.mount(n,ge),tt){ve=wi("thead",null,ge,Ve);let v=wi("tr",null,ve);wi("th",null,v);for(var It in nt)wi("th",tf,v).textContent=It}else ti(ge,Jb),pe.live&&ti(ge,Zb);const gt={show:!0},$t={show:!1};function Mt(v,E){if(E==0&&(tt||!pe.live||s==2))return Wr;let P=[],D=wi("tr",jb,Ve,Ve.childNodes[E]);ti(D,v.class),v.show||ti(D,Xs);let $=wi("th",null,D);if(he.show){let me=ci(Qb,$);if(E>0){let ye=he.width(n,E);ye&&(me.style.border=ye+"px "+he.dash(n,E)+" "+he.stroke(n,E)),me.style.background=he.fill(n,E)}}let j=ci(tf,$);v.label instanceof HTMLElement?j.appendChild(v.label):j.textContent=v.label,E>0&&(he.show||(j.style.color=v.width>0?he.stroke(n,E):he.fill(n,E)),dt("click",$,me=>{if(fe._lock)return;Ze(me);let ye=x.indexOf(v);if((me.ctrlKey||me.metaKey)!=pe.isolate){let Ne=x.some((Ie,Fe)=>Fe>0&&Fe!=ye&&Ie.show);x.forEach((Ie,Fe)=>{Fe>0&&Di(Fe,Ne?Fe==ye?gt:$t:gt,!0,un.setSeries)})}else Di(ye,{show:!v.show},!0,un.setSeries)},!1),Je&&dt(af,$,me=>{fe._lock||(Ze(me),Di(x.indexOf(v),hr,!0,un.setSeries))},!1));for(var le in nt){let me=wi("td",ew,D);me.textContent="--",P.push(me)}return[D,P]}const an=new Map;function dt(v,E,P,D=!0){const $=an.get(E)||{},j=fe.bind[v](n,E,P,D);j&&(qs(v,E,$[v]=j),an.set(E,$))}function pn(v,E,P){const D=an.get(E)||{};for(let $ in D)(v==null||$==v)&&(yh($,E,D[$]),delete D[$]);v==null&&an.delete(E)}let Yt=0,on=0,O=0,Ce=0,qe=0,st=0,we=qe,Ut=st,He=O,$e=Ce,C=0,w=0,q=0,de=0;n.bbox={};let oe=!1,Se=!1,Me=!1,ne=!1,re=!1,_e=!1;function F(v,E,P){(P||v!=n.width||E!=n.height)&&ae(v,E),ot(!1),Me=!0,Se=!0,Ln()}function ae(v,E){n.width=Yt=O=v,n.height=on=Ce=E,qe=st=0,be(),Ge();let P=n.bbox;C=P.left=Gs(qe*Et,.5),w=P.top=Gs(st*Et,.5),q=P.width=Gs(O*Et,.5),de=P.height=Gs(Ce*Et,.5)}const ie=3;function Ee(){let v=!1,E=0;for(;!v;){E++;let P=sr(E),D=Li(E);v=E==ie||P&&D,v||(ae(n.width,n.height),Se=!0)}}function xe({width:v,height:E}){F(v,E)}n.setSize=xe;function be(){let v=!1,E=!1,P=!1,D=!1;A.forEach(($,j)=>{if($.show&&$._show){let{side:le,_size:me}=$,ye=le%2,Ne=$.label!=null?$.labelSize:0,Ie=me+Ne;Ie>0&&(ye?(O-=Ie,le==3?(qe+=Ie,D=!0):P=!0):(Ce-=Ie,le==0?(st+=Ie,v=!0):E=!0))}}),Ci[0]=v,Ci[1]=P,Ci[2]=E,Ci[3]=D,O-=_i[1]+_i[3],qe+=_i[3],Ce-=_i[2]+_i[0],st+=_i[0]}function Ge(){let v=qe+O,E=st+Ce,P=qe,D=st;function $(j,le){switch(j){case 1:return v+=le,v-le;case 2:return E+=le,E-le;case 3:return P-=le,P+le;case 0:return D-=le,D+le}}A.forEach((j,le)=>{if(j.show&&j._show){let me=j.side;j._pos=$(me,j._size),j.label!=null&&(j._lpos=$(me,j.labelSize))}})}if(fe.dataIdx==null){let v=fe.hover,E=v.skip=new Set(v.skip??[]);E.add(void 0);let P=v.prox=vt(v.prox),D=v.bias??=0;fe.dataIdx=($,j,le,me)=>{if(j==0)return le;let ye=le,Ne=P($,j,le,me)??Ft,Ie=Ne>=0&&Ne<Ft,Fe=L.ori==0?O:Ce,it=fe.left,wt=e[0],yt=e[j];if(E.has(yt[le])){ye=null;let ft=null,Ke=null,We;if(D==0||D==-1)for(We=le;ft==null&&We-- >0;)E.has(yt[We])||(ft=We);if(D==0||D==1)for(We=le;Ke==null&&We++<yt.length;)E.has(yt[We])||(Ke=We);if(ft!=null||Ke!=null)if(Ie){let Gt=ft==null?-1/0:W(wt[ft],L,Fe,0),Jt=Ke==null?1/0:W(wt[Ke],L,Fe,0),An=it-Gt,Nt=Jt-it;An<=Nt?An<=Ne&&(ye=ft):Nt<=Ne&&(ye=Ke)}else ye=Ke==null?ft:ft==null?Ke:le-ft<=Ke-le?ft:Ke}else Ie&&xn(it-W(wt[le],L,Fe,0))>Ne&&(ye=null);return ye}}const Ze=v=>{fe.event=v};fe.idxs=se,fe._lock=!1;let ue=fe.points;ue.show=vt(ue.show),ue.size=vt(ue.size),ue.stroke=vt(ue.stroke),ue.width=vt(ue.width),ue.fill=vt(ue.fill);const Oe=n.focus=fn({},i.focus||{alpha:.3},fe.focus),Je=Oe.prox>=0,Re=Je&&ue.one;let at=[],zt=[],Fn=[];function Jr(v,E){let P=ue.show(n,E);if(P instanceof HTMLElement)return ti(P,Yb),ti(P,v.class),Bi(P,-10,-10,O,Ce),_.insertBefore(P,at[E]),P}function tr(v,E){if(s==1||E>0){let P=s==1&&S[v.scale].time,D=v.value;v.value=P?Mf(D)?Rf(J,Af(D,H)):D||ee:D||lE,v.label=v.label||(P?eE:Qw)}if(Re||E>0){v.width=v.width==null?1:v.width,v.paths=v.paths||yE||dw,v.fillTo=vt(v.fillTo||fE),v.pxAlign=+bt(v.pxAlign,M),v.pxRound=Of(v.pxAlign),v.stroke=vt(v.stroke||null),v.fill=vt(v.fill||null),v._stroke=v._fill=v._paths=v._focus=null;let P=cE(Wn(1,v.width),1),D=v.points=fn({},{size:P,width:Wn(1,P*.2),stroke:v.stroke,space:P*2,paths:bE,_stroke:null,_fill:null},v.points);D.show=vt(D.show),D.filter=vt(D.filter),D.fill=vt(D.fill),D.stroke=vt(D.stroke),D.paths=vt(D.paths),D.pxAlign=v.pxAlign}if(B){let P=Mt(v,E);Qe.splice(E,0,P[0]),ze.splice(E,0,P[1]),pe.values.push(null)}if(te){se.splice(E,0,null);let P=null;Re?E==0&&(P=Jr(v,E)):E>0&&(P=Jr(v,E)),at.splice(E,0,P),zt.splice(E,0,0),Fn.splice(E,0,0)}Tn("addSeries",E)}function xl(v,E){E=E??x.length,v=s==1?Rh(v,E,Pf,Uf):Rh(v,E,{},If),x.splice(E,0,v),tr(x[E],E)}n.addSeries=xl;function Wa(v){if(x.splice(v,1),B){pe.values.splice(v,1),ze.splice(v,1);let E=Qe.splice(v,1)[0];pn(null,E.firstChild),E.remove()}te&&(se.splice(v,1),at.splice(v,1)[0].remove(),zt.splice(v,1),Fn.splice(v,1)),Tn("delSeries",v)}n.delSeries=Wa;const Ci=[!1,!1,!1,!1];function Zi(v,E){if(v._show=v.show,v.show){let P=v.side%2,D=S[v.scale];D==null&&(v.scale=P?x[1].scale:y,D=S[v.scale]);let $=D.time;v.size=vt(v.size),v.space=vt(v.space),v.rotate=vt(v.rotate),ws(v.incrs)&&v.incrs.forEach(le=>{!Ns.has(le)&&Ns.set(le,gm(le))}),v.incrs=vt(v.incrs||(D.distr==2?Iw:$?f==1?Fw:Bw:Ws)),v.splits=vt(v.splits||($&&D.distr==1?ce:D.distr==3?wh:D.distr==4?iE:nE)),v.stroke=vt(v.stroke),v.grid.stroke=vt(v.grid.stroke),v.ticks.stroke=vt(v.ticks.stroke),v.border.stroke=vt(v.border.stroke);let j=v.values;v.values=ws(j)&&!ws(j[0])?vt(j):$?ws(j)?Tf(J,Ef(j,H)):Mf(j)?Vw(J,j):j||Z:j||tE,v.filter=vt(v.filter||(D.distr>=3&&D.log==10?aE:D.distr==3&&D.log==2?oE:pm)),v.font=Hf(v.font),v.labelFont=Hf(v.labelFont),v._size=v.size(n,null,E,0),v._space=v._rotate=v._incrs=v._found=v._splits=v._values=null,v._size>0&&(Ci[E]=!0,v._el=ci(Wb,d))}}function Ji(v,E,P,D){let[$,j,le,me]=P,ye=E%2,Ne=0;return ye==0&&(me||j)&&(Ne=E==0&&!$||E==2&&!le?vn(Cf.size/3):0),ye==1&&($||le)&&(Ne=E==1&&!j||E==3&&!me?vn(Df.size/2):0),Ne}const jr=n.padding=(i.padding||[Ji,Ji,Ji,Ji]).map(v=>vt(bt(v,Ji))),_i=n._padding=jr.map((v,E)=>v(n,E,Ci,0));let Kt,en=null,tn=null;const Pi=s==1?x[0].idxs:null;let Kn=null,ds=!1;function Qr(v,E){if(e=v??[],n.data=n._data=e,s==2){Kt=0;for(let P=1;P<x.length;P++)Kt+=e[P][0].length}else{e.length==0&&(n.data=n._data=e=[[]]),Kn=e[0],Kt=Kn.length;let P=e;if(G==2){P=e.slice();let D=P[0]=Array(Kt);for(let $=0;$<Kt;$++)D[$]=$}n._data=e=P}if(ot(!0),Tn("setData"),G==2&&(Me=!0),E!==!1){let P=L;P.auto(n,ds)?ea():ms(y,P.min,P.max),ne=ne||fe.left>=0,_e=!0,Ln()}}n.setData=Qr;function ea(){ds=!0;let v,E;s==1&&(Kt>0?(en=Pi[0]=0,tn=Pi[1]=Kt-1,v=e[0][en],E=e[0][tn],G==2?(v=en,E=tn):v==E&&(G==3?[v,E]=ul(v,v,L.log,!1):G==4?[v,E]=nu(v,v,L.log,!1):L.time?E=v+vn(86400/f):[v,E]=tl(v,E,iu,!0))):(en=Pi[0]=v=null,tn=Pi[1]=E=null)),ms(y,v,E)}let nr,fs,ir,T,V,Q,Y,K,Te,Pe;function Ae(v,E,P,D,$,j){v??=sf,P??=ru,D??="butt",$??=sf,j??="round",v!=nr&&(u.strokeStyle=nr=v),$!=fs&&(u.fillStyle=fs=$),E!=ir&&(u.lineWidth=ir=E),j!=V&&(u.lineJoin=V=j),D!=Q&&(u.lineCap=Q=D),P!=T&&u.setLineDash(T=P)}function Le(v,E,P,D){E!=fs&&(u.fillStyle=fs=E),v!=Y&&(u.font=Y=v),P!=K&&(u.textAlign=K=P),D!=Te&&(u.textBaseline=Te=D)}function Be(v,E,P,D,$=0){if(D.length>0&&v.auto(n,ds)&&(E==null||E.min==null)){let j=bt(en,0),le=bt(tn,D.length-1),me=P.min==null?aw(D,j,le,$,v.distr==3):[P.min,P.max];v.min=Ai(v.min,P.min=me[0]),v.max=Wn(v.max,P.max=me[1])}}const et={min:null,max:null};function ht(){for(let D in S){let $=S[D];X[D]==null&&($.min==null||X[y]!=null&&$.auto(n,ds))&&(X[D]=et)}for(let D in S){let $=S[D];X[D]==null&&$.from!=null&&X[$.from]!=null&&(X[D]=et)}X[y]!=null&&ot(!0);let v={};for(let D in X){let $=X[D];if($!=null){let j=v[D]=Xr(S[D],mw);if($.min!=null)fn(j,$);else if(D!=y||s==2)if(Kt==0&&j.from==null){let le=j.range(n,null,null,D);j.min=le[0],j.max=le[1]}else j.min=Ft,j.max=-Ft}}if(Kt>0){x.forEach((D,$)=>{if(s==1){let j=D.scale,le=X[j];if(le==null)return;let me=v[j];if($==0){let ye=me.range(n,me.min,me.max,j);me.min=ye[0],me.max=ye[1],en=Ei(me.min,e[0]),tn=Ei(me.max,e[0]),tn-en>1&&(e[0][en]<me.min&&en++,e[0][tn]>me.max&&tn--),D.min=Kn[en],D.max=Kn[tn]}else D.show&&D.auto&&Be(me,le,D,e[$],D.sorted);D.idxs[0]=en,D.idxs[1]=tn}else if($>0&&D.show&&D.auto){let[j,le]=D.facets,me=j.scale,ye=le.scale,[Ne,Ie]=e[$],Fe=v[me],it=v[ye];Fe!=null&&Be(Fe,X[me],j,Ne,j.sorted),it!=null&&Be(it,X[ye],le,Ie,le.sorted),D.min=le.min,D.max=le.max}});for(let D in v){let $=v[D],j=X[D];if($.from==null&&(j==null||j.min==null)){let le=$.range(n,$.min==Ft?null:$.min,$.max==-Ft?null:$.max,D);$.min=le[0],$.max=le[1]}}}for(let D in v){let $=v[D];if($.from!=null){let j=v[$.from];if(j.min==null)$.min=$.max=null;else{let le=$.range(n,j.min,j.max,D);$.min=le[0],$.max=le[1]}}}let E={},P=!1;for(let D in v){let $=v[D],j=S[D];if(j.min!=$.min||j.max!=$.max){j.min=$.min,j.max=$.max;let le=j.distr;j._min=le==3?hs(j.min):le==4?vc(j.min,j.asinh):le==100?j.fwd(j.min):j.min,j._max=le==3?hs(j.max):le==4?vc(j.max,j.asinh):le==100?j.fwd(j.max):j.max,E[D]=P=!0}}if(P){x.forEach((D,$)=>{s==2?$>0&&E.y&&(D._paths=null):E[D.scale]&&(D._paths=null)});for(let D in E)Me=!0,Tn("setScale",D);te&&fe.left>=0&&(ne=_e=!0)}for(let D in X)X[D]=null}function ke(v){let E=bh(en-1,0,Kt-1),P=bh(tn+1,0,Kt-1);for(;v[E]==null&&E>0;)E--;for(;v[P]==null&&P<Kt-1;)P++;return[E,P]}function ut(){if(Kt>0){let v=x.some(E=>E._focus)&&Pe!=Oe.alpha;v&&(u.globalAlpha=Pe=Oe.alpha),x.forEach((E,P)=>{if(P>0&&E.show&&(qt(P,!1),qt(P,!0),E._paths==null)){let D=Pe;Pe!=E.alpha&&(u.globalAlpha=Pe=E.alpha);let $=s==2?[0,e[P][0].length-1]:ke(e[P]);E._paths=E.paths(n,P,$[0],$[1]),Pe!=D&&(u.globalAlpha=Pe=D)}}),x.forEach((E,P)=>{if(P>0&&E.show){let D=Pe;Pe!=E.alpha&&(u.globalAlpha=Pe=E.alpha),E._paths!=null&&Rt(P,!1);{let $=E._paths!=null?E._paths.gaps:null,j=E.points.show(n,P,en,tn,$),le=E.points.filter(n,P,j,$);(j||le)&&(E.points._paths=E.points.paths(n,P,en,tn,le),Rt(P,!0))}Pe!=D&&(u.globalAlpha=Pe=D),Tn("drawSeries",P)}}),v&&(u.globalAlpha=Pe=1)}}function qt(v,E){let P=E?x[v].points:x[v];P._stroke=P.stroke(n,v),P._fill=P.fill(n,v)}function Rt(v,E){let P=E?x[v].points:x[v],{stroke:D,fill:$,clip:j,flags:le,_stroke:me=P._stroke,_fill:ye=P._fill,_width:Ne=P.width}=P._paths;Ne=Ot(Ne*Et,3);let Ie=null,Fe=Ne%2/2;E&&ye==null&&(ye=Ne>0?"#fff":me);let it=P.pxAlign==1&&Fe>0;if(it&&u.translate(Fe,Fe),!E){let wt=C-Ne/2,yt=w-Ne/2,ft=q+Ne,Ke=de+Ne;Ie=new Path2D,Ie.rect(wt,yt,ft,Ke)}E?Ue(me,Ne,P.dash,P.cap,ye,D,$,le,j):Ct(v,me,Ne,P.dash,P.cap,ye,D,$,le,Ie,j),it&&u.translate(-Fe,-Fe)}function Ct(v,E,P,D,$,j,le,me,ye,Ne,Ie){let Fe=!1;ye!=0&&R.forEach((it,wt)=>{if(it.series[0]==v){let yt=x[it.series[1]],ft=e[it.series[1]],Ke=(yt._paths||Ea).band;ws(Ke)&&(Ke=it.dir==1?Ke[0]:Ke[1]);let We,Gt=null;yt.show&&Ke&&lw(ft,en,tn)?(Gt=it.fill(n,wt)||j,We=yt._paths.clip):Ke=null,Ue(E,P,D,$,Gt,le,me,ye,Ne,Ie,We,Ke),Fe=!0}}),Fe||Ue(E,P,D,$,j,le,me,ye,Ne,Ie)}const mn=$r|Th;function Ue(v,E,P,D,$,j,le,me,ye,Ne,Ie,Fe){Ae(v,E,P,D,$),(ye||Ne||Fe)&&(u.save(),ye&&u.clip(ye),Ne&&u.clip(Ne)),Fe?(me&mn)==mn?(u.clip(Fe),Ie&&u.clip(Ie),_t($,le),ln(v,j,E)):me&Th?(_t($,le),u.clip(Fe),ln(v,j,E)):me&$r&&(u.save(),u.clip(Fe),Ie&&u.clip(Ie),_t($,le),u.restore(),ln(v,j,E)):(_t($,le),ln(v,j,E)),(ye||Ne||Fe)&&u.restore()}function ln(v,E,P){P>0&&(E instanceof Map?E.forEach((D,$)=>{u.strokeStyle=nr=$,u.stroke(D)}):E!=null&&v&&u.stroke(E))}function _t(v,E){E instanceof Map?E.forEach((P,D)=>{u.fillStyle=fs=D,u.fill(P)}):E!=null&&v&&u.fill(E)}function ji(v,E,P,D){let $=A[v],j;if(D<=0)j=[0,0];else{let le=$._space=$.space(n,v,E,P,D),me=$._incrs=$.incrs(n,v,E,P,D,le);j=CE(E,P,me,D,le)}return $._found=j}function cn(v,E,P,D,$,j,le,me,ye,Ne){let Ie=le%2/2;M==1&&u.translate(Ie,Ie),Ae(me,le,ye,Ne,me),u.beginPath();let Fe,it,wt,yt,ft=$+(D==0||D==3?-j:j);P==0?(it=$,yt=ft):(Fe=$,wt=ft);for(let Ke=0;Ke<v.length;Ke++)E[Ke]!=null&&(P==0?Fe=wt=v[Ke]:it=yt=v[Ke],u.moveTo(Fe,it),u.lineTo(wt,yt));u.stroke(),M==1&&u.translate(-Ie,-Ie)}function sr(v){let E=!0;return A.forEach((P,D)=>{if(!P.show)return;let $=S[P.scale];if($.min==null){P._show&&(E=!1,P._show=!1,ot(!1));return}else P._show||(E=!1,P._show=!0,ot(!1));let j=P.side,le=j%2,{min:me,max:ye}=$,[Ne,Ie]=ji(D,me,ye,le==0?O:Ce);if(Ie==0)return;let Fe=$.distr==2,it=P._splits=P.splits(n,D,me,ye,Ne,Ie,Fe),wt=$.distr==2?it.map(We=>Kn[We]):it,yt=$.distr==2?Kn[it[1]]-Kn[it[0]]:Ne,ft=P._values=P.values(n,P.filter(n,wt,D,Ie,yt),D,Ie,yt);P._rotate=j==2?P.rotate(n,ft,D,Ie):0;let Ke=P._size;P._size=ui(P.size(n,ft,D,v)),Ke!=null&&P._size!=Ke&&(E=!1)}),E}function Li(v){let E=!0;return jr.forEach((P,D)=>{let $=P(n,D,Ci,v);$!=_i[D]&&(E=!1),_i[D]=$}),E}function Qi(){for(let v=0;v<A.length;v++){let E=A[v];if(!E.show||!E._show)continue;let P=E.side,D=P%2,$,j,le=E.stroke(n,v),me=P==0||P==3?-1:1,[ye,Ne]=E._found;if(E.label!=null){let Bn=E.labelGap*me,jn=vn((E._lpos+Bn)*Et);Le(E.labelFont[0],le,"center",P==2?pa:nf),u.save(),D==1?($=j=0,u.translate(jn,vn(w+de/2)),u.rotate((P==3?-Vo:Vo)/2)):($=vn(C+q/2),j=jn);let Os=dm(E.label)?E.label(n,v,ye,Ne):E.label;u.fillText(Os,$,j),u.restore()}if(Ne==0)continue;let Ie=S[E.scale],Fe=D==0?q:de,it=D==0?C:w,wt=E._splits,yt=Ie.distr==2?wt.map(Bn=>Kn[Bn]):wt,ft=Ie.distr==2?Kn[wt[1]]-Kn[wt[0]]:ye,Ke=E.ticks,We=E.border,Gt=Ke.show?Ke.size:0,Jt=vn(Gt*Et),An=vn((E.alignTo==2?E._size-Gt-E.gap:E.gap)*Et),Nt=E._rotate*-Vo/180,jt=p(E._pos*Et),Zn=(Jt+An)*me,kn=jt+Zn;j=D==0?kn:0,$=D==1?kn:0;let ri=E.font[0],vi=E.align==1?Rr:E.align==2?mc:Nt>0?Rr:Nt<0?mc:D==0?"center":P==3?mc:Rr,Ii=Nt||D==1?"middle":P==2?pa:nf;Le(ri,le,vi,Ii);let Jn=E.font[1]*E.lineGap,ai=wt.map(Bn=>p(o(Bn,Ie,Fe,it))),xi=E._values;for(let Bn=0;Bn<xi.length;Bn++){let jn=xi[Bn];if(jn!=null){D==0?$=ai[Bn]:j=ai[Bn],jn=""+jn;let Os=jn.indexOf(`
`)==-1?[jn]:jn.split(/\n/gm);for(let zn=0;zn<Os.length;zn++){let Nu=Os[zn];Nt?(u.save(),u.translate($,j+zn*Jn),u.rotate(Nt),u.fillText(Nu,0,0),u.restore()):u.fillText(Nu,$,j+zn*Jn)}}}Ke.show&&cn(ai,Ke.filter(n,yt,v,Ne,ft),D,P,jt,Jt,Ot(Ke.width*Et,3),Ke.stroke(n,v),Ke.dash,Ke.cap);let Ui=E.grid;Ui.show&&cn(ai,Ui.filter(n,yt,v,Ne,ft),D,D==0?2:1,D==0?w:C,D==0?de:q,Ot(Ui.width*Et,3),Ui.stroke(n,v),Ui.dash,Ui.cap),We.show&&cn([jt],[1],D==0?1:0,D==0?1:2,D==1?w:C,D==1?de:q,Ot(We.width*Et,3),We.stroke(n,v),We.dash,We.cap)}Tn("drawAxes")}function ot(v){x.forEach((E,P)=>{P>0&&(E._paths=null,v&&(s==1?(E.min=null,E.max=null):E.facets.forEach(D=>{D.min=null,D.max=null})))})}let Zt=!1,On=!1,Pt=[];function hn(){On=!1;for(let v=0;v<Pt.length;v++)Tn(...Pt[v]);Pt.length=0}function Ln(){Zt||(yw(mu),Zt=!0)}function Xa(v,E=!1){Zt=!0,On=E,v(n),mu(),E&&Pt.length>0&&queueMicrotask(hn)}n.batch=Xa;function mu(){if(oe&&(ht(),oe=!1),Me&&(Ee(),Me=!1),Se){if(Wt(m,Rr,qe),Wt(m,pa,st),Wt(m,xa,O),Wt(m,Sa,Ce),Wt(_,Rr,qe),Wt(_,pa,st),Wt(_,xa,O),Wt(_,Sa,Ce),Wt(d,xa,Yt),Wt(d,Sa,on),h.width=vn(Yt*Et),h.height=vn(on*Et),A.forEach(({_el:v,_show:E,_size:P,_pos:D,side:$})=>{if(v!=null)if(E){let j=$===3||$===0?P:0,le=$%2==1;Wt(v,le?"left":"top",D-j),Wt(v,le?"width":"height",P),Wt(v,le?"top":"left",le?st:qe),Wt(v,le?"height":"width",le?Ce:O),Mh(v,Xs)}else ti(v,Xs)}),nr=fs=ir=V=Q=Y=K=Te=T=null,Pe=1,ia(!0),qe!=we||st!=Ut||O!=He||Ce!=$e){ot(!1);let v=O/He,E=Ce/$e;if(te&&!ne&&fe.left>=0){fe.left*=v,fe.top*=E,rr&&Bi(rr,vn(fe.left),0,O,Ce),ar&&Bi(ar,0,vn(fe.top),O,Ce);for(let P=0;P<at.length;P++){let D=at[P];D!=null&&(zt[P]*=v,Fn[P]*=E,Bi(D,ui(zt[P]),ui(Fn[P]),O,Ce))}}if(Vt.show&&!re&&Vt.left>=0&&Vt.width>0){Vt.left*=v,Vt.width*=v,Vt.top*=E,Vt.height*=E;for(let P in El)Wt(cr,P,Vt[P])}we=qe,Ut=st,He=O,$e=Ce}Tn("setSize"),Se=!1}Yt>0&&on>0&&(u.clearRect(0,0,h.width,h.height),Tn("drawClear"),b.forEach(v=>v()),Tn("draw")),Vt.show&&re&&($a(Vt),re=!1),te&&ne&&(Fs(null,!0,!1),ne=!1),pe.show&&pe.live&&_e&&(bl(),_e=!1),l||(l=!0,n.status=1,Tn("ready")),ds=!1,Zt=!1}n.redraw=(v,E)=>{Me=E||!1,v!==!1?ms(y,L.min,L.max):Ln()};function Sl(v,E){let P=S[v];if(P.from==null){if(Kt==0){let D=P.range(n,E.min,E.max,v);E.min=D[0],E.max=D[1]}if(E.min>E.max){let D=E.min;E.min=E.max,E.max=D}if(Kt>1&&E.min!=null&&E.max!=null&&E.max-E.min<1e-16)return;v==y&&P.distr==2&&Kt>0&&(E.min=Ei(E.min,e[0]),E.max=Ei(E.max,e[0]),E.min==E.max&&E.max++),X[v]=E,oe=!0,Ln()}}n.setScale=Sl;let Ml,yl,rr,ar,gu,_u,or,lr,vu,xu,Ht,Xt,ps=!1;const Cn=fe.drag;let wn=Cn.x,En=Cn.y;te&&(fe.x&&(Ml=ci($b,_)),fe.y&&(yl=ci(qb,_)),L.ori==0?(rr=Ml,ar=yl):(rr=yl,ar=Ml),Ht=fe.left,Xt=fe.top);const Vt=n.select=fn({show:!0,over:!0,left:0,width:0,top:0,height:0},i.select),cr=Vt.show?ci(Xb,Vt.over?_:m):null;function $a(v,E){if(Vt.show){for(let P in v)Vt[P]=v[P],P in El&&Wt(cr,P,v[P]);E!==!1&&Tn("setSelect")}}n.setSelect=$a;function Km(v){if(x[v].show)B&&Mh(Qe[v],Xs);else if(B&&ti(Qe[v],Xs),te){let P=Re?at[0]:at[v];P!=null&&Bi(P,-10,-10,O,Ce)}}function ms(v,E,P){Sl(v,{min:E,max:P})}function Di(v,E,P,D){E.focus!=null&&eg(v),E.show!=null&&x.forEach(($,j)=>{j>0&&(v==j||v==null)&&($.show=E.show,Km(j),s==2?(ms($.facets[0].scale,null,null),ms($.facets[1].scale,null,null)):ms($.scale,null,null),Ln())}),P!==!1&&Tn("setSeries",v,E),D&&sa("setSeries",n,v,E)}n.setSeries=Di;function Zm(v,E){fn(R[v],E)}function Jm(v,E){v.fill=vt(v.fill||null),v.dir=bt(v.dir,-1),E=E??R.length,R.splice(E,0,v)}function jm(v){v==null?R.length=0:R.splice(v,1)}n.addBand=Jm,n.setBand=Zm,n.delBand=jm;function Qm(v,E){x[v].alpha=E,te&&at[v]!=null&&(at[v].style.opacity=E),B&&Qe[v]&&(Qe[v].style.opacity=E)}let es,gs,Us;const hr={focus:!0};function eg(v){if(v!=Us){let E=v==null,P=Oe.alpha!=1;x.forEach((D,$)=>{if(s==1||$>0){let j=E||$==0||$==v;D._focus=E?null:j,P&&Qm($,j?1:Oe.alpha)}}),Us=v,P&&Ln()}}B&&Je&&dt(of,ge,v=>{fe._lock||(Ze(v),Us!=null&&Di(null,hr,!0,un.setSeries))});function Ni(v,E,P){let D=S[E];P&&(v=v/Et-(D.ori==1?st:qe));let $=O;D.ori==1&&($=Ce,v=$-v),D.dir==-1&&(v=$-v);let j=D._min,le=D._max,me=v/$,ye=j+(le-j)*me,Ne=D.distr;return Ne==3?Gr(10,ye):Ne==4?hw(ye,D.asinh):Ne==100?D.bwd(ye):ye}function tg(v,E){let P=Ni(v,y,E);return Ei(P,e[0],en,tn)}n.valToIdx=v=>Ei(v,e[0]),n.posToIdx=tg,n.posToVal=Ni,n.valToPos=(v,E,P)=>S[E].ori==0?r(v,S[E],P?q:O,P?C:0):a(v,S[E],P?de:Ce,P?w:0),n.setCursor=(v,E,P)=>{Ht=v.left,Xt=v.top,Fs(null,E,P)};function Su(v,E){Wt(cr,Rr,Vt.left=v),Wt(cr,xa,Vt.width=E)}function Mu(v,E){Wt(cr,pa,Vt.top=v),Wt(cr,Sa,Vt.height=E)}let ta=L.ori==0?Su:Mu,na=L.ori==1?Su:Mu;function ng(){if(B&&pe.live)for(let v=s==2?1:0;v<x.length;v++){if(v==0&&tt)continue;let E=pe.values[v],P=0;for(let D in E)ze[v][P++].firstChild.nodeValue=E[D]}}function bl(v,E){if(v!=null&&(v.idxs?v.idxs.forEach((P,D)=>{se[D]=P}):pw(v.idx)||se.fill(v.idx),pe.idx=se[0]),B&&pe.live){for(let P=0;P<x.length;P++)(P>0||s==1&&!tt)&&ig(P,se[P]);ng()}_e=!1,E!==!1&&Tn("setLegend")}n.setLegend=bl;function ig(v,E){let P=x[v],D=v==0&&G==2?Kn:e[v],$;tt?$=P.values(n,v,E)??Ye:($=P.value(n,E==null?null:D[E],v,E),$=$==null?Ye:{_:$}),pe.values[v]=$}function Fs(v,E,P){vu=Ht,xu=Xt,[Ht,Xt]=fe.move(n,Ht,Xt),fe.left=Ht,fe.top=Xt,te&&(rr&&Bi(rr,vn(Ht),0,O,Ce),ar&&Bi(ar,0,vn(Xt),O,Ce));let D,$=en>tn;es=Ft,gs=null;let j=L.ori==0?O:Ce,le=L.ori==1?O:Ce;if(Ht<0||Kt==0||$){D=fe.idx=null;for(let me=0;me<x.length;me++){let ye=at[me];ye!=null&&Bi(ye,-10,-10,O,Ce)}Je&&Di(null,hr,!0,v==null&&un.setSeries),pe.live&&(se.fill(D),_e=!0)}else{let me,ye,Ne;s==1&&(me=L.ori==0?Ht:Xt,ye=Ni(me,y),D=fe.idx=Ei(ye,e[0],en,tn),Ne=W(e[0][D],L,j,0));let Ie=-10,Fe=-10,it=0,wt=0,yt=!0,ft="",Ke="";for(let We=s==2?1:0;We<x.length;We++){let Gt=x[We],Jt=se[We],An=Jt==null?null:s==1?e[We][Jt]:e[We][1][Jt],Nt=fe.dataIdx(n,We,D,ye),jt=Nt==null?null:s==1?e[We][Nt]:e[We][1][Nt];if(_e=_e||jt!=An||Nt!=Jt,se[We]=Nt,We>0&&Gt.show){let Zn=Nt==null?-10:Nt==D?Ne:W(s==1?e[0][Nt]:e[We][0][Nt],L,j,0),kn=jt==null?-10:U(jt,s==1?S[Gt.scale]:S[Gt.facets[1].scale],le,0);if(Je&&jt!=null){let ri=L.ori==1?Ht:Xt,vi=xn(Oe.dist(n,We,Nt,kn,ri));if(vi<es){let Ii=Oe.bias;if(Ii!=0){let Jn=Ni(ri,Gt.scale),ai=jt>=0?1:-1,xi=Jn>=0?1:-1;xi==ai&&(xi==1?Ii==1?jt>=Jn:jt<=Jn:Ii==1?jt<=Jn:jt>=Jn)&&(es=vi,gs=We)}else es=vi,gs=We}}if(_e||Re){let ri,vi;L.ori==0?(ri=Zn,vi=kn):(ri=kn,vi=Zn);let Ii,Jn,ai,xi,Ui,Bn,jn=!0,Os=ue.bbox;if(Os!=null){jn=!1;let zn=Os(n,We);ai=zn.left,xi=zn.top,Ii=zn.width,Jn=zn.height}else ai=ri,xi=vi,Ii=Jn=ue.size(n,We);if(Bn=ue.fill(n,We),Ui=ue.stroke(n,We),Re)We==gs&&es<=Oe.prox&&(Ie=ai,Fe=xi,it=Ii,wt=Jn,yt=jn,ft=Bn,Ke=Ui);else{let zn=at[We];zn!=null&&(zt[We]=ai,Fn[We]=xi,pf(zn,Ii,Jn,jn),df(zn,Bn,Ui),Bi(zn,ui(ai),ui(xi),O,Ce))}}}}if(Re){let We=Oe.prox,Gt=Us==null?es<=We:es>We||gs!=Us;if(_e||Gt){let Jt=at[0];Jt!=null&&(zt[0]=Ie,Fn[0]=Fe,pf(Jt,it,wt,yt),df(Jt,ft,Ke),Bi(Jt,ui(Ie),ui(Fe),O,Ce))}}}if(Vt.show&&ps)if(v!=null){let[me,ye]=un.scales,[Ne,Ie]=un.match,[Fe,it]=v.cursor.sync.scales,wt=v.cursor.drag;if(wn=wt._x,En=wt._y,wn||En){let{left:yt,top:ft,width:Ke,height:We}=v.select,Gt=v.scales[Fe].ori,Jt=v.posToVal,An,Nt,jt,Zn,kn,ri=me!=null&&Ne(me,Fe),vi=ye!=null&&Ie(ye,it);ri&&wn?(Gt==0?(An=yt,Nt=Ke):(An=ft,Nt=We),jt=S[me],Zn=W(Jt(An,Fe),jt,j,0),kn=W(Jt(An+Nt,Fe),jt,j,0),ta(Ai(Zn,kn),xn(kn-Zn))):ta(0,j),vi&&En?(Gt==1?(An=yt,Nt=Ke):(An=ft,Nt=We),jt=S[ye],Zn=U(Jt(An,it),jt,le,0),kn=U(Jt(An+Nt,it),jt,le,0),na(Ai(Zn,kn),xn(kn-Zn))):na(0,le)}else Tl()}else{let me=xn(vu-gu),ye=xn(xu-_u);if(L.ori==1){let it=me;me=ye,ye=it}wn=Cn.x&&me>=Cn.dist,En=Cn.y&&ye>=Cn.dist;let Ne=Cn.uni;Ne!=null?wn&&En&&(wn=me>=Ne,En=ye>=Ne,!wn&&!En&&(ye>me?En=!0:wn=!0)):Cn.x&&Cn.y&&(wn||En)&&(wn=En=!0);let Ie,Fe;wn&&(L.ori==0?(Ie=or,Fe=Ht):(Ie=lr,Fe=Xt),ta(Ai(Ie,Fe),xn(Fe-Ie)),En||na(0,le)),En&&(L.ori==1?(Ie=or,Fe=Ht):(Ie=lr,Fe=Xt),na(Ai(Ie,Fe),xn(Fe-Ie)),wn||ta(0,j)),!wn&&!En&&(ta(0,0),na(0,0))}if(Cn._x=wn,Cn._y=En,v==null){if(P){if(Du!=null){let[me,ye]=un.scales;un.values[0]=me!=null?Ni(L.ori==0?Ht:Xt,me):null,un.values[1]=ye!=null?Ni(L.ori==1?Ht:Xt,ye):null}sa(gc,n,Ht,Xt,O,Ce,D)}if(Je){let me=P&&un.setSeries,ye=Oe.prox;Us==null?es<=ye&&Di(gs,hr,!0,me):es>ye?Di(null,hr,!0,me):gs!=Us&&Di(gs,hr,!0,me)}}_e&&(pe.idx=D,bl()),E!==!1&&Tn("setCursor")}let _s=null;Object.defineProperty(n,"rect",{get(){return _s==null&&ia(!1),_s}});function ia(v=!1){v?_s=null:(_s=_.getBoundingClientRect(),Tn("syncRect",_s))}function yu(v,E,P,D,$,j,le){fe._lock||ps&&v!=null&&v.movementX==0&&v.movementY==0||(wl(v,E,P,D,$,j,le,!1,v!=null),v!=null?Fs(null,!0,!0):Fs(E,!0,!1))}function wl(v,E,P,D,$,j,le,me,ye){if(_s==null&&ia(!1),Ze(v),v!=null)P=v.clientX-_s.left,D=v.clientY-_s.top;else{if(P<0||D<0){Ht=-10,Xt=-10;return}let[Ne,Ie]=un.scales,Fe=E.cursor.sync,[it,wt]=Fe.values,[yt,ft]=Fe.scales,[Ke,We]=un.match,Gt=E.axes[0].side%2==1,Jt=L.ori==0?O:Ce,An=L.ori==1?O:Ce,Nt=Gt?j:$,jt=Gt?$:j,Zn=Gt?D:P,kn=Gt?P:D;if(yt!=null?P=Ke(Ne,yt)?o(it,S[Ne],Jt,0):-10:P=Jt*(Zn/Nt),ft!=null?D=We(Ie,ft)?o(wt,S[Ie],An,0):-10:D=An*(kn/jt),L.ori==1){let ri=P;P=D,D=ri}}ye&&(E==null||E.cursor.event.type==gc)&&((P<=1||P>=O-1)&&(P=Gs(P,O)),(D<=1||D>=Ce-1)&&(D=Gs(D,Ce))),me?(gu=P,_u=D,[or,lr]=fe.move(n,P,D)):(Ht=P,Xt=D)}const El={width:0,height:0,left:0,top:0};function Tl(){$a(El,!1)}let bu,wu,Eu,Tu;function Au(v,E,P,D,$,j,le){ps=!0,wn=En=Cn._x=Cn._y=!1,wl(v,E,P,D,$,j,le,!0,!1),v!=null&&(dt(_c,xh,Ru,!1),sa(rf,n,or,lr,O,Ce,null));let{left:me,top:ye,width:Ne,height:Ie}=Vt;bu=me,wu=ye,Eu=Ne,Tu=Ie}function Ru(v,E,P,D,$,j,le){ps=Cn._x=Cn._y=!1,wl(v,E,P,D,$,j,le,!1,!0);let{left:me,top:ye,width:Ne,height:Ie}=Vt,Fe=Ne>0||Ie>0,it=bu!=me||wu!=ye||Eu!=Ne||Tu!=Ie;if(Fe&&it&&$a(Vt),Cn.setScale&&Fe&&it){let wt=me,yt=Ne,ft=ye,Ke=Ie;if(L.ori==1&&(wt=ye,yt=Ie,ft=me,Ke=Ne),wn&&ms(y,Ni(wt,y),Ni(wt+yt,y)),En)for(let We in S){let Gt=S[We];We!=y&&Gt.from==null&&Gt.min!=Ft&&ms(We,Ni(ft+Ke,We),Ni(ft,We))}Tl()}else fe.lock&&(fe._lock=!fe._lock,Fs(E,!0,v!=null));v!=null&&(pn(_c,xh),sa(_c,n,Ht,Xt,O,Ce,null))}function sg(v,E,P,D,$,j,le){if(fe._lock)return;Ze(v);let me=ps;if(ps){let ye=!0,Ne=!0,Ie=10,Fe,it;L.ori==0?(Fe=wn,it=En):(Fe=En,it=wn),Fe&&it&&(ye=Ht<=Ie||Ht>=O-Ie,Ne=Xt<=Ie||Xt>=Ce-Ie),Fe&&ye&&(Ht=Ht<or?0:O),it&&Ne&&(Xt=Xt<lr?0:Ce),Fs(null,!0,!0),ps=!1}Ht=-10,Xt=-10,se.fill(null),Fs(null,!0,!0),me&&(ps=me)}function Cu(v,E,P,D,$,j,le){fe._lock||(Ze(v),ea(),Tl(),v!=null&&sa(lf,n,Ht,Xt,O,Ce,null))}function Pu(){A.forEach(PE),F(n.width,n.height,!0)}qs(el,kr,Pu);const ur={};ur.mousedown=Au,ur.mousemove=yu,ur.mouseup=Ru,ur.dblclick=Cu,ur.setSeries=(v,E,P,D)=>{let $=un.match[2];P=$(n,E,P),P!=-1&&Di(P,D,!0,!1)},te&&(dt(rf,_,Au),dt(gc,_,yu),dt(af,_,v=>{Ze(v),ia(!1)}),dt(of,_,sg),dt(lf,_,Cu),Ah.add(n),n.syncRect=ia);const qa=n.hooks=i.hooks||{};function Tn(v,E,P){On?Pt.push([v,E,P]):v in qa&&qa[v].forEach(D=>{D.call(null,n,E,P)})}(i.plugins||[]).forEach(v=>{for(let E in v.hooks)qa[E]=(qa[E]||[]).concat(v.hooks[E])});const Lu=(v,E,P)=>P,un=fn({key:null,setSeries:!1,filters:{pub:xf,sub:xf},scales:[y,x[1]?x[1].scale:null],match:[Sf,Sf,Lu],values:[null,null]},fe.sync);un.match.length==2&&un.match.push(Lu),fe.sync=un;const Du=un.key,Al=Fm(Du);function sa(v,E,P,D,$,j,le){un.filters.pub(v,E,P,D,$,j,le)&&Al.pub(v,E,P,D,$,j,le)}Al.sub(n);function rg(v,E,P,D,$,j,le){un.filters.sub(v,E,P,D,$,j,le)&&ur[v](null,E,P,D,$,j,le)}n.pub=rg;function ag(){Al.unsub(n),Ah.delete(n),an.clear(),yh(el,kr,Pu),c.remove(),ge?.remove(),Tn("destroy")}n.destroy=ag;function Rl(){Tn("init",i,e),Qr(e||i.data,!1),X[y]?Sl(y,X[y]):ea(),re=Vt.show&&(Vt.width>0||Vt.height>0),ne=_e=!0,F(i.width,i.height)}return x.forEach(tr),A.forEach(Zi),t?t instanceof HTMLElement?(t.appendChild(c),Rl()):t(n,Rl):Rl(),n}Un.assign=fn;Un.fmtNum=su;Un.rangeNum=tl;Un.rangeLog=ul;Un.rangeAsinh=nu;Un.orient=er;Un.pxRatio=Et;Un.join=Mw;Un.fmtDate=au,Un.tzDate=Dw;Un.sync=Fm;{Un.addGap=pE,Un.clipGaps=pl;let i=Un.paths={points:Vm};i.linear=Wm,i.stepped=_E,i.bars=vE,i.spline=SE}class vl{shown=new Map;observer;constructor(){this.observer=typeof IntersectionObserver>"u"?null:new IntersectionObserver(e=>{for(const t of e)this.shown.set(t.target,t.isIntersecting)})}watch(e){this.shown.set(e,!0),this.observer?.observe(e)}visible(e){return this.shown.get(e)??!0}}const LE=1e-6,DE=1e-12,fu=2**-52;function Ch(i,e,t=.05){if(i===null||e===null||!Number.isFinite(i)||!Number.isFinite(e))return[-1,1];i>e&&([i,e]=[e,i]);const n=Math.max(LE*Math.max(Math.abs(i),Math.abs(e)),DE),s=e-i;if(s<n){const r=i/2+e/2;return[r-n/2,r+n/2]}return[i-t*s,e+t*s]}function NE(i,e){return!Number.isFinite(i)||!(e>0)?null:Math.max(Math.abs(i)/e,fu/10)}function IE(i,e){const t=fu/10,n=i!==null&&Number.isFinite(i)&&i>0?Math.min(i,t):t,s=e!==null&&Number.isFinite(e)&&e>0?Math.max(e,1e-12):1e-12;return[10**Math.floor(Math.log10(n)),10**Math.ceil(Math.log10(s)+1e-9)]}function UE(i,e,t,n,s){const r=Math.max(Math.abs(n),1);return{energy:Math.max(Math.abs(i),t*r*s),j3:Math.max(Math.abs(e),t*s*Math.sqrt(r*s))}}const yc=[{title:"plot.dE",axis:"|ΔE|/E_s",key:"dE",color:"#ffb347",drift:"energy"},{title:"plot.dJ3",axis:"|ΔJ₃|/J_s",key:"dJ3",color:"#7dff8a",drift:"j3"},{title:"plot.z",axis:"z [m]",key:"z",color:"#59c3ff",events:!0},{title:"plot.tension",axis:"T [N]",key:"tension",color:"#ff5d73",events:!0}];function FE(i){if(i===null||!Number.isFinite(i))return"";if(i===0)return"0";const e=Math.abs(i);return e>=.001&&e<1e4?String(+i.toPrecision(4)):i.toExponential(0)}class OE{constructor(e,t=()=>{}){this.container=e;let n=0;const s={stroke:"#aab",grid:{stroke:"#2a2f3a"},ticks:{stroke:"#2a2f3a"},labelSize:16};for(const r of yc){const a=document.createElement("div");a.className="plot",a.dataset.plot=r.key,e.appendChild(a),this.els.push(a),this.visibility.watch(a),this.shown.push({h:null,n:-1,t:NaN,ev:null});const o=[()=>t(performance.now()-n)];r.events&&o.push(c=>this.markEvents(c)),r.drift&&o.push(c=>this.markFloor(c));const l={title:N(r.title),width:this.width(),height:160,scales:{x:{time:!1,range:(c,h,u)=>Ch(h,u,0)},y:r.drift?{distr:3,log:10,range:(c,h,u)=>IE(h,u)}:{range:(c,h,u)=>Ch(h,u)}},legend:{show:!0,live:!1},hooks:{drawClear:[()=>{n=performance.now()}],draw:o},cursor:{show:!0,drag:{x:!1,y:!1}},series:[{label:"t [s]"},{label:r.axis,stroke:r.color,width:1.5}],axes:[{...s,label:N("plot.time")},{...s,label:r.axis,size:64,values:(c,h)=>h.map(FE)}]};this.charts.push(new Un(l,[[],[]],a))}new ResizeObserver(()=>this.resize()).observe(e)}container;charts=[];els=[];visibility=new vl;shown=[];events=[];width(){return Math.max(200,this.container.clientWidth-8)}resize(){for(const e of this.charts)e.setSize({width:this.width(),height:160})}markFloor(e){const{ctx:t,bbox:n}=e,s=Math.round(e.valToPos(fu,"y",!0))+.5;s>=n.top&&s<=n.top+n.height&&(t.save(),t.strokeStyle="#8a93a6",t.setLineDash([5,4]),t.beginPath(),t.moveTo(n.left,s),t.lineTo(n.left+n.width,s),t.stroke(),t.fillStyle="#8a93a6",t.font=`${Math.round(11*devicePixelRatio)}px system-ui, sans-serif`,t.textAlign="left",t.textBaseline="bottom",t.fillText(N("plot.floor"),n.left+4,s-3),t.restore())}markEvents(e){const[t,n]=[e.scales.x?.min,e.scales.x?.max];if(t===void 0||n===void 0||t===null||n===null)return;const{ctx:s,bbox:r}=e;s.save(),s.lineWidth=1,s.strokeStyle="#e0e0e0";for(const a of this.events){if(a.t<t||a.t>n)continue;const o=Math.round(e.valToPos(a.t,"x",!0))+.5;s.setLineDash(a.kind==="slack"?[4,3]:[]),s.beginPath(),s.moveTo(o,r.top),s.lineTo(o,r.top+r.height),s.stroke()}s.restore()}scales(){return yc.map((e,t)=>{const n=this.charts[t]?.scales.y;return{key:e.key,distr:n?.distr??1,min:n?.min??null,max:n?.max??null}})}update(e,t=[],n={energy:1,j3:1}){this.events=t;const s=e.t.length,r=e.t[s-1]??NaN;yc.forEach((a,o)=>{const l=this.charts[o],c=this.els[o],h=this.shown[o];if(l===void 0||c===void 0||h===void 0||!this.visibility.visible(c)||h.h===e&&h.n===s&&Object.is(h.t,r)&&h.ev===t)return;Object.assign(h,{h:e,n:s,t:r,ev:t});const u=e[a.key],d=a.drift;l.setData([e.t,d?u.map(m=>NE(m,n[d])):u])})}}function Ys(i,e=.1){let t=1/0,n=-1/0;for(const a of i)Number.isFinite(a)&&(a<t&&(t=a),a>n&&(n=a));if(t>n)return{lo:-1,hi:1};if(t===n)return{lo:t-Math.max(.5,Math.abs(t)*.1),hi:n+Math.max(.5,Math.abs(t)*.1)};const[s,r]=Ch(t,n,e);return{lo:s,hi:r}}function kE(i,e,t){const n=Math.max(e===null?0:e-i,.2*t);return{lo:i-.15*n,hi:i+2.2*n}}function Lo(i,e=Math.abs(i)){if(i===0)return"0";const t=Math.abs(i),n=Math.min(12,Math.max(3,Math.ceil(Math.log10(t/Math.max(e,1e-300)))+2));return t>=.01&&t<1e4?String(+i.toPrecision(n)):i.toExponential(Math.max(1,n-2))}class Ta{constructor(e,t,n,s,r=150){this.xLabel=n,this.yLabel=s,this.height=r;const a=document.createElement("div");a.className="plot curve";const o=document.createElement("div");o.className="curve-title",o.textContent=t,a.appendChild(o),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("aria-label",t),a.appendChild(this.canvas),e.appendChild(a),this.ctx=this.canvas.getContext("2d")}xLabel;yLabel;height;canvas;ctx;draw(e,t,n,s,r={}){const a=this.ctx;if(a===null)return;const o=Math.min(window.devicePixelRatio||1,2),l=Math.max(100,e),c=this.height;this.canvas.width!==Math.round(l*o)&&(this.canvas.width=Math.round(l*o),this.canvas.height=Math.round(c*o),this.canvas.style.width=`${l}px`,this.canvas.style.height=`${c}px`),a.setTransform(o,0,0,o,0,0),a.clearRect(0,0,l,c);const h=56,u=c-20,d=6,m=l-8,_=x=>h+(x-n.lo)/(n.hi-n.lo)*(m-h),M=x=>u-(x-s.lo)/(s.hi-s.lo)*(u-d);a.strokeStyle="#2a2f3a",a.strokeRect(h,d,m-h,u-d),a.fillStyle="#aab",a.font="11px system-ui, sans-serif",a.fillText(Lo(s.hi,s.hi-s.lo),4,d+10),a.fillText(Lo(s.lo,s.hi-s.lo),4,u),a.fillText(this.yLabel,4,(d+u)/2),a.fillText(Lo(n.lo,n.hi-n.lo),h,c-4);const p=Lo(n.hi,n.hi-n.lo);a.fillText(p,m-a.measureText(p).width,c-4),a.fillText(this.xLabel,(h+m)/2-10,c-4),a.save(),a.beginPath(),a.rect(h,d,m-h,u-d),a.clip(),r.hLine!==void 0&&r.hLine!==null&&this.line(a,h,M(r.hLine),m,M(r.hLine),"#ffb347"),r.vLine!==void 0&&r.vLine!==null&&this.line(a,_(r.vLine),d,_(r.vLine),u,"#888");for(const x of t){a.strokeStyle=x.color,a.lineWidth=1.5,a.beginPath();let A=!1;for(let S=0;S<x.x.length;S++){const R=x.x[S],y=x.y[S];if(!Number.isFinite(R)||!Number.isFinite(y)){A=!1;continue}const g=Math.max(-1e4,Math.min(1e4,M(y)));A?a.lineTo(_(R),g):a.moveTo(_(R),g),A=!0}a.stroke()}r.dot&&(a.fillStyle="#ff8c42",a.beginPath(),a.arc(_(r.dot[0]),M(r.dot[1]),3.5,0,2*Math.PI),a.fill()),a.restore();let f=d+12;a.textAlign="right";for(const x of t)x.label&&(a.fillStyle=x.color,a.fillText(`— ${x.label}`,m-4,f),f+=13);a.textAlign="left"}line(e,t,n,s,r,a){e.strokeStyle=a,e.lineWidth=1,e.setLineDash([4,3]),e.beginPath(),e.moveTo(t,n),e.lineTo(s,r),e.stroke(),e.setLineDash([])}}function BE(i){return Math.atan2(Math.hypot(i[0],i[1]),-i[2])}class zE{constructor(e){this.container=e,this.phase=new Ta(e,N("portrait.phase"),"z [m]","ż [m/s]"),this.potential=new Ta(e,N("portrait.veff"),"θ [rad]","E [J]"),this.em=new Ta(e,N("portrait.em"),"J₃ [kg m²/s]","E [J]");for(const t of[this.phase,this.potential,this.em])this.visibility.watch(t.canvas);this.note=document.createElement("p"),this.note.className="note",this.note.dataset.note="portraits",e.appendChild(this.note)}container;phase;potential;em;note;visibility=new vl;setModel(e){const t=Fh(e)??"";this.note.textContent!==t&&(this.note.textContent=t)}updateEM(e,t){if(!this.visibility.visible(this.em.canvas))return;const n=Math.max(200,this.container.clientWidth-8);if(e===null){this.em.draw(n,[],{lo:-1,hi:1},{lo:-1,hi:1});return}const s=e.top.energy,r=Ys([...e.boundary.j3.filter((o,l)=>(e.boundary.energy[l]??1/0)<2.6*s),t?.j3??0],.05),a={lo:e.bottom.energy-.15*s,hi:Math.max(2.6*s,(t?.energy??0)+.2*s)};this.em.draw(n,[{x:e.boundary.j3,y:e.boundary.energy,color:"#c9a0ff",label:N("portrait.emBoundary")}],r,a,{vLine:0,hLine:e.top.energy,dot:t?[t.j3,t.energy]:null})}update(e,t,n,s,r,a){const o=Math.max(200,this.container.clientWidth-8);if(this.visibility.visible(this.phase.canvas)){const c=t?[t.x[2],t.v[2]]:null,h=Ys(t?[...e.z,t.x[2]]:e.z),u=Ys(t?[...e.zdot,t.v[2]]:e.zdot);this.phase.draw(o,[{x:e.z,y:e.zdot,color:"#59c3ff",label:N("portrait.orbit")}],h,u,{dot:c})}if(!this.visibility.visible(this.potential.canvas))return;if(n===null||n.theta.length===0){this.potential.draw(o,[],{lo:0,hi:Math.PI},{lo:-1,hi:1});return}const l=kE(n.minimum.v_eff,t?.energy??null,s*Math.max(Math.abs(r),1)*a);this.potential.draw(o,[{x:n.theta,y:n.v_eff,color:"#7dff8a",label:"V_eff(θ)"}],{lo:0,hi:Math.PI},l,{hLine:t?.energy??null,vLine:t?BE(t.x):null})}}async function Ph(i,e){const t=await fetch(i,e),n=await t.json();if(!t.ok){const s=n.detail;throw new Error(typeof s=="string"?s:`${i}: HTTP ${t.status}`)}return n}function Do(i,e){return Ph(i,{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(e)})}const No=i=>i instanceof Error?i.message:String(i);class HE{constructor(e,t,n){this.store=e,this.reduced=t,this.explain=n}store;reduced;explain;veff=null;em=null;veffKey="";veffAt=-1/0;veffJ3=null;emKey="";exactEpoch=-1;reducedEpoch=-1;onFrames(){const e=this.store.status,t=this.store.trajectory[0],n=this.store.latest();if(!(e===null||t===void 0||n===null)){if(this.exactEpoch!==e.epoch&&this.fetchExact(e,t),this.reducedEpoch!==e.epoch&&this.fetchReduced(e,t),!Tg(e.model)){[this.veff,this.em,this.veffKey,this.emKey]=[null,null,"",""];return}this.fetchEM(e,t),this.fetchPotential(e,n)}}fetchPotential(e,t){const n=e.params,s=`${e.epoch}:${n.length}:${n.mass}:${n.g}`,r=performance.now(),a=Math.abs(t.j3-(this.veffJ3??NaN))>.001*Math.max(Math.abs(t.j3),1e-9);s===this.veffKey&&!(a&&r-this.veffAt>1e3)||(s!==this.veffKey&&(this.veff=null),[this.veffKey,this.veffAt,this.veffJ3]=[s,r,t.j3],Do("api/effective_potential",{length:n.length,mass:n.mass,g:n.g,j3:t.j3}).then(o=>{this.veffKey===s&&(this.veff=o)},o=>this.explain(`V_eff: ${No(o)}`)))}fetchEM(e,t){const n=e.params,s=`${n.length}:${n.mass}:${n.g}`;s!==this.emKey&&(this.emKey=s,this.em=null,n.g!==0&&Do("api/em_map",{length:n.length,mass:n.mass,g:n.g,x:t.x,v:t.v}).then(r=>{this.emKey===s&&(this.em=r)},r=>this.explain(`energy–momentum map: ${No(r)}`)))}fetchReduced(e,t){if(this.reducedEpoch=e.epoch,e.model!=="ideal"){this.reduced.setNote(Fh(e.model)??N("note.reducedIdeal",{model:e.model}));return}this.reduced.setNote(null);const n=e.params;Do("api/reduced",{length:n.length,mass:n.mass,g:n.g,x:t.x,v:t.v}).then(s=>{this.store.status?.epoch===e.epoch&&this.reduced.set(s)},s=>this.reduced.setNote(`reduced view: ${No(s)}`))}fetchExact(e,t){if(this.exactEpoch=e.epoch,e.model!=="ideal")return;const n=e.params;Do("api/exact",{length:n.length,mass:n.mass,g:n.g,x:t.x,v:t.v}).then(s=>{this.store.status?.epoch===e.epoch&&this.store.setExact(s)},s=>{this.store.status?.epoch===e.epoch&&this.store.setExact(null,No(s))})}}function VE(i,e){const t=e*e;return[i.x[2]/e,i.v[2]/e,(i.v[0]**2+i.v[1]**2+i.v[2]**2)/t]}function GE(i){const e=Math.max(...i.surface.sigma2.map(Math.abs),1e-9),t=Math.max(...i.orbit.sigma3,i.point[2],1e-9);return{s2:e,s3top:1.6*t+1e-9}}class pu{constructor(e,t){this.container=e;const n=document.createElement("div");n.className="curve-title",n.textContent=N("data.reduced"),e.appendChild(n),this.renderer=new tm({antialias:t.antialias,preserveDrawingBuffer:!0}),this.renderer.localClippingEnabled=!0,this.renderer.setPixelRatio(t.pixelRatio),this.renderer.domElement.className="reduced-canvas",e.appendChild(this.renderer.domElement),this.note=document.createElement("p"),this.note.className="note",e.appendChild(this.note),this.scene.background=new ct(1448482),this.camera.up.set(0,0,1),this.camera.position.set(3.2,-3.6,2.2),this.controls=new im(this.camera,this.renderer.domElement),this.point=new sn(new os(.05,16,12),new Rs({color:16747586,depthTest:!1,transparent:!0})),this.point.renderOrder=3,this.point.visible=!1,this.scene.add(this.group,this.point,new Gp(1.2)),this.resize(),new ResizeObserver(()=>this.resize()).observe(e),new IntersectionObserver(s=>{this.visible=s.some(r=>r.isIntersecting)}).observe(this.renderer.domElement),this.controls.addEventListener("change",()=>{this.dirty=!0})}container;renderer;camera=new $n(35,1,.01,100);controls;scene=new Ap;group=new Wi;point;scales=null;note;visible=!1;lastDrawn=-1/0;dirty=!0;resize(){const e=Math.max(200,this.container.clientWidth-8),t=220;this.renderer.setSize(e,t,!1),this.renderer.domElement.style.width=`${e}px`,this.renderer.domElement.style.height=`${t}px`,this.camera.aspect=e/t,this.camera.updateProjectionMatrix()}setNote(e){this.note.textContent=e??"",e!==null&&this.set(null)}set(e){for(const y of[...this.group.children]){this.group.remove(y);const g=y;g.geometry?.dispose(),g.material?.dispose()}if(this.scales=e===null?null:GE(e),this.dirty=!0,e===null||this.scales===null)return;const{s2:t,s3top:n}=this.scales,s=(y,g,b)=>new z(y,g/t,2*b/n-1),r=[new Ti(new z(0,0,-1),1)],{sigma1:a,sigma2:o,sigma3:l}=e.surface,c=[];a.forEach((y,g)=>o.forEach((b,k)=>c.push(...s(y,b,l[g]?.[k]??NaN).toArray())));const h=[],u=o.length;for(let y=0;y+1<a.length;y++)for(let g=0;g+1<u;g++){const b=y*u+g;h.push(b,b+u,b+1,b+1,b+u,b+u+1)}const d=new Bt;d.setAttribute("position",new rn(c,3)),d.setIndex(h);const m={color:9417727,transparent:!0,opacity:.25,side:fi,clippingPlanes:r};this.group.add(new sn(d,new Rs({...m,depthWrite:!1}))),this.group.add(new sn(d.clone(),new Rs({...m,wireframe:!0,opacity:.25})));const{h:_,gamma:M}=e.plane,p=(y,g)=>s(y,g,2*(_-M*y)),f=new Bt().setFromPoints([p(-1,-t),p(1,-t),p(1,t),p(-1,t)]);f.setIndex([0,1,2,0,2,3]);const x=new Rs({color:16757575,transparent:!0,opacity:.22,side:fi,depthWrite:!1,clippingPlanes:[...r,new Ti(new z(0,0,1),1)]});this.group.add(new sn(f,x));const A=e.orbit,S=new Bt().setFromPoints(A.sigma1.map((y,g)=>s(y,A.sigma2[g]??NaN,A.sigma3[g]??NaN))),R=new Ki(S,new gi({color:5882879,depthTest:!1,transparent:!0}));R.renderOrder=2,this.group.add(R),this.point.visible=!0}update(e,t){if(this.scales!==null&&e!==null){const[s,r,a]=VE(e,t);this.point.position.set(s,r/this.scales.s2,2*a/this.scales.s3top-1)}this.point.visible=this.scales!==null&&e!==null;const n=performance.now();!this.visible||!this.dirty&&n-this.lastDrawn<pu.MIN_INTERVAL||(this.lastDrawn=n,this.dirty=!1,this.controls.update(),this.renderer.render(this.scene,this.camera))}static MIN_INTERVAL=250}class WE{constructor(e){this.intervalMs=e}intervalMs;last=-1/0;due(e){return e-this.last<this.intervalMs?!1:(this.last=e,!0)}reset(){this.last=-1/0}}class XE{last=null;changed(e){const t=this.last;return t!==null&&t.length===e.length&&e.every((n,s)=>Object.is(n,t[s]))?!1:(this.last=[...e],!0)}}class $E{sums=new Map;add(e,t){const n=this.sums.get(e);n===void 0?this.sums.set(e,{ms:t,count:1}):(n.ms+=t,n.count++)}take(){const e={};for(const[t,n]of this.sums)e[t]={ms:n.ms/n.count,count:n.count};return this.sums.clear(),e}}function qE(i){const e={model:i.model,length:i.params.length,mass:i.params.mass,g:i.params.g,params:{...i.model_params},x:i.start.x,v:i.start.v,method:i.method,dt:i.dt,t0:i.t0,t_end:Math.max(i.t0+100,Math.ceil(i.t))},t=i.title??i.scenario;return t&&(e.title=`${t} (from the lab)`),e}function bs(i){return Object.is(i,-0)?"-0":String(i)}function YE(i){const e=new URLSearchParams;return i.scenario!==void 0&&e.set("s",i.scenario),i.model!==void 0&&e.set("model",i.model),i.modelParams!==void 0&&Object.keys(i.modelParams).length>0&&e.set("mp",Object.entries(i.modelParams).map(([t,n])=>`${t}:${bs(n)}`).join(",")),i.length!==void 0&&e.set("l",bs(i.length)),i.mass!==void 0&&e.set("m",bs(i.mass)),i.g!==void 0&&e.set("g",bs(i.g)),i.method!==void 0&&e.set("method",i.method),i.dt!==void 0&&e.set("dt",bs(i.dt)),i.timeScale!==void 0&&e.set("ts",bs(i.timeScale)),i.x!==void 0&&e.set("x",i.x.map(bs).join(",")),i.v!==void 0&&e.set("v",i.v.map(bs).join(",")),i.paused===!0&&e.set("paused","1"),e.toString()}const KE=/^[A-Za-z0-9_.-]{1,100}$/;function bc(i){if(!/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(i.trim()))return null;const e=Number(i);return Number.isFinite(e)?e:null}function ZE(i){const e=new URLSearchParams(i.startsWith("?")?i.slice(1):i),t={},n=[],s=new Set(["s","model","mp","l","m","g","method","dt","ts","x","v","paused","lang"]);for(const S of e.keys())s.has(S)||n.push(`unknown URL key ${S}`);const r=S=>{const R=e.get(S);if(R!==null){if(!KE.test(R)){n.push(`${S} = ${JSON.stringify(R)} is not a name`);return}return R}},a=S=>{const R=e.get(S);if(R===null)return;const y=bc(R);return y===null&&n.push(`${S} = ${JSON.stringify(R)} is not a finite number`),y??void 0},o=S=>{const R=e.get(S);if(R===null)return;const y=R.split(",").map(bc);if(y.length!==3||y.some(g=>g===null)){n.push(`${S} = ${JSON.stringify(R)} is not three finite numbers`);return}return y},l=r("s");l!==void 0&&(t.scenario=l);const c=r("model");c!==void 0&&(t.model=c);const h=e.get("mp");if(h!==null){const S={};for(const R of h.split(",")){const[y,g,...b]=R.split(":"),k=g===void 0?null:bc(g);if(y===void 0||!/^[A-Za-z_][A-Za-z0-9_]{0,40}$/.test(y)||k===null||b.length>0){n.push(`mp: ${JSON.stringify(R)} is not name:number`);continue}S[y]=k}Object.keys(S).length>0&&(t.modelParams=S)}const u=a("l");u!==void 0&&(t.length=u);const d=a("m");d!==void 0&&(t.mass=d);const m=a("g");m!==void 0&&(t.g=m);const _=r("method");_!==void 0&&(t.method=_);const M=a("dt");M!==void 0&&(t.dt=M);const p=a("ts");p!==void 0&&(t.timeScale=p);const f=o("x"),x=o("v");f===void 0!=(x===void 0)&&n.length===0?n.push("the start needs both x and v"):f!==void 0&&x!==void 0&&(t.x=f,t.v=x);const A=e.get("paused");return A!==null&&(t.paused=A==="1"||A==="true"),{value:t,problems:n}}function Vf(i){const e={model:i.model,length:i.params.length,mass:i.params.mass,g:i.params.g,method:i.method,dt:i.dt,timeScale:i.time_scale,x:i.start.x,v:i.start.v};return i.scenario!==null&&(e.scenario=i.scenario),Object.keys(i.model_params).length>0&&(e.modelParams={...i.model_params}),i.paused&&(e.paused=!0),e}function Lh(i){const e=[];i.scenario!==void 0&&e.push({type:"load_scenario",name:i.scenario}),i.model!==void 0&&e.push({type:"set_model",model:i.model,params:{...i.modelParams}});const t={type:"set_params"};i.length!==void 0&&(t.length=i.length),i.mass!==void 0&&(t.mass=i.mass),i.g!==void 0&&(t.g=i.g),Object.keys(t).length>1&&e.push(t);const n={type:"set_method"};return i.method!==void 0&&(n.method=i.method),i.dt!==void 0&&(n.dt=i.dt),Object.keys(n).length>1&&e.push(n),i.timeScale!==void 0&&e.push({type:"set_time_scale",time_scale:i.timeScale}),i.x!==void 0&&i.v!==void 0&&e.push({type:"set_state",x:i.x,v:i.v}),e.length>0&&e.push({type:"reset"}),i.paused===!0&&e.push({type:"pause"}),e}const Gf="(max-width: 700px), (max-aspect-ratio: 3/4)";function Cr(i,e,t,n=!1){const s=document.createElement("button");return s.type="button",s.dataset.action=i,s.textContent=e,s.title=t,s.setAttribute("aria-label",t),n&&s.classList.add("when-open"),s}class JE{constructor(e,t,n){this.panel=t,e.setAttribute("aria-label",N("toolbar.label")),this.toggle=Cr("panel","",N("toolbar.collapse")),this.toggle.setAttribute("aria-controls","panel-body"),this.toggle.addEventListener("click",()=>{this.setCollapsed(!t.classList.contains("collapsed")),n.collapsed(t.classList.contains("collapsed"))}),this.runButton=Cr("run",N("toolbar.pauseShort"),N("toolbar.pause")),this.runButton.addEventListener("click",()=>n.run());const s=Cr("reset",N("toolbar.resetShort"),N("toolbar.reset"));s.addEventListener("click",()=>n.reset());const r=Cr("step",N("toolbar.stepShort"),N("toolbar.step"));r.addEventListener("click",()=>n.step()),this.recordButton=Cr("record",N("toolbar.recordShort"),N("toolbar.record")),this.recordButton.setAttribute("aria-pressed","false"),this.recordButton.addEventListener("click",()=>n.record());const a=Cr("help","?",N("toolbar.help"));a.addEventListener("click",()=>n.help());const o=document.createElement("select");o.dataset.input="language",o.classList.add("when-open"),o.setAttribute("aria-label",N("toolbar.language"));for(const[l,c]of Object.entries(Oa)){const h=document.createElement("option");h.value=l,h.textContent=c.name,o.appendChild(h)}o.value=yg(),o.addEventListener("change",()=>n.language(o.value)),e.append(this.toggle,this.runButton,s,r,this.recordButton,a,o),this.setCollapsed(!1),window.matchMedia(Gf).addEventListener("change",()=>this.setCollapsed(t.classList.contains("collapsed")))}panel;runButton;recordButton;toggle;setCollapsed(e){this.panel.classList.toggle("collapsed",e),this.toggle.setAttribute("aria-expanded",String(!e));const t=window.matchMedia(Gf).matches;this.toggle.textContent=t?e?"▴":"▾":e?"◂":"▸",this.toggle.title=N(e?"toolbar.expand":"toolbar.collapse"),this.toggle.setAttribute("aria-label",this.toggle.title)}showRunning(e){const t=N(e?"toolbar.startShort":"toolbar.pauseShort");this.runButton.textContent!==t&&(this.runButton.textContent=t,this.runButton.title=N(e?"toolbar.start":"toolbar.pause"),this.runButton.setAttribute("aria-label",this.runButton.title))}showRecording(e){this.recordButton.setAttribute("aria-pressed",String(e)),this.recordButton.textContent=N(e?"toolbar.recordStopShort":"toolbar.recordShort"),this.recordButton.title=N(e?"toolbar.recordStop":"toolbar.record")}}const Wf=[["gravity.earth",9.81],["gravity.moon",1.62],["gravity.mars",3.71],["gravity.jupiter",24.79],["gravity.zero",0],["gravity.negative",-9.81]];function jE(i,e){return i===null?null:"damping"in(i.model_params??{})?{type:"set_params",params:{damping:e}}:i.model==="ideal"&&e>0?{type:"set_model",model:"damped",params:{damping:e}}:null}function QE(i,e,t){for(const[n,s]of[["θ₀",i],["φ₀",e],["φ̇₀",t]])if(!Number.isFinite(s))return N("start.notNumber",{name:n});return i<0||i>180?N("start.thetaRange",{value:i}):{type:"set_state",theta:i/Gn,phi:e/Gn,theta_dot:0,phi_dot:t/Gn}}function Qt(i,e={},t=""){const n=document.createElement(i);for(const[s,r]of Object.entries(e))n.setAttribute(s,r);return t&&(n.textContent=t),n}function Pr(i,e,t){const n=Qt("section",{class:"tools","data-tool":t});return n.appendChild(Qt("h3",{},e)),i.appendChild(n),n}function wc(i,e,t,n){const s=Qt("label");s.append(`${i} `);const r=Qt("input",{type:"number",step:n,name:e,"data-input":e});return r.value=String(t),r.style.width="5.5em",s.appendChild(r),[s,r]}class eT{constructor(e,t,n){this.store=t;const s=()=>this.now=t.playT??this.now,r=Pr(e,N("tools.start"),"start"),[a,o]=wc("θ₀ [°]","theta0",30,"1"),[l,c]=wc("φ₀ [°]","phi0",0,"1"),[h,u]=wc("φ̇₀ [°/s]","phidot0",0,"10");o.title=N("tools.thetaHelp"),c.title=N("tools.phiHelp"),u.title=N("tools.phiDotHelp");const d=Qt("button",{type:"button","data-action":"set-start"},N("tools.setStart")),m=()=>{const g=QE(Number(o.value),Number(c.value),Number(u.value));typeof g=="string"?n.explain(g):n.send(g)};d.addEventListener("click",m);for(const g of[o,c,u])g.addEventListener("keydown",b=>b.key==="Enter"&&m());r.append(a,l,h,d);const _=Pr(e,N("tools.world"),"world"),M=Qt("label");M.append(`${N("tools.gravity")} `),this.gravity=Qt("select",{"data-input":"gravity-preset"}),this.gravity.appendChild(Qt("option",{value:""},N("gravity.custom")));for(const[g,b]of Wf)this.gravity.appendChild(Qt("option",{value:String(b)},`${N(g)} (${b} m/s²)`));this.gravity.addEventListener("change",()=>{this.gravity.value!==""&&n.send({type:"set_params",g:Number(this.gravity.value)})}),M.appendChild(this.gravity);const p=Qt("label");p.append(`${N("tools.friction")} `),this.friction=Qt("input",{type:"range",min:"0",max:"2",step:"0.01","data-input":"friction"}),this.friction.value="0",this.friction.title=N("tools.frictionHelp"),this.frictionValue=Qt("output"),this.friction.addEventListener("input",()=>{this.frictionValue.textContent=`${Number(this.friction.value).toFixed(2)} 1/s`}),this.friction.addEventListener("change",()=>{const g=jE(t.status,Number(this.friction.value));g!==null?n.send(g):Number(this.friction.value)>0&&n.explain(N("tools.noFriction",{model:t.status?.model??"?"}))}),p.append(this.friction," ",this.frictionValue),_.append(M,p);const f=Pr(e,N("tools.now"),"angles");this.angleText=Qt("div",{class:"big","data-readout":"angles","aria-live":"off"}),f.appendChild(this.angleText);const x=Pr(e,N("tools.stopwatch"),"stopwatch");this.watchText=Qt("div",{class:"big","data-readout":"stopwatch"},"0.000 s"),this.watchButton=Qt("button",{type:"button","data-action":"stopwatch"},N("tools.swStart"));const A=Qt("button",{type:"button","data-action":"lap"},N("tools.swLap")),S=Qt("button",{type:"button","data-action":"stopwatch-reset"},N("tools.swReset"));this.lapList=Qt("ol",{class:"laps"}),this.watchButton.addEventListener("click",()=>{this.stopwatch.running?this.stopwatch.stop(s()):this.stopwatch.start(s()),this.watchButton.textContent=this.stopwatch.running?N("tools.swStop"):N("tools.swStart")}),A.addEventListener("click",()=>this.stopwatch.lap(s())),S.addEventListener("click",()=>{this.stopwatch.reset(),this.watchButton.textContent=N("tools.swStart")}),x.append(this.watchText,this.watchButton," ",A," ",S,this.lapList);const R=Pr(e,N("tools.period"),"period");R.title=N("tools.periodHelp"),this.periodTable=Qt("table",{"data-readout":"period"}),R.appendChild(this.periodTable);const y=Pr(e,N("tools.overlays"),"overlays");for(const g of["ruler","protractor"]){const b=Qt("label"),k=Qt("input",{type:"checkbox","data-input":g});k.addEventListener("change",()=>n.overlay(g,k.checked)),b.append(k,` ${N(g==="ruler"?"tools.ruler":"tools.protractor")}`),y.appendChild(b)}}store;stopwatch=new ky;angleText;watchText;lapList;watchButton;periodTable;friction;frictionValue;gravity;now=0;sync(e){const t=Wf.find(([,s])=>s===e.params.g);document.activeElement!==this.gravity&&(this.gravity.value=t?String(t[1]):"");const n=e.model_params?.damping;document.activeElement!==this.friction&&(this.friction.value=String(n??0),this.friction.disabled=n===void 0&&e.model!=="ideal",this.frictionValue.textContent=`${(n??0).toFixed(2)} 1/s`)}update(e,t){t!==null&&(this.now=t);const n=e===null?null:_h(e),s=n===null?"—":`θ = ${(n.theta*Gn).toFixed(1)}°   φ = ${(n.phi*Gn).toFixed(1)}°`;this.angleText.textContent!==s&&(this.angleText.textContent=s);const r=`${this.stopwatch.reading(this.now).toFixed(3)} s`;this.watchText.textContent!==r&&(this.watchText.textContent=r);const a=this.stopwatch.laps.map(o=>`${o.toFixed(3)} s`).join("|");this.lapList.dataset.shown!==a&&(this.lapList.dataset.shown=a,this.lapList.replaceChildren(...this.stopwatch.laps.map(o=>Qt("li",{},`${o.toFixed(3)} s`)))),this.fillPeriod()}fillPeriod(){const e=this.store.periodTimer.reading(),t=e.kind==="swing"&&e.amplitude!==null?tT(this.store.status,e.amplitude):null,n=Wy(e,this.store.exact,t),s=([u,d])=>u===null||d===null||d===0?"":`${((u-d)/d*100).toFixed(2)} %`,r=u=>u===null?"—":(u*Gn).toFixed(2),a=e.kind===null?N("tools.kindNone"):e.kind==="orbit"?N("tools.kindOrbit"):e.lowPerPeriod===1?N("tools.kindOver"):N("tools.kindSwing"),o=this.store.exact!==null?N("tools.exact"):N("tools.theory"),l=[["head","",N("tools.measured"),o,N("tools.difference")],["kind",N("tools.motion"),a,"",""]];n.swing?(l.push(["period",N("tools.periodSwing"),pt(n.period[0],5),pt(n.period[1],5),s(n.period)]),l.push(["amplitude",N("tools.amplitude"),r(e.amplitude),"",""])):(l.push(["period",N("tools.periodZ"),pt(n.period[0],5),pt(n.period[1],5),s(n.period)]),l.push(["advance",N("tools.advance"),r(n.advance[0]),r(n.advance[1]),s(n.advance)]),l.push(["precession",N("tools.precession"),r(n.precession[0]),r(n.precession[1]),""]),l.push(["band",N("tools.band"),e.thetaMin===null?"—":`${r(e.thetaMin)} … ${r(e.thetaMax)}`,"",""]));const c=this.periodTable;for(;c.rows.length>l.length;)c.deleteRow(-1);l.forEach(([u,...d],m)=>{const _=c.rows[m]??c.insertRow();for(_.dataset.row=u;_.cells.length<4;)_.insertCell();d.forEach((M,p)=>{const f=_.cells[p];f&&f.textContent!==M&&(f.textContent=M)})});const h=e.intervals===0?N("tools.periodWait"):N(n.swing?"tools.periodCount":"tools.periodCountZ",{n:e.intervals});c.caption?.textContent!==h&&(c.createCaption().textContent=h),c.dataset.period=e.period===null?"":String(e.period),c.dataset.kind=e.kind??""}}function tT(i,e){if(i===null)return null;const t=i.model_params??{},n=s=>(t[s]??0)===0;return i.model==="damped"&&!(n("drag")&&n("forcing_amplitude")&&n("gravity_x")&&n("gravity_y"))||i.model!=="ideal"&&i.model!=="damped"?null:Hy(i.params.length,i.params.g,t.damping??0,e)}const nT={kinetic:"#7dff8a",potential:"#59c3ff",lost:"#ff5d73",total:"#e8e8e8"};class iT{canvas;ctx;scale=1;shown=null;constructor(e){const t=document.createElement("h3");t.textContent=N("energy.title"),e.appendChild(t),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("role","img"),this.canvas.setAttribute("aria-label",N("energy.title")),e.appendChild(this.canvas),this.ctx=this.canvas.getContext("2d")}rescale(){this.scale=1}draw(e,t){this.shown=e;const n=this.ctx;if(n===null)return;const s=Math.min(window.devicePixelRatio||1,2),r=Math.max(200,(this.canvas.parentElement?.clientWidth??300)-4),a=130;if(this.canvas.width!==Math.round(r*s)&&(this.canvas.width=Math.round(r*s),this.canvas.height=Math.round(a*s),this.canvas.style.width=`${r}px`,this.canvas.style.height=`${a}px`),n.setTransform(s,0,0,s,0,0),n.clearRect(0,0,r,a),e===null)return;const o=[["kinetic",N("energy.kinetic"),e.kinetic],["potential",N("energy.potential"),e.potential]];t&&o.push(["lost",N("energy.lost"),e.lost]),o.push(["total",N("energy.total"),e.total]);const l=Math.max(...o.map(([,,m])=>Math.abs(m)),1e-12);this.scale=l>this.scale?l:Math.max(l,.995*this.scale);const c=14,h=a-30,u=h,d=r/o.length;n.font="11px system-ui, sans-serif",n.textAlign="center",o.forEach(([m,_,M],p)=>{const f=d*p+d*.2,x=d*.6,A=Math.abs(M)/this.scale*(h-c);n.fillStyle=nT[m],M>=0?n.fillRect(f,u-A,x,A):(n.globalAlpha=.5,n.fillRect(f,u-A,x,A),n.globalAlpha=1),n.fillStyle="#dde3ee",n.fillText(_,f+x/2,a-16),n.fillText(`${M.toPrecision(4)} J`,f+x/2,a-3)}),n.strokeStyle="#555",n.beginPath(),n.moveTo(0,u+.5),n.lineTo(r,u+.5),n.stroke()}}const Xf=(i,e)=>.5*e.mass*(i.v[0]**2+i.v[1]**2+i.v[2]**2),Dh=[{name:"t",label:"var.t",unit:"s",get:i=>i.t},{name:"theta",label:"var.theta",unit:"°",get:i=>_h(i.x).theta*Gn},{name:"phi",label:"var.phi",unit:"°",get:i=>_h(i.x).phi*Gn},{name:"x",label:"var.x",unit:"m",get:i=>i.x[0]},{name:"y",label:"var.y",unit:"m",get:i=>i.x[1]},{name:"z",label:"var.z",unit:"m",get:i=>i.x[2]},{name:"zdot",label:"var.zdot",unit:"m/s",get:i=>i.v[2]},{name:"speed",label:"var.speed",unit:"m/s",get:i=>Math.hypot(...i.v)},{name:"energy",label:"var.energy",unit:"J",get:i=>i.energy},{name:"kinetic",label:"var.kinetic",unit:"J",get:Xf},{name:"potential",label:"var.potential",unit:"J",get:(i,e)=>i.energy-Xf(i,e)},{name:"j3",label:"var.j3",unit:"kg m²/s",get:i=>i.j3},{name:"tension",label:"var.tension",unit:"N",get:i=>i.tension},{name:"power",label:"var.power",unit:"W",get:i=>i.power},{name:"radius",label:"var.radius",unit:"m",get:i=>Math.hypot(...i.x)}];function Aa(i){return Dh.find(e=>e.name===i)??Dh[0]}function $f(i,e,t,n){const[s,r]=[Aa(e),Aa(t)];return{x:i.map(a=>s.get(a,n)),y:i.map(a=>r.get(a,n))}}class sT{constructor(e){this.container=e;const t=document.createElement("div");t.className="tools chosen",t.dataset.tool="chosen";const n=document.createElement("h3");n.textContent=N("chosen.title"),t.appendChild(n);for(const s of["y","x"]){const r=document.createElement("label");r.append(`${N(s==="x"?"chosen.xAxis":"chosen.yAxis")} `);const a=document.createElement("select");a.dataset.input=`chosen-${s}`;for(const o of Dh){const l=document.createElement("option");l.value=o.name,l.textContent=`${N(o.label)} [${o.unit}]`,a.appendChild(l)}a.value=this.choice[s],a.addEventListener("change",()=>{this.choice[s]=a.value,this.labels()}),r.appendChild(a),t.append(r," ")}e.appendChild(t),this.plot=new Ta(e,"","","",170),this.plot.canvas.dataset.plot="chosen",this.visibility.watch(this.plot.canvas),this.labels()}container;plot;visibility=new vl;choice={x:"t",y:"theta"};labels(){const[e,t]=[Aa(this.choice.x),Aa(this.choice.y)];this.plot.xLabel=`${N(e.label)} [${e.unit}]`,this.plot.yLabel=`${N(t.label)} [${t.unit}]`}update(e,t,n=null){if(!this.visibility.visible(this.plot.canvas))return;const r=[{...$f(e,this.choice.x,this.choice.y,t),color:"#59c3ff",label:N(n?"twin.first":Aa(this.choice.y).label)}];n!==null&&r.push({...$f(n,this.choice.x,this.choice.y,t),color:"#c8f560",label:N("twin.second")});const a=r.flatMap(l=>l.x),o=r.flatMap(l=>l.y);this.plot.draw(this.container.clientWidth-8,r,Ys(a,.02),Ys(o))}}function rT(i,e){const t=1.1*(i+e),n=Math.hypot(3.9,3.3);return[t*3.9/n,t*3.3/n,0]}function aT(i,e){const t=Math.hypot(...i),n=Math.atan2(Math.hypot(i[0],i[1]),-i[2])+e,s=Math.atan2(i[1],i[0]);return[t*Math.sin(n)*Math.cos(s),t*Math.sin(n)*Math.sin(s),-t*Math.cos(n)]}function oT(i,e){const t=[];i.scenario&&t.push({type:"load_scenario",name:i.scenario});const n=e.mode==="damped",s=e.mode==="own",r=n&&i.model==="ideal"?"damped":i.model,a={...i.model_params};if(n&&(a.damping=e.damping),t.push({type:"set_model",model:r,params:a}),t.push({type:"set_params",length:s?e.length:i.params.length,mass:s?e.mass:i.params.mass,g:i.params.g}),t.push({type:"set_method",method:e.mode==="method"?e.method:i.method,dt:i.dt}),s)t.push({type:"set_state",theta:e.theta,phi:0,theta_dot:0,phi_dot:0});else{const o=e.mode==="epsilon"?aT(i.start.x,e.epsilon):i.start.x;t.push({type:"set_state",x:o,v:i.start.v,project:!0})}return t.push({type:"set_time_scale",time_scale:i.time_scale}),t.push({type:"reset"}),t.push({type:i.paused?"pause":"resume"}),t}function lT(i,e){const t=i.length;if(t===0)return null;const n=i[0],s=i[t-1];if(e<n.t||e>s.t)return null;let r=0,a=t-1;for(;a-r>1;){const p=r+a>>1;i[p].t<=e?r=p:a=p}const o=i[r],l=i[a],c=l.t-o.t;if(!(c>0))return[o.x[0]+o.pivot[0],o.x[1]+o.pivot[1],o.x[2]+o.pivot[2]];const h=(e-o.t)/c,[u,d,m,_]=[2*h**3-3*h**2+1,h**3-2*h**2+h,-2*h**3+3*h**2,h**3-h**2],M=p=>u*o.x[p]+d*c*o.v[p]+m*l.x[p]+_*c*l.v[p]+(1-h)*o.pivot[p]+h*l.pivot[p];return[M(0),M(1),M(2)]}function qf(i,e){const t=[],n=[];for(const s of i){const r=lT(e,s.t);r!==null&&(t.push(s.t),n.push(Math.hypot(s.x[0]+s.pivot[0]-r[0],s.x[1]+s.pivot[1]-r[1],s.x[2]+s.pivot[2]-r[2])))}return{t,d:n}}class cT{constructor(e,t,n,s,r){this.first=t,this.socket=s,this.actions=r;const a=document.createElement("section");a.className="tools",a.dataset.tool="twin";const o=document.createElement("h3");o.textContent=N("twin.title"),a.appendChild(o);const l=document.createElement("label");l.append(`${N("twin.mode")} `);const c=document.createElement("select");c.dataset.input="twin-mode";const h=[["off",N("twin.off")],["own",N("twin.own")],["epsilon",N("twin.epsilon")],["method",N("twin.method")],["damped",N("twin.damped")]];for(const[b,k]of h){const I=document.createElement("option");I.value=b,I.textContent=k,c.appendChild(I)}l.appendChild(c);const u=document.createElement("label");u.append("ε [°] ");const d=document.createElement("input");d.type="number",d.step="0.01",d.value="0.01",d.dataset.input="twin-epsilon",d.style.width="5em",u.appendChild(d);const m=document.createElement("label");m.append(`${N("twin.methodPick")} `);const _=document.createElement("select");_.dataset.input="twin-method";for(const b of n){const k=document.createElement("option");k.value=b.name,k.textContent=Go(b.name,b.order),_.appendChild(k)}_.value=n.some(b=>b.name==="rk4")?"rk4":n[0]?.name??"",m.appendChild(_);const M=document.createElement("label");M.append(`${N("twin.damping")} `);const p=document.createElement("input");p.type="number",p.step="0.1",p.min="0",p.value="0.5",p.dataset.input="twin-damping",p.style.width="5em",M.appendChild(p);const f=document.createElement("span"),x=(b,k,I,L)=>{const G=document.createElement("label");G.append(`${b} `);const W=document.createElement("input");return W.type="number",W.step=L,W.value=I,W.dataset.input=k,W.style.width="4.5em",G.appendChild(W),f.appendChild(G),W},A=x(N("twin.length"),"twin-length","0.5","0.05"),S=x(N("twin.mass"),"twin-mass","1","0.1"),R=x(N("twin.theta"),"twin-theta","10","1"),y=document.createElement("button");y.type="button",y.dataset.action="twin-start",y.textContent=N("twin.start");const g=()=>{u.hidden=c.value!=="epsilon",m.hidden=c.value!=="method",M.hidden=c.value!=="damped",f.hidden=c.value!=="own",y.hidden=c.value==="off"};c.addEventListener("change",()=>{g(),c.value==="off"&&this.stop()}),y.addEventListener("click",()=>{if(this.options.mode=c.value,this.options.epsilon=Number(d.value)/Gn,this.options.method=_.value,this.options.damping=Number(p.value),this.options.length=Number(A.value),this.options.mass=Number(S.value),this.options.theta=Number(R.value)/Gn,!Number.isFinite(this.options.epsilon)||!(this.options.damping>=0)){r.explain(N("twin.bad"));return}const b=this.options;if(b.mode==="own"&&!(b.length>0&&b.mass>0&&b.theta>=0&&b.theta<=Math.PI)){r.explain(N("twin.badOwn"));return}this.start()}),g(),this.setInputs=b=>{c.value=b.mode,d.value=String(b.epsilon*Gn),_.value=b.method,p.value=String(b.damping),A.value=String(b.length),S.value=String(b.mass),R.value=String(b.theta*Gn),g()},this.periods=document.createElement("table"),this.periods.dataset.readout="twin-periods",this.periods.hidden=!0,a.append(l," ",u,m,M,f," ",y,this.periods),e.appendChild(a),this.plot=new Ta(e,N("twin.separation"),"t [s]","|r₁ − r₂| [m]",140),this.plot.canvas.dataset.plot="separation",this.plot.canvas.parentElement?.setAttribute("hidden",""),this.visibility.watch(this.plot.canvas)}first;socket;actions;store=new sm;options={mode:"off",epsilon:.01/Gn,method:"rk4",damping:.5,length:.5,mass:1,theta:10/Gn};periods;setInputs;conn=null;pending=[];plot;visibility=new vl;get on(){return this.conn!==null}layout(){const[e,t]=[this.first.status,this.store.status];return this.conn===null||this.options.mode!=="own"||e===null||t===null?null:{offset:rT(e.params.length,t.params.length),length:t.params.length}}restore(e){Object.assign(this.options,e),this.setInputs(e),e.mode!=="off"&&this.start()}start(){const e=this.first.status;if(e===null)return this.actions.explain(N("msg.notConnected"));this.pending=oT(e,this.options),this.conn===null?this.conn=new Kf(this.socket,{onOpen:()=>this.flush(),onClose:()=>this.store.setConnected(!1),onFrames:t=>this.store.onFrames(t),onNotice:t=>{t.type==="status"?this.store.onStatus(t):t.type==="event"?this.store.onEvent(t):this.actions.explain(`${N("twin.second")}: ${t.message}`)},onProtocolError:t=>this.actions.explain(`${N("twin.second")}: ${t}`)}):this.flush(),this.actions.send({type:"reset"}),this.plot.canvas.parentElement?.removeAttribute("hidden"),this.periods.hidden=!1}flush(){if(!(this.conn===null||!this.conn.isOpen)){for(const e of this.pending)this.conn.send(e);this.pending=[]}}stop(){this.conn?.close(),this.conn=null,this.store.clear(),this.store.status=null,this.plot.canvas.parentElement?.setAttribute("hidden",""),this.periods.hidden=!0}mirror(e){this.conn!==null&&(e.type==="pause"||e.type==="resume"||e.type==="reset"||e.type==="step")&&this.conn.send(e)}drawn(e,t){if(this.conn===null||e===null||this.store.frames.length===0)return null;const n=this.store.frames;this.store.playT=Math.min(Math.max(e,n[0].t),n[n.length-1].t);const{start:s,end:r}=this.store.trailRange(t);return{frame:this.store.displayed(),trail:{frames:this.store.trail,start:s,end:r}}}update(e){if(this.conn!==null&&this.fillPeriods(),this.conn===null||!this.visibility.visible(this.plot.canvas))return;const t=qf(this.first.history.frames,this.store.trajectory);this.plot.draw(e,[{x:t.t,y:t.d,color:"#c8f560",label:N("twin.separation")}],Ys(t.t,.02),Ys([0,...t.d]))}fillPeriods(){const e=(n,s)=>{const r=s.status,a=s.periodTimer.reading(),o=r===null?null:Math.atan2(Math.hypot(r.start.x[0],r.start.x[1]),-r.start.x[2])*Gn;return[n,r===null?"—":r.params.length.toPrecision(3),r===null?"—":r.params.mass.toPrecision(3),o===null?"—":o.toFixed(1),a.period===null?"—":`${a.period.toFixed(4)} (${a.intervals})`]};[["",N("twin.colLength"),N("twin.colMass"),N("twin.colTheta"),N("twin.colPeriod")],e(N("twin.first"),this.first),e(N("twin.second"),this.store)].forEach((n,s)=>{const r=this.periods.rows[s]??this.periods.insertRow();for(;r.cells.length<n.length;)r.insertCell();n.forEach((a,o)=>{const l=r.cells[o];l&&l.textContent!==a&&(l.textContent=a)})})}separationNow(){return qf(this.first.history.frames,this.store.trajectory)}}const hT=i=>`#${i.toString(16).padStart(6,"0")}`,uT={velocity:"vec.velocity",momentum:"vec.momentum",gravity:"vec.gravity",tension:"vec.tension",net:"vec.net",angularMomentum:"vec.angularMomentum",torque:"vec.torque"};class dT{constructor(e){this.el=e,e.setAttribute("aria-label",N("help.title"));const t=document.createElement("div");t.className="help-box";const n=document.createElement("h2");n.textContent=N("help.title");const s=document.createElement("table"),r=[["Space","help.space"],["R","help.r"],["S","help.s"],["← → ↑ ↓","help.arrows"],["Page ↑ / Page ↓","help.page"],["Tab","help.tab"],["?","help.help"],["Esc","help.esc"]];for(const[h,u]of r){const d=s.insertRow(),m=d.insertCell(),_=document.createElement("kbd");_.textContent=h,m.appendChild(_),d.insertCell().textContent=N(u)}const a=document.createElement("h3");a.textContent=N("help.colours");const o=document.createElement("ul");o.className="colour-key";const l=[["#ff8c42",N("help.bob")],["#59c3ff",N("help.trail")],["#c8f560",N("help.twin")],...Object.entries(uT).map(([h,u])=>[hT(jh[h]),N(u)]),["#e6d3a3",N("help.ruler")]];for(const[h,u]of l){const d=document.createElement("li"),m=document.createElement("span");m.className="swatch",m.style.background=h,d.append(m,` ${u}`),o.appendChild(d)}const c=document.createElement("button");c.type="button",c.dataset.action="help-close",c.textContent=N("help.close"),c.addEventListener("click",()=>this.toggle(!1)),t.append(n,s,a,o,c),e.appendChild(t),e.addEventListener("click",h=>h.target===e&&this.toggle(!1))}el;returnFocus=null;get open(){return!this.el.hidden}toggle(e=!this.open){e!==this.open&&(e?(this.returnFocus=document.activeElement instanceof HTMLElement?document.activeElement:null,this.el.hidden=!1,this.el.querySelector("button")?.focus()):(this.el.hidden=!0,this.returnFocus?.focus()))}}const fT=300,pT=25e5;function mT(i){for(const e of["video/webm;codecs=vp9","video/webm;codecs=vp8","video/webm"])if(i(e))return e;return null}class gT{constructor(e,t){this.canvas=e,this.done=t}canvas;done;recorder=null;chunks=[];timer=null;get recording(){return this.recorder!==null}start(){if(this.recorder!==null)return null;if(typeof MediaRecorder>"u"||typeof this.canvas.captureStream!="function")return"no MediaRecorder";const e=mT(s=>MediaRecorder.isTypeSupported(s));if(e===null)return"no WebM";const t=this.canvas.captureStream(30),n=new MediaRecorder(t,{mimeType:e,videoBitsPerSecond:pT});return this.chunks=[],n.ondataavailable=s=>{s.data.size>0&&this.chunks.push(s.data)},n.onstop=()=>{for(const s of t.getTracks())s.stop();this.done(new Blob(this.chunks,{type:"video/webm"})),this.chunks=[]},n.start(1e3),this.recorder=n,this.timer=setTimeout(()=>this.stop(),fT*1e3),null}stop(){this.timer!==null&&clearTimeout(this.timer),this.timer=null;const e=this.recorder;this.recorder=null,e!==null&&e.state!=="inactive"&&e.stop()}}function _T(i,e){if(e)return null;switch(i){case" ":case"Spacebar":return"run";case"r":case"R":return"reset";case"s":case"S":return"step";case"?":return"help";case"Escape":return"close";default:return null}}function vT(i){switch(i){case"ArrowUp":case"ArrowRight":return 1;case"ArrowDown":case"ArrowLeft":return-1;case"PageUp":return 10;case"PageDown":return-10;case"Home":return-1/0;case"End":return 1/0;default:return null}}function xT(i,e=""){return typeof HTMLElement>"u"||!(i instanceof HTMLElement)?!1:e===" "&&(i instanceof HTMLButtonElement||i instanceof HTMLInputElement&&["checkbox","radio","button"].includes(i.type))||i.isContentEditable||i instanceof HTMLSelectElement||i instanceof HTMLTextAreaElement?!0:i instanceof HTMLInputElement?!["checkbox","radio","button"].includes(i.type):i.getAttribute("role")==="slider"}function Yf(i){for(const e of i.controllersRecursive()){const t=e.$slider;t!==void 0&&(t.setAttribute("aria-valuenow",String(e.getValue())),t.dataset.keys!=="1"&&(t.dataset.keys="1",t.tabIndex=0,t.setAttribute("role","slider"),t.setAttribute("aria-label",e.$name.textContent??""),e._min!==void 0&&t.setAttribute("aria-valuemin",String(e._min)),e._max!==void 0&&t.setAttribute("aria-valuemax",String(e._max)),t.addEventListener("keydown",n=>{const s=vT(n.key);if(s===null)return;n.preventDefault(),n.stopPropagation();const[r,a,o]=[e._min??-1/0,e._max??1/0,e._step??.01],l=Number(e.getValue()),c=s===1/0?a:s===-1/0?r:Math.min(a,Math.max(r,l+s*o));Number.isFinite(c)&&e.setValue(+c.toPrecision(12)),t.setAttribute("aria-valuenow",String(e.getValue()))})))}}const Nh=2*2**20,ST=["damped","ideal","rotating","slewing","vibrating"];function MT(i,e,t,n,s){if(t>Nh)return`${i}: ${(t/2**20).toFixed(1)} MiB; the lab fits files of at most ${Nh/2**20} MiB (use pendulab fit for larger ones)`;if(e.trim()==="")return`${i}: the file is empty`;const r={csv:e,name:i,model:n},a=s.split(/[\s,]+/).filter(o=>o!=="");return a.length>0&&(r.fit=a),r}const Ym=i=>typeof i=="number"&&Number.isFinite(i),yT=i=>Array.isArray(i)&&i.length===3&&i.every(Ym);function bT(i){if(typeof i!="object"||i===null)return"the fit answer is not an object";const e=i;if(typeof e.report!="string"||typeof e.scenario_toml!="string")return"the fit answer has no report";const t=e.measured;if(t!=null){const n=t,s=n.t,r=n.x;if(!Array.isArray(s)||!Array.isArray(r)||s.length!==r.length||!s.every(Ym)||!r.every(yT))return"the fit answer has a malformed measured path"}return{report:e.report,warnings:Array.isArray(e.warnings)?e.warnings.filter(n=>typeof n=="string"):[],params:e.params??{},converged:e.converged===!0,scenario_toml:e.scenario_toml,lab:e.lab??null,measured:t??null}}function wT(i){const e={model:i.model,modelParams:{...i.model_params},length:i.params.length,mass:i.params.mass,g:i.params.g,method:i.method,dt:i.dt,x:i.start.x,v:i.start.v};return Lh(e)}function ET(i){return Object.entries(i).map(([e,t])=>{const n=t.determined&&t.stderr!==null?` ± ${t.stderr.toPrecision(2)}`:" (not determined by these data)",s=t.unit&&t.unit!=="1"?` ${t.unit}`:"";return`${e} = ${t.value.toPrecision(6)}${n}${s}`})}function li(i,e={},t=""){const n=document.createElement(i);for(const[s,r]of Object.entries(e))n.setAttribute(s,r);return t&&(n.textContent=t),n}class TT{constructor(e,t){this.actions=t;const n=li("section",{class:"tools","data-tool":"fit"});n.appendChild(li("h3",{},N("fit.title")));const s=li("label");s.append(`${N("fit.load")} `),this.input=li("input",{type:"file",accept:".csv,.txt,.tsv,text/csv,text/plain","data-input":"fit-file"}),s.appendChild(this.input),s.title=N("fit.help");const r=li("label");r.append(`${N("fit.model")} `),this.model=li("select",{"data-input":"fit-model"});for(const o of ST)this.model.appendChild(li("option",{value:o},o));r.appendChild(this.model);const a=li("label");a.append(`${N("fit.params")} `),this.names=li("input",{type:"text","data-input":"fit-params",placeholder:N("fit.paramsDefault")}),this.names.style.width="12em",a.appendChild(this.names),a.title=N("fit.paramsHelp"),this.clear=li("button",{type:"button","data-action":"fit-clear"},N("fit.clear")),this.clear.disabled=!0,this.clear.addEventListener("click",()=>this.reset()),this.report=li("pre",{class:"fit-report","data-output":"fit-report","aria-live":"polite"}),this.report.hidden=!0;for(const o of[s,r,a,this.clear]){const l=li("p");l.appendChild(o),n.appendChild(l)}n.appendChild(this.report),e.appendChild(n),this.input.addEventListener("change",()=>{const o=this.input.files?.[0];o!==void 0&&this.send(o)})}actions;input;model;names;clear;report;busy=!1;reset(){this.report.hidden=!0,this.report.textContent="",this.clear.disabled=!0,this.input.value="",this.actions.cleared()}async send(e){if(this.busy)return;const t=e.size>Nh?"":await e.text(),n=MT(e.name,t,e.size,this.model.value,this.names.value);if(typeof n=="string")return this.actions.explain(n);this.busy=!0,this.input.disabled=!0,this.report.hidden=!1,this.report.textContent=N("fit.running",{name:e.name});try{const s=await fetch("api/fit",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(n)}),r=await s.json().catch(()=>({detail:`HTTP ${s.status}`}));if(!s.ok){const l=r.detail;throw new Error(typeof l=="string"?l:`HTTP ${s.status}`)}const a=bT(r);if(typeof a=="string")throw new Error(a);const o=[a.report,"",...ET(a.params),...a.warnings.map(l=>`warning: ${l}`)];a.measured===null&&o.push(N("fit.noPath")),this.report.textContent=o.join(`
`),this.clear.disabled=!1,this.actions.loaded(a,e.name)}catch(s){const r=s instanceof Error?s.message:String(s);this.report.textContent=`${e.name}: ${r}`,this.actions.explain(N("fit.failed",{why:r}))}finally{this.busy=!1,this.input.disabled=!1}}}function kt(i){const e=document.getElementById(i);if(e===null)throw new Error(`#${i} missing from index.html`);return e}function Io(i,e){const t=document.createElement("a");t.href=e,t.download=i,document.body.appendChild(t),t.click(),t.remove()}async function AT(){const i=Sg(new URLSearchParams(window.location.search).get("lang"),window.localStorage?.getItem("pendulab.lang")??null,navigator.languages??[navigator.language]);Mg(i),document.documentElement.lang=i,document.title=N("page.title"),kt("units").textContent=N("page.units"),kt("scene").setAttribute("aria-label",N("page.scene")),kt("panel").setAttribute("aria-label",N("page.panel"));const e=new sm,t=kt("message");let n=null;const s=(B,te=!1)=>{t.textContent=B,t.classList.toggle("info",te),t.classList.add("shown"),n!==null&&clearTimeout(n),n=setTimeout(()=>t.classList.remove("shown"),6e3)},[r,a]=await Promise.all([Ph("api/schema"),Ph("api/scenarios")]);e.tickHz=r.tick_hz;const o=ob(lb(),window.devicePixelRatio);o.software&&(kt("render").textContent=` · ${N("page.software")}`,kt("render").title=N("page.softwareHelp",{renderer:o.renderer??""}));const l=new Db(kt("scene"),o);l.renderer.domElement.setAttribute("role","img"),l.renderer.domElement.setAttribute("aria-label",N("page.scene"));const c={...bb},h=new $E,u=new sT(kt("plots")),d=new OE(kt("plots"),B=>h.add("plots drawn (uPlot)",B)),m=new zE(kt("portraits")),_=new pu(kt("reduced"),o),M=new Ug(kt("data")),p=ZE(window.location.search);p.problems.length>0&&s(`link: ${p.problems.join("; ")}`);let f=Lh(p.value),x=null,A=null;const S=B=>{x===null||!x.send(B)?s(N("msg.notConnected")):A?.mirror(B)},R=()=>S({type:e.status?.paused===!1?"pause":"resume"}),y=()=>S({type:"reset"}),g=()=>S({type:"step",n:1});let b=null;const k=new gT(l.renderer.domElement,B=>{B.slice(0,4).arrayBuffer().then(he=>{b={size:B.size,head:[...new Uint8Array(he)].map(ge=>ge.toString(16).padStart(2,"0")).join("")}});const te=URL.createObjectURL(B);Io(`pendulab-${e.status?.scenario??"lab"}.webm`,te),setTimeout(()=>URL.revokeObjectURL(te),1e4),s(N("msg.recorded",{mb:(B.size/1e6).toFixed(1)}),!0)}),I=new dT(kt("help")),L=new JE(kt("toolbar"),kt("panel"),{run:R,reset:y,step:g,record:()=>{if(k.recording)k.stop();else{const B=k.start();B!==null?s(N("msg.noRecording",{why:B})):s(N("msg.recording"),!0)}L.showRecording(k.recording)},help:()=>I.toggle(),language:B=>{window.localStorage?.setItem("pendulab.lang",B),fg(()=>e.status?.commands,()=>x?.sent??0,2e3).then(()=>{const te=new URLSearchParams(window.location.search);te.set("lang",B),window.location.search=te.toString()})},collapsed:()=>{}});document.addEventListener("keydown",B=>{const te=_T(B.key,B.ctrlKey||B.metaKey||B.altKey);if(te!==null){if(te==="close"){I.open&&I.toggle(!1);return}xT(B.target,B.key)||I.open&&te!=="help"||(B.preventDefault(),te==="run"?R():te==="reset"?y():te==="step"?g():I.toggle())}});const G=new eT(kt("tools"),e,{send:S,explain:s,overlay:(B,te)=>{c[B]=te}}),W=new iT(kt("energy"));new TT(kt("tools"),{loaded:(B,te)=>{if(l.setMeasured(B.measured?.x??null),B.lab!==null)for(const he of wT(B.lab))S(he);s(N("fit.loaded",{name:te}),!0)},cleared:()=>l.setMeasured(null),explain:s});const U=new Ub(kt("gui"),r,a,c,{send:S,explain:s,downloadCSV:()=>{const B=new Blob([e.toCSV()],{type:"text/csv"}),te=URL.createObjectURL(B);Io(`pendulab-${e.status?.scenario??"lab"}.csv`,te),setTimeout(()=>URL.revokeObjectURL(te),1e4)},downloadTOML:()=>{const B=e.status;if(B===null)return s(N("msg.notConnected"));fetch("api/scenario.toml",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(qE(B))}).then(async te=>{if(!te.ok)throw new Error((await te.json()).detail??`HTTP ${te.status}`);const he=URL.createObjectURL(await te.blob());Io(`pendulab-${B.scenario??"lab"}.toml`,he),setTimeout(()=>URL.revokeObjectURL(he),1e4)}).catch(te=>s(`scenario download: ${te instanceof Error?te.message:String(te)}`))},screenshot:()=>Io(`pendulab-${e.status?.scenario??"lab"}.png`,l.screenshot()),copyLink:()=>{const B=window.location.href;navigator.clipboard?.writeText(B).then(()=>s(N("msg.linkCopied"),!0),()=>s(B))??s(B)},viewChanged:(B,te)=>{l.setTopView(te),l.setStereo(B.stereo)}}),X=new HE(e,_,s);A=new cT(kt("tools"),e,r.methods,Uu(window.location),{send:S,explain:s}),Yf(U.gui);const J=B=>{const te=e.status;e.onStatus(B),te!==null&&(te.scenario!==B.scenario||te.model!==B.model)&&t.classList.contains("info")&&t.classList.remove("shown"),(te===null||te.epoch!==B.epoch)&&W.rescale(),U.sync(B),Yf(U.gui),G.sync(B),L.showRunning(B.paused),l.setLength(B.params.length),l.setModel(B.model),m.setModel(B.model),f.length===0&&window.history.replaceState(null,"",`?${YE(Vf(B))}`)};x=new Kf(Uu(window.location),{onOpen:()=>{e.setConnected(!0),kt("conn").textContent=N("conn.connected"),kt("offline").hidden=!0},onClose:()=>{e.setConnected(!1),kt("conn").textContent=N("conn.retrying"),kt("offline").textContent=N("conn.gone"),kt("offline").hidden=!1,e.status!==null&&(f=Lh(Vf(e.status)))},onFrames:B=>{const te=performance.now();e.onFrames(B),X.onFrames(),h.add("frames received",performance.now()-te)},onNotice:B=>{if(B.type==="error"){e.onError(B),s(B.command?`${B.command}: ${B.message}`:B.message);return}if(B.type==="event"){e.onEvent(B),s(Rg(B),!0);return}if(J(B),f.length>0){const te=f;f=[];for(const he of te)S(he)}},onProtocolError:B=>s(`protocol: ${B}`)});let H=0;const ce=kh((B,te)=>{S({type:"set_state",x:B,v:te,project:!0})},50),Z=()=>{e.status?.paused===!1&&S({type:"pause"})};l.enableDrag((B,te)=>{te==="start"&&Z(),ce(B,[0,0,0]),te==="end"&&s(N("msg.dragged"),!0)},(B,te,he)=>{if(he==="start"){Z(),s(N("msg.pull"),!0);return}if(te===null)return;ce(B,te.v);const ge=te.capped?N("msg.capped"):"";s(he==="end"?N("msg.velocitySet",{v:te.speed.toFixed(2),cap:ge}):N("msg.velocity",{v:te.speed.toFixed(2),cap:ge}),!0)}),window.pendulab={store:e,drawn:()=>H,send:S,screenshot:()=>l.screenshot(),bobOnScreen:()=>l.bobOnScreen(),handleOnScreen:()=>l.handleOnScreen(),quality:()=>o,frameCosts:()=>h.take(),twin:A.store,twinOnScreen:()=>l.twinOnScreen(),sphereOnScreen:()=>l.sphereOnScreen(),separation:()=>A?.separationNow()??{t:[],d:[]},energy:()=>W.shown,lastVideo:()=>b,plotScales:()=>d.scales(),measuredPoints:()=>l.measuredPoints()};let ee=performance.now();const se=new WE(100),pe=new XE,fe=B=>{const te=(B-ee)/1e3;ee=B;let he=performance.now();e.advancePlayhead(te);const ge=e.displayed(),ve=e.status?.params,Ve=jy(e.status?.model_params),{start:Qe,end:ze}=e.trailRange(c.trailSeconds),nt=ve?.mass??1,tt=ve?.g??9.81,Ye=A?.drawn(e.playT,c.trailSeconds)??null;l.setTwinLayout(A?.layout()??null);const It=pe.changed([ge,e.trail,Qe,ze,nt,tt,...Ve,...Object.values(c),Ye?.frame??null,Ye?.trail.end??0]);It&&(l.update(ge,{frames:e.trail,start:Qe,end:ze},c,nt,tt,Ve),l.updateTwin(Ye?.frame??null,Ye?.trail??{frames:[],start:0,end:0}));let gt=performance.now();if(h.add("scene update",gt-he),l.draw(It)?(H++,he=performance.now(),h.add("scene render (submit)",he-gt)):he=gt,se.due(B)){const $t=e.reference,Mt=ve?.length??1;d.update(e.history,e.events,UE($t?.energy??0,$t?.j3??0,nt,tt,Mt));const an={mass:nt,g:tt,length:Mt};u.update(e.history.frames,an,A?.on?A.store.history.frames:null),A?.update(kt("plots").clientWidth-8),G.update(ge?.x??null,ge?.t??null);const dt=e.latest();W.draw(dt?Vy(dt,nt,tt,Mt,e.work):null,e.status?.model!=="ideal"),gt=performance.now(),h.add("plots setData",gt-he),m.update(e.history,ge,X.veff,ve?.mass??1,ve?.g??9.81,ve?.length??1),m.updateEM(X.em,ge),he=performance.now(),h.add("portraits",he-gt),_.update(ge,ve?.length??1),gt=performance.now(),h.add("reduced view",gt-he),M.update(ge,e),h.add("data panel",performance.now()-gt)}requestAnimationFrame(fe)};requestAnimationFrame(fe)}AT().catch(i=>{const e=document.getElementById("offline");e&&(e.textContent=`${N("conn.noStart")} ${i instanceof Error?i.message:String(i)}`,e.hidden=!1),console.error(i)});
