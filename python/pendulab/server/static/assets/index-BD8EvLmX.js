(function(){const t=document.createElement("link").relList;if(t&&t.supports&&t.supports("modulepreload"))return;for(const s of document.querySelectorAll('link[rel="modulepreload"]'))n(s);new MutationObserver(s=>{for(const r of s)if(r.type==="childList")for(const a of r.addedNodes)a.tagName==="LINK"&&a.rel==="modulepreload"&&n(a)}).observe(document,{childList:!0,subtree:!0});function e(s){const r={};return s.integrity&&(r.integrity=s.integrity),s.referrerPolicy&&(r.referrerPolicy=s.referrerPolicy),s.crossOrigin==="use-credentials"?r.credentials="include":s.crossOrigin==="anonymous"?r.credentials="omit":r.credentials="same-origin",r}function n(s){if(s.ep)return;s.ep=!0;const r=e(s);fetch(s.href,r)}})();const rg=["t","x1","x2","x3","v1","v2","v3","energy","j3","tension","power","a1","a2","a3","pivot1","pivot2","pivot3","taut","error_x"],ag={fields:rg},Lh=ag.fields,og=Lh.length,qa=8*og;function gn(i){const t=Lh.indexOf(i);if(t<0)throw new Error(`frame.json lacks the field ${i}`);return t}const xi={t:gn("t"),x:[gn("x1"),gn("x2"),gn("x3")],v:[gn("v1"),gn("v2"),gn("v3")],energy:gn("energy"),j3:gn("j3"),tension:gn("tension"),power:gn("power"),a:[gn("a1"),gn("a2"),gn("a3")],pivot:[gn("pivot1"),gn("pivot2"),gn("pivot3")],taut:gn("taut"),errorX:gn("error_x")};class ui extends Error{}function lg(i){if(i.byteLength===0||i.byteLength%qa!==0)throw new ui(`a frame message has a multiple of ${qa} bytes, got ${i.byteLength}`);const t=new DataView(i),e=i.byteLength/qa,n=[];for(let s=0;s<e;s++){const r=s*qa,a=l=>t.getFloat64(r+8*l,!0),o=l=>[a(l[0]),a(l[1]),a(l[2])];n.push({t:a(xi.t),x:o(xi.x),v:o(xi.v),energy:a(xi.energy),j3:a(xi.j3),tension:a(xi.tension),power:a(xi.power),a:o(xi.a),pivot:o(xi.pivot),taut:a(xi.taut)!==0,errorX:a(xi.errorX)})}return n}function Pu(i){return typeof i=="object"&&i!==null&&!Array.isArray(i)}function cg(i){let t;try{t=JSON.parse(i)}catch(e){throw new ui(`notice is not JSON: ${String(e)}`)}if(!Pu(t))throw new ui("notice is not a JSON object");if(t.type==="error"&&typeof t.message=="string"){const e=typeof t.command=="string"?t.command:null;return{type:"error",message:t.message,command:e}}if(t.type==="status"){const e=t.params;if(!Pu(e)||typeof t.epoch!="number"||typeof t.method!="string")throw new ui("status notice lacks epoch, method or params");const n=t.frame_fields;if(Array.isArray(n)&&n.join(",")!==Lh.join(","))throw new ui(`server frame layout ${n.join(",")} differs from the page's`);return t}if(t.type==="event")return hg(t);throw new ui(`unknown notice type ${JSON.stringify(t.type)}`)}function wl(i){return typeof i=="number"&&Number.isFinite(i)}function hg(i){const{kind:t,t:e,energy_lost:n,x:s,epoch:r}=i,a=i.skipped??0;if(t!=="slack"&&t!=="taut")throw new ui(`event notice: kind ${JSON.stringify(t)} is not "slack" or "taut"`);if(!wl(e))throw new ui("event notice: t is not a finite number");if(!wl(n)||n<0)throw new ui("event notice: energy_lost is not a finite number ≥ 0");if(!Array.isArray(s)||s.length!==3||!s.every(wl))throw new ui("event notice: x is not 3 finite numbers");if(!Number.isInteger(r)||!Number.isInteger(a)||a<0)throw new ui("event notice: epoch or skipped is not an integer");return{type:"event",kind:t,t:e,energy_lost:n,x:[s[0],s[1],s[2]],epoch:r,skipped:a}}function Lu(i){const t=i.protocol==="https:"?"wss:":"ws:",e=i.pathname.endsWith("/")?i.pathname:i.pathname.replace(/[^/]*$/,"");return`${t}//${i.host}${e}ws`}function ug(i,t,e,n=20){const s=Date.now()+e;return new Promise(r=>{const a=()=>{(i()??-1)>=t()?r(!0):Date.now()>=s?r(!1):setTimeout(a,n)};a()})}class Xf{constructor(t,e){this.url=t,this.handlers=e,this.open()}url;handlers;sent=0;ws=null;retryMs=500;closedByUs=!1;open(){const t=new WebSocket(this.url);t.binaryType="arraybuffer",t.onopen=()=>{this.retryMs=500,this.sent=0,this.handlers.onOpen()},t.onmessage=e=>{try{e.data instanceof ArrayBuffer?this.handlers.onFrames(lg(e.data)):typeof e.data=="string"&&this.handlers.onNotice(cg(e.data))}catch(n){if(n instanceof ui)this.handlers.onProtocolError(n.message);else throw n}},t.onclose=()=>{this.ws=null,this.handlers.onClose(),this.closedByUs||(setTimeout(()=>this.open(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))},this.ws=t}get isOpen(){return this.ws!==null&&this.ws.readyState===WebSocket.OPEN}send(t){return!this.isOpen||this.ws===null?!1:(this.ws.send(JSON.stringify(t)),this.sent++,!0)}close(){this.closedByUs=!0,this.ws?.close()}}const $f={"page.title":"Pendulab lab — the spherical pendulum","page.units":"SI units, z up","page.scene":"3-D view of the pendulum (drag to orbit, scroll to zoom)","page.panel":"controls and measurements","page.software":"software WebGL: no antialiasing","conn.connected":"connected","conn.retrying":"disconnected: retrying…","toolbar.label":"run controls","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Reset","toolbar.stepShort":"Step","toolbar.recordShort":"● Record","toolbar.recordStopShort":"■ Stop","toolbar.start":"start (Space)","toolbar.pause":"pause (Space)","toolbar.reset":"reset to the start (R)","toolbar.step":"one step (S)","toolbar.record":"record a video (WebM)","toolbar.recordStop":"stop recording and download the video","toolbar.help":"keyboard shortcuts and colour key (?)","toolbar.language":"language","toolbar.collapse":"hide the panel","toolbar.expand":"show the panel","gui.title":"Pendulab lab","gui.pendulum":"Pendulum","gui.model":"model","gui.modelParams":"{model}: parameters","gui.paramHelp":"{help} — key {name} [{unit}]; allowed: {range}; default {default}","gui.integrator":"Integrator","gui.method":"method","gui.order":"order {n}","gui.symplectic":"symplectic","gui.adaptive":"adaptive","gui.dtRange":"dt must be between {min} and {max} s","gui.dtHelp":"step size of fixed-step methods; {min} … {max} s (dop853 chooses its own)","gui.run":"Run","gui.timeScale":"time scale [×]","gui.tsRange":"the time scale must be between {min} and {max}","gui.tsHelp":"simulated seconds per second (slow motion below 1); {min} … {max}","gui.stepN":"steps per step","gui.scenario":"scenario","gui.view":"View","gui.trail":"trail","gui.trailSeconds":"trail [s]","gui.sphere":"sphere of reach","gui.axes":"axes","gui.topView":"top view","gui.stereo":"stereo","gui.stereoHelp":"anaglyph: red–cyan glasses; side by side: a stereo viewer","gui.vectors":"Vectors","gui.origin":"origin {axis} [m]","gui.originHelp":"origin of L and τ relative to the pivot (0: the pivot)","gui.export":"Share and export","gui.csv":"download trajectory (CSV)","gui.toml":"download scenario (TOML)","gui.tomlHelp":"the scenario as it stands (model, parameters, start, method) as a file for `pendulab run`","gui.png":"screenshot (PNG)","gui.link":"copy link to this scenario","vec.velocity":"velocity v","vec.velocityHelp":"v [m/s], drawn as 0.25 s of travel","vec.momentum":"momentum m v","vec.momentumHelp":"m v [kg m/s], 0.25 m per kg m/s","vec.gravity":"gravity m g","vec.gravityHelp":"the weight m g d [N] (d: the gravity direction); forces: m·max(|g|, 1) N ↔ 0.5 l","vec.tension":"rod force (tension)","vec.tensionHelp":"the rod force −T x/|x| [N], T from the server","vec.net":"net force m a","vec.netHelp":"m a [N]: a = ẍ computed by the server’s core (relative to the pivot)","vec.angularMomentum":"angular momentum L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] about the origin o, drawn from o","vec.torque":"torque τ","vec.torqueHelp":"τ = (x − o) × m a [N m] about the origin o, drawn from o; dL/dt = τ","data.now":"Now (from the server)","data.exact":"Exact solution of this orbit","data.tension":"tension","data.tensionMin":"tension min","data.tensionMax":"tension max","data.method":"method","data.state":"state","data.paused":"paused","data.running":"running","data.lagging":" (lagging: slower than asked)","data.model":"model","data.kind":"kind of orbit","data.periodZ":"z-period T_z","data.swingPeriod":"swing period T","data.advance":"azimuthal advance Δφ per T_z","data.rotation":"rotation number W = Δφ/2π","data.reduced":"reduced view (σ₁, σ₂, σ₃): J₃ surface ∩ energy plane","portrait.phase":"phase portrait: vertical speed ż against height z","portrait.veff":"effective potential V_eff(θ); energy E dashed, θ now dotted","portrait.em":"energy–momentum map: E against J₃ (dot: now)","portrait.orbit":"orbit","portrait.emBoundary":"boundary (conical orbits)","note.spring":"the swinging spring leaves the sphere (its length varies): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.string":"the string goes slack (free flight inside the sphere): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown","note.exactIdeal":"the exact solution exists for the ideal pendulum only; this is the {model} model","note.reducedIdeal":"the reduced view is the ideal pendulum’s; this is the {model} model","event.slack":"the string went slack (tension 0: free flight)","event.taut":"the string snapped taut, lost {lost} J","event.skippedOne":" ({n} earlier event of this moment not shown)","event.skippedMany":" ({n} earlier events of this moment not shown)","event.slackRow":"went slack","event.tautRow":"snapped taut","event.tautValue":"t = {t} s, lost {lost}","data.power":"power P = dE/dt","data.springForce":"spring force k(|r| − l₀)","data.springLength":"spring length |r|","data.stretch":"stretch |r| − l₀","data.string":"string","data.slackZero":"slack (0)","data.slack":"slack: free flight, |x| = {r} m","data.taut":"taut","data.events":"events","data.noEvents":"none yet (slack, snaps)","data.z3":"z₃ (outside)","data.dynamic":"Δφ dynamic","data.geometric":"Δφ geometric","data.error":"position error |Δx|","data.errorRel":"position error / l","data.errorHow":"error obtained by","data.errorPaused":"estimate paused (the server’s work budget is used up; it catches up when there is time)","data.errorNone":"no estimate","data.howExact":"the true error: against the exact solution (since t = {since} s)","data.howRichardson":"estimate: Richardson against a companion at dt/2 = {dt} s, order p = {p} (since t = {since} s)","data.howCompanion":"estimate: a companion run at rtol = {rtol} (since t = {since} s)","page.softwareHelp":"{renderer}: drawn without multisampling for the frame rate","tools.start":"Start angle","tools.thetaHelp":"θ₀: the angle from the downward vertical, in degrees (0 … 180)","tools.phiHelp":"φ₀: the azimuth around the vertical, in degrees","tools.phiDotHelp":"φ̇₀: how fast the bob starts going round, in degrees per second (0: a planar swing)","tools.setStart":"set start","tools.world":"Gravity and friction","tools.gravity":"gravity","tools.friction":"friction","tools.frictionHelp":"linear damping c [1/s]: the force −m c v; on the ideal pendulum it switches to the damped model","tools.noFriction":"the {model} model has no friction parameter","tools.now":"Angles now","tools.stopwatch":"Stopwatch (simulated time)","tools.swStart":"start","tools.swStop":"stop","tools.swLap":"lap","tools.swReset":"reset","tools.period":"Period timer","tools.periodHelp":"measured from the lowest points of the bob (ż changes sign); the exact values are the server’s closed form (ideal pendulum)","tools.periodCount":"mean over {n} periods","tools.swingPeriod":"T swing [s]","tools.measured":"measured","tools.exact":"exact","tools.difference":"difference","tools.overlays":"Ruler and protractor","tools.ruler":"ruler (metres)","tools.protractor":"protractor (θ in degrees)","start.notNumber":"{name} must be a number","start.thetaRange":"θ₀ = {value}° is not allowed: 0 … 180°","gravity.custom":"custom","gravity.earth":"Earth","gravity.moon":"Moon","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"zero","gravity.negative":"negative (upwards)","energy.title":"Energy","energy.kinetic":"kinetic","energy.potential":"potential","energy.lost":"lost","energy.total":"total","plot.dE":"energy drift |ΔE|/E_s (log)","plot.dJ3":"J₃ drift |ΔJ₃|/J_s (log)","plot.z":"height z(t)","plot.tension":"rod tension T(t)","plot.time":"time t [s]","plot.floor":"float64 roundoff 2.2e-16","chosen.title":"Plot any variables","chosen.xAxis":"across","chosen.yAxis":"up","var.t":"time t","var.theta":"angle θ","var.phi":"azimuth φ","var.x":"x","var.y":"y","var.z":"height z","var.zdot":"vertical speed ż","var.speed":"speed |v|","var.energy":"energy E","var.kinetic":"kinetic energy K","var.potential":"potential energy U","var.j3":"angular momentum J₃","var.tension":"tension T","var.power":"power P","var.radius":"distance |x|","twin.title":"Two pendulums","twin.mode":"second pendulum","twin.off":"off","twin.epsilon":"start differs by ε","twin.method":"another integrator","twin.damped":"damped beside this one","twin.methodPick":"integrator","twin.damping":"damping [1/s]","twin.start":"start both","twin.bad":"ε must be a number and the damping ≥ 0","twin.first":"pendulum 1","twin.second":"pendulum 2","twin.separation":"separation of the bobs |r₁ − r₂| [m]","help.title":"Keyboard shortcuts and colour key","help.space":"start / pause","help.r":"reset to the start","help.s":"one step (paused)","help.arrows":"on a focused slider: one step down / up","help.page":"on a focused slider: ten steps","help.tab":"move between controls","help.help":"this overlay","help.esc":"close this overlay","help.colours":"Colours","help.close":"close","help.bob":"bob","help.trail":"trail","help.twin":"second pendulum","help.ruler":"ruler and protractor","msg.notConnected":"not connected to the server","msg.linkCopied":"link copied: it reproduces this scenario","msg.dragged":"start set by dragging (at rest there): press start to release it","msg.pull":"pull the arrow to set the start velocity","msg.capped":" (capped: the most the arrow sets, 4√(g l))","msg.velocitySet":"start velocity set: |v| = {v} m/s{cap}; press start to run from it","msg.velocity":"start velocity |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} is not allowed: {allowed} ({range})","msg.recording":"recording the view…","msg.recorded":"video saved ({mb} MB, WebM)","msg.noRecording":"this browser cannot record the view ({why})","fit.title":"Measured data","fit.load":"Load measured data…","fit.help":"a CSV file of measurements in SI units (columns t, x, y, z or x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): the server fits the pendulum to it, loads the fitted motion and draws the measured path dotted beside it","fit.model":"model","fit.params":"fit","fit.paramsDefault":"what the data determine","fit.paramsHelp":"the parameters to fit, comma separated (e.g. length,g,damping,pivot); empty: what the data can determine","fit.clear":"clear measured path","fit.running":"fitting {name} …","fit.noPath":"(frame-free data: no measured path to draw)","fit.failed":"fit: {why}","fit.loaded":"fitted {name}: the fitted motion is loaded, the measured path dotted in gold"},dg={"page.title":"Pendulab-Labor — das Kugelpendel","page.units":"SI-Einheiten, z nach oben","page.scene":"3-D-Ansicht des Pendels (ziehen zum Drehen, scrollen zum Zoomen)","page.panel":"Steuerung und Messungen","page.software":"Software-WebGL: ohne Kantenglättung","conn.connected":"verbunden","conn.retrying":"getrennt: neuer Versuch…","toolbar.label":"Ablauf","toolbar.startShort":"▶ Start","toolbar.pauseShort":"Pause","toolbar.resetShort":"Zurück","toolbar.stepShort":"Schritt","toolbar.recordShort":"● Aufnahme","toolbar.recordStopShort":"■ Stopp","toolbar.start":"Start (Leertaste)","toolbar.pause":"Pause (Leertaste)","toolbar.reset":"zurück zum Start (R)","toolbar.step":"ein Schritt (S)","toolbar.record":"Video aufnehmen (WebM)","toolbar.recordStop":"Aufnahme beenden und Video speichern","toolbar.help":"Tastenkürzel und Farben (?)","toolbar.language":"Sprache","toolbar.collapse":"Leiste ausblenden","toolbar.expand":"Leiste einblenden","gui.title":"Pendulab-Labor","gui.pendulum":"Pendel","gui.model":"Modell","gui.modelParams":"{model}: Parameter","gui.paramHelp":"{help} — Schlüssel {name} [{unit}]; erlaubt: {range}; Vorgabe {default}","gui.integrator":"Integrator","gui.method":"Verfahren","gui.order":"Ordnung {n}","gui.symplectic":"symplektisch","gui.adaptive":"adaptiv","gui.dtRange":"dt muss zwischen {min} und {max} s liegen","gui.dtHelp":"Schrittweite der Verfahren mit festem Schritt; {min} … {max} s (dop853 wählt selbst)","gui.run":"Ablauf","gui.timeScale":"Zeitfaktor [×]","gui.tsRange":"der Zeitfaktor muss zwischen {min} und {max} liegen","gui.tsHelp":"simulierte Sekunden pro Sekunde (Zeitlupe unter 1); {min} … {max}","gui.stepN":"Schritte pro Schritt","gui.scenario":"Szenario","gui.view":"Ansicht","gui.trail":"Spur","gui.trailSeconds":"Spur [s]","gui.sphere":"Kugel der Reichweite","gui.axes":"Achsen","gui.topView":"Draufsicht","gui.stereo":"Stereo","gui.stereoHelp":"Anaglyphe: Rot-Cyan-Brille; nebeneinander: ein Stereobetrachter","gui.vectors":"Vektoren","gui.origin":"Ursprung {axis} [m]","gui.originHelp":"Ursprung von L und τ relativ zum Aufhängepunkt (0: der Aufhängepunkt)","gui.export":"Teilen und exportieren","gui.csv":"Bahn herunterladen (CSV)","gui.toml":"Szenario herunterladen (TOML)","gui.tomlHelp":"das Szenario, wie es ist (Modell, Parameter, Start, Verfahren), als Datei für `pendulab run`","gui.png":"Bildschirmfoto (PNG)","gui.link":"Link zu diesem Szenario kopieren","vec.velocity":"Geschwindigkeit v","vec.velocityHelp":"v [m/s], gezeichnet als Weg in 0,25 s","vec.momentum":"Impuls m v","vec.momentumHelp":"m v [kg m/s], 0,25 m pro kg m/s","vec.gravity":"Gewichtskraft m g","vec.gravityHelp":"die Gewichtskraft m g d [N] (d: Richtung der Schwerkraft); Kräfte: m·max(|g|, 1) N ↔ 0,5 l","vec.tension":"Stangenkraft (Zugkraft)","vec.tensionHelp":"die Stangenkraft −T x/|x| [N], T vom Server","vec.net":"Gesamtkraft m a","vec.netHelp":"m a [N]: a = ẍ vom Kern des Servers berechnet (relativ zum Aufhängepunkt)","vec.angularMomentum":"Drehimpuls L","vec.angularMomentumHelp":"L = (x − o) × m v [kg m²/s] um den Ursprung o, von o aus gezeichnet","vec.torque":"Drehmoment τ","vec.torqueHelp":"τ = (x − o) × m a [N m] um den Ursprung o, von o aus gezeichnet; dL/dt = τ","data.now":"Jetzt (vom Server)","data.exact":"Exakte Lösung dieser Bahn","data.tension":"Zugkraft","data.tensionMin":"Zugkraft min","data.tensionMax":"Zugkraft max","data.method":"Verfahren","data.state":"Zustand","data.paused":"angehalten","data.running":"läuft","data.lagging":" (hinkt nach: langsamer als verlangt)","data.model":"Modell","data.kind":"Art der Bahn","data.periodZ":"z-Periode T_z","data.swingPeriod":"Schwingungsdauer T","data.advance":"Azimutvorschub Δφ pro T_z","data.rotation":"Umlaufzahl W = Δφ/2π","data.reduced":"reduzierte Ansicht (σ₁, σ₂, σ₃): J₃-Fläche ∩ Energieebene","portrait.phase":"Phasenporträt: Vertikalgeschwindigkeit ż gegen Höhe z","portrait.veff":"effektives Potential V_eff(θ); Energie E gestrichelt, θ jetzt gepunktet","portrait.em":"Energie-Impuls-Abbildung: E gegen J₃ (Punkt: jetzt)","portrait.orbit":"Bahn","portrait.emBoundary":"Rand (konische Bahnen)","note.spring":"die Schwingfeder verlässt die Kugel (ihre Länge ändert sich): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.string":"die Schnur wird schlaff (freier Flug in der Kugel): V_eff, die Energie-Impuls-Abbildung, die reduzierte Ansicht und die exakte Lösung gehören zum Stangenpendel und werden nicht gezeigt","note.exactIdeal":"die exakte Lösung gibt es nur für das ideale Pendel; dies ist das Modell {model}","note.reducedIdeal":"die reduzierte Ansicht ist die des idealen Pendels; dies ist das Modell {model}","event.slack":"die Schnur wurde schlaff (Zugkraft 0: freier Flug)","event.taut":"die Schnur straffte sich ruckartig, verlor {lost} J","event.skippedOne":" ({n} früheres Ereignis dieses Moments nicht gezeigt)","event.skippedMany":" ({n} frühere Ereignisse dieses Moments nicht gezeigt)","event.slackRow":"schlaff geworden","event.tautRow":"gestrafft","event.tautValue":"t = {t} s, verlor {lost}","data.power":"Leistung P = dE/dt","data.springForce":"Federkraft k(|r| − l₀)","data.springLength":"Federlänge |r|","data.stretch":"Dehnung |r| − l₀","data.string":"Schnur","data.slackZero":"schlaff (0)","data.slack":"schlaff: freier Flug, |x| = {r} m","data.taut":"straff","data.events":"Ereignisse","data.noEvents":"noch keine (schlaff, Straffen)","data.z3":"z₃ (außerhalb)","data.dynamic":"Δφ dynamisch","data.geometric":"Δφ geometrisch","data.error":"Lagefehler |Δx|","data.errorRel":"Lagefehler / l","data.errorHow":"Fehler ermittelt durch","data.errorPaused":"Schätzung pausiert (das Rechenbudget des Servers ist aufgebraucht; sie holt auf, sobald Zeit ist)","data.errorNone":"keine Schätzung","data.howExact":"den wahren Fehler: gegen die exakte Lösung (seit t = {since} s)","data.howRichardson":"Schätzung: Richardson gegen einen Begleitlauf mit dt/2 = {dt} s, Ordnung p = {p} (seit t = {since} s)","data.howCompanion":"Schätzung: einen Begleitlauf mit rtol = {rtol} (seit t = {since} s)","page.softwareHelp":"{renderer}: ohne Multisampling gezeichnet, für die Bildrate","tools.start":"Startwinkel","tools.thetaHelp":"θ₀: der Winkel zur Senkrechten nach unten, in Grad (0 … 180)","tools.phiHelp":"φ₀: der Winkel um die Senkrechte, in Grad","tools.phiDotHelp":"φ̇₀: wie schnell die Kugel zu kreisen beginnt, in Grad pro Sekunde (0: ebene Schwingung)","tools.setStart":"Start setzen","tools.world":"Schwerkraft und Reibung","tools.gravity":"Schwerkraft","tools.friction":"Reibung","tools.frictionHelp":"lineare Dämpfung c [1/s]: die Kraft −m c v; beim idealen Pendel wird auf das gedämpfte Modell gewechselt","tools.noFriction":"das Modell {model} hat keinen Reibungsparameter","tools.now":"Winkel jetzt","tools.stopwatch":"Stoppuhr (simulierte Zeit)","tools.swStart":"Start","tools.swStop":"Stopp","tools.swLap":"Runde","tools.swReset":"Null","tools.period":"Periodenmessung","tools.periodHelp":"gemessen an den tiefsten Punkten der Kugel (ż wechselt das Vorzeichen); die exakten Werte sind die geschlossene Lösung des Servers (ideales Pendel)","tools.periodCount":"Mittel über {n} Perioden","tools.swingPeriod":"T Schwingung [s]","tools.measured":"gemessen","tools.exact":"exakt","tools.difference":"Abweichung","tools.overlays":"Lineal und Winkelmesser","tools.ruler":"Lineal (Meter)","tools.protractor":"Winkelmesser (θ in Grad)","start.notNumber":"{name} muss eine Zahl sein","start.thetaRange":"θ₀ = {value}° ist nicht erlaubt: 0 … 180°","gravity.custom":"eigene","gravity.earth":"Erde","gravity.moon":"Mond","gravity.mars":"Mars","gravity.jupiter":"Jupiter","gravity.zero":"null","gravity.negative":"negativ (nach oben)","energy.title":"Energie","energy.kinetic":"kinetisch","energy.potential":"potentiell","energy.lost":"verloren","energy.total":"gesamt","plot.dE":"Energiedrift |ΔE|/E_s (log)","plot.dJ3":"J₃-Drift |ΔJ₃|/J_s (log)","plot.z":"Höhe z(t)","plot.tension":"Stangenkraft T(t)","plot.time":"Zeit t [s]","plot.floor":"float64-Rundung 2,2e-16","chosen.title":"Beliebige Größen zeichnen","chosen.xAxis":"waagerecht","chosen.yAxis":"senkrecht","var.t":"Zeit t","var.theta":"Winkel θ","var.phi":"Azimut φ","var.x":"x","var.y":"y","var.z":"Höhe z","var.zdot":"Vertikalgeschwindigkeit ż","var.speed":"Geschwindigkeit |v|","var.energy":"Energie E","var.kinetic":"kinetische Energie K","var.potential":"potentielle Energie U","var.j3":"Drehimpuls J₃","var.tension":"Zugkraft T","var.power":"Leistung P","var.radius":"Abstand |x|","twin.title":"Zwei Pendel","twin.mode":"zweites Pendel","twin.off":"aus","twin.epsilon":"Start um ε verschieden","twin.method":"anderer Integrator","twin.damped":"gedämpft daneben","twin.methodPick":"Integrator","twin.damping":"Dämpfung [1/s]","twin.start":"beide starten","twin.bad":"ε muss eine Zahl sein und die Dämpfung ≥ 0","twin.first":"Pendel 1","twin.second":"Pendel 2","twin.separation":"Abstand der Kugeln |r₁ − r₂| [m]","help.title":"Tastenkürzel und Farben","help.space":"Start / Pause","help.r":"zurück zum Start","help.s":"ein Schritt (angehalten)","help.arrows":"auf einem Schieberegler: einen Schritt runter / hoch","help.page":"auf einem Schieberegler: zehn Schritte","help.tab":"zwischen Bedienelementen wechseln","help.help":"diese Übersicht","help.esc":"diese Übersicht schließen","help.colours":"Farben","help.close":"schließen","help.bob":"Kugel","help.trail":"Spur","help.twin":"zweites Pendel","help.ruler":"Lineal und Winkelmesser","msg.notConnected":"keine Verbindung zum Server","msg.linkCopied":"Link kopiert: er stellt dieses Szenario wieder her","msg.dragged":"Start durch Ziehen gesetzt (dort in Ruhe): Start drücken, um loszulassen","msg.pull":"den Pfeil ziehen, um die Startgeschwindigkeit zu setzen","msg.capped":" (begrenzt: höchstens 4√(g l))","msg.velocitySet":"Startgeschwindigkeit gesetzt: |v| = {v} m/s{cap}; Start drücken","msg.velocity":"Startgeschwindigkeit |v| = {v} m/s{cap}","msg.notAllowed":"{name} = {value} ist nicht erlaubt: {allowed} ({range})","msg.recording":"die Ansicht wird aufgenommen…","msg.recorded":"Video gespeichert ({mb} MB, WebM)","msg.noRecording":"dieser Browser kann die Ansicht nicht aufnehmen ({why})","fit.title":"Messdaten","fit.load":"Messdaten laden…","fit.help":"eine CSV-Datei mit Messwerten in SI-Einheiten (Spalten t, x, y, z oder x, z; theta, phi; angle; specific_force; angular_speed — docs/fit.md): der Server passt das Pendel an, lädt die angepasste Bewegung und zeichnet die gemessene Bahn gepunktet daneben","fit.model":"Modell","fit.params":"anpassen","fit.paramsDefault":"was die Daten bestimmen","fit.paramsHelp":"die anzupassenden Parameter, durch Kommas getrennt (z. B. length,g,damping,pivot); leer: was die Daten bestimmen können","fit.clear":"gemessene Bahn löschen","fit.running":"{name} wird angepasst …","fit.noPath":"(Daten ohne Bezugssystem: keine Bahn zu zeichnen)","fit.failed":"Anpassung: {why}","fit.loaded":"{name} angepasst: die angepasste Bewegung ist geladen, die gemessene Bahn golden gepunktet"},fg={length:["Länge l","Länge der Stange vom Aufhängepunkt zur Kugel"],mass:["Masse m","Masse der Kugel"],g:["Schwerebeschleunigung g","Stärke der Schwerkraft (jedes Vorzeichen; 0 erlaubt)"],damping:["Reibung (lineare Dämpfung) c","Reibungskraft −m c v, proportional zur Geschwindigkeit"],drag:["Luftwiderstand c_q","Kraft −m c_q |v| v, quadratisch in der Geschwindigkeit"],forcing_amplitude:["Antrieb: Stärke A","periodische Kraft pro Masse A cos(ω t + ψ) in Richtung e"],forcing_omega:["Antrieb: Kreisfrequenz ω","wie schnell der Antrieb schwingt"],forcing_phase:["Antrieb: Phase ψ","Phase des Antriebs bei t = 0"],forcing_x:["Antriebsrichtung e: x","x-Komponente der Antriebsrichtung (wird normiert)"],forcing_y:["Antriebsrichtung e: y","y-Komponente der Antriebsrichtung"],forcing_z:["Antriebsrichtung e: z","z-Komponente der Antriebsrichtung"],gravity_x:["Schwerkraftrichtung d: x","x-Komponente der Richtung der Schwerkraft (wird normiert)"],gravity_y:["Schwerkraftrichtung d: y","y-Komponente der Richtung der Schwerkraft"],gravity_z:["Schwerkraftrichtung d: z","z-Komponente der Richtung der Schwerkraft"],frame_rate:["Drehrate des Bezugssystems |Ω|","wie schnell sich das Bezugssystem dreht (Erde: 7,292e-5)"],latitude:["geografische Breite λ","Breite des Ortes (Foucault-Pendel)"],radius:["Auslegerradius R","Abstand des Aufhängepunkts von der Drehachse des Krans"],rate:["Drehrate des Krans ω","wie schnell sich der Ausleger dreht"],height:["Höhe des Aufhängepunkts h","Höhe des Auslegers"],amplitude:["Rüttelamplitude A","Amplitude der senkrechten Schwingung des Aufhängepunkts"],frequency:["Rüttelfrequenz ν","Kreisfrequenz der Schwingung des Aufhängepunkts"],stiffness:["Federkonstante k","Steifigkeit der Feder; die Länge l ist die entspannte Länge"],restitution:["Stoßzahl e","wie elastisch die Schnur beim Straffen zurückfedert (0 … 1)"]},pg={ideal:"Ideales Pendel",damped:"Gedämpft und angetrieben",rotating:"Auf der drehenden Erde (Foucault)",slewing:"Drehkran",vibrating:"Gerüttelter Aufhängepunkt (Kapitza)",sampled_pivot:"Aufhängepunkt auf vorgegebener Bahn",spring:"Schwingfeder",string:"Pendel an einer Schnur"},Oa={en:{name:"English",words:$f,params:{},models:{}},de:{name:"Deutsch",words:dg,params:fg,models:pg}};let Ba="en";function Tl(i){return typeof i=="string"&&Object.hasOwn(Oa,i)}function mg(i,t,e){if(Tl(i))return i;if(Tl(t))return t;for(const n of e){const s=n.toLowerCase().split("-")[0];if(Tl(s))return s}return"en"}function gg(i){Ba=i}function _g(){return Ba}function O(i,t={}){return(Oa[Ba].words[i]??$f[i]).replace(/\{(\w+)\}/g,(s,r)=>r in t?String(t[r]):s)}function vg(i,t,e){return Oa[Ba].params[i]??[t,e]}function Yf(i,t){return Oa[Ba].models[i]??t}const xg=["spring","string"];function Sg(i){return!xg.includes(i??"ideal")}function Dh(i){return i==="spring"?O("note.spring"):i==="string"?O("note.string"):null}function qf(i,t){return i==="spring"?"coil":i==="string"?t?"taut string":"slack string":"rod"}function ve(i,t=6){if(i==null||Number.isNaN(i))return"—";if(!Number.isFinite(i))return i>0?"∞":"−∞";if(i===0)return"0";const e=Math.abs(i);return e>=.001&&e<1e6?i.toPrecision(t):i.toExponential(t-1)}const Mg=5;function yg(i){const t=i.kind==="slack"?O("event.slack"):O("event.taut",{lost:ve(i.energy_lost,3)}),e=i.skipped>0?O(i.skipped>1?"event.skippedMany":"event.skippedOne",{n:i.skipped}):"";return`t = ${i.t.toFixed(3)} s: ${t}${e}`}function bg(i){return i.kind==="slack"?[O("event.slackRow"),`t = ${ve(i.t,6)} s`,""]:[O("event.tautRow"),O("event.tautValue",{t:ve(i.t,6),lost:ve(i.energy_lost,4)}),"J"]}function Eg(i,t,e,n=Mg){if(e===null||t.epoch!==e)return i;const s=[...i,t];return s.length>n?s.slice(s.length-n):s}function wg(i,t){const e=t.reference,n=t.status,s=t.tensionExtremes,r=[["t",ve(i?.t,7),"s"],["E",ve(i?.energy,10),"J"],["E − E₀",i&&e?ve(i.energy-e.energy,3):"—","J"],["J₃",ve(i?.j3,10),"kg m²/s"],["J₃ − J₃(0)",i&&e?ve(i.j3-e.j3,3):"—","kg m²/s"],[O("data.tension"),ve(i?.tension,6),"N"],[O("data.tensionMin"),s?`${ve(s.min,6)} (t = ${ve(s.tMin,4)} s)`:"—","N"],[O("data.tensionMax"),s?`${ve(s.max,6)} (t = ${ve(s.tMax,4)} s)`:"—","N"],["z",ve(i?.x[2],6),"m"],[O("data.method"),n?`${n.method}${n.adaptive?"":`, dt = ${n.dt} s`}`:"—",""],[O("data.state"),n?`${n.paused?O("data.paused"):O("data.running")}${n.lagging?O("data.lagging"):""}`:"—",""],...Tg(i,n)];n&&n.model!=="ideal"&&(r.splice(1,0,[O("data.model"),n.model,""]),r.splice(4,0,[O("data.power"),ve(i?.power,6),"W"]));const a=r.findIndex(l=>l[0]===O("data.tension")),o=qf(n?.model,i?.taut??!0);if(o==="coil"&&n){const l=i?Math.hypot(...i.x):null;r[a]=[O("data.springForce"),ve(i?.tension,6),"N"],r.splice(a+1,0,[O("data.springLength"),ve(l,6),"m"],[O("data.stretch"),l===null?"—":ve(l-n.params.length,4),"m"])}else o==="slack string"?(r[a]=[O("data.tension"),O("data.slackZero"),"N"],r.splice(a+1,0,[O("data.string"),O("data.slack",{r:ve(i?Math.hypot(...i.x):null,5)}),""])):o==="taut string"&&r.splice(a+1,0,[O("data.string"),O("data.taut"),""]);if(n?.model==="string"){const l=[...t.events].reverse().map(bg);r.push(...l.length>0?l:[[O("data.events"),O("data.noEvents"),""]])}return r}function Tg(i,t){const e=t?.error_estimate;if(!t||!e)return[];if(e.how===null)return[[O("data.errorHow"),e.note??O("data.errorNone"),""]];const n=ve(e.since,6),s=e.how==="exact"?O("data.howExact",{since:n}):e.how==="richardson"?O("data.howRichardson",{dt:ve(e.reference.dt,3),p:e.order??"?",since:n}):O("data.howCompanion",{rtol:ve(e.reference.rtol,3),since:n}),r=i?.errorX,a=r!==void 0&&r>=0;return[[O("data.error"),a?ve(r,3):r===void 0?"—":O("data.errorPaused"),a?"m":""],[O("data.errorRel"),a?ve(r/t.params.length,3):"—",""],[O("data.errorHow"),s,""]]}function Ag(i){const t=i.status,e=Dh(t?.model);return e!==null?e:t&&t.model!=="ideal"?O("note.exactIdeal",{model:t.model}):i.exactError??i.exact?.phases_note??""}function Rg(i){if(i===null)return[];const t=i.turning_heights,e=[[O("data.kind"),i.kind,""],["z₁, z₂",`${ve(t[0])}, ${ve(t[1])}`,"m"]];return t.length>2&&e.push([O("data.z3"),ve(t[2]),"m"]),e.push([i.kind==="planar"?O("data.swingPeriod"):O("data.periodZ"),i.period_z_infinite?"∞":ve(i.period_z),"s"]),i.azimuth_advance!==null&&e.push([O("data.advance"),ve(i.azimuth_advance),"rad"]),i.rotation_number!==null&&e.push([O("data.rotation"),ve(i.rotation_number),""]),i.phases!==null&&(e.push([O("data.dynamic"),ve(i.phases.dynamic),"rad"]),e.push([O("data.geometric"),ve(i.phases.geometric),"rad"])),e}class Cg{live;exactTable;note;constructor(t){const e=n=>{const s=document.createElement("h3");s.textContent=n,t.appendChild(s)};e(O("data.now")),this.live=document.createElement("table"),t.appendChild(this.live),e(O("data.exact")),this.exactTable=document.createElement("table"),t.appendChild(this.exactTable),this.note=document.createElement("p"),this.note.className="note",t.appendChild(this.note)}fill(t,e){for(;t.rows.length>e.length;)t.deleteRow(-1);e.forEach(([n,s,r],a)=>{const o=t.rows[a]??t.insertRow();for(;o.cells.length<3;)o.insertCell();const[l,c,h]=[o.cells[0],o.cells[1],o.cells[2]];l&&l.textContent!==n&&(l.textContent=n),c&&c.textContent!==s&&(c.textContent=s),h&&h.textContent!==r&&(h.textContent=r)})}update(t,e){this.fill(this.live,wg(t,e)),this.fill(this.exactTable,Rg(e.exact));const n=Ag(e);this.note.textContent!==n&&(this.note.textContent=n)}}class Wi{constructor(t,e,n,s,r="div"){this.parent=t,this.object=e,this.property=n,this._disabled=!1,this._hidden=!1,this.initialValue=this.getValue(),this.domElement=document.createElement(r),this.domElement.classList.add("lil-controller"),this.domElement.classList.add(s),this.$name=document.createElement("div"),this.$name.classList.add("lil-name"),Wi.nextNameID=Wi.nextNameID||0,this.$name.id=`lil-gui-name-${++Wi.nextNameID}`,this.$widget=document.createElement("div"),this.$widget.classList.add("lil-widget"),this.$disable=this.$widget,this.domElement.appendChild(this.$name),this.domElement.appendChild(this.$widget),this.domElement.addEventListener("keydown",a=>a.stopPropagation()),this.domElement.addEventListener("keyup",a=>a.stopPropagation()),this.parent.children.push(this),this.parent.controllers.push(this),this.parent.$children.appendChild(this.domElement),this._listenCallback=this._listenCallback.bind(this),this.name(n)}name(t){return this._name=t,this.$name.textContent=t,this}onChange(t){return this._onChange=t,this}_callOnChange(){this.parent._callOnChange(this),this._onChange!==void 0&&this._onChange.call(this,this.getValue()),this._changed=!0}onFinishChange(t){return this._onFinishChange=t,this}_callOnFinishChange(){this._changed&&(this.parent._callOnFinishChange(this),this._onFinishChange!==void 0&&this._onFinishChange.call(this,this.getValue())),this._changed=!1}reset(){return this.setValue(this.initialValue),this._callOnFinishChange(),this}enable(t=!0){return this.disable(!t)}disable(t=!0){return t===this._disabled?this:(this._disabled=t,this.domElement.classList.toggle("lil-disabled",t),this.$disable.toggleAttribute("disabled",t),this)}show(t=!0){return this._hidden=!t,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}options(t){const e=this.parent.add(this.object,this.property,t);return e.name(this._name),this.destroy(),e}min(t){return this}max(t){return this}step(t){return this}decimals(t){return this}listen(t=!0){return this._listening=t,this._listenCallbackID!==void 0&&(cancelAnimationFrame(this._listenCallbackID),this._listenCallbackID=void 0),this._listening&&this._listenCallback(),this}_listenCallback(){this._listenCallbackID=requestAnimationFrame(this._listenCallback);const t=this.save();t!==this._listenPrevValue&&this.updateDisplay(),this._listenPrevValue=t}getValue(){return this.object[this.property]}setValue(t){return this.getValue()!==t&&(this.object[this.property]=t,this._callOnChange(),this.updateDisplay()),this}updateDisplay(){return this}load(t){return this.setValue(t),this._callOnFinishChange(),this}save(){return this.getValue()}destroy(){this.listen(!1),this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.controllers.splice(this.parent.controllers.indexOf(this),1),this.parent.$children.removeChild(this.domElement)}}class Pg extends Wi{constructor(t,e,n){super(t,e,n,"lil-boolean","label"),this.$input=document.createElement("input"),this.$input.setAttribute("type","checkbox"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$widget.appendChild(this.$input),this.$input.addEventListener("change",()=>{this.setValue(this.$input.checked),this._callOnFinishChange()}),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.checked=this.getValue(),this}}function yc(i){let t,e;return(t=i.match(/(#|0x)?([a-f0-9]{6})/i))?e=t[2]:(t=i.match(/rgb\(\s*(\d*)\s*,\s*(\d*)\s*,\s*(\d*)\s*\)/))?e=parseInt(t[1]).toString(16).padStart(2,0)+parseInt(t[2]).toString(16).padStart(2,0)+parseInt(t[3]).toString(16).padStart(2,0):(t=i.match(/^#?([a-f0-9])([a-f0-9])([a-f0-9])$/i))&&(e=t[1]+t[1]+t[2]+t[2]+t[3]+t[3]),e?"#"+e:!1}const Lg={isPrimitive:!0,match:i=>typeof i=="string",fromHexString:yc,toHexString:yc},Ra={isPrimitive:!0,match:i=>typeof i=="number",fromHexString:i=>parseInt(i.substring(1),16),toHexString:i=>"#"+i.toString(16).padStart(6,0)},Dg={isPrimitive:!1,match:i=>Array.isArray(i)||ArrayBuffer.isView(i),fromHexString(i,t,e=1){const n=Ra.fromHexString(i);t[0]=(n>>16&255)/255*e,t[1]=(n>>8&255)/255*e,t[2]=(n&255)/255*e},toHexString([i,t,e],n=1){n=255/n;const s=i*n<<16^t*n<<8^e*n<<0;return Ra.toHexString(s)}},Ng={isPrimitive:!1,match:i=>Object(i)===i,fromHexString(i,t,e=1){const n=Ra.fromHexString(i);t.r=(n>>16&255)/255*e,t.g=(n>>8&255)/255*e,t.b=(n&255)/255*e},toHexString({r:i,g:t,b:e},n=1){n=255/n;const s=i*n<<16^t*n<<8^e*n<<0;return Ra.toHexString(s)}},Ig=[Lg,Ra,Dg,Ng];function Ug(i){return Ig.find(t=>t.match(i))}class Fg extends Wi{constructor(t,e,n,s){super(t,e,n,"lil-color"),this.$input=document.createElement("input"),this.$input.setAttribute("type","color"),this.$input.setAttribute("tabindex",-1),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$text=document.createElement("input"),this.$text.setAttribute("type","text"),this.$text.setAttribute("spellcheck","false"),this.$text.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$display.appendChild(this.$input),this.$widget.appendChild(this.$display),this.$widget.appendChild(this.$text),this._format=Ug(this.initialValue),this._rgbScale=s,this._initialValueHexString=this.save(),this._textFocused=!1,this.$input.addEventListener("input",()=>{this._setValueFromHexString(this.$input.value)}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$text.addEventListener("input",()=>{const r=yc(this.$text.value);r&&this._setValueFromHexString(r)}),this.$text.addEventListener("focus",()=>{this._textFocused=!0,this.$text.select()}),this.$text.addEventListener("blur",()=>{this._textFocused=!1,this.updateDisplay(),this._callOnFinishChange()}),this.$disable=this.$text,this.updateDisplay()}reset(){return this._setValueFromHexString(this._initialValueHexString),this}_setValueFromHexString(t){if(this._format.isPrimitive){const e=this._format.fromHexString(t);this.setValue(e)}else this._format.fromHexString(t,this.getValue(),this._rgbScale),this._callOnChange(),this.updateDisplay()}save(){return this._format.toHexString(this.getValue(),this._rgbScale)}load(t){return this._setValueFromHexString(t),this._callOnFinishChange(),this}updateDisplay(){return this.$input.value=this._format.toHexString(this.getValue(),this._rgbScale),this._textFocused||(this.$text.value=this.$input.value.substring(1)),this.$display.style.backgroundColor=this.$input.value,this}}class Al extends Wi{constructor(t,e,n){super(t,e,n,"lil-function"),this.$button=document.createElement("button"),this.$button.appendChild(this.$name),this.$widget.appendChild(this.$button),this.$button.addEventListener("click",s=>{s.preventDefault(),this.getValue().call(this.object),this._callOnChange()}),this.$button.addEventListener("touchstart",()=>{},{passive:!0}),this.$disable=this.$button}}class Og extends Wi{constructor(t,e,n,s,r,a){super(t,e,n,"lil-number"),this._initInput(),this.min(s),this.max(r);const o=a!==void 0;this.step(o?a:this._getImplicitStep(),o),this.updateDisplay()}decimals(t){return this._decimals=t,this.updateDisplay(),this}min(t){return this._min=t,this._onUpdateMinMax(),this}max(t){return this._max=t,this._onUpdateMinMax(),this}step(t,e=!0){return this._step=t,this._stepExplicit=e,this}updateDisplay(){const t=this.getValue();if(this._hasSlider){let e=(t-this._min)/(this._max-this._min);e=Math.max(0,Math.min(e,1)),this.$fill.style.width=e*100+"%"}return this._inputFocused||(this.$input.value=this._decimals===void 0?t:t.toFixed(this._decimals)),this}_initInput(){this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("aria-labelledby",this.$name.id),window.matchMedia("(pointer: coarse)").matches&&(this.$input.setAttribute("type","number"),this.$input.setAttribute("step","any")),this.$widget.appendChild(this.$input),this.$disable=this.$input;const e=()=>{let x=parseFloat(this.$input.value);isNaN(x)||(this._stepExplicit&&(x=this._snap(x)),this.setValue(this._clamp(x)))},n=x=>{const A=parseFloat(this.$input.value);isNaN(A)||(this._snapClampSetValue(A+x),this.$input.value=this.getValue())},s=x=>{x.key==="Enter"&&this.$input.blur(),x.code==="ArrowUp"&&(x.preventDefault(),n(this._step*this._arrowKeyMultiplier(x))),x.code==="ArrowDown"&&(x.preventDefault(),n(this._step*this._arrowKeyMultiplier(x)*-1))},r=x=>{this._inputFocused&&(x.preventDefault(),n(this._step*this._normalizeMouseWheel(x)))};let a=!1,o,l,c,h,u;const d=5,m=x=>{o=x.clientX,l=c=x.clientY,a=!0,h=this.getValue(),u=0,window.addEventListener("mousemove",_),window.addEventListener("mouseup",M)},_=x=>{if(a){const A=x.clientX-o,S=x.clientY-l;Math.abs(S)>d?(x.preventDefault(),this.$input.blur(),a=!1,this._setDraggingStyle(!0,"vertical")):Math.abs(A)>d&&M()}if(!a){const A=x.clientY-c;u-=A*this._step*this._arrowKeyMultiplier(x),h+u>this._max?u=this._max-h:h+u<this._min&&(u=this._min-h),this._snapClampSetValue(h+u)}c=x.clientY},M=()=>{this._setDraggingStyle(!1,"vertical"),this._callOnFinishChange(),window.removeEventListener("mousemove",_),window.removeEventListener("mouseup",M)},p=()=>{this._inputFocused=!0},f=()=>{this._inputFocused=!1,this.updateDisplay(),this._callOnFinishChange()};this.$input.addEventListener("input",e),this.$input.addEventListener("keydown",s),this.$input.addEventListener("wheel",r,{passive:!1}),this.$input.addEventListener("mousedown",m),this.$input.addEventListener("focus",p),this.$input.addEventListener("blur",f)}_initSlider(){this._hasSlider=!0,this.$slider=document.createElement("div"),this.$slider.classList.add("lil-slider"),this.$fill=document.createElement("div"),this.$fill.classList.add("lil-fill"),this.$slider.appendChild(this.$fill),this.$widget.insertBefore(this.$slider,this.$input),this.domElement.classList.add("lil-has-slider");const t=(f,x,A,S,R)=>(f-x)/(A-x)*(R-S)+S,e=f=>{const x=this.$slider.getBoundingClientRect();let A=t(f,x.left,x.right,this._min,this._max);this._snapClampSetValue(A)},n=f=>{this._setDraggingStyle(!0),e(f.clientX),window.addEventListener("mousemove",s),window.addEventListener("mouseup",r)},s=f=>{e(f.clientX)},r=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("mousemove",s),window.removeEventListener("mouseup",r)};let a=!1,o,l;const c=f=>{f.preventDefault(),this._setDraggingStyle(!0),e(f.touches[0].clientX),a=!1},h=f=>{f.touches.length>1||(this._hasScrollBar?(o=f.touches[0].clientX,l=f.touches[0].clientY,a=!0):c(f),window.addEventListener("touchmove",u,{passive:!1}),window.addEventListener("touchend",d))},u=f=>{if(a){const x=f.touches[0].clientX-o,A=f.touches[0].clientY-l;Math.abs(x)>Math.abs(A)?c(f):(window.removeEventListener("touchmove",u),window.removeEventListener("touchend",d))}else f.preventDefault(),e(f.touches[0].clientX)},d=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("touchmove",u),window.removeEventListener("touchend",d)},m=this._callOnFinishChange.bind(this),_=400;let M;const p=f=>{if(Math.abs(f.deltaX)<Math.abs(f.deltaY)&&this._hasScrollBar)return;f.preventDefault();const A=this._normalizeMouseWheel(f)*this._step;this._snapClampSetValue(this.getValue()+A),this.$input.value=this.getValue(),clearTimeout(M),M=setTimeout(m,_)};this.$slider.addEventListener("mousedown",n),this.$slider.addEventListener("touchstart",h,{passive:!1}),this.$slider.addEventListener("wheel",p,{passive:!1})}_setDraggingStyle(t,e="horizontal"){this.$slider&&this.$slider.classList.toggle("lil-active",t),document.body.classList.toggle("lil-dragging",t),document.body.classList.toggle(`lil-${e}`,t)}_getImplicitStep(){return this._hasMin&&this._hasMax?(this._max-this._min)/1e3:.1}_onUpdateMinMax(){!this._hasSlider&&this._hasMin&&this._hasMax&&(this._stepExplicit||this.step(this._getImplicitStep(),!1),this._initSlider(),this.updateDisplay())}_normalizeMouseWheel(t){let{deltaX:e,deltaY:n}=t;return Math.floor(t.deltaY)!==t.deltaY&&t.wheelDelta&&(e=0,n=-t.wheelDelta/120,n*=this._stepExplicit?1:10),e+-n}_arrowKeyMultiplier(t){let e=this._stepExplicit?1:10;return t.shiftKey?e*=10:t.altKey&&(e/=10),e}_snap(t){let e=0;return this._hasMin?e=this._min:this._hasMax&&(e=this._max),t-=e,t=Math.round(t/this._step)*this._step,t+=e,t=parseFloat(t.toPrecision(15)),t}_clamp(t){return t<this._min&&(t=this._min),t>this._max&&(t=this._max),t}_snapClampSetValue(t){this.setValue(this._clamp(this._snap(t)))}get _hasScrollBar(){const t=this.parent.root.$children;return t.scrollHeight>t.clientHeight}get _hasMin(){return this._min!==void 0}get _hasMax(){return this._max!==void 0}}class Bg extends Wi{constructor(t,e,n,s){super(t,e,n,"lil-option"),this.$select=document.createElement("select"),this.$select.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$select.addEventListener("change",()=>{this.setValue(this._values[this.$select.selectedIndex]),this._callOnFinishChange()}),this.$select.addEventListener("focus",()=>{this.$display.classList.add("lil-focus")}),this.$select.addEventListener("blur",()=>{this.$display.classList.remove("lil-focus")}),this.$widget.appendChild(this.$select),this.$widget.appendChild(this.$display),this.$disable=this.$select,this.options(s)}options(t){return this._values=Array.isArray(t)?t:Object.values(t),this._names=Array.isArray(t)?t:Object.keys(t),this.$select.replaceChildren(),this._names.forEach(e=>{const n=document.createElement("option");n.textContent=e,this.$select.appendChild(n)}),this.updateDisplay(),this}updateDisplay(){const t=this.getValue(),e=this._values.indexOf(t);return this.$select.selectedIndex=e,this.$display.textContent=e===-1?t:this._names[e],this}}class zg extends Wi{constructor(t,e,n){super(t,e,n,"lil-string"),this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("spellcheck","false"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$input.addEventListener("input",()=>{this.setValue(this.$input.value)}),this.$input.addEventListener("keydown",s=>{s.code==="Enter"&&this.$input.blur()}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$widget.appendChild(this.$input),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.value=this.getValue(),this}}var kg=`.lil-gui {
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
}`;function Hg(i){const t=document.createElement("style");t.innerHTML=i;const e=document.querySelector("head link[rel=stylesheet], head style");e?document.head.insertBefore(t,e):document.head.appendChild(t)}let Du=!1;class Nh{constructor({parent:t,autoPlace:e=t===void 0,container:n,width:s,title:r="Controls",closeFolders:a=!1,injectStyles:o=!0,touchStyles:l=!0}={}){if(this.parent=t,this.root=t?t.root:this,this.children=[],this.controllers=[],this.folders=[],this._closed=!1,this._hidden=!1,this.domElement=document.createElement("div"),this.domElement.classList.add("lil-gui"),this.$title=document.createElement("button"),this.$title.classList.add("lil-title"),this.$title.setAttribute("aria-expanded",!0),this.$title.addEventListener("click",()=>this.openAnimated(this._closed)),this.$title.addEventListener("touchstart",()=>{},{passive:!0}),this.$children=document.createElement("div"),this.$children.classList.add("lil-children"),this.domElement.appendChild(this.$title),this.domElement.appendChild(this.$children),this.title(r),this.parent){this.parent.children.push(this),this.parent.folders.push(this),this.parent.$children.appendChild(this.domElement);return}this.domElement.classList.add("lil-root"),l&&this.domElement.classList.add("lil-allow-touch-styles"),!Du&&o&&(Hg(kg),Du=!0),n?n.appendChild(this.domElement):e&&(this.domElement.classList.add("lil-auto-place","autoPlace"),document.body.appendChild(this.domElement)),s&&this.domElement.style.setProperty("--width",s+"px"),this._closeFolders=a}add(t,e,n,s,r){if(Object(n)===n)return new Bg(this,t,e,n);const a=t[e];switch(typeof a){case"number":return new Og(this,t,e,n,s,r);case"boolean":return new Pg(this,t,e);case"string":return new zg(this,t,e);case"function":return new Al(this,t,e)}console.error(`gui.add failed
	property:`,e,`
	object:`,t,`
	value:`,a)}addColor(t,e,n=1){return new Fg(this,t,e,n)}addFolder(t){const e=new Nh({parent:this,title:t});return this.root._closeFolders&&e.close(),e}load(t,e=!0){return t.controllers&&this.controllers.forEach(n=>{n instanceof Al||n._name in t.controllers&&n.load(t.controllers[n._name])}),e&&t.folders&&this.folders.forEach(n=>{n._title in t.folders&&n.load(t.folders[n._title])}),this}save(t=!0){const e={controllers:{},folders:{}};return this.controllers.forEach(n=>{if(!(n instanceof Al)){if(n._name in e.controllers)throw new Error(`Cannot save GUI with duplicate property "${n._name}"`);e.controllers[n._name]=n.save()}}),t&&this.folders.forEach(n=>{if(n._title in e.folders)throw new Error(`Cannot save GUI with duplicate folder "${n._title}"`);e.folders[n._title]=n.save()}),e}open(t=!0){return this._setClosed(!t),this.$title.setAttribute("aria-expanded",!this._closed),this.domElement.classList.toggle("lil-closed",this._closed),this}close(){return this.open(!1)}_setClosed(t){this._closed!==t&&(this._closed=t,this._callOnOpenClose(this))}show(t=!0){return this._hidden=!t,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}openAnimated(t=!0){return this._setClosed(!t),this.$title.setAttribute("aria-expanded",!this._closed),requestAnimationFrame(()=>{const e=this.$children.clientHeight;this.$children.style.height=e+"px",this.domElement.classList.add("lil-transition");const n=r=>{r.target===this.$children&&(this.$children.style.height="",this.domElement.classList.remove("lil-transition"),this.$children.removeEventListener("transitionend",n))};this.$children.addEventListener("transitionend",n);const s=t?this.$children.scrollHeight:0;this.domElement.classList.toggle("lil-closed",!t),requestAnimationFrame(()=>{this.$children.style.height=s+"px"})}),this}title(t){return this._title=t,this.$title.textContent=t,this}reset(t=!0){return(t?this.controllersRecursive():this.controllers).forEach(n=>n.reset()),this}onChange(t){return this._onChange=t,this}_callOnChange(t){this.parent&&this.parent._callOnChange(t),this._onChange!==void 0&&this._onChange.call(this,{object:t.object,property:t.property,value:t.getValue(),controller:t})}onFinishChange(t){return this._onFinishChange=t,this}_callOnFinishChange(t){this.parent&&this.parent._callOnFinishChange(t),this._onFinishChange!==void 0&&this._onFinishChange.call(this,{object:t.object,property:t.property,value:t.getValue(),controller:t})}onOpenClose(t){return this._onOpenClose=t,this}_callOnOpenClose(t){this.parent&&this.parent._callOnOpenClose(t),this._onOpenClose!==void 0&&this._onOpenClose.call(this,t)}destroy(){this.parent&&(this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.folders.splice(this.parent.folders.indexOf(this),1)),this.domElement.parentElement&&this.domElement.parentElement.removeChild(this.domElement),Array.from(this.children).forEach(t=>t.destroy())}controllersRecursive(){let t=Array.from(this.controllers);return this.folders.forEach(e=>{t=t.concat(e.controllersRecursive())}),t}foldersRecursive(){let t=Array.from(this.folders);return this.folders.forEach(e=>{t=t.concat(e.foldersRecursive())}),t}}function Kf(i){return i==="1"?"":i.replace("^2","²").replace("^3","³")}function Zf(i){return vg(i.name,i.label??i.name,i.description)}function Gg(i){const t=Kf(i.unit),[e]=Zf(i);return t?`${e} [${t}]`:e}function bc(i){const t=Kf(i.unit),e=t?` ${t}`:"";return i.min!==null&&i.max!==null?`${i.min} … ${i.max}${e}`:i.min!==null?`≥ ${i.min}${e}`:i.max!==null?`≤ ${i.max}${e}`:"any finite number"}function Vg(i,t){return Number.isFinite(t)&&(i.min===null||t>=i.min)&&(i.max===null||t<=i.max)?null:O("msg.notAllowed",{name:i.name,value:t,allowed:i.allowed??bc(i),range:bc(i)})}function Jf(i,t,e,n,s){typeof t[e.name]!="number"&&(t[e.name]=e.default);const r=i.add(t,e.name,e.ui_min,e.ui_max).name(Gg(e)).onChange(l=>{const c=Vg(e,l);c!==null?s(c):n(l)}),[,a]=Zf(e);r.domElement.title=O("gui.paramHelp",{help:a,name:e.name,unit:e.unit,range:bc(e),default:e.default}),r.domElement.dataset.param=e.name,r.step(e.step,!1);const o=r;return typeof o._clamp=="function"&&(o._clamp=l=>l),r}function Ih(i,t){let e=-1/0,n=null,s=null;return(...r)=>{s=r;const a=e+t-performance.now();a<=0&&n===null?(e=performance.now(),i(...r),s=null):n===null&&(n=setTimeout(()=>{n=null,e=performance.now(),s!==null&&i(...s),s=null},Math.max(0,a)))}}const Wg={damped:{damping:.3}};function Xg(i){const t=Wg[i];return t?{type:"set_model",model:i,params:{...t}}:{type:"set_model",model:i}}function $g(i){const t={};for(const e of i)t[e.label?`${Yf(e.name,e.label)} (${e.name})`:e.name]=e.name;return t}class Yg{constructor(t,e,n){this.parent=t,this.schema=e,this.actions=n,this.picker=t.add(this.state,"model",$g(e.models)).name(O("gui.model")).onChange(s=>n.send(Xg(s))),this.picker.domElement.dataset.control="model",this.picker.domElement.title=e.models.map(s=>`${s.name}: ${s.summary}`).join(`
`),this.sendParam=Ih((s,r)=>{n.send({type:"set_params",params:{[s]:r}})},50)}parent;schema;actions;state={model:"ideal"};picker;paramsFolder=null;paramControls=[];values={};shown=null;sendParam;spec(t){return this.schema.models.find(e=>e.name===t)}rebuild(t){this.paramsFolder?.destroy(),this.paramsFolder=null,this.paramControls=[],this.values={},this.shown=t;const e=this.spec(t);if(e===void 0||e.params.length===0)return;const n=this.parent.addFolder(O("gui.modelParams",{model:Yf(t,e.label??t)}));for(const s of e.params){this.values[s.name]=s.default;const r=Jf(n,this.values,s,a=>this.sendParam(s.name,a),this.actions.explain);this.paramControls.push(r)}this.paramsFolder=n}sync(t){const e=t.model??"ideal";this.state.model=e,this.picker.updateDisplay(),this.shown!==e&&this.rebuild(e);for(const[n,s]of Object.entries(t.model_params??{}))this.values[n]=s;for(const n of this.paramControls)n.domElement.contains(document.activeElement)||n.updateDisplay()}}const Uh="187",Ir={ROTATE:0,DOLLY:1,PAN:2},Nr={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},qg=0,Nu=1,Kg=2,No=1,Zg=2,ma=3,Cs=0,Yn=1,di=2,Ur=0,Ma=1,Iu=2,Uu=3,Fu=4,Jg=5,Lr=100,jg=101,Qg=102,t0=103,e0=104,n0=200,i0=201,s0=202,r0=203,jf=204,Qf=205,a0=206,o0=207,l0=208,c0=209,h0=210,u0=211,d0=212,f0=213,p0=214,Ec=0,wc=1,Tc=2,Ca=3,Ac=4,Rc=5,Cc=6,Pc=7,tp=0,m0=1,g0=2,os=0,ep=1,np=2,ip=3,sp=4,rp=5,ap=6,op=7,lp=300,Br=301,Pa=302,Rl=303,Cl=304,Lc=1e3,as=1001,Dc=1002,Pn=1003,_0=1004,Ka=1005,$n=1006,Pl=1007,ws=1008,ei=1009,cp=1010,hp=1011,La=1012,Fh=1013,Yi=1014,Hi=1015,qi=1016,Oh=1017,Bh=1018,zr=1020,up=35902,dp=35899,fp=1021,pp=1022,Gi=1023,Ps=1026,Ts=1027,mp=1028,zh=1029,Ks=1030,kh=1031,Hh=1033,Io=33776,Uo=33777,Fo=33778,Oo=33779,Nc=35840,Ic=35841,Uc=35842,Fc=35843,Oc=36196,Bc=37492,zc=37496,kc=37488,Hc=37489,Ho=37490,Gc=37491,Vc=37808,Wc=37809,Xc=37810,$c=37811,Yc=37812,qc=37813,Kc=37814,Zc=37815,Jc=37816,jc=37817,Qc=37818,th=37819,eh=37820,nh=37821,ih=36492,sh=36494,rh=36495,ah=36283,oh=36284,Go=36285,lh=36286,v0=3200,ch=0,x0=1,Es="",ci="srgb",Vo="srgb-linear",Wo="linear",Le="srgb",Ll=7680,S0=519,M0=512,y0=513,b0=514,gp=515,E0=516,w0=517,_p=518,vp=519,xp=35044,Ou="300 es",Ai=2e3,Da=2001;function T0(i){for(let t=i.length-1;t>=0;--t)if(i[t]>=65535)return!0;return!1}function Xo(i){return document.createElementNS("http://www.w3.org/1999/xhtml",i)}function A0(){const i=Xo("canvas");return i.style.display="block",i}const Bu={};function $o(...i){const t="THREE."+i.shift();console.log(t,...i)}function Sp(i){const t=i[0];if(typeof t=="string"&&t.startsWith("TSL:")){const e=i[1];e&&e.isStackTrace?i[0]+=" "+e.getLocation():i[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return i}function jt(...i){i=Sp(i);const t="THREE."+i.shift();{const e=i[0];e&&e.isStackTrace?console.warn(e.getError(t)):console.warn(t,...i)}}function Se(...i){i=Sp(i);const t="THREE."+i.shift();{const e=i[0];e&&e.isStackTrace?console.error(e.getError(t)):console.error(t,...i)}}function Bo(...i){const t=i.join(" ");t in Bu||(Bu[t]=!0,jt(...i))}function R0(i,t,e){return new Promise(function(n,s){function r(){switch(i.clientWaitSync(t,i.SYNC_FLUSH_COMMANDS_BIT,0)){case i.WAIT_FAILED:s();break;case i.TIMEOUT_EXPIRED:setTimeout(r,e);break;default:n()}}setTimeout(r,e)})}const C0={[Ec]:Ec,[Tc]:Cc,[Ac]:Ac,[Ca]:Rc,[wc]:wc,[Cc]:Tc,[Pc]:Pc,[Rc]:Ca};class Is{addEventListener(t,e){this._listeners===void 0&&(this._listeners={});const n=this._listeners;n[t]===void 0&&(n[t]=[]),n[t].indexOf(e)===-1&&n[t].push(e)}hasEventListener(t,e){const n=this._listeners;return n===void 0?!1:n[t]!==void 0&&n[t].indexOf(e)!==-1}removeEventListener(t,e){const n=this._listeners;if(n===void 0)return;const s=n[t];if(s!==void 0){const r=s.indexOf(e);r!==-1&&s.splice(r,1)}}dispatchEvent(t){const e=this._listeners;if(e===void 0)return;const n=e[t.type];if(n!==void 0){t.target=this;const s=n.slice(0);for(let r=0,a=s.length;r<a;r++)s[r].call(this,t);t.target=null}}}const Dn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],ya=Math.PI/180,hh=180/Math.PI;function js(){const i=Math.random()*4294967295|0,t=Math.random()*4294967295|0,e=Math.random()*4294967295|0,n=Math.random()*4294967295|0;return(Dn[i&255]+Dn[i>>8&255]+Dn[i>>16&255]+Dn[i>>24&255]+"-"+Dn[t&255]+Dn[t>>8&255]+"-"+Dn[t>>16&15|64]+Dn[t>>24&255]+"-"+Dn[e&63|128]+Dn[e>>8&255]+"-"+Dn[e>>16&255]+Dn[e>>24&255]+Dn[n&255]+Dn[n>>8&255]+Dn[n>>16&255]+Dn[n>>24&255]).toLowerCase()}function pe(i,t,e){return Math.max(t,Math.min(e,i))}function P0(i,t){return(i%t+t)%t}function Dl(i,t,e){return(1-e)*i+e*t}function L0(i){return Math.pow(2,Math.floor(Math.log(i)/Math.LN2))}function tl(i){switch(i.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function Mp(i,t){if(t.constructor===Float32Array)return i;const e=tl(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(i/e,-1)}function yp(i,t){if(t.constructor===Float32Array)return i;const e=tl(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(i*e)}const D0={DEG2RAD:ya};class Xt{static{this.prototype.isVector2=!0}constructor(t=0,e=0){this.x=t,this.y=e}get width(){return this.x}set width(t){this.x=t}get height(){return this.y}set height(t){this.y=t}set(t,e){return this.x=t,this.y=e,this}setScalar(t){return this.x=t,this.y=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;default:throw new Error("THREE.Vector2: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y)}copy(t){return this.x=t.x,this.y=t.y,this}add(t){return this.x+=t.x,this.y+=t.y,this}addScalar(t){return this.x+=t,this.y+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this}subScalar(t){return this.x-=t,this.y-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this}multiply(t){return this.x*=t.x,this.y*=t.y,this}multiplyScalar(t){return this.x*=t,this.y*=t,this}divide(t){return this.x/=t.x,this.y/=t.y,this}divideScalar(t){return this.multiplyScalar(1/t)}applyMatrix3(t){const e=this.x,n=this.y,s=t.elements;return this.x=s[0]*e+s[3]*n+s[6],this.y=s[1]*e+s[4]*n+s[7],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this}clamp(t,e){return this.x=pe(this.x,t.x,e.x),this.y=pe(this.y,t.y,e.y),this}clampScalar(t,e){return this.x=pe(this.x,t,e),this.y=pe(this.y,t,e),this}clampLength(t,e){const n=this.length();return this.divideScalar(n||1).multiplyScalar(pe(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(t){return this.x*t.x+this.y*t.y}cross(t){return this.x*t.y-this.y*t.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(t){const e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;const n=this.dot(t)/e;return Math.acos(pe(n,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){const e=this.x-t.x,n=this.y-t.y;return e*e+n*n}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this}equals(t){return t.x===this.x&&t.y===this.y}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this}rotateAround(t,e){const n=Math.cos(e),s=Math.sin(e),r=this.x-t.x,a=this.y-t.y;return this.x=r*n-a*s+t.x,this.y=r*s+a*n+t.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}}class Ls{constructor(t=0,e=0,n=0,s=1){this.isQuaternion=!0,this._x=t,this._y=e,this._z=n,this._w=s}static slerpFlat(t,e,n,s,r,a,o){let l=n[s+0],c=n[s+1],h=n[s+2],u=n[s+3],d=r[a+0],m=r[a+1],_=r[a+2],M=r[a+3];if(u!==M||l!==d||c!==m||h!==_){let p=l*d+c*m+h*_+u*M;p<0&&(d=-d,m=-m,_=-_,M=-M,p=-p);let f=1-o;if(p<.9995){const x=Math.acos(p),A=Math.sin(x);f=Math.sin(f*x)/A,o=Math.sin(o*x)/A,l=l*f+d*o,c=c*f+m*o,h=h*f+_*o,u=u*f+M*o}else{l=l*f+d*o,c=c*f+m*o,h=h*f+_*o,u=u*f+M*o;const x=1/Math.sqrt(l*l+c*c+h*h+u*u);l*=x,c*=x,h*=x,u*=x}}t[e]=l,t[e+1]=c,t[e+2]=h,t[e+3]=u}static multiplyQuaternionsFlat(t,e,n,s,r,a){const o=n[s],l=n[s+1],c=n[s+2],h=n[s+3],u=r[a],d=r[a+1],m=r[a+2],_=r[a+3];return t[e]=o*_+h*u+l*m-c*d,t[e+1]=l*_+h*d+c*u-o*m,t[e+2]=c*_+h*m+o*d-l*u,t[e+3]=h*_-o*u-l*d-c*m,t}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get w(){return this._w}set w(t){this._w=t,this._onChangeCallback()}set(t,e,n,s){return this._x=t,this._y=e,this._z=n,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(t){return this._x=t.x,this._y=t.y,this._z=t.z,this._w=t.w,this._onChangeCallback(),this}setFromEuler(t,e=!0){const n=t._x,s=t._y,r=t._z,a=t._order,o=Math.cos,l=Math.sin,c=o(n/2),h=o(s/2),u=o(r/2),d=l(n/2),m=l(s/2),_=l(r/2);switch(a){case"XYZ":this._x=d*h*u+c*m*_,this._y=c*m*u-d*h*_,this._z=c*h*_+d*m*u,this._w=c*h*u-d*m*_;break;case"YXZ":this._x=d*h*u+c*m*_,this._y=c*m*u-d*h*_,this._z=c*h*_-d*m*u,this._w=c*h*u+d*m*_;break;case"ZXY":this._x=d*h*u-c*m*_,this._y=c*m*u+d*h*_,this._z=c*h*_+d*m*u,this._w=c*h*u-d*m*_;break;case"ZYX":this._x=d*h*u-c*m*_,this._y=c*m*u+d*h*_,this._z=c*h*_-d*m*u,this._w=c*h*u+d*m*_;break;case"YZX":this._x=d*h*u+c*m*_,this._y=c*m*u+d*h*_,this._z=c*h*_-d*m*u,this._w=c*h*u-d*m*_;break;case"XZY":this._x=d*h*u-c*m*_,this._y=c*m*u-d*h*_,this._z=c*h*_+d*m*u,this._w=c*h*u+d*m*_;break;default:jt("Quaternion: .setFromEuler() encountered an unknown order: "+a)}return e===!0&&this._onChangeCallback(),this}setFromAxisAngle(t,e){const n=e/2,s=Math.sin(n);return this._x=t.x*s,this._y=t.y*s,this._z=t.z*s,this._w=Math.cos(n),this._onChangeCallback(),this}setFromRotationMatrix(t){const e=t.elements,n=e[0],s=e[4],r=e[8],a=e[1],o=e[5],l=e[9],c=e[2],h=e[6],u=e[10],d=n+o+u;if(d>0){const m=.5/Math.sqrt(d+1);this._w=.25/m,this._x=(h-l)*m,this._y=(r-c)*m,this._z=(a-s)*m}else if(n>o&&n>u){const m=2*Math.sqrt(1+n-o-u);this._w=(h-l)/m,this._x=.25*m,this._y=(s+a)/m,this._z=(r+c)/m}else if(o>u){const m=2*Math.sqrt(1+o-n-u);this._w=(r-c)/m,this._x=(s+a)/m,this._y=.25*m,this._z=(l+h)/m}else{const m=2*Math.sqrt(1+u-n-o);this._w=(a-s)/m,this._x=(r+c)/m,this._y=(l+h)/m,this._z=.25*m}return this._onChangeCallback(),this}setFromUnitVectors(t,e){let n=t.dot(e)+1;return n<1e-8?(n=0,Math.abs(t.x)>Math.abs(t.z)?(this._x=-t.y,this._y=t.x,this._z=0,this._w=n):(this._x=0,this._y=-t.z,this._z=t.y,this._w=n)):(this._x=t.y*e.z-t.z*e.y,this._y=t.z*e.x-t.x*e.z,this._z=t.x*e.y-t.y*e.x,this._w=n),this.normalize()}angleTo(t){return 2*Math.acos(Math.abs(pe(this.dot(t),-1,1)))}rotateTowards(t,e){const n=this.angleTo(t);if(n===0)return this;const s=Math.min(1,e/n);return this.slerp(t,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(t){return this._x*t._x+this._y*t._y+this._z*t._z+this._w*t._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let t=this.length();return t===0?(this._x=0,this._y=0,this._z=0,this._w=1):(t=1/t,this._x=this._x*t,this._y=this._y*t,this._z=this._z*t,this._w=this._w*t),this._onChangeCallback(),this}multiply(t){return this.multiplyQuaternions(this,t)}premultiply(t){return this.multiplyQuaternions(t,this)}multiplyQuaternions(t,e){const n=t._x,s=t._y,r=t._z,a=t._w,o=e._x,l=e._y,c=e._z,h=e._w;return this._x=n*h+a*o+s*c-r*l,this._y=s*h+a*l+r*o-n*c,this._z=r*h+a*c+n*l-s*o,this._w=a*h-n*o-s*l-r*c,this._onChangeCallback(),this}slerp(t,e){let n=t._x,s=t._y,r=t._z,a=t._w,o=this.dot(t);o<0&&(n=-n,s=-s,r=-r,a=-a,o=-o);let l=1-e;if(o<.9995){const c=Math.acos(o),h=Math.sin(c);l=Math.sin(l*c)/h,e=Math.sin(e*c)/h,this._x=this._x*l+n*e,this._y=this._y*l+s*e,this._z=this._z*l+r*e,this._w=this._w*l+a*e,this._onChangeCallback()}else this._x=this._x*l+n*e,this._y=this._y*l+s*e,this._z=this._z*l+r*e,this._w=this._w*l+a*e,this.normalize();return this}slerpQuaternions(t,e,n){return this.copy(t).slerp(e,n)}random(){const t=2*Math.PI*Math.random(),e=2*Math.PI*Math.random(),n=Math.random(),s=Math.sqrt(1-n),r=Math.sqrt(n);return this.set(s*Math.sin(t),s*Math.cos(t),r*Math.sin(e),r*Math.cos(e))}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._w===this._w}fromArray(t,e=0){return this._x=t[e],this._y=t[e+1],this._z=t[e+2],this._w=t[e+3],this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._w,t}fromBufferAttribute(t,e){return this._x=t.getX(e),this._y=t.getY(e),this._z=t.getZ(e),this._w=t.getW(e),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}}class k{static{this.prototype.isVector3=!0}constructor(t=0,e=0,n=0){this.x=t,this.y=e,this.z=n}set(t,e,n){return n===void 0&&(n=this.z),this.x=t,this.y=e,this.z=n,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;default:throw new Error("THREE.Vector3: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this}multiplyVectors(t,e){return this.x=t.x*e.x,this.y=t.y*e.y,this.z=t.z*e.z,this}applyEuler(t){return this.applyQuaternion(zu.setFromEuler(t))}applyAxisAngle(t,e){return this.applyQuaternion(zu.setFromAxisAngle(t,e))}applyMatrix3(t){const e=this.x,n=this.y,s=this.z,r=t.elements;return this.x=r[0]*e+r[3]*n+r[6]*s,this.y=r[1]*e+r[4]*n+r[7]*s,this.z=r[2]*e+r[5]*n+r[8]*s,this}applyNormalMatrix(t){return this.applyMatrix3(t).normalize()}applyMatrix4(t){const e=this.x,n=this.y,s=this.z,r=t.elements,a=1/(r[3]*e+r[7]*n+r[11]*s+r[15]);return this.x=(r[0]*e+r[4]*n+r[8]*s+r[12])*a,this.y=(r[1]*e+r[5]*n+r[9]*s+r[13])*a,this.z=(r[2]*e+r[6]*n+r[10]*s+r[14])*a,this}applyQuaternion(t){const e=this.x,n=this.y,s=this.z,r=t.x,a=t.y,o=t.z,l=t.w,c=2*(a*s-o*n),h=2*(o*e-r*s),u=2*(r*n-a*e);return this.x=e+l*c+a*u-o*h,this.y=n+l*h+o*c-r*u,this.z=s+l*u+r*h-a*c,this}project(t){return this.applyMatrix4(t.matrixWorldInverse).applyMatrix4(t.projectionMatrix)}unproject(t){return this.applyMatrix4(t.projectionMatrixInverse).applyMatrix4(t.matrixWorld)}transformDirection(t){const e=this.x,n=this.y,s=this.z,r=t.elements;return this.x=r[0]*e+r[4]*n+r[8]*s,this.y=r[1]*e+r[5]*n+r[9]*s,this.z=r[2]*e+r[6]*n+r[10]*s,this.normalize()}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this}divideScalar(t){return this.multiplyScalar(1/t)}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this}clamp(t,e){return this.x=pe(this.x,t.x,e.x),this.y=pe(this.y,t.y,e.y),this.z=pe(this.z,t.z,e.z),this}clampScalar(t,e){return this.x=pe(this.x,t,e),this.y=pe(this.y,t,e),this.z=pe(this.z,t,e),this}clampLength(t,e){const n=this.length();return this.divideScalar(n||1).multiplyScalar(pe(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this.z=t.z+(e.z-t.z)*n,this}cross(t){return this.crossVectors(this,t)}crossVectors(t,e){const n=t.x,s=t.y,r=t.z,a=e.x,o=e.y,l=e.z;return this.x=s*l-r*o,this.y=r*a-n*l,this.z=n*o-s*a,this}projectOnVector(t){const e=t.lengthSq();if(e===0)return this.set(0,0,0);const n=t.dot(this)/e;return this.copy(t).multiplyScalar(n)}projectOnPlane(t){return Nl.copy(this).projectOnVector(t),this.sub(Nl)}reflect(t){return this.sub(Nl.copy(t).multiplyScalar(2*this.dot(t)))}angleTo(t){const e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;const n=this.dot(t)/e;return Math.acos(pe(n,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){const e=this.x-t.x,n=this.y-t.y,s=this.z-t.z;return e*e+n*n+s*s}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)+Math.abs(this.z-t.z)}setFromSpherical(t){return this.setFromSphericalCoords(t.radius,t.phi,t.theta)}setFromSphericalCoords(t,e,n){const s=Math.sin(e)*t;return this.x=s*Math.sin(n),this.y=Math.cos(e)*t,this.z=s*Math.cos(n),this}setFromCylindrical(t){return this.setFromCylindricalCoords(t.radius,t.theta,t.y)}setFromCylindricalCoords(t,e,n){return this.x=t*Math.sin(e),this.y=n,this.z=t*Math.cos(e),this}setFromMatrixPosition(t){const e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this}setFromMatrixScale(t){const e=this.setFromMatrixColumn(t,0).length(),n=this.setFromMatrixColumn(t,1).length(),s=this.setFromMatrixColumn(t,2).length();return this.x=e,this.y=n,this.z=s,this}setFromMatrixColumn(t,e){return this.fromArray(t.elements,e*4)}setFromMatrix3Column(t,e){return this.fromArray(t.elements,e*3)}setFromEuler(t){return this.x=t._x,this.y=t._y,this.z=t._z,this}setFromColor(t){return this.x=t.r,this.y=t.g,this.z=t.b,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){const t=Math.random()*Math.PI*2,e=Math.random()*2-1,n=Math.sqrt(1-e*e);return this.x=n*Math.cos(t),this.y=e,this.z=n*Math.sin(t),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}}const Nl=new k,zu=new Ls;class re{static{this.prototype.isMatrix3=!0}constructor(t,e,n,s,r,a,o,l,c){this.elements=[1,0,0,0,1,0,0,0,1],t!==void 0&&this.set(t,e,n,s,r,a,o,l,c)}set(t,e,n,s,r,a,o,l,c){const h=this.elements;return h[0]=t,h[1]=s,h[2]=o,h[3]=e,h[4]=r,h[5]=l,h[6]=n,h[7]=a,h[8]=c,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(t){const e=this.elements,n=t.elements;return e[0]=n[0],e[1]=n[1],e[2]=n[2],e[3]=n[3],e[4]=n[4],e[5]=n[5],e[6]=n[6],e[7]=n[7],e[8]=n[8],this}extractBasis(t,e,n){return t.setFromMatrix3Column(this,0),e.setFromMatrix3Column(this,1),n.setFromMatrix3Column(this,2),this}setFromMatrix4(t){const e=t.elements;return this.set(e[0],e[4],e[8],e[1],e[5],e[9],e[2],e[6],e[10]),this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){const n=t.elements,s=e.elements,r=this.elements,a=n[0],o=n[3],l=n[6],c=n[1],h=n[4],u=n[7],d=n[2],m=n[5],_=n[8],M=s[0],p=s[3],f=s[6],x=s[1],A=s[4],S=s[7],R=s[2],b=s[5],g=s[8];return r[0]=a*M+o*x+l*R,r[3]=a*p+o*A+l*b,r[6]=a*f+o*S+l*g,r[1]=c*M+h*x+u*R,r[4]=c*p+h*A+u*b,r[7]=c*f+h*S+u*g,r[2]=d*M+m*x+_*R,r[5]=d*p+m*A+_*b,r[8]=d*f+m*S+_*g,this}multiplyScalar(t){const e=this.elements;return e[0]*=t,e[3]*=t,e[6]*=t,e[1]*=t,e[4]*=t,e[7]*=t,e[2]*=t,e[5]*=t,e[8]*=t,this}determinant(){const t=this.elements,e=t[0],n=t[1],s=t[2],r=t[3],a=t[4],o=t[5],l=t[6],c=t[7],h=t[8];return e*a*h-e*o*c-n*r*h+n*o*l+s*r*c-s*a*l}invert(){const t=this.elements,e=t[0],n=t[1],s=t[2],r=t[3],a=t[4],o=t[5],l=t[6],c=t[7],h=t[8],u=h*a-o*c,d=o*l-h*r,m=c*r-a*l,_=e*u+n*d+s*m;if(_===0)return this.set(0,0,0,0,0,0,0,0,0);const M=1/_;return t[0]=u*M,t[1]=(s*c-h*n)*M,t[2]=(o*n-s*a)*M,t[3]=d*M,t[4]=(h*e-s*l)*M,t[5]=(s*r-o*e)*M,t[6]=m*M,t[7]=(n*l-c*e)*M,t[8]=(a*e-n*r)*M,this}transpose(){let t;const e=this.elements;return t=e[1],e[1]=e[3],e[3]=t,t=e[2],e[2]=e[6],e[6]=t,t=e[5],e[5]=e[7],e[7]=t,this}getNormalMatrix(t){return this.setFromMatrix4(t).invert().transpose()}transposeIntoArray(t){const e=this.elements;return t[0]=e[0],t[1]=e[3],t[2]=e[6],t[3]=e[1],t[4]=e[4],t[5]=e[7],t[6]=e[2],t[7]=e[5],t[8]=e[8],this}setUvTransform(t,e,n,s,r,a,o){const l=Math.cos(r),c=Math.sin(r);return this.set(n*l,n*c,-n*(l*a+c*o)+a+t,-s*c,s*l,-s*(-c*a+l*o)+o+e,0,0,1),this}scale(t,e){return Bo("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(Il.makeScale(t,e)),this}rotate(t){return Bo("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(Il.makeRotation(-t)),this}translate(t,e){return Bo("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(Il.makeTranslation(t,e)),this}makeTranslation(t,e){return t.isVector2?this.set(1,0,t.x,0,1,t.y,0,0,1):this.set(1,0,t,0,1,e,0,0,1),this}makeRotation(t){const e=Math.cos(t),n=Math.sin(t);return this.set(e,-n,0,n,e,0,0,0,1),this}makeScale(t,e){return this.set(t,0,0,0,e,0,0,0,1),this}equals(t){const e=this.elements,n=t.elements;for(let s=0;s<9;s++)if(e[s]!==n[s])return!1;return!0}fromArray(t,e=0){for(let n=0;n<9;n++)this.elements[n]=t[n+e];return this}toArray(t=[],e=0){const n=this.elements;return t[e]=n[0],t[e+1]=n[1],t[e+2]=n[2],t[e+3]=n[3],t[e+4]=n[4],t[e+5]=n[5],t[e+6]=n[6],t[e+7]=n[7],t[e+8]=n[8],t}clone(){return new this.constructor().fromArray(this.elements)}}const Il=new re,ku=new re().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Hu=new re().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function N0(){const i={enabled:!0,workingColorSpace:Vo,spaces:{},convert:function(s,r,a){return this.enabled===!1||r===a||!r||!a||(this.spaces[r].transfer===Le&&(s.r=ls(s.r),s.g=ls(s.g),s.b=ls(s.b)),this.spaces[r].primaries!==this.spaces[a].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[a].fromXYZ)),this.spaces[a].transfer===Le&&(s.r=Fr(s.r),s.g=Fr(s.g),s.b=Fr(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===Es?Wo:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,a){return s.copy(this.spaces[a].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},t=[.64,.33,.3,.6,.15,.06],e=[.2126,.7152,.0722],n=[.3127,.329];return i.define({[Vo]:{primaries:t,whitePoint:n,transfer:Wo,toXYZ:ku,fromXYZ:Hu,luminanceCoefficients:e,workingColorSpaceConfig:{unpackColorSpace:ci},outputColorSpaceConfig:{drawingBufferColorSpace:ci}},[ci]:{primaries:t,whitePoint:n,transfer:Le,toXYZ:ku,fromXYZ:Hu,luminanceCoefficients:e,outputColorSpaceConfig:{drawingBufferColorSpace:ci}}}),i}const xe=N0();function ls(i){return i<.04045?i*.0773993808:Math.pow(i*.9478672986+.0521327014,2.4)}function Fr(i){return i<.0031308?i*12.92:1.055*Math.pow(i,.41666)-.055}let dr;class I0{static getDataURL(t,e="image/png"){if(/^data:/i.test(t.src)||typeof HTMLCanvasElement>"u")return t.src;let n;if(t instanceof HTMLCanvasElement)n=t;else{dr===void 0&&(dr=Xo("canvas")),dr.width=t.width,dr.height=t.height;const s=dr.getContext("2d");t instanceof ImageData?s.putImageData(t,0,0):s.drawImage(t,0,0,t.width,t.height),n=dr}return n.toDataURL(e)}static sRGBToLinear(t){if(typeof HTMLImageElement<"u"&&t instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&t instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&t instanceof ImageBitmap){const e=Xo("canvas");e.width=t.width,e.height=t.height;const n=e.getContext("2d");n.drawImage(t,0,0,t.width,t.height);const s=n.getImageData(0,0,t.width,t.height),r=s.data;for(let a=0;a<r.length;a++)r[a]=ls(r[a]/255)*255;return n.putImageData(s,0,0),e}else if(t.data){const e=t.data.slice(0);for(let n=0;n<e.length;n++)e instanceof Uint8Array||e instanceof Uint8ClampedArray?e[n]=Math.floor(ls(e[n]/255)*255):e[n]=ls(e[n]);return{data:e,width:t.width,height:t.height}}else return jt("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),t}}let U0=0;class Gh{constructor(t=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:U0++}),this.uuid=js(),this.data=t,this.dataReady=!0,this.version=0}getSize(t){const e=this.data;return typeof HTMLVideoElement<"u"&&e instanceof HTMLVideoElement?t.set(e.videoWidth,e.videoHeight,0):typeof VideoFrame<"u"&&e instanceof VideoFrame?t.set(e.displayWidth,e.displayHeight,0):e!==null?t.set(e.width||0,e.height||0,e.depth||0):t.set(0,0,0),t}set needsUpdate(t){t===!0&&this.version++}toJSON(t){const e=t===void 0||typeof t=="string";if(!e&&t.images[this.uuid]!==void 0)return t.images[this.uuid];const n={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let a=0,o=s.length;a<o;a++)s[a].isDataTexture?r.push(Ul(s[a].image)):r.push(Ul(s[a]))}else r=Ul(s);n.url=r}return e||(t.images[this.uuid]=n),n}}function Ul(i){return typeof HTMLImageElement<"u"&&i instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&i instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&i instanceof ImageBitmap?I0.getDataURL(i):i.data?{data:Array.from(i.data),width:i.width,height:i.height,type:i.data.constructor.name}:(jt("Texture: Unable to serialize Texture."),{})}let F0=0;const Fl=new k;class In extends Is{constructor(t=In.DEFAULT_IMAGE,e=In.DEFAULT_MAPPING,n=as,s=as,r=$n,a=ws,o=Gi,l=ei,c=In.DEFAULT_ANISOTROPY,h=Es){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:F0++}),this.uuid=js(),this.name="",this.source=new Gh(t),this.mipmaps=[],this.mapping=e,this.channel=0,this.wrapS=n,this.wrapT=s,this.magFilter=r,this.minFilter=a,this.anisotropy=c,this.format=o,this.internalFormat=null,this.type=l,this.offset=new Xt(0,0),this.repeat=new Xt(1,1),this.center=new Xt(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new re,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(t&&t.depth&&t.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(Fl).x}get height(){return this.source.getSize(Fl).y}get depth(){return this.source.getSize(Fl).z}get image(){return this.source.data}set image(t){this.source.data=t}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(t){return this.name=t.name,this.source=t.source,this.mipmaps=t.mipmaps.slice(0),this.mapping=t.mapping,this.channel=t.channel,this.wrapS=t.wrapS,this.wrapT=t.wrapT,this.magFilter=t.magFilter,this.minFilter=t.minFilter,this.anisotropy=t.anisotropy,this.format=t.format,this.internalFormat=t.internalFormat,this.type=t.type,this.normalized=t.normalized,this.offset.copy(t.offset),this.repeat.copy(t.repeat),this.center.copy(t.center),this.rotation=t.rotation,this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrix.copy(t.matrix),this.generateMipmaps=t.generateMipmaps,this.mipmapsAutoUpdate=t.mipmapsAutoUpdate,this.premultiplyAlpha=t.premultiplyAlpha,this.flipY=t.flipY,this.unpackAlignment=t.unpackAlignment,this.colorSpace=t.colorSpace,this.renderTarget=t.renderTarget,this.isRenderTargetTexture=t.isRenderTargetTexture,this.isPMREMTexture=t.isPMREMTexture,this.isArrayTexture=t.isArrayTexture,this.userData=JSON.parse(JSON.stringify(t.userData)),this.needsUpdate=!0,this}setValues(t){for(const e in t){const n=t[e];if(n===void 0){jt(`Texture.setValues(): parameter '${e}' has value of undefined.`);continue}const s=this[e];if(s===void 0){jt(`Texture.setValues(): property '${e}' does not exist.`);continue}s&&n&&s.isVector2&&n.isVector2||s&&n&&s.isVector3&&n.isVector3||s&&n&&s.isMatrix3&&n.isMatrix3?s.copy(n):this[e]=n}}toJSON(t){const e=t===void 0||typeof t=="string";if(!e&&t.textures[this.uuid]!==void 0)return t.textures[this.uuid];const n={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(t).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(n.userData=this.userData),e||(t.textures[this.uuid]=n),n}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(t){if(this.mapping!==lp)return t;if(t.applyMatrix3(this.matrix),t.x<0||t.x>1)switch(this.wrapS){case Lc:t.x=t.x-Math.floor(t.x);break;case as:t.x=t.x<0?0:1;break;case Dc:Math.abs(Math.floor(t.x)%2)===1?t.x=Math.ceil(t.x)-t.x:t.x=t.x-Math.floor(t.x);break}if(t.y<0||t.y>1)switch(this.wrapT){case Lc:t.y=t.y-Math.floor(t.y);break;case as:t.y=t.y<0?0:1;break;case Dc:Math.abs(Math.floor(t.y)%2)===1?t.y=Math.ceil(t.y)-t.y:t.y=t.y-Math.floor(t.y);break}return this.flipY&&(t.y=1-t.y),t}set needsUpdate(t){t===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(t){t===!0&&this.pmremVersion++}}In.DEFAULT_IMAGE=null;In.DEFAULT_MAPPING=lp;In.DEFAULT_ANISOTROPY=1;class nn{static{this.prototype.isVector4=!0}constructor(t=0,e=0,n=0,s=1){this.x=t,this.y=e,this.z=n,this.w=s}get width(){return this.z}set width(t){this.z=t}get height(){return this.w}set height(t){this.w=t}set(t,e,n,s){return this.x=t,this.y=e,this.z=n,this.w=s,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this.w=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setW(t){return this.w=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;case 3:this.w=e;break;default:throw new Error("THREE.Vector4: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this.w=t.w!==void 0?t.w:1,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this.w+=t.w,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this.w+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this.w=t.w+e.w,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this.w+=t.w*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this.w-=t.w,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this.w-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this.w=t.w-e.w,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this.w*=t.w,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this.w*=t,this}applyMatrix4(t){const e=this.x,n=this.y,s=this.z,r=this.w,a=t.elements;return this.x=a[0]*e+a[4]*n+a[8]*s+a[12]*r,this.y=a[1]*e+a[5]*n+a[9]*s+a[13]*r,this.z=a[2]*e+a[6]*n+a[10]*s+a[14]*r,this.w=a[3]*e+a[7]*n+a[11]*s+a[15]*r,this}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this.w/=t.w,this}divideScalar(t){return this.multiplyScalar(1/t)}setAxisAngleFromQuaternion(t){this.w=2*Math.acos(t.w);const e=Math.sqrt(1-t.w*t.w);return e<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=t.x/e,this.y=t.y/e,this.z=t.z/e),this}setAxisAngleFromRotationMatrix(t){let e,n,s,r;const l=t.elements,c=l[0],h=l[4],u=l[8],d=l[1],m=l[5],_=l[9],M=l[2],p=l[6],f=l[10];if(Math.abs(h-d)<.01&&Math.abs(u-M)<.01&&Math.abs(_-p)<.01){if(Math.abs(h+d)<.1&&Math.abs(u+M)<.1&&Math.abs(_+p)<.1&&Math.abs(c+m+f-3)<.1)return this.set(1,0,0,0),this;e=Math.PI;const A=(c+1)/2,S=(m+1)/2,R=(f+1)/2,b=(h+d)/4,g=(u+M)/4,w=(_+p)/4;return A>S&&A>R?A<.01?(n=0,s=.707106781,r=.707106781):(n=Math.sqrt(A),s=b/n,r=g/n):S>R?S<.01?(n=.707106781,s=0,r=.707106781):(s=Math.sqrt(S),n=b/s,r=w/s):R<.01?(n=.707106781,s=.707106781,r=0):(r=Math.sqrt(R),n=g/r,s=w/r),this.set(n,s,r,e),this}let x=Math.sqrt((p-_)*(p-_)+(u-M)*(u-M)+(d-h)*(d-h));return Math.abs(x)<.001&&(x=1),this.x=(p-_)/x,this.y=(u-M)/x,this.z=(d-h)/x,this.w=Math.acos((c+m+f-1)/2),this}setFromMatrixPosition(t){const e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this.w=e[15],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this.w=Math.min(this.w,t.w),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this.w=Math.max(this.w,t.w),this}clamp(t,e){return this.x=pe(this.x,t.x,e.x),this.y=pe(this.y,t.y,e.y),this.z=pe(this.z,t.z,e.z),this.w=pe(this.w,t.w,e.w),this}clampScalar(t,e){return this.x=pe(this.x,t,e),this.y=pe(this.y,t,e),this.z=pe(this.z,t,e),this.w=pe(this.w,t,e),this}clampLength(t,e){const n=this.length();return this.divideScalar(n||1).multiplyScalar(pe(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z+this.w*t.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this.w+=(t.w-this.w)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this.z=t.z+(e.z-t.z)*n,this.w=t.w+(e.w-t.w)*n,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z&&t.w===this.w}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this.w=t[e+3],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t[e+3]=this.w,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this.w=t.getW(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}}class O0 extends Is{constructor(t=1,e=1,n={}){super(),n=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:$n,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},n),this.isRenderTarget=!0,this.width=t,this.height=e,this.depth=n.depth,this.scissor=new nn(0,0,t,e),this.scissorTest=!1,this.viewport=new nn(0,0,t,e),this.textures=[];const s=n.count;for(let r=0;r<s;r++)this.textures[r]=new In({width:t,height:e,depth:n.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(n),this.depthBuffer=n.depthBuffer,this.stencilBuffer=n.stencilBuffer,this.resolveColorBuffer=n.resolveColorBuffer,this.resolveDepthBuffer=n.resolveDepthBuffer,this.resolveStencilBuffer=n.resolveStencilBuffer,this.storeMultisampledColorBuffer=n.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=n.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=n.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=n.depthTexture,this.samples=n.samples,this.multiview=n.multiview,this.useArrayDepthTexture=n.useArrayDepthTexture}_setTextureOptions(t={}){const e={minFilter:$n,generateMipmaps:!1,flipY:!1,internalFormat:null};t.mapping!==void 0&&(e.mapping=t.mapping),t.wrapS!==void 0&&(e.wrapS=t.wrapS),t.wrapT!==void 0&&(e.wrapT=t.wrapT),t.wrapR!==void 0&&(e.wrapR=t.wrapR),t.magFilter!==void 0&&(e.magFilter=t.magFilter),t.minFilter!==void 0&&(e.minFilter=t.minFilter),t.format!==void 0&&(e.format=t.format),t.type!==void 0&&(e.type=t.type),t.anisotropy!==void 0&&(e.anisotropy=t.anisotropy),t.colorSpace!==void 0&&(e.colorSpace=t.colorSpace),t.flipY!==void 0&&(e.flipY=t.flipY),t.generateMipmaps!==void 0&&(e.generateMipmaps=t.generateMipmaps),t.mipmapsAutoUpdate!==void 0&&(e.mipmapsAutoUpdate=t.mipmapsAutoUpdate),t.internalFormat!==void 0&&(e.internalFormat=t.internalFormat);for(let n=0;n<this.textures.length;n++)this.textures[n].setValues(e)}get texture(){return this.textures[0]}set texture(t){this.textures[0]=t}set depthTexture(t){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),t!==null&&t.renderTarget===null&&(t.renderTarget=this),this._depthTexture=t}get depthTexture(){return this._depthTexture}setSize(t,e,n=1){if(this.width!==t||this.height!==e||this.depth!==n){this.width=t,this.height=e,this.depth=n;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=t,this.textures[s].image.height=e,this.textures[s].image.depth=n,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,t,e),this.scissor.set(0,0,t,e)}clone(){return new this.constructor().copy(this)}copy(t){this.width=t.width,this.height=t.height,this.depth=t.depth,this.scissor.copy(t.scissor),this.scissorTest=t.scissorTest,this.viewport.copy(t.viewport),this.textures.length=0;for(let e=0,n=t.textures.length;e<n;e++){this.textures[e]=t.textures[e].clone(),this.textures[e].isRenderTargetTexture=!0,this.textures[e].renderTarget=this;const s=Object.assign({},t.textures[e].image);this.textures[e].source=new Gh(s)}if(this.depthBuffer=t.depthBuffer,this.stencilBuffer=t.stencilBuffer,this.resolveColorBuffer=t.resolveColorBuffer,this.resolveDepthBuffer=t.resolveDepthBuffer,this.resolveStencilBuffer=t.resolveStencilBuffer,this.storeMultisampledColorBuffer=t.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=t.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=t.storeMultisampledStencilBuffer,t.depthTexture!==null)if(t.depthTexture.renderTarget===t){const e=t.depthTexture.clone();e.renderTarget=null,this.depthTexture=e}else this.depthTexture=t.depthTexture;else this.depthTexture=null;return this.samples=t.samples,this.multiview=t.multiview,this.useArrayDepthTexture=t.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}}class Xi extends O0{constructor(t=1,e=1,n={}){super(t,e,n),this.isWebGLRenderTarget=!0}}class bp extends In{constructor(t=null,e=1,n=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:t,width:e,height:n,depth:s},this.magFilter=Pn,this.minFilter=Pn,this.wrapR=as,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}addLayerUpdate(t){this.layerUpdates.add(t)}clearLayerUpdates(){this.layerUpdates.clear()}}class B0 extends In{constructor(t=null,e=1,n=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:t,width:e,height:n,depth:s},this.magFilter=Pn,this.minFilter=Pn,this.wrapR=as,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}}class De{static{this.prototype.isMatrix4=!0}constructor(t,e,n,s,r,a,o,l,c,h,u,d,m,_,M,p){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],t!==void 0&&this.set(t,e,n,s,r,a,o,l,c,h,u,d,m,_,M,p)}set(t,e,n,s,r,a,o,l,c,h,u,d,m,_,M,p){const f=this.elements;return f[0]=t,f[4]=e,f[8]=n,f[12]=s,f[1]=r,f[5]=a,f[9]=o,f[13]=l,f[2]=c,f[6]=h,f[10]=u,f[14]=d,f[3]=m,f[7]=_,f[11]=M,f[15]=p,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new De().fromArray(this.elements)}copy(t){const e=this.elements,n=t.elements;return e[0]=n[0],e[1]=n[1],e[2]=n[2],e[3]=n[3],e[4]=n[4],e[5]=n[5],e[6]=n[6],e[7]=n[7],e[8]=n[8],e[9]=n[9],e[10]=n[10],e[11]=n[11],e[12]=n[12],e[13]=n[13],e[14]=n[14],e[15]=n[15],this}copyPosition(t){const e=this.elements,n=t.elements;return e[12]=n[12],e[13]=n[13],e[14]=n[14],this}setFromMatrix3(t){const e=t.elements;return this.set(e[0],e[3],e[6],0,e[1],e[4],e[7],0,e[2],e[5],e[8],0,0,0,0,1),this}extractBasis(t,e,n){return this.determinantAffine()===0?(t.set(1,0,0),e.set(0,1,0),n.set(0,0,1),this):(t.setFromMatrixColumn(this,0),e.setFromMatrixColumn(this,1),n.setFromMatrixColumn(this,2),this)}makeBasis(t,e,n){return this.set(t.x,e.x,n.x,0,t.y,e.y,n.y,0,t.z,e.z,n.z,0,0,0,0,1),this}extractRotation(t){if(t.determinantAffine()===0)return this.identity();const e=this.elements,n=t.elements,s=1/fr.setFromMatrixColumn(t,0).length(),r=1/fr.setFromMatrixColumn(t,1).length(),a=1/fr.setFromMatrixColumn(t,2).length();return e[0]=n[0]*s,e[1]=n[1]*s,e[2]=n[2]*s,e[3]=0,e[4]=n[4]*r,e[5]=n[5]*r,e[6]=n[6]*r,e[7]=0,e[8]=n[8]*a,e[9]=n[9]*a,e[10]=n[10]*a,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromEuler(t){const e=this.elements,n=t.x,s=t.y,r=t.z,a=Math.cos(n),o=Math.sin(n),l=Math.cos(s),c=Math.sin(s),h=Math.cos(r),u=Math.sin(r);if(t.order==="XYZ"){const d=a*h,m=a*u,_=o*h,M=o*u;e[0]=l*h,e[4]=-l*u,e[8]=c,e[1]=m+_*c,e[5]=d-M*c,e[9]=-o*l,e[2]=M-d*c,e[6]=_+m*c,e[10]=a*l}else if(t.order==="YXZ"){const d=l*h,m=l*u,_=c*h,M=c*u;e[0]=d+M*o,e[4]=_*o-m,e[8]=a*c,e[1]=a*u,e[5]=a*h,e[9]=-o,e[2]=m*o-_,e[6]=M+d*o,e[10]=a*l}else if(t.order==="ZXY"){const d=l*h,m=l*u,_=c*h,M=c*u;e[0]=d-M*o,e[4]=-a*u,e[8]=_+m*o,e[1]=m+_*o,e[5]=a*h,e[9]=M-d*o,e[2]=-a*c,e[6]=o,e[10]=a*l}else if(t.order==="ZYX"){const d=a*h,m=a*u,_=o*h,M=o*u;e[0]=l*h,e[4]=_*c-m,e[8]=d*c+M,e[1]=l*u,e[5]=M*c+d,e[9]=m*c-_,e[2]=-c,e[6]=o*l,e[10]=a*l}else if(t.order==="YZX"){const d=a*l,m=a*c,_=o*l,M=o*c;e[0]=l*h,e[4]=M-d*u,e[8]=_*u+m,e[1]=u,e[5]=a*h,e[9]=-o*h,e[2]=-c*h,e[6]=m*u+_,e[10]=d-M*u}else if(t.order==="XZY"){const d=a*l,m=a*c,_=o*l,M=o*c;e[0]=l*h,e[4]=-u,e[8]=c*h,e[1]=d*u+M,e[5]=a*h,e[9]=m*u-_,e[2]=_*u-m,e[6]=o*h,e[10]=M*u+d}return e[3]=0,e[7]=0,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromQuaternion(t){return this.compose(z0,t,k0)}lookAt(t,e,n){const s=this.elements;return jn.subVectors(t,e),jn.lengthSq()===0&&(jn.z=1),jn.normalize(),_s.crossVectors(n,jn),_s.lengthSq()===0&&(Math.abs(n.z)===1?jn.x+=1e-4:jn.z+=1e-4,jn.normalize(),_s.crossVectors(n,jn)),_s.normalize(),Za.crossVectors(jn,_s),s[0]=_s.x,s[4]=Za.x,s[8]=jn.x,s[1]=_s.y,s[5]=Za.y,s[9]=jn.y,s[2]=_s.z,s[6]=Za.z,s[10]=jn.z,this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){const n=t.elements,s=e.elements,r=this.elements,a=n[0],o=n[4],l=n[8],c=n[12],h=n[1],u=n[5],d=n[9],m=n[13],_=n[2],M=n[6],p=n[10],f=n[14],x=n[3],A=n[7],S=n[11],R=n[15],b=s[0],g=s[4],w=s[8],z=s[12],I=s[1],L=s[5],V=s[9],$=s[13],N=s[2],W=s[6],J=s[10],H=s[14],ct=s[3],Z=s[7],tt=s[11],st=s[15];return r[0]=a*b+o*I+l*N+c*ct,r[4]=a*g+o*L+l*W+c*Z,r[8]=a*w+o*V+l*J+c*tt,r[12]=a*z+o*$+l*H+c*st,r[1]=h*b+u*I+d*N+m*ct,r[5]=h*g+u*L+d*W+m*Z,r[9]=h*w+u*V+d*J+m*tt,r[13]=h*z+u*$+d*H+m*st,r[2]=_*b+M*I+p*N+f*ct,r[6]=_*g+M*L+p*W+f*Z,r[10]=_*w+M*V+p*J+f*tt,r[14]=_*z+M*$+p*H+f*st,r[3]=x*b+A*I+S*N+R*ct,r[7]=x*g+A*L+S*W+R*Z,r[11]=x*w+A*V+S*J+R*tt,r[15]=x*z+A*$+S*H+R*st,this}multiplyScalar(t){const e=this.elements;return e[0]*=t,e[4]*=t,e[8]*=t,e[12]*=t,e[1]*=t,e[5]*=t,e[9]*=t,e[13]*=t,e[2]*=t,e[6]*=t,e[10]*=t,e[14]*=t,e[3]*=t,e[7]*=t,e[11]*=t,e[15]*=t,this}determinant(){const t=this.elements,e=t[0],n=t[4],s=t[8],r=t[12],a=t[1],o=t[5],l=t[9],c=t[13],h=t[2],u=t[6],d=t[10],m=t[14],_=t[3],M=t[7],p=t[11],f=t[15],x=l*m-c*d,A=o*m-c*u,S=o*d-l*u,R=a*m-c*h,b=a*d-l*h,g=a*u-o*h;return e*(M*x-p*A+f*S)-n*(_*x-p*R+f*b)+s*(_*A-M*R+f*g)-r*(_*S-M*b+p*g)}determinantAffine(){const t=this.elements,e=t[0],n=t[4],s=t[8],r=t[1],a=t[5],o=t[9],l=t[2],c=t[6],h=t[10];return e*(a*h-o*c)-n*(r*h-o*l)+s*(r*c-a*l)}transpose(){const t=this.elements;let e;return e=t[1],t[1]=t[4],t[4]=e,e=t[2],t[2]=t[8],t[8]=e,e=t[6],t[6]=t[9],t[9]=e,e=t[3],t[3]=t[12],t[12]=e,e=t[7],t[7]=t[13],t[13]=e,e=t[11],t[11]=t[14],t[14]=e,this}setPosition(t,e,n){const s=this.elements;return t.isVector3?(s[12]=t.x,s[13]=t.y,s[14]=t.z):(s[12]=t,s[13]=e,s[14]=n),this}invert(){const t=this.elements,e=t[0],n=t[1],s=t[2],r=t[3],a=t[4],o=t[5],l=t[6],c=t[7],h=t[8],u=t[9],d=t[10],m=t[11],_=t[12],M=t[13],p=t[14],f=t[15],x=e*o-n*a,A=e*l-s*a,S=e*c-r*a,R=n*l-s*o,b=n*c-r*o,g=s*c-r*l,w=h*M-u*_,z=h*p-d*_,I=h*f-m*_,L=u*p-d*M,V=u*f-m*M,$=d*f-m*p,N=x*$-A*V+S*L+R*I-b*z+g*w;if(N===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);const W=1/N;return t[0]=(o*$-l*V+c*L)*W,t[1]=(s*V-n*$-r*L)*W,t[2]=(M*g-p*b+f*R)*W,t[3]=(d*b-u*g-m*R)*W,t[4]=(l*I-a*$-c*z)*W,t[5]=(e*$-s*I+r*z)*W,t[6]=(p*S-_*g-f*A)*W,t[7]=(h*g-d*S+m*A)*W,t[8]=(a*V-o*I+c*w)*W,t[9]=(n*I-e*V-r*w)*W,t[10]=(_*b-M*S+f*x)*W,t[11]=(u*S-h*b-m*x)*W,t[12]=(o*z-a*L-l*w)*W,t[13]=(e*L-n*z+s*w)*W,t[14]=(M*A-_*R-p*x)*W,t[15]=(h*R-u*A+d*x)*W,this}scale(t){const e=this.elements,n=t.x,s=t.y,r=t.z;return e[0]*=n,e[4]*=s,e[8]*=r,e[1]*=n,e[5]*=s,e[9]*=r,e[2]*=n,e[6]*=s,e[10]*=r,e[3]*=n,e[7]*=s,e[11]*=r,this}getMaxScaleOnAxis(){const t=this.elements,e=t[0]*t[0]+t[1]*t[1]+t[2]*t[2],n=t[4]*t[4]+t[5]*t[5]+t[6]*t[6],s=t[8]*t[8]+t[9]*t[9]+t[10]*t[10];return Math.sqrt(Math.max(e,n,s))}makeTranslation(t,e,n){return t.isVector3?this.set(1,0,0,t.x,0,1,0,t.y,0,0,1,t.z,0,0,0,1):this.set(1,0,0,t,0,1,0,e,0,0,1,n,0,0,0,1),this}makeRotationX(t){const e=Math.cos(t),n=Math.sin(t);return this.set(1,0,0,0,0,e,-n,0,0,n,e,0,0,0,0,1),this}makeRotationY(t){const e=Math.cos(t),n=Math.sin(t);return this.set(e,0,n,0,0,1,0,0,-n,0,e,0,0,0,0,1),this}makeRotationZ(t){const e=Math.cos(t),n=Math.sin(t);return this.set(e,-n,0,0,n,e,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(t,e){const n=Math.cos(e),s=Math.sin(e),r=1-n,a=t.x,o=t.y,l=t.z,c=r*a,h=r*o;return this.set(c*a+n,c*o-s*l,c*l+s*o,0,c*o+s*l,h*o+n,h*l-s*a,0,c*l-s*o,h*l+s*a,r*l*l+n,0,0,0,0,1),this}makeScale(t,e,n){return this.set(t,0,0,0,0,e,0,0,0,0,n,0,0,0,0,1),this}makeShear(t,e,n,s,r,a){return this.set(1,n,r,0,t,1,a,0,e,s,1,0,0,0,0,1),this}compose(t,e,n){const s=this.elements,r=e._x,a=e._y,o=e._z,l=e._w,c=r+r,h=a+a,u=o+o,d=r*c,m=r*h,_=r*u,M=a*h,p=a*u,f=o*u,x=l*c,A=l*h,S=l*u,R=n.x,b=n.y,g=n.z;return s[0]=(1-(M+f))*R,s[1]=(m+S)*R,s[2]=(_-A)*R,s[3]=0,s[4]=(m-S)*b,s[5]=(1-(d+f))*b,s[6]=(p+x)*b,s[7]=0,s[8]=(_+A)*g,s[9]=(p-x)*g,s[10]=(1-(d+M))*g,s[11]=0,s[12]=t.x,s[13]=t.y,s[14]=t.z,s[15]=1,this}decompose(t,e,n){const s=this.elements;t.x=s[12],t.y=s[13],t.z=s[14];const r=this.determinantAffine();if(r===0)return n.set(1,1,1),e.identity(),this;let a=fr.set(s[0],s[1],s[2]).length();const o=fr.set(s[4],s[5],s[6]).length(),l=fr.set(s[8],s[9],s[10]).length();r<0&&(a=-a),Si.copy(this);const c=1/a,h=1/o,u=1/l;return Si.elements[0]*=c,Si.elements[1]*=c,Si.elements[2]*=c,Si.elements[4]*=h,Si.elements[5]*=h,Si.elements[6]*=h,Si.elements[8]*=u,Si.elements[9]*=u,Si.elements[10]*=u,e.setFromRotationMatrix(Si),n.x=a,n.y=o,n.z=l,this}makePerspective(t,e,n,s,r,a,o=Ai,l=!1){const c=this.elements,h=2*r/(e-t),u=2*r/(n-s),d=(e+t)/(e-t),m=(n+s)/(n-s);let _,M;if(l)_=r/(a-r),M=a*r/(a-r);else if(o===Ai)_=-(a+r)/(a-r),M=-2*a*r/(a-r);else if(o===Da)_=-a/(a-r),M=-a*r/(a-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return c[0]=h,c[4]=0,c[8]=d,c[12]=0,c[1]=0,c[5]=u,c[9]=m,c[13]=0,c[2]=0,c[6]=0,c[10]=_,c[14]=M,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(t,e,n,s,r,a,o=Ai,l=!1){const c=this.elements,h=2/(e-t),u=2/(n-s),d=-(e+t)/(e-t),m=-(n+s)/(n-s);let _,M;if(l)_=1/(a-r),M=a/(a-r);else if(o===Ai)_=-2/(a-r),M=-(a+r)/(a-r);else if(o===Da)_=-1/(a-r),M=-r/(a-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return c[0]=h,c[4]=0,c[8]=0,c[12]=d,c[1]=0,c[5]=u,c[9]=0,c[13]=m,c[2]=0,c[6]=0,c[10]=_,c[14]=M,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(t){const e=this.elements,n=t.elements;for(let s=0;s<16;s++)if(e[s]!==n[s])return!1;return!0}fromArray(t,e=0){for(let n=0;n<16;n++)this.elements[n]=t[n+e];return this}toArray(t=[],e=0){const n=this.elements;return t[e]=n[0],t[e+1]=n[1],t[e+2]=n[2],t[e+3]=n[3],t[e+4]=n[4],t[e+5]=n[5],t[e+6]=n[6],t[e+7]=n[7],t[e+8]=n[8],t[e+9]=n[9],t[e+10]=n[10],t[e+11]=n[11],t[e+12]=n[12],t[e+13]=n[13],t[e+14]=n[14],t[e+15]=n[15],t}}const fr=new k,Si=new De,z0=new k(0,0,0),k0=new k(1,1,1),_s=new k,Za=new k,jn=new k,Gu=new De,Vu=new Ls;class Ds{constructor(t=0,e=0,n=0,s=Ds.DEFAULT_ORDER){this.isEuler=!0,this._x=t,this._y=e,this._z=n,this._order=s}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get order(){return this._order}set order(t){this._order=t,this._onChangeCallback()}set(t,e,n,s=this._order){return this._x=t,this._y=e,this._z=n,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(t){return this._x=t._x,this._y=t._y,this._z=t._z,this._order=t._order,this._onChangeCallback(),this}setFromRotationMatrix(t,e=this._order,n=!0){const s=t.elements,r=s[0],a=s[4],o=s[8],l=s[1],c=s[5],h=s[9],u=s[2],d=s[6],m=s[10];switch(e){case"XYZ":this._y=Math.asin(pe(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-h,m),this._z=Math.atan2(-a,r)):(this._x=Math.atan2(d,c),this._z=0);break;case"YXZ":this._x=Math.asin(-pe(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(o,m),this._z=Math.atan2(l,c)):(this._y=Math.atan2(-u,r),this._z=0);break;case"ZXY":this._x=Math.asin(pe(d,-1,1)),Math.abs(d)<.9999999?(this._y=Math.atan2(-u,m),this._z=Math.atan2(-a,c)):(this._y=0,this._z=Math.atan2(l,r));break;case"ZYX":this._y=Math.asin(-pe(u,-1,1)),Math.abs(u)<.9999999?(this._x=Math.atan2(d,m),this._z=Math.atan2(l,r)):(this._x=0,this._z=Math.atan2(-a,c));break;case"YZX":this._z=Math.asin(pe(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-h,c),this._y=Math.atan2(-u,r)):(this._x=0,this._y=Math.atan2(o,m));break;case"XZY":this._z=Math.asin(-pe(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(d,c),this._y=Math.atan2(o,r)):(this._x=Math.atan2(-h,m),this._y=0);break;default:jt("Euler: .setFromRotationMatrix() encountered an unknown order: "+e)}return this._order=e,n===!0&&this._onChangeCallback(),this}setFromQuaternion(t,e,n){return Gu.makeRotationFromQuaternion(t),this.setFromRotationMatrix(Gu,e,n)}setFromVector3(t,e=this._order){return this.set(t.x,t.y,t.z,e)}reorder(t){return Vu.setFromEuler(this),this.setFromQuaternion(Vu,t)}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._order===this._order}fromArray(t){return this._x=t[0],this._y=t[1],this._z=t[2],t[3]!==void 0&&(this._order=t[3]),this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._order,t}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}}Ds.DEFAULT_ORDER="XYZ";class Vh{constructor(){this.mask=1}set(t){this.mask=(1<<t|0)>>>0}enable(t){this.mask|=1<<t|0}enableAll(){this.mask=-1}toggle(t){this.mask^=1<<t|0}disable(t){this.mask&=~(1<<t|0)}disableAll(){this.mask=0}test(t){return(this.mask&t.mask)!==0}isEnabled(t){return(this.mask&(1<<t|0))!==0}}let H0=0;const Wu=new k,pr=new Ls,es=new De,Ja=new k,sa=new k,G0=new k,V0=new Ls,Xu=new k(1,0,0),$u=new k(0,1,0),Yu=new k(0,0,1),qu={type:"added"},W0={type:"removed"},mr={type:"childadded",child:null},Ol={type:"childremoved",child:null};class Sn extends Is{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:H0++}),this.uuid=js(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=Sn.DEFAULT_UP.clone();const t=new k,e=new Ds,n=new Ls,s=new k(1,1,1);function r(){n.setFromEuler(e,!1)}function a(){e.setFromQuaternion(n,void 0,!1)}e._onChange(r),n._onChange(a),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:t},rotation:{configurable:!0,enumerable:!0,value:e},quaternion:{configurable:!0,enumerable:!0,value:n},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new De},normalMatrix:{value:new re}}),this.matrix=new De,this.matrixWorld=new De,this.matrixAutoUpdate=Sn.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=Sn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Vh,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(t){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(t),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(t){return this.quaternion.premultiply(t),this}setRotationFromAxisAngle(t,e){this.quaternion.setFromAxisAngle(t,e)}setRotationFromEuler(t){this.quaternion.setFromEuler(t,!0)}setRotationFromMatrix(t){this.quaternion.setFromRotationMatrix(t)}setRotationFromQuaternion(t){this.quaternion.copy(t)}rotateOnAxis(t,e){return pr.setFromAxisAngle(t,e),this.quaternion.multiply(pr),this}rotateOnWorldAxis(t,e){return pr.setFromAxisAngle(t,e),this.quaternion.premultiply(pr),this}rotateX(t){return this.rotateOnAxis(Xu,t)}rotateY(t){return this.rotateOnAxis($u,t)}rotateZ(t){return this.rotateOnAxis(Yu,t)}translateOnAxis(t,e){return Wu.copy(t).applyQuaternion(this.quaternion),this.position.add(Wu.multiplyScalar(e)),this}translateX(t){return this.translateOnAxis(Xu,t)}translateY(t){return this.translateOnAxis($u,t)}translateZ(t){return this.translateOnAxis(Yu,t)}localToWorld(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(this.matrixWorld)}worldToLocal(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(es.copy(this.matrixWorld).invert())}lookAt(t,e,n){t.isVector3?Ja.copy(t):Ja.set(t,e,n);const s=this.parent;this.updateWorldMatrix(!0,!1),sa.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?es.lookAt(sa,Ja,this.up):es.lookAt(Ja,sa,this.up),this.quaternion.setFromRotationMatrix(es),s&&(es.extractRotation(s.matrixWorld),pr.setFromRotationMatrix(es),this.quaternion.premultiply(pr.invert()))}add(t){if(arguments.length>1){for(let e=0;e<arguments.length;e++)this.add(arguments[e]);return this}return t===this?(Se("Object3D.add: object can't be added as a child of itself.",t),this):(t&&t.isObject3D?(t.removeFromParent(),t.parent=this,this.children.push(t),t.dispatchEvent(qu),mr.child=t,this.dispatchEvent(mr),mr.child=null):Se("Object3D.add: object not an instance of THREE.Object3D.",t),this)}remove(t){if(arguments.length>1){for(let n=0;n<arguments.length;n++)this.remove(arguments[n]);return this}const e=this.children.indexOf(t);return e!==-1&&(t.parent=null,this.children.splice(e,1),t.dispatchEvent(W0),Ol.child=t,this.dispatchEvent(Ol),Ol.child=null),this}removeFromParent(){const t=this.parent;return t!==null&&t.remove(this),this}clear(){return this.remove(...this.children)}attach(t){return this.updateWorldMatrix(!0,!1),es.copy(this.matrixWorld).invert(),t.parent!==null&&(t.parent.updateWorldMatrix(!0,!1),es.multiply(t.parent.matrixWorld)),t.applyMatrix4(es),t.removeFromParent(),t.parent=this,this.children.push(t),t.updateWorldMatrix(!1,!0),t.dispatchEvent(qu),mr.child=t,this.dispatchEvent(mr),mr.child=null,this}getObjectById(t){return this.getObjectByProperty("id",t)}getObjectByName(t){return this.getObjectByProperty("name",t)}getObjectByProperty(t,e){if(this[t]===e)return this;for(let n=0,s=this.children.length;n<s;n++){const a=this.children[n].getObjectByProperty(t,e);if(a!==void 0)return a}}getObjectsByProperty(t,e,n=[]){this[t]===e&&n.push(this);const s=this.children;for(let r=0,a=s.length;r<a;r++)s[r].getObjectsByProperty(t,e,n);return n}getWorldPosition(t){return this.updateWorldMatrix(!0,!1),t.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(sa,t,G0),t}getWorldScale(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(sa,V0,t),t}getWorldDirection(t){this.updateWorldMatrix(!0,!1);const e=this.matrixWorld.elements;return t.set(e[8],e[9],e[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(t){t(this);const e=this.children;for(let n=0,s=e.length;n<s;n++)e[n].traverse(t)}traverseVisible(t){if(this.visible===!1)return;t(this);const e=this.children;for(let n=0,s=e.length;n<s;n++)e[n].traverseVisible(t)}traverseAncestors(t){const e=this.parent;e!==null&&(t(e),e.traverseAncestors(t))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);const t=this.pivot;if(t!==null){const e=t.x,n=t.y,s=t.z,r=this.matrix.elements;r[12]+=e-r[0]*e-r[4]*n-r[8]*s,r[13]+=n-r[1]*e-r[5]*n-r[9]*s,r[14]+=s-r[2]*e-r[6]*n-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(t){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||t)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,t=!0);const e=this.children;for(let n=0,s=e.length;n<s;n++)e[n].updateMatrixWorld(t)}updateWorldMatrix(t,e,n=!1){const s=this.parent;if(t===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||n)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,n=!0),e===!0){const r=this.children;for(let a=0,o=r.length;a<o;a++)r[a].updateWorldMatrix(!1,!0,n)}}toJSON(t){const e=t===void 0||typeof t=="string",n={};e&&(t={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},n.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});const s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(o=>({...o,boundingBox:o.boundingBox?o.boundingBox.toJSON():void 0,boundingSphere:o.boundingSphere?o.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(o=>({...o})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(t),s.indirectTexture=this._indirectTexture.toJSON(t),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(t)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(o,l){return o[l.uuid]===void 0&&(o[l.uuid]=l.toJSON(t)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(t).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(t).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(t.geometries,this.geometry);const o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){const l=o.shapes;if(Array.isArray(l))for(let c=0,h=l.length;c<h;c++){const u=l[c];r(t.shapes,u)}else r(t.shapes,l)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(t.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){const o=[];for(let l=0,c=this.material.length;l<c;l++)o.push(r(t.materials,this.material[l]));s.material=o}else s.material=r(t.materials,this.material);if(this.children.length>0){s.children=[];for(let o=0;o<this.children.length;o++)s.children.push(this.children[o].toJSON(t).object)}if(this.animations.length>0){s.animations=[];for(let o=0;o<this.animations.length;o++){const l=this.animations[o];s.animations.push(r(t.animations,l))}}if(e){const o=a(t.geometries),l=a(t.materials),c=a(t.textures),h=a(t.images),u=a(t.shapes),d=a(t.skeletons),m=a(t.animations),_=a(t.nodes);o.length>0&&(n.geometries=o),l.length>0&&(n.materials=l),c.length>0&&(n.textures=c),h.length>0&&(n.images=h),u.length>0&&(n.shapes=u),d.length>0&&(n.skeletons=d),m.length>0&&(n.animations=m),_.length>0&&(n.nodes=_)}return n.object=s,n;function a(o){const l=[];for(const c in o){const h=o[c];delete h.metadata,l.push(h)}return l}}clone(t){return new this.constructor().copy(this,t)}copy(t,e=!0){if(this.name=t.name,this.up.copy(t.up),this.position.copy(t.position),this.rotation.order=t.rotation.order,this.quaternion.copy(t.quaternion),this.scale.copy(t.scale),this.pivot=t.pivot!==null?t.pivot.clone():null,this.matrix.copy(t.matrix),this.matrixWorld.copy(t.matrixWorld),this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrixWorldAutoUpdate=t.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=t.matrixWorldNeedsUpdate,this.layers.mask=t.layers.mask,this.visible=t.visible,this.castShadow=t.castShadow,this.receiveShadow=t.receiveShadow,this.frustumCulled=t.frustumCulled,this.renderOrder=t.renderOrder,this.static=t.static,this.animations=t.animations.slice(),this.userData=JSON.parse(JSON.stringify(t.userData)),e===!0)for(let n=0;n<t.children.length;n++){const s=t.children[n];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}}Sn.DEFAULT_UP=new k(0,1,0);Sn.DEFAULT_MATRIX_AUTO_UPDATE=!0;Sn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;class Vi extends Sn{constructor(){super(),this.isGroup=!0,this.type="Group"}}const X0={type:"move"};class Bl{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Vi,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Vi,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new k,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new k),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Vi,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new k,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new k,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(t){return this._targetRay!==null&&this._targetRay.dispatchEvent(t),this._grip!==null&&this._grip.dispatchEvent(t),this._hand!==null&&this._hand.dispatchEvent(t),this}connect(t){if(t&&t.hand){const e=this._hand;if(e)for(const n of t.hand.values())this._getHandJoint(e,n)}return this.dispatchEvent({type:"connected",data:t}),this}disconnect(t){return this.dispatchEvent({type:"disconnected",data:t}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(t,e,n){let s=null,r=null,a=null;const o=this._targetRay,l=this._grip,c=this._hand;if(t&&e.session.visibilityState!=="visible-blurred"){if(c&&t.hand){a=!0;for(const M of t.hand.values()){const p=e.getJointPose(M,n),f=this._getHandJoint(c,M);p!==null&&(f.matrix.fromArray(p.transform.matrix),f.matrix.decompose(f.position,f.quaternion,f.scale),f.matrixWorldNeedsUpdate=!0,f.jointRadius=p.radius),f.visible=p!==null}const h=c.joints["index-finger-tip"],u=c.joints["thumb-tip"],d=h.position.distanceTo(u.position),m=.02,_=.005;c.inputState.pinching&&d>m+_?(c.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:t.handedness,target:this})):!c.inputState.pinching&&d<=m-_&&(c.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:t.handedness,target:this}))}else l!==null&&t.gripSpace&&(r=e.getPose(t.gripSpace,n),r!==null&&(l.matrix.fromArray(r.transform.matrix),l.matrix.decompose(l.position,l.quaternion,l.scale),l.matrixWorldNeedsUpdate=!0,r.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(r.linearVelocity)):l.hasLinearVelocity=!1,r.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(r.angularVelocity)):l.hasAngularVelocity=!1,l.eventsEnabled&&l.dispatchEvent({type:"gripUpdated",data:t,target:this})));o!==null&&(s=e.getPose(t.targetRaySpace,n),s===null&&r!==null&&(s=r),s!==null&&(o.matrix.fromArray(s.transform.matrix),o.matrix.decompose(o.position,o.quaternion,o.scale),o.matrixWorldNeedsUpdate=!0,s.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(s.linearVelocity)):o.hasLinearVelocity=!1,s.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(s.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(X0)))}return o!==null&&(o.visible=s!==null),l!==null&&(l.visible=r!==null),c!==null&&(c.visible=a!==null),this}_getHandJoint(t,e){if(t.joints[e.jointName]===void 0){const n=new Vi;n.matrixAutoUpdate=!1,n.visible=!1,t.joints[e.jointName]=n,t.add(n)}return t.joints[e.jointName]}}const Ep={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},vs={h:0,s:0,l:0},ja={h:0,s:0,l:0};function zl(i,t,e){return e<0&&(e+=1),e>1&&(e-=1),e<1/6?i+(t-i)*6*e:e<1/2?t:e<2/3?i+(t-i)*6*(2/3-e):i}class ce{constructor(t,e,n){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(t,e,n)}set(t,e,n){if(e===void 0&&n===void 0){const s=t;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(t,e,n);return this}setScalar(t){return this.r=t,this.g=t,this.b=t,this}setHex(t,e=ci){return t=Math.floor(t),this.r=(t>>16&255)/255,this.g=(t>>8&255)/255,this.b=(t&255)/255,xe.colorSpaceToWorking(this,e),this}setRGB(t,e,n,s=xe.workingColorSpace){return this.r=t,this.g=e,this.b=n,xe.colorSpaceToWorking(this,s),this}setHSL(t,e,n,s=xe.workingColorSpace){if(t=P0(t,1),e=pe(e,0,1),n=pe(n,0,1),e===0)this.r=this.g=this.b=n;else{const r=n<=.5?n*(1+e):n+e-n*e,a=2*n-r;this.r=zl(a,r,t+1/3),this.g=zl(a,r,t),this.b=zl(a,r,t-1/3)}return xe.colorSpaceToWorking(this,s),this}setStyle(t,e=ci){function n(r){r!==void 0&&parseFloat(r)<1&&jt("Color: Alpha component of "+t+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(t)){let r;const a=s[1],o=s[2];switch(a){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,e);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,e);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,e);break;default:jt("Color: Unknown color model "+t)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(t)){const r=s[1],a=r.length;if(a===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,e);if(a===6)return this.setHex(parseInt(r,16),e);jt("Color: Invalid hex color "+t)}else if(t&&t.length>0)return this.setColorName(t,e);return this}setColorName(t,e=ci){const n=Ep[t.toLowerCase()];return n!==void 0?this.setHex(n,e):jt("Color: Unknown color "+t),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(t){return this.r=t.r,this.g=t.g,this.b=t.b,this}copySRGBToLinear(t){return this.r=ls(t.r),this.g=ls(t.g),this.b=ls(t.b),this}copyLinearToSRGB(t){return this.r=Fr(t.r),this.g=Fr(t.g),this.b=Fr(t.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(t=ci){return xe.workingToColorSpace(Nn.copy(this),t),Math.round(pe(Nn.r*255,0,255))*65536+Math.round(pe(Nn.g*255,0,255))*256+Math.round(pe(Nn.b*255,0,255))}getHexString(t=ci){return("000000"+this.getHex(t).toString(16)).slice(-6)}getHSL(t,e=xe.workingColorSpace){xe.workingToColorSpace(Nn.copy(this),e);const n=Nn.r,s=Nn.g,r=Nn.b,a=Math.max(n,s,r),o=Math.min(n,s,r);let l,c;const h=(o+a)/2;if(o===a)l=0,c=0;else{const u=a-o;switch(c=h<=.5?u/(a+o):u/(2-a-o),a){case n:l=(s-r)/u+(s<r?6:0);break;case s:l=(r-n)/u+2;break;case r:l=(n-s)/u+4;break}l/=6}return t.h=l,t.s=c,t.l=h,t}getRGB(t,e=xe.workingColorSpace){return xe.workingToColorSpace(Nn.copy(this),e),t.r=Nn.r,t.g=Nn.g,t.b=Nn.b,t}getStyle(t=ci){xe.workingToColorSpace(Nn.copy(this),t);const e=Nn.r,n=Nn.g,s=Nn.b;return t!==ci?`color(${t} ${e.toFixed(3)} ${n.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(e*255)},${Math.round(n*255)},${Math.round(s*255)})`}offsetHSL(t,e,n){return this.getHSL(vs),this.setHSL(vs.h+t,vs.s+e,vs.l+n)}add(t){return this.r+=t.r,this.g+=t.g,this.b+=t.b,this}addColors(t,e){return this.r=t.r+e.r,this.g=t.g+e.g,this.b=t.b+e.b,this}addScalar(t){return this.r+=t,this.g+=t,this.b+=t,this}sub(t){return this.r=Math.max(0,this.r-t.r),this.g=Math.max(0,this.g-t.g),this.b=Math.max(0,this.b-t.b),this}multiply(t){return this.r*=t.r,this.g*=t.g,this.b*=t.b,this}multiplyScalar(t){return this.r*=t,this.g*=t,this.b*=t,this}lerp(t,e){return this.r+=(t.r-this.r)*e,this.g+=(t.g-this.g)*e,this.b+=(t.b-this.b)*e,this}lerpColors(t,e,n){return this.r=t.r+(e.r-t.r)*n,this.g=t.g+(e.g-t.g)*n,this.b=t.b+(e.b-t.b)*n,this}lerpHSL(t,e){this.getHSL(vs),t.getHSL(ja);const n=Dl(vs.h,ja.h,e),s=Dl(vs.s,ja.s,e),r=Dl(vs.l,ja.l,e);return this.setHSL(n,s,r),this}setFromVector3(t){return this.r=t.x,this.g=t.y,this.b=t.z,this}applyMatrix3(t){const e=this.r,n=this.g,s=this.b,r=t.elements;return this.r=r[0]*e+r[3]*n+r[6]*s,this.g=r[1]*e+r[4]*n+r[7]*s,this.b=r[2]*e+r[5]*n+r[8]*s,this}equals(t){return t.r===this.r&&t.g===this.g&&t.b===this.b}fromArray(t,e=0){return this.r=t[e],this.g=t[e+1],this.b=t[e+2],this}toArray(t=[],e=0){return t[e]=this.r,t[e+1]=this.g,t[e+2]=this.b,t}fromBufferAttribute(t,e){return this.r=t.getX(e),this.g=t.getY(e),this.b=t.getZ(e),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}}const Nn=new ce;ce.NAMES=Ep;class wp extends Sn{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Ds,this.environmentIntensity=1,this.environmentRotation=new Ds,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(t,e){return super.copy(t,e),this.background=t.background!==null?t.background.clone():null,this.environment=t.environment!==null?t.environment.clone():null,this.fog=t.fog!==null?t.fog.clone():null,this.backgroundBlurriness=t.backgroundBlurriness,this.backgroundIntensity=t.backgroundIntensity,this.backgroundRotation.copy(t.backgroundRotation),this.environmentIntensity=t.environmentIntensity,this.environmentRotation.copy(t.environmentRotation),this.overrideMaterial=t.overrideMaterial!==null?t.overrideMaterial.clone():null,this.matrixAutoUpdate=t.matrixAutoUpdate,this}toJSON(t){const e=super.toJSON(t);return this.fog!==null&&(e.object.fog=this.fog.toJSON()),e.object.backgroundBlurriness=this.backgroundBlurriness,e.object.backgroundIntensity=this.backgroundIntensity,e.object.backgroundRotation=this.backgroundRotation.toArray(),e.object.environmentIntensity=this.environmentIntensity,e.object.environmentRotation=this.environmentRotation.toArray(),e}}const Mi=new k,ns=new k,kl=new k,is=new k,gr=new k,_r=new k,Ku=new k,Hl=new k,Gl=new k,Vl=new k,Wl=new nn,Xl=new nn,$l=new nn;class fi{constructor(t=new k,e=new k,n=new k){this.a=t,this.b=e,this.c=n}static getNormal(t,e,n,s){s.subVectors(n,e),Mi.subVectors(t,e),s.cross(Mi);const r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(t,e,n,s,r){Mi.subVectors(s,e),ns.subVectors(n,e),kl.subVectors(t,e);const a=Mi.dot(Mi),o=Mi.dot(ns),l=Mi.dot(kl),c=ns.dot(ns),h=ns.dot(kl),u=a*c-o*o;if(u===0)return r.set(0,0,0),null;const d=1/u,m=(c*l-o*h)*d,_=(a*h-o*l)*d;return r.set(1-m-_,_,m)}static containsPoint(t,e,n,s){return this.getBarycoord(t,e,n,s,is)===null?!1:is.x>=0&&is.y>=0&&is.x+is.y<=1}static getInterpolation(t,e,n,s,r,a,o,l){return this.getBarycoord(t,e,n,s,is)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(r,is.x),l.addScaledVector(a,is.y),l.addScaledVector(o,is.z),l)}static getInterpolatedAttribute(t,e,n,s,r,a){return Wl.setScalar(0),Xl.setScalar(0),$l.setScalar(0),Wl.fromBufferAttribute(t,e),Xl.fromBufferAttribute(t,n),$l.fromBufferAttribute(t,s),a.setScalar(0),a.addScaledVector(Wl,r.x),a.addScaledVector(Xl,r.y),a.addScaledVector($l,r.z),a}static isFrontFacing(t,e,n,s){return Mi.subVectors(n,e),ns.subVectors(t,e),Mi.cross(ns).dot(s)<0}set(t,e,n){return this.a.copy(t),this.b.copy(e),this.c.copy(n),this}setFromPointsAndIndices(t,e,n,s){return this.a.copy(t[e]),this.b.copy(t[n]),this.c.copy(t[s]),this}setFromAttributeAndIndices(t,e,n,s){return this.a.fromBufferAttribute(t,e),this.b.fromBufferAttribute(t,n),this.c.fromBufferAttribute(t,s),this}clone(){return new this.constructor().copy(this)}copy(t){return this.a.copy(t.a),this.b.copy(t.b),this.c.copy(t.c),this}getArea(){return Mi.subVectors(this.c,this.b),ns.subVectors(this.a,this.b),Mi.cross(ns).length()*.5}getMidpoint(t){return t.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(t){return fi.getNormal(this.a,this.b,this.c,t)}getPlane(t){return t.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(t,e){return fi.getBarycoord(t,this.a,this.b,this.c,e)}getInterpolation(t,e,n,s,r){return fi.getInterpolation(t,this.a,this.b,this.c,e,n,s,r)}containsPoint(t){return fi.containsPoint(t,this.a,this.b,this.c)}isFrontFacing(t){return fi.isFrontFacing(this.a,this.b,this.c,t)}intersectsBox(t){return t.intersectsTriangle(this)}closestPointToPoint(t,e){const n=this.a,s=this.b,r=this.c;let a,o;gr.subVectors(s,n),_r.subVectors(r,n),Hl.subVectors(t,n);const l=gr.dot(Hl),c=_r.dot(Hl);if(l<=0&&c<=0)return e.copy(n);Gl.subVectors(t,s);const h=gr.dot(Gl),u=_r.dot(Gl);if(h>=0&&u<=h)return e.copy(s);const d=l*u-h*c;if(d<=0&&l>=0&&h<=0&&l-h>0)return a=l/(l-h),e.copy(n).addScaledVector(gr,a);Vl.subVectors(t,r);const m=gr.dot(Vl),_=_r.dot(Vl);if(_>=0&&m<=_)return e.copy(r);const M=m*c-l*_;if(M<=0&&c>=0&&_<=0)return o=c/(c-_),e.copy(n).addScaledVector(_r,o);const p=h*_-m*u;if(p<=0&&u-h>=0&&m-_>=0)return Ku.subVectors(r,s),o=(u-h)/(u-h+(m-_)),e.copy(s).addScaledVector(Ku,o);const f=1/(p+M+d);return a=M*f,o=d*f,e.copy(n).addScaledVector(gr,a).addScaledVector(_r,o)}equals(t){return t.a.equals(this.a)&&t.b.equals(this.b)&&t.c.equals(this.c)}}class za{constructor(t=new k(1/0,1/0,1/0),e=new k(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=t,this.max=e}set(t,e){return this.min.copy(t),this.max.copy(e),this}setFromArray(t){this.makeEmpty();for(let e=0,n=t.length;e<n;e+=3)this.expandByPoint(yi.fromArray(t,e));return this}setFromBufferAttribute(t){this.makeEmpty();for(let e=0,n=t.count;e<n;e++)this.expandByPoint(yi.fromBufferAttribute(t,e));return this}setFromPoints(t){this.makeEmpty();for(let e=0,n=t.length;e<n;e++)this.expandByPoint(t[e]);return this}setFromCenterAndSize(t,e){const n=yi.copy(e).multiplyScalar(.5);return this.min.copy(t).sub(n),this.max.copy(t).add(n),this}setFromObject(t,e=!1){return this.makeEmpty(),this.expandByObject(t,e)}clone(){return new this.constructor().copy(this)}copy(t){return this.min.copy(t.min),this.max.copy(t.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(t){return this.isEmpty()?t.set(0,0,0):t.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(t){return this.isEmpty()?t.set(0,0,0):t.subVectors(this.max,this.min)}expandByPoint(t){return this.min.min(t),this.max.max(t),this}expandByVector(t){return this.min.sub(t),this.max.add(t),this}expandByScalar(t){return this.min.addScalar(-t),this.max.addScalar(t),this}expandByObject(t,e=!1){t.updateWorldMatrix(!1,!1);const n=t.geometry;if(n!==void 0){const r=n.getAttribute("position");if(e===!0&&r!==void 0&&t.isInstancedMesh!==!0&&t.isBatchedMesh!==!0)for(let a=0,o=r.count;a<o;a++)t.isMesh===!0?t.getVertexPosition(a,yi):yi.fromBufferAttribute(r,a),yi.applyMatrix4(t.matrixWorld),this.expandByPoint(yi);else t.boundingBox!==void 0?(t.boundingBox===null&&t.computeBoundingBox(),Qa.copy(t.boundingBox)):(n.boundingBox===null&&n.computeBoundingBox(),Qa.copy(n.boundingBox)),Qa.applyMatrix4(t.matrixWorld),this.union(Qa)}const s=t.children;for(let r=0,a=s.length;r<a;r++)this.expandByObject(s[r],e);return this}containsPoint(t){return t.x>=this.min.x&&t.x<=this.max.x&&t.y>=this.min.y&&t.y<=this.max.y&&t.z>=this.min.z&&t.z<=this.max.z}containsBox(t){return this.min.x<=t.min.x&&t.max.x<=this.max.x&&this.min.y<=t.min.y&&t.max.y<=this.max.y&&this.min.z<=t.min.z&&t.max.z<=this.max.z}getParameter(t,e){return e.set((t.x-this.min.x)/(this.max.x-this.min.x),(t.y-this.min.y)/(this.max.y-this.min.y),(t.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(t){return t.max.x>=this.min.x&&t.min.x<=this.max.x&&t.max.y>=this.min.y&&t.min.y<=this.max.y&&t.max.z>=this.min.z&&t.min.z<=this.max.z}intersectsSphere(t){return this.clampPoint(t.center,yi),yi.distanceToSquared(t.center)<=t.radius*t.radius}intersectsPlane(t){let e,n;return t.normal.x>0?(e=t.normal.x*this.min.x,n=t.normal.x*this.max.x):(e=t.normal.x*this.max.x,n=t.normal.x*this.min.x),t.normal.y>0?(e+=t.normal.y*this.min.y,n+=t.normal.y*this.max.y):(e+=t.normal.y*this.max.y,n+=t.normal.y*this.min.y),t.normal.z>0?(e+=t.normal.z*this.min.z,n+=t.normal.z*this.max.z):(e+=t.normal.z*this.max.z,n+=t.normal.z*this.min.z),e<=-t.constant&&n>=-t.constant}intersectsTriangle(t){if(this.isEmpty())return!1;this.getCenter(ra),to.subVectors(this.max,ra),vr.subVectors(t.a,ra),xr.subVectors(t.b,ra),Sr.subVectors(t.c,ra),xs.subVectors(xr,vr),Ss.subVectors(Sr,xr),Bs.subVectors(vr,Sr);let e=[0,-xs.z,xs.y,0,-Ss.z,Ss.y,0,-Bs.z,Bs.y,xs.z,0,-xs.x,Ss.z,0,-Ss.x,Bs.z,0,-Bs.x,-xs.y,xs.x,0,-Ss.y,Ss.x,0,-Bs.y,Bs.x,0];return!Yl(e,vr,xr,Sr,to)||(e=[1,0,0,0,1,0,0,0,1],!Yl(e,vr,xr,Sr,to))?!1:(eo.crossVectors(xs,Ss),e=[eo.x,eo.y,eo.z],Yl(e,vr,xr,Sr,to))}clampPoint(t,e){return e.copy(t).clamp(this.min,this.max)}distanceToPoint(t){return this.clampPoint(t,yi).distanceTo(t)}getBoundingSphere(t){return this.isEmpty()?t.makeEmpty():(this.getCenter(t.center),t.radius=this.getSize(yi).length()*.5),t}intersect(t){return this.min.max(t.min),this.max.min(t.max),this.isEmpty()&&this.makeEmpty(),this}union(t){return this.min.min(t.min),this.max.max(t.max),this}applyMatrix4(t){return this.isEmpty()?this:(ss[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(t),ss[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(t),ss[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(t),ss[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(t),ss[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(t),ss[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(t),ss[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(t),ss[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(t),this.setFromPoints(ss),this)}translate(t){return this.min.add(t),this.max.add(t),this}equals(t){return t.min.equals(this.min)&&t.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(t){return this.min.fromArray(t.min),this.max.fromArray(t.max),this}}const ss=[new k,new k,new k,new k,new k,new k,new k,new k],yi=new k,Qa=new za,vr=new k,xr=new k,Sr=new k,xs=new k,Ss=new k,Bs=new k,ra=new k,to=new k,eo=new k,zs=new k;function Yl(i,t,e,n,s){for(let r=0,a=i.length-3;r<=a;r+=3){zs.fromArray(i,r);const o=s.x*Math.abs(zs.x)+s.y*Math.abs(zs.y)+s.z*Math.abs(zs.z),l=t.dot(zs),c=e.dot(zs),h=n.dot(zs);if(Math.max(-Math.max(l,c,h),Math.min(l,c,h))>o)return!1}return!0}const un=new k,no=new Xt;let $0=0;class pi extends Is{constructor(t,e,n=!1){if(super(),Array.isArray(t))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:$0++}),this.name="",this.array=t,this.itemSize=e,this.count=t!==void 0?t.length/e:0,this.normalized=n,this.usage=xp,this.updateRanges=[],this.gpuType=Hi,this.version=0,this._normalizationScale=t!==void 0?tl(t):void 0}onUploadCallback(){}set needsUpdate(t){t===!0&&this.version++}setUsage(t){return this.usage=t,this}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}copy(t){return this.name=t.name,this.array=new t.array.constructor(t.array),this.itemSize=t.itemSize,this.count=t.count,this.normalized=t.normalized,this.usage=t.usage,this.gpuType=t.gpuType,this._normalizationScale=t._normalizationScale,this}copyAt(t,e,n){t*=this.itemSize,n*=e.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[t+s]=e.array[n+s];return this}copyArray(t){return this.array.set(t),this}applyMatrix3(t){if(this.itemSize===2)for(let e=0,n=this.count;e<n;e++)no.fromBufferAttribute(this,e),no.applyMatrix3(t),this.setXY(e,no.x,no.y);else if(this.itemSize===3)for(let e=0,n=this.count;e<n;e++)un.fromBufferAttribute(this,e),un.applyMatrix3(t),this.setXYZ(e,un.x,un.y,un.z);return this}applyMatrix4(t){for(let e=0,n=this.count;e<n;e++)un.fromBufferAttribute(this,e),un.applyMatrix4(t),this.setXYZ(e,un.x,un.y,un.z);return this}applyNormalMatrix(t){for(let e=0,n=this.count;e<n;e++)un.fromBufferAttribute(this,e),un.applyNormalMatrix(t),this.setXYZ(e,un.x,un.y,un.z);return this}transformDirection(t){for(let e=0,n=this.count;e<n;e++)un.fromBufferAttribute(this,e),un.transformDirection(t),this.setXYZ(e,un.x,un.y,un.z);return this}set(t,e=0){return this.array.set(t,e),this}getComponent(t,e){let n=this.array[t*this.itemSize+e];return this.normalized&&(n=this._denormalize(n)),n}setComponent(t,e,n){return this.normalized&&(n=this._normalize(n)),this.array[t*this.itemSize+e]=n,this}getX(t){let e=this.array[t*this.itemSize];return this.normalized&&(e=this._denormalize(e)),e}setX(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize]=e,this}getY(t){let e=this.array[t*this.itemSize+1];return this.normalized&&(e=this._denormalize(e)),e}setY(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+1]=e,this}getZ(t){let e=this.array[t*this.itemSize+2];return this.normalized&&(e=this._denormalize(e)),e}setZ(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+2]=e,this}getW(t){let e=this.array[t*this.itemSize+3];return this.normalized&&(e=this._denormalize(e)),e}setW(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+3]=e,this}setXY(t,e,n){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n)),this.array[t+0]=e,this.array[t+1]=n,this}setXYZ(t,e,n,s){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n),s=this._normalize(s)),this.array[t+0]=e,this.array[t+1]=n,this.array[t+2]=s,this}setXYZW(t,e,n,s,r){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.array[t+0]=e,this.array[t+1]=n,this.array[t+2]=s,this.array[t+3]=r,this}onUpload(t){return this.onUploadCallback=t,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){const t={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return t.name=this.name,t.usage=this.usage,t.gpuType=this.gpuType,t}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(t){const e=this._normalizationScale;return e!==void 0?Math.max(t/e,-1):Mp(t,this.array)}_normalize(t){const e=this._normalizationScale;return e!==void 0?Math.round(t*e):yp(t,this.array)}}class Tp extends pi{constructor(t,e,n){super(new Uint16Array(t),e,n)}}class Ap extends pi{constructor(t,e,n){super(new Uint32Array(t),e,n)}}class sn extends pi{constructor(t,e,n){super(new Float32Array(t),e,n)}}const Y0=new za,aa=new k,ql=new k;class ka{constructor(t=new k,e=-1){this.isSphere=!0,this.center=t,this.radius=e}set(t,e){return this.center.copy(t),this.radius=e,this}setFromPoints(t,e){const n=this.center;e!==void 0?n.copy(e):Y0.setFromPoints(t).getCenter(n);let s=0;for(let r=0,a=t.length;r<a;r++)s=Math.max(s,n.distanceToSquared(t[r]));return this.radius=Math.sqrt(s),this}copy(t){return this.center.copy(t.center),this.radius=t.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(t){return t.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(t){return t.distanceTo(this.center)-this.radius}intersectsSphere(t){const e=this.radius+t.radius;return t.center.distanceToSquared(this.center)<=e*e}intersectsBox(t){return t.intersectsSphere(this)}intersectsPlane(t){return Math.abs(t.distanceToPoint(this.center))<=this.radius}clampPoint(t,e){const n=this.center.distanceToSquared(t);return e.copy(t),n>this.radius*this.radius&&(e.sub(this.center).normalize(),e.multiplyScalar(this.radius).add(this.center)),e}getBoundingBox(t){return this.isEmpty()?(t.makeEmpty(),t):(t.set(this.center,this.center),t.expandByScalar(this.radius),t)}applyMatrix4(t){return this.center.applyMatrix4(t),this.radius=this.radius*t.getMaxScaleOnAxis(),this}translate(t){return this.center.add(t),this}expandByPoint(t){if(this.isEmpty())return this.center.copy(t),this.radius=0,this;aa.subVectors(t,this.center);const e=aa.lengthSq();if(e>this.radius*this.radius){const n=Math.sqrt(e),s=(n-this.radius)*.5;this.center.addScaledVector(aa,s/n),this.radius+=s}return this}union(t){return t.isEmpty()?this:this.isEmpty()?(this.copy(t),this):(this.center.equals(t.center)===!0?this.radius=Math.max(this.radius,t.radius):(ql.subVectors(t.center,this.center).setLength(t.radius),this.expandByPoint(aa.copy(t.center).add(ql)),this.expandByPoint(aa.copy(t.center).sub(ql))),this)}equals(t){return t.center.equals(this.center)&&t.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(t){return this.radius=t.radius,this.center.fromArray(t.center),this}}let q0=0;const ai=new De,Kl=new Sn,Mr=new k,Qn=new za,oa=new za,Rn=new k;class Be extends Is{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:q0++}),this.uuid=js(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(t){return Array.isArray(t)?this.index=new(T0(t)?Ap:Tp)(t,1):this.index=t,this}setIndirect(t,e=0){return this.indirect=t,this.indirectOffset=e,this}getIndirect(){return this.indirect}getAttribute(t){return this.attributes[t]}setAttribute(t,e){return this.attributes[t]=e,this}deleteAttribute(t){return delete this.attributes[t],this}hasAttribute(t){return this.attributes[t]!==void 0}addGroup(t,e,n=0){this.groups.push({start:t,count:e,materialIndex:n})}clearGroups(){this.groups=[]}setDrawRange(t,e){this.drawRange.start=t,this.drawRange.count=e}applyMatrix4(t){const e=this.attributes.position;e!==void 0&&(e.applyMatrix4(t),e.needsUpdate=!0);const n=this.attributes.normal;if(n!==void 0){const r=new re().getNormalMatrix(t);n.applyNormalMatrix(r),n.needsUpdate=!0}const s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(t),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(t){return ai.makeRotationFromQuaternion(t),this.applyMatrix4(ai),this}rotateX(t){return ai.makeRotationX(t),this.applyMatrix4(ai),this}rotateY(t){return ai.makeRotationY(t),this.applyMatrix4(ai),this}rotateZ(t){return ai.makeRotationZ(t),this.applyMatrix4(ai),this}translate(t,e,n){return ai.makeTranslation(t,e,n),this.applyMatrix4(ai),this}scale(t,e,n){return ai.makeScale(t,e,n),this.applyMatrix4(ai),this}lookAt(t){return Kl.lookAt(t),Kl.updateMatrix(),this.applyMatrix4(Kl.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(Mr).negate(),this.translate(Mr.x,Mr.y,Mr.z),this}setFromPoints(t){const e=this.getAttribute("position");if(e===void 0){const n=[];for(let s=0,r=t.length;s<r;s++){const a=t[s];n.push(a.x,a.y,a.z||0)}this.setAttribute("position",new sn(n,3))}else{const n=Math.min(t.length,e.count);for(let s=0;s<n;s++){const r=t[s];e.setXYZ(s,r.x,r.y,r.z||0)}t.length>e.count&&jt("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),e.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new za);const t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){Se("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new k(-1/0,-1/0,-1/0),new k(1/0,1/0,1/0));return}if(t!==void 0){if(this.boundingBox.setFromBufferAttribute(t),e)for(let n=0,s=e.length;n<s;n++){const r=e[n];Qn.setFromBufferAttribute(r),this.morphTargetsRelative?(Rn.addVectors(this.boundingBox.min,Qn.min),this.boundingBox.expandByPoint(Rn),Rn.addVectors(this.boundingBox.max,Qn.max),this.boundingBox.expandByPoint(Rn)):(this.boundingBox.expandByPoint(Qn.min),this.boundingBox.expandByPoint(Qn.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&Se('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new ka);const t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){Se("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new k,1/0);return}if(t){const n=this.boundingSphere.center;if(Qn.setFromBufferAttribute(t),e)for(let r=0,a=e.length;r<a;r++){const o=e[r];oa.setFromBufferAttribute(o),this.morphTargetsRelative?(Rn.addVectors(Qn.min,oa.min),Qn.expandByPoint(Rn),Rn.addVectors(Qn.max,oa.max),Qn.expandByPoint(Rn)):(Qn.expandByPoint(oa.min),Qn.expandByPoint(oa.max))}Qn.getCenter(n);let s=0;for(let r=0,a=t.count;r<a;r++)Rn.fromBufferAttribute(t,r),s=Math.max(s,n.distanceToSquared(Rn));if(e)for(let r=0,a=e.length;r<a;r++){const o=e[r],l=this.morphTargetsRelative;for(let c=0,h=o.count;c<h;c++)Rn.fromBufferAttribute(o,c),l&&(Mr.fromBufferAttribute(t,c),Rn.add(Mr)),s=Math.max(s,n.distanceToSquared(Rn))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&Se('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){const t=this.index,e=this.attributes;if(t===null||e.position===void 0||e.normal===void 0||e.uv===void 0){Se("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}const n=e.position,s=e.normal,r=e.uv;let a=this.getAttribute("tangent");(a===void 0||a.count!==n.count)&&(a=new pi(new Float32Array(4*n.count),4),this.setAttribute("tangent",a));const o=[],l=[],c=new Uint8Array(n.count);for(let z=0;z<n.count;z++)o[z]=new k,l[z]=new k;const h=new k,u=new k,d=new k,m=new Xt,_=new Xt,M=new Xt,p=new k,f=new k;function x(z,I,L){c[z]=c[I]=c[L]=1,h.fromBufferAttribute(n,z),u.fromBufferAttribute(n,I),d.fromBufferAttribute(n,L),m.fromBufferAttribute(r,z),_.fromBufferAttribute(r,I),M.fromBufferAttribute(r,L),u.sub(h),d.sub(h),_.sub(m),M.sub(m);const V=1/(_.x*M.y-M.x*_.y);isFinite(V)&&(p.copy(u).multiplyScalar(M.y).addScaledVector(d,-_.y).multiplyScalar(V),f.copy(d).multiplyScalar(_.x).addScaledVector(u,-M.x).multiplyScalar(V),o[z].add(p),o[I].add(p),o[L].add(p),l[z].add(f),l[I].add(f),l[L].add(f))}let A=this.groups;A.length===0&&(A=[{start:0,count:t.count}]);for(let z=0,I=A.length;z<I;++z){const L=A[z],V=L.start,$=L.count;for(let N=V,W=V+$;N<W;N+=3)x(t.getX(N+0),t.getX(N+1),t.getX(N+2))}const S=new k,R=new k,b=new k,g=new k;function w(z){b.fromBufferAttribute(s,z),g.copy(b);const I=o[z];S.copy(I),S.sub(b.multiplyScalar(b.dot(I))).normalize(),R.crossVectors(g,I);const V=R.dot(l[z])<0?-1:1;a.setXYZW(z,S.x,S.y,S.z,V)}for(let z=0,I=n.count;z<I;++z)c[z]&&w(z);this._transformed=!0}computeVertexNormals(){const t=this.index,e=this.getAttribute("position");if(e!==void 0){let n=this.getAttribute("normal");if(n===void 0||n.count!==e.count)n=new pi(new Float32Array(e.count*3),3),this.setAttribute("normal",n);else for(let d=0,m=n.count;d<m;d++)n.setXYZ(d,0,0,0);const s=new k,r=new k,a=new k,o=new k,l=new k,c=new k,h=new k,u=new k;if(t)for(let d=0,m=t.count;d<m;d+=3){const _=t.getX(d+0),M=t.getX(d+1),p=t.getX(d+2);s.fromBufferAttribute(e,_),r.fromBufferAttribute(e,M),a.fromBufferAttribute(e,p),h.subVectors(a,r),u.subVectors(s,r),h.cross(u),o.fromBufferAttribute(n,_),l.fromBufferAttribute(n,M),c.fromBufferAttribute(n,p),o.add(h),l.add(h),c.add(h),n.setXYZ(_,o.x,o.y,o.z),n.setXYZ(M,l.x,l.y,l.z),n.setXYZ(p,c.x,c.y,c.z)}else for(let d=0,m=e.count;d<m;d+=3)s.fromBufferAttribute(e,d+0),r.fromBufferAttribute(e,d+1),a.fromBufferAttribute(e,d+2),h.subVectors(a,r),u.subVectors(s,r),h.cross(u),n.setXYZ(d+0,h.x,h.y,h.z),n.setXYZ(d+1,h.x,h.y,h.z),n.setXYZ(d+2,h.x,h.y,h.z);this.normalizeNormals(),n.needsUpdate=!0}}normalizeNormals(){const t=this.attributes.normal;for(let e=0,n=t.count;e<n;e++)Rn.fromBufferAttribute(t,e),Rn.normalize(),t.setXYZ(e,Rn.x,Rn.y,Rn.z)}toNonIndexed(){function t(o,l){const c=o.array,h=o.itemSize,u=o.normalized,d=new c.constructor(l.length*h);let m=0,_=0;for(let M=0,p=l.length;M<p;M++){o.isInterleavedBufferAttribute?m=l[M]*o.data.stride+o.offset:m=l[M]*h;for(let f=0;f<h;f++)d[_++]=c[m++]}return new pi(d,h,u)}if(this.index===null)return jt("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;const e=new Be,n=this.index.array,s=this.attributes;for(const o in s){const l=s[o],c=t(l,n);e.setAttribute(o,c)}const r=this.morphAttributes;for(const o in r){const l=[],c=r[o];for(let h=0,u=c.length;h<u;h++){const d=c[h],m=t(d,n);l.push(m)}e.morphAttributes[o]=l}e.morphTargetsRelative=this.morphTargetsRelative;const a=this.groups;for(let o=0,l=a.length;o<l;o++){const c=a[o];e.addGroup(c.start,c.count,c.materialIndex)}return e}toJSON(){const t={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(t.uuid=this.uuid,t.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,t.name=this.name,Object.keys(this.userData).length>0&&(t.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){const l=this.parameters;for(const c in l)l[c]!==void 0&&(t[c]=l[c]);return t}t.data={attributes:{}};const e=this.index;e!==null&&(t.data.index={type:e.array.constructor.name,array:Array.prototype.slice.call(e.array)});const n=this.attributes;for(const l in n){const c=n[l];t.data.attributes[l]=c.toJSON(t.data)}const s={};let r=!1;for(const l in this.morphAttributes){const c=this.morphAttributes[l],h=[];for(let u=0,d=c.length;u<d;u++){const m=c[u];h.push(m.toJSON(t.data))}h.length>0&&(s[l]=h,r=!0)}r&&(t.data.morphAttributes=s,t.data.morphTargetsRelative=this.morphTargetsRelative);const a=this.groups;a.length>0&&(t.data.groups=JSON.parse(JSON.stringify(a)));const o=this.boundingSphere;return o!==null&&(t.data.boundingSphere=o.toJSON()),t}clone(){return new this.constructor().copy(this)}copy(t){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;const e={};this.name=t.name;const n=t.index;n!==null&&this.setIndex(n.clone());const s=t.attributes;for(const c in s){const h=s[c];this.setAttribute(c,h.clone(e))}const r=t.morphAttributes;for(const c in r){const h=[],u=r[c];for(let d=0,m=u.length;d<m;d++)h.push(u[d].clone(e));this.morphAttributes[c]=h}this.morphTargetsRelative=t.morphTargetsRelative;const a=t.groups;for(let c=0,h=a.length;c<h;c++){const u=a[c];this.addGroup(u.start,u.count,u.materialIndex)}const o=t.boundingBox;o!==null&&(this.boundingBox=o.clone());const l=t.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=t.drawRange.start,this.drawRange.count=t.drawRange.count,this.userData=t.userData,this._transformed=t._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}}class K0{constructor(t,e){this.isInterleavedBuffer=!0,this.array=t,this.stride=e,this.count=t!==void 0?t.length/e:0,this.usage=xp,this.updateRanges=[],this.version=0,this.uuid=js()}onUploadCallback(){}set needsUpdate(t){t===!0&&this.version++}setUsage(t){return this.usage=t,this}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}copy(t){return this.array=new t.array.constructor(t.array),this.count=t.count,this.stride=t.stride,this.usage=t.usage,this}copyAt(t,e,n){t*=this.stride,n*=e.stride;for(let s=0,r=this.stride;s<r;s++)this.array[t+s]=e.array[n+s];return this}set(t,e=0){return this.array.set(t,e),this}clone(t){t.arrayBuffers===void 0&&(t.arrayBuffers={});const e=Zu(this.array);t.arrayBuffers[e]===void 0&&(t.arrayBuffers[e]=this.array.slice(0).buffer);const n=new this.array.constructor(t.arrayBuffers[e]),s=new this.constructor(n,this.stride);return s.setUsage(this.usage),s}onUpload(t){return this.onUploadCallback=t,this}toJSON(t){t.arrayBuffers===void 0&&(t.arrayBuffers={});const e=Zu(this.array);t.arrayBuffers[e]===void 0&&(t.arrayBuffers[e]=Array.from(new Uint32Array(this.array.slice(0).buffer)));const n={uuid:this.uuid,buffer:e,type:this.array.constructor.name,stride:this.stride};return n.usage=this.usage,n}}function Zu(i){return i.buffer._uuid===void 0&&(i.buffer._uuid=js()),i.byteOffset===0&&i.byteLength===i.buffer.byteLength?i.buffer._uuid:i.buffer._uuid+":"+i.byteOffset+":"+i.byteLength}const Hn=new k;class Yo{constructor(t,e,n,s=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=t,this.itemSize=e,this.offset=n,this.normalized=s,this._normalizationScale=t!==void 0?tl(t.array):void 0}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(t){this.data.needsUpdate=t}applyMatrix4(t){for(let e=0,n=this.data.count;e<n;e++)Hn.fromBufferAttribute(this,e),Hn.applyMatrix4(t),this.setXYZ(e,Hn.x,Hn.y,Hn.z);return this}applyNormalMatrix(t){for(let e=0,n=this.count;e<n;e++)Hn.fromBufferAttribute(this,e),Hn.applyNormalMatrix(t),this.setXYZ(e,Hn.x,Hn.y,Hn.z);return this}transformDirection(t){for(let e=0,n=this.count;e<n;e++)Hn.fromBufferAttribute(this,e),Hn.transformDirection(t),this.setXYZ(e,Hn.x,Hn.y,Hn.z);return this}getComponent(t,e){let n=this.array[t*this.data.stride+this.offset+e];return this.normalized&&(n=this._denormalize(n)),n}setComponent(t,e,n){return this.normalized&&(n=this._normalize(n)),this.data.array[t*this.data.stride+this.offset+e]=n,this}setX(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset]=e,this}setY(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+1]=e,this}setZ(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+2]=e,this}setW(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+3]=e,this}getX(t){let e=this.data.array[t*this.data.stride+this.offset];return this.normalized&&(e=this._denormalize(e)),e}getY(t){let e=this.data.array[t*this.data.stride+this.offset+1];return this.normalized&&(e=this._denormalize(e)),e}getZ(t){let e=this.data.array[t*this.data.stride+this.offset+2];return this.normalized&&(e=this._denormalize(e)),e}getW(t){let e=this.data.array[t*this.data.stride+this.offset+3];return this.normalized&&(e=this._denormalize(e)),e}setXY(t,e,n){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n)),this.data.array[t+0]=e,this.data.array[t+1]=n,this}setXYZ(t,e,n,s){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n),s=this._normalize(s)),this.data.array[t+0]=e,this.data.array[t+1]=n,this.data.array[t+2]=s,this}setXYZW(t,e,n,s,r){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.data.array[t+0]=e,this.data.array[t+1]=n,this.data.array[t+2]=s,this.data.array[t+3]=r,this}clone(t){if(t===void 0){$o("InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");const e=[];for(let n=0;n<this.count;n++){const s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)e.push(this.data.array[s+r])}return new pi(new this.array.constructor(e),this.itemSize,this.normalized)}else return t.interleavedBuffers===void 0&&(t.interleavedBuffers={}),t.interleavedBuffers[this.data.uuid]===void 0&&(t.interleavedBuffers[this.data.uuid]=this.data.clone(t)),new Yo(t.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(t){if(t===void 0){$o("InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");const e=[];for(let n=0;n<this.count;n++){const s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)e.push(this.data.array[s+r])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:e,normalized:this.normalized}}else return t.interleavedBuffers===void 0&&(t.interleavedBuffers={}),t.interleavedBuffers[this.data.uuid]===void 0&&(t.interleavedBuffers[this.data.uuid]=this.data.toJSON(t)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}_denormalize(t){const e=this._normalizationScale;return e!==void 0?Math.max(t/e,-1):Mp(t,this.data.array)}_normalize(t){const e=this._normalizationScale;return e!==void 0?Math.round(t*e):yp(t,this.data.array)}}const Zl=new k,Z0=new k,J0=new re;class wi{constructor(t=new k(1,0,0),e=0){this.isPlane=!0,this.normal=t,this.constant=e}set(t,e){return this.normal.copy(t),this.constant=e,this}setComponents(t,e,n,s){return this.normal.set(t,e,n),this.constant=s,this}setFromNormalAndCoplanarPoint(t,e){return this.normal.copy(t),this.constant=-e.dot(this.normal),this}setFromCoplanarPoints(t,e,n){const s=Zl.subVectors(n,e).cross(Z0.subVectors(t,e)).normalize();return this.setFromNormalAndCoplanarPoint(s,t),this}copy(t){return this.normal.copy(t.normal),this.constant=t.constant,this}normalize(){const t=1/this.normal.length();return this.normal.multiplyScalar(t),this.constant*=t,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(t){return this.normal.dot(t)+this.constant}distanceToSphere(t){return this.distanceToPoint(t.center)-t.radius}projectPoint(t,e){return e.copy(t).addScaledVector(this.normal,-this.distanceToPoint(t))}intersectLine(t,e,n=!0){const s=t.delta(Zl),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(t.start)===0?e.copy(t.start):null;const a=-(t.start.dot(this.normal)+this.constant)/r;return n===!0&&(a<0||a>1)?null:e.copy(t.start).addScaledVector(s,a)}intersectsLine(t){const e=this.distanceToPoint(t.start),n=this.distanceToPoint(t.end);return e<0&&n>0||n<0&&e>0}intersectsBox(t){return t.intersectsPlane(this)}intersectsSphere(t){return t.intersectsPlane(this)}coplanarPoint(t){return t.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(t,e){const n=e||J0.getNormalMatrix(t),s=this.coplanarPoint(Zl).applyMatrix4(t),r=this.normal.applyMatrix3(n).normalize();return this.constant=-s.dot(r),this}translate(t){return this.constant-=t.dot(this.normal),this}equals(t){return t.normal.equals(this.normal)&&t.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(t){return this.normal.fromArray(t.normal),this.constant=t.constant,this}}let j0=0;class Qs extends Is{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:j0++}),this.uuid=js(),this.name="",this.type="Material",this.blending=Ma,this.side=Cs,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=jf,this.blendDst=Qf,this.blendEquation=Lr,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new ce(0,0,0),this.blendAlpha=0,this.depthFunc=Ca,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=S0,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=Ll,this.stencilZFail=Ll,this.stencilZPass=Ll,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(t){this._alphaTest>0!=t>0&&this.version++,this._alphaTest=t}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(t){if(t!==void 0)for(const e in t){const n=t[e];if(n===void 0){jt(`Material: parameter '${e}' has value of undefined.`);continue}const s=this[e];if(s===void 0){jt(`Material: '${e}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(n):s&&s.isVector2&&n&&n.isVector2||s&&s.isEuler&&n&&n.isEuler||s&&s.isVector3&&n&&n.isVector3?s.copy(n):this[e]=n}}toJSON(t){const e=t===void 0||typeof t=="string";e&&(t={textures:{},images:{}});const n={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};n.uuid=this.uuid,n.type=this.type,n.blending=this.blending,n.side=this.side,n.shadowSide=this.shadowSide,n.vertexColors=this.vertexColors,n.opacity=this.opacity,n.transparent=this.transparent,n.blendSrc=this.blendSrc,n.blendDst=this.blendDst,n.blendEquation=this.blendEquation,n.blendSrcAlpha=this.blendSrcAlpha,n.blendDstAlpha=this.blendDstAlpha,n.blendEquationAlpha=this.blendEquationAlpha,n.blendColor=this.blendColor.getHex(),n.blendAlpha=this.blendAlpha,n.depthFunc=this.depthFunc,n.depthTest=this.depthTest,n.depthWrite=this.depthWrite,n.colorWrite=this.colorWrite,n.clipIntersection=this.clipIntersection,n.clipShadows=this.clipShadows,n.stencilWriteMask=this.stencilWriteMask,n.stencilFunc=this.stencilFunc,n.stencilRef=this.stencilRef,n.stencilFuncMask=this.stencilFuncMask,n.stencilFail=this.stencilFail,n.stencilZFail=this.stencilZFail,n.stencilZPass=this.stencilZPass,n.stencilWrite=this.stencilWrite,n.polygonOffset=this.polygonOffset,n.polygonOffsetFactor=this.polygonOffsetFactor,n.polygonOffsetUnits=this.polygonOffsetUnits,n.dithering=this.dithering,n.alphaTest=this.alphaTest,n.alphaHash=this.alphaHash,n.alphaToCoverage=this.alphaToCoverage,n.premultipliedAlpha=this.premultipliedAlpha,n.forceSinglePass=this.forceSinglePass,n.allowOverride=this.allowOverride,n.visible=this.visible,n.toneMapped=this.toneMapped,n.name=this.name,this.color&&this.color.isColor&&(n.color=this.color.getHex()),this.roughness!==void 0&&(n.roughness=this.roughness),this.metalness!==void 0&&(n.metalness=this.metalness),this.sheen!==void 0&&(n.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(n.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(n.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(n.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(n.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(n.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(n.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(n.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(n.shininess=this.shininess),this.clearcoat!==void 0&&(n.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(n.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(n.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(n.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(t).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(n.clearcoatMap=this.clearcoatMap.toJSON(t).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(n.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(t).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(n.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(t).uuid,n.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(n.sheenColorMap=this.sheenColorMap.toJSON(t).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(n.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(t).uuid),this.dispersion!==void 0&&(n.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(n.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(n.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(n.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(n.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(n.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(n.iridescenceMap=this.iridescenceMap.toJSON(t).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(n.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(t).uuid),this.anisotropy!==void 0&&(n.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(n.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(n.anisotropyMap=this.anisotropyMap.toJSON(t).uuid),this.map&&this.map.isTexture&&(n.map=this.map.toJSON(t).uuid),this.matcap&&this.matcap.isTexture&&(n.matcap=this.matcap.toJSON(t).uuid),this.alphaMap&&this.alphaMap.isTexture&&(n.alphaMap=this.alphaMap.toJSON(t).uuid),this.lightMap&&this.lightMap.isTexture&&(n.lightMap=this.lightMap.toJSON(t).uuid,n.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(n.aoMap=this.aoMap.toJSON(t).uuid,n.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(n.bumpMap=this.bumpMap.toJSON(t).uuid,n.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(n.normalMap=this.normalMap.toJSON(t).uuid,n.normalMapType=this.normalMapType,n.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(n.displacementMap=this.displacementMap.toJSON(t).uuid,n.displacementScale=this.displacementScale,n.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(n.roughnessMap=this.roughnessMap.toJSON(t).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(n.metalnessMap=this.metalnessMap.toJSON(t).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(n.emissiveMap=this.emissiveMap.toJSON(t).uuid),this.specularMap&&this.specularMap.isTexture&&(n.specularMap=this.specularMap.toJSON(t).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(n.specularIntensityMap=this.specularIntensityMap.toJSON(t).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(n.specularColorMap=this.specularColorMap.toJSON(t).uuid),this.envMap&&this.envMap.isTexture&&(n.envMap=this.envMap.toJSON(t).uuid,this.combine!==void 0&&(n.combine=this.combine)),this.envMapRotation!==void 0&&(n.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(n.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(n.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(n.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(n.gradientMap=this.gradientMap.toJSON(t).uuid),this.transmission!==void 0&&(n.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(n.transmissionMap=this.transmissionMap.toJSON(t).uuid),this.thickness!==void 0&&(n.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(n.thicknessMap=this.thicknessMap.toJSON(t).uuid),this.attenuationDistance!==void 0&&(n.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(n.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(n.size=this.size),this.sizeAttenuation!==void 0&&(n.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(n.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(n.rotation=this.rotation),this.depthPacking!==void 0&&(n.depthPacking=this.depthPacking),this.linewidth!==void 0&&(n.linewidth=this.linewidth),this.linecap!==void 0&&(n.linecap=this.linecap),this.linejoin!==void 0&&(n.linejoin=this.linejoin),this.dashSize!==void 0&&(n.dashSize=this.dashSize),this.gapSize!==void 0&&(n.gapSize=this.gapSize),this.scale!==void 0&&(n.scale=this.scale),this.wireframe!==void 0&&(n.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(n.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(n.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(n.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(n.flatShading=this.flatShading),this.fog!==void 0&&(n.fog=this.fog),Object.keys(this.userData).length>0&&(n.userData=this.userData);function s(r){const a=[];for(const o in r){const l=r[o];delete l.metadata,a.push(l)}return a}if(e){const r=s(t.textures),a=s(t.images);r.length>0&&(n.textures=r),a.length>0&&(n.images=a)}return n}fromJSON(t,e){if(t.uuid!==void 0&&(this.uuid=t.uuid),t.name!==void 0&&(this.name=t.name),t.color!==void 0&&this.color!==void 0&&this.color.setHex(t.color),t.roughness!==void 0&&(this.roughness=t.roughness),t.metalness!==void 0&&(this.metalness=t.metalness),t.sheen!==void 0&&(this.sheen=t.sheen),t.sheenColor!==void 0&&(this.sheenColor=new ce().setHex(t.sheenColor)),t.sheenRoughness!==void 0&&(this.sheenRoughness=t.sheenRoughness),t.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(t.emissive),t.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(t.specular),t.specularIntensity!==void 0&&(this.specularIntensity=t.specularIntensity),t.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(t.specularColor),t.shininess!==void 0&&(this.shininess=t.shininess),t.clearcoat!==void 0&&(this.clearcoat=t.clearcoat),t.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=t.clearcoatRoughness),t.diffuseRoughness!==void 0&&(this.diffuseRoughness=t.diffuseRoughness),t.dispersion!==void 0&&(this.dispersion=t.dispersion),t.retroreflectivity!==void 0&&(this.retroreflectivity=t.retroreflectivity),t.iridescence!==void 0&&(this.iridescence=t.iridescence),t.iridescenceIOR!==void 0&&(this.iridescenceIOR=t.iridescenceIOR),t.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessMinimum),t.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=t.iridescenceThicknessMaximum),t.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=t.iridescenceThicknessRange[1]),t.transmission!==void 0&&(this.transmission=t.transmission),t.thickness!==void 0&&(this.thickness=t.thickness),t.attenuationDistance!==void 0&&(this.attenuationDistance=t.attenuationDistance),t.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(t.attenuationColor),t.anisotropy!==void 0&&(this.anisotropy=t.anisotropy),t.anisotropyRotation!==void 0&&(this.anisotropyRotation=t.anisotropyRotation),t.fog!==void 0&&(this.fog=t.fog),t.flatShading!==void 0&&(this.flatShading=t.flatShading),t.blending!==void 0&&(this.blending=t.blending),t.combine!==void 0&&(this.combine=t.combine),t.side!==void 0&&(this.side=t.side),t.shadowSide!==void 0&&(this.shadowSide=t.shadowSide),t.opacity!==void 0&&(this.opacity=t.opacity),t.transparent!==void 0&&(this.transparent=t.transparent),t.alphaTest!==void 0&&(this.alphaTest=t.alphaTest),t.alphaHash!==void 0&&(this.alphaHash=t.alphaHash),t.depthFunc!==void 0&&(this.depthFunc=t.depthFunc),t.depthTest!==void 0&&(this.depthTest=t.depthTest),t.depthWrite!==void 0&&(this.depthWrite=t.depthWrite),t.colorWrite!==void 0&&(this.colorWrite=t.colorWrite),t.clippingPlanes!==void 0&&(this.clippingPlanes=t.clippingPlanes.map(n=>new wi().fromJSON(n))),t.clipIntersection!==void 0&&(this.clipIntersection=t.clipIntersection),t.clipShadows!==void 0&&(this.clipShadows=t.clipShadows),t.depthPacking!==void 0&&(this.depthPacking=t.depthPacking),t.blendSrc!==void 0&&(this.blendSrc=t.blendSrc),t.blendDst!==void 0&&(this.blendDst=t.blendDst),t.blendEquation!==void 0&&(this.blendEquation=t.blendEquation),t.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=t.blendSrcAlpha),t.blendDstAlpha!==void 0&&(this.blendDstAlpha=t.blendDstAlpha),t.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=t.blendEquationAlpha),t.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(t.blendColor),t.blendAlpha!==void 0&&(this.blendAlpha=t.blendAlpha),t.stencilWriteMask!==void 0&&(this.stencilWriteMask=t.stencilWriteMask),t.stencilFunc!==void 0&&(this.stencilFunc=t.stencilFunc),t.stencilRef!==void 0&&(this.stencilRef=t.stencilRef),t.stencilFuncMask!==void 0&&(this.stencilFuncMask=t.stencilFuncMask),t.stencilFail!==void 0&&(this.stencilFail=t.stencilFail),t.stencilZFail!==void 0&&(this.stencilZFail=t.stencilZFail),t.stencilZPass!==void 0&&(this.stencilZPass=t.stencilZPass),t.stencilWrite!==void 0&&(this.stencilWrite=t.stencilWrite),t.wireframe!==void 0&&(this.wireframe=t.wireframe),t.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=t.wireframeLinewidth),t.wireframeLinecap!==void 0&&(this.wireframeLinecap=t.wireframeLinecap),t.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=t.wireframeLinejoin),t.rotation!==void 0&&(this.rotation=t.rotation),t.linewidth!==void 0&&(this.linewidth=t.linewidth),t.linecap!==void 0&&(this.linecap=t.linecap),t.linejoin!==void 0&&(this.linejoin=t.linejoin),t.dashSize!==void 0&&(this.dashSize=t.dashSize),t.gapSize!==void 0&&(this.gapSize=t.gapSize),t.scale!==void 0&&(this.scale=t.scale),t.polygonOffset!==void 0&&(this.polygonOffset=t.polygonOffset),t.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=t.polygonOffsetFactor),t.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=t.polygonOffsetUnits),t.dithering!==void 0&&(this.dithering=t.dithering),t.alphaToCoverage!==void 0&&(this.alphaToCoverage=t.alphaToCoverage),t.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=t.premultipliedAlpha),t.forceSinglePass!==void 0&&(this.forceSinglePass=t.forceSinglePass),t.allowOverride!==void 0&&(this.allowOverride=t.allowOverride),t.visible!==void 0&&(this.visible=t.visible),t.toneMapped!==void 0&&(this.toneMapped=t.toneMapped),t.userData!==void 0&&(this.userData=t.userData),t.vertexColors!==void 0&&(typeof t.vertexColors=="number"?this.vertexColors=t.vertexColors>0:this.vertexColors=t.vertexColors),t.size!==void 0&&(this.size=t.size),t.sizeAttenuation!==void 0&&(this.sizeAttenuation=t.sizeAttenuation),t.map!==void 0&&(this.map=e[t.map]||null),t.matcap!==void 0&&(this.matcap=e[t.matcap]||null),t.alphaMap!==void 0&&(this.alphaMap=e[t.alphaMap]||null),t.bumpMap!==void 0&&(this.bumpMap=e[t.bumpMap]||null),t.bumpScale!==void 0&&(this.bumpScale=t.bumpScale),t.normalMap!==void 0&&(this.normalMap=e[t.normalMap]||null),t.normalMapType!==void 0&&(this.normalMapType=t.normalMapType),t.normalScale!==void 0){let n=t.normalScale;Array.isArray(n)===!1&&(n=[n,n]),this.normalScale=new Xt().fromArray(n)}return t.displacementMap!==void 0&&(this.displacementMap=e[t.displacementMap]||null),t.displacementScale!==void 0&&(this.displacementScale=t.displacementScale),t.displacementBias!==void 0&&(this.displacementBias=t.displacementBias),t.roughnessMap!==void 0&&(this.roughnessMap=e[t.roughnessMap]||null),t.metalnessMap!==void 0&&(this.metalnessMap=e[t.metalnessMap]||null),t.emissiveMap!==void 0&&(this.emissiveMap=e[t.emissiveMap]||null),t.emissiveIntensity!==void 0&&(this.emissiveIntensity=t.emissiveIntensity),t.specularMap!==void 0&&(this.specularMap=e[t.specularMap]||null),t.specularIntensityMap!==void 0&&(this.specularIntensityMap=e[t.specularIntensityMap]||null),t.specularColorMap!==void 0&&(this.specularColorMap=e[t.specularColorMap]||null),t.envMap!==void 0&&(this.envMap=e[t.envMap]||null),t.envMapRotation!==void 0&&this.envMapRotation.fromArray(t.envMapRotation),t.envMapIntensity!==void 0&&(this.envMapIntensity=t.envMapIntensity),t.reflectivity!==void 0&&(this.reflectivity=t.reflectivity),t.refractionRatio!==void 0&&(this.refractionRatio=t.refractionRatio),t.lightMap!==void 0&&(this.lightMap=e[t.lightMap]||null),t.lightMapIntensity!==void 0&&(this.lightMapIntensity=t.lightMapIntensity),t.aoMap!==void 0&&(this.aoMap=e[t.aoMap]||null),t.aoMapIntensity!==void 0&&(this.aoMapIntensity=t.aoMapIntensity),t.gradientMap!==void 0&&(this.gradientMap=e[t.gradientMap]||null),t.clearcoatMap!==void 0&&(this.clearcoatMap=e[t.clearcoatMap]||null),t.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=e[t.clearcoatRoughnessMap]||null),t.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=e[t.clearcoatNormalMap]||null),t.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new Xt().fromArray(t.clearcoatNormalScale)),t.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=e[t.diffuseRoughnessMap]||null),t.iridescenceMap!==void 0&&(this.iridescenceMap=e[t.iridescenceMap]||null),t.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=e[t.iridescenceThicknessMap]||null),t.transmissionMap!==void 0&&(this.transmissionMap=e[t.transmissionMap]||null),t.thicknessMap!==void 0&&(this.thicknessMap=e[t.thicknessMap]||null),t.anisotropyMap!==void 0&&(this.anisotropyMap=e[t.anisotropyMap]||null),t.sheenColorMap!==void 0&&(this.sheenColorMap=e[t.sheenColorMap]||null),t.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=e[t.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(t){this.name=t.name,this.blending=t.blending,this.side=t.side,this.vertexColors=t.vertexColors,this.opacity=t.opacity,this.transparent=t.transparent,this.blendSrc=t.blendSrc,this.blendDst=t.blendDst,this.blendEquation=t.blendEquation,this.blendSrcAlpha=t.blendSrcAlpha,this.blendDstAlpha=t.blendDstAlpha,this.blendEquationAlpha=t.blendEquationAlpha,this.blendColor.copy(t.blendColor),this.blendAlpha=t.blendAlpha,this.depthFunc=t.depthFunc,this.depthTest=t.depthTest,this.depthWrite=t.depthWrite,this.stencilWriteMask=t.stencilWriteMask,this.stencilFunc=t.stencilFunc,this.stencilRef=t.stencilRef,this.stencilFuncMask=t.stencilFuncMask,this.stencilFail=t.stencilFail,this.stencilZFail=t.stencilZFail,this.stencilZPass=t.stencilZPass,this.stencilWrite=t.stencilWrite;const e=t.clippingPlanes;let n=null;if(e!==null){const s=e.length;n=new Array(s);for(let r=0;r!==s;++r)n[r]=e[r].clone()}return this.clippingPlanes=n,this.clipIntersection=t.clipIntersection,this.clipShadows=t.clipShadows,this.shadowSide=t.shadowSide,this.colorWrite=t.colorWrite,this.precision=t.precision,this.polygonOffset=t.polygonOffset,this.polygonOffsetFactor=t.polygonOffsetFactor,this.polygonOffsetUnits=t.polygonOffsetUnits,this.dithering=t.dithering,this.alphaTest=t.alphaTest,this.alphaHash=t.alphaHash,this.alphaToCoverage=t.alphaToCoverage,this.premultipliedAlpha=t.premultipliedAlpha,this.forceSinglePass=t.forceSinglePass,this.allowOverride=t.allowOverride,this.visible=t.visible,this.toneMapped=t.toneMapped,this.userData=JSON.parse(JSON.stringify(t.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(t){t===!0&&this.version++}}class Rp extends Qs{constructor(t){super(),this.isSpriteMaterial=!0,this.type="SpriteMaterial",this.color=new ce(16777215),this.map=null,this.alphaMap=null,this.rotation=0,this.sizeAttenuation=!0,this.transparent=!0,this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.alphaMap=t.alphaMap,this.rotation=t.rotation,this.sizeAttenuation=t.sizeAttenuation,this.fog=t.fog,this}}let yr;const la=new k,br=new k,Er=new k,wr=new Xt,ca=new Xt,Cp=new De,io=new k,ha=new k,so=new k,Ju=new Xt,Jl=new Xt,ju=new Xt;class Pp extends Sn{constructor(t=new Rp){if(super(),this.isSprite=!0,this.type="Sprite",yr===void 0){yr=new Be;const e=new Float32Array([-.5,-.5,0,0,0,.5,-.5,0,1,0,.5,.5,0,1,1,-.5,.5,0,0,1]),n=new K0(e,5);yr.setIndex([0,1,2,0,2,3]),yr.setAttribute("position",new Yo(n,3,0,!1)),yr.setAttribute("uv",new Yo(n,2,3,!1))}this.geometry=yr,this.material=t,this.center=new Xt(.5,.5),this.count=1}intersectsFrustum(t){return t.intersectsSprite(this)}raycast(t,e){t.camera===null&&Se('Sprite: "Raycaster.camera" needs to be set in order to raycast against sprites.'),br.setFromMatrixScale(this.matrixWorld),Cp.copy(t.camera.matrixWorld),this.modelViewMatrix.multiplyMatrices(t.camera.matrixWorldInverse,this.matrixWorld),Er.setFromMatrixPosition(this.modelViewMatrix),t.camera.isPerspectiveCamera&&this.material.sizeAttenuation===!1&&br.multiplyScalar(-Er.z);const n=this.material.rotation;let s,r;n!==0&&(r=Math.cos(n),s=Math.sin(n));const a=this.center;ro(io.set(-.5,-.5,0),Er,a,br,s,r),ro(ha.set(.5,-.5,0),Er,a,br,s,r),ro(so.set(.5,.5,0),Er,a,br,s,r),Ju.set(0,0),Jl.set(1,0),ju.set(1,1);let o=t.ray.intersectTriangle(io,ha,so,!1,la);if(o===null&&(ro(ha.set(-.5,.5,0),Er,a,br,s,r),Jl.set(0,1),o=t.ray.intersectTriangle(io,so,ha,!1,la),o===null))return;const l=t.ray.origin.distanceTo(la);l<t.near||l>t.far||e.push({distance:l,point:la.clone(),uv:fi.getInterpolation(la,io,ha,so,Ju,Jl,ju,new Xt),face:null,object:this})}copy(t,e){return super.copy(t,e),t.center!==void 0&&this.center.copy(t.center),this.material=t.material,this}toJSON(t){const e=super.toJSON(t);return e.object.center=this.center.toArray(),e}}function ro(i,t,e,n,s,r){wr.subVectors(i,e).addScalar(.5).multiply(n),s!==void 0?(ca.x=r*wr.x-s*wr.y,ca.y=s*wr.x+r*wr.y):ca.copy(wr),i.copy(t),i.x+=ca.x,i.y+=ca.y,i.applyMatrix4(Cp)}const rs=new k,jl=new k,ao=new k,oo=new k;class el{constructor(t=new k,e=new k(0,0,-1)){this.origin=t,this.direction=e}set(t,e){return this.origin.copy(t),this.direction.copy(e),this}copy(t){return this.origin.copy(t.origin),this.direction.copy(t.direction),this}at(t,e){return e.copy(this.origin).addScaledVector(this.direction,t)}lookAt(t){return this.direction.copy(t).sub(this.origin).normalize(),this}recast(t){return this.origin.copy(this.at(t,rs)),this}closestPointToPoint(t,e){e.subVectors(t,this.origin);const n=e.dot(this.direction);return n<0?e.copy(this.origin):e.copy(this.origin).addScaledVector(this.direction,n)}distanceToPoint(t){return Math.sqrt(this.distanceSqToPoint(t))}distanceSqToPoint(t){const e=rs.subVectors(t,this.origin).dot(this.direction);return e<0?this.origin.distanceToSquared(t):(rs.copy(this.origin).addScaledVector(this.direction,e),rs.distanceToSquared(t))}distanceSqToSegment(t,e,n,s){jl.copy(t).add(e).multiplyScalar(.5),ao.copy(e).sub(t).normalize(),oo.copy(this.origin).sub(jl);const r=t.distanceTo(e)*.5,a=-this.direction.dot(ao),o=oo.dot(this.direction),l=-oo.dot(ao),c=oo.lengthSq(),h=Math.abs(1-a*a);let u,d,m,_;if(h>0)if(u=a*l-o,d=a*o-l,_=r*h,u>=0)if(d>=-_)if(d<=_){const M=1/h;u*=M,d*=M,m=u*(u+a*d+2*o)+d*(a*u+d+2*l)+c}else d=r,u=Math.max(0,-(a*d+o)),m=-u*u+d*(d+2*l)+c;else d=-r,u=Math.max(0,-(a*d+o)),m=-u*u+d*(d+2*l)+c;else d<=-_?(u=Math.max(0,-(-a*r+o)),d=u>0?-r:Math.min(Math.max(-r,-l),r),m=-u*u+d*(d+2*l)+c):d<=_?(u=0,d=Math.min(Math.max(-r,-l),r),m=d*(d+2*l)+c):(u=Math.max(0,-(a*r+o)),d=u>0?r:Math.min(Math.max(-r,-l),r),m=-u*u+d*(d+2*l)+c);else d=a>0?-r:r,u=Math.max(0,-(a*d+o)),m=-u*u+d*(d+2*l)+c;return n&&n.copy(this.origin).addScaledVector(this.direction,u),s&&s.copy(jl).addScaledVector(ao,d),m}intersectSphere(t,e){if(t.radius<0)return null;rs.subVectors(t.center,this.origin);const n=rs.dot(this.direction),s=rs.dot(rs)-n*n,r=t.radius*t.radius;if(s>r)return null;const a=Math.sqrt(r-s),o=n-a,l=n+a;return l<0?null:o<0?this.at(l,e):this.at(o,e)}intersectsSphere(t){return t.radius<0?!1:this.distanceSqToPoint(t.center)<=t.radius*t.radius}distanceToPlane(t){const e=t.normal.dot(this.direction);if(e===0)return t.distanceToPoint(this.origin)===0?0:null;const n=-(this.origin.dot(t.normal)+t.constant)/e;return n>=0?n:null}intersectPlane(t,e){const n=this.distanceToPlane(t);return n===null?null:this.at(n,e)}intersectsPlane(t){const e=t.distanceToPoint(this.origin);return e===0||t.normal.dot(this.direction)*e<0}intersectBox(t,e){let n,s,r,a,o,l;const c=1/this.direction.x,h=1/this.direction.y,u=1/this.direction.z,d=this.origin;return c>=0?(n=(t.min.x-d.x)*c,s=(t.max.x-d.x)*c):(n=(t.max.x-d.x)*c,s=(t.min.x-d.x)*c),h>=0?(r=(t.min.y-d.y)*h,a=(t.max.y-d.y)*h):(r=(t.max.y-d.y)*h,a=(t.min.y-d.y)*h),n>a||r>s||((r>n||isNaN(n))&&(n=r),(a<s||isNaN(s))&&(s=a),u>=0?(o=(t.min.z-d.z)*u,l=(t.max.z-d.z)*u):(o=(t.max.z-d.z)*u,l=(t.min.z-d.z)*u),n>l||o>s)||((o>n||n!==n)&&(n=o),(l<s||s!==s)&&(s=l),s<0)?null:this.at(n>=0?n:s,e)}intersectsBox(t){return this.intersectBox(t,rs)!==null}intersectTriangle(t,e,n,s,r){const a=this.origin,o=this.direction,l=o.x,c=o.y,h=o.z,u=t.x-a.x,d=t.y-a.y,m=t.z-a.z,_=e.x-a.x,M=e.y-a.y,p=e.z-a.z,f=n.x-a.x,x=n.y-a.y,A=n.z-a.z,S=Math.abs(l),R=Math.abs(c),b=Math.abs(h);let g,w,z,I,L,V,$,N,W,J,H,ct;if(S>=R&&S>=b?(z=l,V=u,W=_,ct=f,l>=0?(g=c,w=h,I=d,L=m,$=M,N=p,J=x,H=A):(g=h,w=c,I=m,L=d,$=p,N=M,J=A,H=x)):R>=b?(z=c,V=d,W=M,ct=x,c>=0?(g=h,w=l,I=m,L=u,$=p,N=_,J=A,H=f):(g=l,w=h,I=u,L=m,$=_,N=p,J=f,H=A)):(z=h,V=m,W=p,ct=A,h>=0?(g=l,w=c,I=u,L=d,$=_,N=M,J=f,H=x):(g=c,w=l,I=d,L=u,$=M,N=_,J=x,H=f)),z===0)return null;const Z=g/z,tt=w/z,st=1/z,pt=I-Z*V,ft=L-tt*V,B=$-Z*W,et=N-tt*W,ht=J-Z*ct,gt=H-tt*ct,vt=ht*et-gt*B,Gt=pt*gt-ft*ht,Qt=B*ft-et*pt;if(s){if(vt<0||Gt<0||Qt<0)return null}else if((vt<0||Gt<0||Qt<0)&&(vt>0||Gt>0||Qt>0))return null;const kt=vt+Gt+Qt;if(kt===0)return null;const ne=st*(vt*V+Gt*W+Qt*ct);return(kt>0?ne<0:ne>0)?null:this.at(ne/kt,r)}applyMatrix4(t){return this.origin.applyMatrix4(t),this.direction.transformDirection(t),this}equals(t){return t.origin.equals(this.origin)&&t.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}}class As extends Qs{constructor(t){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new ce(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ds,this.combine=tp,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.specularMap=t.specularMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.combine=t.combine,this.reflectivity=t.reflectivity,this.refractionRatio=t.refractionRatio,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.fog=t.fog,this}}const Qu=new De,ks=new el,lo=new ka,td=new k,co=new k,ho=new k,uo=new k,Ql=new k,fo=new k,ed=new k,po=new k;class fn extends Sn{constructor(t=new Be,e=new As){super(),this.isMesh=!0,this.type="Mesh",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}updateMorphTargets(){const e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){const s=e[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}getVertexPosition(t,e){const n=this.geometry,s=n.attributes.position,r=n.morphAttributes.position,a=n.morphTargetsRelative;e.fromBufferAttribute(s,t);const o=this.morphTargetInfluences;if(r&&o){fo.set(0,0,0);for(let l=0,c=r.length;l<c;l++){const h=o[l],u=r[l];h!==0&&(Ql.fromBufferAttribute(u,t),a?fo.addScaledVector(Ql,h):fo.addScaledVector(Ql.sub(e),h))}e.add(fo)}return e}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){const n=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(n.boundingSphere===null&&n.computeBoundingSphere(),lo.copy(n.boundingSphere),lo.applyMatrix4(r),ks.copy(t.ray).recast(t.near),!(lo.containsPoint(ks.origin)===!1&&(ks.intersectSphere(lo,td)===null||ks.origin.distanceToSquared(td)>(t.far-t.near)**2))&&(Qu.copy(r).invert(),ks.copy(t.ray).applyMatrix4(Qu),!(n.boundingBox!==null&&ks.intersectsBox(n.boundingBox)===!1)&&this._computeIntersections(t,e,ks)))}_computeIntersections(t,e,n){let s;const r=this.geometry,a=this.material,o=r.index,l=r.attributes.position,c=r.attributes.uv,h=r.attributes.uv1,u=r.attributes.normal,d=r.groups,m=r.drawRange;if(o!==null)if(Array.isArray(a))for(let _=0,M=d.length;_<M;_++){const p=d[_],f=a[p.materialIndex],x=Math.max(p.start,m.start),A=Math.min(o.count,Math.min(p.start+p.count,m.start+m.count));for(let S=x,R=A;S<R;S+=3){const b=o.getX(S),g=o.getX(S+1),w=o.getX(S+2);s=mo(this,f,t,n,c,h,u,b,g,w),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=p.materialIndex,e.push(s))}}else{const _=Math.max(0,m.start),M=Math.min(o.count,m.start+m.count);for(let p=_,f=M;p<f;p+=3){const x=o.getX(p),A=o.getX(p+1),S=o.getX(p+2);s=mo(this,a,t,n,c,h,u,x,A,S),s&&(s.faceIndex=Math.floor(p/3),e.push(s))}}else if(l!==void 0)if(Array.isArray(a))for(let _=0,M=d.length;_<M;_++){const p=d[_],f=a[p.materialIndex],x=Math.max(p.start,m.start),A=Math.min(l.count,Math.min(p.start+p.count,m.start+m.count));for(let S=x,R=A;S<R;S+=3){const b=S,g=S+1,w=S+2;s=mo(this,f,t,n,c,h,u,b,g,w),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=p.materialIndex,e.push(s))}}else{const _=Math.max(0,m.start),M=Math.min(l.count,m.start+m.count);for(let p=_,f=M;p<f;p+=3){const x=p,A=p+1,S=p+2;s=mo(this,a,t,n,c,h,u,x,A,S),s&&(s.faceIndex=Math.floor(p/3),e.push(s))}}}}function Q0(i,t,e,n,s,r,a,o){let l;if(t.side===Yn?l=n.intersectTriangle(a,r,s,!0,o):l=n.intersectTriangle(s,r,a,t.side===Cs,o),l===null)return null;po.copy(o),po.applyMatrix4(i.matrixWorld);const c=e.ray.origin.distanceTo(po);return c<e.near||c>e.far?null:{distance:c,point:po.clone(),object:i}}function mo(i,t,e,n,s,r,a,o,l,c){i.getVertexPosition(o,co),i.getVertexPosition(l,ho),i.getVertexPosition(c,uo);const h=Q0(i,t,e,n,co,ho,uo,ed);if(h){const u=new k;fi.getBarycoord(ed,co,ho,uo,u),s&&(h.uv=fi.getInterpolatedAttribute(s,o,l,c,u,new Xt)),r&&(h.uv1=fi.getInterpolatedAttribute(r,o,l,c,u,new Xt)),a&&(h.normal=fi.getInterpolatedAttribute(a,o,l,c,u,new k),h.normal.dot(n.direction)>0&&h.normal.multiplyScalar(-1));const d={a:o,b:l,c,normal:new k,materialIndex:0};fi.getNormal(co,ho,uo,d.normal),h.face=d,h.barycoord=u}return h}class t_ extends In{constructor(t=null,e=1,n=1,s,r,a,o,l,c=Pn,h=Pn,u,d){super(null,a,o,l,c,h,s,r,u,d),this.isDataTexture=!0,this.image={data:t,width:e,height:n},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}}const Hs=new ka,e_=new Xt(.5,.5),go=new k;class Na{constructor(t=new wi,e=new wi,n=new wi,s=new wi,r=new wi,a=new wi){this.planes=[t,e,n,s,r,a]}set(t,e,n,s,r,a){const o=this.planes;return o[0].copy(t),o[1].copy(e),o[2].copy(n),o[3].copy(s),o[4].copy(r),o[5].copy(a),this}copy(t){const e=this.planes;for(let n=0;n<6;n++)e[n].copy(t.planes[n]);return this}setFromProjectionMatrix(t,e=Ai,n=!1){const s=this.planes,r=t.elements,a=r[0],o=r[1],l=r[2],c=r[3],h=r[4],u=r[5],d=r[6],m=r[7],_=r[8],M=r[9],p=r[10],f=r[11],x=r[12],A=r[13],S=r[14],R=r[15];if(s[0].setComponents(c-a,m-h,f-_,R-x).normalize(),s[1].setComponents(c+a,m+h,f+_,R+x).normalize(),s[2].setComponents(c+o,m+u,f+M,R+A).normalize(),s[3].setComponents(c-o,m-u,f-M,R-A).normalize(),n)s[4].setComponents(l,d,p,S).normalize(),s[5].setComponents(c-l,m-d,f-p,R-S).normalize();else if(s[4].setComponents(c-l,m-d,f-p,R-S).normalize(),e===Ai)s[5].setComponents(c+l,m+d,f+p,R+S).normalize();else if(e===Da)s[5].setComponents(l,d,p,S).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+e);return this}intersectsObject(t){if(t.boundingSphere!==void 0)t.boundingSphere===null&&t.computeBoundingSphere(),Hs.copy(t.boundingSphere).applyMatrix4(t.matrixWorld);else{const e=t.geometry;e.boundingSphere===null&&e.computeBoundingSphere(),Hs.copy(e.boundingSphere).applyMatrix4(t.matrixWorld)}return this.intersectsSphere(Hs)}intersectsSprite(t){Hs.center.set(0,0,0);const e=e_.distanceTo(t.center);return Hs.radius=.7071067811865476+e,Hs.applyMatrix4(t.matrixWorld),this.intersectsSphere(Hs)}intersectsSphere(t){const e=this.planes,n=t.center,s=-t.radius;for(let r=0;r<6;r++)if(e[r].distanceToPoint(n)<s)return!1;return!0}intersectsBox(t){const e=this.planes;for(let n=0;n<6;n++){const s=e[n];if(go.x=s.normal.x>0?t.max.x:t.min.x,go.y=s.normal.y>0?t.max.y:t.min.y,go.z=s.normal.z>0?t.max.z:t.min.z,s.distanceToPoint(go)<0)return!1}return!0}containsPoint(t){const e=this.planes;for(let n=0;n<6;n++)if(e[n].distanceToPoint(t)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}}const nd=new De;class Wh{constructor(){this.coordinateSystem=Ai,this._frustums=[],this._count=0}setFromArrayCamera(t){const e=t.cameras,n=this._frustums;for(let s=0;s<e.length;s++){const r=e[s];nd.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),n[s]===void 0&&(n[s]=new Na),n[s].setFromProjectionMatrix(nd,r.coordinateSystem,r.reversedDepth)}return this._count=e.length,this}getFrustum(t){return this._frustums[t]}intersectsObject(t){const e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsObject(t))return!0;return!1}intersectsSprite(t){const e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsSprite(t))return!0;return!1}intersectsSphere(t){const e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsSphere(t))return!0;return!1}intersectsBox(t){const e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsBox(t))return!0;return!1}containsPoint(t){const e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].containsPoint(t))return!0;return!1}copy(t){this.coordinateSystem=t.coordinateSystem;const e=this._frustums,n=t._frustums;for(let s=0;s<t._count;s++)e[s]===void 0&&(e[s]=new Na),e[s].copy(n[s]);return this._count=t._count,this}clone(){return new Wh().copy(this)}}class mi extends Qs{constructor(t){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new ce(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.linewidth=t.linewidth,this.linecap=t.linecap,this.linejoin=t.linejoin,this.fog=t.fog,this}}const qo=new k,Ko=new k,id=new De,ua=new el,_o=new ka,tc=new k,sd=new k;class Ki extends Sn{constructor(t=new Be,e=new mi){super(),this.isLine=!0,this.type="Line",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}computeLineDistances(){const t=this.geometry;if(t.index===null){const e=t.attributes.position,n=[0];for(let s=1,r=e.count;s<r;s++)qo.fromBufferAttribute(e,s-1),Ko.fromBufferAttribute(e,s),n[s]=n[s-1],n[s]+=qo.distanceTo(Ko);t.setAttribute("lineDistance",new sn(n,1))}else jt("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){const n=this.geometry,s=this.matrixWorld,r=t.params.Line.threshold,a=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),_o.copy(n.boundingSphere),_o.applyMatrix4(s),_o.radius+=r,t.ray.intersectsSphere(_o)===!1)return;id.copy(s).invert(),ua.copy(t.ray).applyMatrix4(id);const o=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=o*o,c=this.isLineSegments?2:1,h=n.index,d=n.attributes.position;if(h!==null){const m=Math.max(0,a.start),_=Math.min(h.count,a.start+a.count);for(let M=m,p=_-1;M<p;M+=c){const f=h.getX(M),x=h.getX(M+1),A=vo(this,t,ua,l,f,x,M);A&&e.push(A)}if(this.isLineLoop){const M=h.getX(_-1),p=h.getX(m),f=vo(this,t,ua,l,M,p,_-1);f&&e.push(f)}}else{const m=Math.max(0,a.start),_=Math.min(d.count,a.start+a.count);for(let M=m,p=_-1;M<p;M+=c){const f=vo(this,t,ua,l,M,M+1,M);f&&e.push(f)}if(this.isLineLoop){const M=vo(this,t,ua,l,_-1,m,_-1);M&&e.push(M)}}}updateMorphTargets(){const e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){const s=e[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}}function vo(i,t,e,n,s,r,a){const o=i.geometry.attributes.position;if(qo.fromBufferAttribute(o,s),Ko.fromBufferAttribute(o,r),e.distanceSqToSegment(qo,Ko,tc,sd)>n)return;tc.applyMatrix4(i.matrixWorld);const c=t.ray.origin.distanceTo(tc);if(!(c<t.near||c>t.far))return{distance:c,point:sd.clone().applyMatrix4(i.matrixWorld),index:a,face:null,faceIndex:null,barycoord:null,object:i}}const rd=new k,ad=new k;class nl extends Ki{constructor(t,e){super(t,e),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){const t=this.geometry;if(t.index===null){const e=t.attributes.position,n=[];for(let s=0,r=e.count;s<r;s+=2)rd.fromBufferAttribute(e,s),ad.fromBufferAttribute(e,s+1),n[s]=s===0?0:n[s-1],n[s+1]=n[s]+rd.distanceTo(ad);t.setAttribute("lineDistance",new sn(n,1))}else jt("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}}class n_ extends Ki{constructor(t,e){super(t,e),this.isLineLoop=!0,this.type="LineLoop"}}class Lp extends In{constructor(t=[],e=Br,n,s,r,a,o,l,c,h){super(t,e,n,s,r,a,o,l,c,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(t){this.image=t}}class i_ extends In{constructor(t,e,n,s,r,a,o,l,c){super(t,e,n,s,r,a,o,l,c),this.isCanvasTexture=!0,this.needsUpdate=!0}}class kr extends In{constructor(t,e,n=Yi,s,r,a,o=Pn,l=Pn,c,h=Ps,u=1){if(h!==Ps&&h!==Ts)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");const d={width:t,height:e,depth:u};super(d,s,r,a,o,l,h,n,c),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(t){return super.copy(t),this.source=new Gh(Object.assign({},t.image)),this.compareFunction=t.compareFunction,this}toJSON(t){const e=super.toJSON(t);return e.compareFunction=this.compareFunction,e}}class Dp extends kr{constructor(t,e=Yi,n=Br,s,r,a=Pn,o=Pn,l,c=Ps){const h={width:t,height:t,depth:1},u=[h,h,h,h,h,h];super(t,t,e,n,s,r,a,o,l,c),this.image=u,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(t){this.image=t}}class Np extends In{constructor(t=null){super(),this.sourceTexture=t,this.isExternalTexture=!0}copy(t){return super.copy(t),this.sourceTexture=t.sourceTexture,this}}class Ha extends Be{constructor(t=1,e=1,n=1,s=1,r=1,a=1){super(),this.type="BoxGeometry",this.parameters={width:t,height:e,depth:n,widthSegments:s,heightSegments:r,depthSegments:a};const o=this;s=Math.floor(s),r=Math.floor(r),a=Math.floor(a);const l=[],c=[],h=[],u=[];let d=0,m=0;_("z","y","x",-1,-1,n,e,t,a,r,0),_("z","y","x",1,-1,n,e,-t,a,r,1),_("x","z","y",1,1,t,n,e,s,a,2),_("x","z","y",1,-1,t,n,-e,s,a,3),_("x","y","z",1,-1,t,e,n,s,r,4),_("x","y","z",-1,-1,t,e,-n,s,r,5),this.setIndex(l),this.setAttribute("position",new sn(c,3)),this.setAttribute("normal",new sn(h,3)),this.setAttribute("uv",new sn(u,2));function _(M,p,f,x,A,S,R,b,g,w,z){const I=S/g,L=R/w,V=S/2,$=R/2,N=b/2,W=g+1,J=w+1;let H=0,ct=0;const Z=new k;for(let tt=0;tt<J;tt++){const st=tt*L-$;for(let pt=0;pt<W;pt++){const ft=pt*I-V;Z[M]=ft*x,Z[p]=st*A,Z[f]=N,c.push(Z.x,Z.y,Z.z),Z[M]=0,Z[p]=0,Z[f]=b>0?1:-1,h.push(Z.x,Z.y,Z.z),u.push(pt/g),u.push(1-tt/w),H+=1}}for(let tt=0;tt<w;tt++)for(let st=0;st<g;st++){const pt=d+st+W*tt,ft=d+st+W*(tt+1),B=d+(st+1)+W*(tt+1),et=d+(st+1)+W*tt;l.push(pt,ft,et),l.push(ft,B,et),ct+=6}o.addGroup(m,ct,z),m+=ct,d+=H}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new Ha(t.width,t.height,t.depth,t.widthSegments,t.heightSegments,t.depthSegments)}}class Ga extends Be{constructor(t=1,e=1,n=1,s=32,r=1,a=!1,o=0,l=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:t,radiusBottom:e,height:n,radialSegments:s,heightSegments:r,openEnded:a,thetaStart:o,thetaLength:l};const c=this;s=Math.floor(s),r=Math.floor(r);const h=[],u=[],d=[],m=[];let _=0;const M=[],p=n/2;let f=0;x(),a===!1&&(t>0&&A(!0),e>0&&A(!1)),this.setIndex(h),this.setAttribute("position",new sn(u,3)),this.setAttribute("normal",new sn(d,3)),this.setAttribute("uv",new sn(m,2));function x(){const S=new k,R=new k;let b=0;const g=(e-t)/n;for(let w=0;w<=r;w++){const z=[],I=w/r,L=I*(e-t)+t;for(let V=0;V<=s;V++){const $=V/s,N=$*l+o,W=Math.sin(N),J=Math.cos(N);R.x=L*W,R.y=-I*n+p,R.z=L*J,u.push(R.x,R.y,R.z),S.set(W,g,J).normalize(),d.push(S.x,S.y,S.z),m.push($,1-I),z.push(_++)}M.push(z)}for(let w=0;w<s;w++)for(let z=0;z<r;z++){const I=M[z][w],L=M[z+1][w],V=M[z+1][w+1],$=M[z][w+1];(t>0||z!==0)&&(h.push(I,L,$),b+=3),(e>0||z!==r-1)&&(h.push(L,V,$),b+=3)}c.addGroup(f,b,0),f+=b}function A(S){const R=_,b=new Xt,g=new k;let w=0;const z=S===!0?t:e,I=S===!0?1:-1;for(let V=1;V<=s;V++)u.push(0,p*I,0),d.push(0,I,0),m.push(.5,.5),_++;const L=_;for(let V=0;V<=s;V++){const N=V/s*l+o,W=Math.cos(N),J=Math.sin(N);g.x=z*J,g.y=p*I,g.z=z*W,u.push(g.x,g.y,g.z),d.push(0,I,0),b.x=W*.5+.5,b.y=J*.5*I+.5,m.push(b.x,b.y),_++}for(let V=0;V<s;V++){const $=R+V,N=L+V;S===!0?h.push(N,N+1,$):h.push(N+1,N,$),w+=3}c.addGroup(f,w,S===!0?1:2),f+=w}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new Ga(t.radiusTop,t.radiusBottom,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}}class Xh extends Ga{constructor(t=1,e=1,n=32,s=1,r=!1,a=0,o=Math.PI*2){super(0,t,e,n,s,r,a,o),this.type="ConeGeometry",this.parameters={radius:t,height:e,radialSegments:n,heightSegments:s,openEnded:r,thetaStart:a,thetaLength:o}}static fromJSON(t){return new Xh(t.radius,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}}class il extends Be{constructor(t=1,e=1,n=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:t,height:e,widthSegments:n,heightSegments:s};const r=t/2,a=e/2,o=Math.floor(n),l=Math.floor(s),c=o+1,h=l+1,u=t/o,d=e/l,m=[],_=[],M=[],p=[];for(let f=0;f<h;f++){const x=f*d-a;for(let A=0;A<c;A++){const S=A*u-r;_.push(S,-x,0),M.push(0,0,1),p.push(A/o),p.push(1-f/l)}}for(let f=0;f<l;f++)for(let x=0;x<o;x++){const A=x+c*f,S=x+c*(f+1),R=x+1+c*(f+1),b=x+1+c*f;m.push(A,S,b),m.push(S,R,b)}this.setIndex(m),this.setAttribute("position",new sn(_,3)),this.setAttribute("normal",new sn(M,3)),this.setAttribute("uv",new sn(p,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new il(t.width,t.height,t.widthSegments,t.heightSegments)}}class Rs extends Be{constructor(t=1,e=32,n=16,s=0,r=Math.PI*2,a=0,o=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:t,widthSegments:e,heightSegments:n,phiStart:s,phiLength:r,thetaStart:a,thetaLength:o},e=Math.max(3,Math.floor(e)),n=Math.max(2,Math.floor(n));const l=Math.min(a+o,Math.PI);let c=0;const h=[],u=new k,d=new k,m=[],_=[],M=[],p=[];for(let f=0;f<=n;f++){const x=[],A=f/n,S=a+A*o,R=t*Math.cos(S),b=Math.sqrt(t*t-R*R);let g=0;f===0&&a===0?g=.5/e:f===n&&l===Math.PI&&(g=-.5/e);for(let w=0;w<=e;w++){const z=w/e,I=s+z*r;u.x=-b*Math.cos(I),u.y=R,u.z=b*Math.sin(I),_.push(u.x,u.y,u.z),d.copy(u).normalize(),M.push(d.x,d.y,d.z),p.push(z+g,1-A),x.push(c++)}h.push(x)}for(let f=0;f<n;f++)for(let x=0;x<e;x++){const A=h[f][x+1],S=h[f][x],R=h[f+1][x],b=h[f+1][x+1];(f!==0||a>0)&&m.push(A,S,b),(f!==n-1||l<Math.PI)&&m.push(S,R,b)}this.setIndex(m),this.setAttribute("position",new sn(_,3)),this.setAttribute("normal",new sn(M,3)),this.setAttribute("uv",new sn(p,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new Rs(t.radius,t.widthSegments,t.heightSegments,t.phiStart,t.phiLength,t.thetaStart,t.thetaLength)}}function Hr(i){const t={};for(const e in i){t[e]={};for(const n in i[e]){const s=i[e][n];if(od(s))s.isRenderTargetTexture?(jt("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),t[e][n]=null):t[e][n]=s.clone();else if(Array.isArray(s))if(od(s[0])){const r=[];for(let a=0,o=s.length;a<o;a++)r[a]=s[a].clone();t[e][n]=r}else t[e][n]=s.slice();else t[e][n]=s}}return t}function Gn(i){const t={};for(let e=0;e<i.length;e++){const n=Hr(i[e]);for(const s in n)t[s]=n[s]}return t}function od(i){return i&&(i.isColor||i.isMatrix3||i.isMatrix4||i.isVector2||i.isVector3||i.isVector4||i.isTexture||i.isQuaternion)}function s_(i){const t=[];for(let e=0;e<i.length;e++)t.push(i[e].clone());return t}function Ip(i){const t=i.getRenderTarget();return t===null?i.outputColorSpace:t.isXRRenderTarget===!0?t.texture.colorSpace:xe.workingColorSpace}const r_={clone:Hr,merge:Gn};var a_=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,o_=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`;class Zs extends Qs{constructor(t){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=a_,this.fragmentShader=o_,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,t!==void 0&&this.setValues(t)}copy(t){return super.copy(t),this.fragmentShader=t.fragmentShader,this.vertexShader=t.vertexShader,this.uniforms=Hr(t.uniforms),this.uniformsGroups=s_(t.uniformsGroups),this.defines=Object.assign({},t.defines),this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.fog=t.fog,this.lights=t.lights,this.clipping=t.clipping,this.extensions=Object.assign({},t.extensions),this.glslVersion=t.glslVersion,this.defaultAttributeValues=Object.assign({},t.defaultAttributeValues),this.index0AttributeName=t.index0AttributeName,this.uniformsNeedUpdate=t.uniformsNeedUpdate,this}toJSON(t){const e=super.toJSON(t);e.glslVersion=this.glslVersion,e.uniforms={};for(const s in this.uniforms){const a=this.uniforms[s].value;a&&a.isTexture?e.uniforms[s]={type:"t",value:a.toJSON(t).uuid}:a&&a.isColor?e.uniforms[s]={type:"c",value:a.getHex()}:a&&a.isVector2?e.uniforms[s]={type:"v2",value:a.toArray()}:a&&a.isVector3?e.uniforms[s]={type:"v3",value:a.toArray()}:a&&a.isVector4?e.uniforms[s]={type:"v4",value:a.toArray()}:a&&a.isMatrix3?e.uniforms[s]={type:"m3",value:a.toArray()}:a&&a.isMatrix4?e.uniforms[s]={type:"m4",value:a.toArray()}:e.uniforms[s]={value:a}}Object.keys(this.defines).length>0&&(e.defines=this.defines),e.vertexShader=this.vertexShader,e.fragmentShader=this.fragmentShader,e.lights=this.lights,e.clipping=this.clipping;const n={};for(const s in this.extensions)this.extensions[s]===!0&&(n[s]=!0);return Object.keys(n).length>0&&(e.extensions=n),e}fromJSON(t,e){if(super.fromJSON(t,e),t.uniforms!==void 0)for(const n in t.uniforms){const s=t.uniforms[n];switch(this.uniforms[n]={},s.type){case"t":this.uniforms[n].value=e[s.value]||null;break;case"c":this.uniforms[n].value=new ce().setHex(s.value);break;case"v2":this.uniforms[n].value=new Xt().fromArray(s.value);break;case"v3":this.uniforms[n].value=new k().fromArray(s.value);break;case"v4":this.uniforms[n].value=new nn().fromArray(s.value);break;case"m3":this.uniforms[n].value=new re().fromArray(s.value);break;case"m4":this.uniforms[n].value=new De().fromArray(s.value);break;default:this.uniforms[n].value=s.value}}if(t.defines!==void 0&&(this.defines=t.defines),t.vertexShader!==void 0&&(this.vertexShader=t.vertexShader),t.fragmentShader!==void 0&&(this.fragmentShader=t.fragmentShader),t.glslVersion!==void 0&&(this.glslVersion=t.glslVersion),t.extensions!==void 0)for(const n in t.extensions)this.extensions[n]=t.extensions[n];return t.lights!==void 0&&(this.lights=t.lights),t.clipping!==void 0&&(this.clipping=t.clipping),this}}class l_ extends Zs{constructor(t){super(t),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}}class ba extends Qs{constructor(t){super(),this.isMeshStandardMaterial=!0,this.type="MeshStandardMaterial",this.defines={STANDARD:""},this.color=new ce(16777215),this.roughness=1,this.metalness=0,this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new ce(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=ch,this.normalScale=new Xt(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.roughnessMap=null,this.metalnessMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ds,this.envMapIntensity=1,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.defines={STANDARD:""},this.color.copy(t.color),this.roughness=t.roughness,this.metalness=t.metalness,this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.emissive.copy(t.emissive),this.emissiveMap=t.emissiveMap,this.emissiveIntensity=t.emissiveIntensity,this.bumpMap=t.bumpMap,this.bumpScale=t.bumpScale,this.normalMap=t.normalMap,this.normalMapType=t.normalMapType,this.normalScale.copy(t.normalScale),this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.roughnessMap=t.roughnessMap,this.metalnessMap=t.metalnessMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.envMapIntensity=t.envMapIntensity,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.flatShading=t.flatShading,this.fog=t.fog,this}}class c_ extends Qs{constructor(t){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=v0,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(t)}copy(t){return super.copy(t),this.depthPacking=t.depthPacking,this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this}}class h_ extends Qs{constructor(t){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(t)}copy(t){return super.copy(t),this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this}}class Up extends mi{constructor(t){super(),this.isLineDashedMaterial=!0,this.type="LineDashedMaterial",this.scale=1,this.dashSize=3,this.gapSize=1,this.setValues(t)}copy(t){return super.copy(t),this.scale=t.scale,this.dashSize=t.dashSize,this.gapSize=t.gapSize,this}}class Fp extends Sn{static registerNode(t){this.prototype._lightNode=t}constructor(t,e=1){super(),this.isLight=!0,this.type="Light",this.color=new ce(t),this.intensity=e}copy(t,e){return super.copy(t,e),this.color.copy(t.color),this.intensity=t.intensity,this}toJSON(t){const e=super.toJSON(t);return e.object.color=this.color.getHex(),e.object.intensity=this.intensity,e}}const ec=new De,ld=new k,cd=new k;class u_{constructor(t){this.camera=t,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new Xt(512,512),this.mapType=ei,this.map=null,this.mapPass=null,this.matrix=new De,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new Na,this._frameExtents=new Xt(1,1),this._viewportCount=1,this._viewports=[new nn(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(t){const e=this.camera;ld.setFromMatrixPosition(t.matrixWorld),e.position.copy(ld),cd.setFromMatrixPosition(t.target.matrixWorld),e.lookAt(cd),e.updateMatrixWorld(),this._updateMatrix(e,this.matrix,this._frustum)}_updateMatrix(t,e,n,s){ec.multiplyMatrices(t.projectionMatrix,t.matrixWorldInverse),n.setFromProjectionMatrix(ec,t.coordinateSystem,t.reversedDepth);const r=this._frameExtents,a=s?s.z/r.x:1,o=s?s.w/r.y:1,l=s?s.x/r.x:0,c=s?s.y/r.y:0;t.coordinateSystem===Da||t.reversedDepth?e.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,1,0,0,0,0,1):e.set(.5*a,0,0,.5*a+l,0,.5*o,0,.5*o+c,0,0,.5,.5,0,0,0,1),e.multiply(ec)}getViewport(t){return this._viewports[t]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(t){return this.camera=t.camera.clone(),this.intensity=t.intensity,this.bias=t.bias,this.radius=t.radius,this.autoUpdate=t.autoUpdate,this.needsUpdate=t.needsUpdate,this.normalBias=t.normalBias,this.blurSamples=t.blurSamples,this.mapSize.copy(t.mapSize),this.mapType=t.mapType,this.biasNode=t.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){const t={};return t.intensity=this.intensity,t.bias=this.bias,t.normalBias=this.normalBias,t.radius=this.radius,t.blurSamples=this.blurSamples,t.mapSize=this.mapSize.toArray(),t.mapType=this.mapType,t.camera=this.camera.toJSON(!1).object,delete t.camera.matrix,t}}const xo=new k,So=new Ls,Ui=new k;class Op extends Sn{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new De,this.projectionMatrix=new De,this.projectionMatrixInverse=new De,this.coordinateSystem=Ai,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(t,e){return super.copy(t,e),this.matrixWorldInverse.copy(t.matrixWorldInverse),this.projectionMatrix.copy(t.projectionMatrix),this.projectionMatrixInverse.copy(t.projectionMatrixInverse),this.coordinateSystem=t.coordinateSystem,this}getWorldDirection(t){return super.getWorldDirection(t).negate()}updateMatrixWorld(t){super.updateMatrixWorld(t),this.matrixWorld.decompose(xo,So,Ui),Ui.x===1&&Ui.y===1&&Ui.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(xo,So,Ui.set(1,1,1)).invert()}updateWorldMatrix(t,e,n=!1){super.updateWorldMatrix(t,e,n),this.matrixWorld.decompose(xo,So,Ui),Ui.x===1&&Ui.y===1&&Ui.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(xo,So,Ui.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}}const Ms=new k,hd=new Xt,ud=new Xt;class Xn extends Op{constructor(t=50,e=1,n=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=t,this.zoom=1,this.near=n,this.far=s,this.focus=10,this.aspect=e,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.fov=t.fov,this.zoom=t.zoom,this.near=t.near,this.far=t.far,this.focus=t.focus,this.aspect=t.aspect,this.view=t.view===null?null:Object.assign({},t.view),this.filmGauge=t.filmGauge,this.filmOffset=t.filmOffset,this}setFocalLength(t){const e=.5*this.getFilmHeight()/t;this.fov=hh*2*Math.atan(e),this.updateProjectionMatrix()}getFocalLength(){const t=Math.tan(ya*.5*this.fov);return .5*this.getFilmHeight()/t}getEffectiveFOV(){return hh*2*Math.atan(Math.tan(ya*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(t,e,n){Ms.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),e.set(Ms.x,Ms.y).multiplyScalar(-t/Ms.z),Ms.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),n.set(Ms.x,Ms.y).multiplyScalar(-t/Ms.z)}getViewSize(t,e){return this.getViewBounds(t,hd,ud),e.subVectors(ud,hd)}setViewOffset(t,e,n,s,r,a){this.aspect=t/e,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const t=this.near;let e=t*Math.tan(ya*.5*this.fov)/this.zoom,n=2*e,s=this.aspect*n,r=-.5*s;const a=this.view;if(this.view!==null&&this.view.enabled){const l=a.fullWidth,c=a.fullHeight;r+=a.offsetX*s/l,e-=a.offsetY*n/c,s*=a.width/l,n*=a.height/c}const o=this.filmOffset;o!==0&&(r+=t*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,e,e-n,t,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){const e=super.toJSON(t);return e.object.fov=this.fov,e.object.zoom=this.zoom,e.object.near=this.near,e.object.far=this.far,e.object.focus=this.focus,e.object.aspect=this.aspect,this.view!==null&&(e.object.view=Object.assign({},this.view)),e.object.filmGauge=this.filmGauge,e.object.filmOffset=this.filmOffset,e}}class Bp extends Op{constructor(t=-1,e=1,n=1,s=-1,r=.1,a=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=t,this.right=e,this.top=n,this.bottom=s,this.near=r,this.far=a,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.left=t.left,this.right=t.right,this.top=t.top,this.bottom=t.bottom,this.near=t.near,this.far=t.far,this.zoom=t.zoom,this.view=t.view===null?null:Object.assign({},t.view),this}setViewOffset(t,e,n,s,r,a){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const t=(this.right-this.left)/(2*this.zoom),e=(this.top-this.bottom)/(2*this.zoom),n=(this.right+this.left)/2,s=(this.top+this.bottom)/2;let r=n-t,a=n+t,o=s+e,l=s-e;if(this.view!==null&&this.view.enabled){const c=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=c*this.view.offsetX,a=r+c*this.view.width,o-=h*this.view.offsetY,l=o-h*this.view.height}this.projectionMatrix.makeOrthographic(r,a,o,l,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){const e=super.toJSON(t);return e.object.zoom=this.zoom,e.object.left=this.left,e.object.right=this.right,e.object.top=this.top,e.object.bottom=this.bottom,e.object.near=this.near,e.object.far=this.far,this.view!==null&&(e.object.view=Object.assign({},this.view)),e}}class d_ extends u_{constructor(){super(new Bp(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}}class f_ extends Fp{constructor(t,e){super(t,e),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(Sn.DEFAULT_UP),this.updateMatrix(),this.target=new Sn,this.shadow=new d_}dispose(){super.dispose(),this.shadow.dispose()}copy(t){return super.copy(t),this.target=t.target.clone(),this.shadow=t.shadow.clone(),this}toJSON(t){const e=super.toJSON(t);return e.object.shadow=this.shadow.toJSON(),e.object.target=this.target.uuid,e}}class p_ extends Fp{constructor(t,e){super(t,e),this.isAmbientLight=!0,this.type="AmbientLight"}}const dd=new De,fd=new De,Gs=new De;class zp{constructor(){this.type="StereoCamera",this.aspect=1,this.eyeSep=.064,this.cameraL=new Xn,this.cameraL.layers.enable(1),this.cameraL.matrixAutoUpdate=!1,this.cameraR=new Xn,this.cameraR.layers.enable(2),this.cameraR.matrixAutoUpdate=!1,this._cache={focus:null,fov:null,aspect:null,near:null,far:null,zoom:null,eyeSep:null}}update(t){const e=this._cache;if(e.focus!==t.focus||e.fov!==t.fov||e.aspect!==t.aspect*this.aspect||e.near!==t.near||e.far!==t.far||e.zoom!==t.zoom||e.eyeSep!==this.eyeSep){e.focus=t.focus,e.fov=t.fov,e.aspect=t.aspect*this.aspect,e.near=t.near,e.far=t.far,e.zoom=t.zoom,e.eyeSep=this.eyeSep,Gs.copy(t.projectionMatrix);const s=e.eyeSep/2,r=s*e.near/e.focus,a=e.near*Math.tan(ya*e.fov*.5)/e.zoom;let o,l;fd.elements[12]=-s,dd.elements[12]=s,o=-a*e.aspect+r,l=a*e.aspect+r,Gs.elements[0]=2*e.near/(l-o),Gs.elements[8]=(l+o)/(l-o),this.cameraL.projectionMatrix.copy(Gs),o=-a*e.aspect-r,l=a*e.aspect-r,Gs.elements[0]=2*e.near/(l-o),Gs.elements[8]=(l+o)/(l-o),this.cameraR.projectionMatrix.copy(Gs)}this.cameraL.matrix.copy(t.matrixWorld).multiply(fd),this.cameraL.matrixWorldNeedsUpdate=!0,this.cameraR.matrix.copy(t.matrixWorld).multiply(dd),this.cameraR.matrixWorldNeedsUpdate=!0}}const Tr=-90,Ar=1;class uh extends Sn{constructor(t,e,n){super(),this.type="CubeCamera",this.renderTarget=n,this.coordinateSystem=null,this.activeMipmapLevel=0;const s=new Xn(Tr,Ar,t,e);s.layers=this.layers,this.add(s);const r=new Xn(Tr,Ar,t,e);r.layers=this.layers,this.add(r);const a=new Xn(Tr,Ar,t,e);a.layers=this.layers,this.add(a);const o=new Xn(Tr,Ar,t,e);o.layers=this.layers,this.add(o);const l=new Xn(Tr,Ar,t,e);l.layers=this.layers,this.add(l);const c=new Xn(Tr,Ar,t,e);c.layers=this.layers,this.add(c)}updateCoordinateSystem(){const t=this.coordinateSystem,e=this.children.concat(),[n,s,r,a,o,l]=e;for(const c of e)this.remove(c);if(t===Ai)n.up.set(0,1,0),n.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),a.up.set(0,0,1),a.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(t===Da)n.up.set(0,-1,0),n.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),a.up.set(0,0,-1),a.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+t);for(const c of e)this.add(c),c.updateMatrixWorld()}update(t,e){this.parent===null&&this.updateMatrixWorld();const{renderTarget:n,activeMipmapLevel:s}=this;this.coordinateSystem!==t.coordinateSystem&&(this.coordinateSystem=t.coordinateSystem,this.updateCoordinateSystem());const[r,a,o,l,c,h]=this.children,u=t.getRenderTarget(),d=t.getActiveCubeFace(),m=t.getActiveMipmapLevel(),_=t.xr.enabled;t.xr.enabled=!1;const M=n.texture.mipmapsAutoUpdate;n.texture.mipmapsAutoUpdate=!1;let p=!1;t.isWebGLRenderer===!0?p=t.state.buffers.depth.getReversed():p=t.reversedDepthBuffer,t.setRenderTarget(n,0,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,r),t.setRenderTarget(n,1,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,a),t.setRenderTarget(n,2,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,o),t.setRenderTarget(n,3,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,l),t.setRenderTarget(n,4,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,c),n.texture.mipmapsAutoUpdate=M,t.setRenderTarget(n,5,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,h),t.setRenderTarget(u,d,m),t.xr.enabled=_,n.texture.needsPMREMUpdate=!0}}class m_ extends Xn{constructor(t=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=t,this.perCameraFrustumCulled=!1}}const pd=new De;class kp{constructor(t,e,n=0,s=1/0){this.ray=new el(t,e),this.near=n,this.far=s,this.camera=null,this.layers=new Vh,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(t,e){this.ray.set(t,e)}setFromCamera(t,e){e.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(t.x,t.y,.5).unproject(e).sub(this.ray.origin).normalize(),this.camera=e):e.isOrthographicCamera?(this.ray.origin.set(t.x,t.y,e.projectionMatrix.elements[14]).unproject(e),this.ray.direction.set(0,0,-1).transformDirection(e.matrixWorld),this.camera=e):Se("Raycaster: Unsupported camera type: "+e.type)}setFromXRController(t){return pd.identity().extractRotation(t.matrixWorld),this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4(pd),this}intersectObject(t,e=!0,n=[]){return dh(t,this,n,e),n.sort(md),n}intersectObjects(t,e=!0,n=[]){for(let s=0,r=t.length;s<r;s++)dh(t[s],this,n,e);return n.sort(md),n}}function md(i,t){return i.distance-t.distance}function dh(i,t,e,n){let s=!0;if(i.layers.test(t.layers)&&i.raycast(t,e)===!1&&(s=!1),s===!0&&n===!0){const r=i.children;for(let a=0,o=r.length;a<o;a++)dh(r[a],t,e,!0)}}class gd{constructor(t=1,e=0,n=0){this.radius=t,this.phi=e,this.theta=n}set(t,e,n){return this.radius=t,this.phi=e,this.theta=n,this}copy(t){return this.radius=t.radius,this.phi=t.phi,this.theta=t.theta,this}makeSafe(){return this.phi=pe(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(t){return this.setFromCartesianCoords(t.x,t.y,t.z)}setFromCartesianCoords(t,e,n){return this.radius=Math.sqrt(t*t+e*e+n*n),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(t,n),this.phi=Math.acos(pe(e/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}}const _d=new k;let Mo,nc;class g_ extends Sn{constructor(t=new k(0,0,1),e=new k(0,0,0),n=1,s=16776960,r=n*.2,a=r*.2){super(),this.type="ArrowHelper",Mo===void 0&&(Mo=new Be,Mo.setAttribute("position",new sn([0,0,0,0,1,0],3)),nc=new Xh(.5,1,5,1),nc.translate(0,-.5,0)),this.position.copy(e),this.line=new Ki(Mo,new mi({color:s,toneMapped:!1})),this.line.matrixAutoUpdate=!1,this.add(this.line),this.cone=new fn(nc,new As({color:s,toneMapped:!1})),this.cone.matrixAutoUpdate=!1,this.add(this.cone),this.setDirection(t),this.setLength(n,r,a)}setDirection(t){if(t.y>.99999)this.quaternion.set(0,0,0,1);else if(t.y<-.99999)this.quaternion.set(1,0,0,0);else{_d.set(t.z,0,-t.x).normalize();const e=Math.acos(t.y);this.quaternion.setFromAxisAngle(_d,e)}}setLength(t,e=t*.2,n=e*.2){this.line.scale.set(1,Math.max(1e-4,t-e),1),this.line.updateMatrix(),this.cone.scale.set(n,e,n),this.cone.position.y=t,this.cone.updateMatrix()}setColor(t){this.line.material.color.set(t),this.cone.material.color.set(t)}copy(t){return super.copy(t,!1),this.line.copy(t.line),this.cone.copy(t.cone),this}dispose(){super.dispose(),this.line.geometry.dispose(),this.line.material.dispose(),this.cone.geometry.dispose(),this.cone.material.dispose()}}class Hp extends nl{constructor(t=1){const e=[0,0,0,t,0,0,0,0,0,0,t,0,0,0,0,0,0,t],n=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new Be;s.setAttribute("position",new sn(e,3)),s.setAttribute("color",new sn(n,3));const r=new mi({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(t,e,n){const s=new ce,r=this.geometry.attributes.color.array;return s.set(t),s.toArray(r,0),s.toArray(r,3),s.set(e),s.toArray(r,6),s.toArray(r,9),s.set(n),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}}let __=class extends Is{constructor(t,e=null){super(),this.object=t,this.domElement=e,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(t){this.domElement!==null&&this.disconnect(),this.domElement=t}disconnect(){}dispose(){}update(){}};function vd(i,t,e,n){const s=v_(n);switch(e){case fp:return i*t;case mp:return i*t/s.components*s.byteLength;case zh:return i*t/s.components*s.byteLength;case Ks:return i*t*2/s.components*s.byteLength;case kh:return i*t*2/s.components*s.byteLength;case pp:return i*t*3/s.components*s.byteLength;case Gi:return i*t*4/s.components*s.byteLength;case Hh:return i*t*4/s.components*s.byteLength;case Io:case Uo:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*8;case Fo:case Oo:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Ic:case Fc:return Math.max(i,16)*Math.max(t,8)/4;case Nc:case Uc:return Math.max(i,8)*Math.max(t,8)/2;case Oc:case Bc:case kc:case Hc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*8;case zc:case Ho:case Gc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Vc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Wc:return Math.floor((i+4)/5)*Math.floor((t+3)/4)*16;case Xc:return Math.floor((i+4)/5)*Math.floor((t+4)/5)*16;case $c:return Math.floor((i+5)/6)*Math.floor((t+4)/5)*16;case Yc:return Math.floor((i+5)/6)*Math.floor((t+5)/6)*16;case qc:return Math.floor((i+7)/8)*Math.floor((t+4)/5)*16;case Kc:return Math.floor((i+7)/8)*Math.floor((t+5)/6)*16;case Zc:return Math.floor((i+7)/8)*Math.floor((t+7)/8)*16;case Jc:return Math.floor((i+9)/10)*Math.floor((t+4)/5)*16;case jc:return Math.floor((i+9)/10)*Math.floor((t+5)/6)*16;case Qc:return Math.floor((i+9)/10)*Math.floor((t+7)/8)*16;case th:return Math.floor((i+9)/10)*Math.floor((t+9)/10)*16;case eh:return Math.floor((i+11)/12)*Math.floor((t+9)/10)*16;case nh:return Math.floor((i+11)/12)*Math.floor((t+11)/12)*16;case ih:case sh:case rh:return Math.ceil(i/4)*Math.ceil(t/4)*16;case ah:case oh:return Math.ceil(i/4)*Math.ceil(t/4)*8;case Go:case lh:return Math.ceil(i/4)*Math.ceil(t/4)*16}throw new Error(`Unable to determine texture byte length for ${e} format.`)}function v_(i){switch(i){case ei:case cp:return{byteLength:1,components:1};case La:case hp:case qi:return{byteLength:2,components:1};case Oh:case Bh:return{byteLength:2,components:4};case Yi:case Fh:case Hi:return{byteLength:4,components:1};case up:case dp:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${i}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:Uh}}));typeof window<"u"&&(window.__THREE__?jt("WARNING: Multiple instances of Three.js being imported."):window.__THREE__=Uh);function Gp(){let i=null,t=!1,e=null,n=null;function s(r,a){n=i.requestAnimationFrame(s),e(r,a)}return{start:function(){t!==!0&&e!==null&&i!==null&&(n=i.requestAnimationFrame(s),t=!0)},stop:function(){i!==null&&i.cancelAnimationFrame(n),t=!1},setAnimationLoop:function(r){e=r},setContext:function(r){i=r}}}function x_(i){const t=new WeakMap;function e(o,l){const c=o.array,h=o.usage,u=c.byteLength,d=i.createBuffer();i.bindBuffer(l,d),i.bufferData(l,c,h),o.onUploadCallback();let m;if(c instanceof Float32Array)m=i.FLOAT;else if(typeof Float16Array<"u"&&c instanceof Float16Array)m=i.HALF_FLOAT;else if(c instanceof Uint16Array)o.isFloat16BufferAttribute?m=i.HALF_FLOAT:m=i.UNSIGNED_SHORT;else if(c instanceof Int16Array)m=i.SHORT;else if(c instanceof Uint32Array)m=i.UNSIGNED_INT;else if(c instanceof Int32Array)m=i.INT;else if(c instanceof Int8Array)m=i.BYTE;else if(c instanceof Uint8Array)m=i.UNSIGNED_BYTE;else if(c instanceof Uint8ClampedArray)m=i.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+c);return{buffer:d,type:m,bytesPerElement:c.BYTES_PER_ELEMENT,version:o.version,size:u}}function n(o,l,c){const h=l.array,u=l.updateRanges;if(i.bindBuffer(c,o),u.length===0)i.bufferSubData(c,0,h);else{u.sort((m,_)=>m.start-_.start);let d=0;for(let m=1;m<u.length;m++){const _=u[d],M=u[m];M.start<=_.start+_.count+1?_.count=Math.max(_.count,M.start+M.count-_.start):(++d,u[d]=M)}u.length=d+1;for(let m=0,_=u.length;m<_;m++){const M=u[m];i.bufferSubData(c,M.start*h.BYTES_PER_ELEMENT,h,M.start,M.count)}l.clearUpdateRanges()}l.onUploadCallback()}function s(o){return o.isInterleavedBufferAttribute&&(o=o.data),t.get(o)}function r(o){o.isInterleavedBufferAttribute&&(o=o.data);const l=t.get(o);l&&(i.deleteBuffer(l.buffer),t.delete(o))}function a(o,l){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){const h=t.get(o);(!h||h.version<o.version)&&t.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}const c=t.get(o);if(c===void 0)t.set(o,e(o,l));else if(c.version<o.version){if(c.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");n(c.buffer,o,l),c.version=o.version}}return{get:s,remove:r,update:a}}var S_=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,M_=`#ifdef USE_ALPHAHASH
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
#endif`,y_=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,b_=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,E_=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,w_=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,T_=`#ifdef USE_AOMAP
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
#endif`,A_=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,R_=`#ifdef USE_BATCHING
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
#endif`,C_=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,P_=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,L_=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,D_=`float G_BlinnPhong_Implicit( ) {
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
} // validated`,N_=`#ifdef USE_IRIDESCENCE
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
#endif`,I_=`#ifdef USE_BUMPMAP
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
#endif`,U_=`#if NUM_CLIPPING_PLANES > 0
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
#endif`,F_=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,O_=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,B_=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,z_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,k_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,H_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,G_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
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
#endif`,V_=`#define PI 3.141592653589793
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
} // validated`,W_=`vec3 transformedNormal = objectNormal;
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
#endif`,X_=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,$_=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,Y_=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,q_=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,K_="gl_FragColor = linearToOutputTexel( gl_FragColor );",Z_=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,J_=`#ifdef USE_ENVMAP
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
#endif`,j_=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,Q_=`#ifdef USE_ENVMAP
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
#endif`,tv=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,ev=`#ifdef USE_ENVMAP
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
#endif`,nv=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,iv=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,sv=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,rv=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,av=`#ifdef USE_GRADIENTMAP
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
}`,ov=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,lv=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,cv=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,hv=`uniform bool receiveShadow;
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
#include <lightprobes_pars_fragment>`,uv=`#ifdef USE_ENVMAP
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
#endif`,dv=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,fv=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,pv=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,mv=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,gv=`PhysicalMaterial material;
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
#endif`,_v=`uniform sampler2D dfgLUT;
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
}`,vv=`
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
#endif`,xv=`#if defined( RE_IndirectDiffuse )
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
#endif`,Sv=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,Mv=`#if NUM_LIGHT_PROBE_GRIDS > 0
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
#endif`,yv=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,bv=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Ev=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,wv=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,Tv=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,Av=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,Rv=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
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
#endif`,Cv=`#if defined( USE_POINTS_UV )
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
#endif`,Pv=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,Lv=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,Dv=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,Nv=`#if defined( USE_MORPHCOLORS )
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
#endif`,Iv=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Uv=`#ifdef USE_MORPHTARGETS
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
#endif`,Fv=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Ov=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
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
vec3 nonPerturbedNormal = normal;`,Bv=`#ifdef USE_NORMALMAP_OBJECTSPACE
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
#endif`,zv=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,kv=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,Hv=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,Gv=`#ifdef USE_NORMALMAP
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
#endif`,Vv=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,Wv=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,Xv=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,$v=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,Yv=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,qv=`vec3 packNormalToRGB( const in vec3 normal ) {
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
}`,Kv=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,Zv=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,Jv=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,jv=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,Qv=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,tx=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,ex=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,nx=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,ix=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
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
#endif`,sx=`float getShadowMask() {
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
}`,rx=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,ax=`#ifdef USE_SKINNING
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
#endif`,ox=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,lx=`#ifdef USE_SKINNING
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
#endif`,cx=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,hx=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,ux=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,dx=`#ifndef saturate
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
vec3 CustomToneMapping( vec3 color ) { return color; }`,fx=`#ifdef USE_TRANSMISSION
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
#endif`,px=`#ifdef USE_TRANSMISSION
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
#endif`,mx=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,gx=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,_x=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,vx=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`;const xx=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,Sx=`uniform sampler2D t2D;
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
}`,Mx=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,yx=`uniform float backgroundBlurriness;
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
}`,bx=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Ex=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,wx=`#include <common>
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
}`,Tx=`#if DEPTH_PACKING == 3200
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
}`,Ax=`#define DISTANCE
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
}`,Rx=`#define DISTANCE
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
}`,Cx=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,Px=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Lx=`uniform float scale;
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
}`,Dx=`uniform vec3 diffuse;
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
}`,Nx=`#include <common>
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
}`,Ix=`uniform vec3 diffuse;
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
}`,Ux=`#define LAMBERT
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
}`,Fx=`#define LAMBERT
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
}`,Ox=`#define MATCAP
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
}`,Bx=`#define MATCAP
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
}`,zx=`#define NORMAL
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
}`,kx=`#define NORMAL
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
}`,Hx=`#define PHONG
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
}`,Gx=`#define PHONG
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
}`,Vx=`#define STANDARD
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
}`,Wx=`#define STANDARD
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
}`,Xx=`#define TOON
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
}`,$x=`#define TOON
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
}`,Yx=`uniform float size;
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
}`,qx=`uniform vec3 diffuse;
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
}`,Kx=`#include <common>
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
}`,Zx=`uniform vec3 color;
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
}`,Jx=`uniform float rotation;
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
}`,jx=`uniform vec3 diffuse;
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
}`,le={alphahash_fragment:S_,alphahash_pars_fragment:M_,alphamap_fragment:y_,alphamap_pars_fragment:b_,alphatest_fragment:E_,alphatest_pars_fragment:w_,aomap_fragment:T_,aomap_pars_fragment:A_,batching_pars_vertex:R_,batching_vertex:C_,begin_vertex:P_,beginnormal_vertex:L_,bsdfs:D_,iridescence_fragment:N_,bumpmap_pars_fragment:I_,clipping_planes_fragment:U_,clipping_planes_pars_fragment:F_,clipping_planes_pars_vertex:O_,clipping_planes_vertex:B_,color_fragment:z_,color_pars_fragment:k_,color_pars_vertex:H_,color_vertex:G_,common:V_,defaultnormal_vertex:W_,displacementmap_pars_vertex:X_,displacementmap_vertex:$_,emissivemap_fragment:Y_,emissivemap_pars_fragment:q_,colorspace_fragment:K_,colorspace_pars_fragment:Z_,envmap_fragment:J_,envmap_common_pars_fragment:j_,envmap_pars_fragment:Q_,envmap_pars_vertex:tv,envmap_physical_pars_fragment:uv,envmap_vertex:ev,fog_vertex:nv,fog_pars_vertex:iv,fog_fragment:sv,fog_pars_fragment:rv,gradientmap_pars_fragment:av,lightmap_pars_fragment:ov,lights_lambert_fragment:lv,lights_lambert_pars_fragment:cv,lights_pars_begin:hv,lights_toon_fragment:dv,lights_toon_pars_fragment:fv,lights_phong_fragment:pv,lights_phong_pars_fragment:mv,lights_physical_fragment:gv,lights_physical_pars_fragment:_v,lights_fragment_begin:vv,lights_fragment_maps:xv,lights_fragment_end:Sv,lightprobes_pars_fragment:Mv,logdepthbuf_fragment:yv,logdepthbuf_pars_fragment:bv,logdepthbuf_pars_vertex:Ev,logdepthbuf_vertex:wv,map_fragment:Tv,map_pars_fragment:Av,map_particle_fragment:Rv,map_particle_pars_fragment:Cv,metalnessmap_fragment:Pv,metalnessmap_pars_fragment:Lv,morphinstance_vertex:Dv,morphcolor_vertex:Nv,morphnormal_vertex:Iv,morphtarget_pars_vertex:Uv,morphtarget_vertex:Fv,normal_fragment_begin:Ov,normal_fragment_maps:Bv,normal_pars_fragment:zv,normal_pars_vertex:kv,normal_vertex:Hv,normalmap_pars_fragment:Gv,clearcoat_normal_fragment_begin:Vv,clearcoat_normal_fragment_maps:Wv,clearcoat_pars_fragment:Xv,iridescence_pars_fragment:$v,opaque_fragment:Yv,packing:qv,premultiplied_alpha_fragment:Kv,project_vertex:Zv,dithering_fragment:Jv,dithering_pars_fragment:jv,roughnessmap_fragment:Qv,roughnessmap_pars_fragment:tx,shadowmap_pars_fragment:ex,shadowmap_pars_vertex:nx,shadowmap_vertex:ix,shadowmask_pars_fragment:sx,skinbase_vertex:rx,skinning_pars_vertex:ax,skinning_vertex:ox,skinnormal_vertex:lx,specularmap_fragment:cx,specularmap_pars_fragment:hx,tonemapping_fragment:ux,tonemapping_pars_fragment:dx,transmission_fragment:fx,transmission_pars_fragment:px,uv_pars_fragment:mx,uv_pars_vertex:gx,uv_vertex:_x,worldpos_vertex:vx,background_vert:xx,background_frag:Sx,backgroundCube_vert:Mx,backgroundCube_frag:yx,cube_vert:bx,cube_frag:Ex,depth_vert:wx,depth_frag:Tx,distance_vert:Ax,distance_frag:Rx,equirect_vert:Cx,equirect_frag:Px,linedashed_vert:Lx,linedashed_frag:Dx,meshbasic_vert:Nx,meshbasic_frag:Ix,meshlambert_vert:Ux,meshlambert_frag:Fx,meshmatcap_vert:Ox,meshmatcap_frag:Bx,meshnormal_vert:zx,meshnormal_frag:kx,meshphong_vert:Hx,meshphong_frag:Gx,meshphysical_vert:Vx,meshphysical_frag:Wx,meshtoon_vert:Xx,meshtoon_frag:$x,points_vert:Yx,points_frag:qx,shadow_vert:Kx,shadow_frag:Zx,sprite_vert:Jx,sprite_frag:jx},Dt={common:{diffuse:{value:new ce(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new re},alphaMap:{value:null},alphaMapTransform:{value:new re},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new re}},envmap:{envMap:{value:null},envMapRotation:{value:new re},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new re}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new re}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new re},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new re},normalScale:{value:new Xt(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new re},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new re}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new re}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new re}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new ce(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new ce(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new re},alphaTest:{value:0},uvTransform:{value:new re}},sprite:{diffuse:{value:new ce(16777215)},opacity:{value:1},center:{value:new Xt(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new re},alphaMap:{value:null},alphaMapTransform:{value:new re},alphaTest:{value:0}}},ki={basic:{uniforms:Gn([Dt.common,Dt.specularmap,Dt.envmap,Dt.aomap,Dt.lightmap,Dt.fog]),vertexShader:le.meshbasic_vert,fragmentShader:le.meshbasic_frag},lambert:{uniforms:Gn([Dt.common,Dt.specularmap,Dt.envmap,Dt.aomap,Dt.lightmap,Dt.emissivemap,Dt.bumpmap,Dt.normalmap,Dt.displacementmap,Dt.fog,Dt.lights,{emissive:{value:new ce(0)},envMapIntensity:{value:1}}]),vertexShader:le.meshlambert_vert,fragmentShader:le.meshlambert_frag},phong:{uniforms:Gn([Dt.common,Dt.specularmap,Dt.envmap,Dt.aomap,Dt.lightmap,Dt.emissivemap,Dt.bumpmap,Dt.normalmap,Dt.displacementmap,Dt.fog,Dt.lights,{emissive:{value:new ce(0)},specular:{value:new ce(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:le.meshphong_vert,fragmentShader:le.meshphong_frag},standard:{uniforms:Gn([Dt.common,Dt.envmap,Dt.aomap,Dt.lightmap,Dt.emissivemap,Dt.bumpmap,Dt.normalmap,Dt.displacementmap,Dt.roughnessmap,Dt.metalnessmap,Dt.fog,Dt.lights,{emissive:{value:new ce(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:le.meshphysical_vert,fragmentShader:le.meshphysical_frag},toon:{uniforms:Gn([Dt.common,Dt.aomap,Dt.lightmap,Dt.emissivemap,Dt.bumpmap,Dt.normalmap,Dt.displacementmap,Dt.gradientmap,Dt.fog,Dt.lights,{emissive:{value:new ce(0)}}]),vertexShader:le.meshtoon_vert,fragmentShader:le.meshtoon_frag},matcap:{uniforms:Gn([Dt.common,Dt.bumpmap,Dt.normalmap,Dt.displacementmap,Dt.fog,{matcap:{value:null}}]),vertexShader:le.meshmatcap_vert,fragmentShader:le.meshmatcap_frag},points:{uniforms:Gn([Dt.points,Dt.fog]),vertexShader:le.points_vert,fragmentShader:le.points_frag},dashed:{uniforms:Gn([Dt.common,Dt.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:le.linedashed_vert,fragmentShader:le.linedashed_frag},depth:{uniforms:Gn([Dt.common,Dt.displacementmap]),vertexShader:le.depth_vert,fragmentShader:le.depth_frag},normal:{uniforms:Gn([Dt.common,Dt.bumpmap,Dt.normalmap,Dt.displacementmap,{opacity:{value:1}}]),vertexShader:le.meshnormal_vert,fragmentShader:le.meshnormal_frag},sprite:{uniforms:Gn([Dt.sprite,Dt.fog]),vertexShader:le.sprite_vert,fragmentShader:le.sprite_frag},background:{uniforms:{uvTransform:{value:new re},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:le.background_vert,fragmentShader:le.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new re}},vertexShader:le.backgroundCube_vert,fragmentShader:le.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:le.cube_vert,fragmentShader:le.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:le.equirect_vert,fragmentShader:le.equirect_frag},distance:{uniforms:Gn([Dt.common,Dt.displacementmap,{referencePosition:{value:new k},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:le.distance_vert,fragmentShader:le.distance_frag},shadow:{uniforms:Gn([Dt.lights,Dt.fog,{color:{value:new ce(0)},opacity:{value:1}}]),vertexShader:le.shadow_vert,fragmentShader:le.shadow_frag}};ki.physical={uniforms:Gn([ki.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new re},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new re},clearcoatNormalScale:{value:new Xt(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new re},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new re},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new re},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new re},sheen:{value:0},sheenColor:{value:new ce(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new re},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new re},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new re},transmissionSamplerSize:{value:new Xt},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new re},attenuationDistance:{value:0},attenuationColor:{value:new ce(0)},specularColor:{value:new ce(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new re},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new re},anisotropyVector:{value:new Xt},anisotropyMap:{value:null},anisotropyMapTransform:{value:new re}}]),vertexShader:le.meshphysical_vert,fragmentShader:le.meshphysical_frag};const yo={r:0,b:0,g:0},Qx=new De,Vp=new re;Vp.set(-1,0,0,0,1,0,0,0,1);function tS(i,t,e,n,s,r){const a=new ce(0);let o=s===!0?0:1,l,c,h=null,u=0,d=null;function m(x){let A=x.isScene===!0?x.background:null;if(A&&A.isTexture){const S=x.backgroundBlurriness>0;A=t.get(A,S)}return A}function _(x){let A=!1;const S=m(x);S===null?p(a,o):S&&S.isColor&&(p(S,1),A=!0);const R=i.xr.getEnvironmentBlendMode();R==="additive"?e.buffers.color.setClear(0,0,0,1,r):R==="alpha-blend"&&e.buffers.color.setClear(0,0,0,0,r),(i.autoClear||A)&&(e.buffers.depth.setTest(!0),e.buffers.depth.setMask(!0),e.buffers.color.setMask(!0),i.clear(i.autoClearColor,i.autoClearDepth,i.autoClearStencil))}function M(x,A){const S=m(A);S&&S.isCubeTexture?(c===void 0&&(c=new fn(new Ha(1,1,1),new Zs({name:"BackgroundCubeMaterial",uniforms:Hr(ki.backgroundCube.uniforms),vertexShader:ki.backgroundCube.vertexShader,fragmentShader:ki.backgroundCube.fragmentShader,side:Yn,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),c.geometry.deleteAttribute("uv"),c.onBeforeRender=function(R,b,g){this.matrixWorld.copyPosition(g.matrixWorld)},Object.defineProperty(c.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),n.update(c)),c.material.uniforms.envMap.value=S,c.material.uniforms.backgroundBlurriness.value=A.backgroundBlurriness,c.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,c.material.uniforms.backgroundRotation.value.setFromMatrix4(Qx.makeRotationFromEuler(A.backgroundRotation)).transpose(),S.isRenderTargetTexture===!1&&c.material.uniforms.backgroundRotation.value.premultiply(Vp),c.material.toneMapped=xe.getTransfer(S.colorSpace)!==Le,(h!==S||u!==S.version||d!==i.toneMapping)&&(c.material.needsUpdate=!0,h=S,u=S.version,d=i.toneMapping),c.layers.enableAll(),x.unshift(c,c.geometry,c.material,0,0,null)):S&&S.isTexture&&(l===void 0&&(l=new fn(new il(2,2),new Zs({name:"BackgroundMaterial",uniforms:Hr(ki.background.uniforms),vertexShader:ki.background.vertexShader,fragmentShader:ki.background.fragmentShader,side:Cs,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),n.update(l)),l.material.uniforms.t2D.value=S,l.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,l.material.toneMapped=xe.getTransfer(S.colorSpace)!==Le,S.matrixAutoUpdate===!0&&S.updateMatrix(),l.material.uniforms.uvTransform.value.copy(S.matrix),(h!==S||u!==S.version||d!==i.toneMapping)&&(l.material.needsUpdate=!0,h=S,u=S.version,d=i.toneMapping),l.layers.enableAll(),x.unshift(l,l.geometry,l.material,0,0,null))}function p(x,A){x.getRGB(yo,Ip(i)),e.buffers.color.setClear(yo.r,yo.g,yo.b,A,r)}function f(){c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0),l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0)}return{getClearColor:function(){return a},setClearColor:function(x,A=1){a.set(x),o=A,p(a,o)},getClearAlpha:function(){return o},setClearAlpha:function(x){o=x,p(a,o)},render:_,addToRenderList:M,dispose:f}}function eS(i,t){const e=i.getParameter(i.MAX_VERTEX_ATTRIBS),n={},s=d(null);let r=s,a=!1;function o(L,V,$,N,W){let J=!1;const H=u(L,N,$,V);r!==H&&(r=H,c(r.object)),J=m(L,N,$,W),J&&_(L,N,$,W),W!==null&&t.update(W,i.ELEMENT_ARRAY_BUFFER),(J||a)&&(a=!1,S(L,V,$,N),W!==null&&i.bindBuffer(i.ELEMENT_ARRAY_BUFFER,t.get(W).buffer))}function l(){return i.createVertexArray()}function c(L){return i.bindVertexArray(L)}function h(L){return i.deleteVertexArray(L)}function u(L,V,$,N){const W=N.wireframe===!0;let J=n[V.id];J===void 0&&(J={},n[V.id]=J);const H=L.isInstancedMesh===!0?L.id:0;let ct=J[H];ct===void 0&&(ct={},J[H]=ct);let Z=ct[$.id];Z===void 0&&(Z={},ct[$.id]=Z);let tt=Z[W];return tt===void 0&&(tt=d(l()),Z[W]=tt),tt}function d(L){const V=[],$=[],N=[];for(let W=0;W<e;W++)V[W]=0,$[W]=0,N[W]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:V,enabledAttributes:$,attributeDivisors:N,object:L,attributes:{},index:null}}function m(L,V,$,N){const W=r.attributes,J=V.attributes;let H=0;const ct=$.getAttributes();for(const Z in ct)if(ct[Z].location>=0){const st=W[Z];let pt=J[Z];if(pt===void 0&&(Z==="instanceMatrix"&&L.instanceMatrix&&(pt=L.instanceMatrix),Z==="instanceColor"&&L.instanceColor&&(pt=L.instanceColor)),st===void 0||st.attribute!==pt||pt&&st.data!==pt.data)return!0;H++}return r.attributesNum!==H||r.index!==N}function _(L,V,$,N){const W={},J=V.attributes;let H=0;const ct=$.getAttributes();for(const Z in ct)if(ct[Z].location>=0){let st=J[Z];st===void 0&&(Z==="instanceMatrix"&&L.instanceMatrix&&(st=L.instanceMatrix),Z==="instanceColor"&&L.instanceColor&&(st=L.instanceColor));const pt={};pt.attribute=st,st&&st.data&&(pt.data=st.data),W[Z]=pt,H++}r.attributes=W,r.attributesNum=H,r.index=N}function M(){const L=r.newAttributes;for(let V=0,$=L.length;V<$;V++)L[V]=0}function p(L){f(L,0)}function f(L,V){const $=r.newAttributes,N=r.enabledAttributes,W=r.attributeDivisors;$[L]=1,N[L]===0&&(i.enableVertexAttribArray(L),N[L]=1),W[L]!==V&&(i.vertexAttribDivisor(L,V),W[L]=V)}function x(){const L=r.newAttributes,V=r.enabledAttributes;for(let $=0,N=V.length;$<N;$++)V[$]!==L[$]&&(i.disableVertexAttribArray($),V[$]=0)}function A(L,V,$,N,W,J,H){H===!0?i.vertexAttribIPointer(L,V,$,W,J):i.vertexAttribPointer(L,V,$,N,W,J)}function S(L,V,$,N){M();const W=N.attributes,J=$.getAttributes(),H=V.defaultAttributeValues;for(const ct in J){const Z=J[ct];if(Z.location>=0){let tt=W[ct];if(tt===void 0&&(ct==="instanceMatrix"&&L.instanceMatrix&&(tt=L.instanceMatrix),ct==="instanceColor"&&L.instanceColor&&(tt=L.instanceColor)),tt!==void 0){const st=tt.normalized,pt=tt.itemSize,ft=t.get(tt);if(ft===void 0)continue;const B=ft.buffer,et=ft.type,ht=ft.bytesPerElement,gt=et===i.INT||et===i.UNSIGNED_INT||tt.gpuType===Fh;if(tt.isInterleavedBufferAttribute){const vt=tt.data,Gt=vt.isInterleavedBuffer===!0?vt.stride:vt.itemSize,Qt=tt.offset;if(vt.isInstancedInterleavedBuffer||vt.isInstancedBufferAttribute){for(let kt=0;kt<Z.locationSize;kt++)f(Z.location+kt,vt.meshPerAttribute);L.isInstancedMesh!==!0&&N._maxInstanceCount===void 0&&(N._maxInstanceCount=vt.meshPerAttribute*vt.count)}else for(let kt=0;kt<Z.locationSize;kt++)p(Z.location+kt);i.bindBuffer(i.ARRAY_BUFFER,B);for(let kt=0;kt<Z.locationSize;kt++)A(Z.location+kt,pt/Z.locationSize,et,st,Gt*ht,(Qt+pt/Z.locationSize*kt)*ht,gt)}else{if(tt.isInstancedBufferAttribute){for(let vt=0;vt<Z.locationSize;vt++)f(Z.location+vt,tt.meshPerAttribute);L.isInstancedMesh!==!0&&N._maxInstanceCount===void 0&&(N._maxInstanceCount=tt.meshPerAttribute*tt.count)}else for(let vt=0;vt<Z.locationSize;vt++)p(Z.location+vt);i.bindBuffer(i.ARRAY_BUFFER,B);for(let vt=0;vt<Z.locationSize;vt++)A(Z.location+vt,pt/Z.locationSize,et,st,pt*ht,pt/Z.locationSize*vt*ht,gt)}}else if(H!==void 0){const st=H[ct];if(st!==void 0)switch(st.length){case 2:i.vertexAttrib2fv(Z.location,st);break;case 3:i.vertexAttrib3fv(Z.location,st);break;case 4:i.vertexAttrib4fv(Z.location,st);break;default:i.vertexAttrib1fv(Z.location,st)}}}}x()}function R(){z();for(const L in n){const V=n[L];for(const $ in V){const N=V[$];for(const W in N){const J=N[W];for(const H in J)h(J[H].object),delete J[H];delete N[W]}}delete n[L]}}function b(L){if(n[L.id]===void 0)return;const V=n[L.id];for(const $ in V){const N=V[$];for(const W in N){const J=N[W];for(const H in J)h(J[H].object),delete J[H];delete N[W]}}delete n[L.id]}function g(L){for(const V in n){const $=n[V];for(const N in $){const W=$[N];if(W[L.id]===void 0)continue;const J=W[L.id];for(const H in J)h(J[H].object),delete J[H];delete W[L.id]}}}function w(L){for(const V in n){const $=n[V],N=L.isInstancedMesh===!0?L.id:0,W=$[N];if(W!==void 0){for(const J in W){const H=W[J];for(const ct in H)h(H[ct].object),delete H[ct];delete W[J]}delete $[N],Object.keys($).length===0&&delete n[V]}}}function z(){I(),a=!0,r!==s&&(r=s,c(r.object))}function I(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:o,reset:z,resetDefaultState:I,dispose:R,releaseStatesOfGeometry:b,releaseStatesOfObject:w,releaseStatesOfProgram:g,initAttributes:M,enableAttribute:p,disableUnusedAttributes:x}}function nS(i,t,e){let n;function s(l){n=l}function r(l,c){i.drawArrays(n,l,c),e.update(c,n,1)}function a(l,c,h){h!==0&&(i.drawArraysInstanced(n,l,c,h),e.update(c,n,h))}function o(l,c,h){if(h===0)return;t.get("WEBGL_multi_draw").multiDrawArraysWEBGL(n,l,0,c,0,h);let d=0;for(let m=0;m<h;m++)d+=c[m];e.update(d,n,1)}this.setMode=s,this.render=r,this.renderInstances=a,this.renderMultiDraw=o}function iS(i,t,e,n){let s;function r(){if(s!==void 0)return s;if(t.has("EXT_texture_filter_anisotropic")===!0){const g=t.get("EXT_texture_filter_anisotropic");s=i.getParameter(g.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function a(g){return!(g!==Gi&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(g){const w=g===qi&&(t.has("EXT_color_buffer_half_float")||t.has("EXT_color_buffer_float"));return!(g!==ei&&g!==Hi&&!w&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_TYPE))}function l(g){if(g==="highp"){if(i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.HIGH_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.HIGH_FLOAT).precision>0)return"highp";g="mediump"}return g==="mediump"&&i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.MEDIUM_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let c=e.precision!==void 0?e.precision:"highp";const h=l(c);h!==c&&(jt("WebGLRenderer:",c,"not supported, using",h,"instead."),c=h);const u=e.reversedDepthBuffer===!0&&t.has("EXT_clip_control"),d=e.logarithmicDepthBuffer===!0&&u===!1;e.reversedDepthBuffer===!0&&u===!1&&jt("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),e.logarithmicDepthBuffer===!0&&u===!0&&jt("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");const m=i.getParameter(i.MAX_TEXTURE_IMAGE_UNITS),_=i.getParameter(i.MAX_VERTEX_TEXTURE_IMAGE_UNITS),M=i.getParameter(i.MAX_TEXTURE_SIZE),p=i.getParameter(i.MAX_CUBE_MAP_TEXTURE_SIZE),f=i.getParameter(i.MAX_VERTEX_ATTRIBS),x=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),A=i.getParameter(i.MAX_VARYING_VECTORS),S=i.getParameter(i.MAX_FRAGMENT_UNIFORM_VECTORS),R=i.getParameter(i.MAX_SAMPLES),b=i.getParameter(i.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:l,textureFormatReadable:a,textureTypeReadable:o,precision:c,logarithmicDepthBuffer:d,reversedDepthBuffer:u,maxTextures:m,maxVertexTextures:_,maxTextureSize:M,maxCubemapSize:p,maxAttributes:f,maxVertexUniforms:x,maxVaryings:A,maxFragmentUniforms:S,maxSamples:R,samples:b}}function sS(i){const t=this;let e=null,n=0,s=!1,r=!1;const a=new wi,o=new re,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(u,d){const m=u.length!==0||d||n!==0||s;return s=d,n=u.length,m},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(u,d){e=h(u,d,0)},this.setState=function(u,d,m){const _=u.clippingPlanes,M=u.clipIntersection,p=u.clipShadows,f=i.get(u);if(!s||_===null||_.length===0||r&&!p)r?h(null):c();else{const x=r?0:n,A=x*4;let S=f.clippingState||null;l.value=S,S=h(_,d,A,m);for(let R=0;R!==A;++R)S[R]=e[R];f.clippingState=S,this.numIntersection=M?this.numPlanes:0,this.numPlanes+=x}};function c(){l.value!==e&&(l.value=e,l.needsUpdate=n>0),t.numPlanes=n,t.numIntersection=0}function h(u,d,m,_){const M=u!==null?u.length:0;let p=null;if(M!==0){if(p=l.value,_!==!0||p===null){const f=m+M*4,x=d.matrixWorldInverse;o.getNormalMatrix(x),(p===null||p.length<f)&&(p=new Float32Array(f));for(let A=0,S=m;A!==M;++A,S+=4)a.copy(u[A]).applyMatrix4(x,o),a.normal.toArray(p,S),p[S+3]=a.constant}l.value=p,l.needsUpdate=!0}return t.numPlanes=M,t.numIntersection=0,p}}class $h extends Xi{constructor(t=1,e={}){super(t,t,e),this.isWebGLCubeRenderTarget=!0;const n={width:t,height:t,depth:1},s=[n,n,n,n,n,n];this.texture=new Lp(s),this._setTextureOptions(e),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(t,e){this.texture.type=e.type,this.texture.colorSpace=e.colorSpace,this.texture.generateMipmaps=e.generateMipmaps,this.texture.minFilter=e.minFilter,this.texture.magFilter=e.magFilter;const n={uniforms:{tEquirect:{value:null}},vertexShader:`

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
			`},s=new Ha(5,5,5),r=new Zs({name:"CubemapFromEquirect",uniforms:Hr(n.uniforms),vertexShader:n.vertexShader,fragmentShader:n.fragmentShader,side:Yn,blending:Ur});r.uniforms.tEquirect.value=e;const a=new fn(s,r),o=e.minFilter;return e.minFilter===ws&&(e.minFilter=$n),new uh(1,10,this).update(t,a),e.minFilter=o,a.geometry.dispose(),a.material.dispose(),this}clear(t,e=!0,n=!0,s=!0){const r=t.getRenderTarget();for(let a=0;a<6;a++)t.setRenderTarget(this,a),t.clear(e,n,s);t.setRenderTarget(r)}}const xd=256,rS=3,aS=20,Wp=256,Xp=16,oS=3,lS=new k,cS=new ce;class Zo{constructor(t){this._renderer=t,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new uh(1,10,null),this._boxMesh=new fn(new Ha(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(t,e=0,n=.1,s=100,r={}){const{size:a=256,position:o=lS}=r,l=this._renderer;this._setSize(a);const c=this._allocateTarget(),h=this._getSourceTarget(!0);e>0&&(h.texture.mipmapsAutoUpdate=!1);const u=l.autoClear,d=l.autoClearColor,m=l.autoClearDepth,_=l.autoClearStencil,M=t.background;l.autoClear=!0,l.autoClearColor=!0,l.autoClearDepth=!0,l.autoClearStencil=!0,M===null&&(t.background=l.getClearColor(cS));const p=new uh(n,s,h);return p.position.copy(o),p.update(l,t),l.autoClear=u,l.autoClearColor=d,l.autoClearDepth=m,l.autoClearStencil=_,t.background=M,e>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(c,e)),this._applyPMREM(c),c}fromEquirectangular(t,e=null){return this._fromTexture(t,e)}fromCubemap(t,e=null){return this._fromTexture(t,e)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=yd(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Md(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(t,e){return e>0?1-Math.sqrt(1-t/e):0}_setSize(t){this._cubeSize=Math.max(xd,L0(t))}_fromTexture(t,e){t.mapping===Br||t.mapping===Pa?this._setSize(t.image.length===0?xd:t.image[0].width||t.image[0].image.width):this._setSize(t.image.width/4);const n=e||this._allocateTarget();return this._textureToCubemap(t),this._applyPMREM(n),n}_allocateTarget(){const t=this._cubeSize,e=Sd(t,!1,!1),n=Math.log2(t)-rS;for(let s=0;s<=n;s++)e.texture.mipmaps.push({width:t>>s,height:t>>s});return e.texture.name="PMREM",e.texture.isPMREMTexture=!0,e}_getSourceTarget(t=!1){const e=this._cubeSize,n=this._sourceTarget;return(n===null||n.width!==e||t&&n.depthBuffer===!1)&&(n!==null&&n.dispose(),this._sourceTarget=Sd(e,!0,t)),this._sourceTarget}_compileMaterial(t){this._boxMesh.material=t,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(t,e,n){const s=this._boxMesh,r=this._cubeCamera;s.material=n,r.renderTarget=t,r.activeMipmapLevel=e;const a=t.width>>e;t.viewport.set(0,0,a,a),r.update(this._renderer,s),t.viewport.set(0,0,t.width,t.height)}_textureToCubemap(t){let e;t.mapping===Br||t.mapping===Pa?(this._cubemapMaterial===null&&(this._cubemapMaterial=yd()),e=this._cubemapMaterial,e.uniforms.flipEnvMap.value=t.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Md()),e=this._equirectMaterial),e.uniforms.envMap.value=t,this._renderCube(this._getSourceTarget(),0,e)}_applyPMREM(t){this._ggxMaterial===null&&(this._ggxMaterial=hS(),this._integrationMaterial=uS());const e=this._cubeSize,n=t.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;const r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(e/Xp);for(let a=0;a<=n;a++){const o=Zo.lodToRoughness(a,n);if(a>n-oS)r.roughness.value=o,this._renderCube(t,a,this._integrationMaterial);else{const l=o>0?Math.log2(e)+.5*Math.log2(6/(Wp*Math.pow(o,4)))+.5:0;s.roughness.value=o,s.lodBias.value=l,this._renderCube(t,a,this._ggxMaterial)}}}_blur(t,e){this._blurMaterial===null&&(this._blurMaterial=dS());const n=this._blurMaterial,s=n.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(e,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(t,0,n),s.envMap.value=t.texture,this._renderCube(r,0,n)}}function Sd(i,t,e){return new $h(i,{minFilter:ws,generateMipmaps:t,type:qi,colorSpace:Vo,depthBuffer:e})}function Va(i,t,e){return new Zs({name:i,uniforms:t,vertexShader:le.cube_vert,fragmentShader:e,side:Yn,blending:Ur,depthTest:!1,depthWrite:!1})}function hS(){return Va("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${Wp}u

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
	`)}function uS(){return Va("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:Xp}},`

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
	`)}function dS(){return Va("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${aS}
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
	`)}function Md(){return Va("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

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
	`)}function yd(){return Va("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function fS(i){let t=new WeakMap,e=new WeakMap,n=null;function s(d,m=!1){return d==null?null:m?a(d):r(d)}function r(d){if(d&&d.isTexture){const m=d.mapping;if(m===Rl||m===Cl)if(t.has(d)){const _=t.get(d).texture;return o(_,d.mapping)}else{const _=d.image;if(_&&_.height>0){const M=new $h(_.height);return M.fromEquirectangularTexture(i,d),t.set(d,M),d.addEventListener("dispose",c),o(M.texture,d.mapping)}else return null}}return d}function a(d){if(d&&d.isTexture&&d.isPMREMTexture!==!0){const m=d.mapping,_=m===Rl||m===Cl,M=m===Br||m===Pa;if(_||M){let p=e.get(d);const f=p!==void 0?p.texture.pmremVersion:0;if(d.isRenderTargetTexture&&d.pmremVersion!==f)return n===null&&(n=new Zo(i)),p=_?n.fromEquirectangular(d,p):n.fromCubemap(d,p),p.texture.pmremVersion=d.pmremVersion,e.set(d,p),p.texture;if(p!==void 0)return p.texture;{const x=d.image;return _&&x&&x.height>0||M&&x&&l(x)?(n===null&&(n=new Zo(i)),p=_?n.fromEquirectangular(d):n.fromCubemap(d),p.texture.pmremVersion=d.pmremVersion,e.set(d,p),d.addEventListener("dispose",h),p.texture):null}}}return d}function o(d,m){return m===Rl?d.mapping=Br:m===Cl&&(d.mapping=Pa),d}function l(d){let m=0;const _=6;for(let M=0;M<_;M++)d[M]!==void 0&&m++;return m===_}function c(d){const m=d.target;m.removeEventListener("dispose",c);const _=t.get(m);_!==void 0&&(t.delete(m),_.dispose())}function h(d){const m=d.target;m.removeEventListener("dispose",h);const _=e.get(m);_!==void 0&&(e.delete(m),_.dispose())}function u(){t=new WeakMap,e=new WeakMap,n!==null&&(n.dispose(),n=null)}return{get:s,dispose:u}}function pS(i){const t={};function e(n){if(t[n]!==void 0)return t[n];const s=i.getExtension(n);return t[n]=s,s}return{has:function(n){return e(n)!==null},init:function(){e("EXT_color_buffer_float"),e("WEBGL_clip_cull_distance"),e("OES_texture_float_linear"),e("EXT_color_buffer_half_float"),e("WEBGL_multisampled_render_to_texture"),e("WEBGL_render_shared_exponent")},get:function(n){const s=e(n);return s===null&&Bo("WebGLRenderer: "+n+" extension not supported."),s}}}function mS(i,t,e,n){const s={},r=new WeakMap,a=new FinalizationRegistry(_=>delete s[_]);function o(_){l(_.target)}function l(_){_.index!==null&&t.remove(_.index);for(const p in _.attributes)t.remove(_.attributes[p]);_.removeEventListener("dispose",o),delete s[_.id],a.unregister(_);const M=r.get(_);M&&(t.remove(M),r.delete(_)),n.releaseStatesOfGeometry(_),_.isInstancedBufferGeometry===!0&&delete _._maxInstanceCount,e.memory.geometries--}function c(_,M){return s[M.id]!==void 0||(M.addEventListener("dispose",o),s[M.id]=new WeakRef(M),a.register(M,M.id,M),e.memory.geometries++),M}function h(_){const M=_.attributes;for(const p in M)t.update(M[p],i.ARRAY_BUFFER)}function u(_){const M=_.index,p=_.attributes.position;let f=0;if(p===void 0)return;const x=M!==null?M.array.length:p.array.length/3-1,A=p.count>=65535?Ap:Tp,S=new A(Math.ceil(x/3)*6,1),R=S.array;if(M!==null){const g=M.array;f=M.version;for(let w=0,z=0;w<x;w+=3){const I=g[w+0],L=g[w+1],V=g[w+2];R[z++]=I,R[z++]=L,R[z++]=L,R[z++]=V,R[z++]=V,R[z++]=I}}else{f=p.version;for(let g=0,w=0;g<x;g+=3){const z=g+0,I=g+1,L=g+2;R[w++]=z,R[w++]=I,R[w++]=I,R[w++]=L,R[w++]=L,R[w++]=z}}S.version=f;const b=r.get(_);b&&t.remove(b),r.set(_,S)}function d(_){const M=r.get(_);if(M){const p=_.index;p!==null&&M.version<p.version&&u(_)}else u(_);return r.get(_)}function m(){for(const _ in s){const M=s[_].deref();M!==void 0&&l(M)}}return{get:c,update:h,getWireframeAttribute:d,dispose:m}}function gS(i,t,e){let n;function s(u){n=u}let r,a;function o(u){r=u.type,a=u.bytesPerElement}function l(u,d){i.drawElements(n,d,r,u*a),e.update(d,n,1)}function c(u,d,m){m!==0&&(i.drawElementsInstanced(n,d,r,u*a,m),e.update(d,n,m))}function h(u,d,m){if(m===0)return;t.get("WEBGL_multi_draw").multiDrawElementsWEBGL(n,d,0,r,u,0,m);let M=0;for(let p=0;p<m;p++)M+=d[p];e.update(M,n,1)}this.setMode=s,this.setIndex=o,this.render=l,this.renderInstances=c,this.renderMultiDraw=h}function _S(i){const t={geometries:0,textures:0},e={frame:0,calls:0,triangles:0,points:0,lines:0};function n(r,a,o){switch(e.calls++,a){case i.TRIANGLES:e.triangles+=o*(r/3);break;case i.LINES:e.lines+=o*(r/2);break;case i.LINE_STRIP:e.lines+=o*(r-1);break;case i.LINE_LOOP:e.lines+=o*r;break;case i.POINTS:e.points+=o*r;break;default:Se("WebGLInfo: Unknown draw mode:",a);break}}function s(){e.calls=0,e.triangles=0,e.points=0,e.lines=0}return{memory:t,render:e,programs:null,autoReset:!0,reset:s,update:n}}function vS(i,t,e){const n=new WeakMap,s=new nn;function r(a,o,l){const c=a.morphTargetInfluences,h=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,u=h!==void 0?h.length:0;let d=n.get(o);if(d===void 0||d.count!==u){let I=function(){w.dispose(),n.delete(o),o.removeEventListener("dispose",I)};var m=I;d!==void 0&&d.texture.dispose();const _=o.morphAttributes.position!==void 0,M=o.morphAttributes.normal!==void 0,p=o.morphAttributes.color!==void 0,f=o.morphAttributes.position||[],x=o.morphAttributes.normal||[],A=o.morphAttributes.color||[];let S=0;_===!0&&(S=1),M===!0&&(S=2),p===!0&&(S=3);let R=o.attributes.position.count*S,b=1;R>t.maxTextureSize&&(b=Math.ceil(R/t.maxTextureSize),R=t.maxTextureSize);const g=new Float32Array(R*b*4*u),w=new bp(g,R,b,u);w.type=Hi,w.needsUpdate=!0;const z=S*4;for(let L=0;L<u;L++){const V=f[L],$=x[L],N=A[L],W=R*b*4*L;for(let J=0;J<V.count;J++){const H=J*z;_===!0&&(s.fromBufferAttribute(V,J),g[W+H+0]=s.x,g[W+H+1]=s.y,g[W+H+2]=s.z,g[W+H+3]=0),M===!0&&(s.fromBufferAttribute($,J),g[W+H+4]=s.x,g[W+H+5]=s.y,g[W+H+6]=s.z,g[W+H+7]=0),p===!0&&(s.fromBufferAttribute(N,J),g[W+H+8]=s.x,g[W+H+9]=s.y,g[W+H+10]=s.z,g[W+H+11]=N.itemSize===4?s.w:1)}}d={count:u,texture:w,size:new Xt(R,b)},n.set(o,d),o.addEventListener("dispose",I)}if(a.isInstancedMesh===!0&&a.morphTexture!==null)l.getUniforms().setValue(i,"morphTexture",a.morphTexture,e);else{let _=0;for(let p=0;p<c.length;p++)_+=c[p];const M=o.morphTargetsRelative?1:1-_;l.getUniforms().setValue(i,"morphTargetBaseInfluence",M),l.getUniforms().setValue(i,"morphTargetInfluences",c)}l.getUniforms().setValue(i,"morphTargetsTexture",d.texture,e),l.getUniforms().setValue(i,"morphTargetsTextureSize",d.size)}return{update:r}}function xS(i,t,e,n,s){let r=new WeakMap;function a(c){const h=s.render.frame,u=c.geometry,d=t.get(c,u);if(r.get(d)!==h&&(t.update(d),r.set(d,h)),c.isInstancedMesh&&(c.hasEventListener("dispose",l)===!1&&c.addEventListener("dispose",l),r.get(c)!==h&&(e.update(c.instanceMatrix,i.ARRAY_BUFFER),c.instanceColor!==null&&e.update(c.instanceColor,i.ARRAY_BUFFER),r.set(c,h))),c.isSkinnedMesh){const m=c.skeleton;r.get(m)!==h&&(m.update(),r.set(m,h))}return d}function o(){r=new WeakMap}function l(c){const h=c.target;h.removeEventListener("dispose",l),n.releaseStatesOfObject(h),e.remove(h.instanceMatrix),h.instanceColor!==null&&e.remove(h.instanceColor)}return{update:a,dispose:o}}const SS={[ep]:"LINEAR_TONE_MAPPING",[np]:"REINHARD_TONE_MAPPING",[ip]:"CINEON_TONE_MAPPING",[sp]:"ACES_FILMIC_TONE_MAPPING",[ap]:"AGX_TONE_MAPPING",[op]:"NEUTRAL_TONE_MAPPING",[rp]:"CUSTOM_TONE_MAPPING"};function MS(i,t,e,n,s,r){const a=new Xi(t,e,{type:i,depthBuffer:s,stencilBuffer:r,samples:n?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1});let o=null,l=null,c=null;const h=new Be;h.setAttribute("position",new sn([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new sn([0,2,0,0,2,0],2));const u=new l_({uniforms:{tDiffuse:{value:null}},vertexShader:`
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
			}`,depthTest:!1,depthWrite:!1}),d=new fn(h,u),m=new Bp(-1,1,1,-1,0,1);let _=null,M=null,p=!1,f,x=null,A=[],S=!1;this.setSize=function(R,b){a.setSize(R,b),o!==null&&o.setSize(R,b),l!==null&&l.setSize(R,b);for(let g=0;g<A.length;g++){const w=A[g];w.setSize&&w.setSize(R,b)}},this.setEffects=function(R){A=R,S=A.length>0&&A[0].isRenderPass===!0;const b=a.width,g=a.height;A.length>0&&o===null&&(o=new Xi(b,g,{type:qi,depthBuffer:!1,stencilBuffer:!1}),l=new Xi(b,g,{type:qi,depthBuffer:!1,stencilBuffer:!1}));const w=s===!0&&A.some(z=>z.needsDepthTexture===!0);w!==(a.depthTexture!==null)&&(w===!0&&c===null&&(c=new kr(b,g),r===!0&&(c.format=Ts,c.type=zr)),a.dispose(),a.depthTexture=w?c:null,a.resolveDepthBuffer=w,a.storeMultisampledDepthBuffer=w);for(let z=0;z<A.length;z++){const I=A[z];I.setSize&&I.setSize(b,g),w&&I.needsDepthTexture===!0&&I.setDepthTexture&&I.setDepthTexture(c)}},this.begin=function(R,b){if(p||R.toneMapping===os&&A.length===0)return!1;if(x=b,b!==null){const g=b.width,w=b.height;(a.width!==g||a.height!==w)&&this.setSize(g,w)}return S===!1&&R.setRenderTarget(a),f=R.toneMapping,R.toneMapping=os,!0},this.hasRenderPass=function(){return S},this.end=function(R,b){R.toneMapping=f,p=!0;let g=a,w=o;for(let z=0;z<A.length;z++){const I=A[z];I.enabled!==!1&&(I.render(R,w,g,b),I.needsSwap!==!1&&(g=w,w=w===o?l:o))}if(_!==R.outputColorSpace||M!==R.toneMapping){_=R.outputColorSpace,M=R.toneMapping,u.defines={},xe.getTransfer(_)===Le&&(u.defines.SRGB_TRANSFER="");const z=SS[M];z&&(u.defines[z]=""),u.needsUpdate=!0}u.uniforms.tDiffuse.value=g.texture,R.setRenderTarget(x),R.render(d,m),x=null,p=!1},this.isCompositing=function(){return p},this.dispose=function(){a.dispose(),o!==null&&o.dispose(),l!==null&&l.dispose(),h.dispose(),u.dispose()}}const $p=new In,Yp=new kr(1,1),qp=new Dp(1),Kp=new bp,Zp=new B0,Jp=new Lp,bd=[],Ed=[],wd=new Float32Array(16),Td=new Float32Array(9),Ad=new Float32Array(4);function $r(i,t,e){const n=i[0];if(n<=0||n>0)return i;const s=t*e;let r=bd[s];if(r===void 0&&(r=new Float32Array(s),bd[s]=r),t!==0){n.toArray(r,0);for(let a=1,o=0;a!==t;++a)o+=e,i[a].toArray(r,o)}return r}function Mn(i,t){if(i.length!==t.length)return!1;for(let e=0,n=i.length;e<n;e++)if(i[e]!==t[e])return!1;return!0}function yn(i,t){for(let e=0,n=t.length;e<n;e++)i[e]=t[e]}function sl(i,t){let e=Ed[t];e===void 0&&(e=new Int32Array(t),Ed[t]=e);for(let n=0;n!==t;++n)e[n]=i.allocateTextureUnit();return e}function yS(i,t){const e=this.cache;e[0]!==t&&(i.uniform1f(this.addr,t),e[0]=t)}function bS(i,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2f(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Mn(e,t))return;i.uniform2fv(this.addr,t),yn(e,t)}}function ES(i,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3f(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else if(t.r!==void 0)(e[0]!==t.r||e[1]!==t.g||e[2]!==t.b)&&(i.uniform3f(this.addr,t.r,t.g,t.b),e[0]=t.r,e[1]=t.g,e[2]=t.b);else{if(Mn(e,t))return;i.uniform3fv(this.addr,t),yn(e,t)}}function wS(i,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4f(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Mn(e,t))return;i.uniform4fv(this.addr,t),yn(e,t)}}function TS(i,t){const e=this.cache,n=t.elements;if(n===void 0){if(Mn(e,t))return;i.uniformMatrix2fv(this.addr,!1,t),yn(e,t)}else{if(Mn(e,n))return;Ad.set(n),i.uniformMatrix2fv(this.addr,!1,Ad),yn(e,n)}}function AS(i,t){const e=this.cache,n=t.elements;if(n===void 0){if(Mn(e,t))return;i.uniformMatrix3fv(this.addr,!1,t),yn(e,t)}else{if(Mn(e,n))return;Td.set(n),i.uniformMatrix3fv(this.addr,!1,Td),yn(e,n)}}function RS(i,t){const e=this.cache,n=t.elements;if(n===void 0){if(Mn(e,t))return;i.uniformMatrix4fv(this.addr,!1,t),yn(e,t)}else{if(Mn(e,n))return;wd.set(n),i.uniformMatrix4fv(this.addr,!1,wd),yn(e,n)}}function CS(i,t){const e=this.cache;e[0]!==t&&(i.uniform1i(this.addr,t),e[0]=t)}function PS(i,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2i(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Mn(e,t))return;i.uniform2iv(this.addr,t),yn(e,t)}}function LS(i,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3i(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(Mn(e,t))return;i.uniform3iv(this.addr,t),yn(e,t)}}function DS(i,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4i(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Mn(e,t))return;i.uniform4iv(this.addr,t),yn(e,t)}}function NS(i,t){const e=this.cache;e[0]!==t&&(i.uniform1ui(this.addr,t),e[0]=t)}function IS(i,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2ui(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Mn(e,t))return;i.uniform2uiv(this.addr,t),yn(e,t)}}function US(i,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3ui(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(Mn(e,t))return;i.uniform3uiv(this.addr,t),yn(e,t)}}function FS(i,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4ui(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Mn(e,t))return;i.uniform4uiv(this.addr,t),yn(e,t)}}function rl(i){return i.version===0&&(i.compareFunction=vp,i.needsUpdate=!0),i}function OS(i,t,e){const n=this.cache,s=e.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_2D_SHADOW?r=rl(Yp):r=$p,e.setTexture2D(t||r,s)}function BS(i,t,e){const n=this.cache,s=e.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),e.setTexture3D(t||Zp,s)}function zS(i,t,e){const n=this.cache,s=e.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_CUBE_SHADOW?r=rl(qp):r=Jp,e.setTextureCube(t||r,s)}function kS(i,t,e){const n=this.cache,s=e.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),e.setTexture2DArray(t||Kp,s)}function HS(i){switch(i){case 5126:return yS;case 35664:return bS;case 35665:return ES;case 35666:return wS;case 35674:return TS;case 35675:return AS;case 35676:return RS;case 5124:case 35670:return CS;case 35667:case 35671:return PS;case 35668:case 35672:return LS;case 35669:case 35673:return DS;case 5125:return NS;case 36294:return IS;case 36295:return US;case 36296:return FS;case 35678:case 36198:case 36298:case 36306:case 35682:return OS;case 35679:case 36299:case 36307:return BS;case 35680:case 36300:case 36308:case 36293:return zS;case 36289:case 36303:case 36311:case 36292:return kS}}function GS(i,t){i.uniform1fv(this.addr,t)}function VS(i,t){const e=$r(t,this.size,2);i.uniform2fv(this.addr,e)}function WS(i,t){const e=$r(t,this.size,3);i.uniform3fv(this.addr,e)}function XS(i,t){const e=$r(t,this.size,4);i.uniform4fv(this.addr,e)}function $S(i,t){const e=$r(t,this.size,4);i.uniformMatrix2fv(this.addr,!1,e)}function YS(i,t){const e=$r(t,this.size,9);i.uniformMatrix3fv(this.addr,!1,e)}function qS(i,t){const e=$r(t,this.size,16);i.uniformMatrix4fv(this.addr,!1,e)}function KS(i,t){i.uniform1iv(this.addr,t)}function ZS(i,t){i.uniform2iv(this.addr,t)}function JS(i,t){i.uniform3iv(this.addr,t)}function jS(i,t){i.uniform4iv(this.addr,t)}function QS(i,t){i.uniform1uiv(this.addr,t)}function tM(i,t){i.uniform2uiv(this.addr,t)}function eM(i,t){i.uniform3uiv(this.addr,t)}function nM(i,t){i.uniform4uiv(this.addr,t)}function iM(i,t,e){const n=this.cache,s=t.length,r=sl(e,s);Mn(n,r)||(i.uniform1iv(this.addr,r),yn(n,r));let a;this.type===i.SAMPLER_2D_SHADOW?a=rl(Yp):a=$p;for(let o=0;o!==s;++o)e.setTexture2D(t[o]||a,r[o])}function sM(i,t,e){const n=this.cache,s=t.length,r=sl(e,s);Mn(n,r)||(i.uniform1iv(this.addr,r),yn(n,r));for(let a=0;a!==s;++a)e.setTexture3D(t[a]||Zp,r[a])}function rM(i,t,e){const n=this.cache,s=t.length,r=sl(e,s);Mn(n,r)||(i.uniform1iv(this.addr,r),yn(n,r));let a;this.type===i.SAMPLER_CUBE_SHADOW?a=rl(qp):a=Jp;for(let o=0;o!==s;++o)e.setTextureCube(t[o]||a,r[o])}function aM(i,t,e){const n=this.cache,s=t.length,r=sl(e,s);Mn(n,r)||(i.uniform1iv(this.addr,r),yn(n,r));for(let a=0;a!==s;++a)e.setTexture2DArray(t[a]||Kp,r[a])}function oM(i){switch(i){case 5126:return GS;case 35664:return VS;case 35665:return WS;case 35666:return XS;case 35674:return $S;case 35675:return YS;case 35676:return qS;case 5124:case 35670:return KS;case 35667:case 35671:return ZS;case 35668:case 35672:return JS;case 35669:case 35673:return jS;case 5125:return QS;case 36294:return tM;case 36295:return eM;case 36296:return nM;case 35678:case 36198:case 36298:case 36306:case 35682:return iM;case 35679:case 36299:case 36307:return sM;case 35680:case 36300:case 36308:case 36293:return rM;case 36289:case 36303:case 36311:case 36292:return aM}}class lM{constructor(t,e,n){this.id=t,this.addr=n,this.cache=[],this.type=e.type,this.setValue=HS(e.type)}}class cM{constructor(t,e,n){this.id=t,this.addr=n,this.cache=[],this.type=e.type,this.size=e.size,this.setValue=oM(e.type)}}class hM{constructor(t){this.id=t,this.seq=[],this.map={}}setValue(t,e,n){const s=this.seq;for(let r=0,a=s.length;r!==a;++r){const o=s[r];o.setValue(t,e[o.id],n)}}}const ic=/(\w+)(\])?(\[|\.)?/g;function Rd(i,t){i.seq.push(t),i.map[t.id]=t}function uM(i,t,e){const n=i.name,s=n.length;for(ic.lastIndex=0;;){const r=ic.exec(n),a=ic.lastIndex;let o=r[1];const l=r[2]==="]",c=r[3];if(l&&(o=o|0),c===void 0||c==="["&&a+2===s){Rd(e,c===void 0?new lM(o,i,t):new cM(o,i,t));break}else{let u=e.map[o];u===void 0&&(u=new hM(o),Rd(e,u)),e=u}}}class zo{constructor(t,e){this.seq=[],this.map={};const n=t.getProgramParameter(e,t.ACTIVE_UNIFORMS);for(let a=0;a<n;++a){const o=t.getActiveUniform(e,a),l=t.getUniformLocation(e,o.name);uM(o,l,this)}const s=[],r=[];for(const a of this.seq)a.type===t.SAMPLER_2D_SHADOW||a.type===t.SAMPLER_CUBE_SHADOW||a.type===t.SAMPLER_2D_ARRAY_SHADOW?s.push(a):r.push(a);s.length>0&&(this.seq=s.concat(r))}setValue(t,e,n,s){const r=this.map[e];r!==void 0&&r.setValue(t,n,s)}setOptional(t,e,n){const s=e[n];s!==void 0&&this.setValue(t,n,s)}static upload(t,e,n,s){for(let r=0,a=e.length;r!==a;++r){const o=e[r],l=n[o.id];l.needsUpdate!==!1&&o.setValue(t,l.value,s)}}static seqWithValue(t,e){const n=[];for(let s=0,r=t.length;s!==r;++s){const a=t[s];a.id in e&&n.push(a)}return n}}function Cd(i,t,e){const n=i.createShader(t);return i.shaderSource(n,e),i.compileShader(n),n}const dM=37297;let fM=0;function pM(i,t){const e=i.split(`
`),n=[],s=Math.max(t-6,0),r=Math.min(t+6,e.length);for(let a=s;a<r;a++){const o=a+1;n.push(`${o===t?">":" "} ${o}: ${e[a]}`)}return n.join(`
`)}const Pd=new re;function mM(i){xe._getMatrix(Pd,xe.workingColorSpace,i);const t=`mat3( ${Pd.elements.map(e=>e.toFixed(4))} )`;switch(xe.getTransfer(i)){case Wo:return[t,"LinearTransferOETF"];case Le:return[t,"sRGBTransferOETF"];default:return jt("WebGLProgram: Unsupported color space: ",i),[t,"LinearTransferOETF"]}}function Ld(i,t,e){const n=i.getShaderParameter(t,i.COMPILE_STATUS),r=(i.getShaderInfoLog(t)||"").trim();if(n&&r==="")return"";const a=/ERROR: 0:(\d+)/.exec(r);if(a){const o=parseInt(a[1]);return e.toUpperCase()+`

`+r+`

`+pM(i.getShaderSource(t),o)}else return r}function gM(i,t){const e=mM(t);return[`vec4 ${i}( vec4 value ) {`,`	return ${e[1]}( vec4( ${e[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}const _M={[ep]:"Linear",[np]:"Reinhard",[ip]:"Cineon",[sp]:"ACESFilmic",[ap]:"AgX",[op]:"Neutral",[rp]:"Custom"};function vM(i,t){const e=_M[t];return e===void 0?(jt("WebGLProgram: Unsupported toneMapping:",t),"vec3 "+i+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+i+"( vec3 color ) { return "+e+"ToneMapping( color ); }"}const bo=new k;function xM(){xe.getLuminanceCoefficients(bo);const i=bo.x.toFixed(4),t=bo.y.toFixed(4),e=bo.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${i}, ${t}, ${e} );`,"	return dot( weights, rgb );","}"].join(`
`)}function SM(i){return[i.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",i.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(ga).join(`
`)}function MM(i){const t=[];for(const e in i){const n=i[e];n!==!1&&t.push("#define "+e+" "+n)}return t.join(`
`)}function yM(i,t){const e={},n=i.getProgramParameter(t,i.ACTIVE_ATTRIBUTES);for(let s=0;s<n;s++){const r=i.getActiveAttrib(t,s),a=r.name;let o=1;r.type===i.FLOAT_MAT2&&(o=2),r.type===i.FLOAT_MAT3&&(o=3),r.type===i.FLOAT_MAT4&&(o=4),e[a]={type:r.type,location:i.getAttribLocation(t,a),locationSize:o}}return e}function ga(i){return i!==""}function Dd(i,t){const e=t.numSpotLightShadows+t.numSpotLightMaps-t.numSpotLightShadowsWithMaps;return i.replace(/NUM_SUN_LIGHTS/g,t.numSunLights).replace(/NUM_DIR_LIGHTS/g,t.numDirLights).replace(/NUM_SPOT_LIGHTS/g,t.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,t.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,e).replace(/NUM_RECT_AREA_LIGHTS/g,t.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,t.numPointLights).replace(/NUM_HEMI_LIGHTS/g,t.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,t.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,t.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,t.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,t.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,t.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,t.numLightProbeGrids)}function Nd(i,t){return i.replace(/NUM_CLIPPING_PLANES/g,t.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,t.numClippingPlanes-t.numClipIntersection)}const bM=/^[ \t]*#include +<([\w\d./]+)>/gm;function fh(i){return i.replace(bM,EM)}function EM(i,t){const e=le[t];if(e===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+t+">");return fh(e)}const wM=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function Id(i){return i.replace(wM,TM)}function TM(i,t,e,n){let s="";for(let r=parseInt(t);r<parseInt(e);r++)s+=n.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function Ud(i){let t=`precision ${i.precision} float;
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
	`;return i.precision==="highp"?t+=`
#define HIGH_PRECISION`:i.precision==="mediump"?t+=`
#define MEDIUM_PRECISION`:i.precision==="lowp"&&(t+=`
#define LOW_PRECISION`),t}const AM={[No]:"SHADOWMAP_TYPE_PCF",[ma]:"SHADOWMAP_TYPE_VSM"};function RM(i){return AM[i.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}const CM={[Pa]:"ENVMAP_MODE_REFRACTION"};function PM(i){return i.envMap===!1?"ENVMAP_MODE_REFLECTION":CM[i.envMapMode]||"ENVMAP_MODE_REFLECTION"}const LM={[tp]:"ENVMAP_BLENDING_MULTIPLY",[m0]:"ENVMAP_BLENDING_MIX",[g0]:"ENVMAP_BLENDING_ADD"};function DM(i){return i.envMap===!1?"ENVMAP_BLENDING_NONE":LM[i.combine]||"ENVMAP_BLENDING_NONE"}function NM(i,t,e,n){const s=i.getContext(),r=e.defines;let a=e.vertexShader,o=e.fragmentShader;const l=RM(e),c=e.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=PM(e),u=DM(e),d=SM(e),m=MM(r),_=s.createProgram();let M,p,f=e.glslVersion?"#version "+e.glslVersion+`
`:"";e.isRawShaderMaterial?(M=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,m].filter(ga).join(`
`),M.length>0&&(M+=`
`),p=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,m].filter(ga).join(`
`),p.length>0&&(p+=`
`)):(M=[Ud(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,m,e.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",e.batching?"#define USE_BATCHING":"",e.batchingColor?"#define USE_BATCHING_COLOR":"",e.instancing?"#define USE_INSTANCING":"",e.instancingColor?"#define USE_INSTANCING_COLOR":"",e.instancingMorph?"#define USE_INSTANCING_MORPH":"",e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.map?"#define USE_MAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+h:"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.displacementMap?"#define USE_DISPLACEMENTMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.mapUv?"#define MAP_UV "+e.mapUv:"",e.alphaMapUv?"#define ALPHAMAP_UV "+e.alphaMapUv:"",e.lightMapUv?"#define LIGHTMAP_UV "+e.lightMapUv:"",e.aoMapUv?"#define AOMAP_UV "+e.aoMapUv:"",e.emissiveMapUv?"#define EMISSIVEMAP_UV "+e.emissiveMapUv:"",e.bumpMapUv?"#define BUMPMAP_UV "+e.bumpMapUv:"",e.normalMapUv?"#define NORMALMAP_UV "+e.normalMapUv:"",e.displacementMapUv?"#define DISPLACEMENTMAP_UV "+e.displacementMapUv:"",e.metalnessMapUv?"#define METALNESSMAP_UV "+e.metalnessMapUv:"",e.roughnessMapUv?"#define ROUGHNESSMAP_UV "+e.roughnessMapUv:"",e.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+e.anisotropyMapUv:"",e.clearcoatMapUv?"#define CLEARCOATMAP_UV "+e.clearcoatMapUv:"",e.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+e.clearcoatNormalMapUv:"",e.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+e.clearcoatRoughnessMapUv:"",e.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+e.diffuseRoughnessMapUv:"",e.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+e.iridescenceMapUv:"",e.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+e.iridescenceThicknessMapUv:"",e.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+e.sheenColorMapUv:"",e.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+e.sheenRoughnessMapUv:"",e.specularMapUv?"#define SPECULARMAP_UV "+e.specularMapUv:"",e.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+e.specularColorMapUv:"",e.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+e.specularIntensityMapUv:"",e.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+e.transmissionMapUv:"",e.thicknessMapUv?"#define THICKNESSMAP_UV "+e.thicknessMapUv:"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexNormals?"#define HAS_NORMAL":"",e.vertexColors?"#define USE_COLOR":"",e.vertexAlphas?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.flatShading?"#define FLAT_SHADED":"",e.skinning?"#define USE_SKINNING":"",e.morphTargets?"#define USE_MORPHTARGETS":"",e.morphNormals&&e.flatShading===!1?"#define USE_MORPHNORMALS":"",e.morphColors?"#define USE_MORPHCOLORS":"",e.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+e.morphTextureStride:"",e.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+e.morphTargetsCount:"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+l:"",e.sizeAttenuation?"#define USE_SIZEATTENUATION":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(ga).join(`
`),p=[Ud(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,m,e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",e.map?"#define USE_MAP":"",e.matcap?"#define USE_MATCAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+c:"",e.envMap?"#define "+h:"",e.envMap?"#define "+u:"",e.envMapPMREM?"#define ENVMAP_MAX_LOD "+e.envMapMaxLod+".0":"",e.envMapPMREM?"#define ENVMAP_SIZE "+e.envMapSize+".0":"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoat?"#define USE_CLEARCOAT":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.dispersion?"#define USE_DISPERSION":"",e.retroreflection?"#define USE_RETROREFLECTION":"",e.iridescence?"#define USE_IRIDESCENCE":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaTest?"#define USE_ALPHATEST":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.sheen?"#define USE_SHEEN":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexColors||e.instancingColor?"#define USE_COLOR":"",e.vertexAlphas||e.batchingColor?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.gradientMap?"#define USE_GRADIENTMAP":"",e.flatShading?"#define FLAT_SHADED":"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+l:"",e.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",e.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",e.toneMapping!==os?"#define TONE_MAPPING":"",e.toneMapping!==os?le.tonemapping_pars_fragment:"",e.toneMapping!==os?vM("toneMapping",e.toneMapping):"",e.dithering?"#define DITHERING":"",e.opaque?"#define OPAQUE":"",le.colorspace_pars_fragment,gM("linearToOutputTexel",e.outputColorSpace),xM(),e.useDepthPacking?"#define DEPTH_PACKING "+e.depthPacking:"",`
`].filter(ga).join(`
`)),a=fh(a),a=Dd(a,e),a=Nd(a,e),o=fh(o),o=Dd(o,e),o=Nd(o,e),a=Id(a),o=Id(o),e.isRawShaderMaterial!==!0&&(f=`#version 300 es
`,M=[d,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+M,p=["#define varying in",e.glslVersion===Ou?"":"layout(location = 0) out highp vec4 pc_fragColor;",e.glslVersion===Ou?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+p);const x=f+M+a,A=f+p+o,S=Cd(s,s.VERTEX_SHADER,x),R=Cd(s,s.FRAGMENT_SHADER,A);s.attachShader(_,S),s.attachShader(_,R),e.index0AttributeName!==void 0?s.bindAttribLocation(_,0,e.index0AttributeName):e.hasPositionAttribute===!0&&s.bindAttribLocation(_,0,"position"),s.linkProgram(_);function b(I){if(i.debug.checkShaderErrors){const L=s.getProgramInfoLog(_)||"",V=s.getShaderInfoLog(S)||"",$=s.getShaderInfoLog(R)||"",N=L.trim(),W=V.trim(),J=$.trim();let H=!0,ct=!0;if(s.getProgramParameter(_,s.LINK_STATUS)===!1)if(H=!1,typeof i.debug.onShaderError=="function")i.debug.onShaderError(s,_,S,R);else{const Z=Ld(s,S,"vertex"),tt=Ld(s,R,"fragment");Se("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(_,s.VALIDATE_STATUS)+`

Material Name: `+I.name+`
Material Type: `+I.type+`

Program Info Log: `+N+`
`+Z+`
`+tt)}else N!==""?jt("WebGLProgram: Program Info Log:",N):(W===""||J==="")&&(ct=!1);ct&&(I.diagnostics={runnable:H,programLog:N,vertexShader:{log:W,prefix:M},fragmentShader:{log:J,prefix:p}})}s.deleteShader(S),s.deleteShader(R),g=new zo(s,_),w=yM(s,_)}let g;this.getUniforms=function(){return g===void 0&&b(this),g};let w;this.getAttributes=function(){return w===void 0&&b(this),w};let z=e.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return z===!1&&(z=s.getProgramParameter(_,dM)),z},this.destroy=function(){n.releaseStatesOfProgram(this),s.deleteProgram(_),this.program=void 0},this.type=e.shaderType,this.name=e.shaderName,this.id=fM++,this.cacheKey=t,this.usedTimes=1,this.program=_,this.vertexShader=S,this.fragmentShader=R,this}let IM=0;class UM{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(t,e,n){const s=this._getShaderCacheForMaterial(t);return s.has(e)===!1&&(s.add(e),e.usedTimes++),s.has(n)===!1&&(s.add(n),n.usedTimes++),this}remove(t){const e=this.materialCache.get(t);for(const n of e)n.usedTimes--,n.usedTimes===0&&this.shaderCache.delete(n.code);return this.materialCache.delete(t),this}getVertexShaderStage(t){return this._getShaderStage(t.vertexShader)}getFragmentShaderStage(t){return this._getShaderStage(t.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(t){const e=this.materialCache;let n=e.get(t);return n===void 0&&(n=new Set,e.set(t,n)),n}_getShaderStage(t){const e=this.shaderCache;let n=e.get(t);return n===void 0&&(n=new FM(t),e.set(t,n)),n}}class FM{constructor(t){this.id=IM++,this.code=t,this.usedTimes=0}}function OM(i){return i===Ks||i===Ho||i===Go}function BM(i,t,e,n,s,r){const a=new Vh,o=new UM,l=new Set,c=[],h=new Map,u=n.logarithmicDepthBuffer,d={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function m(g){return l.add(g),g===0?"uv":`uv${g}`}function _(g,w,z,I,L,V){const $=I.fog,N=L.geometry,W=g.isMeshStandardMaterial||g.isMeshLambertMaterial||g.isMeshPhongMaterial?I.environment:null,J=g.isMeshStandardMaterial||g.isMeshLambertMaterial&&!g.envMap||g.isMeshPhongMaterial&&!g.envMap,H=t.get(g.envMap||W,J),ct=d[g.type];let Z=n.precision;g.precision!==null&&(Z=n.getMaxPrecision(g.precision),Z!==g.precision&&jt("WebGLProgram.getParameters:",g.precision,"not supported, using",Z,"instead."));const tt=N.morphAttributes.position||N.morphAttributes.normal||N.morphAttributes.color,st=tt!==void 0?tt.length:0;let pt=0;N.morphAttributes.position!==void 0&&(pt=1),N.morphAttributes.normal!==void 0&&(pt=2),N.morphAttributes.color!==void 0&&(pt=3);let ft,B,et,ht;if(ct){const Rt=ki[ct];ft=Rt.vertexShader,B=Rt.fragmentShader}else{ft=g.vertexShader,B=g.fragmentShader;const Rt=o.getVertexShaderStage(g),ae=o.getFragmentShaderStage(g);o.update(g,Rt,ae),et=Rt.id,ht=ae.id}const gt=i.getRenderTarget(),vt=i.state.buffers.depth.getReversed(),Gt=L.isInstancedMesh===!0,Qt=L.isBatchedMesh===!0,kt=!!g.map,ne=!!g.matcap,ee=!!H,qt=ee&&H.isPMREMTexture===!0,Ie=!!g.aoMap,me=!!g.lightMap,Xe=!!g.bumpMap&&g.wireframe===!1,Me=!!g.normalMap,rn=!!g.displacementMap,de=!!g.emissiveMap,pn=!!g.metalnessMap,qe=!!g.roughnessMap,an=g.anisotropy>0,F=g.clearcoat>0,Ct=g.diffuseRoughness>0,Yt=g.dispersion>0,se=g.retroreflectivity>0,Et=g.iridescence>0,Ue=g.sheen>0,Ht=g.transmission>0,$t=an&&!!g.anisotropyMap,C=F&&!!g.clearcoatMap,y=F&&!!g.clearcoatNormalMap,Y=F&&!!g.clearcoatRoughnessMap,dt=Ct&&!!g.diffuseRoughnessMap,ot=Et&&!!g.iridescenceMap,St=Et&&!!g.iridescenceThicknessMap,Mt=Ue&&!!g.sheenColorMap,nt=Ue&&!!g.sheenRoughnessMap,rt=!!g.specularMap,_t=!!g.specularColorMap,U=!!g.specularIntensityMap,at=Ht&&!!g.transmissionMap,it=Ht&&!!g.thicknessMap,wt=!!g.gradientMap,xt=!!g.alphaMap,bt=g.alphaTest>0,Vt=!!g.alphaHash,Zt=!!g.extensions;let ut=os;g.toneMapped&&(gt===null||gt.isXRRenderTarget===!0)&&(ut=i.toneMapping);const Ot=qt?H.isCompressedCubeTexture?H.image[0].mipmaps:H.mipmaps:null,Jt={shaderID:ct,shaderType:g.type,shaderName:g.name,vertexShader:ft,fragmentShader:B,defines:g.defines,customVertexShaderID:et,customFragmentShaderID:ht,isRawShaderMaterial:g.isRawShaderMaterial===!0,glslVersion:g.glslVersion,precision:Z,batching:Qt,batchingColor:Qt&&L._colorsTexture!==null,instancing:Gt,instancingColor:Gt&&L.instanceColor!==null,instancingMorph:Gt&&L.morphTexture!==null,outputColorSpace:gt===null?i.outputColorSpace:gt.isXRRenderTarget===!0?gt.texture.colorSpace:xe.workingColorSpace,alphaToCoverage:!!g.alphaToCoverage,map:kt,matcap:ne,envMap:ee,envMapMode:ee&&H.mapping,envMapPMREM:qt,envMapMaxLod:qt?Ot.length-1:null,envMapSize:qt?Ot[0].width:null,aoMap:Ie,lightMap:me,bumpMap:Xe,normalMap:Me,displacementMap:rn,emissiveMap:de,normalMapObjectSpace:Me&&g.normalMapType===x0,normalMapTangentSpace:Me&&g.normalMapType===ch,packedNormalMap:Me&&g.normalMapType===ch&&OM(g.normalMap.format),metalnessMap:pn,roughnessMap:qe,anisotropy:an,anisotropyMap:$t,clearcoat:F,clearcoatMap:C,clearcoatNormalMap:y,clearcoatRoughnessMap:Y,diffuseRoughness:Ct,diffuseRoughnessMap:dt,dispersion:Yt,retroreflection:se,iridescence:Et,iridescenceMap:ot,iridescenceThicknessMap:St,sheen:Ue,sheenColorMap:Mt,sheenRoughnessMap:nt,specularMap:rt,specularColorMap:_t,specularIntensityMap:U,transmission:Ht,transmissionMap:at,thicknessMap:it,gradientMap:wt,opaque:g.transparent===!1&&g.blending===Ma&&g.alphaToCoverage===!1,alphaMap:xt,alphaTest:bt,alphaHash:Vt,combine:g.combine,mapUv:kt&&m(g.map.channel),aoMapUv:Ie&&m(g.aoMap.channel),lightMapUv:me&&m(g.lightMap.channel),bumpMapUv:Xe&&m(g.bumpMap.channel),normalMapUv:Me&&m(g.normalMap.channel),displacementMapUv:rn&&m(g.displacementMap.channel),emissiveMapUv:de&&m(g.emissiveMap.channel),metalnessMapUv:pn&&m(g.metalnessMap.channel),roughnessMapUv:qe&&m(g.roughnessMap.channel),anisotropyMapUv:$t&&m(g.anisotropyMap.channel),clearcoatMapUv:C&&m(g.clearcoatMap.channel),clearcoatNormalMapUv:y&&m(g.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:Y&&m(g.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:dt&&m(g.diffuseRoughnessMap.channel),iridescenceMapUv:ot&&m(g.iridescenceMap.channel),iridescenceThicknessMapUv:St&&m(g.iridescenceThicknessMap.channel),sheenColorMapUv:Mt&&m(g.sheenColorMap.channel),sheenRoughnessMapUv:nt&&m(g.sheenRoughnessMap.channel),specularMapUv:rt&&m(g.specularMap.channel),specularColorMapUv:_t&&m(g.specularColorMap.channel),specularIntensityMapUv:U&&m(g.specularIntensityMap.channel),transmissionMapUv:at&&m(g.transmissionMap.channel),thicknessMapUv:it&&m(g.thicknessMap.channel),alphaMapUv:xt&&m(g.alphaMap.channel),vertexTangents:!!N.attributes.tangent&&(Me||an),vertexNormals:!!N.attributes.normal,vertexColors:g.vertexColors,vertexAlphas:g.vertexColors===!0&&!!N.attributes.color&&N.attributes.color.itemSize===4,pointsUvs:L.isPoints===!0&&!!N.attributes.uv&&(kt||xt),fog:!!$,useFog:g.fog===!0,fogExp2:!!$&&$.isFogExp2,flatShading:g.wireframe===!1&&(g.flatShading===!0||N.attributes.normal===void 0&&Me===!1&&(g.isMeshLambertMaterial||g.isMeshPhongMaterial||g.isMeshStandardMaterial||g.isMeshPhysicalMaterial)),sizeAttenuation:g.sizeAttenuation===!0,logarithmicDepthBuffer:u,reversedDepthBuffer:vt,skinning:L.isSkinnedMesh===!0,hasPositionAttribute:N.attributes.position!==void 0,morphTargets:N.morphAttributes.position!==void 0,morphNormals:N.morphAttributes.normal!==void 0,morphColors:N.morphAttributes.color!==void 0,morphTargetsCount:st,morphTextureStride:pt,numSunLights:w.sun.length,numDirLights:w.directional.length,numPointLights:w.point.length,numSpotLights:w.spot.length,numSpotLightMaps:w.spotLightMap.length,numRectAreaLights:w.rectArea.length,numHemiLights:w.hemi.length,numSunLightShadows:w.sunShadowMap.length,numDirLightShadows:w.directionalShadowMap.length,numPointLightShadows:w.pointShadowMap.length,numSpotLightShadows:w.spotShadowMap.length,numSpotLightShadowsWithMaps:w.numSpotLightShadowsWithMaps,numLightProbes:w.numLightProbes,numLightProbeGrids:V.filter(Rt=>Rt.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:g.dithering,shadowMapEnabled:i.shadowMap.enabled&&z.length>0,shadowMapType:i.shadowMap.type,toneMapping:ut,decodeVideoTexture:kt&&g.map.isVideoTexture===!0&&xe.getTransfer(g.map.colorSpace)===Le,decodeVideoTextureEmissive:de&&g.emissiveMap.isVideoTexture===!0&&xe.getTransfer(g.emissiveMap.colorSpace)===Le,premultipliedAlpha:g.premultipliedAlpha,doubleSided:g.side===di,flipSided:g.side===Yn,useDepthPacking:g.depthPacking>=0,depthPacking:g.depthPacking||0,index0AttributeName:g.index0AttributeName,extensionClipCullDistance:Zt&&g.extensions.clipCullDistance===!0&&e.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Zt&&g.extensions.multiDraw===!0||Qt)&&e.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:e.has("KHR_parallel_shader_compile"),customProgramCacheKey:g.customProgramCacheKey()};return Jt.vertexUv1s=l.has(1),Jt.vertexUv2s=l.has(2),Jt.vertexUv3s=l.has(3),l.clear(),Jt}function M(g){const w=[];if(g.shaderID?w.push(g.shaderID):(w.push(g.customVertexShaderID),w.push(g.customFragmentShaderID)),g.defines!==void 0)for(const z in g.defines)w.push(z),w.push(g.defines[z]);return g.isRawShaderMaterial===!1&&(p(w,g),f(w,g),w.push(i.outputColorSpace)),w.push(g.customProgramCacheKey),w.join()}function p(g,w){g.push(w.precision),g.push(w.outputColorSpace),g.push(w.envMapMode),g.push(w.envMapPMREM),g.push(w.envMapMaxLod),g.push(w.envMapSize),g.push(w.mapUv),g.push(w.alphaMapUv),g.push(w.lightMapUv),g.push(w.aoMapUv),g.push(w.bumpMapUv),g.push(w.normalMapUv),g.push(w.displacementMapUv),g.push(w.emissiveMapUv),g.push(w.metalnessMapUv),g.push(w.roughnessMapUv),g.push(w.anisotropyMapUv),g.push(w.clearcoatMapUv),g.push(w.clearcoatNormalMapUv),g.push(w.clearcoatRoughnessMapUv),g.push(w.diffuseRoughnessMapUv),g.push(w.iridescenceMapUv),g.push(w.iridescenceThicknessMapUv),g.push(w.sheenColorMapUv),g.push(w.sheenRoughnessMapUv),g.push(w.specularMapUv),g.push(w.specularColorMapUv),g.push(w.specularIntensityMapUv),g.push(w.transmissionMapUv),g.push(w.thicknessMapUv),g.push(w.combine),g.push(w.fogExp2),g.push(w.sizeAttenuation),g.push(w.morphTargetsCount),g.push(w.numSunLights),g.push(w.numDirLights),g.push(w.numPointLights),g.push(w.numSpotLights),g.push(w.numSpotLightMaps),g.push(w.numHemiLights),g.push(w.numRectAreaLights),g.push(w.numSunLightShadows),g.push(w.numDirLightShadows),g.push(w.numPointLightShadows),g.push(w.numSpotLightShadows),g.push(w.numSpotLightShadowsWithMaps),g.push(w.numLightProbes),g.push(w.numLightProbeGrids),g.push(w.shadowMapType),g.push(w.toneMapping),g.push(w.numClippingPlanes),g.push(w.numClipIntersection),g.push(w.depthPacking)}function f(g,w){a.disableAll(),w.instancing&&a.enable(0),w.instancingColor&&a.enable(1),w.instancingMorph&&a.enable(2),w.matcap&&a.enable(3),w.envMap&&a.enable(4),w.normalMapObjectSpace&&a.enable(5),w.normalMapTangentSpace&&a.enable(6),w.clearcoat&&a.enable(7),w.iridescence&&a.enable(8),w.alphaTest&&a.enable(9),w.vertexColors&&a.enable(10),w.vertexAlphas&&a.enable(11),w.vertexUv1s&&a.enable(12),w.vertexUv2s&&a.enable(13),w.vertexUv3s&&a.enable(14),w.vertexTangents&&a.enable(15),w.anisotropy&&a.enable(16),w.alphaHash&&a.enable(17),w.batching&&a.enable(18),w.dispersion&&a.enable(19),w.retroreflection&&a.enable(24),w.diffuseRoughness&&a.enable(25),w.batchingColor&&a.enable(20),w.gradientMap&&a.enable(21),w.packedNormalMap&&a.enable(22),w.vertexNormals&&a.enable(23),g.push(a.mask),a.disableAll(),w.fog&&a.enable(0),w.useFog&&a.enable(1),w.flatShading&&a.enable(2),w.logarithmicDepthBuffer&&a.enable(3),w.reversedDepthBuffer&&a.enable(4),w.skinning&&a.enable(5),w.morphTargets&&a.enable(6),w.morphNormals&&a.enable(7),w.morphColors&&a.enable(8),w.premultipliedAlpha&&a.enable(9),w.shadowMapEnabled&&a.enable(10),w.doubleSided&&a.enable(11),w.flipSided&&a.enable(12),w.useDepthPacking&&a.enable(13),w.dithering&&a.enable(14),w.transmission&&a.enable(15),w.sheen&&a.enable(16),w.opaque&&a.enable(17),w.pointsUvs&&a.enable(18),w.decodeVideoTexture&&a.enable(19),w.decodeVideoTextureEmissive&&a.enable(20),w.alphaToCoverage&&a.enable(21),w.numLightProbeGrids>0&&a.enable(22),w.hasPositionAttribute&&a.enable(23),g.push(a.mask)}function x(g){const w=d[g.type];let z;if(w){const I=ki[w];z=r_.clone(I.uniforms)}else z=g.uniforms;return z}function A(g,w){let z=h.get(w);return z!==void 0?++z.usedTimes:(z=new NM(i,w,g,s),c.push(z),h.set(w,z)),z}function S(g){if(--g.usedTimes===0){const w=c.indexOf(g);c[w]=c[c.length-1],c.pop(),h.delete(g.cacheKey),g.destroy()}}function R(g){o.remove(g)}function b(){o.dispose()}return{getParameters:_,getProgramCacheKey:M,getUniforms:x,acquireProgram:A,releaseProgram:S,releaseShaderCache:R,programs:c,dispose:b}}function zM(){let i=new WeakMap;function t(a){return i.has(a)}function e(a){let o=i.get(a);return o===void 0&&(o={},i.set(a,o)),o}function n(a){i.delete(a)}function s(a,o,l){i.get(a)[o]=l}function r(){i=new WeakMap}return{has:t,get:e,remove:n,update:s,dispose:r}}function kM(i,t){return i.groupOrder!==t.groupOrder?i.groupOrder-t.groupOrder:i.renderOrder!==t.renderOrder?i.renderOrder-t.renderOrder:i.material.id!==t.material.id?i.material.id-t.material.id:i.materialVariant!==t.materialVariant?i.materialVariant-t.materialVariant:i.z!==t.z?i.z-t.z:i.id-t.id}function Fd(i,t){return i.groupOrder!==t.groupOrder?i.groupOrder-t.groupOrder:i.renderOrder!==t.renderOrder?i.renderOrder-t.renderOrder:i.z!==t.z?t.z-i.z:i.id-t.id}function Od(){const i=[];let t=0;const e=[],n=[],s=[];function r(){t=0,e.length=0,n.length=0,s.length=0}function a(d){let m=0;return d.isInstancedMesh&&(m+=2),d.isSkinnedMesh&&(m+=1),m}function o(d,m,_,M,p,f){let x=i[t];return x===void 0?(x={id:d.id,object:d,geometry:m,material:_,materialVariant:a(d),groupOrder:M,renderOrder:d.renderOrder,z:p,group:f},i[t]=x):(x.id=d.id,x.object=d,x.geometry=m,x.material=_,x.materialVariant=a(d),x.groupOrder=M,x.renderOrder=d.renderOrder,x.z=p,x.group=f),t++,x}function l(d,m,_,M,p,f,x){x.reversedDepth===!0&&(p=-p);const A=o(d,m,_,M,p,f);_.transmission>0?n.push(A):_.transparent===!0?s.push(A):e.push(A)}function c(d,m,_,M,p,f){const x=o(d,m,_,M,p,f);_.transmission>0?n.unshift(x):_.transparent===!0?s.unshift(x):e.unshift(x)}function h(d,m){e.length>1&&e.sort(d||kM),n.length>1&&n.sort(m||Fd),s.length>1&&s.sort(m||Fd)}function u(){for(let d=t,m=i.length;d<m;d++){const _=i[d];if(_.id===null)break;_.id=null,_.object=null,_.geometry=null,_.material=null,_.group=null}}return{opaque:e,transmissive:n,transparent:s,init:r,push:l,unshift:c,finish:u,sort:h}}function HM(){let i=new WeakMap;function t(n,s){const r=i.get(n);let a;return r===void 0?(a=new Od,i.set(n,[a])):s>=r.length?(a=new Od,r.push(a)):a=r[s],a}function e(){i=new WeakMap}return{get:t,dispose:e}}function GM(){const i={};return{get:function(t){if(i[t.id]!==void 0)return i[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={direction:new k,color:new ce};break;case"SpotLight":e={position:new k,direction:new k,color:new ce,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":e={position:new k,color:new ce,distance:0,decay:0};break;case"HemisphereLight":e={direction:new k,skyColor:new ce,groundColor:new ce};break;case"RectAreaLight":e={color:new ce,position:new k,halfWidth:new k,halfHeight:new k};break}return i[t.id]=e,e}}}function VM(){const i={};return{get:function(t){if(i[t.id]!==void 0)return i[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Xt};break;case"SpotLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Xt};break;case"PointLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Xt,shadowCameraNear:1,shadowCameraFar:1e3};break}return i[t.id]=e,e}}}let WM=0;function XM(i,t){return(t.castShadow?2:0)-(i.castShadow?2:0)+(t.map?1:0)-(i.map?1:0)}function $M(i){const t=new GM,e=VM(),n={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let c=0;c<9;c++)n.probe.push(new k);const s=new k,r=new De,a=new De;function o(c){let h=0,u=0,d=0;for(let V=0;V<9;V++)n.probe[V].set(0,0,0);let m=0,_=0,M=0,p=0,f=0,x=0,A=0,S=0,R=0,b=0,g=0,w=0,z=0,I=0;c.sort(XM);for(let V=0,$=c.length;V<$;V++){const N=c[V],W=N.color,J=N.intensity,H=N.distance;let ct=null;if(N.shadow&&N.shadow.map&&(N.shadow.map.texture.format===Ks?ct=N.shadow.map.texture:ct=N.shadow.map.depthTexture||N.shadow.map.texture),N.isAmbientLight)h+=W.r*J,u+=W.g*J,d+=W.b*J;else if(N.isLightProbe){for(let Z=0;Z<9;Z++)n.probe[Z].addScaledVector(N.sh.coefficients[Z],J);I++}else if(N.isSunLight){const Z=t.get(N);if(Z.color.copy(N.color).multiplyScalar(N.intensity),N.castShadow){const tt=N.shadow,st=e.get(N);st.shadowIntensity=tt.intensity,st.shadowBias=tt.bias,st.shadowNormalBias=tt.normalBias,st.shadowRadius=tt.radius,st.shadowMapSize.copy(tt.mapSize).multiply(tt.getFrameExtents()),n.sunShadow[_]=st,n.sunShadowMap[_]=ct;const pt=tt.getViewportCount();for(let ft=0;ft<pt;ft++)n.sunShadowMatrix[M+ft]=tt.getMatrix(ft),n.sunShadowCascade[M+ft]=tt._cascadeData[ft];M+=pt,_++}n.sun[m]=Z,m++}else if(N.isDirectionalLight){const Z=t.get(N);if(Z.color.copy(N.color).multiplyScalar(N.intensity),N.castShadow){const tt=N.shadow,st=e.get(N);st.shadowIntensity=tt.intensity,st.shadowBias=tt.bias,st.shadowNormalBias=tt.normalBias,st.shadowRadius=tt.radius,st.shadowMapSize=tt.mapSize,n.directionalShadow[p]=st,n.directionalShadowMap[p]=ct,n.directionalShadowMatrix[p]=N.shadow.matrix,R++}n.directional[p]=Z,p++}else if(N.isSpotLight){const Z=t.get(N);Z.position.setFromMatrixPosition(N.matrixWorld),Z.color.copy(W).multiplyScalar(J),Z.distance=H,Z.coneCos=Math.cos(N.angle),Z.penumbraCos=Math.cos(N.angle*(1-N.penumbra)),Z.decay=N.decay,n.spot[x]=Z;const tt=N.shadow;if(N.map&&(n.spotLightMap[w]=N.map,w++,tt.updateMatrices(N),N.castShadow&&z++),n.spotLightMatrix[x]=tt.matrix,N.castShadow){const st=e.get(N);st.shadowIntensity=tt.intensity,st.shadowBias=tt.bias,st.shadowNormalBias=tt.normalBias,st.shadowRadius=tt.radius,st.shadowMapSize=tt.mapSize,n.spotShadow[x]=st,n.spotShadowMap[x]=ct,g++}x++}else if(N.isRectAreaLight){const Z=t.get(N);Z.color.copy(W).multiplyScalar(J),Z.halfWidth.set(N.width*.5,0,0),Z.halfHeight.set(0,N.height*.5,0),n.rectArea[A]=Z,A++}else if(N.isPointLight){const Z=t.get(N);if(Z.color.copy(N.color).multiplyScalar(N.intensity),Z.distance=N.distance,Z.decay=N.decay,N.castShadow){const tt=N.shadow,st=e.get(N);st.shadowIntensity=tt.intensity,st.shadowBias=tt.bias,st.shadowNormalBias=tt.normalBias,st.shadowRadius=tt.radius,st.shadowMapSize=tt.mapSize,st.shadowCameraNear=tt.camera.near,st.shadowCameraFar=tt.camera.far,n.pointShadow[f]=st,n.pointShadowMap[f]=ct,n.pointShadowMatrix[f]=N.shadow.matrix,b++}n.point[f]=Z,f++}else if(N.isHemisphereLight){const Z=t.get(N);Z.skyColor.copy(N.color).multiplyScalar(J),Z.groundColor.copy(N.groundColor).multiplyScalar(J),n.hemi[S]=Z,S++}}A>0&&(i.has("OES_texture_float_linear")===!0?(n.rectAreaLTC1=Dt.LTC_FLOAT_1,n.rectAreaLTC2=Dt.LTC_FLOAT_2):(n.rectAreaLTC1=Dt.LTC_HALF_1,n.rectAreaLTC2=Dt.LTC_HALF_2)),n.ambient[0]=h,n.ambient[1]=u,n.ambient[2]=d;const L=n.hash;(L.sunLength!==m||L.directionalLength!==p||L.pointLength!==f||L.spotLength!==x||L.rectAreaLength!==A||L.hemiLength!==S||L.numSunShadows!==_||L.numDirectionalShadows!==R||L.numPointShadows!==b||L.numSpotShadows!==g||L.numSpotMaps!==w||L.numLightProbes!==I)&&(n.sun.length=m,n.directional.length=p,n.spot.length=x,n.rectArea.length=A,n.point.length=f,n.hemi.length=S,n.sunShadow.length=_,n.sunShadowMap.length=_,n.sunShadowMatrix.length=M,n.sunShadowCascade.length=M,n.directionalShadow.length=R,n.directionalShadowMap.length=R,n.directionalShadowMatrix.length=R,n.pointShadow.length=b,n.pointShadowMap.length=b,n.pointShadowMatrix.length=b,n.spotShadow.length=g,n.spotShadowMap.length=g,n.spotLightMatrix.length=g+w-z,n.spotLightMap.length=w,n.numSpotLightShadowsWithMaps=z,n.numLightProbes=I,L.sunLength=m,L.directionalLength=p,L.pointLength=f,L.spotLength=x,L.rectAreaLength=A,L.hemiLength=S,L.numSunShadows=_,L.numDirectionalShadows=R,L.numPointShadows=b,L.numSpotShadows=g,L.numSpotMaps=w,L.numLightProbes=I,n.version=WM++)}function l(c,h){let u=0,d=0,m=0,_=0,M=0,p=0;const f=h.matrixWorldInverse;for(let x=0,A=c.length;x<A;x++){const S=c[x];if(S.isSunLight){const R=n.sun[u];R.direction.setFromMatrixPosition(S.matrixWorld),R.direction.transformDirection(f),u++}else if(S.isDirectionalLight){const R=n.directional[d];R.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),R.direction.sub(s),R.direction.transformDirection(f),d++}else if(S.isSpotLight){const R=n.spot[_];R.position.setFromMatrixPosition(S.matrixWorld),R.position.applyMatrix4(f),R.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),R.direction.sub(s),R.direction.transformDirection(f),_++}else if(S.isRectAreaLight){const R=n.rectArea[M];R.position.setFromMatrixPosition(S.matrixWorld),R.position.applyMatrix4(f),a.identity(),r.copy(S.matrixWorld),r.premultiply(f),a.extractRotation(r),R.halfWidth.set(S.width*.5,0,0),R.halfHeight.set(0,S.height*.5,0),R.halfWidth.applyMatrix4(a),R.halfHeight.applyMatrix4(a),M++}else if(S.isPointLight){const R=n.point[m];R.position.setFromMatrixPosition(S.matrixWorld),R.position.applyMatrix4(f),m++}else if(S.isHemisphereLight){const R=n.hemi[p];R.direction.setFromMatrixPosition(S.matrixWorld),R.direction.transformDirection(f),p++}}}return{setup:o,setupView:l,state:n}}function Bd(i){const t=new $M(i),e=[],n=[],s=[];function r(u){h.camera=u,e.length=0,n.length=0,s.length=0}function a(u){u.isLightProbeGrid?s.push(u):e.push(u)}function o(u){n.push(u)}function l(){t.setup(e),s.sort((u,d)=>u.priority-d.priority||u.id-d.id)}function c(u){t.setupView(e,u)}const h={lightsArray:e,shadowsArray:n,lightProbeGridArray:s,camera:null,lights:t,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:h,setupLights:l,setupLightsView:c,pushLight:a,pushShadow:o}}function YM(i){let t=new WeakMap;function e(s,r=0){const a=t.get(s);let o;return a===void 0?(o=new Bd(i),t.set(s,[o])):r>=a.length?(o=new Bd(i),a.push(o)):o=a[r],o}function n(){t=new WeakMap}return{get:e,dispose:n}}const qM=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,KM=`uniform sampler2D shadow_pass;
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
}`,ZM=[new k(1,0,0),new k(-1,0,0),new k(0,1,0),new k(0,-1,0),new k(0,0,1),new k(0,0,-1)],JM=[new k(0,-1,0),new k(0,-1,0),new k(0,0,1),new k(0,0,-1),new k(0,-1,0),new k(0,-1,0)],zd=new De,da=new k,sc=new k;function jM(i,t,e){let n=new Na;const s=new Xt,r=new Xt,a=new nn,o=new c_,l=new h_,c={},h=e.maxTextureSize,u={[Cs]:Yn,[Yn]:Cs,[di]:di},d=new Zs({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new Xt},radius:{value:4}},vertexShader:qM,fragmentShader:KM}),m=d.clone();m.defines.HORIZONTAL_PASS=1;const _=new Be;_.setAttribute("position",new pi(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));const M=new fn(_,d),p=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=No;let f=this.type;this.render=function(b,g,w){if(p.enabled===!1||p.autoUpdate===!1&&p.needsUpdate===!1||b.length===0)return;this.type===Zg&&(jt("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=No);const z=i.getRenderTarget(),I=i.getActiveCubeFace(),L=i.getActiveMipmapLevel(),V=i.state;V.setBlending(Ur),V.buffers.depth.getReversed()===!0?V.buffers.color.setClear(0,0,0,0):V.buffers.color.setClear(1,1,1,1),V.buffers.depth.setTest(!0),V.setScissorTest(!1);const $=f!==this.type;$&&g.traverse(function(N){N.material&&(Array.isArray(N.material)?N.material.forEach(W=>W.needsUpdate=!0):N.material.needsUpdate=!0)});for(let N=0,W=b.length;N<W;N++){const J=b[N],H=J.shadow;if(H===void 0){jt("WebGLShadowMap:",J,"has no shadow.");continue}if(H.autoUpdate===!1&&H.needsUpdate===!1)continue;s.copy(H.mapSize);const ct=H.getFrameExtents();s.multiply(ct),r.copy(H.mapSize),(s.x>h||s.y>h)&&(s.x>h&&(r.x=Math.floor(h/ct.x),s.x=r.x*ct.x,H.mapSize.x=r.x),s.y>h&&(r.y=Math.floor(h/ct.y),s.y=r.y*ct.y,H.mapSize.y=r.y));const Z=i.state.buffers.depth.getReversed();if(H.camera._reversedDepth=Z,H.map===null||$===!0){if(H.map!==null&&(H.map.depthTexture!==null&&(H.map.depthTexture.dispose(),H.map.depthTexture=null),H.map.dispose()),this.type===ma){if(J.isPointLight){jt("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}H.map=new Xi(s.x,s.y,{format:Ks,type:qi,minFilter:$n,magFilter:$n,generateMipmaps:!1}),H.map.texture.name=J.name+".shadowMap",H.map.depthTexture=new kr(s.x,s.y,Hi),H.map.depthTexture.name=J.name+".shadowMapDepth",H.map.depthTexture.format=Ps,H.map.depthTexture.compareFunction=null,H.map.depthTexture.minFilter=Pn,H.map.depthTexture.magFilter=Pn}else J.isPointLight?(H.map=new $h(s.x),H.map.depthTexture=new Dp(s.x,Yi)):(H.map=new Xi(s.x,s.y),H.map.depthTexture=new kr(s.x,s.y,Yi)),H.map.depthTexture.name=J.name+".shadowMap",H.map.depthTexture.format=Ps,this.type===No?(H.map.depthTexture.compareFunction=Z?_p:gp,H.map.depthTexture.minFilter=$n,H.map.depthTexture.magFilter=$n):(H.map.depthTexture.compareFunction=null,H.map.depthTexture.minFilter=Pn,H.map.depthTexture.magFilter=Pn);H.camera.updateProjectionMatrix()}H.map.isWebGLCubeRenderTarget!==!0&&(H.map.width!==s.x||H.map.height!==s.y)&&H.map.setSize(s.x,s.y);const tt=H.map.isWebGLCubeRenderTarget?6:H.getViewportCount();J.isPointLight!==!0&&H.updateMatrices(J,w);const st=(H.camera.layers.mask&4294967294)!==0?H.camera.layers:w.layers;for(let pt=0;pt<tt;pt++){const ft=H.getCamera(pt);if(J.isPointLight){const B=H.camera,et=H.matrix,ht=J.distance||B.far;ht!==B.far&&(B.far=ht,B.updateProjectionMatrix()),da.setFromMatrixPosition(J.matrixWorld),B.position.copy(da),sc.copy(B.position),sc.add(ZM[pt]),B.up.copy(JM[pt]),B.lookAt(sc),B.updateMatrixWorld(),et.makeTranslation(-da.x,-da.y,-da.z),zd.multiplyMatrices(B.projectionMatrix,B.matrixWorldInverse),H._frustum.setFromProjectionMatrix(zd,B.coordinateSystem,B.reversedDepth)}if(H.map.isWebGLCubeRenderTarget)i.setRenderTarget(H.map,pt),i.clear();else{pt===0&&(i.setRenderTarget(H.map),i.clear());const B=H.getViewport(pt);a.set(r.x*B.x,r.y*B.y,r.x*B.z,r.y*B.w),V.viewport(a)}n=H.getFrustum(pt),S(g,w,ft,J,st,this.type)}H.isPointLightShadow!==!0&&this.type===ma&&x(H,w),H.needsUpdate=!1}f=this.type,p.needsUpdate=!1,i.setRenderTarget(z,I,L)};function x(b,g){const w=t.update(M);d.defines.VSM_SAMPLES!==b.blurSamples&&(d.defines.VSM_SAMPLES=b.blurSamples,m.defines.VSM_SAMPLES=b.blurSamples,d.needsUpdate=!0,m.needsUpdate=!0),b.mapPass===null?b.mapPass=new Xi(s.x,s.y,{format:Ks,type:qi}):(b.mapPass.width!==b.map.width||b.mapPass.height!==b.map.height)&&b.mapPass.setSize(b.map.width,b.map.height),d.uniforms.shadow_pass.value=b.map.depthTexture,d.uniforms.resolution.value.set(b.map.width,b.map.height),d.uniforms.radius.value=b.radius,i.setRenderTarget(b.mapPass),i.clear(),i.renderBufferDirect(g,null,w,d,M,null),m.uniforms.shadow_pass.value=b.mapPass.texture,m.uniforms.resolution.value.set(b.map.width,b.map.height),m.uniforms.radius.value=b.radius,i.setRenderTarget(b.map),i.clear(),i.renderBufferDirect(g,null,w,m,M,null)}function A(b,g,w,z){let I=null;const L=w.isPointLight===!0?b.customDistanceMaterial:b.customDepthMaterial;if(L!==void 0)I=L;else if(I=w.isPointLight===!0?l:o,i.localClippingEnabled&&g.clipShadows===!0&&Array.isArray(g.clippingPlanes)&&g.clippingPlanes.length!==0||g.displacementMap&&g.displacementScale!==0||g.alphaMap&&g.alphaTest>0||g.map&&g.alphaTest>0||g.alphaToCoverage===!0){const V=I.uuid,$=g.uuid;let N=c[V];N===void 0&&(N={},c[V]=N);let W=N[$];W===void 0&&(W=I.clone(),N[$]=W,g.addEventListener("dispose",R)),I=W}if(I.visible=g.visible,I.wireframe=g.wireframe,z===ma?I.side=g.shadowSide!==null?g.shadowSide:g.side:I.side=g.shadowSide!==null?g.shadowSide:u[g.side],I.alphaMap=g.alphaMap,I.alphaTest=g.alphaToCoverage===!0?.5:g.alphaTest,I.map=g.map,I.clipShadows=g.clipShadows,I.clippingPlanes=g.clippingPlanes,I.clipIntersection=g.clipIntersection,I.displacementMap=g.displacementMap,I.displacementScale=g.displacementScale,I.displacementBias=g.displacementBias,I.wireframeLinewidth=g.wireframeLinewidth,I.linewidth=g.linewidth,w.isPointLight===!0&&I.isMeshDistanceMaterial===!0){const V=i.properties.get(I);V.light=w}return I}function S(b,g,w,z,I,L){if(b.visible===!1)return;if(b.layers.test(I)&&(b.isMesh||b.isLine||b.isPoints)&&(b.castShadow||b.receiveShadow&&L===ma)&&(!b.frustumCulled||b.intersectsFrustum(n))){b.modelViewMatrix.multiplyMatrices(w.matrixWorldInverse,b.matrixWorld);const N=t.update(b),W=b.material;if(Array.isArray(W)){const J=N.groups;for(let H=0,ct=J.length;H<ct;H++){const Z=J[H],tt=W[Z.materialIndex];if(tt&&tt.visible){const st=A(b,tt,z,L);b.onBeforeShadow(i,b,g,w,N,st,Z),i.renderBufferDirect(w,null,N,st,b,Z),b.onAfterShadow(i,b,g,w,N,st,Z)}}}else if(W.visible){const J=A(b,W,z,L);b.onBeforeShadow(i,b,g,w,N,J,null),i.renderBufferDirect(w,null,N,J,b,null),b.onAfterShadow(i,b,g,w,N,J,null)}}const $=b.children;for(let N=0,W=$.length;N<W;N++)S($[N],g,w,z,I,L)}function R(b){b.target.removeEventListener("dispose",R);for(const w in c){const z=c[w],I=b.target.uuid;I in z&&(z[I].dispose(),delete z[I])}}}function QM(i,t){function e(){let U=!1;const at=new nn;let it=null;const wt=new nn(0,0,0,0);return{setMask:function(xt){it!==xt&&!U&&(i.colorMask(xt,xt,xt,xt),it=xt)},setLocked:function(xt){U=xt},setClear:function(xt,bt,Vt,Zt,ut){ut===!0&&(xt*=Zt,bt*=Zt,Vt*=Zt),at.set(xt,bt,Vt,Zt),wt.equals(at)===!1&&(i.clearColor(xt,bt,Vt,Zt),wt.copy(at))},reset:function(){U=!1,it=null,wt.set(-1,0,0,0)}}}function n(){let U=!1,at=!1,it=null,wt=null,xt=null;return{setReversed:function(bt){if(at!==bt){const Vt=t.get("EXT_clip_control");bt?Vt.clipControlEXT(Vt.LOWER_LEFT_EXT,Vt.ZERO_TO_ONE_EXT):Vt.clipControlEXT(Vt.LOWER_LEFT_EXT,Vt.NEGATIVE_ONE_TO_ONE_EXT),at=bt;const Zt=xt;xt=null,this.setClear(Zt)}},getReversed:function(){return at},setTest:function(bt){bt?vt(i.DEPTH_TEST):Gt(i.DEPTH_TEST)},setMask:function(bt){it!==bt&&!U&&(i.depthMask(bt),it=bt)},setFunc:function(bt){if(at&&(bt=C0[bt]),wt!==bt){switch(bt){case Ec:i.depthFunc(i.NEVER);break;case wc:i.depthFunc(i.ALWAYS);break;case Tc:i.depthFunc(i.LESS);break;case Ca:i.depthFunc(i.LEQUAL);break;case Ac:i.depthFunc(i.EQUAL);break;case Rc:i.depthFunc(i.GEQUAL);break;case Cc:i.depthFunc(i.GREATER);break;case Pc:i.depthFunc(i.NOTEQUAL);break;default:i.depthFunc(i.LEQUAL)}wt=bt}},setLocked:function(bt){U=bt},setClear:function(bt){xt!==bt&&(xt=bt,at&&(bt=1-bt),i.clearDepth(bt))},reset:function(){U=!1,it=null,wt=null,xt=null,at=!1}}}function s(){let U=!1,at=null,it=null,wt=null,xt=null,bt=null,Vt=null,Zt=null,ut=null;return{setTest:function(Ot){U||(Ot?vt(i.STENCIL_TEST):Gt(i.STENCIL_TEST))},setMask:function(Ot){at!==Ot&&!U&&(i.stencilMask(Ot),at=Ot)},setFunc:function(Ot,Jt,Rt){(it!==Ot||wt!==Jt||xt!==Rt)&&(i.stencilFunc(Ot,Jt,Rt),it=Ot,wt=Jt,xt=Rt)},setOp:function(Ot,Jt,Rt){(bt!==Ot||Vt!==Jt||Zt!==Rt)&&(i.stencilOp(Ot,Jt,Rt),bt=Ot,Vt=Jt,Zt=Rt)},setLocked:function(Ot){U=Ot},setClear:function(Ot){ut!==Ot&&(i.clearStencil(Ot),ut=Ot)},reset:function(){U=!1,at=null,it=null,wt=null,xt=null,bt=null,Vt=null,Zt=null,ut=null}}}const r=new e,a=new n,o=new s;let l={};const c=new WeakMap;let h={},u={},d={},m=new WeakMap,_=[],M=null,p=!1,f=null,x=null,A=null,S=null,R=null,b=null,g=null,w=new ce(0,0,0),z=0,I=!1,L=null,V=null,$=null,N=null,W=null;const J=i.getParameter(i.MAX_COMBINED_TEXTURE_IMAGE_UNITS);let H=!1,ct=0;const Z=i.getParameter(i.VERSION);Z.indexOf("WebGL")!==-1?(ct=parseFloat(/^WebGL (\d)/.exec(Z)[1]),H=ct>=1):Z.indexOf("OpenGL ES")!==-1&&(ct=parseFloat(/^OpenGL ES (\d)/.exec(Z)[1]),H=ct>=2);let tt=null,st={};const pt=i.getParameter(i.SCISSOR_BOX),ft=i.getParameter(i.VIEWPORT),B=new nn().fromArray(pt),et=new nn().fromArray(ft);function ht(U,at,it,wt){const xt=new Uint8Array(4),bt=i.createTexture();i.bindTexture(U,bt),i.texParameteri(U,i.TEXTURE_MIN_FILTER,i.NEAREST),i.texParameteri(U,i.TEXTURE_MAG_FILTER,i.NEAREST);for(let Vt=0;Vt<it;Vt++)U===i.TEXTURE_3D||U===i.TEXTURE_2D_ARRAY?i.texImage3D(at,0,i.RGBA,1,1,wt,0,i.RGBA,i.UNSIGNED_BYTE,xt):i.texImage2D(at+Vt,0,i.RGBA,1,1,0,i.RGBA,i.UNSIGNED_BYTE,xt);return bt}const gt={};gt[i.TEXTURE_2D]=ht(i.TEXTURE_2D,i.TEXTURE_2D,1),gt[i.TEXTURE_CUBE_MAP]=ht(i.TEXTURE_CUBE_MAP,i.TEXTURE_CUBE_MAP_POSITIVE_X,6),gt[i.TEXTURE_2D_ARRAY]=ht(i.TEXTURE_2D_ARRAY,i.TEXTURE_2D_ARRAY,1,1),gt[i.TEXTURE_3D]=ht(i.TEXTURE_3D,i.TEXTURE_3D,1,1),r.setClear(0,0,0,1),a.setClear(1),o.setClear(0),vt(i.DEPTH_TEST),a.setFunc(Ca),Xe(!1),Me(Nu),vt(i.CULL_FACE),Ie(Ur);function vt(U){h[U]!==!0&&(i.enable(U),h[U]=!0)}function Gt(U){h[U]!==!1&&(i.disable(U),h[U]=!1)}function Qt(U,at){return d[U]!==at?(i.bindFramebuffer(U,at),d[U]=at,U===i.DRAW_FRAMEBUFFER&&(d[i.FRAMEBUFFER]=at),U===i.FRAMEBUFFER&&(d[i.DRAW_FRAMEBUFFER]=at),!0):!1}function kt(U,at){let it=_,wt=!1;if(U){it=m.get(at),it===void 0&&(it=[],m.set(at,it));const xt=U.textures;if(it.length!==xt.length||it[0]!==i.COLOR_ATTACHMENT0){for(let bt=0,Vt=xt.length;bt<Vt;bt++)it[bt]=i.COLOR_ATTACHMENT0+bt;it.length=xt.length,wt=!0}}else it[0]!==i.BACK&&(it[0]=i.BACK,wt=!0);wt&&i.drawBuffers(it)}function ne(U){return M!==U?(i.useProgram(U),M=U,!0):!1}const ee={[Lr]:i.FUNC_ADD,[jg]:i.FUNC_SUBTRACT,[Qg]:i.FUNC_REVERSE_SUBTRACT};ee[t0]=i.MIN,ee[e0]=i.MAX;const qt={[n0]:i.ZERO,[i0]:i.ONE,[s0]:i.SRC_COLOR,[jf]:i.SRC_ALPHA,[h0]:i.SRC_ALPHA_SATURATE,[l0]:i.DST_COLOR,[a0]:i.DST_ALPHA,[r0]:i.ONE_MINUS_SRC_COLOR,[Qf]:i.ONE_MINUS_SRC_ALPHA,[c0]:i.ONE_MINUS_DST_COLOR,[o0]:i.ONE_MINUS_DST_ALPHA,[u0]:i.CONSTANT_COLOR,[d0]:i.ONE_MINUS_CONSTANT_COLOR,[f0]:i.CONSTANT_ALPHA,[p0]:i.ONE_MINUS_CONSTANT_ALPHA};function Ie(U,at,it,wt,xt,bt,Vt,Zt,ut,Ot){if(U===Ur){p===!0&&(Gt(i.BLEND),p=!1);return}if(p===!1&&(vt(i.BLEND),p=!0),U!==Jg){if(U!==f||Ot!==I){if((x!==Lr||R!==Lr)&&(i.blendEquation(i.FUNC_ADD),x=Lr,R=Lr),Ot)switch(U){case Ma:i.blendFuncSeparate(i.ONE,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Iu:i.blendFunc(i.ONE,i.ONE);break;case Uu:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case Fu:i.blendFuncSeparate(i.DST_COLOR,i.ONE_MINUS_SRC_ALPHA,i.ZERO,i.ONE);break;default:Se("WebGLState: Invalid blending: ",U);break}else switch(U){case Ma:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Iu:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE,i.ONE,i.ONE);break;case Uu:Se("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case Fu:Se("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:Se("WebGLState: Invalid blending: ",U);break}A=null,S=null,b=null,g=null,w.set(0,0,0),z=0,f=U,I=Ot}return}xt=xt||at,bt=bt||it,Vt=Vt||wt,(at!==x||xt!==R)&&(i.blendEquationSeparate(ee[at],ee[xt]),x=at,R=xt),(it!==A||wt!==S||bt!==b||Vt!==g)&&(i.blendFuncSeparate(qt[it],qt[wt],qt[bt],qt[Vt]),A=it,S=wt,b=bt,g=Vt),(Zt.equals(w)===!1||ut!==z)&&(i.blendColor(Zt.r,Zt.g,Zt.b,ut),w.copy(Zt),z=ut),f=U,I=!1}function me(U,at){U.side===di?Gt(i.CULL_FACE):vt(i.CULL_FACE);let it=U.side===Yn;at&&(it=!it),Xe(it),U.blending===Ma&&U.transparent===!1?Ie(Ur):Ie(U.blending,U.blendEquation,U.blendSrc,U.blendDst,U.blendEquationAlpha,U.blendSrcAlpha,U.blendDstAlpha,U.blendColor,U.blendAlpha,U.premultipliedAlpha),a.setFunc(U.depthFunc),a.setTest(U.depthTest),a.setMask(U.depthWrite),r.setMask(U.colorWrite);const wt=U.stencilWrite;o.setTest(wt),wt&&(o.setMask(U.stencilWriteMask),o.setFunc(U.stencilFunc,U.stencilRef,U.stencilFuncMask),o.setOp(U.stencilFail,U.stencilZFail,U.stencilZPass)),de(U.polygonOffset,U.polygonOffsetFactor,U.polygonOffsetUnits),U.alphaToCoverage===!0?vt(i.SAMPLE_ALPHA_TO_COVERAGE):Gt(i.SAMPLE_ALPHA_TO_COVERAGE)}function Xe(U){L!==U&&(U?i.frontFace(i.CW):i.frontFace(i.CCW),L=U)}function Me(U){U!==qg?(vt(i.CULL_FACE),U!==V&&(U===Nu?i.cullFace(i.BACK):U===Kg?i.cullFace(i.FRONT):i.cullFace(i.FRONT_AND_BACK))):Gt(i.CULL_FACE),V=U}function rn(U){U!==$&&(H&&i.lineWidth(U),$=U)}function de(U,at,it){U?(vt(i.POLYGON_OFFSET_FILL),(N!==at||W!==it)&&(N=at,W=it,a.getReversed()&&(at=-at,it=-it),i.polygonOffset(at,it))):Gt(i.POLYGON_OFFSET_FILL)}function pn(U){U?vt(i.SCISSOR_TEST):Gt(i.SCISSOR_TEST)}function qe(U){U===void 0&&(U=i.TEXTURE0+J-1),tt!==U&&(i.activeTexture(U),tt=U)}function an(U,at,it){it===void 0&&(tt===null?it=i.TEXTURE0+J-1:it=tt);let wt=st[it];wt===void 0&&(wt={type:void 0,texture:void 0},st[it]=wt),(wt.type!==U||wt.texture!==at)&&(tt!==it&&(i.activeTexture(it),tt=it),i.bindTexture(U,at||gt[U]),wt.type=U,wt.texture=at)}function F(){const U=st[tt];U!==void 0&&U.type!==void 0&&(i.bindTexture(U.type,null),U.type=void 0,U.texture=void 0)}function Ct(){try{i.compressedTexImage2D(...arguments)}catch(U){Se("WebGLState:",U)}}function Yt(){try{i.compressedTexImage3D(...arguments)}catch(U){Se("WebGLState:",U)}}function se(){try{i.texSubImage2D(...arguments)}catch(U){Se("WebGLState:",U)}}function Et(){try{i.texSubImage3D(...arguments)}catch(U){Se("WebGLState:",U)}}function Ue(){try{i.compressedTexSubImage2D(...arguments)}catch(U){Se("WebGLState:",U)}}function Ht(){try{i.compressedTexSubImage3D(...arguments)}catch(U){Se("WebGLState:",U)}}function $t(){try{i.texStorage2D(...arguments)}catch(U){Se("WebGLState:",U)}}function C(){try{i.texStorage3D(...arguments)}catch(U){Se("WebGLState:",U)}}function y(){try{i.texImage2D(...arguments)}catch(U){Se("WebGLState:",U)}}function Y(){try{i.texImage3D(...arguments)}catch(U){Se("WebGLState:",U)}}function dt(U){return u[U]!==void 0?u[U]:i.getParameter(U)}function ot(U,at){u[U]!==at&&(i.pixelStorei(U,at),u[U]=at)}function St(U){B.equals(U)===!1&&(i.scissor(U.x,U.y,U.z,U.w),B.copy(U))}function Mt(U){et.equals(U)===!1&&(i.viewport(U.x,U.y,U.z,U.w),et.copy(U))}function nt(U,at){let it=c.get(at);it===void 0&&(it=new WeakMap,c.set(at,it));let wt=it.get(U);wt===void 0&&(wt=i.getUniformBlockIndex(at,U.name),i.uniformBlockBinding(at,wt,wt),it.set(U,wt))}function rt(U,at,it){const xt=c.get(at).get(U);l[xt]!==it&&(i.bindBufferBase(i.UNIFORM_BUFFER,xt,it),l[xt]=it)}function _t(){i.disable(i.BLEND),i.disable(i.CULL_FACE),i.disable(i.DEPTH_TEST),i.disable(i.POLYGON_OFFSET_FILL),i.disable(i.SCISSOR_TEST),i.disable(i.STENCIL_TEST),i.disable(i.SAMPLE_ALPHA_TO_COVERAGE),i.blendEquation(i.FUNC_ADD),i.blendFunc(i.ONE,i.ZERO),i.blendFuncSeparate(i.ONE,i.ZERO,i.ONE,i.ZERO),i.blendColor(0,0,0,0),i.colorMask(!0,!0,!0,!0),i.clearColor(0,0,0,0),i.depthMask(!0),i.depthFunc(i.LESS),a.setReversed(!1),i.clearDepth(1),i.stencilMask(4294967295),i.stencilFunc(i.ALWAYS,0,4294967295),i.stencilOp(i.KEEP,i.KEEP,i.KEEP),i.clearStencil(0),i.cullFace(i.BACK),i.frontFace(i.CCW),i.polygonOffset(0,0),i.activeTexture(i.TEXTURE0),i.bindFramebuffer(i.FRAMEBUFFER,null),i.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),i.bindFramebuffer(i.READ_FRAMEBUFFER,null),i.useProgram(null),i.lineWidth(1),i.scissor(0,0,i.canvas.width,i.canvas.height),i.viewport(0,0,i.canvas.width,i.canvas.height),i.pixelStorei(i.PACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,!1),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,i.BROWSER_DEFAULT_WEBGL),i.pixelStorei(i.PACK_ROW_LENGTH,0),i.pixelStorei(i.PACK_SKIP_PIXELS,0),i.pixelStorei(i.PACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_ROW_LENGTH,0),i.pixelStorei(i.UNPACK_IMAGE_HEIGHT,0),i.pixelStorei(i.UNPACK_SKIP_PIXELS,0),i.pixelStorei(i.UNPACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_SKIP_IMAGES,0),h={},u={},tt=null,st={},d={},l={},m=new WeakMap,_=[],M=null,p=!1,f=null,x=null,A=null,S=null,R=null,b=null,g=null,w=new ce(0,0,0),z=0,I=!1,L=null,V=null,$=null,N=null,W=null,B.set(0,0,i.canvas.width,i.canvas.height),et.set(0,0,i.canvas.width,i.canvas.height),r.reset(),a.reset(),o.reset()}return{buffers:{color:r,depth:a,stencil:o},enable:vt,disable:Gt,bindFramebuffer:Qt,drawBuffers:kt,useProgram:ne,setBlending:Ie,setMaterial:me,setFlipSided:Xe,setCullFace:Me,setLineWidth:rn,setPolygonOffset:de,setScissorTest:pn,activeTexture:qe,bindTexture:an,unbindTexture:F,compressedTexImage2D:Ct,compressedTexImage3D:Yt,texImage2D:y,texImage3D:Y,pixelStorei:ot,getParameter:dt,updateUBOMapping:nt,uniformBlockBinding:rt,texStorage2D:$t,texStorage3D:C,texSubImage2D:se,texSubImage3D:Et,compressedTexSubImage2D:Ue,compressedTexSubImage3D:Ht,scissor:St,viewport:Mt,reset:_t}}function ty(i,t,e,n,s,r,a){const o=t.has("WEBGL_multisampled_render_to_texture")?t.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),c=new Xt,h=new WeakMap,u=new Set;let d;const m=new WeakMap,_=new Set,M=new FinalizationRegistry(C=>_.delete(C));let p=!1;try{p=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function f(C,y){return p?new OffscreenCanvas(C,y):Xo("canvas")}function x(C,y,Y){let dt=1;const ot=$t(C);if((ot.width>Y||ot.height>Y)&&(dt=Y/Math.max(ot.width,ot.height)),dt<1)if(typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&C instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&C instanceof ImageBitmap||typeof VideoFrame<"u"&&C instanceof VideoFrame){const St=Math.floor(dt*ot.width),Mt=Math.floor(dt*ot.height);d===void 0&&(d=f(St,Mt));const nt=y?f(St,Mt):d;return nt.width=St,nt.height=Mt,nt.getContext("2d").drawImage(C,0,0,St,Mt),jt("WebGLRenderer: Texture has been resized from ("+ot.width+"x"+ot.height+") to ("+St+"x"+Mt+")."),nt}else return"data"in C&&jt("WebGLRenderer: Image in DataTexture is too big ("+ot.width+"x"+ot.height+")."),C;return C}function A(C){return C.generateMipmaps}function S(C){i.generateMipmap(C)}function R(C){return C.isWebGLCubeRenderTarget?i.TEXTURE_CUBE_MAP:C.isWebGL3DRenderTarget?i.TEXTURE_3D:C.isWebGLArrayRenderTarget||C.isCompressedArrayTexture?i.TEXTURE_2D_ARRAY:i.TEXTURE_2D}function b(C,y,Y,dt,ot,St=!1){if(C!==null){if(i[C]!==void 0)return i[C];jt("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+C+"'")}let Mt;dt&&(Mt=t.get("EXT_texture_norm16"),Mt||jt("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let nt=y;if(y===i.RED&&(Y===i.FLOAT&&(nt=i.R32F),Y===i.HALF_FLOAT&&(nt=i.R16F),Y===i.UNSIGNED_BYTE&&(nt=i.R8),Y===i.UNSIGNED_SHORT&&Mt&&(nt=Mt.R16_EXT),Y===i.SHORT&&Mt&&(nt=Mt.R16_SNORM_EXT)),y===i.RED_INTEGER&&(Y===i.UNSIGNED_BYTE&&(nt=i.R8UI),Y===i.UNSIGNED_SHORT&&(nt=i.R16UI),Y===i.UNSIGNED_INT&&(nt=i.R32UI),Y===i.BYTE&&(nt=i.R8I),Y===i.SHORT&&(nt=i.R16I),Y===i.INT&&(nt=i.R32I)),y===i.RG&&(Y===i.FLOAT&&(nt=i.RG32F),Y===i.HALF_FLOAT&&(nt=i.RG16F),Y===i.UNSIGNED_BYTE&&(nt=i.RG8),Y===i.UNSIGNED_SHORT&&Mt&&(nt=Mt.RG16_EXT),Y===i.SHORT&&Mt&&(nt=Mt.RG16_SNORM_EXT)),y===i.RG_INTEGER&&(Y===i.UNSIGNED_BYTE&&(nt=i.RG8UI),Y===i.UNSIGNED_SHORT&&(nt=i.RG16UI),Y===i.UNSIGNED_INT&&(nt=i.RG32UI),Y===i.BYTE&&(nt=i.RG8I),Y===i.SHORT&&(nt=i.RG16I),Y===i.INT&&(nt=i.RG32I)),y===i.RGB_INTEGER&&(Y===i.UNSIGNED_BYTE&&(nt=i.RGB8UI),Y===i.UNSIGNED_SHORT&&(nt=i.RGB16UI),Y===i.UNSIGNED_INT&&(nt=i.RGB32UI),Y===i.BYTE&&(nt=i.RGB8I),Y===i.SHORT&&(nt=i.RGB16I),Y===i.INT&&(nt=i.RGB32I)),y===i.RGBA_INTEGER&&(Y===i.UNSIGNED_BYTE&&(nt=i.RGBA8UI),Y===i.UNSIGNED_SHORT&&(nt=i.RGBA16UI),Y===i.UNSIGNED_INT&&(nt=i.RGBA32UI),Y===i.BYTE&&(nt=i.RGBA8I),Y===i.SHORT&&(nt=i.RGBA16I),Y===i.INT&&(nt=i.RGBA32I)),y===i.RGB&&(Y===i.UNSIGNED_SHORT&&Mt&&(nt=Mt.RGB16_EXT),Y===i.SHORT&&Mt&&(nt=Mt.RGB16_SNORM_EXT),Y===i.UNSIGNED_INT_5_9_9_9_REV&&(nt=i.RGB9_E5),Y===i.UNSIGNED_INT_10F_11F_11F_REV&&(nt=i.R11F_G11F_B10F)),y===i.RGBA){const rt=St?Wo:xe.getTransfer(ot);Y===i.FLOAT&&(nt=i.RGBA32F),Y===i.HALF_FLOAT&&(nt=i.RGBA16F),Y===i.UNSIGNED_BYTE&&(nt=rt===Le?i.SRGB8_ALPHA8:i.RGBA8),Y===i.UNSIGNED_SHORT&&Mt&&(nt=Mt.RGBA16_EXT),Y===i.SHORT&&Mt&&(nt=Mt.RGBA16_SNORM_EXT),Y===i.UNSIGNED_SHORT_4_4_4_4&&(nt=i.RGBA4),Y===i.UNSIGNED_SHORT_5_5_5_1&&(nt=i.RGB5_A1)}return(nt===i.R16F||nt===i.R32F||nt===i.RG16F||nt===i.RG32F||nt===i.RGBA16F||nt===i.RGBA32F)&&t.get("EXT_color_buffer_float"),nt}function g(C,y){let Y;return C?y===null||y===Yi||y===zr?Y=i.DEPTH24_STENCIL8:y===Hi?Y=i.DEPTH32F_STENCIL8:y===La&&(Y=i.DEPTH24_STENCIL8,jt("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):y===null||y===Yi||y===zr?Y=i.DEPTH_COMPONENT24:y===Hi?Y=i.DEPTH_COMPONENT32F:y===La&&(Y=i.DEPTH_COMPONENT16),Y}function w(C,y){return A(C)===!0||C.isFramebufferTexture&&C.minFilter!==Pn&&C.minFilter!==$n?Math.log2(Math.max(y.width,y.height))+1:C.mipmaps.length>0?C.mipmaps.length:C.isCompressedTexture&&Array.isArray(C.image)?y.mipmaps.length:1}function z(C){const y=new WeakRef(C);n.get(C).__ref=y,_.add(y),M.register(C,y,y)}function I(C){const y=n.get(C).__ref;y!==void 0&&(_.delete(y),M.unregister(y))}function L(C){$(C.target)}function V(C){N(C.target)}function $(C){C.removeEventListener("dispose",L),I(C),J(C),C.isVideoTexture&&h.delete(C),C.isHTMLTexture&&u.delete(C)}function N(C){C.removeEventListener("dispose",V),I(C),ct(C)}function W(){for(const C of _){const y=C.deref();y!==void 0&&(y.isRenderTarget===!0?N(y):$(y))}_.clear(),u.clear()}function J(C){const y=n.get(C);if(y.__webglInit===void 0)return;const Y=C.source,dt=m.get(Y);if(dt){const ot=dt[y.__cacheKey];ot.usedTimes--,ot.usedTimes===0&&H(C),Object.keys(dt).length===0&&m.delete(Y)}n.remove(C)}function H(C){const y=n.get(C);i.deleteTexture(y.__webglTexture);const Y=C.source,dt=m.get(Y);delete dt[y.__cacheKey],a.memory.textures--}function ct(C){const y=n.get(C);y.__depthDisposeCallback&&y.__depthDisposeCallback();const Y=C.depthTexture;if(Y&&Y.renderTarget===C&&$(Y),C.isWebGLCubeRenderTarget)for(let ot=0;ot<6;ot++){if(Array.isArray(y.__webglFramebuffer[ot]))for(let St=0;St<y.__webglFramebuffer[ot].length;St++)i.deleteFramebuffer(y.__webglFramebuffer[ot][St]);else i.deleteFramebuffer(y.__webglFramebuffer[ot]);y.__webglDepthbuffer&&i.deleteRenderbuffer(y.__webglDepthbuffer[ot])}else{if(Array.isArray(y.__webglFramebuffer))for(let ot=0;ot<y.__webglFramebuffer.length;ot++)i.deleteFramebuffer(y.__webglFramebuffer[ot]);else i.deleteFramebuffer(y.__webglFramebuffer);if(y.__webglDepthbuffer&&i.deleteRenderbuffer(y.__webglDepthbuffer),y.__webglMultisampledFramebuffer&&i.deleteFramebuffer(y.__webglMultisampledFramebuffer),y.__webglColorRenderbuffer)for(let ot=0;ot<y.__webglColorRenderbuffer.length;ot++)y.__webglColorRenderbuffer[ot]&&i.deleteRenderbuffer(y.__webglColorRenderbuffer[ot]);y.__webglDepthRenderbuffer&&i.deleteRenderbuffer(y.__webglDepthRenderbuffer)}const dt=C.textures;for(let ot=0,St=dt.length;ot<St;ot++){const Mt=n.get(dt[ot]);Mt.__webglTexture&&(i.deleteTexture(Mt.__webglTexture),a.memory.textures--),n.remove(dt[ot])}n.remove(C)}let Z=0;function tt(){Z=0}function st(){return Z}function pt(C){Z=C}function ft(){const C=Z;return C>=s.maxTextures&&jt("WebGLTextures: Trying to use "+(C+1)+" texture units while this GPU supports only "+s.maxTextures),Z+=1,C}function B(C){const y=[];return y.push(C.wrapS),y.push(C.wrapT),y.push(C.wrapR||0),y.push(C.magFilter),y.push(C.minFilter),y.push(C.anisotropy),y.push(C.internalFormat),y.push(C.format),y.push(C.type),y.push(C.generateMipmaps),y.push(C.mipmapsAutoUpdate),y.push(C.premultiplyAlpha),y.push(C.flipY),y.push(C.unpackAlignment),y.push(C.colorSpace),y.join()}function et(C,y){const Y=n.get(C);if(C.isVideoTexture&&Ue(C),C.isRenderTargetTexture===!1&&C.isExternalTexture!==!0&&C.version>0&&Y.__version!==C.version){const dt=C.image;if(dt===null)jt("WebGLRenderer: Texture marked for update but no image data found.");else if(dt.complete===!1)jt("WebGLRenderer: Texture marked for update but image is incomplete");else{me(Y,C,y);return}}else C.isExternalTexture&&(Y.__webglTexture=C.sourceTexture?C.sourceTexture:null);e.bindTexture(i.TEXTURE_2D,Y.__webglTexture,i.TEXTURE0+y)}function ht(C,y){const Y=n.get(C);if(C.isRenderTargetTexture===!1&&C.version>0&&Y.__version!==C.version){me(Y,C,y);return}else C.isExternalTexture&&(Y.__webglTexture=C.sourceTexture?C.sourceTexture:null);e.bindTexture(i.TEXTURE_2D_ARRAY,Y.__webglTexture,i.TEXTURE0+y)}function gt(C,y){const Y=n.get(C);if(C.isRenderTargetTexture===!1&&C.version>0&&Y.__version!==C.version){me(Y,C,y);return}e.bindTexture(i.TEXTURE_3D,Y.__webglTexture,i.TEXTURE0+y)}function vt(C,y){const Y=n.get(C);if(C.version>0&&Y.__version!==C.version){Xe(Y,C,y);return}e.bindTexture(i.TEXTURE_CUBE_MAP,Y.__webglTexture,i.TEXTURE0+y)}const Gt={[Lc]:i.REPEAT,[as]:i.CLAMP_TO_EDGE,[Dc]:i.MIRRORED_REPEAT},Qt={[Pn]:i.NEAREST,[_0]:i.NEAREST_MIPMAP_NEAREST,[Ka]:i.NEAREST_MIPMAP_LINEAR,[$n]:i.LINEAR,[Pl]:i.LINEAR_MIPMAP_NEAREST,[ws]:i.LINEAR_MIPMAP_LINEAR},kt={[M0]:i.NEVER,[vp]:i.ALWAYS,[y0]:i.LESS,[gp]:i.LEQUAL,[b0]:i.EQUAL,[_p]:i.GEQUAL,[E0]:i.GREATER,[w0]:i.NOTEQUAL};function ne(C,y){if(y.type===Hi&&t.has("OES_texture_float_linear")===!1&&(y.magFilter===$n||y.magFilter===Pl||y.magFilter===Ka||y.magFilter===ws||y.minFilter===$n||y.minFilter===Pl||y.minFilter===Ka||y.minFilter===ws)&&jt("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),i.texParameteri(C,i.TEXTURE_WRAP_S,Gt[y.wrapS]),i.texParameteri(C,i.TEXTURE_WRAP_T,Gt[y.wrapT]),(C===i.TEXTURE_3D||C===i.TEXTURE_2D_ARRAY)&&i.texParameteri(C,i.TEXTURE_WRAP_R,Gt[y.wrapR]),i.texParameteri(C,i.TEXTURE_MAG_FILTER,Qt[y.magFilter]),i.texParameteri(C,i.TEXTURE_MIN_FILTER,Qt[y.minFilter]),y.compareFunction&&(i.texParameteri(C,i.TEXTURE_COMPARE_MODE,i.COMPARE_REF_TO_TEXTURE),i.texParameteri(C,i.TEXTURE_COMPARE_FUNC,kt[y.compareFunction])),t.has("EXT_texture_filter_anisotropic")===!0){if(y.magFilter===Pn||y.minFilter!==Ka&&y.minFilter!==ws||y.type===Hi&&t.has("OES_texture_float_linear")===!1)return;if(y.anisotropy>1||n.get(y).__currentAnisotropy){const Y=t.get("EXT_texture_filter_anisotropic");i.texParameterf(C,Y.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(y.anisotropy,s.getMaxAnisotropy())),n.get(y).__currentAnisotropy=y.anisotropy}}}function ee(C,y){let Y=!1;C.__webglInit===void 0&&(C.__webglInit=!0,y.addEventListener("dispose",L),z(y));const dt=y.source;let ot=m.get(dt);ot===void 0&&(ot={},m.set(dt,ot));const St=B(y);if(St!==C.__cacheKey){ot[St]===void 0&&(ot[St]={texture:i.createTexture(),usedTimes:0},a.memory.textures++,Y=!0),ot[St].usedTimes++;const Mt=ot[C.__cacheKey];Mt!==void 0&&(ot[C.__cacheKey].usedTimes--,Mt.usedTimes===0&&H(y)),C.__cacheKey=St,C.__webglTexture=ot[St].texture}return Y}function qt(C,y,Y){return Math.floor(Math.floor(C/Y)/y)}function Ie(C,y,Y,dt){const St=C.updateRanges;if(St.length===0)e.texSubImage2D(i.TEXTURE_2D,0,0,0,y.width,y.height,Y,dt,y.data);else{St.sort((U,at)=>U.start-at.start);let Mt=0;for(let U=1;U<St.length;U++){const at=St[Mt],it=St[U],wt=at.start+at.count,xt=qt(it.start,y.width,4),bt=qt(at.start,y.width,4);it.start<=wt+1&&xt===bt&&qt(it.start+it.count-1,y.width,4)===xt?at.count=Math.max(at.count,it.start+it.count-at.start):(++Mt,St[Mt]=it)}St.length=Mt+1;const nt=e.getParameter(i.UNPACK_ROW_LENGTH),rt=e.getParameter(i.UNPACK_SKIP_PIXELS),_t=e.getParameter(i.UNPACK_SKIP_ROWS);e.pixelStorei(i.UNPACK_ROW_LENGTH,y.width);for(let U=0,at=St.length;U<at;U++){const it=St[U],wt=Math.floor(it.start/4),xt=Math.ceil(it.count/4),bt=wt%y.width,Vt=Math.floor(wt/y.width),Zt=xt,ut=1;e.pixelStorei(i.UNPACK_SKIP_PIXELS,bt),e.pixelStorei(i.UNPACK_SKIP_ROWS,Vt),e.texSubImage2D(i.TEXTURE_2D,0,bt,Vt,Zt,ut,Y,dt,y.data)}C.clearUpdateRanges(),e.pixelStorei(i.UNPACK_ROW_LENGTH,nt),e.pixelStorei(i.UNPACK_SKIP_PIXELS,rt),e.pixelStorei(i.UNPACK_SKIP_ROWS,_t)}}function me(C,y,Y){let dt=i.TEXTURE_2D;(y.isDataArrayTexture||y.isCompressedArrayTexture)&&(dt=i.TEXTURE_2D_ARRAY),y.isData3DTexture&&(dt=i.TEXTURE_3D);const ot=ee(C,y),St=y.source;e.bindTexture(dt,C.__webglTexture,i.TEXTURE0+Y);const Mt=n.get(St);if(St.version!==Mt.__version||ot===!0){if(e.activeTexture(i.TEXTURE0+Y),(typeof ImageBitmap<"u"&&y.image instanceof ImageBitmap)===!1){const ut=xe.getPrimaries(xe.workingColorSpace),Ot=y.colorSpace===Es?null:xe.getPrimaries(y.colorSpace),Jt=y.colorSpace===Es||ut===Ot?i.NONE:i.BROWSER_DEFAULT_WEBGL;e.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,y.flipY),e.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,y.premultiplyAlpha),e.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,Jt)}e.pixelStorei(i.UNPACK_ALIGNMENT,y.unpackAlignment);let rt=x(y.image,!1,s.maxTextureSize);rt=Ht(y,rt);const _t=r.convert(y.format,y.colorSpace),U=r.convert(y.type);let at=b(y.internalFormat,_t,U,y.normalized,y.colorSpace,y.isVideoTexture);ne(dt,y);let it;const wt=y.mipmaps,xt=y.isVideoTexture!==!0,bt=Mt.__version===void 0||ot===!0,Vt=St.dataReady,Zt=w(y,rt);if(y.isDepthTexture)at=g(y.format===Ts,y.type),bt&&(xt?e.texStorage2D(i.TEXTURE_2D,1,at,rt.width,rt.height):e.texImage2D(i.TEXTURE_2D,0,at,rt.width,rt.height,0,_t,U,null));else if(y.isDataTexture)if(wt.length>0){xt&&bt&&e.texStorage2D(i.TEXTURE_2D,Zt,at,wt[0].width,wt[0].height);for(let ut=0,Ot=wt.length;ut<Ot;ut++)it=wt[ut],xt?Vt&&e.texSubImage2D(i.TEXTURE_2D,ut,0,0,it.width,it.height,_t,U,it.data):e.texImage2D(i.TEXTURE_2D,ut,at,it.width,it.height,0,_t,U,it.data);y.generateMipmaps=!1}else xt?(bt&&e.texStorage2D(i.TEXTURE_2D,Zt,at,rt.width,rt.height),Vt&&Ie(y,rt,_t,U)):e.texImage2D(i.TEXTURE_2D,0,at,rt.width,rt.height,0,_t,U,rt.data);else if(y.isCompressedTexture)if(y.isCompressedArrayTexture){xt&&bt&&e.texStorage3D(i.TEXTURE_2D_ARRAY,Zt,at,wt[0].width,wt[0].height,rt.depth);for(let ut=0,Ot=wt.length;ut<Ot;ut++)if(it=wt[ut],y.format!==Gi)if(_t!==null)if(xt){if(Vt)if(y.layerUpdates.size>0){const Jt=vd(it.width,it.height,y.format,y.type);for(const Rt of y.layerUpdates){const ae=it.data.subarray(Rt*Jt/it.data.BYTES_PER_ELEMENT,(Rt+1)*Jt/it.data.BYTES_PER_ELEMENT);e.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ut,0,0,Rt,it.width,it.height,1,_t,ae)}}else e.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ut,0,0,0,it.width,it.height,rt.depth,_t,it.data)}else e.compressedTexImage3D(i.TEXTURE_2D_ARRAY,ut,at,it.width,it.height,rt.depth,0,it.data,0,0);else jt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else xt?Vt&&e.texSubImage3D(i.TEXTURE_2D_ARRAY,ut,0,0,0,it.width,it.height,rt.depth,_t,U,it.data):e.texImage3D(i.TEXTURE_2D_ARRAY,ut,at,it.width,it.height,rt.depth,0,_t,U,it.data);y.layerUpdates.size>0&&y.clearLayerUpdates()}else{xt&&bt&&e.texStorage2D(i.TEXTURE_2D,Zt,at,wt[0].width,wt[0].height);for(let ut=0,Ot=wt.length;ut<Ot;ut++)it=wt[ut],y.format!==Gi?_t!==null?xt?Vt&&e.compressedTexSubImage2D(i.TEXTURE_2D,ut,0,0,it.width,it.height,_t,it.data):e.compressedTexImage2D(i.TEXTURE_2D,ut,at,it.width,it.height,0,it.data):jt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):xt?Vt&&e.texSubImage2D(i.TEXTURE_2D,ut,0,0,it.width,it.height,_t,U,it.data):e.texImage2D(i.TEXTURE_2D,ut,at,it.width,it.height,0,_t,U,it.data)}else if(y.isDataArrayTexture)if(xt){if(bt&&e.texStorage3D(i.TEXTURE_2D_ARRAY,Zt,at,rt.width,rt.height,rt.depth),Vt)if(y.layerUpdates.size>0){const ut=vd(rt.width,rt.height,y.format,y.type);for(const Ot of y.layerUpdates){const Jt=rt.data.subarray(Ot*ut/rt.data.BYTES_PER_ELEMENT,(Ot+1)*ut/rt.data.BYTES_PER_ELEMENT);e.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,Ot,rt.width,rt.height,1,_t,U,Jt)}y.clearLayerUpdates()}else e.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,0,rt.width,rt.height,rt.depth,_t,U,rt.data)}else e.texImage3D(i.TEXTURE_2D_ARRAY,0,at,rt.width,rt.height,rt.depth,0,_t,U,rt.data);else if(y.isData3DTexture)xt?(bt&&e.texStorage3D(i.TEXTURE_3D,Zt,at,rt.width,rt.height,rt.depth),Vt&&e.texSubImage3D(i.TEXTURE_3D,0,0,0,0,rt.width,rt.height,rt.depth,_t,U,rt.data)):e.texImage3D(i.TEXTURE_3D,0,at,rt.width,rt.height,rt.depth,0,_t,U,rt.data);else if(y.isFramebufferTexture){if(bt)if(xt)e.texStorage2D(i.TEXTURE_2D,Zt,at,rt.width,rt.height);else{let ut=rt.width,Ot=rt.height;for(let Jt=0;Jt<Zt;Jt++)e.texImage2D(i.TEXTURE_2D,Jt,at,ut,Ot,0,_t,U,null),ut>>=1,Ot>>=1}}else if(y.isHTMLTexture){if("texElementImage2D"in i){const ut=i.canvas;if(ut.hasAttribute("layoutsubtree")||ut.setAttribute("layoutsubtree","true"),rt.parentNode!==ut){ut.appendChild(rt),u.add(y),ut.onpaint=Ot=>{const Jt=Ot.changedElements;for(const Rt of u)Jt.includes(Rt.image)&&(Rt.needsUpdate=!0)},ut.requestPaint();return}if(i.texElementImage2D.length===3)i.texElementImage2D(i.TEXTURE_2D,i.RGBA8,rt);else{const Jt=i.RGBA,Rt=i.RGBA,ae=i.UNSIGNED_BYTE;i.texElementImage2D(i.TEXTURE_2D,0,Jt,Rt,ae,rt)}i.texParameteri(i.TEXTURE_2D,i.TEXTURE_MIN_FILTER,i.LINEAR),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_S,i.CLAMP_TO_EDGE),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_T,i.CLAMP_TO_EDGE)}}else if(wt.length>0){if(xt&&bt){const ut=$t(wt[0]);e.texStorage2D(i.TEXTURE_2D,Zt,at,ut.width,ut.height)}for(let ut=0,Ot=wt.length;ut<Ot;ut++)it=wt[ut],xt?Vt&&e.texSubImage2D(i.TEXTURE_2D,ut,0,0,_t,U,it):e.texImage2D(i.TEXTURE_2D,ut,at,_t,U,it);y.generateMipmaps=!1}else if(xt){if(bt){const ut=$t(rt);e.texStorage2D(i.TEXTURE_2D,Zt,at,ut.width,ut.height)}Vt&&e.texSubImage2D(i.TEXTURE_2D,0,0,0,_t,U,rt)}else e.texImage2D(i.TEXTURE_2D,0,at,_t,U,rt);A(y)&&y.mipmapsAutoUpdate===!0&&S(dt),Mt.__version=St.version,y.onUpdate&&y.onUpdate(y)}C.__version=y.version}function Xe(C,y,Y){if(y.image.length!==6)return;const dt=ee(C,y),ot=y.source;e.bindTexture(i.TEXTURE_CUBE_MAP,C.__webglTexture,i.TEXTURE0+Y);const St=n.get(ot);if(ot.version!==St.__version||dt===!0){e.activeTexture(i.TEXTURE0+Y);const Mt=xe.getPrimaries(xe.workingColorSpace),nt=y.colorSpace===Es?null:xe.getPrimaries(y.colorSpace),rt=y.colorSpace===Es||Mt===nt?i.NONE:i.BROWSER_DEFAULT_WEBGL;e.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,y.flipY),e.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,y.premultiplyAlpha),e.pixelStorei(i.UNPACK_ALIGNMENT,y.unpackAlignment),e.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,rt);const _t=y.isCompressedTexture||y.image[0].isCompressedTexture,U=y.image[0]&&y.image[0].isDataTexture,at=[];for(let Rt=0;Rt<6;Rt++)!_t&&!U?at[Rt]=x(y.image[Rt],!0,s.maxCubemapSize):at[Rt]=U?y.image[Rt].image:y.image[Rt],at[Rt]=Ht(y,at[Rt]);const it=at[0],wt=r.convert(y.format,y.colorSpace),xt=r.convert(y.type);let bt=b(y.internalFormat,wt,xt,y.normalized,y.colorSpace);const Vt=y.isVideoTexture!==!0,Zt=St.__version===void 0||dt===!0,ut=ot.dataReady;let Ot=w(y,it);ne(i.TEXTURE_CUBE_MAP,y);let Jt;if(y.isDepthTexture){if(bt=g(y.format===Ts,y.type),Zt)if(Vt)e.texStorage2D(i.TEXTURE_CUBE_MAP,1,bt,it.width,it.height);else for(let Rt=0;Rt<6;Rt++)e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,0,bt,it.width,it.height,0,wt,xt,null)}else if(_t){Vt&&Zt&&e.texStorage2D(i.TEXTURE_CUBE_MAP,Ot,bt,it.width,it.height);for(let Rt=0;Rt<6;Rt++){Jt=at[Rt].mipmaps;for(let ae=0;ae<Jt.length;ae++){const ze=Jt[ae];y.format!==Gi?wt!==null?Vt?ut&&e.compressedTexSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,ae,0,0,ze.width,ze.height,wt,ze.data):e.compressedTexImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,ae,bt,ze.width,ze.height,0,ze.data):jt("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Vt?ut&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,ae,0,0,ze.width,ze.height,wt,xt,ze.data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,ae,bt,ze.width,ze.height,0,wt,xt,ze.data)}}}else{if(Jt=y.mipmaps,Vt&&Zt){Jt.length>0&&Ot++;const Rt=$t(at[0]);e.texStorage2D(i.TEXTURE_CUBE_MAP,Ot,bt,Rt.width,Rt.height)}for(let Rt=0;Rt<6;Rt++)if(U){Vt?ut&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,0,0,0,at[Rt].width,at[Rt].height,wt,xt,at[Rt].data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,0,bt,at[Rt].width,at[Rt].height,0,wt,xt,at[Rt].data);for(let ae=0;ae<Jt.length;ae++){const Fn=Jt[ae].image[Rt].image;Vt?ut&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,ae+1,0,0,Fn.width,Fn.height,wt,xt,Fn.data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,ae+1,bt,Fn.width,Fn.height,0,wt,xt,Fn.data)}}else{Vt?ut&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,0,0,0,wt,xt,at[Rt]):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,0,bt,wt,xt,at[Rt]);for(let ae=0;ae<Jt.length;ae++){const ze=Jt[ae];Vt?ut&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,ae+1,0,0,wt,xt,ze.image[Rt]):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Rt,ae+1,bt,wt,xt,ze.image[Rt])}}}A(y)&&y.mipmapsAutoUpdate===!0&&S(i.TEXTURE_CUBE_MAP),St.__version=ot.version,y.onUpdate&&y.onUpdate(y)}C.__version=y.version}function Me(C,y,Y,dt,ot,St){const Mt=r.convert(Y.format,Y.colorSpace),nt=r.convert(Y.type),rt=b(Y.internalFormat,Mt,nt,Y.normalized,Y.colorSpace),_t=n.get(y),U=n.get(Y);if(U.__renderTarget=y,!_t.__hasExternalTextures){const at=Math.max(1,y.width>>St),it=Math.max(1,y.height>>St);ot===i.TEXTURE_3D||ot===i.TEXTURE_2D_ARRAY?e.texImage3D(ot,St,rt,at,it,y.depth,0,Mt,nt,null):e.texImage2D(ot,St,rt,at,it,0,Mt,nt,null)}e.bindFramebuffer(i.FRAMEBUFFER,C),Et(y)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,dt,ot,U.__webglTexture,0,se(y)):(ot===i.TEXTURE_2D||ot>=i.TEXTURE_CUBE_MAP_POSITIVE_X&&ot<=i.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&i.framebufferTexture2D(i.FRAMEBUFFER,dt,ot,U.__webglTexture,St),e.bindFramebuffer(i.FRAMEBUFFER,null)}function rn(C,y,Y){if(i.bindRenderbuffer(i.RENDERBUFFER,C),y.depthBuffer){const dt=y.depthTexture,ot=dt&&dt.isDepthTexture?dt.type:null,St=g(y.stencilBuffer,ot),Mt=y.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;Et(y)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,se(y),St,y.width,y.height):Y?i.renderbufferStorageMultisample(i.RENDERBUFFER,se(y),St,y.width,y.height):i.renderbufferStorage(i.RENDERBUFFER,St,y.width,y.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,Mt,i.RENDERBUFFER,C)}else{const dt=y.textures;for(let ot=0;ot<dt.length;ot++){const St=dt[ot],Mt=r.convert(St.format,St.colorSpace),nt=r.convert(St.type),rt=b(St.internalFormat,Mt,nt,St.normalized,St.colorSpace);Et(y)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,se(y),rt,y.width,y.height):Y?i.renderbufferStorageMultisample(i.RENDERBUFFER,se(y),rt,y.width,y.height):i.renderbufferStorage(i.RENDERBUFFER,rt,y.width,y.height)}}i.bindRenderbuffer(i.RENDERBUFFER,null)}function de(C,y,Y){const dt=y.isWebGLCubeRenderTarget===!0;if(e.bindFramebuffer(i.FRAMEBUFFER,C),!(y.depthTexture&&y.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");const ot=n.get(y.depthTexture);ot.__renderTarget=y;const St=dt?y.depthTexture.image[0]:y.depthTexture.image;(!ot.__webglTexture||St.width!==y.width||St.height!==y.height)&&(St.width=y.width,St.height=y.height,y.depthTexture.needsUpdate=!0),dt?vt(y.depthTexture,0):et(y.depthTexture,0);const Mt=ot.__webglTexture,nt=se(y),rt=dt?i.TEXTURE_CUBE_MAP_POSITIVE_X+Y:i.TEXTURE_2D,_t=y.depthTexture.format===Ts?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;if(y.depthTexture.format===Ps)Et(y)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,_t,rt,Mt,0,nt):i.framebufferTexture2D(i.FRAMEBUFFER,_t,rt,Mt,0);else if(y.depthTexture.format===Ts)Et(y)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,_t,rt,Mt,0,nt):i.framebufferTexture2D(i.FRAMEBUFFER,_t,rt,Mt,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function pn(C){const y=n.get(C),Y=C.isWebGLCubeRenderTarget===!0;if(y.__boundDepthTexture!==C.depthTexture){const dt=C.depthTexture;if(y.__depthDisposeCallback&&y.__depthDisposeCallback(),dt){const ot=()=>{delete y.__boundDepthTexture,delete y.__depthDisposeCallback,dt.removeEventListener("dispose",ot)};dt.addEventListener("dispose",ot),y.__depthDisposeCallback=ot}y.__boundDepthTexture=dt}if(C.depthTexture&&!y.__autoAllocateDepthBuffer)if(Y)for(let dt=0;dt<6;dt++)de(y.__webglFramebuffer[dt],C,dt);else C.texture.mipmaps.length>0?de(y.__webglFramebuffer[0],C,0):de(y.__webglFramebuffer,C,0);else if(Y){y.__webglDepthbuffer=[];for(let dt=0;dt<6;dt++)if(e.bindFramebuffer(i.FRAMEBUFFER,y.__webglFramebuffer[dt]),y.__webglDepthbuffer[dt]===void 0)y.__webglDepthbuffer[dt]=i.createRenderbuffer(),rn(y.__webglDepthbuffer[dt],C,!1);else{const ot=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,St=y.__webglDepthbuffer[dt];i.bindRenderbuffer(i.RENDERBUFFER,St),i.framebufferRenderbuffer(i.FRAMEBUFFER,ot,i.RENDERBUFFER,St)}}else if(C.texture.mipmaps.length>0?e.bindFramebuffer(i.FRAMEBUFFER,y.__webglFramebuffer[0]):e.bindFramebuffer(i.FRAMEBUFFER,y.__webglFramebuffer),y.__webglDepthbuffer===void 0)y.__webglDepthbuffer=i.createRenderbuffer(),rn(y.__webglDepthbuffer,C,!1);else{const ot=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,St=y.__webglDepthbuffer;i.bindRenderbuffer(i.RENDERBUFFER,St),i.framebufferRenderbuffer(i.FRAMEBUFFER,ot,i.RENDERBUFFER,St)}e.bindFramebuffer(i.FRAMEBUFFER,null)}function qe(C,y,Y){const dt=n.get(C);y!==void 0&&Me(dt.__webglFramebuffer,C,C.texture,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,0),Y!==void 0&&pn(C)}function an(C){const y=C.texture,Y=n.get(C),dt=n.get(y);C.addEventListener("dispose",V),z(C);const ot=C.textures,St=C.isWebGLCubeRenderTarget===!0,Mt=ot.length>1;if(Mt||(dt.__webglTexture===void 0&&(dt.__webglTexture=i.createTexture()),dt.__version=y.version,a.memory.textures++),St){Y.__webglFramebuffer=[];for(let nt=0;nt<6;nt++)if(y.mipmaps.length>0){Y.__webglFramebuffer[nt]=[];for(let rt=0;rt<y.mipmaps.length;rt++)Y.__webglFramebuffer[nt][rt]=i.createFramebuffer()}else Y.__webglFramebuffer[nt]=i.createFramebuffer()}else{if(y.mipmaps.length>0){Y.__webglFramebuffer=[];for(let nt=0;nt<y.mipmaps.length;nt++)Y.__webglFramebuffer[nt]=i.createFramebuffer()}else Y.__webglFramebuffer=i.createFramebuffer();if(Mt)for(let nt=0,rt=ot.length;nt<rt;nt++){const _t=n.get(ot[nt]);_t.__webglTexture===void 0&&(_t.__webglTexture=i.createTexture(),a.memory.textures++)}if(C.samples>0&&Et(C)===!1){Y.__webglMultisampledFramebuffer=i.createFramebuffer(),Y.__webglColorRenderbuffer=[],e.bindFramebuffer(i.FRAMEBUFFER,Y.__webglMultisampledFramebuffer);for(let nt=0;nt<ot.length;nt++){const rt=ot[nt];Y.__webglColorRenderbuffer[nt]=i.createRenderbuffer(),i.bindRenderbuffer(i.RENDERBUFFER,Y.__webglColorRenderbuffer[nt]);const _t=r.convert(rt.format,rt.colorSpace),U=r.convert(rt.type),at=b(rt.internalFormat,_t,U,rt.normalized,rt.colorSpace,C.isXRRenderTarget===!0),it=se(C);i.renderbufferStorageMultisample(i.RENDERBUFFER,it,at,C.width,C.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+nt,i.RENDERBUFFER,Y.__webglColorRenderbuffer[nt])}i.bindRenderbuffer(i.RENDERBUFFER,null),C.depthBuffer&&(Y.__webglDepthRenderbuffer=i.createRenderbuffer(),rn(Y.__webglDepthRenderbuffer,C,!0)),e.bindFramebuffer(i.FRAMEBUFFER,null)}}if(St){e.bindTexture(i.TEXTURE_CUBE_MAP,dt.__webglTexture),ne(i.TEXTURE_CUBE_MAP,y);for(let nt=0;nt<6;nt++)if(y.mipmaps.length>0)for(let rt=0;rt<y.mipmaps.length;rt++)Me(Y.__webglFramebuffer[nt][rt],C,y,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+nt,rt);else Me(Y.__webglFramebuffer[nt],C,y,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+nt,0);A(y)?S(i.TEXTURE_CUBE_MAP):y.mipmaps.length>0&&i.texParameteri(i.TEXTURE_CUBE_MAP,i.TEXTURE_MAX_LEVEL,y.mipmaps.length-1),e.unbindTexture()}else if(Mt){for(let nt=0,rt=ot.length;nt<rt;nt++){const _t=ot[nt],U=n.get(_t);let at=i.TEXTURE_2D;(C.isWebGL3DRenderTarget||C.isWebGLArrayRenderTarget)&&(at=C.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),e.bindTexture(at,U.__webglTexture),ne(at,_t),Me(Y.__webglFramebuffer,C,_t,i.COLOR_ATTACHMENT0+nt,at,0),A(_t)&&S(at)}e.unbindTexture()}else{let nt=i.TEXTURE_2D;if((C.isWebGL3DRenderTarget||C.isWebGLArrayRenderTarget)&&(nt=C.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),e.bindTexture(nt,dt.__webglTexture),ne(nt,y),y.mipmaps.length>0)for(let rt=0;rt<y.mipmaps.length;rt++)Me(Y.__webglFramebuffer[rt],C,y,i.COLOR_ATTACHMENT0,nt,rt);else Me(Y.__webglFramebuffer,C,y,i.COLOR_ATTACHMENT0,nt,0);A(y)?S(nt):y.mipmaps.length>0&&i.texParameteri(nt,i.TEXTURE_MAX_LEVEL,y.mipmaps.length-1),e.unbindTexture()}C.depthBuffer&&pn(C)}function F(C){const y=C.textures;for(let Y=0,dt=y.length;Y<dt;Y++){const ot=y[Y];if(A(ot)&&ot.mipmapsAutoUpdate===!0){const St=R(C),Mt=n.get(ot).__webglTexture;e.bindTexture(St,Mt),S(St),e.unbindTexture()}}}const Ct=[];function Yt(C){if(C.samples>0){if(Et(C)===!1){const y=C.textures,Y=C.width,dt=C.height;let ot=i.COLOR_BUFFER_BIT;const St=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,Mt=n.get(C),nt=y.length>1;if(nt)for(let _t=0;_t<y.length;_t++)e.bindFramebuffer(i.FRAMEBUFFER,Mt.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+_t,i.RENDERBUFFER,null),e.bindFramebuffer(i.FRAMEBUFFER,Mt.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+_t,i.TEXTURE_2D,null,0);e.bindFramebuffer(i.READ_FRAMEBUFFER,Mt.__webglMultisampledFramebuffer),C.texture.mipmaps.length>0?e.bindFramebuffer(i.DRAW_FRAMEBUFFER,Mt.__webglFramebuffer[0]):e.bindFramebuffer(i.DRAW_FRAMEBUFFER,Mt.__webglFramebuffer);for(let _t=0;_t<y.length;_t++){if(C.resolveDepthBuffer&&(C.depthBuffer&&(ot|=i.DEPTH_BUFFER_BIT),C.stencilBuffer&&C.resolveStencilBuffer&&(ot|=i.STENCIL_BUFFER_BIT)),nt){i.framebufferRenderbuffer(i.READ_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.RENDERBUFFER,Mt.__webglColorRenderbuffer[_t]);const U=n.get(y[_t]).__webglTexture;i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,U,0)}i.blitFramebuffer(0,0,Y,dt,0,0,Y,dt,ot,i.NEAREST),l===!0&&(Ct.length=0,Ct.push(i.COLOR_ATTACHMENT0+_t),C.depthBuffer&&C.storeMultisampledDepthBuffer===!1&&Ct.push(St),i.invalidateFramebuffer(i.READ_FRAMEBUFFER,Ct))}if(e.bindFramebuffer(i.READ_FRAMEBUFFER,null),e.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),nt)for(let _t=0;_t<y.length;_t++){e.bindFramebuffer(i.FRAMEBUFFER,Mt.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+_t,i.RENDERBUFFER,Mt.__webglColorRenderbuffer[_t]);const U=n.get(y[_t]).__webglTexture;e.bindFramebuffer(i.FRAMEBUFFER,Mt.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+_t,i.TEXTURE_2D,U,0)}e.bindFramebuffer(i.DRAW_FRAMEBUFFER,Mt.__webglMultisampledFramebuffer)}else if(C.depthBuffer&&C.storeMultisampledDepthBuffer===!1&&l){const y=C.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,[y])}}}function se(C){return Math.min(s.maxSamples,C.samples)}function Et(C){const y=n.get(C);return C.samples>0&&t.has("WEBGL_multisampled_render_to_texture")===!0&&y.__useRenderToTexture!==!1}function Ue(C){const y=a.render.frame;h.get(C)!==y&&(h.set(C,y),C.update())}function Ht(C,y){const Y=C.colorSpace,dt=C.format,ot=C.type;return C.isCompressedTexture===!0||C.isVideoTexture===!0||Y!==Vo&&Y!==Es&&(xe.getTransfer(Y)===Le?(dt!==Gi||ot!==ei)&&jt("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):Se("WebGLTextures: Unsupported texture color space:",Y)),y}function $t(C){return typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement?(c.width=C.naturalWidth||C.width,c.height=C.naturalHeight||C.height):typeof VideoFrame<"u"&&C instanceof VideoFrame?(c.width=C.displayWidth,c.height=C.displayHeight):(c.width=C.width,c.height=C.height),c}this.allocateTextureUnit=ft,this.resetTextureUnits=tt,this.getTextureUnits=st,this.setTextureUnits=pt,this.setTexture2D=et,this.setTexture2DArray=ht,this.setTexture3D=gt,this.setTextureCube=vt,this.rebindTextures=qe,this.setupRenderTarget=an,this.updateRenderTargetMipmap=F,this.updateMultisampleRenderTarget=Yt,this.setupDepthRenderbuffer=pn,this.setupFrameBufferTexture=Me,this.useMultisampledRTT=Et,this.dispose=W}function ey(i,t){function e(n,s=Es){let r;const a=xe.getTransfer(s);if(n===ei)return i.UNSIGNED_BYTE;if(n===Oh)return i.UNSIGNED_SHORT_4_4_4_4;if(n===Bh)return i.UNSIGNED_SHORT_5_5_5_1;if(n===up)return i.UNSIGNED_INT_5_9_9_9_REV;if(n===dp)return i.UNSIGNED_INT_10F_11F_11F_REV;if(n===cp)return i.BYTE;if(n===hp)return i.SHORT;if(n===La)return i.UNSIGNED_SHORT;if(n===Fh)return i.INT;if(n===Yi)return i.UNSIGNED_INT;if(n===Hi)return i.FLOAT;if(n===qi)return i.HALF_FLOAT;if(n===fp)return i.ALPHA;if(n===pp)return i.RGB;if(n===Gi)return i.RGBA;if(n===Ps)return i.DEPTH_COMPONENT;if(n===Ts)return i.DEPTH_STENCIL;if(n===mp)return i.RED;if(n===zh)return i.RED_INTEGER;if(n===Ks)return i.RG;if(n===kh)return i.RG_INTEGER;if(n===Hh)return i.RGBA_INTEGER;if(n===Io||n===Uo||n===Fo||n===Oo)if(a===Le)if(r=t.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(n===Io)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(n===Uo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(n===Fo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(n===Oo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=t.get("WEBGL_compressed_texture_s3tc"),r!==null){if(n===Io)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(n===Uo)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(n===Fo)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(n===Oo)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(n===Nc||n===Ic||n===Uc||n===Fc)if(r=t.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(n===Nc)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(n===Ic)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(n===Uc)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(n===Fc)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(n===Oc||n===Bc||n===zc||n===kc||n===Hc||n===Ho||n===Gc)if(r=t.get("WEBGL_compressed_texture_etc"),r!==null){if(n===Oc||n===Bc)return a===Le?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(n===zc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(n===kc)return r.COMPRESSED_R11_EAC;if(n===Hc)return r.COMPRESSED_SIGNED_R11_EAC;if(n===Ho)return r.COMPRESSED_RG11_EAC;if(n===Gc)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(n===Vc||n===Wc||n===Xc||n===$c||n===Yc||n===qc||n===Kc||n===Zc||n===Jc||n===jc||n===Qc||n===th||n===eh||n===nh)if(r=t.get("WEBGL_compressed_texture_astc"),r!==null){if(n===Vc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(n===Wc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(n===Xc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(n===$c)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(n===Yc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(n===qc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(n===Kc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(n===Zc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(n===Jc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(n===jc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(n===Qc)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(n===th)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(n===eh)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(n===nh)return a===Le?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(n===ih||n===sh||n===rh)if(r=t.get("EXT_texture_compression_bptc"),r!==null){if(n===ih)return a===Le?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(n===sh)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(n===rh)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(n===ah||n===oh||n===Go||n===lh)if(r=t.get("EXT_texture_compression_rgtc"),r!==null){if(n===ah)return r.COMPRESSED_RED_RGTC1_EXT;if(n===oh)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(n===Go)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(n===lh)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return n===zr?i.UNSIGNED_INT_24_8:i[n]!==void 0?i[n]:null}return{convert:e}}const ny=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,iy=`
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

}`;class sy{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(t,e){if(this.texture===null){const n=new Np(t.texture);(t.depthNear!==e.depthNear||t.depthFar!==e.depthFar)&&(this.depthNear=t.depthNear,this.depthFar=t.depthFar),this.texture=n}}getMesh(t){if(this.texture!==null&&this.mesh===null){const e=t.cameras[0].viewport,n=new Zs({vertexShader:ny,fragmentShader:iy,uniforms:{depthColor:{value:this.texture},depthWidth:{value:e.z},depthHeight:{value:e.w}}});this.mesh=new fn(new il(20,20),n)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}}class ry extends Is{constructor(t,e){super();const n=this;let s=null,r=1,a=null,o="local-floor",l=1,c=null,h=null,u=null,d=null,m=null,_=null;const M=typeof XRWebGLBinding<"u",p=new sy,f={},x=e.getContextAttributes();let A=null,S=null;const R=[],b=[],g=new Xt;let w=null,z=null;const I=new Xn;I.viewport=new nn;const L=new Xn;L.viewport=new nn;const V=[I,L],$=new m_;let N=null,W=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(B){let et=R[B];return et===void 0&&(et=new Bl,R[B]=et),et.getTargetRaySpace()},this.getControllerGrip=function(B){let et=R[B];return et===void 0&&(et=new Bl,R[B]=et),et.getGripSpace()},this.getHand=function(B){let et=R[B];return et===void 0&&(et=new Bl,R[B]=et),et.getHandSpace()};function J(B){const et=b.indexOf(B.inputSource);if(et===-1)return;const ht=R[et];ht!==void 0&&(ht.update(B.inputSource,B.frame,c||a),ht.dispatchEvent({type:B.type,data:B.inputSource}))}function H(){s.removeEventListener("select",J),s.removeEventListener("selectstart",J),s.removeEventListener("selectend",J),s.removeEventListener("squeeze",J),s.removeEventListener("squeezestart",J),s.removeEventListener("squeezeend",J),s.removeEventListener("end",H),s.removeEventListener("inputsourceschange",ct);for(let B=0;B<R.length;B++){const et=b[B];et!==null&&(b[B]=null,R[B].disconnect(et))}N=null,W=null,p.reset();for(const B in f)delete f[B];if(t.setRenderTarget(A),m=null,d=null,u=null,s=null,S=null,ft.stop(),n.isPresenting=!1,t.setPixelRatio(w),t.setSize(g.width,g.height,!1),z!==null){const B=z.camera;B.fov=z.fov,B.zoom=z.zoom,B.updateProjectionMatrix(),z=null}n.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(B){r=B,n.isPresenting===!0&&jt("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(B){o=B,n.isPresenting===!0&&jt("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return c||a},this.setReferenceSpace=function(B){c=B},this.getBaseLayer=function(){return d!==null?d:m},this.getBinding=function(){return u===null&&M&&(u=new XRWebGLBinding(s,e)),u},this.getFrame=function(){return _},this.getSession=function(){return s},this.setSession=async function(B){if(s=B,s!==null){if(A=t.getRenderTarget(),s.addEventListener("select",J),s.addEventListener("selectstart",J),s.addEventListener("selectend",J),s.addEventListener("squeeze",J),s.addEventListener("squeezestart",J),s.addEventListener("squeezeend",J),s.addEventListener("end",H),s.addEventListener("inputsourceschange",ct),x.xrCompatible!==!0&&await e.makeXRCompatible(),w=t.getPixelRatio(),t.getSize(g),M&&"createProjectionLayer"in XRWebGLBinding.prototype){let ht=null,gt=null,vt=null;x.depth&&(vt=x.stencil?e.DEPTH24_STENCIL8:e.DEPTH_COMPONENT24,ht=x.stencil?Ts:Ps,gt=x.stencil?zr:Yi);const Gt={colorFormat:e.RGBA8,depthFormat:vt,scaleFactor:r};u=this.getBinding(),d=u.createProjectionLayer(Gt),s.updateRenderState({layers:[d]}),t.setPixelRatio(1),t.setSize(d.textureWidth,d.textureHeight,!1),S=new Xi(d.textureWidth,d.textureHeight,{format:Gi,type:ei,depthTexture:new kr(d.textureWidth,d.textureHeight,gt,void 0,void 0,void 0,void 0,void 0,void 0,ht),stencilBuffer:x.stencil,colorSpace:t.outputColorSpace,samples:x.antialias?4:0,resolveDepthBuffer:d.ignoreDepthValues===!1,resolveStencilBuffer:d.ignoreDepthValues===!1,storeMultisampledDepthBuffer:d.ignoreDepthValues===!1,storeMultisampledStencilBuffer:d.ignoreDepthValues===!1})}else{const ht={antialias:x.antialias,alpha:!0,depth:x.depth,stencil:x.stencil,framebufferScaleFactor:r};m=new XRWebGLLayer(s,e,ht),s.updateRenderState({baseLayer:m}),t.setPixelRatio(1),t.setSize(m.framebufferWidth,m.framebufferHeight,!1),S=new Xi(m.framebufferWidth,m.framebufferHeight,{format:Gi,type:ei,colorSpace:t.outputColorSpace,stencilBuffer:x.stencil,resolveDepthBuffer:m.ignoreDepthValues===!1,resolveStencilBuffer:m.ignoreDepthValues===!1,storeMultisampledDepthBuffer:m.ignoreDepthValues===!1,storeMultisampledStencilBuffer:m.ignoreDepthValues===!1})}S.isXRRenderTarget=!0,this.setFoveation(l),c=null,a=await s.requestReferenceSpace(o),ft.setContext(s),ft.start(),n.isPresenting=!0,n.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return p.getDepthTexture()};function ct(B){for(let et=0;et<B.removed.length;et++){const ht=B.removed[et],gt=b.indexOf(ht);gt>=0&&(b[gt]=null,R[gt].disconnect(ht))}for(let et=0;et<B.added.length;et++){const ht=B.added[et];let gt=b.indexOf(ht);if(gt===-1){for(let Gt=0;Gt<R.length;Gt++)if(Gt>=b.length){b.push(ht),gt=Gt;break}else if(b[Gt]===null){b[Gt]=ht,gt=Gt;break}if(gt===-1)break}const vt=R[gt];vt&&vt.connect(ht)}}function Z(B,et){et===null?B.matrixWorld.copy(B.matrix):B.matrixWorld.multiplyMatrices(et.matrixWorld,B.matrix),B.matrixWorldInverse.copy(B.matrixWorld).invert()}this.updateCamera=function(B){if(s===null)return;let et=B.near,ht=B.far;p.texture!==null&&(p.depthNear>0&&(et=p.depthNear),p.depthFar>0&&(ht=p.depthFar)),$.near=L.near=I.near=et,$.far=L.far=I.far=ht,(N!==$.near||W!==$.far)&&(s.updateRenderState({depthNear:$.near,depthFar:$.far}),N=$.near,W=$.far),$.layers.mask=B.layers.mask|6,I.layers.mask=$.layers.mask&-5,L.layers.mask=$.layers.mask&-3;const gt=B.parent,vt=$.cameras;Z($,gt);for(let Gt=0;Gt<vt.length;Gt++)Z(vt[Gt],gt);$.projectionMatrix.copy(I.projectionMatrix),$.projectionMatrixInverse.copy(I.projectionMatrixInverse),z===null&&B.isPerspectiveCamera&&(z={camera:B,fov:B.fov,zoom:B.zoom}),tt(B,$,gt)};function tt(B,et,ht){ht===null?B.matrix.copy(et.matrixWorld):(B.matrix.copy(ht.matrixWorld),B.matrix.invert(),B.matrix.multiply(et.matrixWorld)),B.matrix.decompose(B.position,B.quaternion,B.scale),B.updateMatrixWorld(!0),B.projectionMatrix.copy(et.projectionMatrix),B.projectionMatrixInverse.copy(et.projectionMatrixInverse),B.isPerspectiveCamera&&(B.fov=hh*2*Math.atan(1/B.projectionMatrix.elements[5]),B.zoom=1)}this.getCamera=function(){return $},this.getFoveation=function(){if(!(d===null&&m===null))return l},this.setFoveation=function(B){l=B,d!==null&&(d.fixedFoveation=B),m!==null&&m.fixedFoveation!==void 0&&(m.fixedFoveation=B)},this.hasDepthSensing=function(){return p.texture!==null},this.getDepthSensingMesh=function(){return p.getMesh($)},this.getCameraTexture=function(B){return f[B]};let st=null;function pt(B,et){if(h=et.getViewerPose(c||a),_=et,h!==null){const ht=h.views;m!==null&&(t.setRenderTargetFramebuffer(S,m.framebuffer),t.setRenderTarget(S));let gt=!1;ht.length!==$.cameras.length&&($.cameras.length=0,gt=!0);for(let kt=0;kt<ht.length;kt++){const ne=ht[kt];let ee=null;if(m!==null)ee=m.getViewport(ne);else{const Ie=u.getViewSubImage(d,ne);ee=Ie.viewport,kt===0&&(t.setRenderTargetTextures(S,Ie.colorTexture,Ie.depthStencilTexture),t.setRenderTarget(S))}let qt=V[kt];qt===void 0&&(qt=new Xn,qt.layers.enable(kt),qt.viewport=new nn,V[kt]=qt),qt.matrix.fromArray(ne.transform.matrix),qt.matrix.decompose(qt.position,qt.quaternion,qt.scale),qt.projectionMatrix.fromArray(ne.projectionMatrix),qt.projectionMatrixInverse.copy(qt.projectionMatrix).invert(),qt.viewport.set(ee.x,ee.y,ee.width,ee.height),kt===0&&($.matrix.copy(qt.matrix),$.matrix.decompose($.position,$.quaternion,$.scale)),gt===!0&&$.cameras.push(qt)}const vt=s.enabledFeatures;if(vt&&vt.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&M){u=n.getBinding();const kt=u.getDepthInformation(ht[0]);kt&&kt.isValid&&kt.texture&&p.init(kt,s.renderState)}if(vt&&vt.includes("camera-access")&&M){t.state.unbindTexture(),u=n.getBinding();for(let kt=0;kt<ht.length;kt++){const ne=ht[kt].camera;if(ne){let ee=f[ne];ee||(ee=new Np,f[ne]=ee);const qt=u.getCameraImage(ne);ee.sourceTexture=qt}}}}for(let ht=0;ht<R.length;ht++){const gt=b[ht],vt=R[ht];gt!==null&&vt!==void 0&&vt.update(gt,et,c||a)}st&&st(B,et),et.detectedPlanes&&n.dispatchEvent({type:"planesdetected",data:et}),_=null}const ft=new Gp;ft.setAnimationLoop(pt),this.setAnimationLoop=function(B){st=B},this.dispose=function(){}}}const ay=new De,jp=new re;jp.set(-1,0,0,0,1,0,0,0,1);function oy(i,t){function e(p,f){p.matrixAutoUpdate===!0&&p.updateMatrix(),f.value.copy(p.matrix)}function n(p,f){f.color.getRGB(p.fogColor.value,Ip(i)),f.isFog?(p.fogNear.value=f.near,p.fogFar.value=f.far):f.isFogExp2&&(p.fogDensity.value=f.density)}function s(p,f,x,A,S){f.isNodeMaterial?f.uniformsNeedUpdate=!1:f.isMeshBasicMaterial?r(p,f):f.isMeshLambertMaterial?(r(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshToonMaterial?(r(p,f),u(p,f)):f.isMeshPhongMaterial?(r(p,f),h(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshStandardMaterial?(r(p,f),d(p,f),f.isMeshPhysicalMaterial&&m(p,f,S)):f.isMeshMatcapMaterial?(r(p,f),_(p,f)):f.isMeshDepthMaterial?r(p,f):f.isMeshDistanceMaterial?(r(p,f),M(p,f)):f.isMeshNormalMaterial?r(p,f):f.isLineBasicMaterial?(a(p,f),f.isLineDashedMaterial&&o(p,f)):f.isPointsMaterial?l(p,f,x,A):f.isSpriteMaterial?c(p,f):f.isShadowMaterial?(p.color.value.copy(f.color),p.opacity.value=f.opacity):f.isShaderMaterial&&(f.uniformsNeedUpdate=!1)}function r(p,f){p.opacity.value=f.opacity,f.color&&p.diffuse.value.copy(f.color),f.emissive&&p.emissive.value.copy(f.emissive).multiplyScalar(f.emissiveIntensity),f.map&&(p.map.value=f.map,e(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,e(f.alphaMap,p.alphaMapTransform)),f.bumpMap&&(p.bumpMap.value=f.bumpMap,e(f.bumpMap,p.bumpMapTransform),p.bumpScale.value=f.bumpScale,f.side===Yn&&(p.bumpScale.value*=-1)),f.normalMap&&(p.normalMap.value=f.normalMap,e(f.normalMap,p.normalMapTransform),p.normalScale.value.copy(f.normalScale),f.side===Yn&&p.normalScale.value.negate()),f.displacementMap&&(p.displacementMap.value=f.displacementMap,e(f.displacementMap,p.displacementMapTransform),p.displacementScale.value=f.displacementScale,p.displacementBias.value=f.displacementBias),f.emissiveMap&&(p.emissiveMap.value=f.emissiveMap,e(f.emissiveMap,p.emissiveMapTransform)),f.specularMap&&(p.specularMap.value=f.specularMap,e(f.specularMap,p.specularMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest);const x=t.get(f),A=x.envMap,S=x.envMapRotation;A&&(p.envMap.value=A,p.envMapRotation.value.setFromMatrix4(ay.makeRotationFromEuler(S)).transpose(),A.isCubeTexture&&A.isRenderTargetTexture===!1&&p.envMapRotation.value.premultiply(jp),p.reflectivity.value=f.reflectivity,p.ior.value=f.ior,p.refractionRatio.value=f.refractionRatio),f.lightMap&&(p.lightMap.value=f.lightMap,p.lightMapIntensity.value=f.lightMapIntensity,e(f.lightMap,p.lightMapTransform)),f.aoMap&&(p.aoMap.value=f.aoMap,p.aoMapIntensity.value=f.aoMapIntensity,e(f.aoMap,p.aoMapTransform))}function a(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,f.map&&(p.map.value=f.map,e(f.map,p.mapTransform))}function o(p,f){p.dashSize.value=f.dashSize,p.totalSize.value=f.dashSize+f.gapSize,p.scale.value=f.scale}function l(p,f,x,A){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.size.value=f.size*x,p.scale.value=A*.5,f.map&&(p.map.value=f.map,e(f.map,p.uvTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,e(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function c(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.rotation.value=f.rotation,f.map&&(p.map.value=f.map,e(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,e(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function h(p,f){p.specular.value.copy(f.specular),p.shininess.value=Math.max(f.shininess,1e-4)}function u(p,f){f.gradientMap&&(p.gradientMap.value=f.gradientMap)}function d(p,f){p.metalness.value=f.metalness,f.metalnessMap&&(p.metalnessMap.value=f.metalnessMap,e(f.metalnessMap,p.metalnessMapTransform)),p.roughness.value=f.roughness,f.roughnessMap&&(p.roughnessMap.value=f.roughnessMap,e(f.roughnessMap,p.roughnessMapTransform)),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)}function m(p,f,x){p.ior.value=f.ior,f.diffuseRoughness>0&&(p.diffuseRoughness.value=f.diffuseRoughness,f.diffuseRoughnessMap&&(p.diffuseRoughnessMap.value=f.diffuseRoughnessMap,e(f.diffuseRoughnessMap,p.diffuseRoughnessMapTransform))),f.sheen>0&&(p.sheenColor.value.copy(f.sheenColor).multiplyScalar(f.sheen),p.sheenRoughness.value=f.sheenRoughness,f.sheenColorMap&&(p.sheenColorMap.value=f.sheenColorMap,e(f.sheenColorMap,p.sheenColorMapTransform)),f.sheenRoughnessMap&&(p.sheenRoughnessMap.value=f.sheenRoughnessMap,e(f.sheenRoughnessMap,p.sheenRoughnessMapTransform))),f.clearcoat>0&&(p.clearcoat.value=f.clearcoat,p.clearcoatRoughness.value=f.clearcoatRoughness,f.clearcoatMap&&(p.clearcoatMap.value=f.clearcoatMap,e(f.clearcoatMap,p.clearcoatMapTransform)),f.clearcoatRoughnessMap&&(p.clearcoatRoughnessMap.value=f.clearcoatRoughnessMap,e(f.clearcoatRoughnessMap,p.clearcoatRoughnessMapTransform)),f.clearcoatNormalMap&&(p.clearcoatNormalMap.value=f.clearcoatNormalMap,e(f.clearcoatNormalMap,p.clearcoatNormalMapTransform),p.clearcoatNormalScale.value.copy(f.clearcoatNormalScale),f.side===Yn&&p.clearcoatNormalScale.value.negate())),f.dispersion>0&&(p.dispersion.value=f.dispersion),f.retroreflectivity>0&&(p.retroreflectivity.value=f.retroreflectivity),f.iridescence>0&&(p.iridescence.value=f.iridescence,p.iridescenceIOR.value=f.iridescenceIOR,p.iridescenceThicknessMinimum.value=f.iridescenceThicknessMinimum,p.iridescenceThicknessMaximum.value=f.iridescenceThicknessMaximum,f.iridescenceMap&&(p.iridescenceMap.value=f.iridescenceMap,e(f.iridescenceMap,p.iridescenceMapTransform)),f.iridescenceThicknessMap&&(p.iridescenceThicknessMap.value=f.iridescenceThicknessMap,e(f.iridescenceThicknessMap,p.iridescenceThicknessMapTransform))),f.transmission>0&&(p.transmission.value=f.transmission,p.transmissionSamplerMap.value=x.texture,p.transmissionSamplerSize.value.set(x.width,x.height),f.transmissionMap&&(p.transmissionMap.value=f.transmissionMap,e(f.transmissionMap,p.transmissionMapTransform)),p.thickness.value=f.thickness,f.thicknessMap&&(p.thicknessMap.value=f.thicknessMap,e(f.thicknessMap,p.thicknessMapTransform)),p.attenuationDistance.value=f.attenuationDistance,p.attenuationColor.value.copy(f.attenuationColor)),f.anisotropy>0&&(p.anisotropyVector.value.set(f.anisotropy*Math.cos(f.anisotropyRotation),f.anisotropy*Math.sin(f.anisotropyRotation)),f.anisotropyMap&&(p.anisotropyMap.value=f.anisotropyMap,e(f.anisotropyMap,p.anisotropyMapTransform))),p.specularIntensity.value=f.specularIntensity,p.specularColor.value.copy(f.specularColor),f.specularColorMap&&(p.specularColorMap.value=f.specularColorMap,e(f.specularColorMap,p.specularColorMapTransform)),f.specularIntensityMap&&(p.specularIntensityMap.value=f.specularIntensityMap,e(f.specularIntensityMap,p.specularIntensityMapTransform))}function _(p,f){f.matcap&&(p.matcap.value=f.matcap)}function M(p,f){const x=t.get(f).light;p.referencePosition.value.setFromMatrixPosition(x.matrixWorld),p.nearDistance.value=x.shadow.camera.near,p.farDistance.value=x.shadow.camera.far}return{refreshFogUniforms:n,refreshMaterialUniforms:s}}function ly(i,t,e,n){let s={},r={};function a(x,A){const S=A.program;n.uniformBlockBinding(x,S,s[x.id])}function o(x,A){let S=s[x.id];S===void 0&&(_(x),S=l(x),s[x.id]=S,x.addEventListener("dispose",p));const R=A.program;n.updateUBOMapping(x,R);const b=t.render.frame;r[x.id]!==b&&(c(x),r[x.id]=b)}function l(x){const A=i.createBuffer(),S=x.__size,R=x.usage;return i.bindBuffer(i.UNIFORM_BUFFER,A),i.bufferData(i.UNIFORM_BUFFER,S,R),i.bindBuffer(i.UNIFORM_BUFFER,null),A}function c(x){const A=s[x.id],S=x.uniforms,R=x.__cache;i.bindBuffer(i.UNIFORM_BUFFER,A);for(let b=0,g=S.length;b<g;b++){const w=S[b];if(Array.isArray(w))for(let z=0,I=w.length;z<I;z++)h(w[z],b,z,R);else h(w,b,0,R)}i.bindBuffer(i.UNIFORM_BUFFER,null)}function h(x,A,S,R){if(d(x,A,S,R)===!0){const b=x.__offset,g=x.value;if(Array.isArray(g)){let w=0;for(let z=0;z<g.length;z++){const I=g[z],L=M(I,!0);u(I,x.__data,w),w+=L.storage/Float32Array.BYTES_PER_ELEMENT}}else u(g,x.__data,0);i.bufferSubData(i.UNIFORM_BUFFER,b,x.__data)}}function u(x,A,S){typeof x=="number"||typeof x=="boolean"?A[S]=x:x.isMatrix3?(A[S]=x.elements[0],A[S+1]=x.elements[1],A[S+2]=x.elements[2],A[S+3]=0,A[S+4]=x.elements[3],A[S+5]=x.elements[4],A[S+6]=x.elements[5],A[S+7]=0,A[S+8]=x.elements[6],A[S+9]=x.elements[7],A[S+10]=x.elements[8],A[S+11]=0):ArrayBuffer.isView(x)?A.set(x.subarray(0,A.length-S),S):x.toArray(A,S)}function d(x,A,S,R){const b=x.value,g=A+"_"+S;if(Array.isArray(b)){R[g]===void 0&&(R[g]=[]);const w=R[g];let z=!1;for(let I=0;I<b.length;I++)m(b[I],w,I)===!0&&(z=!0);return z}return m(b,R,g)}function m(x,A,S){if(A[S]===void 0)return typeof x=="number"||typeof x=="boolean"?A[S]=x:ArrayBuffer.isView(x)?A[S]=x.slice():A[S]=x.clone(),!0;{const R=A[S];if(typeof x=="number"||typeof x=="boolean"){if(R!==x)return A[S]=x,!0}else{if(ArrayBuffer.isView(x))return!0;if(R.equals(x)===!1)return R.copy(x),!0}}return!1}function _(x){const A=x.uniforms;let S=0;const R=16;for(let g=0,w=A.length;g<w;g++){const z=Array.isArray(A[g])?A[g]:[A[g]];for(let I=0,L=z.length;I<L;I++){const V=z[I],$=Array.isArray(V.value)?V.value:[V.value],N=Array.isArray(A[g])||Array.isArray(V.value);let W=S;for(let H=0,ct=$.length;H<ct;H++){const Z=$[H],tt=M(Z,N),st=S%R,pt=st%tt.boundary,ft=st+pt;S+=pt,ft!==0&&R-ft<tt.storage&&(S+=R-ft),H===0&&(W=S),S+=tt.storage}const J=V.type==="int"?Int32Array:V.type==="uint"?Uint32Array:Float32Array;V.__data=new J((S-W)/Float32Array.BYTES_PER_ELEMENT),V.__offset=W}}const b=S%R;return b>0&&(S+=R-b),x.__size=S,x.__cache={},this}function M(x,A){const S={boundary:0,storage:0};return typeof x=="number"||typeof x=="boolean"?(S.boundary=4,S.storage=4):x.isVector2?(S.boundary=8,S.storage=8):x.isVector3||x.isColor?(S.boundary=16,S.storage=12):x.isVector4?(S.boundary=16,S.storage=16):x.isMatrix3?(S.boundary=16,S.storage=48):x.isMatrix4?(S.boundary=16,S.storage=64):x.isTexture?jt("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(x)?(S.boundary=16,S.storage=x.byteLength):jt("WebGLRenderer: Unsupported uniform value type.",x),A===!0&&(S.boundary=16,S.storage=Math.ceil(S.storage/16)*16),S}function p(x){const A=x.target;A.removeEventListener("dispose",p),i.deleteBuffer(s[A.id]),delete s[A.id],delete r[A.id]}function f(){for(const x in s)i.deleteBuffer(s[x]);s={},r={}}return{bind:a,update:o,dispose:f}}const cy=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]);let Fi=null;function hy(){return Fi===null&&(Fi=new t_(cy,16,16,Ks,qi),Fi.name="DFG_LUT",Fi.minFilter=$n,Fi.magFilter=$n,Fi.wrapS=as,Fi.wrapT=as,Fi.generateMipmaps=!1,Fi.needsUpdate=!0),Fi}class Qp{constructor(t={}){const{canvas:e=A0(),context:n=null,depth:s=!0,stencil:r=!1,alpha:a=!1,antialias:o=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:c=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:u=!1,reversedDepthBuffer:d=!1,outputBufferType:m=ei}=t;this.isWebGLRenderer=!0;let _;if(n!==null){if(typeof WebGLRenderingContext<"u"&&n instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");_=n.getContextAttributes().alpha}else _=a;const M=m,p=new Set([Hh,kh,zh]),f=new Set([ei,Yi,La,zr,Oh,Bh]),x=new Uint32Array(4),A=new Int32Array(4),S={textures:[],min:[],max:[],resolution:[]};let R=null,b=null;const g=[],w=[];let z=null;this.domElement=e,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=os,this.toneMappingExposure=1,this.transmissionResolutionScale=1;const I=this;let L=!1,V=null,$=null,N=null,W=null;this._outputColorSpace=ci;let J=0,H=0,ct=null,Z=-1,tt=null;const st=new nn,pt=new nn;let ft=null;const B=new ce(0);let et=0,ht=e.width,gt=e.height,vt=1,Gt=null,Qt=null;const kt=new nn(0,0,ht,gt),ne=new nn(0,0,ht,gt);let ee=!1;const qt=new Na,Ie=new Wh;let me=!1,Xe=!1;const Me=new De,rn=new k,de=new nn,pn={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0};let qe=!1;function an(){return ct===null?vt:1}let F=n;function Ct(T,G){return e.getContext(T,G)}let Yt,se,Et,Ue,Ht,$t,C,y,Y,dt,ot,St,Mt,nt,rt,_t,U,at,it,wt,xt,bt,Vt;try{const T={alpha:!0,depth:s,stencil:r,antialias:o,premultipliedAlpha:l,preserveDrawingBuffer:c,powerPreference:h,failIfMajorPerformanceCaveat:u};if("setAttribute"in e&&e.setAttribute("data-engine",`three.js r${Uh}`),e.addEventListener("webglcontextlost",Ot,!1),e.addEventListener("webglcontextrestored",Jt,!1),e.addEventListener("webglcontextcreationerror",Rt,!1),F===null){const G="webgl2";if(F=Ct(G,T),F===null)throw Ct(G)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}Zt()}catch(T){throw e.removeEventListener("webglcontextlost",Ot,!1),e.removeEventListener("webglcontextrestored",Jt,!1),e.removeEventListener("webglcontextcreationerror",Rt,!1),Se("WebGLRenderer: "+T.message),T}function Zt(){Yt=new pS(F),Yt.init(),xt=new ey(F,Yt),se=new iS(F,Yt,t,xt),Et=new QM(F,Yt),se.reversedDepthBuffer&&d&&Et.buffers.depth.setReversed(!0),$=F.createFramebuffer(),N=F.createFramebuffer(),W=F.createFramebuffer(),Ue=new _S(F),Ht=new zM,$t=new ty(F,Yt,Et,Ht,se,xt,Ue),C=new fS(I),y=new x_(F),bt=new eS(F,y),Y=new mS(F,y,Ue,bt),dt=new xS(F,Y,y,bt,Ue),at=new vS(F,se,$t),rt=new sS(Ht),ot=new BM(I,C,Yt,se,bt,rt),St=new oy(I,Ht),Mt=new HM,nt=new YM(Yt),U=new tS(I,C,Et,dt,_,l),_t=new jM(I,dt,se),Vt=new ly(F,Ue,se,Et),it=new nS(F,Yt,Ue),wt=new gS(F,Yt,Ue),Ue.programs=ot.programs,I.capabilities=se,I.extensions=Yt,I.properties=Ht,I.renderLists=Mt,I.shadowMap=_t,I.state=Et,I.info=Ue}M!==ei&&(z=new MS(M,e.width,e.height,o,s,r));const ut=new ry(I,F);this.xr=ut,this.getContext=function(){return F},this.getContextAttributes=function(){return F.getContextAttributes()},this.forceContextLoss=function(){const T=Yt.get("WEBGL_lose_context");T&&T.loseContext()},this.forceContextRestore=function(){const T=Yt.get("WEBGL_lose_context");T&&T.restoreContext()},this.getPixelRatio=function(){return vt},this.setPixelRatio=function(T){T!==void 0&&(vt=T,this.setSize(ht,gt,!1))},this.getSize=function(T){return T.set(ht,gt)},this.setSize=function(T,G,Q=!0){if(ut.isPresenting){jt("WebGLRenderer: Can't change size while VR device is presenting.");return}ht=T,gt=G,e.width=Math.floor(T*vt),e.height=Math.floor(G*vt),Q===!0&&(e.style.width=T+"px",e.style.height=G+"px"),z!==null&&z.setSize(e.width,e.height),this.setViewport(0,0,T,G)},this.getDrawingBufferSize=function(T){return T.set(ht*vt,gt*vt).floor()},this.setDrawingBufferSize=function(T,G,Q){ht=T,gt=G,vt=Q,e.width=Math.floor(T*Q),e.height=Math.floor(G*Q),this.setViewport(0,0,T,G)},this.setEffects=function(T){if(M===ei){Se("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(T){for(let G=0;G<T.length;G++)if(T[G].isOutputPass===!0){jt("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}z.setEffects(T||[])},this.getCurrentViewport=function(T){return T.copy(st)},this.getViewport=function(T){return T.copy(kt)},this.setViewport=function(T,G,Q,q){T.isVector4?kt.set(T.x,T.y,T.z,T.w):kt.set(T,G,Q,q),Et.viewport(st.copy(kt).multiplyScalar(an()).round())},this.getScissor=function(T){return T.copy(ne)},this.setScissor=function(T,G,Q,q){T.isVector4?ne.set(T.x,T.y,T.z,T.w):ne.set(T,G,Q,q),Et.scissor(pt.copy(ne).multiplyScalar(an()).round())},this.getScissorTest=function(){return ee},this.setScissorTest=function(T){Et.setScissorTest(ee=T)},this.setOpaqueSort=function(T){Gt=T},this.setTransparentSort=function(T){Qt=T},this.getClearColor=function(T){return T.copy(U.getClearColor())},this.setClearColor=function(){U.setClearColor(...arguments)},this.getClearAlpha=function(){return U.getClearAlpha()},this.setClearAlpha=function(){U.setClearAlpha(...arguments)},this.clear=function(T=!0,G=!0,Q=!0){let q=0;if(T){let K=!1;if(ct!==null){const Tt=ct.texture.format;K=p.has(Tt)}if(K){const Tt=ct.texture.type,Pt=f.has(Tt),At=U.getClearColor(),Lt=U.getClearAlpha(),zt=At.r,te=At.g,he=At.b;Pt?(x[0]=zt,x[1]=te,x[2]=he,x[3]=Lt,F.clearBufferuiv(F.COLOR,0,x)):(A[0]=zt,A[1]=te,A[2]=he,A[3]=Lt,F.clearBufferiv(F.COLOR,0,A))}else q|=F.COLOR_BUFFER_BIT}G&&(q|=F.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),Q&&(q|=F.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),q!==0&&F.clear(q)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(T){T.setRenderer(this),V=T},this.dispose=function(){e.removeEventListener("webglcontextlost",Ot,!1),e.removeEventListener("webglcontextrestored",Jt,!1),e.removeEventListener("webglcontextcreationerror",Rt,!1),U.dispose(),Mt.dispose(),nt.dispose(),$t.dispose(),Ht.dispose(),C.dispose(),dt.dispose(),Y.dispose(),bt.dispose(),Vt.dispose(),ot.dispose(),ut.dispose(),ut.removeEventListener("sessionstart",Wa),ut.removeEventListener("sessionend",Ri),Zi.stop()};function Ot(T){T.preventDefault(),$o("WebGLRenderer: Context Lost."),L=!0}function Jt(){$o("WebGLRenderer: Context Restored."),L=!1;const T=Ue.autoReset,G=_t.enabled,Q=_t.autoUpdate,q=_t.needsUpdate,K=_t.type;Zt(),Ue.autoReset=T,_t.enabled=G,_t.autoUpdate=Q,_t.needsUpdate=q,_t.type=K}function Rt(T){Se("WebGLRenderer: A WebGL context could not be created. Reason: ",T.statusMessage)}function ae(T){const G=T.target;G.removeEventListener("dispose",ae),ze(G)}function ze(T){Fn(T),Ht.remove(T)}function Fn(T){const G=Ht.get(T).programs;G!==void 0&&(G.forEach(function(Q){ot.releaseProgram(Q)}),T.isShaderMaterial&&ot.releaseShaderCache(T))}this.renderBufferDirect=function(T,G,Q,q,K,Tt){G===null&&(G=pn);const Pt=K.isMesh&&K.matrixWorld.determinantAffine()<0,At=Qr(T,G,Q,q,K);Et.setMaterial(q,Pt);let Lt=Q.index,zt=1;if(q.wireframe===!0){if(Lt=Y.getWireframeAttribute(Q),Lt===void 0)return;zt=2}const te=Q.drawRange,he=Q.attributes.position;let Bt=te.start*zt,ue=(te.start+te.count)*zt;Tt!==null&&(Bt=Math.max(Bt,Tt.start*zt),ue=Math.min(ue,(Tt.start+Tt.count)*zt)),Lt!==null?(Bt=Math.max(Bt,0),ue=Math.min(ue,Lt.count)):he!=null&&(Bt=Math.max(Bt,0),ue=Math.min(ue,he.count));const $e=ue-Bt;if($e<0||$e===1/0)return;bt.setup(K,q,At,Q,Lt);let Re,Ce=it;if(Lt!==null&&(Re=y.get(Lt),Ce=wt,Ce.setIndex(Re)),K.isMesh)q.wireframe===!0?(Et.setLineWidth(q.wireframeLinewidth*an()),Ce.setMode(F.LINES)):Ce.setMode(F.TRIANGLES);else if(K.isLine){let mn=q.linewidth;mn===void 0&&(mn=1),Et.setLineWidth(mn*an()),K.isLineSegments?Ce.setMode(F.LINES):K.isLineLoop?Ce.setMode(F.LINE_LOOP):Ce.setMode(F.LINE_STRIP)}else K.isPoints?Ce.setMode(F.POINTS):K.isSprite&&Ce.setMode(F.TRIANGLES);if(K.isBatchedMesh)if(Yt.get("WEBGL_multi_draw"))Ce.renderMultiDraw(K._multiDrawStarts,K._multiDrawCounts,K._multiDrawCount);else{const mn=K._multiDrawStarts,Ut=K._multiDrawCounts,on=K._multiDrawCount,ge=Lt?y.get(Lt).bytesPerElement:1,ji=Ht.get(q).currentProgram.getUniforms();for(let ln=0;ln<on;ln++)ji.setValue(F,"_gl_DrawID",ln),Ce.render(mn[ln]/ge,Ut[ln])}else if(K.isInstancedMesh)Ce.renderInstances(Bt,$e,K.count);else if(Q.isInstancedBufferGeometry){const mn=Q._maxInstanceCount!==void 0?Q._maxInstanceCount:1/0,Ut=Math.min(Q.instanceCount,mn);Ce.renderInstances(Bt,$e,Ut)}else Ce.render(Bt,$e)};function Zr(T,G,Q,q){V!==null&&T.isNodeMaterial&&V.setObject(q,T),me===!0&&rt.setState(T,Q,!1),T.transparent===!0&&T.side===di&&T.forceSinglePass===!1?(T.side=Yn,T.needsUpdate=!0,Ci(T,G,q),T.side=Cs,T.needsUpdate=!0,Ci(T,G,q),T.side=di):Ci(T,G,q)}this.compile=function(T,G,Q=null){Q===null&&(Q=T),V!==null&&V.renderStart(T,G,Q),b=nt.get(Q),b.init(G),w.push(b),Q.traverseVisible(function(K){K.isLight&&K.layers.test(G.layers)&&(b.pushLight(K),K.castShadow&&b.pushShadow(K))}),T!==Q&&T.traverseVisible(function(K){K.isLight&&K.layers.test(G.layers)&&(b.pushLight(K),K.castShadow&&b.pushShadow(K))}),b.setupLights(),V!==null&&V.updateLights(b.state.lightsArray),Xe=this.localClippingEnabled,me=rt.init(this.clippingPlanes,Xe),me===!0&&rt.setGlobalState(this.clippingPlanes,G),V!==null&&_t.render(b.state.shadowsArray,Q,G);const q=new Set;return T.traverse(function(K){if(!(K.isMesh||K.isPoints||K.isLine||K.isSprite))return;const Tt=K.material;if(Tt)if(Array.isArray(Tt))for(let Pt=0;Pt<Tt.length;Pt++){const At=Tt[Pt];Zr(At,Q,G,K),q.add(At)}else Zr(Tt,Q,G,K),q.add(Tt)}),b=w.pop(),V!==null&&V.renderEnd(),q},this.compileAsync=function(T,G,Q=null){const q=this.compile(T,G,Q);return new Promise(K=>{function Tt(){if(q.forEach(function(Pt){const Lt=Ht.get(Pt).currentProgram;(Lt===void 0||Lt.isReady())&&q.delete(Pt)}),q.size===0){K(T);return}setTimeout(Tt,10)}Yt.get("KHR_parallel_shader_compile")!==null?Tt():setTimeout(Tt,10)})};let er=null;function ml(T){er&&er(T)}function Wa(){Zi.stop()}function Ri(){Zi.start()}const Zi=new Gp;Zi.setAnimationLoop(ml),typeof self<"u"&&Zi.setContext(self),this.setAnimationLoop=function(T){er=T,ut.setAnimationLoop(T),T===null?Zi.stop():Zi.start()},ut.addEventListener("sessionstart",Wa),ut.addEventListener("sessionend",Ri),this.render=function(T,G){if(G!==void 0&&G.isCamera!==!0){Se("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(L===!0)return;V!==null&&V.renderStart(T,G);const Q=ut.enabled===!0&&ut.isPresenting===!0,q=z!==null&&(ct===null||Q)&&z.begin(I,ct);if(T.matrixWorldAutoUpdate===!0&&T.updateMatrixWorld(),G.parent===null&&G.matrixWorldAutoUpdate===!0&&G.updateMatrixWorld(),ut.enabled===!0&&ut.isPresenting===!0&&(z===null||z.isCompositing()===!1)&&(ut.cameraAutoUpdate===!0&&ut.updateCamera(G),G=ut.getCamera()),T.isScene===!0&&T.onBeforeRender(I,T,G,ct),b=nt.get(T,w.length),b.init(G),b.state.textureUnits=$t.getTextureUnits(),w.push(b),Me.multiplyMatrices(G.projectionMatrix,G.matrixWorldInverse),G.isArrayCamera?Ie.setFromArrayCamera(G):qt.setFromProjectionMatrix(Me,Ai,G.reversedDepth),Xe=this.localClippingEnabled,me=rt.init(this.clippingPlanes,Xe),R=Mt.get(T,g.length),R.init(),g.push(R),this.info.render.frame++,ut.enabled===!0&&ut.isPresenting===!0){const Pt=I.xr.getDepthSensingMesh();Pt!==null&&Ji(Pt,G,-1/0,I.sortObjects)}Ji(T,G,0,I.sortObjects),R.finish(),V!==null&&V.updateLights(b.state.lightsArray),I.sortObjects===!0&&R.sort(Gt,Qt),qe=ut.enabled===!1||ut.isPresenting===!1||ut.hasDepthSensing()===!1,qe&&U.addToRenderList(R,T),this.info.autoReset===!0&&this.info.reset(),me===!0&&rt.beginShadows();const K=b.state.shadowsArray;if(_t.render(K,T,G),me===!0&&rt.endShadows(),(q&&z.hasRenderPass())===!1){const Pt=R.opaque,At=R.transmissive;if(b.setupLights(),G.isArrayCamera){const Lt=G.cameras;if(At.length>0)for(let zt=0,te=Lt.length;zt<te;zt++){const he=Lt[zt];gi(Pt,At,T,he)}qe&&U.render(T);for(let zt=0,te=Lt.length;zt<te;zt++){const he=Lt[zt];Jr(R,T,he,he.viewport)}}else At.length>0&&gi(Pt,At,T,G),qe&&U.render(T),Jr(R,T,G)}ct!==null&&H===0&&($t.updateMultisampleRenderTarget(ct),$t.updateRenderTargetMipmap(ct)),q&&z.end(I),T.isScene===!0&&T.onAfterRender(I,T,G),bt.resetDefaultState(),Z=-1,tt=null,w.pop(),w.length>0?(b=w[w.length-1],$t.setTextureUnits(b.state.textureUnits),me===!0&&rt.setGlobalState(I.clippingPlanes,b.state.camera)):b=null,g.pop(),g.length>0?R=g[g.length-1]:R=null,V!==null&&V.renderEnd()};function Ji(T,G,Q,q){if(T.visible===!1)return;if(T.layers.test(G.layers)){if(T.isGroup)Q=T.renderOrder;else if(T.isLOD)T.autoUpdate===!0&&T.update(G);else if(T.isLight)b.pushLight(T),T.castShadow&&b.pushShadow(T);else if(T.isSprite){const Pt=G.isArrayCamera?Ie:qt;if(!T.frustumCulled||T.intersectsFrustum(Pt)){q&&de.setFromMatrixPosition(T.matrixWorld).applyMatrix4(Me);const At=dt.update(T),Lt=T.material;Lt.visible&&R.push(T,At,Lt,Q,de.z,null,G)}}else if(T.isMesh||T.isLine||T.isPoints){const Pt=G.isArrayCamera?Ie:qt;if(!T.frustumCulled||T.intersectsFrustum(Pt)){const At=dt.update(T),Lt=T.material;if(q&&(T.boundingSphere!==void 0?(T.boundingSphere===null&&T.computeBoundingSphere(),de.copy(T.boundingSphere.center)):(At.boundingSphere===null&&At.computeBoundingSphere(),de.copy(At.boundingSphere.center)),de.applyMatrix4(T.matrixWorld).applyMatrix4(Me)),Array.isArray(Lt)){const zt=At.groups;for(let te=0,he=zt.length;te<he;te++){const Bt=zt[te],ue=Lt[Bt.materialIndex];ue&&ue.visible&&R.push(T,At,ue,Q,de.z,Bt,G)}}else Lt.visible&&R.push(T,At,Lt,Q,de.z,null,G)}}}const Tt=T.children;for(let Pt=0,At=Tt.length;Pt<At;Pt++)Ji(Tt[Pt],G,Q,q)}function Jr(T,G,Q,q){const{opaque:K,transmissive:Tt,transparent:Pt}=T;b.setupLightsView(Q),me===!0&&rt.setGlobalState(I.clippingPlanes,Q),q&&Et.viewport(st.copy(q)),K.length>0&&Ke(K,G,Q),Tt.length>0&&Ke(Tt,G,Q),Pt.length>0&&Ke(Pt,G,Q),Et.buffers.depth.setTest(!0),Et.buffers.depth.setMask(!0),Et.buffers.color.setMask(!0),Et.setPolygonOffset(!1)}function gi(T,G,Q,q){if((Q.isScene===!0?Q.overrideMaterial:null)!==null)return;if(b.state.transmissionRenderTarget[q.id]===void 0){const Bt=Yt.has("EXT_color_buffer_half_float")||Yt.has("EXT_color_buffer_float");b.state.transmissionRenderTarget[q.id]=new Xi(1,1,{generateMipmaps:!0,type:Bt?qi:ei,minFilter:ws,samples:Math.max(4,se.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:xe.workingColorSpace})}const Tt=b.state.transmissionRenderTarget[q.id],Pt=q.viewport||st;Tt.setSize(Pt.z*I.transmissionResolutionScale,Pt.w*I.transmissionResolutionScale);const At=I.getRenderTarget(),Lt=I.getActiveCubeFace(),zt=I.getActiveMipmapLevel();I.setRenderTarget(Tt),I.getClearColor(B),et=I.getClearAlpha(),et<1&&I.setClearColor(16777215,.5),I.clear(),qe&&U.render(Q);const te=I.toneMapping;I.toneMapping=os;const he=q.viewport;if(q.viewport!==void 0&&(q.viewport=void 0),b.setupLightsView(q),me===!0&&rt.setGlobalState(I.clippingPlanes,q),Ke(T,Q,q),$t.updateMultisampleRenderTarget(Tt),$t.updateRenderTargetMipmap(Tt),Yt.has("WEBGL_multisampled_render_to_texture")===!1){let Bt=!1;for(let ue=0,$e=G.length;ue<$e;ue++){const Re=G[ue],{object:Ce,geometry:mn,material:Ut,group:on}=Re;if(Ut.side===di&&Ce.layers.test(q.layers)){const ge=Ut.side;Ut.side=Yn,Ut.needsUpdate=!0,tn(Ce,Q,q,mn,Ut,on),Ut.side=ge,Ut.needsUpdate=!0,Bt=!0}}Bt===!0&&($t.updateMultisampleRenderTarget(Tt),$t.updateRenderTargetMipmap(Tt))}I.setRenderTarget(At,Lt,zt),I.setClearColor(B,et),he!==void 0&&(q.viewport=he),I.toneMapping=te}function Ke(T,G,Q){const q=G.isScene===!0?G.overrideMaterial:null;for(let K=0,Tt=T.length;K<Tt;K++){const Pt=T[K],{object:At,geometry:Lt,group:zt}=Pt;let te=Pt.material;te.allowOverride===!0&&q!==null&&(te=q),At.layers.test(Q.layers)&&tn(At,G,Q,Lt,te,zt)}}function tn(T,G,Q,q,K,Tt){V!==null&&K.isNodeMaterial&&V.setObject(T,K),T.onBeforeRender(I,G,Q,q,K,Tt),T.modelViewMatrix.multiplyMatrices(Q.matrixWorldInverse,T.matrixWorld),T.normalMatrix.getNormalMatrix(T.modelViewMatrix),K.onBeforeRender(I,G,Q,q,T,Tt),K.transparent===!0&&K.side===di&&K.forceSinglePass===!1?(K.side=Yn,K.needsUpdate=!0,I.renderBufferDirect(Q,G,q,K,T,Tt),K.side=Cs,K.needsUpdate=!0,I.renderBufferDirect(Q,G,q,K,T,Tt),K.side=di):I.renderBufferDirect(Q,G,q,K,T,Tt),T.onAfterRender(I,G,Q,q,K,Tt)}function en(T){let G=0;for(const Q of T)Q.texture!==null&&G++;return G}function Ci(T,G,Q){G.isScene!==!0&&(G=pn);const q=Ht.get(T),K=b.state.lights,Tt=b.state.shadowsArray,Pt=K.state.version,At=ot.getParameters(T,K.state,Tt,G,Q,b.state.lightProbeGridArray),Lt=ot.getProgramCacheKey(At);let zt=q.programs;q.environment=T.isMeshStandardMaterial||T.isMeshLambertMaterial||T.isMeshPhongMaterial?G.environment:null,q.fog=G.fog;const te=T.isMeshStandardMaterial||T.isMeshLambertMaterial&&!T.envMap||T.isMeshPhongMaterial&&!T.envMap;q.envMap=C.get(T.envMap||q.environment,te),q.envMapRotation=q.environment!==null&&T.envMap===null?G.environmentRotation:T.envMapRotation,zt===void 0&&(T.addEventListener("dispose",ae),zt=new Map,q.programs=zt,q.programVariants=new Map);let he=zt.get(Lt);if(he!==void 0){if(q.currentProgram===he&&q.lightsStateVersion===Pt)return jr(T,At),he}else At.uniforms=ot.getUniforms(T),V!==null&&T.isNodeMaterial&&V.build(T,Q,At),T.onBeforeCompile(At,I),he=ot.acquireProgram(At,Lt),zt.set(Lt,he),q.uniforms=At.uniforms;const Bt=q.uniforms;return(!T.isShaderMaterial&&!T.isRawShaderMaterial||T.clipping===!0)&&(Bt.clippingPlanes=rt.uniform),jr(T,At),q.needsLights=ds(T),q.lightsStateVersion=Pt,q.needsLights&&(Bt.ambientLightColor.value=K.state.ambient,Bt.lightProbe.value=K.state.probe,Bt.sunLights.value=K.state.sun,Bt.sunLightShadows.value=K.state.sunShadow,Bt.directionalLights.value=K.state.directional,Bt.directionalLightShadows.value=K.state.directionalShadow,Bt.spotLights.value=K.state.spot,Bt.spotLightShadows.value=K.state.spotShadow,Bt.rectAreaLights.value=K.state.rectArea,Bt.ltc_1.value=K.state.rectAreaLTC1,Bt.ltc_2.value=K.state.rectAreaLTC2,Bt.pointLights.value=K.state.point,Bt.pointLightShadows.value=K.state.pointShadow,Bt.hemisphereLights.value=K.state.hemi,Bt.sunShadowMatrix.value=K.state.sunShadowMatrix,Bt.sunShadowCascade.value=K.state.sunShadowCascade,Bt.directionalShadowMatrix.value=K.state.directionalShadowMatrix,Bt.spotLightMatrix.value=K.state.spotLightMatrix,Bt.spotLightMap.value=K.state.spotLightMap,Bt.pointShadowMatrix.value=K.state.pointShadowMatrix),q.numLightProbeGrids=en(b.state.lightProbeGridArray),q.currentProgram=he,q.uniformsList=null,he}function qn(T,G,Q,q,K){const Tt=Ht.get(T),Pt=Tt.currentProgram.id+","+q+","+K;let At=Tt.programVariants.get(Pt);return At===void 0?(At=Ci(T,G,Q),Tt.programVariants.set(Pt,At)):(Tt.currentProgram=At,Tt.uniformsList=null,Tt.outputColorSpace=q,Tt.toneMapping=K),At}function us(T){if(T.uniformsList===null){const G=T.currentProgram.getUniforms();T.uniformsList=zo.seqWithValue(G.seq,T.uniforms)}return T.uniformsList}function jr(T,G){const Q=Ht.get(T);Q.outputColorSpace=G.outputColorSpace,Q.batching=G.batching,Q.batchingColor=G.batchingColor,Q.instancing=G.instancing,Q.instancingColor=G.instancingColor,Q.instancingMorph=G.instancingMorph,Q.skinning=G.skinning,Q.morphTargets=G.morphTargets,Q.morphNormals=G.morphNormals,Q.morphColors=G.morphColors,Q.morphTargetsCount=G.morphTargetsCount,Q.numClippingPlanes=G.numClippingPlanes,Q.numIntersection=G.numClipIntersection,Q.vertexAlphas=G.vertexAlphas,Q.vertexTangents=G.vertexTangents,Q.toneMapping=G.toneMapping}function Qr(T,G,Q,q,K){G.isScene!==!0&&(G=pn),$t.resetTextureUnits();const Tt=G.fog,Pt=q.isMeshStandardMaterial||q.isMeshLambertMaterial||q.isMeshPhongMaterial?G.environment:null,At=ct===null?I.outputColorSpace:ct.isXRRenderTarget===!0?ct.texture.colorSpace:xe.workingColorSpace,Lt=q.isMeshStandardMaterial||q.isMeshLambertMaterial&&!q.envMap||q.isMeshPhongMaterial&&!q.envMap,zt=C.get(q.envMap||Pt,Lt),te=q.vertexColors===!0&&!!Q.attributes.color&&Q.attributes.color.itemSize===4,he=!!Q.attributes.tangent&&(!!q.normalMap||q.anisotropy>0),Bt=!!Q.morphAttributes.position,ue=!!Q.morphAttributes.normal,$e=!!Q.morphAttributes.color;let Re=os;q.toneMapped&&(ct===null||ct.isXRRenderTarget===!0)&&(Re=I.toneMapping);const Ce=Q.morphAttributes.position||Q.morphAttributes.normal||Q.morphAttributes.color,mn=Ce!==void 0?Ce.length:0,Ut=Ht.get(q),on=b.state.lights;if(me===!0&&(Xe===!0||T!==tt)){const Pe=T===tt&&q.id===Z;rt.setState(q,T,Pe)}let ge=!1,ji=!1;q.version===Ut.__version?Ut.needsLights&&Ut.lightsStateVersion!==on.state.version||K.isBatchedMesh&&Ut.batching===!1||!K.isBatchedMesh&&Ut.batching===!0||K.isBatchedMesh&&Ut.batchingColor===!0&&K._colorsTexture===null||K.isBatchedMesh&&Ut.batchingColor===!1&&K._colorsTexture!==null||K.isInstancedMesh&&Ut.instancing===!1||!K.isInstancedMesh&&Ut.instancing===!0||K.isSkinnedMesh&&Ut.skinning===!1||!K.isSkinnedMesh&&Ut.skinning===!0||K.isInstancedMesh&&Ut.instancingColor===!0&&K.instanceColor===null||K.isInstancedMesh&&Ut.instancingColor===!1&&K.instanceColor!==null||K.isInstancedMesh&&Ut.instancingMorph===!0&&K.morphTexture===null||K.isInstancedMesh&&Ut.instancingMorph===!1&&K.morphTexture!==null||Ut.envMap!==zt||q.fog===!0&&Ut.fog!==Tt||Ut.numClippingPlanes!==void 0&&(Ut.numClippingPlanes!==rt.numPlanes||Ut.numIntersection!==rt.numIntersection)||Ut.vertexAlphas!==te||Ut.vertexTangents!==he||Ut.morphTargets!==Bt||Ut.morphNormals!==ue||Ut.morphColors!==$e||Ut.morphTargetsCount!==mn||Ut.numLightProbeGrids!==en(b.state.lightProbeGridArray)?ge=!0:(Ut.outputColorSpace!==At||Ut.toneMapping!==Re)&&(ji=!0):(ge=!0,Ut.__version=q.version);let ln=Ut.currentProgram;(ge===!0||ji===!0)&&(ln=ji===!0?qn(q,G,K,At,Re):Ci(q,G,K),V&&q.isNodeMaterial&&V.onUpdateProgram(q,ln,Ut));let sr=!1,Pi=!1,Qi=!1;const oe=ln.getUniforms(),Ze=Ut.uniforms;if(Et.useProgram(ln.program)&&(sr=!0,Pi=!0,Qi=!0),q.id!==Z&&(Z=q.id,Pi=!0),sr||tt!==T){Et.buffers.depth.getReversed()&&T.reversedDepth!==!0&&(T._reversedDepth=!0,T.updateProjectionMatrix()),oe.setValue(F,"projectionMatrix",T.projectionMatrix),oe.setValue(F,"viewMatrix",T.matrixWorldInverse);const cn=oe.map.cameraPosition;cn!==void 0&&cn.setValue(F,rn.setFromMatrixPosition(T.matrixWorld)),se.logarithmicDepthBuffer&&oe.setValue(F,"logDepthBufFC",2/(Math.log(T.far+1)/Math.LN2)),(q.isMeshPhongMaterial||q.isMeshToonMaterial||q.isMeshLambertMaterial||q.isMeshBasicMaterial||q.isMeshStandardMaterial||q.isShaderMaterial)&&oe.setValue(F,"isOrthographic",T.isOrthographicCamera===!0),tt!==T&&(tt=T,Pi=!0,Qi=!0)}if(Ut.needsLights&&(on.state.sunShadowMap.length>0&&oe.setValue(F,"sunShadowMap",on.state.sunShadowMap,$t),on.state.directionalShadowMap.length>0&&oe.setValue(F,"directionalShadowMap",on.state.directionalShadowMap,$t),on.state.spotShadowMap.length>0&&oe.setValue(F,"spotShadowMap",on.state.spotShadowMap,$t),on.state.pointShadowMap.length>0&&oe.setValue(F,"pointShadowMap",on.state.pointShadowMap,$t)),K.isSkinnedMesh){oe.setOptional(F,K,"bindMatrix"),oe.setOptional(F,K,"bindMatrixInverse");const Pe=K.skeleton;Pe&&(Pe.boneTexture===null&&Pe.computeBoneTexture(),oe.setValue(F,"boneTexture",Pe.boneTexture,$t))}K.isBatchedMesh&&(oe.setOptional(F,K,"batchingTexture"),oe.setValue(F,"batchingTexture",K._matricesTexture,$t),oe.setOptional(F,K,"batchingIdTexture"),oe.setValue(F,"batchingIdTexture",K._indirectTexture,$t),oe.setOptional(F,K,"batchingColorTexture"),K._colorsTexture!==null&&oe.setValue(F,"batchingColorTexture",K._colorsTexture,$t));const On=Q.morphAttributes;if((On.position!==void 0||On.normal!==void 0||On.color!==void 0)&&at.update(K,Q,ln),(Pi||Ut.receiveShadow!==K.receiveShadow)&&(Ut.receiveShadow=K.receiveShadow,oe.setValue(F,"receiveShadow",K.receiveShadow)),(q.isMeshStandardMaterial||q.isMeshLambertMaterial||q.isMeshPhongMaterial)&&q.envMap===null&&G.environment!==null&&(Ze.envMapIntensity.value=G.environmentIntensity),Ze.dfgLUT!==void 0&&(Ze.dfgLUT.value=hy()),Pi){if(oe.setValue(F,"toneMappingExposure",I.toneMappingExposure),Ut.needsLights&&nr(Ze,Qi),Tt&&q.fog===!0&&St.refreshFogUniforms(Ze,Tt),St.refreshMaterialUniforms(Ze,q,vt,gt,b.state.transmissionRenderTarget[T.id]),Ut.needsLights&&Ut.numLightProbeGrids>0){const Pe=S;let cn=0;for(const Ln of b.state.lightProbeGridArray)Ln.texture!==null&&(Pe.textures[cn]=Ln.texture,Pe.min[cn]=Ln.boundingBox.min,Pe.max[cn]=Ln.boundingBox.max,Pe.resolution[cn]=Ln.resolution,cn++);for(const Ln in Pe)Pe[Ln].length=cn;Ze.probesSH.value=Pe.textures,Ze.probesMin.value=Pe.min,Ze.probesMax.value=Pe.max,Ze.probesResolution.value=Pe.resolution}zo.upload(F,us(Ut),Ze,$t)}if(q.isShaderMaterial&&q.uniformsNeedUpdate===!0&&(zo.upload(F,us(Ut),Ze,$t),q.uniformsNeedUpdate=!1),q.isSpriteMaterial&&oe.setValue(F,"center",K.center),oe.setValue(F,"modelViewMatrix",K.modelViewMatrix),oe.setValue(F,"normalMatrix",K.normalMatrix),oe.setValue(F,"modelMatrix",K.matrixWorld),q.uniformsGroups!==void 0){const Pe=q.uniformsGroups;for(let cn=0,Ln=Pe.length;cn<Ln;cn++){const Xa=Pe[cn];Vt.update(Xa,ln),Vt.bind(Xa,ln)}}return ln}function nr(T,G){T.ambientLightColor.needsUpdate=G,T.lightProbe.needsUpdate=G,T.sunLights.needsUpdate=G,T.sunLightShadows.needsUpdate=G,T.directionalLights.needsUpdate=G,T.directionalLightShadows.needsUpdate=G,T.pointLights.needsUpdate=G,T.pointLightShadows.needsUpdate=G,T.spotLights.needsUpdate=G,T.spotLightShadows.needsUpdate=G,T.rectAreaLights.needsUpdate=G,T.hemisphereLights.needsUpdate=G}function ds(T){return T.isMeshLambertMaterial||T.isMeshToonMaterial||T.isMeshPhongMaterial||T.isMeshStandardMaterial||T.isShadowMaterial||T.isShaderMaterial&&T.lights===!0}this.getActiveCubeFace=function(){return J},this.getActiveMipmapLevel=function(){return H},this.getRenderTarget=function(){return ct},this.setRenderTargetTextures=function(T,G,Q){const q=Ht.get(T);q.__autoAllocateDepthBuffer=T.resolveDepthBuffer===!1,q.__autoAllocateDepthBuffer===!1&&(q.__useRenderToTexture=!1),Ht.get(T.texture).__webglTexture=G,Ht.get(T.depthTexture).__webglTexture=q.__autoAllocateDepthBuffer?void 0:Q,q.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(T,G){const Q=Ht.get(T);Q.__webglFramebuffer=G,Q.__useDefaultFramebuffer=G===void 0},this.setRenderTarget=function(T,G=0,Q=0){ct=T,J=G,H=Q;let q=null,K=!1,Tt=!1;if(T){const At=Ht.get(T);if(At.__useDefaultFramebuffer!==void 0){Et.bindFramebuffer(F.FRAMEBUFFER,At.__webglFramebuffer),st.copy(T.viewport),pt.copy(T.scissor),ft=T.scissorTest,Et.viewport(st),Et.scissor(pt),Et.setScissorTest(ft),Z=-1;return}else if(At.__webglFramebuffer===void 0)$t.setupRenderTarget(T);else if(At.__hasExternalTextures)$t.rebindTextures(T,Ht.get(T.texture).__webglTexture,Ht.get(T.depthTexture).__webglTexture);else if(T.depthBuffer){const te=T.depthTexture;if(At.__boundDepthTexture!==te){if(te!==null&&Ht.has(te)&&(T.width!==te.image.width||T.height!==te.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");$t.setupDepthRenderbuffer(T)}}const Lt=T.texture;(Lt.isData3DTexture||Lt.isDataArrayTexture||Lt.isCompressedArrayTexture)&&(Tt=!0);const zt=Ht.get(T).__webglFramebuffer;T.isWebGLCubeRenderTarget?(Array.isArray(zt[G])?q=zt[G][Q]:q=zt[G],K=!0):T.samples>0&&$t.useMultisampledRTT(T)===!1?q=Ht.get(T).__webglMultisampledFramebuffer:Array.isArray(zt)?q=zt[Q]:q=zt,st.copy(T.viewport),pt.copy(T.scissor),ft=T.scissorTest}else st.copy(kt).multiplyScalar(vt).floor(),pt.copy(ne).multiplyScalar(vt).floor(),ft=ee;if(Q!==0&&(q=$),Et.bindFramebuffer(F.FRAMEBUFFER,q)&&Et.drawBuffers(T,q),Et.viewport(st),Et.scissor(pt),Et.setScissorTest(ft),K){const At=Ht.get(T.texture);F.framebufferTexture2D(F.FRAMEBUFFER,F.COLOR_ATTACHMENT0,F.TEXTURE_CUBE_MAP_POSITIVE_X+G,At.__webglTexture,Q)}else if(Tt){const At=G;for(let Lt=0;Lt<T.textures.length;Lt++){const zt=Ht.get(T.textures[Lt]);F.framebufferTextureLayer(F.FRAMEBUFFER,F.COLOR_ATTACHMENT0+Lt,zt.__webglTexture,Q,At)}}else if(T!==null&&Q!==0){const At=Ht.get(T.texture);F.framebufferTexture2D(F.FRAMEBUFFER,F.COLOR_ATTACHMENT0,F.TEXTURE_2D,At.__webglTexture,Q)}Z=-1};function ir(T){const G=Ht.get(T);return(G.__readFormat!==T.format||G.__readType!==T.type)&&(G.__readFormat=T.format,G.__readType=T.type,G.__formatReadable=se.textureFormatReadable(T.format),G.__typeReadable=se.textureTypeReadable(T.type)),G}this.readRenderTargetPixels=function(T,G,Q,q,K,Tt,Pt,At=0){if(!(T&&T.isWebGLRenderTarget)){Se("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Lt=Ht.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Pt!==void 0&&(Lt=Lt[Pt],Array.isArray(Lt)&&(Lt=Lt[0])),Lt){Et.bindFramebuffer(F.FRAMEBUFFER,Lt);try{const zt=T.textures[At],te=zt.format,he=zt.type;T.textures.length>1&&F.readBuffer(F.COLOR_ATTACHMENT0+At);const Bt=ir(zt);if(Bt.__formatReadable===!1){Se("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(Bt.__typeReadable===!1){Se("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}G>=0&&G<=T.width-q&&Q>=0&&Q<=T.height-K&&F.readPixels(G,Q,q,K,xt.convert(te),xt.convert(he),Tt)}finally{const zt=ct!==null?Ht.get(ct).__webglFramebuffer:null;Et.bindFramebuffer(F.FRAMEBUFFER,zt)}}},this.readRenderTargetPixelsAsync=async function(T,G,Q,q,K,Tt,Pt,At=0){if(!(T&&T.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Lt=Ht.get(T).__webglFramebuffer;if(T.isWebGLCubeRenderTarget&&Pt!==void 0&&(Lt=Lt[Pt],Array.isArray(Lt)&&(Lt=Lt[0])),Lt)if(G>=0&&G<=T.width-q&&Q>=0&&Q<=T.height-K){Et.bindFramebuffer(F.FRAMEBUFFER,Lt);const zt=T.textures[At],te=zt.format,he=zt.type;T.textures.length>1&&F.readBuffer(F.COLOR_ATTACHMENT0+At);const Bt=ir(zt);if(Bt.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(Bt.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");const ue=F.createBuffer();F.bindBuffer(F.PIXEL_PACK_BUFFER,ue),F.bufferData(F.PIXEL_PACK_BUFFER,Tt.byteLength,F.STREAM_READ),F.readPixels(G,Q,q,K,xt.convert(te),xt.convert(he),0),F.bindBuffer(F.PIXEL_PACK_BUFFER,null);const $e=ct!==null?Ht.get(ct).__webglFramebuffer:null;Et.bindFramebuffer(F.FRAMEBUFFER,$e);const Re=F.fenceSync(F.SYNC_GPU_COMMANDS_COMPLETE,0);return F.flush(),await R0(F,Re,4),F.bindBuffer(F.PIXEL_PACK_BUFFER,ue),F.getBufferSubData(F.PIXEL_PACK_BUFFER,0,Tt),F.bindBuffer(F.PIXEL_PACK_BUFFER,null),F.deleteBuffer(ue),F.deleteSync(Re),Tt}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(T,G=null,Q=0){const q=Math.pow(2,-Q),K=Math.floor(T.image.width*q),Tt=Math.floor(T.image.height*q),Pt=G!==null?G.x:0,At=G!==null?G.y:0;$t.setTexture2D(T,0),F.copyTexSubImage2D(F.TEXTURE_2D,Q,0,0,Pt,At,K,Tt),Et.unbindTexture()},this.copyTextureToTexture=function(T,G,Q=null,q=null,K=0,Tt=0){let Pt,At,Lt,zt,te,he,Bt,ue,$e;const Re=T.isCompressedTexture?T.mipmaps[Tt]:T.image;if(Q!==null)Pt=Q.max.x-Q.min.x,At=Q.max.y-Q.min.y,Lt=Q.isBox3?Q.max.z-Q.min.z:1,zt=Q.min.x,te=Q.min.y,he=Q.isBox3?Q.min.z:0;else{const oe=Math.pow(2,-K);Pt=Math.floor(Re.width*oe),At=Math.floor(Re.height*oe),T.isDataArrayTexture?Lt=Re.depth:T.isData3DTexture?Lt=Math.floor(Re.depth*oe):Lt=1,zt=0,te=0,he=0}q!==null?(Bt=q.x,ue=q.y,$e=q.z):(Bt=0,ue=0,$e=0);const Ce=xt.convert(G.format),mn=xt.convert(G.type);let Ut;G.isData3DTexture?($t.setTexture3D(G,0),Ut=F.TEXTURE_3D):G.isDataArrayTexture||G.isCompressedArrayTexture?($t.setTexture2DArray(G,0),Ut=F.TEXTURE_2D_ARRAY):($t.setTexture2D(G,0),Ut=F.TEXTURE_2D),Et.activeTexture(F.TEXTURE0),Et.pixelStorei(F.UNPACK_FLIP_Y_WEBGL,G.flipY),Et.pixelStorei(F.UNPACK_PREMULTIPLY_ALPHA_WEBGL,G.premultiplyAlpha),Et.pixelStorei(F.UNPACK_ALIGNMENT,G.unpackAlignment);const on=Et.getParameter(F.UNPACK_ROW_LENGTH),ge=Et.getParameter(F.UNPACK_IMAGE_HEIGHT),ji=Et.getParameter(F.UNPACK_SKIP_PIXELS),ln=Et.getParameter(F.UNPACK_SKIP_ROWS),sr=Et.getParameter(F.UNPACK_SKIP_IMAGES);Et.pixelStorei(F.UNPACK_ROW_LENGTH,Re.width),Et.pixelStorei(F.UNPACK_IMAGE_HEIGHT,Re.height),Et.pixelStorei(F.UNPACK_SKIP_PIXELS,zt),Et.pixelStorei(F.UNPACK_SKIP_ROWS,te),Et.pixelStorei(F.UNPACK_SKIP_IMAGES,he);const Pi=T.isDataArrayTexture||T.isData3DTexture,Qi=G.isDataArrayTexture||G.isData3DTexture;if(T.isDepthTexture){const oe=Ht.get(T),Ze=Ht.get(G),On=Ht.get(oe.__renderTarget),Pe=Ht.get(Ze.__renderTarget);Et.bindFramebuffer(F.READ_FRAMEBUFFER,On.__webglFramebuffer),Et.bindFramebuffer(F.DRAW_FRAMEBUFFER,Pe.__webglFramebuffer);for(let cn=0;cn<Lt;cn++)Pi&&(F.framebufferTextureLayer(F.READ_FRAMEBUFFER,F.COLOR_ATTACHMENT0,Ht.get(T).__webglTexture,K,he+cn),F.framebufferTextureLayer(F.DRAW_FRAMEBUFFER,F.COLOR_ATTACHMENT0,Ht.get(G).__webglTexture,Tt,$e+cn)),F.blitFramebuffer(zt,te,zt+Pt,te+At,Bt,ue,Bt+Pt,ue+At,F.DEPTH_BUFFER_BIT,F.NEAREST);Et.bindFramebuffer(F.READ_FRAMEBUFFER,null),Et.bindFramebuffer(F.DRAW_FRAMEBUFFER,null)}else if(K!==0||T.isRenderTargetTexture||Ht.has(T)){const oe=Ht.get(T),Ze=Ht.get(G);Et.bindFramebuffer(F.READ_FRAMEBUFFER,N),Et.bindFramebuffer(F.DRAW_FRAMEBUFFER,W);for(let On=0;On<Lt;On++)Pi?F.framebufferTextureLayer(F.READ_FRAMEBUFFER,F.COLOR_ATTACHMENT0,oe.__webglTexture,K,he+On):F.framebufferTexture2D(F.READ_FRAMEBUFFER,F.COLOR_ATTACHMENT0,F.TEXTURE_2D,oe.__webglTexture,K),Qi?F.framebufferTextureLayer(F.DRAW_FRAMEBUFFER,F.COLOR_ATTACHMENT0,Ze.__webglTexture,Tt,$e+On):F.framebufferTexture2D(F.DRAW_FRAMEBUFFER,F.COLOR_ATTACHMENT0,F.TEXTURE_2D,Ze.__webglTexture,Tt),K!==0?F.blitFramebuffer(zt,te,zt+Pt,te+At,Bt,ue,Bt+Pt,ue+At,F.COLOR_BUFFER_BIT,F.NEAREST):Qi?F.copyTexSubImage3D(Ut,Tt,Bt,ue,$e+On,zt,te,Pt,At):F.copyTexSubImage2D(Ut,Tt,Bt,ue,zt,te,Pt,At);Et.bindFramebuffer(F.READ_FRAMEBUFFER,null),Et.bindFramebuffer(F.DRAW_FRAMEBUFFER,null)}else Qi?T.isDataTexture||T.isData3DTexture?F.texSubImage3D(Ut,Tt,Bt,ue,$e,Pt,At,Lt,Ce,mn,Re.data):G.isCompressedArrayTexture?F.compressedTexSubImage3D(Ut,Tt,Bt,ue,$e,Pt,At,Lt,Ce,Re.data):F.texSubImage3D(Ut,Tt,Bt,ue,$e,Pt,At,Lt,Ce,mn,Re):T.isDataTexture?F.texSubImage2D(F.TEXTURE_2D,Tt,Bt,ue,Pt,At,Ce,mn,Re.data):T.isCompressedTexture?F.compressedTexSubImage2D(F.TEXTURE_2D,Tt,Bt,ue,Re.width,Re.height,Ce,Re.data):F.texSubImage2D(F.TEXTURE_2D,Tt,Bt,ue,Pt,At,Ce,mn,Re);Et.pixelStorei(F.UNPACK_ROW_LENGTH,on),Et.pixelStorei(F.UNPACK_IMAGE_HEIGHT,ge),Et.pixelStorei(F.UNPACK_SKIP_PIXELS,ji),Et.pixelStorei(F.UNPACK_SKIP_ROWS,ln),Et.pixelStorei(F.UNPACK_SKIP_IMAGES,sr),Tt===0&&G.generateMipmaps===!0&&G.mipmapsAutoUpdate===!0&&F.generateMipmap(Ut),Et.unbindTexture()},this.initRenderTarget=function(T){Ht.get(T).__webglFramebuffer===void 0&&$t.setupRenderTarget(T)},this.initTexture=function(T){T.isCubeTexture?$t.setTextureCube(T,0):T.isData3DTexture?$t.setTexture3D(T,0):T.isDataArrayTexture||T.isCompressedArrayTexture?$t.setTexture2DArray(T,0):$t.setTexture2D(T,0),Et.unbindTexture()},this.resetState=function(){J=0,H=0,ct=null,Et.reset(),bt.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Ai}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(t){this._outputColorSpace=t;const e=this.getContext();e.drawingBufferColorSpace=xe._getDrawingBufferColorSpace(t),e.unpackColorSpace=xe._getUnpackColorSpace()}}const kd={type:"change"},Yh={type:"start"},tm={type:"end"},Eo=new el,Hd=new wi,uy=Math.cos(70*D0.DEG2RAD),_n=new k,Wn=2*Math.PI,Te={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},rc=1e-6;class em extends __{constructor(t,e=null){super(t,e),this.state=Te.NONE,this.target=new k,this.cursor=new k,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:Ir.ROTATE,MIDDLE:Ir.DOLLY,RIGHT:Ir.PAN},this.touches={ONE:Nr.ROTATE,TWO:Nr.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new k,this._lastQuaternion=new Ls,this._lastTargetPosition=new k,this._quat=new Ls().setFromUnitVectors(t.up,new k(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new gd,this._sphericalDelta=new gd,this._scale=1,this._panOffset=new k,this._rotateStart=new Xt,this._rotateEnd=new Xt,this._rotateDelta=new Xt,this._panStart=new Xt,this._panEnd=new Xt,this._panDelta=new Xt,this._dollyStart=new Xt,this._dollyEnd=new Xt,this._dollyDelta=new Xt,this._dollyDirection=new k,this._mouse=new Xt,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=fy.bind(this),this._onPointerDown=dy.bind(this),this._onPointerUp=py.bind(this),this._onContextMenu=My.bind(this),this._onMouseWheel=_y.bind(this),this._onKeyDown=vy.bind(this),this._onTouchStart=xy.bind(this),this._onTouchMove=Sy.bind(this),this._onMouseDown=my.bind(this),this._onMouseMove=gy.bind(this),this._interceptControlDown=yy.bind(this),this._interceptControlUp=by.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(t){this._cursorStyle=t,t==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(t){super.connect(t),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Te.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(t){t.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=t}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(kd),this.update(),this.state=Te.NONE}pan(t,e){this._pan(t,e),this.update()}dollyIn(t){this._dollyIn(t),this.update()}dollyOut(t){this._dollyOut(t),this.update()}rotateLeft(t){this._rotateLeft(t),this.update()}rotateUp(t){this._rotateUp(t),this.update()}update(t=null){const e=this.object.position;_n.copy(e).sub(this.target),_n.applyQuaternion(this._quat),this._spherical.setFromVector3(_n),this.autoRotate&&this.state===Te.NONE&&this._rotateLeft(this._getAutoRotationAngle(t)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let n=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(n)&&isFinite(s)&&(n<-Math.PI?n+=Wn:n>Math.PI&&(n-=Wn),s<-Math.PI?s+=Wn:s>Math.PI&&(s-=Wn),n<=s?this._spherical.theta=Math.max(n,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(n+s)/2?Math.max(n,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{const a=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=a!=this._spherical.radius}if(_n.setFromSpherical(this._spherical),_n.applyQuaternion(this._quatInverse),e.copy(this.target).add(_n),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let a=null;if(this.object.isPerspectiveCamera){const o=_n.length();a=this._clampDistance(o*this._scale);const l=o-a;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),r=!!l}else if(this.object.isOrthographicCamera){const o=new k(this._mouse.x,this._mouse.y,0);o.unproject(this.object);const l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=l!==this.object.zoom;const c=new k(this._mouse.x,this._mouse.y,0);c.unproject(this.object),this.object.position.sub(c).add(o),this.object.updateMatrixWorld(),a=_n.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;a!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(a).add(this.object.position):(Eo.origin.copy(this.object.position),Eo.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(Eo.direction))<uy?this.object.lookAt(this.target):(Hd.setFromNormalAndCoplanarPoint(this.object.up,this.target),Eo.intersectPlane(Hd,this.target))))}else if(this.object.isOrthographicCamera){const a=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),a!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>rc||8*(1-this._lastQuaternion.dot(this.object.quaternion))>rc||this._lastTargetPosition.distanceToSquared(this.target)>rc?(this.dispatchEvent(kd),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(t){return t!==null?Wn/60*this.autoRotateSpeed*t:Wn/60/60*this.autoRotateSpeed}_getZoomScale(t){const e=Math.abs(t*.01);return Math.pow(.95,this.zoomSpeed*e)}_rotateLeft(t){this._sphericalDelta.theta-=t}_rotateUp(t){this._sphericalDelta.phi-=t}_panLeft(t,e){_n.setFromMatrixColumn(e,0),_n.multiplyScalar(-t),this._panOffset.add(_n)}_panUp(t,e){this.screenSpacePanning===!0?_n.setFromMatrixColumn(e,1):(_n.setFromMatrixColumn(e,0),_n.crossVectors(this.object.up,_n)),_n.multiplyScalar(t),this._panOffset.add(_n)}_pan(t,e){const n=this.domElement;if(this.object.isPerspectiveCamera){const s=this.object.position;_n.copy(s).sub(this.target);let r=_n.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*t*r/n.clientHeight,this.object.matrix),this._panUp(2*e*r/n.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(t*(this.object.right-this.object.left)/this.object.zoom/n.clientWidth,this.object.matrix),this._panUp(e*(this.object.top-this.object.bottom)/this.object.zoom/n.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(t,e){if(!this.zoomToCursor)return;this._performCursorZoom=!0;const n=this.domElement.getBoundingClientRect(),s=t-n.left,r=e-n.top,a=n.width,o=n.height;this._mouse.x=s/a*2-1,this._mouse.y=-(r/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(t){return Math.max(this.minDistance,Math.min(this.maxDistance,t))}_handleMouseDownRotate(t){this._rotateStart.set(t.clientX,t.clientY)}_handleMouseDownDolly(t){this._updateZoomParameters(t.clientX,t.clientY),this._dollyStart.set(t.clientX,t.clientY)}_handleMouseDownPan(t){this._panStart.set(t.clientX,t.clientY)}_handleMouseMoveRotate(t){this._rotateEnd.set(t.clientX,t.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const e=this.domElement;this._rotateLeft(Wn*this._rotateDelta.x/e.clientHeight),this._rotateUp(Wn*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(t){this._dollyEnd.set(t.clientX,t.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(t){this._panEnd.set(t.clientX,t.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(t){this._updateZoomParameters(t.clientX,t.clientY),t.deltaY<0?this._dollyIn(this._getZoomScale(t.deltaY)):t.deltaY>0&&this._dollyOut(this._getZoomScale(t.deltaY)),this.update()}_handleKeyDown(t){let e=!1;switch(t.code){case this.keys.UP:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(Wn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),e=!0;break;case this.keys.BOTTOM:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(-Wn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),e=!0;break;case this.keys.LEFT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(Wn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),e=!0;break;case this.keys.RIGHT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(-Wn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),e=!0;break}e&&(t.preventDefault(),this.update())}_handleTouchStartRotate(t){if(this._pointers.length===1)this._rotateStart.set(t.pageX,t.pageY);else{const e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),s=.5*(t.pageY+e.y);this._rotateStart.set(n,s)}}_handleTouchStartPan(t){if(this._pointers.length===1)this._panStart.set(t.pageX,t.pageY);else{const e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),s=.5*(t.pageY+e.y);this._panStart.set(n,s)}}_handleTouchStartDolly(t){const e=this._getSecondPointerPosition(t),n=t.pageX-e.x,s=t.pageY-e.y,r=Math.sqrt(n*n+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enablePan&&this._handleTouchStartPan(t)}_handleTouchStartDollyRotate(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enableRotate&&this._handleTouchStartRotate(t)}_handleTouchMoveRotate(t){if(this._pointers.length==1)this._rotateEnd.set(t.pageX,t.pageY);else{const n=this._getSecondPointerPosition(t),s=.5*(t.pageX+n.x),r=.5*(t.pageY+n.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const e=this.domElement;this._rotateLeft(Wn*this._rotateDelta.x/e.clientHeight),this._rotateUp(Wn*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(t){if(this._pointers.length===1)this._panEnd.set(t.pageX,t.pageY);else{const e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),s=.5*(t.pageY+e.y);this._panEnd.set(n,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(t){const e=this._getSecondPointerPosition(t),n=t.pageX-e.x,s=t.pageY-e.y,r=Math.sqrt(n*n+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);const a=(t.pageX+e.x)*.5,o=(t.pageY+e.y)*.5;this._updateZoomParameters(a,o)}_handleTouchMoveDollyPan(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enablePan&&this._handleTouchMovePan(t)}_handleTouchMoveDollyRotate(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enableRotate&&this._handleTouchMoveRotate(t)}_addPointer(t){this._pointers.push(t.pointerId)}_removePointer(t){delete this._pointerPositions[t.pointerId];for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId){this._pointers.splice(e,1);return}}_isTrackingPointer(t){for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId)return!0;return!1}_trackPointer(t){let e=this._pointerPositions[t.pointerId];e===void 0&&(e=new Xt,this._pointerPositions[t.pointerId]=e),e.set(t.pageX,t.pageY)}_getSecondPointerPosition(t){const e=t.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[e]}_customWheelEvent(t){const e=t.deltaMode,n={clientX:t.clientX,clientY:t.clientY,deltaY:t.deltaY};switch(e){case 1:n.deltaY*=16;break;case 2:n.deltaY*=100;break}return t.ctrlKey&&!this._controlActive&&(n.deltaY*=10),n}}function dy(i){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(i.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(i)&&(this._addPointer(i),i.pointerType==="touch"?this._onTouchStart(i):this._onMouseDown(i),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function fy(i){this.enabled!==!1&&(i.pointerType==="touch"?this._onTouchMove(i):this._onMouseMove(i))}function py(i){switch(this._removePointer(i),this._pointers.length){case 0:this.domElement.releasePointerCapture(i.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(tm),this.state=Te.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:const t=this._pointers[0],e=this._pointerPositions[t];this._onTouchStart({pointerId:t,pageX:e.x,pageY:e.y});break}}function my(i){let t;switch(i.button){case 0:t=this.mouseButtons.LEFT;break;case 1:t=this.mouseButtons.MIDDLE;break;case 2:t=this.mouseButtons.RIGHT;break;default:t=-1}switch(t){case Ir.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(i),this.state=Te.DOLLY;break;case Ir.ROTATE:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Te.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Te.ROTATE}break;case Ir.PAN:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Te.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Te.PAN}break;default:this.state=Te.NONE}this.state!==Te.NONE&&this.dispatchEvent(Yh)}function gy(i){switch(this.state){case Te.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(i);break;case Te.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(i);break;case Te.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(i);break}}function _y(i){this.enabled===!1||this.enableZoom===!1||this.state!==Te.NONE||(i.preventDefault(),this.dispatchEvent(Yh),this._handleMouseWheel(this._customWheelEvent(i)),this.dispatchEvent(tm))}function vy(i){this.enabled!==!1&&this._handleKeyDown(i)}function xy(i){switch(this._trackPointer(i),this._pointers.length){case 1:switch(this.touches.ONE){case Nr.ROTATE:if(this.enableRotate===!1){this.state=Te.NONE;break}this._handleTouchStartRotate(i),this.state=Te.TOUCH_ROTATE;break;case Nr.PAN:if(this.enablePan===!1){this.state=Te.NONE;break}this._handleTouchStartPan(i),this.state=Te.TOUCH_PAN;break;default:this.state=Te.NONE}break;case 2:switch(this.touches.TWO){case Nr.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(i),this.state=Te.TOUCH_DOLLY_PAN;break;case Nr.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(i),this.state=Te.TOUCH_DOLLY_ROTATE;break;default:this.state=Te.NONE}break;default:this.state=Te.NONE}this.state!==Te.NONE&&this.dispatchEvent(Yh)}function Sy(i){switch(this._trackPointer(i),this.state){case Te.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(i),this.update();break;case Te.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(i),this.update();break;case Te.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(i),this.update();break;case Te.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(i),this.update();break;default:this.state=Te.NONE}}function My(i){this.enabled!==!1&&i.preventDefault()}function yy(i){i.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function by(i){i.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}class Ey{constructor(t){const e=new zp;e.aspect=.5;const n=new Xt;this.setEyeSeparation=function(s){e.eyeSep=s},this.setSize=function(s,r){t.setSize(s,r)},this.render=function(s,r){s.matrixWorldAutoUpdate===!0&&s.updateMatrixWorld(),r.parent===null&&r.matrixWorldAutoUpdate===!0&&r.updateMatrixWorld(),e.update(r);const a=t.autoClear;t.getSize(n),t.autoClear=!1,t.clear(),t.setScissorTest(!0),t.setScissor(0,0,n.width/2,n.height),t.setViewport(0,0,n.width/2,n.height),t.render(s,e.cameraL),t.setScissor(n.width/2,0,n.width/2,n.height),t.setViewport(n.width/2,0,n.width/2,n.height),t.render(s,e.cameraR),t.setScissorTest(!1),t.autoClear=a}}}const wo=(i,t)=>i[0]*t[0]+i[1]*t[1]+i[2]*t[2],ac=(i,t)=>[i[0]+t[0],i[1]+t[1],i[2]+t[2]],oc=(i,t)=>[i[0]-t[0],i[1]-t[1],i[2]-t[2]],zi=(i,t)=>[i[0]*t,i[1]*t,i[2]*t];function wy(i,t){return 4*Math.sqrt(Math.max(Math.abs(t),1)*Math.max(i,0))}function Ty(i,t,e,n,s){const r=Math.hypot(...e),a=Math.hypot(...i.direction);if(!(r>0)||!(a>0)||!(n>0)||!Number.isFinite(r)||!Number.isFinite(a)||![...t,...i.origin].every(Number.isFinite))return null;const o=zi(e,1/r),l=zi(i.direction,1/a),c=ac(t,e),h=oc(c,i.origin),u=wo(o,l),d=Math.abs(u)>1e-9?wo(o,h)/u:-1,m=d>0?ac(i.origin,zi(l,d)):ac(i.origin,zi(l,Math.max(wo(h,l),0)));let _=oc(m,c);_=oc(_,zi(o,wo(_,o)));let M=zi(_,1/n);const p=Math.hypot(...M);if(!Number.isFinite(p))return null;const f=Math.max(s,0);return p>f?(M=p>0?zi(M,f/p):[0,0,0],{v:M,speed:f,capped:!0}):{v:M,speed:p,capped:!1}}function Ay(i,t,e,n){const s=zi(t,e),r=Math.hypot(...s);if(r>=n)return s;if(r>1e-12*n)return zi(s,n/r);const a=[-i[1],i[0],0],o=Math.hypot(...a);return o>1e-12*Math.hypot(...i)&&o>0?zi(a,n/o):[n,0,0]}function Ry(i,t,e){const n=i.intersectSphere(new ka(t,e),new k);if(n!==null)return n.sub(t);const s=i.closestPointToPoint(t,new k).sub(t),r=s.length();return r>0?s.multiplyScalar(e/r):new k(0,0,-e)}class Cy{constructor(t,e,n,s,r,a){this.canvas=t,this.camera=e,this.controls=n,this.bob=s,this.onDrag=r,this.sphere=a,t.addEventListener("pointerdown",o=>this.down(o),{capture:!0}),t.addEventListener("pointermove",o=>this.move(o)),t.addEventListener("pointerup",o=>this.up(o)),t.addEventListener("pointercancel",o=>this.up(o))}canvas;camera;controls;bob;onDrag;sphere;dragging=!1;raycaster=new kp;get active(){return this.dragging}ray(t){const e=this.canvas.getBoundingClientRect(),n=new Xt((t.clientX-e.left)/e.width*2-1,-((t.clientY-e.top)/e.height)*2+1);return this.raycaster.setFromCamera(n,this.camera),this.raycaster.ray}position(t){const{pivot:e,length:n}=this.sphere(),s=Ry(this.ray(t),e,n);return[s.x,s.y,s.z]}down(t){t.button!==0||!this.bob.visible||(this.ray(t),this.raycaster.intersectObject(this.bob,!1).length!==0&&(this.dragging=!0,this.controls.enabled=!1,this.canvas.setPointerCapture?.(t.pointerId),t.stopImmediatePropagation(),this.onDrag(this.position(t),"start")))}move(t){this.dragging&&this.onDrag(this.position(t),"move")}up(t){this.dragging&&(this.dragging=!1,this.controls.enabled=!0,this.onDrag(this.position(t),"end"))}}class Py{constructor(t,e,n,s,r,a,o,l){this.canvas=t,this.camera=e,this.controls=n,this.handle=s,this.occluder=r,this.grabRadius=a,this.pullBasis=o,this.onPull=l,t.addEventListener("pointerdown",c=>this.down(c),{capture:!0}),t.addEventListener("pointermove",c=>this.move(c)),t.addEventListener("pointerup",c=>this.up(c)),t.addEventListener("pointercancel",c=>this.up(c))}canvas;camera;controls;handle;occluder;grabRadius;pullBasis;onPull;basis=null;moved=!1;raycaster=new kp;tmp=new k;get active(){return this.basis!==null}ray(t){const e=this.canvas.getBoundingClientRect(),n=new Xt((t.clientX-e.left)/e.width*2-1,-((t.clientY-e.top)/e.height)*2+1);return this.raycaster.setFromCamera(n,this.camera),this.raycaster.ray}pulled(t){if(this.basis===null)return null;const e=this.ray(t),{pivot:n,x:s,arrowScale:r,vmax:a}=this.basis;return Ty({origin:[e.origin.x,e.origin.y,e.origin.z],direction:[e.direction.x,e.direction.y,e.direction.z]},n,s,r,a)}down(t){if(t.button!==0||!this.handle.visible)return;const e=this.ray(t),n=this.handle.getWorldPosition(this.tmp),s=this.grabRadius();if(e.distanceToPoint(n)>s)return;const r=this.raycaster.intersectObject(this.occluder,!1)[0];if(r!==void 0&&r.distance<n.sub(e.origin).dot(e.direction)-s)return;const a=this.pullBasis();a!==null&&(this.basis=a,this.moved=!1,this.controls.enabled=!1,this.canvas.setPointerCapture?.(t.pointerId),t.stopImmediatePropagation(),this.onPull(a.x,null,"start"))}move(t){this.basis!==null&&(this.moved=!0,this.onPull(this.basis.x,this.pulled(t),"move"))}up(t){if(this.basis===null)return;const e=this.moved?this.pulled(t):null,n=this.basis.x;this.basis=null,this.controls.enabled=!0,this.onPull(n,e,"end")}}const $i=180/Math.PI;function ph(i){return{theta:Math.atan2(Math.hypot(i[0],i[1]),-i[2]),phi:Math.atan2(i[1],i[0])}}function Ly(i){let t=i%(2*Math.PI);return t<=-Math.PI&&(t+=2*Math.PI),t>Math.PI&&(t-=2*Math.PI),t}class Dy{constructor(t=8){this.maxLaps=t}maxLaps;acc=0;since=null;laps=[];get running(){return this.since!==null}reading(t){return this.acc+(this.since===null?0:Math.max(0,t-this.since))}start(t){this.since===null&&(this.since=t)}stop(t){this.since!==null&&(this.acc=this.reading(t),this.since=null)}lap(t){this.laps.push(this.reading(t)),this.laps.length>this.maxLaps&&this.laps.shift()}reset(){[this.acc,this.since,this.laps]=[0,null,[]]}}class Ny{constructor(t=1e-7,e=10){this.minRise=t,this.keep=e}minRise;keep;prev=null;phi=0;crossings=[];zLow=1/0;zHigh=-1/0;reset(){this.prev=null,this.phi=0,this.crossings=[],this.zLow=1/0,this.zHigh=-1/0}push(t){const e=this.prev;if(e!==null&&t.t<=e.t)return;const n=Math.atan2(t.x[1],t.x[0]);if(e===null){this.phi=n,this.prev=t,this.zLow=this.zHigh=t.x[2];return}const s=this.phi;this.phi=s+Ly(n-Math.atan2(e.x[1],e.x[0])),this.zLow=Math.min(this.zLow,t.x[2]),this.zHigh=Math.max(this.zHigh,t.x[2]);const[r,a]=[e.v[2],t.v[2]];if(r<0&&a>=0){const o=r===a?0:-r/(a-r),l=e.t+o*(t.t-e.t),c=s+o*(this.phi-s);(this.crossings.length===0||this.zHigh-this.zLow>this.minRise)&&(this.crossings.push({t:l,phi:c}),this.crossings.length>this.keep+1&&this.crossings.shift()),this.zLow=this.zHigh=t.x[2]}this.prev=t}reading(){const t=this.crossings,e=t.length-1;if(e<1)return{period:null,advance:null,intervals:0};const n=t[0],s=t[e];return{period:(s.t-n.t)/e,advance:(s.phi-n.phi)/e,intervals:e}}}function Iy(i,t,e,n,s){const r=.5*t*(i.v[0]**2+i.v[1]**2+i.v[2]**2),a=i.energy-r+t*Math.abs(e)*n,o=-s;return{kinetic:r,potential:a,lost:o,total:r+a+o}}function Uy(i,t){return .5*(i.power+t.power)*(t.t-i.t)}function Fy(i,t){const e=t?.kind==="planar",n=t===null||t.period_z_infinite?null:t.period_z;return{swing:e,period:[i.period===null?null:e?2*i.period:i.period,n],advance:[e?null:i.advance,t?.azimuth_advance??null]}}const Gd=512,$s=4e3,Oy=4e3,By=2e5,zy=3,ky=["t [s]","x1 [m]","x2 [m]","x3 [m]","v1 [m/s]","v2 [m/s]","v3 [m/s]","energy [J]","j3 [kg m^2/s]","tension [N]","power [W]","a1 [m/s^2]","a2 [m/s^2]","a3 [m/s^2]","pivot1 [m]","pivot2 [m]","pivot3 [m]","taut [1]","error_x [m]"];function Vd(){return{t:[],dE:[],dJ3:[],z:[],zdot:[],tension:[],frames:[]}}function Oi(i,t,e){return i+(t-i)*e}function Hy(i,t,e){const n=(o,l)=>[Oi(o[0],l[0],e),Oi(o[1],l[1],e),Oi(o[2],l[2],e)],s=n(i.x,t.x),r=Oi(Math.hypot(...i.x),Math.hypot(...t.x),e),a=Math.hypot(...s);if(a>0)for(let o=0;o<3;o++)s[o]=s[o]*(r/a);return{t:Oi(i.t,t.t,e),x:s,v:n(i.v,t.v),energy:Oi(i.energy,t.energy,e),j3:Oi(i.j3,t.j3,e),tension:Oi(i.tension,t.tension,e),power:Oi(i.power,t.power,e),a:n(i.a,t.a),pivot:n(i.pivot,t.pivot),taut:i.taut&&t.taut,errorX:i.errorX<0||t.errorX<0?-1:Oi(i.errorX,t.errorX,e)}}function Gy(i,t,e){return i===null||t.epoch!==i.epoch||e!==null&&t.t<e}function Wd(i,t,e){let n=0,s=i.length;for(;n<s;){const r=n+s>>1,a=i[r].t;(e?a<t:a<=t)?n=r+1:s=r}return n}class nm{status=null;frames=[];trail=[];history=Vd();trajectory=[];trajectoryTruncated=!1;reference=null;tensionExtremes=null;playT=null;exact=null;exactError=null;errors=[];events=[];connected=!1;tickHz=60;work=0;periodTimer=new Ny;historyStride=1;historyCount=0;disconnected=!1;listeners=new Set;subscribe(t){return this.listeners.add(t),()=>this.listeners.delete(t)}emit(){for(const t of this.listeners)t()}onStatus(t){const e=this.disconnected||Gy(this.status,t,this.latest()?.t??null);this.disconnected=!1,this.status=t,e&&this.clear(),this.emit()}clear(){this.frames=[],this.trail=[],this.history=Vd(),this.trajectory=[],this.trajectoryTruncated=!1,this.reference=null,this.tensionExtremes=null,this.playT=null,this.exact=null,this.exactError=null,this.events=[],this.work=0,this.periodTimer.reset(),this.historyStride=1,this.historyCount=0}onError(t){this.errors.push(t),this.errors.length>20&&this.errors.shift(),this.emit()}onEvent(t){const e=this.events;this.events=Eg(e,t,this.status?.epoch??null),this.events!==e&&(this.work-=t.energy_lost,this.emit())}setConnected(t){this.connected=t,t||(this.disconnected=!0),this.emit()}setExact(t,e=null){this.exact=t,this.exactError=e,this.emit()}onFrames(t){for(const e of t){const n=this.frames[this.frames.length-1];if(n!==void 0&&e.t<n.t)continue;n!==void 0&&e.t===n.t?this.frames.pop():n!==void 0&&(this.work+=Uy(n,e)),this.frames.push(e),this.periodTimer.push(e),this.reference===null&&(this.reference={energy:e.energy,j3:e.j3});const s=this.tensionExtremes;s===null?this.tensionExtremes={min:e.tension,tMin:e.t,max:e.tension,tMax:e.t}:(e.tension<s.min&&([s.min,s.tMin]=[e.tension,e.t]),e.tension>s.max&&([s.max,s.tMax]=[e.tension,e.t])),this.pushTrail(e),this.pushHistory(e),this.trajectory.length<By?this.trajectory.push(e):this.trajectoryTruncated=!0,this.playT===null&&(this.playT=e.t)}this.frames.length>Gd&&this.frames.splice(0,this.frames.length-Gd)}pushTrail(t){const e=this.trail[this.trail.length-1];e!==void 0&&e.t===t.t&&this.trail.pop(),this.trail.push(t),this.trail.length>$s&&this.trail.splice(0,this.trail.length-$s)}pushHistory(t){const e=this.reference;if(e===null)return;const n=this.history;if(!(n.t.length>0&&t.t<=n.t[n.t.length-1])&&this.historyCount++%this.historyStride===0&&(n.t.push(t.t),n.dE.push(t.energy-e.energy),n.dJ3.push(t.j3-e.j3),n.z.push(t.x[2]),n.zdot.push(t.v[2]),n.tension.push(t.tension),n.frames.push(t),n.t.length>Oy)){const s=r=>r.filter((a,o)=>o%2===0);this.history={t:s(n.t),dE:s(n.dE),dJ3:s(n.dJ3),z:s(n.z),zdot:s(n.zdot),tension:s(n.tension),frames:s(n.frames)},this.historyStride*=2,this.historyCount=1}}latest(){return this.frames[this.frames.length-1]??null}advancePlayhead(t){const e=this.latest(),n=this.frames[0];if(e==null||n===void 0)return this.playT=null;const s=this.status;if(s===null||s.paused||this.playT===null)return this.playT=e.t,this.playT;const r=zy*s.time_scale/this.tickHz;let a=this.playT+Math.max(0,t)*s.time_scale;return a=Math.min(a,e.t),a=Math.max(a,e.t-r,n.t),this.playT=a,a}displayed(){const t=this.playT,e=this.frames;if(t===null||e.length===0)return null;const n=e[e.length-1];if(t>=n.t)return n;let s=0,r=e.length-1;if(t<=e[0].t)return e[0];for(;r-s>1;){const c=s+r>>1;e[c].t<=t?s=c:r=c}const a=e[s],o=e[r],l=o.t-a.t;return Hy(a,o,l>0?(t-a.t)/l:1)}trailRange(t){const e=this.playT;if(e===null)return{start:0,end:0};const n=Wd(this.trail,e,!1),s=Wd(this.trail,e-t,!0);return{start:Math.min(s,n),end:n}}trailWindow(t){const{start:e,end:n}=this.trailRange(t);return this.trail.slice(e,n)}toCSV(){const t=this.status,e={source:"pendulab lab",scenario:t?.scenario??null,params:t?.params??null,model:t?.model??null,model_params:t?.model_params??null,method:t?.method??null,dt:t?.dt??null,truncated:this.trajectoryTruncated},n=ky.join(","),s=this.trajectory.map(r=>[r.t,...r.x,...r.v,r.energy,r.j3,r.tension,r.power,...r.a,...r.pivot,r.taut?1:0,r.errorX].map(a=>String(a)).join(","));return[`# ${JSON.stringify(e)}`,n,...s].join(`
`)+`
`}}const Xd=(i,t)=>[i[1]*t[2]-i[2]*t[1],i[2]*t[0]-i[0]*t[2],i[0]*t[1]-i[1]*t[0]],_a=(i,t)=>[i[0]*t,i[1]*t,i[2]*t],Vy=(i,t)=>[i[0]-t[0],i[1]-t[1],i[2]-t[2]];function Wy(i){const t=[i?.gravity_x??0,i?.gravity_y??0,i?.gravity_z??-1],e=Math.hypot(...t);return e>0?_a(t,1/e):[0,0,-1]}function Xy(i,t,e,n,s){const r=Math.hypot(...i.x),a=_a(i.v,t),o=_a(i.a,t),l=Vy(i.x,s);return{velocity:i.v,momentum:a,gravity:_a(n,t*e),tension:r>0?_a(i.x,-i.tension/r):[0,0,0],net:o,angularMomentum:Xd(l,a),torque:Xd(l,o)}}function lc(i,t,e){const n=Math.max(Math.abs(e),1),s=.5*i/(t*n),r=Math.sqrt(n/i);return{velocity:.25,momentum:.25,gravity:s,tension:s,net:s,angularMomentum:.5*i/(t*i*i*r),torque:s/i}}const im=(i,t)=>[i[0]-t[0],i[1]-t[1],i[2]-t[2]],Ia=i=>Math.hypot(i[0],i[1],i[2]),Ua=(i,t)=>[i[0]*t,i[1]*t,i[2]*t],mh=(i,t)=>[i[1]*t[2]-i[2]*t[1],i[2]*t[0]-i[0]*t[2],i[0]*t[1]-i[1]*t[0]];function sm(i,t){const e=t[0]*i[0]+t[1]*i[1]+t[2]*i[2];let n=im(t,Ua(i,e));return Ia(n)<1e-9&&(n=Math.abs(i[0])<.9?mh(i,[1,0,0]):mh(i,[0,1,0])),Ua(n,1/Ia(n))}function $y(i,t,e,n){const s=Ia(i);if(!(s>0))return[[0,0,0],[...i]];const r=Ua(i,1/s),a=sm(r,[0,0,1]),o=mh(r,a),l=[];for(let c=0;c<=n;c++){const h=c/n,u=e*Math.min(1,h/.05,(1-h)/.05),d=2*Math.PI*t*h,[m,_]=[Math.cos(d)*u,Math.sin(d)*u];l.push([i[0]*h+a[0]*m+o[0]*_,i[1]*h+a[1]*m+o[1]*_,i[2]*h+a[2]*m+o[2]*_])}return l}function Yy(i){let t=0;for(let e=1;e<i.length;e++)t+=Ia(im(i[e],i[e-1]));return t}function $d(i,t,e){const n=[];for(let s=0;s<=e;s++){const r=s/e,[a,o]=[2*r*(1-r),r*r];n.push([t[0]*a+i[0]*o,t[1]*a+i[1]*o,t[2]*a+i[2]*o])}return n}function qy(i,t,e,n=[0,0,-1]){const s=Ia(i),r=Ua(i,.5);if(!(s>0)||s>=t)return $d(i,r,e);const a=sm(Ua(i,1/s),n),o=h=>$d(i,[r[0]+a[0]*h,r[1]+a[1]*h,r[2]+a[2]*h],e);let[l,c]=[0,t];for(let h=0;h<40&&c-l>1e-4*t;h++){const u=.5*(l+c);Yy(o(u))<t?l=u:c=u}return o(.5*(l+c))}const Yd=400,qd=48;class Ky{group=new Vi;coil;slack;constructor(){this.coil=new Ki(new Be().setFromPoints(Array.from({length:Yd+1},()=>new k)),new mi({color:14211288})),this.slack=new Ki(new Be().setFromPoints(Array.from({length:qd+1},()=>new k)),new Up({color:15918793,dashSize:.04,gapSize:.03}));for(const t of[this.coil,this.slack])t.frustumCulled=!1,t.visible=!1;this.group.add(this.coil,this.slack)}update(t,e,n,s,r){if(this.coil.visible=t==="coil",this.slack.visible=t==="slack string",this.group.position.set(...n),t==="coil"&&this.fill(this.coil,$y(e,14,.035*s,Yd)),t==="slack string"){this.fill(this.slack,qy(e,s,qd,r));const a=this.slack.material;a.dashSize=.04*s,a.gapSize=.03*s,this.slack.computeLineDistances()}}fill(t,e){const n=t.geometry.getAttribute("position");e.forEach((s,r)=>n.setXYZ(r,s[0],s[1],s[2])),n.needsUpdate=!0}}const Zy=/swiftshader|llvmpipe|softpipe|software|basic render driver|lavapipe/i;function Jy(i){return i!==null&&Zy.test(i)}function jy(i,t){return 1-(1-i)**t}function Qy(i,t){const e=Jy(i),n=Number.isFinite(t)&&t>0?t:1;return{renderer:i,software:e,antialias:!e,pixelRatio:Math.min(n,e?1:2),reachLayers:e?1:2}}function tb(){const i=document.createElement("canvas"),t=i.getContext("webgl2")??i.getContext("webgl");if(t===null)return null;let e=t.getParameter(t.RENDERER);if(typeof e!="string"||e===""||/^webkit webgl$/i.test(e)){const n=t.getExtension("WEBGL_debug_renderer_info");n!==null&&(e=t.getParameter(n.UNMASKED_RENDERER_WEBGL))}return t.getExtension("WEBGL_lose_context")?.loseContext(),typeof e=="string"&&e!==""&&!/^webkit webgl$/i.test(e)?e:null}const rm=15127459;function eb(i){const t=i/20,e=10**Math.floor(Math.log10(t)),n=t/e;return(n<1.5?1:n<3.5?2:5)*e}class cc{sprite;canvas=document.createElement("canvas");texture;text="";constructor(t,e){this.canvas.width=256,this.canvas.height=64,this.texture=new i_(this.canvas),this.sprite=new Pp(new Rp({map:this.texture,depthTest:!1,transparent:!0})),this.sprite.scale.set(4*e,e,1),this.set(t)}set(t){if(t===this.text)return;this.text=t;const e=this.canvas.getContext("2d");e!==null&&(e.clearRect(0,0,256,64),e.font="bold 44px system-ui, sans-serif",e.fillStyle=`#${rm.toString(16)}`,e.textAlign="center",e.textBaseline="middle",e.fillText(t,128,32),this.texture.needsUpdate=!0)}}function Kd(i){const t=new Be().setFromPoints(i);return new nl(t,new mi({color:rm}))}class nb{ruler=new Vi;protractor=new Vi;dial=new Vi;thetaLabel=new cc("",.1);built=-1;constructor(){this.ruler.visible=!1,this.protractor.visible=!1,this.protractor.add(this.dial,this.thetaLabel.sprite)}build(t){if(t===this.built)return;this.built=t;for(const l of[this.ruler,this.dial])for(const c of[...l.children])l.remove(c),(c instanceof fn||c instanceof nl||c instanceof Pp)&&(c.geometry.dispose(),c.material.dispose());const e=eb(2*t),n=1.1*t,s=[new k(n,0,-t),new k(n,0,t)],r=Math.floor(t/e+1e-9);for(let l=-r;l<=r;l++){const c=l*e,h=l%5===0;if(s.push(new k(n,0,c),new k(n-(h?.08:.04)*t,0,c)),h){const u=new cc(`${+c.toPrecision(6)} m`,.07*t);u.sprite.position.set(n+.16*t,0,c),this.ruler.add(u.sprite)}}this.ruler.add(Kd(s));const a=.4*t,o=[];for(let l=0;l<360;l+=2){const c=l*Math.PI/180,h=(l+2)*Math.PI/180;o.push(new k(a*Math.sin(c),0,-a*Math.cos(c)),new k(a*Math.sin(h),0,-a*Math.cos(h)))}for(let l=0;l<360;l+=10){const c=l*Math.PI/180,h=l%30===0?.85:.92;if(o.push(new k(a*Math.sin(c),0,-a*Math.cos(c)),new k(h*a*Math.sin(c),0,-h*a*Math.cos(c))),l%30===0&&l<=180){const u=new cc(`${l}°`,.06*t);u.sprite.position.set(1.2*a*Math.sin(c),0,-1.2*a*Math.cos(c)),this.dial.add(u.sprite)}}o.push(new k(0,0,-a),new k(0,0,a)),this.dial.add(Kd(o))}face(t){const e=this.ruler.position;this.ruler.rotation.set(0,0,Math.atan2(t.x-e.x,-(t.y-e.y)))}update(t,e,n,s,r,a){if(this.ruler.visible=s,this.protractor.visible=r,!s&&!r)return;this.build(n),this.ruler.position.copy(t),this.face(a),this.protractor.position.copy(t);const o=Math.atan2(e[1],e[0]),l=Math.atan2(Math.hypot(e[0],e[1]),-e[2]);this.dial.rotation.set(0,0,Number.isFinite(o)?o:0);const c=.55*n,h=l/2;this.thetaLabel.sprite.position.set(c*Math.sin(h)*Math.cos(o),c*Math.sin(h)*Math.sin(o),-c*Math.cos(h)),this.thetaLabel.sprite.scale.set(.4*n,.1*n,1),this.thetaLabel.set(`θ = ${(l*180/Math.PI).toFixed(1)}°`)}}class ib{constructor(t){this.renderer=t,this.stereo.aspect=1}renderer;stereo=new zp;render(t,e,n,s,r){const a=this.renderer,o=a.getContext();e.focus=s,e.updateMatrixWorld(),this.stereo.eyeSep=n,this.stereo.update(e);const l=a.autoClear,c=t.background;a.autoClear=!1,t.background=null,a.setClearColor(r,1),a.clear();try{o.colorMask(!0,!1,!1,!0),a.render(t,this.stereo.cameraL),a.clearDepth(),o.colorMask(!1,!0,!0,!0),a.render(t,this.stereo.cameraR)}finally{o.colorMask(!0,!0,!0,!0),t.background=c,a.autoClear=l}}}function sb(i,t,e,n=.9){const s=t*Math.PI/360,r=Math.atan(Math.tan(s)*Math.max(e,.001)),a=Math.min(s,r);return i/Math.sin(a*n)}function rb(i,t){const e=[],s=a=>{for(let o=0;o<96;o++)e.push(a(2*Math.PI*o/96),a(2*Math.PI*(o+1)/96))};for(let a=0;a<6;a++){const o=a*Math.PI/6;s(l=>new k(Math.sin(l)*Math.cos(o),Math.sin(l)*Math.sin(o),Math.cos(l)))}for(const a of[-.75,-.5,-.25,.25,.5,.75]){const o=Math.sqrt(1-a*a);s(l=>new k(o*Math.cos(l),o*Math.sin(l),a))}const r=new nl(new Be().setFromPoints(e),new mi({color:i,transparent:!0,opacity:t}));return r.visible=!1,r}function ab(i,t,e,n){const s=e.position.clone().sub(i).normalize(),r=new k().crossVectors(s,new k(0,0,1));r.lengthSq()<1e-12&&r.set(1,0,0),r.normalize();const a=new k().crossVectors(s,r).normalize(),o=e.position.distanceTo(i),l=t*Math.sqrt(Math.max(0,1-t*t/(o*o))),c=i.clone().addScaledVector(s,t*t/o),h=n.getBoundingClientRect(),u={left:1/0,right:-1/0,top:1/0,bottom:-1/0};for(let d=0;d<64;d++){const m=2*Math.PI*d/64,_=c.clone().addScaledVector(r,l*Math.cos(m)).addScaledVector(a,l*Math.sin(m)).project(e),M=h.left+(_.x+1)/2*h.width,p=h.top+(1-_.y)/2*h.height;u.left=Math.min(u.left,M),u.right=Math.max(u.right,M),u.top=Math.min(u.top,p),u.bottom=Math.max(u.bottom,p)}return u}const hc=13170016,ob=new k(0,1,0);class lb{group=new Vi;bob;rod;trail;positions=new Float32Array(3*($s+1));tmpX=new k;tmpPivot=new k;tmpDir=new k;length=1;constructor(){this.bob=new fn(new Rs(1,24,16),new ba({color:hc,roughness:.4})),this.rod=new fn(new Ga(1,1,1,8),new ba({color:hc,metalness:.3,roughness:.5}));const t=new Be;t.setAttribute("position",new pi(this.positions,3)),t.setDrawRange(0,0),this.trail=new Ki(t,new mi({color:hc,transparent:!0,opacity:.6})),this.trail.frustumCulled=!1,this.group.add(this.bob,this.rod,this.trail),this.group.visible=!1}setLength(t){this.length=t,this.bob.scale.setScalar(.045*t)}update(t,e){if(this.group.visible=t!==null,t===null)return;const n=this.tmpX.fromArray(t.x),s=this.tmpPivot.fromArray(t.pivot);this.bob.position.copy(n).add(s);const r=n.length();r>0&&(this.rod.position.copy(n).multiplyScalar(.5).add(s),this.rod.quaternion.setFromUnitVectors(ob,this.tmpDir.copy(n).divideScalar(r)),this.rod.scale.set(.005*this.length,r,.005*this.length));const a=Math.max(0,Math.min(e.end-e.start,$s)),o=this.positions;for(let h=0;h<a;h++){const u=e.frames[e.end-a+h];o[3*h]=u.x[0]+u.pivot[0],o[3*h+1]=u.x[1]+u.pivot[1],o[3*h+2]=u.x[2]+u.pivot[2]}const l=this.trail.geometry;l.setDrawRange(0,a);const c=l.getAttribute("position");c.clearUpdateRanges(),c.addUpdateRange(0,3*Math.max(a,1)),c.needsUpdate=!0}}const cb=16766720,hb=4e3;function ub(i,t=[0,0,0]){const e=i.filter(s=>s.every(Number.isFinite)).slice(0,hb),n=new Float32Array(3*e.length);return e.forEach((s,r)=>{n[3*r]=s[0]+t[0],n[3*r+1]=s[1]+t[1],n[3*r+2]=s[2]+t[2]}),n}function db(i,t){const e=t>1?i/(t-1):0,n=Math.max(e/3,1e-4);return{dash:n,gap:Math.max(2*n,1e-4)}}class fb{line;material=new Up({color:cb,dashSize:.01,gapSize:.02});constructor(){this.line=new Ki(new Be,this.material),this.line.frustumCulled=!1,this.line.visible=!1,this.line.name="measured-path"}set(t){this.line.geometry.dispose();const e=new Be,n=ub(t??[]);e.setAttribute("position",new pi(n,3)),this.line.geometry=e;const s=n.length/3;if(this.line.visible=s>1,s<2)return;this.line.computeLineDistances();const r=e.getAttribute("lineDistance"),{dash:a,gap:o}=db(r.getX(s-1),s);this.material.dashSize=a,this.material.gapSize=o}get points(){return this.line.visible?this.line.geometry.getAttribute("position").count:0}}const pb=["off","anaglyph","side by side"],mb={trail:!0,trailSeconds:10,sphere:!0,axes:!0,velocity:!0,momentum:!1,gravity:!1,tension:!1,net:!1,angularMomentum:!1,torque:!1,originX:0,originY:0,originZ:0,stereo:"off",ruler:!1,protractor:!1},qh={velocity:14711807,momentum:10194175,gravity:16757575,tension:16735603,net:16777215,angularMomentum:5102016,torque:16769357},gb=["angularMomentum","torque"],uc=new ce(1119259),Zd=.06,_b=new ce(5882879),vb=new k(0,1,0),xb=.025,Sb=.06,Mb=.085,yb={frames:[],start:0,end:0};function bb(i){const t=new g_(new k(1,0,0),new k,1,i);return t.visible=!1,t}class Eb{constructor(t,e){this.container=t,this.renderer=new Qp({antialias:e.antialias}),this.renderer.setPixelRatio(e.pixelRatio),this.renderer.domElement.id="scene-canvas",t.appendChild(this.renderer.domElement),this.scene.background=uc,this.camera=new Xn(40,1,.01,1e3),this.camera.up.set(0,0,1),this.controls=new em(this.camera,this.renderer.domElement),this.controls.enableDamping=!0,this.scene.add(new p_(16777215,.6));const n=new f_(16777215,1.6);n.position.set(2,-3,4),this.scene.add(n),this.sphere=new fn(new Rs(1,48,32),new As({color:9417727,transparent:!0,opacity:e.reachLayers===1?jy(Zd,2):Zd,depthWrite:!1,side:e.reachLayers===2?di:Cs}));const s=new Be().setFromPoints(Array.from({length:128},(a,o)=>{const l=2*Math.PI*o/128;return new k(Math.cos(l),Math.sin(l),0)}));this.equator=new n_(s,new mi({color:9417727,transparent:!0,opacity:.25})),this.pivot=new fn(new Rs(.02,16,12),new ba({color:13421772})),this.rod=new fn(new Ga(1,1,1,12),new ba({color:14211288,metalness:.6,roughness:.3})),this.bob=new fn(new Rs(1,32,24),new ba({color:16747586,roughness:.35})),this.axes=new Hp(1.3),this.handle=new fn(new Rs(1,16,12),new As({color:15911167})),this.handle.name="velocity handle",this.handle.visible=!1,this.trailPositions=new Float32Array(3*($s+1)),this.trailColors=new Float32Array(3*($s+1));const r=new Be;r.setAttribute("position",new pi(this.trailPositions,3)),r.setAttribute("color",new pi(this.trailColors,3)),r.setDrawRange(0,0),this.trail=new Ki(r,new mi({vertexColors:!0})),this.trail.frustumCulled=!1,this.boom=new Ki(new Be().setFromPoints([new k,new k]),new mi({color:10134712})),this.boom.visible=!1,this.boom.frustumCulled=!1,this.scene.add(this.sphere,this.equator,this.reachLines,this.pivot,this.rod,this.bob,this.axes,this.trail,this.tether.group,this.handle,this.boom,this.twin.group,this.measured.line,this.instruments.ruler,this.instruments.protractor,...Object.values(this.arrows)),this.setLength(1),this.resetCamera(),new ResizeObserver(()=>this.resize()).observe(t),this.resize()}container;renderer;camera;controls;scene=new wp;sphere;equator;reachLines=rb(9417727,.18);rod;bob;pivot;axes;trail;trailPositions;trailColors;trailColored=-1;tmpX=new k;tmpBob=new k;tmpDir=new k;tmpVec=new k;tmpOrigin=new k;arrows=Object.fromEntries(Object.entries(qh).map(([t,e])=>[t,bb(e)]));length=1;extent=1;stereo="off";anaglyph=null;instruments=new nb;boom;twin=new lb;measured=new fb;follow=!1;followAt=null;reach=1;sideBySide=null;drag=null;pull=null;handle;drawn=null;velocityScale=lc(1,1,9.81).velocity;gNow=9.81;tmpHandle=new k;pivotNow=new k;topView=!1;tether=new Ky;model="ideal";invalid=!0;setLength(t){if(!(t>0))return;const e=Math.abs(t-this.length)>1e-12*t;this.length=t,e&&(this.extent=this.reach=t),this.sphere.scale.setScalar(t),this.equator.scale.setScalar(t),this.reachLines.scale.setScalar(t),this.pivot.scale.setScalar(t),this.bob.scale.setScalar(.05*t),this.twin.setLength(t),this.handle.scale.setScalar(xb*t),this.axes.scale.setScalar(t),e&&this.resetCamera(),this.invalid=!0}fit(t){Math.abs(t-this.extent)<=.2*this.extent||(this.extent=t,this.resetCamera())}resetCamera(){const t=this.extent,e=1.1*t,n=this.stereo==="side by side"?this.camera.aspect/2:this.camera.aspect,s=sb(e,this.camera.fov,n),r=this.follow&&this.followAt!==null?this.followAt:new k;this.topView?this.camera.position.set(0,-1e-4*s,s).add(r):this.camera.position.set(3.3,-3.9,1.5).normalize().multiplyScalar(s).add(r),this.controls.target.copy(r),this.camera.near=.01*this.length,this.camera.far=100*t,this.camera.updateProjectionMatrix(),this.controls.update(),this.invalid=!0}setModel(t){t!==this.model&&(this.invalid=!0,this.model=t,this.follow=t==="slewing",this.followAt=null,this.extent=this.reach=this.length,this.resetCamera())}setTopView(t){this.topView=t,this.resetCamera()}enableDrag(t,e){const n=this.renderer.domElement;this.pull=new Py(n,this.camera,this.controls,this.handle,this.bob,()=>Sb*this.length,()=>this.pullBasis(),e),this.drag=new Cy(n,this.camera,this.controls,this.bob,t,()=>({pivot:this.pivotNow,length:this.length}))}pullBasis(){const t=this.drawn;return t===null?null:{pivot:[...t.pivot],x:[...t.x],arrowScale:this.velocityScale,vmax:wy(this.length,this.gNow)}}onScreen(t){if(!t.visible)return null;const e=t.position.clone().project(this.camera),n=this.renderer.domElement.getBoundingClientRect();return{x:n.left+(e.x+1)/2*n.width,y:n.top+(1-e.y)/2*n.height}}bobOnScreen(){return this.onScreen(this.bob)}handleOnScreen(){return this.onScreen(this.handle)}setStereo(t){this.stereo=t,t==="anaglyph"&&this.anaglyph===null&&(this.anaglyph=new ib(this.renderer)),t==="side by side"&&this.sideBySide===null&&(this.sideBySide=new Ey(this.renderer)),this.resize(),this.resetCamera()}resize(){const t=Math.max(1,this.container.clientWidth),e=Math.max(1,this.container.clientHeight);this.renderer.setSize(t,e,!1),this.stereo==="side by side"&&this.sideBySide?.setSize(t,e),this.renderer.domElement.style.width="",this.renderer.domElement.style.height="",this.camera.aspect=t/e,this.camera.updateProjectionMatrix(),this.resetCamera(),this.invalid=!0}update(t,e,n,s,r,a){const o=this.stereo==="anaglyph";this.sphere.visible=n.sphere&&!o,this.reachLines.visible=n.sphere&&o,this.equator.visible=n.sphere,this.axes.visible=n.axes;const l=t!==null,c=qf(this.model,t?.taut??!0);if(this.rod.visible=l&&(c==="rod"||c==="taut string"),this.bob.visible=l,this.drawn=t,this.gNow=r,this.velocityScale=lc(this.length,s,r).velocity,this.handle.visible=l&&n.velocity,t===null){this.tether.update("rod",[0,0,0],[0,0,0],this.length,a),this.trail.geometry.setDrawRange(0,0);for(const R of Object.values(this.arrows))R.visible=!1;return}const h=this.pivotNow.fromArray(t.pivot);this.followPivot(h),this.reach=Math.max(this.reach,Math.hypot(...t.x)),this.fit(this.reach+(this.follow?0:h.length())),this.instruments.update(h,t.x,this.length,n.ruler,n.protractor,this.camera.position);const u=Math.hypot(h.x,h.y);if(this.boom.visible=u>1e-9*this.length,this.boom.visible){const R=this.boom.geometry.getAttribute("position");R.setXYZ(0,0,0,h.z),R.setXYZ(1,h.x,h.y,h.z),R.needsUpdate=!0}for(const R of[this.sphere,this.equator,this.reachLines,this.pivot])R.position.copy(h);const d=this.tmpX.fromArray(t.x),m=d.length(),_=this.tmpBob.copy(d).add(h);if(this.bob.position.copy(_),m>0){this.rod.position.copy(d).multiplyScalar(.5).add(h),this.rod.quaternion.setFromUnitVectors(vb,this.tmpDir.copy(d).divideScalar(m));const R=c==="taut string"?.003:.008;this.rod.scale.set(R*this.length,m,R*this.length)}const M=r<0?[-a[0],-a[1],-a[2]]:a;if(this.tether.update(c,t.x,t.pivot,this.length,M),this.updateTrail(n.trail?e:yb,t),this.handle.visible){const R=Ay(t.x,t.v,this.velocityScale,Mb*this.length);this.handle.position.copy(this.tmpHandle.fromArray(R).add(_))}const p=Object.keys(this.arrows);if(!p.some(R=>n[R])){for(const R of p)this.arrows[R].visible=!1;return}const f=[n.originX,n.originY,n.originZ],x=Xy(t,s,r,a,f),A=lc(this.length,s,r),S=this.tmpOrigin.fromArray(f).add(h);for(const R of p){const b=gb.includes(R)?S:_,g=this.tmpVec.fromArray(x[R]).multiplyScalar(A[R]);this.setArrow(this.arrows[R],n[R],b,g)}}followPivot(t){if(!this.follow)return;if(this.followAt===null){this.followAt=t.clone(),this.resetCamera();return}const e=this.tmpVec.copy(t).sub(this.followAt);e.lengthSq()!==0&&(this.camera.position.add(e),this.controls.target.add(e),this.followAt.copy(t))}updateTwin(t,e){this.twin.update(t,e),this.invalid=!0}setMeasured(t){this.measured.set(t),this.invalid=!0}measuredPoints(){return this.measured.points}sphereOnScreen(){return ab(this.sphere.position,this.sphere.scale.x,this.camera,this.renderer.domElement)}twinOnScreen(){return this.twin.group.visible?this.onScreen(this.twin.bob):null}setArrow(t,e,n,s){const r=s.length();if(t.visible=e&&r>1e-6*this.length,!t.visible)return;t.position.copy(n),t.setDirection(s.divideScalar(r));const a=Math.min(.25*r,.08*this.length);t.setLength(r,a,.5*a)}updateTrail(t,e){const n=Math.min(t.end-t.start,$s),s=this.trail.geometry;if(n<=0){s.setDrawRange(0,0);return}const r=t.end-n,a=this.trailPositions,o=n+1;for(let c=0;c<o;c++){const h=c<n?t.frames[r+c]:e;a[3*c]=h.x[0]+h.pivot[0],a[3*c+1]=h.x[1]+h.pivot[1],a[3*c+2]=h.x[2]+h.pivot[2]}s.setDrawRange(0,o);const l=s.getAttribute("position");if(l.clearUpdateRanges(),l.addUpdateRange(0,3*o),l.needsUpdate=!0,o!==this.trailColored){this.trailColored=o;const c=this.trailColors,h=new ce;for(let d=0;d<o;d++)h.copy(uc).lerp(_b,(d+1)/o),c[3*d]=h.r,c[3*d+1]=h.g,c[3*d+2]=h.b;const u=s.getAttribute("color");u.clearUpdateRanges(),u.addUpdateRange(0,3*o),u.needsUpdate=!0}}draw(t){const e=this.controls.update();return e&&this.instruments.ruler.visible&&this.instruments.face(this.camera.position),!t&&!e&&!this.invalid?!1:(this.invalid=!1,this.render(),!0)}render(){const t=this.camera.position.distanceTo(this.controls.target);this.stereo==="anaglyph"&&this.anaglyph!==null?this.anaglyph.render(this.scene,this.camera,t/30,t,uc):this.stereo==="side by side"&&this.sideBySide!==null?(this.camera.focus=t,this.sideBySide.setEyeSeparation(t/30),this.sideBySide.render(this.scene,this.camera)):this.renderer.render(this.scene,this.camera)}screenshot(){return this.render(),this.renderer.domElement.toDataURL("image/png")}}const wb={velocity:["vec.velocity","vec.velocityHelp"],momentum:["vec.momentum","vec.momentumHelp"],gravity:["vec.gravity","vec.gravityHelp"],tension:["vec.tension","vec.tensionHelp"],net:["vec.net","vec.netHelp"],angularMomentum:["vec.angularMomentum","vec.angularMomentumHelp"],torque:["vec.torque","vec.torqueHelp"]};function Tb(i,t,e,n){const s=i.addFolder(O("gui.view"));s.add(t,"trail").name(O("gui.trail")).onChange(e),s.add(t,"trailSeconds",1,120,1).name(O("gui.trailSeconds")).onChange(e),s.add(t,"sphere").name(O("gui.sphere")).onChange(e),s.add(t,"axes").name(O("gui.axes")).onChange(e);const r={topView:!1};s.add(r,"topView").name(O("gui.topView")).onChange(l=>{n(l),e()});const a=s.add(t,"stereo",[...pb]).name(O("gui.stereo")).onChange(e);a.domElement.title=O("gui.stereoHelp"),a.domElement.dataset.control="stereo",s.close();const o=i.addFolder(O("gui.vectors"));for(const[l,[c,h]]of Object.entries(wb)){const u=o.add(t,l).name(O(c)).onChange(e);u.domElement.title=O(h),u.domElement.dataset.vector=l,u.$name.style.borderLeft=`10px solid #${qh[l].toString(16).padStart(6,"0")}`,u.$name.style.paddingLeft="4px"}for(const l of["X","Y","Z"]){const c=`origin${l}`;o.add(t,c,-5,5,.01).name(O("gui.origin",{axis:l.toLowerCase()})).onChange(e).domElement.title=O("gui.originHelp")}return o.close(),s}class Ab{constructor(t,e,n,s,r){this.view=s,this.gui=new Nh({container:t,title:O("gui.title"),width:270});const a={};this.model=a;const o=this.gui.addFolder(O("gui.pendulum")),l=Ih((b,g)=>{r.send({type:"set_params",[b]:g})},50);for(const b of e.model.params){const g=w=>l(b.name,w);this.synced.push(Jf(o,a,b,g,r.explain))}this.modelControls=new Yg(o,e,r);const c=this.gui.addFolder(O("gui.integrator")).close(),h={};for(const b of e.methods){const g=[O("gui.order",{n:b.order}),b.symplectic?O("gui.symplectic"):"",b.adaptive?O("gui.adaptive"):""].filter(Boolean).join(", ");h[`${b.name} (${g})`]=b.name}a.method=e.methods.find(b=>b.default)?.name??e.methods[0]?.name??"rattle";const u=c.add(a,"method",h).name(O("gui.method")).onChange(b=>r.send({type:"set_method",method:b}));u.domElement.title=e.methods.map(b=>`${b.name}: ${b.summary}`).join(`
`),this.synced.push(u);const d=e.controls.dt;a.dt=d.default??.001;const m=c.add(a,"dt").name("dt [s]").decimals(6).onFinishChange(b=>{if(!(b>=d.min&&b<=d.max)){r.explain(O("gui.dtRange",{min:d.min,max:d.max}));return}r.send({type:"set_method",dt:b})});m.domElement.title=O("gui.dtHelp",{min:d.min,max:d.max}),this.synced.push(m);const _=this.gui.addFolder(O("gui.run")),M=e.controls.time_scale;a.time_scale=M.default??1;const p=_.add(a,"time_scale").name(O("gui.timeScale")).decimals(3).onFinishChange(b=>{if(!(b>=M.min&&b<=M.max)){r.explain(O("gui.tsRange",{min:M.min,max:M.max}));return}r.send({type:"set_time_scale",time_scale:b})});p.domElement.title=O("gui.tsHelp",{min:M.min,max:M.max}),this.synced.push(p),a.paused=!1,a.run=()=>r.send({type:a.paused===!0?"resume":"pause"}),this.runButton=_.add(a,"run").name(O("toolbar.pause")),a.stepN=1;const f=e.controls.step_n;_.add(a,"stepN",f.min,Math.min(f.max,1e3),1).name(O("gui.stepN")),a.step=()=>r.send({type:"step",n:Math.round(Number(a.stepN))}),_.add(a,"step").name(O("toolbar.step")),a.reset=()=>r.send({type:"reset"}),_.add(a,"reset").name(O("toolbar.reset"));const x={};for(const b of n)b.error===void 0&&(x[b.title?`${b.title}`:b.name]=b.name);a.scenario="";const A=_.add(a,"scenario",x).name(O("gui.scenario")).onChange(b=>r.send({type:"load_scenario",name:b}));A.domElement.title=n.filter(b=>b.error===void 0).map(b=>`${b.name}: ${b.title??""}`).join(`
`),this.synced.push(A),Tb(this.gui,s,()=>r.viewChanged(this.view,this.topView),b=>{this.topView=b});const S=this.gui.addFolder(O("gui.export")).close();a.csv=()=>r.downloadCSV(),S.add(a,"csv").name(O("gui.csv")),a.toml=()=>r.downloadTOML();const R=S.add(a,"toml").name(O("gui.toml"));R.domElement.dataset.control="toml",R.domElement.title=O("gui.tomlHelp"),a.png=()=>r.screenshot(),S.add(a,"png").name(O("gui.png")),a.link=()=>r.copyLink(),S.add(a,"link").name(O("gui.link"))}view;gui;model;synced=[];runButton;modelControls;topView=!1;sync(t){const e=this.model;e.length=t.params.length,e.mass=t.params.mass,e.g=t.params.g,e.method=t.method,e.dt=t.dt,e.time_scale=t.time_scale,e.paused=t.paused,e.scenario=t.scenario??"";for(const n of this.synced)n.domElement.contains(document.activeElement)||n.updateDisplay();this.runButton.name(t.paused?O("toolbar.start"):O("toolbar.pause")),this.modelControls.sync(t)}}const Rb=!0,bn="u-",Cb="uplot",Pb=bn+"hz",Lb=bn+"vt",Db=bn+"title",Nb=bn+"wrap",Ib=bn+"under",Ub=bn+"over",Fb=bn+"axis",Xs=bn+"off",Ob=bn+"select",Bb=bn+"cursor-x",zb=bn+"cursor-y",kb=bn+"cursor-pt",Hb=bn+"legend",Gb=bn+"live",Vb=bn+"inline",Wb=bn+"series",Xb=bn+"marker",Jd=bn+"label",$b=bn+"value",va="width",xa="height",fa="top",jd="bottom",Rr="left",dc="right",Kh="#000",Qd=Kh+"0",fc="mousemove",tf="mousedown",pc="mouseup",ef="mouseenter",nf="mouseleave",sf="dblclick",Yb="resize",qb="scroll",rf="change",Jo="dppxchange",Zh="--",Yr=typeof window<"u",gh=Yr?document:null,Or=Yr?window:null,Kb=Yr?navigator:null;let we,To;function _h(){let i=devicePixelRatio;we!=i&&(we=i,To&&xh(rf,To,_h),To=matchMedia(`(min-resolution: ${we-.001}dppx) and (max-resolution: ${we+.001}dppx)`),Ys(rf,To,_h),Or.dispatchEvent(new CustomEvent(Jo)))}function ti(i,t){if(t!=null){let e=i.classList;!e.contains(t)&&e.add(t)}}function vh(i,t){let e=i.classList;e.contains(t)&&e.remove(t)}function Ve(i,t,e){i.style[t]=e+"px"}function bi(i,t,e,n){let s=gh.createElement(i);return t!=null&&ti(s,t),e?.insertBefore(s,n),s}function li(i,t){return bi("div",i,t)}const af=new WeakMap;function Bi(i,t,e,n,s){let r="translate("+t+"px,"+e+"px)",a=af.get(i);r!=a&&(i.style.transform=r,af.set(i,r),t<0||e<0||t>n||e>s?ti(i,Xs):vh(i,Xs))}const of=new WeakMap;function lf(i,t,e){let n=t+e,s=of.get(i);n!=s&&(of.set(i,n),i.style.background=t,i.style.borderColor=e)}const cf=new WeakMap;function hf(i,t,e,n){let s=t+""+e,r=cf.get(i);s!=r&&(cf.set(i,s),i.style.height=e+"px",i.style.width=t+"px",i.style.marginLeft=n?-t/2+"px":0,i.style.marginTop=n?-e/2+"px":0)}const Jh={passive:!0},Zb={...Jh,capture:!0};function Ys(i,t,e,n){t.addEventListener(i,e,n?Zb:Jh)}function xh(i,t,e,n){t.removeEventListener(i,e,Jh)}Yr&&_h();function Ei(i,t,e,n){let s;e=e||0,n=n||t.length-1;let r=n<=2147483647;for(;n-e>1;)s=r?e+n>>1:ni((e+n)/2),t[s]<i?e=s:n=s;return i-t[e]<=t[n]-i?e:n}function am(i){return(e,n,s)=>{let r=-1,a=-1;for(let o=n;o<=s;o++)if(i(e[o])){r=o;break}for(let o=s;o>=n;o--)if(i(e[o])){a=o;break}return[r,a]}}const om=i=>i!=null,lm=i=>i!=null&&i>0,al=am(om),Jb=am(lm);function jb(i,t,e,n=0,s=!1){let r=s?Jb:al,a=s?lm:om;[t,e]=r(i,t,e);let o=i[t],l=i[t];if(t>-1)if(n==1)o=i[t],l=i[e];else if(n==-1)o=i[e],l=i[t];else for(let c=t;c<=e;c++){let h=i[c];a(h)&&(h<o?o=h:h>l&&(l=h))}return[o??Fe,l??-Fe]}function ol(i,t,e,n){let s=ff(i),r=ff(t);i==t&&(s==-1?(i*=e,t/=e):(i/=e,t*=e));let a=e==10?cs:cm,o=s==1?ni:hi,l=r==1?hi:ni,c=o(a(xn(i))),h=l(a(xn(t))),u=Gr(e,c),d=Gr(e,h);return e==10&&(c<0&&(u=Oe(u,-c)),h<0&&(d=Oe(d,-h))),n||e==2?(i=u*s,t=d*r):(i=fm(i,u),t=ll(t,d)),[i,t]}function jh(i,t,e,n){let s=ol(i,t,e,n);return i==0&&(s[0]=0),t==0&&(s[1]=0),s}const Qh=.1,uf={mode:3,pad:Qh},Ea={pad:0,soft:null,mode:0},Qb={min:Ea,max:Ea};function jo(i,t,e,n){return cl(e)?df(i,t,e):(Ea.pad=e,Ea.soft=n?0:null,Ea.mode=n?3:0,df(i,t,Qb))}function be(i,t){return i??t}function tE(i,t,e){for(t=be(t,0),e=be(e,i.length-1);t<=e;){if(i[t]!=null)return!0;t++}return!1}function df(i,t,e){let n=e.min,s=e.max,r=be(n.pad,0),a=be(s.pad,0),o=be(n.hard,-Fe),l=be(s.hard,Fe),c=be(n.soft,Fe),h=be(s.soft,-Fe),u=be(n.mode,0),d=be(s.mode,0),m=t-i,_=cs(m),M=Vn(xn(i),xn(t)),p=cs(M),f=xn(p-_);(m<1e-24||f>10)&&(m=0,(i==0||t==0)&&(m=1e-24,u==2&&c!=Fe&&(r=0),d==2&&h!=-Fe&&(a=0)));let x=m||M||1e3,A=cs(x),S=Gr(10,ni(A)),R=x*(m==0?i==0?.1:1:r),b=Oe(fm(i-R,S/10),24),g=i>=c&&(u==1||u==3&&b<=c||u==2&&b>=c)?c:Fe,w=Vn(o,b<g&&i>=g?g:Ti(g,b)),z=x*(m==0?t==0?.1:1:a),I=Oe(ll(t+z,S/10),24),L=t<=h&&(d==1||d==3&&I>=h||d==2&&I<=h)?h:-Fe,V=Ti(l,I>L&&t<=L?L:Vn(L,I));return w==V&&w==0&&(V=100),[w,V]}const eE=new Intl.NumberFormat(Yr?Kb.language:"en-US"),tu=i=>eE.format(i),ii=Math,ko=ii.PI,xn=ii.abs,ni=ii.floor,vn=ii.round,hi=ii.ceil,Ti=ii.min,Vn=ii.max,Gr=ii.pow,ff=ii.sign,cs=ii.log10,cm=ii.log2,nE=(i,t=1)=>ii.sinh(i)*t,mc=(i,t=1)=>ii.asinh(i/t),Fe=1/0;function pf(i){return(cs((i^i>>31)-(i>>31))|0)+1}function Sh(i,t,e){return Ti(Vn(i,t),e)}function hm(i){return typeof i=="function"}function _e(i){return hm(i)?i:()=>i}const iE=()=>{},um=i=>i,dm=(i,t)=>t,sE=i=>null,mf=i=>!0,gf=(i,t)=>i==t,rE=/\.\d*?(?=9{6,}|0{6,})/gm,Js=i=>{if(mm(i)||Ns.has(i))return i;const t=`${i}`,e=t.match(rE);if(e==null)return i;let n=e[0].length-1;if(t.indexOf("e-")!=-1){let[s,r]=t.split("e");return+`${Js(s)}e${r}`}return Oe(i,n)};function Vs(i,t){return Js(Oe(Js(i/t))*t)}function ll(i,t){return Js(hi(Js(i/t))*t)}function fm(i,t){return Js(ni(Js(i/t))*t)}function Oe(i,t=0){if(mm(i))return i;let e=10**t,n=i*e*(1+Number.EPSILON);return vn(n)/e}const Ns=new Map;function pm(i){return((""+i).split(".")[1]||"").length}function Fa(i,t,e,n){let s=[],r=n.map(pm);for(let a=t;a<e;a++){let o=xn(a),l=Oe(Gr(i,a),o);for(let c=0;c<n.length;c++){let h=i==10?+`${n[c]}e${a}`:n[c]*l,u=(a>=0?0:o)+(a>=r[c]?0:r[c]),d=i==10?h:Oe(h,u);s.push(d),Ns.set(d,u)}}return s}const wa={},eu=[],Vr=[null,null],bs=Array.isArray,mm=Number.isInteger,aE=i=>i===void 0;function _f(i){return typeof i=="string"}function cl(i){let t=!1;if(i!=null){let e=i.constructor;t=e==null||e==Object}return t}function oE(i){return i!=null&&typeof i=="object"}const lE=Object.getPrototypeOf(Uint8Array),gm="__proto__";function Wr(i,t=cl){let e;if(bs(i)){let n=i.find(s=>s!=null);if(bs(n)||t(n)){e=Array(i.length);for(let s=0;s<i.length;s++)e[s]=Wr(i[s],t)}else e=i.slice()}else if(i instanceof lE)e=i.slice();else if(t(i)){e={};for(let n in i)n!=gm&&(e[n]=Wr(i[n],t))}else e=i;return e}function dn(i){let t=arguments;for(let e=1;e<t.length;e++){let n=t[e];for(let s in n)s!=gm&&(cl(i[s])?dn(i[s],Wr(n[s])):i[s]=Wr(n[s]))}return i}const cE=0,hE=1,uE=2;function dE(i,t,e){for(let n=0,s,r=-1;n<t.length;n++){let a=t[n];if(a>r){for(s=a-1;s>=0&&i[s]==null;)i[s--]=null;for(s=a+1;s<e&&i[s]==null;)i[r=s++]=null}}}function fE(i,t){if(gE(i)){let a=i[0].slice();for(let o=1;o<i.length;o++)a.push(...i[o].slice(1));return _E(a[0])||(a=mE(a)),a}let e=new Set;for(let a=0;a<i.length;a++){let l=i[a][0],c=l.length;for(let h=0;h<c;h++)e.add(l[h])}let n=[Array.from(e).sort((a,o)=>a-o)],s=n[0].length,r=new Map;for(let a=0;a<s;a++)r.set(n[0][a],a);for(let a=0;a<i.length;a++){let o=i[a],l=o[0];for(let c=1;c<o.length;c++){let h=o[c],u=Array(s).fill(void 0),d=t?t[a][c]:hE,m=[];for(let _=0;_<h.length;_++){let M=h[_],p=r.get(l[_]);M===null?d!=cE&&(u[p]=M,d==uE&&m.push(p)):u[p]=M}dE(u,m,s),n.push(u)}}return n}const pE=typeof queueMicrotask>"u"?i=>Promise.resolve().then(i):queueMicrotask;function mE(i){let t=i[0],e=t.length,n=Array(e);for(let r=0;r<n.length;r++)n[r]=r;n.sort((r,a)=>t[r]-t[a]);let s=[];for(let r=0;r<i.length;r++){let a=i[r],o=Array(e);for(let l=0;l<e;l++)o[l]=a[n[l]];s.push(o)}return s}function gE(i){let t=i[0][0],e=t.length;for(let n=1;n<i.length;n++){let s=i[n][0];if(s.length!=e)return!1;if(s!=t){for(let r=0;r<e;r++)if(s[r]!=t[r])return!1}}return!0}function _E(i,t=100){const e=i.length;if(e<=1)return!0;let n=0,s=e-1;for(;n<=s&&i[n]==null;)n++;for(;s>=n&&i[s]==null;)s--;if(s<=n)return!0;const r=Vn(1,ni((s-n+1)/t));for(let a=i[n],o=n+r;o<=s;o+=r){const l=i[o];if(l!=null){if(l<=a)return!1;a=l}}return!0}const _m=["January","February","March","April","May","June","July","August","September","October","November","December"],vm=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function xm(i){return i.slice(0,3)}const vE=vm.map(xm),xE=_m.map(xm),SE={MMMM:_m,MMM:xE,WWWW:vm,WWW:vE};function pa(i){return(i<10?"0":"")+i}function ME(i){return(i<10?"00":i<100?"0":"")+i}const yE={YYYY:i=>i.getFullYear(),YY:i=>(i.getFullYear()+"").slice(2),MMMM:(i,t)=>t.MMMM[i.getMonth()],MMM:(i,t)=>t.MMM[i.getMonth()],MM:i=>pa(i.getMonth()+1),M:i=>i.getMonth()+1,DD:i=>pa(i.getDate()),D:i=>i.getDate(),WWWW:(i,t)=>t.WWWW[i.getDay()],WWW:(i,t)=>t.WWW[i.getDay()],HH:i=>pa(i.getHours()),H:i=>i.getHours(),h:i=>{let t=i.getHours();return t==0?12:t>12?t-12:t},AA:i=>i.getHours()>=12?"PM":"AM",aa:i=>i.getHours()>=12?"pm":"am",a:i=>i.getHours()>=12?"p":"a",mm:i=>pa(i.getMinutes()),m:i=>i.getMinutes(),ss:i=>pa(i.getSeconds()),s:i=>i.getSeconds(),fff:i=>ME(i.getMilliseconds())};function nu(i,t){t=t||SE;let e=[],n=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=n.exec(i);)e.push(s[0][0]=="{"?yE[s[1]]:s[0]);return r=>{let a="";for(let o=0;o<e.length;o++)a+=typeof e[o]=="string"?e[o]:e[o](r,t);return a}}const bE=new Intl.DateTimeFormat().resolvedOptions().timeZone;function EE(i,t){let e;return t=="UTC"||t=="Etc/UTC"?e=new Date(+i+i.getTimezoneOffset()*6e4):t==bE?e=i:(e=new Date(i.toLocaleString("en-US",{timeZone:t})),e.setMilliseconds(i.getMilliseconds())),e}const Sm=i=>i%1==0,Qo=[1,2,2.5,5],wE=Fa(10,-32,0,Qo),Mm=Fa(10,0,32,Qo),TE=Mm.filter(Sm),Ws=wE.concat(Mm),iu=`
`,ym="{YYYY}",vf=iu+ym,bm="{M}/{D}",Sa=iu+bm,Ao=Sa+"/{YY}",Em="{aa}",AE="{h}:{mm}",Dr=AE+Em,xf=iu+Dr,Sf=":{ss}",Ae=null;function wm(i){let t=i*1e3,e=t*60,n=e*60,s=n*24,r=s*30,a=s*365,l=(i==1?Fa(10,0,3,Qo).filter(Sm):Fa(10,-3,0,Qo)).concat([t,t*5,t*10,t*15,t*30,e,e*5,e*10,e*15,e*30,n,n*2,n*3,n*4,n*6,n*8,n*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,a,a*2,a*5,a*10,a*25,a*50,a*100]);const c=[[a,ym,Ae,Ae,Ae,Ae,Ae,Ae,1],[s*28,"{MMM}",vf,Ae,Ae,Ae,Ae,Ae,1],[s,bm,vf,Ae,Ae,Ae,Ae,Ae,1],[n,"{h}"+Em,Ao,Ae,Sa,Ae,Ae,Ae,1],[e,Dr,Ao,Ae,Sa,Ae,Ae,Ae,1],[t,Sf,Ao+" "+Dr,Ae,Sa+" "+Dr,Ae,xf,Ae,1],[i,Sf+".{fff}",Ao+" "+Dr,Ae,Sa+" "+Dr,Ae,xf,Ae,1]];function h(u){return(d,m,_,M,p,f)=>{let x=[],A=p>=a,S=p>=r&&p<a,R=u(_),b=Oe(R*i,3),g=gc(R.getFullYear(),A?0:R.getMonth(),S||A?1:R.getDate()),w=Oe(g*i,3);if(S||A){let z=S?p/r:0,I=A?p/a:0,L=b==w?b:Oe(gc(g.getFullYear()+I,g.getMonth()+z,1)*i,3),V=new Date(vn(L/i)),$=V.getFullYear(),N=V.getMonth();for(let W=0;L<=M;W++){let J=gc($+I*W,N+z*W,1),H=J-u(Oe(J*i,3));L=Oe((+J+H)*i,3),L<=M&&x.push(L)}}else{let z=p>=s?s:p,I=ni(_)-ni(b),L=w+I+ll(b-w,z);x.push(L);let V=u(L),$=V.getHours()+V.getMinutes()/e+V.getSeconds()/n,N=p/n,W=d.axes[m]._space,J=f/W;for(;L=Oe(L+p,i==1?0:3),!(L>M);)if(N>1){let H=ni(Oe($+N,6))%24,tt=u(L).getHours()-H;tt>1&&(tt=-1),L-=tt*n,$=($+N)%24;let st=x[x.length-1];Oe((L-st)/p,3)*J>=.7&&x.push(L)}else x.push(L)}return x}}return[l,c,h]}const[RE,CE,PE]=wm(1),[LE,DE,NE]=wm(.001);Fa(2,-53,53,[1]);function Mf(i,t){return i.map(e=>e.map((n,s)=>s==0||s==8||n==null?n:t(s==1||e[8]==0?n:e[1]+n)))}function yf(i,t){return(e,n,s,r,a)=>{let o=t.find(_=>a>=_[0])||t[t.length-1],l,c,h,u,d,m;return n.map(_=>{let M=i(_),p=M.getFullYear(),f=M.getMonth(),x=M.getDate(),A=M.getHours(),S=M.getMinutes(),R=M.getSeconds(),b=p!=l&&o[2]||f!=c&&o[3]||x!=h&&o[4]||A!=u&&o[5]||S!=d&&o[6]||R!=m&&o[7]||o[1];return l=p,c=f,h=x,u=A,d=S,m=R,b(M)})}}function IE(i,t){let e=nu(t);return(n,s,r,a,o)=>s.map(l=>e(i(l)))}function gc(i,t,e){return new Date(i,t,e)}function bf(i,t){return t(i)}const UE="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function Ef(i,t){return(e,n,s,r)=>r==null?Zh:t(i(n))}function FE(i,t){let e=i.series[t];return e.width?e.stroke(i,t):e.points.width?e.points.stroke(i,t):null}function OE(i,t){return i.series[t].fill(i,t)}const BE={show:!0,live:!0,isolate:!1,mount:iE,markers:{show:!0,width:2,stroke:FE,fill:OE,dash:"solid"},idx:null,idxs:null,values:[]};function zE(i,t){let e=i.cursor.points,n=li(),s=e.size(i,t);Ve(n,va,s),Ve(n,xa,s);let r=s/-2;Ve(n,"marginLeft",r),Ve(n,"marginTop",r);let a=e.width(i,t,s);return a&&Ve(n,"borderWidth",a),n}function kE(i,t){let e=i.series[t].points;return e._fill||e._stroke}function HE(i,t){let e=i.series[t].points;return e._stroke||e._fill}function GE(i,t){return i.series[t].points.size}const _c=[0,0];function VE(i,t,e){return _c[0]=t,_c[1]=e,_c}function Ro(i,t,e,n=!0){return s=>{s.button==0&&(!n||s.target==t)&&e(s)}}function vc(i,t,e,n=!0){return s=>{(!n||s.target==t)&&e(s)}}const WE={show:!0,x:!0,y:!0,lock:!1,move:VE,points:{one:!1,show:zE,size:GE,width:0,stroke:HE,fill:kE},bind:{mousedown:Ro,mouseup:Ro,click:Ro,dblclick:Ro,mousemove:vc,mouseleave:vc,mouseenter:vc},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(i,t)=>{t.stopPropagation(),t.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(i,t,e,n,s)=>n-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},Tm={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},su=dn({},Tm,{filter:dm}),Am=dn({},su,{size:10}),Rm=dn({},Tm,{show:!1}),ru='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',Cm="bold "+ru,Pm=1.5,wf={show:!0,scale:"x",stroke:Kh,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Cm,side:2,grid:su,ticks:Am,border:Rm,font:ru,lineGap:Pm,rotate:0},XE="Value",$E="Time",Tf={show:!0,scale:"x",auto:!1,sorted:1,min:Fe,max:-Fe,idxs:[]};function YE(i,t,e,n,s){return t.map(r=>r==null?"":tu(r))}function qE(i,t,e,n,s,r,a){let o=[],l=Ns.get(s)||0;e=a?e:Oe(ll(e,s),l);for(let c=e;c<=n;c=Oe(c+s,l))o.push(Object.is(c,-0)?0:c);return o}function Mh(i,t,e,n,s,r,a){const o=[],l=i.scales[i.axes[t].scale].log,c=l==10?cs:cm,h=ni(c(e));s=Gr(l,h),l==10&&(s=Ws[Ei(s,Ws)]);let u=e,d=s*l;l==10&&(d=Ws[Ei(d,Ws)]);do o.push(u),u=u+s,l==10&&!Ns.has(u)&&(u=Oe(u,Ns.get(s))),u>=d&&(s=u,d=s*l,l==10&&(d=Ws[Ei(d,Ws)]));while(u<=n);return o}function KE(i,t,e,n,s,r,a){let l=i.scales[i.axes[t].scale].asinh,c=n>l?Mh(i,t,Vn(l,e),n,s):[l],h=n>=0&&e<=0?[0]:[];return(e<-l?Mh(i,t,Vn(l,-n),-e,s):[l]).reverse().map(d=>-d).concat(h,c)}const Lm=/./,ZE=/[12357]/,JE=/[125]/,Af=/1/,yh=(i,t,e,n)=>i.map((s,r)=>t==4&&s==0||r%n==0&&e.test(s.toExponential()[s<0?1:0])?s:null);function jE(i,t,e,n,s){let r=i.axes[e],a=r.scale,o=i.scales[a],l=i.valToPos,c=r._space,h=l(10,a),u=l(9,a)-h>=c?Lm:l(7,a)-h>=c?ZE:l(5,a)-h>=c?JE:Af;if(u==Af){let d=xn(l(1,a)-h);if(d<c)return yh(t.slice().reverse(),o.distr,u,hi(c/d)).reverse()}return yh(t,o.distr,u,1)}function QE(i,t,e,n,s){let r=i.axes[e],a=r.scale,o=r._space,l=i.valToPos,c=xn(l(1,a)-l(2,a));return c<o?yh(t.slice().reverse(),3,Lm,hi(o/c)).reverse():t}function tw(i,t,e,n){return n==null?Zh:t==null?"":tu(t)}const Rf={show:!0,scale:"y",stroke:Kh,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Cm,side:3,grid:su,ticks:Am,border:Rm,font:ru,lineGap:Pm,rotate:0};function ew(i,t){let e=3+(i||1)*2;return Oe(e*t,3)}function nw(i,t){let{scale:e,idxs:n}=i.series[0],s=i._data[0],r=i.valToPos(s[n[0]],e,!0),a=i.valToPos(s[n[1]],e,!0),o=xn(a-r),l=i.series[t],c=o/(l.points.space*we);return n[1]-n[0]<=c}const Cf={scale:null,auto:!0,sorted:0,min:Fe,max:-Fe},Dm=(i,t,e,n,s)=>s,Pf={show:!0,auto:!0,sorted:0,gaps:Dm,alpha:1,facets:[dn({},Cf,{scale:"x"}),dn({},Cf,{scale:"y"})]},Lf={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:Dm,alpha:1,points:{show:nw,filter:null},values:null,min:Fe,max:-Fe,idxs:[],path:null,clip:null};function iw(i,t,e,n,s){return e/10}const Nm={time:Rb,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},sw=dn({},Nm,{time:!1,ori:1}),Df={};function Im(i,t){let e=Df[i];return e||(e={key:i,plots:[],sub(n){e.plots.push(n)},unsub(n){e.plots=e.plots.filter(s=>s!=n)},pub(n,s,r,a,o,l,c){for(let h=0;h<e.plots.length;h++)e.plots[h]!=s&&e.plots[h].pub(n,s,r,a,o,l,c)}},i!=null&&(Df[i]=e)),e}const Xr=1,bh=2;function tr(i,t,e){const n=i.mode,s=i.series[t],r=n==2?i._data[t]:i._data,a=i.scales,o=i.bbox;let l=r[0],c=n==2?r[1]:r[t],h=n==2?a[s.facets[0].scale]:a[i.series[0].scale],u=n==2?a[s.facets[1].scale]:a[s.scale],d=o.left,m=o.top,_=o.width,M=o.height,p=i.valToPosH,f=i.valToPosV;return h.ori==0?e(s,l,c,h,u,p,f,d,m,_,M,ul,qr,fl,Fm,Bm):e(s,l,c,h,u,f,p,m,d,M,_,dl,Kr,lu,Om,zm)}function au(i,t){let e=0,n=0,s=be(i.bands,eu);for(let r=0;r<s.length;r++){let a=s[r];a.series[0]==t?e=a.dir:a.series[1]==t&&(a.dir==1?n|=1:n|=2)}return[e,n==1?-1:n==2?1:n==3?2:0]}function rw(i,t,e,n,s){let r=i.mode,a=i.series[t],o=r==2?a.facets[1].scale:a.scale,l=i.scales[o];return s==-1?l.min:s==1?l.max:l.distr==3?l.dir==1?l.min:l.max:0}function hs(i,t,e,n,s,r){return tr(i,t,(a,o,l,c,h,u,d,m,_,M,p)=>{let f=a.pxRound;const x=c.dir*(c.ori==0?1:-1),A=c.ori==0?qr:Kr;let S,R;x==1?(S=e,R=n):(S=n,R=e);let b=f(u(o[S],c,M,m)),g=f(d(l[S],h,p,_)),w=f(u(o[R],c,M,m)),z=f(d(r==1?h.max:h.min,h,p,_)),I=new Path2D(s);return A(I,w,z),A(I,b,z),A(I,b,g),I})}function hl(i,t,e,n,s,r){let a=null;if(i.length>0){a=new Path2D;const o=t==0?fl:lu;let l=e;for(let u=0;u<i.length;u++){let d=i[u];if(d[1]>d[0]){let m=d[0]-l;m>0&&o(a,l,n,m,n+r),l=d[1]}}let c=e+s-l,h=10;c>0&&o(a,l,n-h/2,c,n+r+h)}return a}function aw(i,t,e){let n=i[i.length-1];n&&n[0]==t?n[1]=e:i.push([t,e])}function ou(i,t,e,n,s,r,a){let o=[],l=i.length;for(let c=s==1?e:n;c>=e&&c<=n;c+=s)if(t[c]===null){let u=c,d=c;if(s==1)for(;++c<=n&&t[c]===null;)d=c;else for(;--c>=e&&t[c]===null;)d=c;let m=r(i[u]),_=d==u?m:r(i[d]),M=u-s;m=a<=0&&M>=0&&M<l?r(i[M]):m;let f=d+s;_=a>=0&&f>=0&&f<l?r(i[f]):_,_>=m&&o.push([m,_])}return o}function Nf(i){return i==0?um:i==1?vn:t=>Vs(t,i)}function Um(i){let t=i==0?ul:dl,e=i==0?(s,r,a,o,l,c)=>{s.arcTo(r,a,o,l,c)}:(s,r,a,o,l,c)=>{s.arcTo(a,r,l,o,c)},n=i==0?(s,r,a,o,l)=>{s.rect(r,a,o,l)}:(s,r,a,o,l)=>{s.rect(a,r,l,o)};return(s,r,a,o,l,c=0,h=0)=>{c==0&&h==0?n(s,r,a,o,l):(c=Ti(c,o/2,l/2),h=Ti(h,o/2,l/2),t(s,r+c,a),e(s,r+o,a,r+o,a+l,c),e(s,r+o,a+l,r,a+l,h),e(s,r,a+l,r,a,h),e(s,r,a,r+o,a,c),s.closePath())}}const ul=(i,t,e)=>{i.moveTo(t,e)},dl=(i,t,e)=>{i.moveTo(e,t)},qr=(i,t,e)=>{i.lineTo(t,e)},Kr=(i,t,e)=>{i.lineTo(e,t)},fl=Um(0),lu=Um(1),Fm=(i,t,e,n,s,r)=>{i.arc(t,e,n,s,r)},Om=(i,t,e,n,s,r)=>{i.arc(e,t,n,s,r)},Bm=(i,t,e,n,s,r,a)=>{i.bezierCurveTo(t,e,n,s,r,a)},zm=(i,t,e,n,s,r,a)=>{i.bezierCurveTo(e,t,s,n,a,r)};function km(i){return(t,e,n,s,r)=>tr(t,e,(a,o,l,c,h,u,d,m,_,M,p)=>{let{pxRound:f,points:x}=a,A,S;c.ori==0?(A=ul,S=Fm):(A=dl,S=Om);const R=Oe(x.width*we,3);let b=(x.size-x.width)/2*we,g=Oe(b*2,3),w=new Path2D,z=new Path2D,{left:I,top:L,width:V,height:$}=t.bbox;fl(z,I-g,L-g,V+g*2,$+g*2);const N=W=>{if(l[W]!=null){let J=f(u(o[W],c,M,m)),H=f(d(l[W],h,p,_));A(w,J+b,H),S(w,J,H,b,0,ko*2)}};if(r)r.forEach(N);else for(let W=n;W<=s;W++)N(W);return{stroke:R>0?w:null,fill:w,clip:z,flags:Xr|bh}})}function Hm(i){return(t,e,n,s,r,a)=>{n!=s&&(r!=n&&a!=n&&i(t,e,n),r!=s&&a!=s&&i(t,e,s),i(t,e,a))}}const ow=Hm(qr),lw=Hm(Kr);function Gm(i){const t=be(i?.alignGaps,0);return(e,n,s,r)=>tr(e,n,(a,o,l,c,h,u,d,m,_,M,p)=>{[s,r]=al(l,s,r);let f=a.pxRound,x=$=>f(u($,c,M,m)),A=$=>f(d($,h,p,_)),S,R;c.ori==0?(S=qr,R=ow):(S=Kr,R=lw);const b=c.dir*(c.ori==0?1:-1),g={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:Xr},w=g.stroke;let z=!1;if(r-s>=M*4){let $=ft=>e.posToVal(ft,c.key,!0),N=null,W=null,J,H,ct,Z=x(o[b==1?s:r]),tt=x(o[s]),st=x(o[r]),pt=$(b==1?tt+1:st-1);for(let ft=b==1?s:r;ft>=s&&ft<=r;ft+=b){let B=o[ft],ht=(b==1?B<pt:B>pt)?Z:x(B),gt=l[ft];ht==Z?gt!=null?(H=gt,N==null?(S(w,ht,A(H)),J=N=W=H):H<N?N=H:H>W&&(W=H)):gt===null&&(z=!0):(N!=null&&R(w,Z,A(N),A(W),A(J),A(H)),gt!=null?(H=gt,S(w,ht,A(H)),N=W=J=H):(N=W=null,gt===null&&(z=!0)),Z=ht,pt=$(Z+b))}N!=null&&N!=W&&ct!=Z&&R(w,Z,A(N),A(W),A(J),A(H))}else for(let $=b==1?s:r;$>=s&&$<=r;$+=b){let N=l[$];N===null?z=!0:N!=null&&S(w,x(o[$]),A(N))}let[L,V]=au(e,n);if(a.fill!=null||L!=0){let $=g.fill=new Path2D(w),N=a.fillTo(e,n,a.min,a.max,L),W=A(N),J=x(o[s]),H=x(o[r]);b==-1&&([H,J]=[J,H]),S($,H,W),S($,J,W)}if(!a.spanGaps){let $=[];z&&$.push(...ou(o,l,s,r,b,x,t)),g.gaps=$=a.gaps(e,n,s,r,$),g.clip=hl($,c.ori,m,_,M,p)}return V!=0&&(g.band=V==2?[hs(e,n,s,r,w,-1),hs(e,n,s,r,w,1)]:hs(e,n,s,r,w,V)),g})}function cw(i){const t=be(i.align,1),e=be(i.ascDesc,!1),n=be(i.alignGaps,0),s=be(i.extend,!1);return(r,a,o,l)=>tr(r,a,(c,h,u,d,m,_,M,p,f,x,A)=>{[o,l]=al(u,o,l);let S=c.pxRound,{left:R,width:b}=r.bbox,g=tt=>S(_(tt,d,x,p)),w=tt=>S(M(tt,m,A,f)),z=d.ori==0?qr:Kr;const I={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:Xr},L=I.stroke,V=d.dir*(d.ori==0?1:-1);let $=w(u[V==1?o:l]),N=g(h[V==1?o:l]),W=N,J=N;s&&t==-1&&(J=R,z(L,J,$)),z(L,N,$);for(let tt=V==1?o:l;tt>=o&&tt<=l;tt+=V){let st=u[tt];if(st==null)continue;let pt=g(h[tt]),ft=w(st);t==1?z(L,pt,$):z(L,W,ft),z(L,pt,ft),$=ft,W=pt}let H=W;s&&t==1&&(H=R+b,z(L,H,$));let[ct,Z]=au(r,a);if(c.fill!=null||ct!=0){let tt=I.fill=new Path2D(L),st=c.fillTo(r,a,c.min,c.max,ct),pt=w(st);z(tt,H,pt),z(tt,J,pt)}if(!c.spanGaps){let tt=[];tt.push(...ou(h,u,o,l,V,g,n));let st=c.width*we/2,pt=e||t==1?st:-st,ft=e||t==-1?-st:st;tt.forEach(B=>{B[0]+=pt,B[1]+=ft}),I.gaps=tt=c.gaps(r,a,o,l,tt),I.clip=hl(tt,d.ori,p,f,x,A)}return Z!=0&&(I.band=Z==2?[hs(r,a,o,l,L,-1),hs(r,a,o,l,L,1)]:hs(r,a,o,l,L,Z)),I})}function If(i,t,e,n,s,r,a=Fe){if(i.length>1){let o=null;for(let l=0,c=1/0;l<i.length;l++)if(t[l]!==void 0){if(o!=null){let h=xn(i[l]-i[o]);h<c&&(c=h,a=xn(e(i[l],n,s,r)-e(i[o],n,s,r)))}o=l}}return a}function hw(i){i=i||wa;const t=be(i.size,[.6,Fe,1]),e=i.align||0,n=i.gap||0;let s=i.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;const r=_e(s),a=1-t[0],o=be(t[1],Fe),l=be(t[2],1),c=be(i.disp,wa),h=be(i.each,m=>{}),{fill:u,stroke:d}=c;return(m,_,M,p)=>tr(m,_,(f,x,A,S,R,b,g,w,z,I,L)=>{let V=f.pxRound,$=e,N=n*we,W=o*we,J=l*we,H,ct;S.ori==0?[H,ct]=r(m,_):[ct,H]=r(m,_);const Z=S.dir*(S.ori==0?1:-1);let tt=S.ori==0?fl:lu,st=S.ori==0?h:(Ct,Yt,se,Et,Ue,Ht,$t)=>{h(Ct,Yt,se,Ue,Et,$t,Ht)},pt=be(m.bands,eu).find(Ct=>Ct.series[0]==_),ft=pt!=null?pt.dir:0,B=f.fillTo(m,_,f.min,f.max,ft),et=V(g(B,R,L,z)),ht,gt,vt,Gt=I,Qt=V(f.width*we),kt=!1,ne=null,ee=null,qt=null,Ie=null;u!=null&&(Qt==0||d!=null)&&(kt=!0,ne=u.values(m,_,M,p),ee=new Map,new Set(ne).forEach(Ct=>{Ct!=null&&ee.set(Ct,new Path2D)}),Qt>0&&(qt=d.values(m,_,M,p),Ie=new Map,new Set(qt).forEach(Ct=>{Ct!=null&&Ie.set(Ct,new Path2D)})));let{x0:me,size:Xe}=c;if(me!=null&&Xe!=null){$=1,x=me.values(m,_,M,p),me.unit==2&&(x=x.map(se=>m.posToVal(w+se*I,S.key,!0)));let Ct=Xe.values(m,_,M,p);Xe.unit==2?gt=Ct[0]*I:gt=b(Ct[0],S,I,w)-b(0,S,I,w),Gt=If(x,A,b,S,I,w,Gt),vt=Gt-gt+N}else Gt=If(x,A,b,S,I,w,Gt),vt=Gt*a+N,gt=Gt-vt;vt<1&&(vt=0),Qt>=gt/2&&(Qt=0),vt<5&&(V=um);let Me=vt>0,rn=Gt-vt-(Me?Qt:0);gt=V(Sh(rn,J,W)),ht=($==0?gt/2:$==Z?0:gt)-$*Z*(($==0?N/2:0)+(Me?Qt/2:0));const de={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},pn=kt?null:new Path2D;let qe=null;if(pt!=null)qe=m.data[pt.series[1]];else{let{y0:Ct,y1:Yt}=c;Ct!=null&&Yt!=null&&(A=Yt.values(m,_,M,p),qe=Ct.values(m,_,M,p))}let an=H*gt,F=ct*gt;for(let Ct=Z==1?M:p;Ct>=M&&Ct<=p;Ct+=Z){let Yt=A[Ct];if(Yt==null)continue;if(qe!=null){let Y=qe[Ct]??0;if(Yt-Y==0)continue;et=g(Y,R,L,z)}let se=S.distr!=2||c!=null?x[Ct]:Ct,Et=b(se,S,I,w),Ue=g(be(Yt,B),R,L,z),Ht=V(Et-ht),$t=V(Vn(Ue,et)),C=V(Ti(Ue,et)),y=$t-C;if(Yt!=null){let Y=Yt<0?F:an,dt=Yt<0?an:F;kt?(Qt>0&&qt[Ct]!=null&&tt(Ie.get(qt[Ct]),Ht,C+ni(Qt/2),gt,Vn(0,y-Qt),Y,dt),ne[Ct]!=null&&tt(ee.get(ne[Ct]),Ht,C+ni(Qt/2),gt,Vn(0,y-Qt),Y,dt)):tt(pn,Ht,C+ni(Qt/2),gt,Vn(0,y-Qt),Y,dt),st(m,_,Ct,Ht-Qt/2,C,gt+Qt,y)}}return Qt>0?de.stroke=kt?Ie:pn:kt||(de._fill=f.width==0?f._fill:f._stroke??f._fill,de.width=0),de.fill=kt?ee:pn,de})}function uw(i,t){const e=be(t?.alignGaps,0);return(n,s,r,a)=>tr(n,s,(o,l,c,h,u,d,m,_,M,p,f)=>{[r,a]=al(c,r,a);let x=o.pxRound,A=H=>x(d(H,h,p,_)),S=H=>x(m(H,u,f,M)),R,b,g;h.ori==0?(R=ul,g=qr,b=Bm):(R=dl,g=Kr,b=zm);const w=h.dir*(h.ori==0?1:-1);let z=A(l[w==1?r:a]),I=z,L=[],V=[];for(let H=w==1?r:a;H>=r&&H<=a;H+=w)if(c[H]!=null){let Z=l[H],tt=A(Z);L.push(I=tt),V.push(S(c[H]))}const $={stroke:i(L,V,R,g,b,x),fill:null,clip:null,band:null,gaps:null,flags:Xr},N=$.stroke;let[W,J]=au(n,s);if(o.fill!=null||W!=0){let H=$.fill=new Path2D(N),ct=o.fillTo(n,s,o.min,o.max,W),Z=S(ct);g(H,I,Z),g(H,z,Z)}if(!o.spanGaps){let H=[];H.push(...ou(l,c,r,a,w,A,e)),$.gaps=H=o.gaps(n,s,r,a,H),$.clip=hl(H,h.ori,_,M,p,f)}return J!=0&&($.band=J==2?[hs(n,s,r,a,N,-1),hs(n,s,r,a,N,1)]:hs(n,s,r,a,N,J)),$})}function dw(i){return uw(fw,i)}function fw(i,t,e,n,s,r){const a=i.length;if(a<2)return null;const o=new Path2D;if(e(o,i[0],t[0]),a==2)n(o,i[1],t[1]);else{let l=Array(a),c=Array(a-1),h=Array(a-1),u=Array(a-1);for(let d=0;d<a-1;d++)h[d]=t[d+1]-t[d],u[d]=i[d+1]-i[d],c[d]=h[d]/u[d];l[0]=c[0];for(let d=1;d<a-1;d++)c[d]===0||c[d-1]===0||c[d-1]>0!=c[d]>0?l[d]=0:(l[d]=3*(u[d-1]+u[d])/((2*u[d]+u[d-1])/c[d-1]+(u[d]+2*u[d-1])/c[d]),isFinite(l[d])||(l[d]=0));l[a-1]=c[a-2];for(let d=0;d<a-1;d++)s(o,i[d]+u[d]/3,t[d]+l[d]*u[d]/3,i[d+1]-u[d]/3,t[d+1]-l[d+1]*u[d]/3,i[d+1],t[d+1])}return o}const Eh=new Set;function Uf(){for(let i of Eh)i.syncRect(!0)}Yr&&(Ys(Yb,Or,Uf),Ys(qb,Or,Uf,!0),Ys(Jo,Or,()=>{Un.pxRatio=we}));const pw=Gm(),mw=km();function Ff(i,t,e,n){return(n?[i[0],i[1]].concat(i.slice(2)):[i[0]].concat(i.slice(1))).map((r,a)=>wh(r,a,t,e))}function gw(i,t){return i.map((e,n)=>n==0?{}:dn({},t,e))}function wh(i,t,e,n){return dn({},t==0?e:n,i)}function Vm(i,t,e){return t==null?Vr:[t,e]}const _w=Vm;function vw(i,t,e){return t==null?Vr:jo(t,e,Qh,!0)}function Wm(i,t,e,n){return t==null?Vr:ol(t,e,i.scales[n].log,!1)}const xw=Wm;function Xm(i,t,e,n){return t==null?Vr:jh(t,e,i.scales[n].log,!1)}const Sw=Xm;function Mw(i,t,e,n,s){let r=Vn(pf(i),pf(t)),a=t-i,o=Ei(s/n*a,e);do{let l=e[o],c=n*l/a;if(c>=s&&r+(l<5?Ns.get(l):0)<=17)return[l,c]}while(++o<e.length);return[0,0]}function Of(i){let t,e;return i=i.replace(/(\d+)px/,(n,s)=>(t=vn((e=+s)*we))+"px"),[i,t,e]}function yw(i){i.show&&[i.font,i.labelFont].forEach(t=>{let e=Oe(t[2]*we,1);t[0]=t[0].replace(/[0-9.]+px/,e+"px"),t[1]=e})}function Un(i,t,e){const n={mode:be(i.mode,1)},s=n.mode;function r(v,E,P,D){let X=E.valToPct(v);return D+P*(E.dir==-1?1-X:X)}function a(v,E,P,D){let X=E.valToPct(v);return D+P*(E.dir==-1?X:1-X)}function o(v,E,P,D){return E.ori==0?r(v,E,P,D):a(v,E,P,D)}n.valToPosH=r,n.valToPosV=a;let l=!1;n.status=0;const c=n.root=li(Cb);if(i.id!=null&&(c.id=i.id),ti(c,i.class),i.title){let v=li(Db,c);v.textContent=i.title}const h=bi("canvas"),u=n.ctx=h.getContext("2d"),d=li(Nb,c);Ys("click",d,v=>{v.target===_&&(ke!=or||We!=lr)&&Cn.click(n,v)},!0);const m=n.under=li(Ib,d);d.appendChild(h);const _=n.over=li(Ub,d);i=Wr(i);const M=+be(i.pxAlign,1),p=Nf(M);(i.plugins||[]).forEach(v=>{v.opts&&(i=v.opts(n,i)||i)});const f=i.ms||.001,x=n.series=s==1?Ff(i.series||[],Tf,Lf,!1):gw(i.series||[null],Pf),A=n.axes=Ff(i.axes||[],wf,Rf,!0),S=n.scales={},R=n.bands=i.bands||[];R.forEach(v=>{v.fill=_e(v.fill||null),v.dir=be(v.dir,-1)});const b=s==2?x[1].facets[0].scale:x[0].scale,g={axes:Qi,series:ue},w=(i.drawOrder||["axes","series"]).map(v=>g[v]);function z(v){const E=v.distr==3?P=>cs(P>0?P:v.clamp(n,P,v.min,v.max,v.key)):v.distr==4?P=>mc(P,v.asinh):v.distr==100?P=>v.fwd(P):P=>P;return P=>{let D=E(P),{_min:X,_max:j}=v,lt=j-X;return(D-X)/lt}}function I(v){let E=S[v];if(E==null){let P=(i.scales||wa)[v]||wa;if(P.from!=null){I(P.from);let D=dn({},S[P.from],P,{key:v});D.valToPct=z(D),S[v]=D}else{E=S[v]=dn({},v==b?Nm:sw,P),E.key=v;let D=E.time,X=E.range,j=bs(X);if((v!=b||s==2&&!D)&&(j&&(X[0]==null||X[1]==null)&&(X={min:X[0]==null?uf:{mode:1,hard:X[0],soft:X[0]},max:X[1]==null?uf:{mode:1,hard:X[1],soft:X[1]}},j=!1),!j&&cl(X))){let lt=X;X=(mt,yt,Nt)=>yt==null?Vr:jo(yt,Nt,lt)}E.range=_e(X||(D?_w:v==b?E.distr==3?xw:E.distr==4?Sw:Vm:E.distr==3?Wm:E.distr==4?Xm:vw)),E.auto=_e(j?!1:E.auto),E.clamp=_e(E.clamp||iw),E._min=E._max=null,E.valToPct=z(E)}}}I("x"),I("y"),s==1&&x.forEach(v=>{I(v.scale)}),A.forEach(v=>{I(v.scale)});for(let v in i.scales)I(v);const L=S[b],V=L.distr;let $,N;L.ori==0?(ti(c,Pb),$=r,N=a):(ti(c,Lb),$=a,N=r);const W={};for(let v in S){let E=S[v];(E.min!=null||E.max!=null)&&(W[v]={min:E.min,max:E.max},E.min=E.max=null)}const J=i.tzDate||(v=>new Date(vn(v/f))),H=i.fmtDate||nu,ct=f==1?PE(J):NE(J),Z=yf(J,Mf(f==1?CE:DE,H)),tt=Ef(J,bf(UE,H)),st=[],pt=n.legend=dn({},BE,i.legend),ft=n.cursor=dn({},WE,{drag:{y:s==2}},i.cursor),B=pt.show,et=ft.show,ht=pt.markers;pt.idxs=st,ht.width=_e(ht.width),ht.dash=_e(ht.dash),ht.stroke=_e(ht.stroke),ht.fill=_e(ht.fill);let gt,vt,Gt,Qt=[],kt=[],ne,ee=!1,qt={};if(pt.live){const v=x[1]?x[1].values:null;ee=v!=null,ne=ee?v(n,1,0):{_:0};for(let E in ne)qt[E]=Zh}if(B)if(gt=bi("table",Hb,c),Gt=bi("tbody",null,gt),pt.mount(n,gt),ee){vt=bi("thead",null,gt,Gt);let v=bi("tr",null,vt);bi("th",null,v);for(var Ie in ne)bi("th",Jd,v).textContent=Ie}else ti(gt,Vb),pt.live&&ti(gt,Gb);const me={show:!0},Xe={show:!1};function Me(v,E){if(E==0&&(ee||!pt.live||s==2))return Vr;let P=[],D=bi("tr",Wb,Gt,Gt.childNodes[E]);ti(D,v.class),v.show||ti(D,Xs);let X=bi("th",null,D);if(ht.show){let mt=li(Xb,X);if(E>0){let yt=ht.width(n,E);yt&&(mt.style.border=yt+"px "+ht.dash(n,E)+" "+ht.stroke(n,E)),mt.style.background=ht.fill(n,E)}}let j=li(Jd,X);v.label instanceof HTMLElement?j.appendChild(v.label):j.textContent=v.label,E>0&&(ht.show||(j.style.color=v.width>0?ht.stroke(n,E):ht.fill(n,E)),de("click",X,mt=>{if(ft._lock)return;Zt(mt);let yt=x.indexOf(v);if((mt.ctrlKey||mt.metaKey)!=pt.isolate){let Nt=x.some((It,Ft)=>Ft>0&&Ft!=yt&&It.show);x.forEach((It,Ft)=>{Ft>0&&Li(Ft,Nt?Ft==yt?me:Xe:me,!0,hn.setSeries)})}else Li(yt,{show:!v.show},!0,hn.setSeries)},!1),Jt&&de(ef,X,mt=>{ft._lock||(Zt(mt),Li(x.indexOf(v),hr,!0,hn.setSeries))},!1));for(var lt in ne){let mt=bi("td",$b,D);mt.textContent="--",P.push(mt)}return[D,P]}const rn=new Map;function de(v,E,P,D=!0){const X=rn.get(E)||{},j=ft.bind[v](n,E,P,D);j&&(Ys(v,E,X[v]=j),rn.set(E,X))}function pn(v,E,P){const D=rn.get(E)||{};for(let X in D)(v==null||X==v)&&(xh(X,E,D[X]),delete D[X]);v==null&&rn.delete(E)}let qe=0,an=0,F=0,Ct=0,Yt=0,se=0,Et=Yt,Ue=se,Ht=F,$t=Ct,C=0,y=0,Y=0,dt=0;n.bbox={};let ot=!1,St=!1,Mt=!1,nt=!1,rt=!1,_t=!1;function U(v,E,P){(P||v!=n.width||E!=n.height)&&at(v,E),oe(!1),Mt=!0,St=!0,Ln()}function at(v,E){n.width=qe=F=v,n.height=an=Ct=E,Yt=se=0,bt(),Vt();let P=n.bbox;C=P.left=Vs(Yt*we,.5),y=P.top=Vs(se*we,.5),Y=P.width=Vs(F*we,.5),dt=P.height=Vs(Ct*we,.5)}const it=3;function wt(){let v=!1,E=0;for(;!v;){E++;let P=sr(E),D=Pi(E);v=E==it||P&&D,v||(at(n.width,n.height),St=!0)}}function xt({width:v,height:E}){U(v,E)}n.setSize=xt;function bt(){let v=!1,E=!1,P=!1,D=!1;A.forEach((X,j)=>{if(X.show&&X._show){let{side:lt,_size:mt}=X,yt=lt%2,Nt=X.label!=null?X.labelSize:0,It=mt+Nt;It>0&&(yt?(F-=It,lt==3?(Yt+=It,D=!0):P=!0):(Ct-=It,lt==0?(se+=It,v=!0):E=!0))}}),Ri[0]=v,Ri[1]=P,Ri[2]=E,Ri[3]=D,F-=gi[1]+gi[3],Yt+=gi[3],Ct-=gi[2]+gi[0],se+=gi[0]}function Vt(){let v=Yt+F,E=se+Ct,P=Yt,D=se;function X(j,lt){switch(j){case 1:return v+=lt,v-lt;case 2:return E+=lt,E-lt;case 3:return P-=lt,P+lt;case 0:return D-=lt,D+lt}}A.forEach((j,lt)=>{if(j.show&&j._show){let mt=j.side;j._pos=X(mt,j._size),j.label!=null&&(j._lpos=X(mt,j.labelSize))}})}if(ft.dataIdx==null){let v=ft.hover,E=v.skip=new Set(v.skip??[]);E.add(void 0);let P=v.prox=_e(v.prox),D=v.bias??=0;ft.dataIdx=(X,j,lt,mt)=>{if(j==0)return lt;let yt=lt,Nt=P(X,j,lt,mt)??Fe,It=Nt>=0&&Nt<Fe,Ft=L.ori==0?F:Ct,ie=ft.left,Ee=t[0],ye=t[j];if(E.has(ye[lt])){yt=null;let fe=null,Kt=null,Wt;if(D==0||D==-1)for(Wt=lt;fe==null&&Wt-- >0;)E.has(ye[Wt])||(fe=Wt);if(D==0||D==1)for(Wt=lt;Kt==null&&Wt++<ye.length;)E.has(ye[Wt])||(Kt=Wt);if(fe!=null||Kt!=null)if(It){let Ge=fe==null?-1/0:$(Ee[fe],L,Ft,0),Je=Kt==null?1/0:$(Ee[Kt],L,Ft,0),An=ie-Ge,Ne=Je-ie;An<=Ne?An<=Nt&&(yt=fe):Ne<=Nt&&(yt=Kt)}else yt=Kt==null?fe:fe==null?Kt:lt-fe<=Kt-lt?fe:Kt}else It&&xn(ie-$(Ee[lt],L,Ft,0))>Nt&&(yt=null);return yt}}const Zt=v=>{ft.event=v};ft.idxs=st,ft._lock=!1;let ut=ft.points;ut.show=_e(ut.show),ut.size=_e(ut.size),ut.stroke=_e(ut.stroke),ut.width=_e(ut.width),ut.fill=_e(ut.fill);const Ot=n.focus=dn({},i.focus||{alpha:.3},ft.focus),Jt=Ot.prox>=0,Rt=Jt&&ut.one;let ae=[],ze=[],Fn=[];function Zr(v,E){let P=ut.show(n,E);if(P instanceof HTMLElement)return ti(P,kb),ti(P,v.class),Bi(P,-10,-10,F,Ct),_.insertBefore(P,ae[E]),P}function er(v,E){if(s==1||E>0){let P=s==1&&S[v.scale].time,D=v.value;v.value=P?_f(D)?Ef(J,bf(D,H)):D||tt:D||tw,v.label=v.label||(P?$E:XE)}if(Rt||E>0){v.width=v.width==null?1:v.width,v.paths=v.paths||pw||sE,v.fillTo=_e(v.fillTo||rw),v.pxAlign=+be(v.pxAlign,M),v.pxRound=Nf(v.pxAlign),v.stroke=_e(v.stroke||null),v.fill=_e(v.fill||null),v._stroke=v._fill=v._paths=v._focus=null;let P=ew(Vn(1,v.width),1),D=v.points=dn({},{size:P,width:Vn(1,P*.2),stroke:v.stroke,space:P*2,paths:mw,_stroke:null,_fill:null},v.points);D.show=_e(D.show),D.filter=_e(D.filter),D.fill=_e(D.fill),D.stroke=_e(D.stroke),D.paths=_e(D.paths),D.pxAlign=v.pxAlign}if(B){let P=Me(v,E);Qt.splice(E,0,P[0]),kt.splice(E,0,P[1]),pt.values.push(null)}if(et){st.splice(E,0,null);let P=null;Rt?E==0&&(P=Zr(v,E)):E>0&&(P=Zr(v,E)),ae.splice(E,0,P),ze.splice(E,0,0),Fn.splice(E,0,0)}Tn("addSeries",E)}function ml(v,E){E=E??x.length,v=s==1?wh(v,E,Tf,Lf):wh(v,E,{},Pf),x.splice(E,0,v),er(x[E],E)}n.addSeries=ml;function Wa(v){if(x.splice(v,1),B){pt.values.splice(v,1),kt.splice(v,1);let E=Qt.splice(v,1)[0];pn(null,E.firstChild),E.remove()}et&&(st.splice(v,1),ae.splice(v,1)[0].remove(),ze.splice(v,1),Fn.splice(v,1)),Tn("delSeries",v)}n.delSeries=Wa;const Ri=[!1,!1,!1,!1];function Zi(v,E){if(v._show=v.show,v.show){let P=v.side%2,D=S[v.scale];D==null&&(v.scale=P?x[1].scale:b,D=S[v.scale]);let X=D.time;v.size=_e(v.size),v.space=_e(v.space),v.rotate=_e(v.rotate),bs(v.incrs)&&v.incrs.forEach(lt=>{!Ns.has(lt)&&Ns.set(lt,pm(lt))}),v.incrs=_e(v.incrs||(D.distr==2?TE:X?f==1?RE:LE:Ws)),v.splits=_e(v.splits||(X&&D.distr==1?ct:D.distr==3?Mh:D.distr==4?KE:qE)),v.stroke=_e(v.stroke),v.grid.stroke=_e(v.grid.stroke),v.ticks.stroke=_e(v.ticks.stroke),v.border.stroke=_e(v.border.stroke);let j=v.values;v.values=bs(j)&&!bs(j[0])?_e(j):X?bs(j)?yf(J,Mf(j,H)):_f(j)?IE(J,j):j||Z:j||YE,v.filter=_e(v.filter||(D.distr>=3&&D.log==10?jE:D.distr==3&&D.log==2?QE:dm)),v.font=Of(v.font),v.labelFont=Of(v.labelFont),v._size=v.size(n,null,E,0),v._space=v._rotate=v._incrs=v._found=v._splits=v._values=null,v._size>0&&(Ri[E]=!0,v._el=li(Fb,d))}}function Ji(v,E,P,D){let[X,j,lt,mt]=P,yt=E%2,Nt=0;return yt==0&&(mt||j)&&(Nt=E==0&&!X||E==2&&!lt?vn(wf.size/3):0),yt==1&&(X||lt)&&(Nt=E==1&&!j||E==3&&!mt?vn(Rf.size/2):0),Nt}const Jr=n.padding=(i.padding||[Ji,Ji,Ji,Ji]).map(v=>_e(be(v,Ji))),gi=n._padding=Jr.map((v,E)=>v(n,E,Ri,0));let Ke,tn=null,en=null;const Ci=s==1?x[0].idxs:null;let qn=null,us=!1;function jr(v,E){if(t=v??[],n.data=n._data=t,s==2){Ke=0;for(let P=1;P<x.length;P++)Ke+=t[P][0].length}else{t.length==0&&(n.data=n._data=t=[[]]),qn=t[0],Ke=qn.length;let P=t;if(V==2){P=t.slice();let D=P[0]=Array(Ke);for(let X=0;X<Ke;X++)D[X]=X}n._data=t=P}if(oe(!0),Tn("setData"),V==2&&(Mt=!0),E!==!1){let P=L;P.auto(n,us)?Qr():ps(b,P.min,P.max),nt=nt||ft.left>=0,_t=!0,Ln()}}n.setData=jr;function Qr(){us=!0;let v,E;s==1&&(Ke>0?(tn=Ci[0]=0,en=Ci[1]=Ke-1,v=t[0][tn],E=t[0][en],V==2?(v=tn,E=en):v==E&&(V==3?[v,E]=ol(v,v,L.log,!1):V==4?[v,E]=jh(v,v,L.log,!1):L.time?E=v+vn(86400/f):[v,E]=jo(v,E,Qh,!0))):(tn=Ci[0]=v=null,en=Ci[1]=E=null)),ps(b,v,E)}let nr,ds,ir,T,G,Q,q,K,Tt,Pt;function At(v,E,P,D,X,j){v??=Qd,P??=eu,D??="butt",X??=Qd,j??="round",v!=nr&&(u.strokeStyle=nr=v),X!=ds&&(u.fillStyle=ds=X),E!=ir&&(u.lineWidth=ir=E),j!=G&&(u.lineJoin=G=j),D!=Q&&(u.lineCap=Q=D),P!=T&&u.setLineDash(T=P)}function Lt(v,E,P,D){E!=ds&&(u.fillStyle=ds=E),v!=q&&(u.font=q=v),P!=K&&(u.textAlign=K=P),D!=Tt&&(u.textBaseline=Tt=D)}function zt(v,E,P,D,X=0){if(D.length>0&&v.auto(n,us)&&(E==null||E.min==null)){let j=be(tn,0),lt=be(en,D.length-1),mt=P.min==null?jb(D,j,lt,X,v.distr==3):[P.min,P.max];v.min=Ti(v.min,P.min=mt[0]),v.max=Vn(v.max,P.max=mt[1])}}const te={min:null,max:null};function he(){for(let D in S){let X=S[D];W[D]==null&&(X.min==null||W[b]!=null&&X.auto(n,us))&&(W[D]=te)}for(let D in S){let X=S[D];W[D]==null&&X.from!=null&&W[X.from]!=null&&(W[D]=te)}W[b]!=null&&oe(!0);let v={};for(let D in W){let X=W[D];if(X!=null){let j=v[D]=Wr(S[D],oE);if(X.min!=null)dn(j,X);else if(D!=b||s==2)if(Ke==0&&j.from==null){let lt=j.range(n,null,null,D);j.min=lt[0],j.max=lt[1]}else j.min=Fe,j.max=-Fe}}if(Ke>0){x.forEach((D,X)=>{if(s==1){let j=D.scale,lt=W[j];if(lt==null)return;let mt=v[j];if(X==0){let yt=mt.range(n,mt.min,mt.max,j);mt.min=yt[0],mt.max=yt[1],tn=Ei(mt.min,t[0]),en=Ei(mt.max,t[0]),en-tn>1&&(t[0][tn]<mt.min&&tn++,t[0][en]>mt.max&&en--),D.min=qn[tn],D.max=qn[en]}else D.show&&D.auto&&zt(mt,lt,D,t[X],D.sorted);D.idxs[0]=tn,D.idxs[1]=en}else if(X>0&&D.show&&D.auto){let[j,lt]=D.facets,mt=j.scale,yt=lt.scale,[Nt,It]=t[X],Ft=v[mt],ie=v[yt];Ft!=null&&zt(Ft,W[mt],j,Nt,j.sorted),ie!=null&&zt(ie,W[yt],lt,It,lt.sorted),D.min=lt.min,D.max=lt.max}});for(let D in v){let X=v[D],j=W[D];if(X.from==null&&(j==null||j.min==null)){let lt=X.range(n,X.min==Fe?null:X.min,X.max==-Fe?null:X.max,D);X.min=lt[0],X.max=lt[1]}}}for(let D in v){let X=v[D];if(X.from!=null){let j=v[X.from];if(j.min==null)X.min=X.max=null;else{let lt=X.range(n,j.min,j.max,D);X.min=lt[0],X.max=lt[1]}}}let E={},P=!1;for(let D in v){let X=v[D],j=S[D];if(j.min!=X.min||j.max!=X.max){j.min=X.min,j.max=X.max;let lt=j.distr;j._min=lt==3?cs(j.min):lt==4?mc(j.min,j.asinh):lt==100?j.fwd(j.min):j.min,j._max=lt==3?cs(j.max):lt==4?mc(j.max,j.asinh):lt==100?j.fwd(j.max):j.max,E[D]=P=!0}}if(P){x.forEach((D,X)=>{s==2?X>0&&E.y&&(D._paths=null):E[D.scale]&&(D._paths=null)});for(let D in E)Mt=!0,Tn("setScale",D);et&&ft.left>=0&&(nt=_t=!0)}for(let D in W)W[D]=null}function Bt(v){let E=Sh(tn-1,0,Ke-1),P=Sh(en+1,0,Ke-1);for(;v[E]==null&&E>0;)E--;for(;v[P]==null&&P<Ke-1;)P++;return[E,P]}function ue(){if(Ke>0){let v=x.some(E=>E._focus)&&Pt!=Ot.alpha;v&&(u.globalAlpha=Pt=Ot.alpha),x.forEach((E,P)=>{if(P>0&&E.show&&($e(P,!1),$e(P,!0),E._paths==null)){let D=Pt;Pt!=E.alpha&&(u.globalAlpha=Pt=E.alpha);let X=s==2?[0,t[P][0].length-1]:Bt(t[P]);E._paths=E.paths(n,P,X[0],X[1]),Pt!=D&&(u.globalAlpha=Pt=D)}}),x.forEach((E,P)=>{if(P>0&&E.show){let D=Pt;Pt!=E.alpha&&(u.globalAlpha=Pt=E.alpha),E._paths!=null&&Re(P,!1);{let X=E._paths!=null?E._paths.gaps:null,j=E.points.show(n,P,tn,en,X),lt=E.points.filter(n,P,j,X);(j||lt)&&(E.points._paths=E.points.paths(n,P,tn,en,lt),Re(P,!0))}Pt!=D&&(u.globalAlpha=Pt=D),Tn("drawSeries",P)}}),v&&(u.globalAlpha=Pt=1)}}function $e(v,E){let P=E?x[v].points:x[v];P._stroke=P.stroke(n,v),P._fill=P.fill(n,v)}function Re(v,E){let P=E?x[v].points:x[v],{stroke:D,fill:X,clip:j,flags:lt,_stroke:mt=P._stroke,_fill:yt=P._fill,_width:Nt=P.width}=P._paths;Nt=Oe(Nt*we,3);let It=null,Ft=Nt%2/2;E&&yt==null&&(yt=Nt>0?"#fff":mt);let ie=P.pxAlign==1&&Ft>0;if(ie&&u.translate(Ft,Ft),!E){let Ee=C-Nt/2,ye=y-Nt/2,fe=Y+Nt,Kt=dt+Nt;It=new Path2D,It.rect(Ee,ye,fe,Kt)}E?Ut(mt,Nt,P.dash,P.cap,yt,D,X,lt,j):Ce(v,mt,Nt,P.dash,P.cap,yt,D,X,lt,It,j),ie&&u.translate(-Ft,-Ft)}function Ce(v,E,P,D,X,j,lt,mt,yt,Nt,It){let Ft=!1;yt!=0&&R.forEach((ie,Ee)=>{if(ie.series[0]==v){let ye=x[ie.series[1]],fe=t[ie.series[1]],Kt=(ye._paths||wa).band;bs(Kt)&&(Kt=ie.dir==1?Kt[0]:Kt[1]);let Wt,Ge=null;ye.show&&Kt&&tE(fe,tn,en)?(Ge=ie.fill(n,Ee)||j,Wt=ye._paths.clip):Kt=null,Ut(E,P,D,X,Ge,lt,mt,yt,Nt,It,Wt,Kt),Ft=!0}}),Ft||Ut(E,P,D,X,j,lt,mt,yt,Nt,It)}const mn=Xr|bh;function Ut(v,E,P,D,X,j,lt,mt,yt,Nt,It,Ft){At(v,E,P,D,X),(yt||Nt||Ft)&&(u.save(),yt&&u.clip(yt),Nt&&u.clip(Nt)),Ft?(mt&mn)==mn?(u.clip(Ft),It&&u.clip(It),ge(X,lt),on(v,j,E)):mt&bh?(ge(X,lt),u.clip(Ft),on(v,j,E)):mt&Xr&&(u.save(),u.clip(Ft),It&&u.clip(It),ge(X,lt),u.restore(),on(v,j,E)):(ge(X,lt),on(v,j,E)),(yt||Nt||Ft)&&u.restore()}function on(v,E,P){P>0&&(E instanceof Map?E.forEach((D,X)=>{u.strokeStyle=nr=X,u.stroke(D)}):E!=null&&v&&u.stroke(E))}function ge(v,E){E instanceof Map?E.forEach((P,D)=>{u.fillStyle=ds=D,u.fill(P)}):E!=null&&v&&u.fill(E)}function ji(v,E,P,D){let X=A[v],j;if(D<=0)j=[0,0];else{let lt=X._space=X.space(n,v,E,P,D),mt=X._incrs=X.incrs(n,v,E,P,D,lt);j=Mw(E,P,mt,D,lt)}return X._found=j}function ln(v,E,P,D,X,j,lt,mt,yt,Nt){let It=lt%2/2;M==1&&u.translate(It,It),At(mt,lt,yt,Nt,mt),u.beginPath();let Ft,ie,Ee,ye,fe=X+(D==0||D==3?-j:j);P==0?(ie=X,ye=fe):(Ft=X,Ee=fe);for(let Kt=0;Kt<v.length;Kt++)E[Kt]!=null&&(P==0?Ft=Ee=v[Kt]:ie=ye=v[Kt],u.moveTo(Ft,ie),u.lineTo(Ee,ye));u.stroke(),M==1&&u.translate(-It,-It)}function sr(v){let E=!0;return A.forEach((P,D)=>{if(!P.show)return;let X=S[P.scale];if(X.min==null){P._show&&(E=!1,P._show=!1,oe(!1));return}else P._show||(E=!1,P._show=!0,oe(!1));let j=P.side,lt=j%2,{min:mt,max:yt}=X,[Nt,It]=ji(D,mt,yt,lt==0?F:Ct);if(It==0)return;let Ft=X.distr==2,ie=P._splits=P.splits(n,D,mt,yt,Nt,It,Ft),Ee=X.distr==2?ie.map(Wt=>qn[Wt]):ie,ye=X.distr==2?qn[ie[1]]-qn[ie[0]]:Nt,fe=P._values=P.values(n,P.filter(n,Ee,D,It,ye),D,It,ye);P._rotate=j==2?P.rotate(n,fe,D,It):0;let Kt=P._size;P._size=hi(P.size(n,fe,D,v)),Kt!=null&&P._size!=Kt&&(E=!1)}),E}function Pi(v){let E=!0;return Jr.forEach((P,D)=>{let X=P(n,D,Ri,v);X!=gi[D]&&(E=!1),gi[D]=X}),E}function Qi(){for(let v=0;v<A.length;v++){let E=A[v];if(!E.show||!E._show)continue;let P=E.side,D=P%2,X,j,lt=E.stroke(n,v),mt=P==0||P==3?-1:1,[yt,Nt]=E._found;if(E.label!=null){let zn=E.labelGap*mt,Jn=vn((E._lpos+zn)*we);Lt(E.labelFont[0],lt,"center",P==2?fa:jd),u.save(),D==1?(X=j=0,u.translate(Jn,vn(y+dt/2)),u.rotate((P==3?-ko:ko)/2)):(X=vn(C+Y/2),j=Jn);let Os=hm(E.label)?E.label(n,v,yt,Nt):E.label;u.fillText(Os,X,j),u.restore()}if(Nt==0)continue;let It=S[E.scale],Ft=D==0?Y:dt,ie=D==0?C:y,Ee=E._splits,ye=It.distr==2?Ee.map(zn=>qn[zn]):Ee,fe=It.distr==2?qn[Ee[1]]-qn[Ee[0]]:yt,Kt=E.ticks,Wt=E.border,Ge=Kt.show?Kt.size:0,Je=vn(Ge*we),An=vn((E.alignTo==2?E._size-Ge-E.gap:E.gap)*we),Ne=E._rotate*-ko/180,je=p(E._pos*we),Kn=(Je+An)*mt,Bn=je+Kn;j=D==0?Bn:0,X=D==1?Bn:0;let si=E.font[0],_i=E.align==1?Rr:E.align==2?dc:Ne>0?Rr:Ne<0?dc:D==0?"center":P==3?dc:Rr,Ni=Ne||D==1?"middle":P==2?fa:jd;Lt(si,lt,_i,Ni);let Zn=E.font[1]*E.lineGap,ri=Ee.map(zn=>p(o(zn,It,Ft,ie))),vi=E._values;for(let zn=0;zn<vi.length;zn++){let Jn=vi[zn];if(Jn!=null){D==0?X=ri[zn]:j=ri[zn],Jn=""+Jn;let Os=Jn.indexOf(`
`)==-1?[Jn]:Jn.split(/\n/gm);for(let kn=0;kn<Os.length;kn++){let Cu=Os[kn];Ne?(u.save(),u.translate(X,j+kn*Zn),u.rotate(Ne),u.fillText(Cu,0,0),u.restore()):u.fillText(Cu,X,j+kn*Zn)}}}Kt.show&&ln(ri,Kt.filter(n,ye,v,Nt,fe),D,P,je,Je,Oe(Kt.width*we,3),Kt.stroke(n,v),Kt.dash,Kt.cap);let Ii=E.grid;Ii.show&&ln(ri,Ii.filter(n,ye,v,Nt,fe),D,D==0?2:1,D==0?y:C,D==0?dt:Y,Oe(Ii.width*we,3),Ii.stroke(n,v),Ii.dash,Ii.cap),Wt.show&&ln([je],[1],D==0?1:0,D==0?1:2,D==1?y:C,D==1?dt:Y,Oe(Wt.width*we,3),Wt.stroke(n,v),Wt.dash,Wt.cap)}Tn("drawAxes")}function oe(v){x.forEach((E,P)=>{P>0&&(E._paths=null,v&&(s==1?(E.min=null,E.max=null):E.facets.forEach(D=>{D.min=null,D.max=null})))})}let Ze=!1,On=!1,Pe=[];function cn(){On=!1;for(let v=0;v<Pe.length;v++)Tn(...Pe[v]);Pe.length=0}function Ln(){Ze||(pE(uu),Ze=!0)}function Xa(v,E=!1){Ze=!0,On=E,v(n),uu(),E&&Pe.length>0&&queueMicrotask(cn)}n.batch=Xa;function uu(){if(ot&&(he(),ot=!1),Mt&&(wt(),Mt=!1),St){if(Ve(m,Rr,Yt),Ve(m,fa,se),Ve(m,va,F),Ve(m,xa,Ct),Ve(_,Rr,Yt),Ve(_,fa,se),Ve(_,va,F),Ve(_,xa,Ct),Ve(d,va,qe),Ve(d,xa,an),h.width=vn(qe*we),h.height=vn(an*we),A.forEach(({_el:v,_show:E,_size:P,_pos:D,side:X})=>{if(v!=null)if(E){let j=X===3||X===0?P:0,lt=X%2==1;Ve(v,lt?"left":"top",D-j),Ve(v,lt?"width":"height",P),Ve(v,lt?"top":"left",lt?se:Yt),Ve(v,lt?"height":"width",lt?Ct:F),vh(v,Xs)}else ti(v,Xs)}),nr=ds=ir=G=Q=q=K=Tt=T=null,Pt=1,na(!0),Yt!=Et||se!=Ue||F!=Ht||Ct!=$t){oe(!1);let v=F/Ht,E=Ct/$t;if(et&&!nt&&ft.left>=0){ft.left*=v,ft.top*=E,rr&&Bi(rr,vn(ft.left),0,F,Ct),ar&&Bi(ar,0,vn(ft.top),F,Ct);for(let P=0;P<ae.length;P++){let D=ae[P];D!=null&&(ze[P]*=v,Fn[P]*=E,Bi(D,hi(ze[P]),hi(Fn[P]),F,Ct))}}if(He.show&&!rt&&He.left>=0&&He.width>0){He.left*=v,He.width*=v,He.top*=E,He.height*=E;for(let P in Ml)Ve(cr,P,He[P])}Et=Yt,Ue=se,Ht=F,$t=Ct}Tn("setSize"),St=!1}qe>0&&an>0&&(u.clearRect(0,0,h.width,h.height),Tn("drawClear"),w.forEach(v=>v()),Tn("draw")),He.show&&rt&&($a(He),rt=!1),et&&nt&&(Fs(null,!0,!1),nt=!1),pt.show&&pt.live&&_t&&(xl(),_t=!1),l||(l=!0,n.status=1,Tn("ready")),us=!1,Ze=!1}n.redraw=(v,E)=>{Mt=E||!1,v!==!1?ps(b,L.min,L.max):Ln()};function gl(v,E){let P=S[v];if(P.from==null){if(Ke==0){let D=P.range(n,E.min,E.max,v);E.min=D[0],E.max=D[1]}if(E.min>E.max){let D=E.min;E.min=E.max,E.max=D}if(Ke>1&&E.min!=null&&E.max!=null&&E.max-E.min<1e-16)return;v==b&&P.distr==2&&Ke>0&&(E.min=Ei(E.min,t[0]),E.max=Ei(E.max,t[0]),E.min==E.max&&E.max++),W[v]=E,ot=!0,Ln()}}n.setScale=gl;let _l,vl,rr,ar,du,fu,or,lr,pu,mu,ke,We,fs=!1;const Cn=ft.drag;let En=Cn.x,wn=Cn.y;et&&(ft.x&&(_l=li(Bb,_)),ft.y&&(vl=li(zb,_)),L.ori==0?(rr=_l,ar=vl):(rr=vl,ar=_l),ke=ft.left,We=ft.top);const He=n.select=dn({show:!0,over:!0,left:0,width:0,top:0,height:0},i.select),cr=He.show?li(Ob,He.over?_:m):null;function $a(v,E){if(He.show){for(let P in v)He[P]=v[P],P in Ml&&Ve(cr,P,v[P]);E!==!1&&Tn("setSelect")}}n.setSelect=$a;function Ym(v){if(x[v].show)B&&vh(Qt[v],Xs);else if(B&&ti(Qt[v],Xs),et){let P=Rt?ae[0]:ae[v];P!=null&&Bi(P,-10,-10,F,Ct)}}function ps(v,E,P){gl(v,{min:E,max:P})}function Li(v,E,P,D){E.focus!=null&&jm(v),E.show!=null&&x.forEach((X,j)=>{j>0&&(v==j||v==null)&&(X.show=E.show,Ym(j),s==2?(ps(X.facets[0].scale,null,null),ps(X.facets[1].scale,null,null)):ps(X.scale,null,null),Ln())}),P!==!1&&Tn("setSeries",v,E),D&&ia("setSeries",n,v,E)}n.setSeries=Li;function qm(v,E){dn(R[v],E)}function Km(v,E){v.fill=_e(v.fill||null),v.dir=be(v.dir,-1),E=E??R.length,R.splice(E,0,v)}function Zm(v){v==null?R.length=0:R.splice(v,1)}n.addBand=Km,n.setBand=qm,n.delBand=Zm;function Jm(v,E){x[v].alpha=E,et&&ae[v]!=null&&(ae[v].style.opacity=E),B&&Qt[v]&&(Qt[v].style.opacity=E)}let ts,ms,Us;const hr={focus:!0};function jm(v){if(v!=Us){let E=v==null,P=Ot.alpha!=1;x.forEach((D,X)=>{if(s==1||X>0){let j=E||X==0||X==v;D._focus=E?null:j,P&&Jm(X,j?1:Ot.alpha)}}),Us=v,P&&Ln()}}B&&Jt&&de(nf,gt,v=>{ft._lock||(Zt(v),Us!=null&&Li(null,hr,!0,hn.setSeries))});function Di(v,E,P){let D=S[E];P&&(v=v/we-(D.ori==1?se:Yt));let X=F;D.ori==1&&(X=Ct,v=X-v),D.dir==-1&&(v=X-v);let j=D._min,lt=D._max,mt=v/X,yt=j+(lt-j)*mt,Nt=D.distr;return Nt==3?Gr(10,yt):Nt==4?nE(yt,D.asinh):Nt==100?D.bwd(yt):yt}function Qm(v,E){let P=Di(v,b,E);return Ei(P,t[0],tn,en)}n.valToIdx=v=>Ei(v,t[0]),n.posToIdx=Qm,n.posToVal=Di,n.valToPos=(v,E,P)=>S[E].ori==0?r(v,S[E],P?Y:F,P?C:0):a(v,S[E],P?dt:Ct,P?y:0),n.setCursor=(v,E,P)=>{ke=v.left,We=v.top,Fs(null,E,P)};function gu(v,E){Ve(cr,Rr,He.left=v),Ve(cr,va,He.width=E)}function _u(v,E){Ve(cr,fa,He.top=v),Ve(cr,xa,He.height=E)}let ta=L.ori==0?gu:_u,ea=L.ori==1?gu:_u;function tg(){if(B&&pt.live)for(let v=s==2?1:0;v<x.length;v++){if(v==0&&ee)continue;let E=pt.values[v],P=0;for(let D in E)kt[v][P++].firstChild.nodeValue=E[D]}}function xl(v,E){if(v!=null&&(v.idxs?v.idxs.forEach((P,D)=>{st[D]=P}):aE(v.idx)||st.fill(v.idx),pt.idx=st[0]),B&&pt.live){for(let P=0;P<x.length;P++)(P>0||s==1&&!ee)&&eg(P,st[P]);tg()}_t=!1,E!==!1&&Tn("setLegend")}n.setLegend=xl;function eg(v,E){let P=x[v],D=v==0&&V==2?qn:t[v],X;ee?X=P.values(n,v,E)??qt:(X=P.value(n,E==null?null:D[E],v,E),X=X==null?qt:{_:X}),pt.values[v]=X}function Fs(v,E,P){pu=ke,mu=We,[ke,We]=ft.move(n,ke,We),ft.left=ke,ft.top=We,et&&(rr&&Bi(rr,vn(ke),0,F,Ct),ar&&Bi(ar,0,vn(We),F,Ct));let D,X=tn>en;ts=Fe,ms=null;let j=L.ori==0?F:Ct,lt=L.ori==1?F:Ct;if(ke<0||Ke==0||X){D=ft.idx=null;for(let mt=0;mt<x.length;mt++){let yt=ae[mt];yt!=null&&Bi(yt,-10,-10,F,Ct)}Jt&&Li(null,hr,!0,v==null&&hn.setSeries),pt.live&&(st.fill(D),_t=!0)}else{let mt,yt,Nt;s==1&&(mt=L.ori==0?ke:We,yt=Di(mt,b),D=ft.idx=Ei(yt,t[0],tn,en),Nt=$(t[0][D],L,j,0));let It=-10,Ft=-10,ie=0,Ee=0,ye=!0,fe="",Kt="";for(let Wt=s==2?1:0;Wt<x.length;Wt++){let Ge=x[Wt],Je=st[Wt],An=Je==null?null:s==1?t[Wt][Je]:t[Wt][1][Je],Ne=ft.dataIdx(n,Wt,D,yt),je=Ne==null?null:s==1?t[Wt][Ne]:t[Wt][1][Ne];if(_t=_t||je!=An||Ne!=Je,st[Wt]=Ne,Wt>0&&Ge.show){let Kn=Ne==null?-10:Ne==D?Nt:$(s==1?t[0][Ne]:t[Wt][0][Ne],L,j,0),Bn=je==null?-10:N(je,s==1?S[Ge.scale]:S[Ge.facets[1].scale],lt,0);if(Jt&&je!=null){let si=L.ori==1?ke:We,_i=xn(Ot.dist(n,Wt,Ne,Bn,si));if(_i<ts){let Ni=Ot.bias;if(Ni!=0){let Zn=Di(si,Ge.scale),ri=je>=0?1:-1,vi=Zn>=0?1:-1;vi==ri&&(vi==1?Ni==1?je>=Zn:je<=Zn:Ni==1?je<=Zn:je>=Zn)&&(ts=_i,ms=Wt)}else ts=_i,ms=Wt}}if(_t||Rt){let si,_i;L.ori==0?(si=Kn,_i=Bn):(si=Bn,_i=Kn);let Ni,Zn,ri,vi,Ii,zn,Jn=!0,Os=ut.bbox;if(Os!=null){Jn=!1;let kn=Os(n,Wt);ri=kn.left,vi=kn.top,Ni=kn.width,Zn=kn.height}else ri=si,vi=_i,Ni=Zn=ut.size(n,Wt);if(zn=ut.fill(n,Wt),Ii=ut.stroke(n,Wt),Rt)Wt==ms&&ts<=Ot.prox&&(It=ri,Ft=vi,ie=Ni,Ee=Zn,ye=Jn,fe=zn,Kt=Ii);else{let kn=ae[Wt];kn!=null&&(ze[Wt]=ri,Fn[Wt]=vi,hf(kn,Ni,Zn,Jn),lf(kn,zn,Ii),Bi(kn,hi(ri),hi(vi),F,Ct))}}}}if(Rt){let Wt=Ot.prox,Ge=Us==null?ts<=Wt:ts>Wt||ms!=Us;if(_t||Ge){let Je=ae[0];Je!=null&&(ze[0]=It,Fn[0]=Ft,hf(Je,ie,Ee,ye),lf(Je,fe,Kt),Bi(Je,hi(It),hi(Ft),F,Ct))}}}if(He.show&&fs)if(v!=null){let[mt,yt]=hn.scales,[Nt,It]=hn.match,[Ft,ie]=v.cursor.sync.scales,Ee=v.cursor.drag;if(En=Ee._x,wn=Ee._y,En||wn){let{left:ye,top:fe,width:Kt,height:Wt}=v.select,Ge=v.scales[Ft].ori,Je=v.posToVal,An,Ne,je,Kn,Bn,si=mt!=null&&Nt(mt,Ft),_i=yt!=null&&It(yt,ie);si&&En?(Ge==0?(An=ye,Ne=Kt):(An=fe,Ne=Wt),je=S[mt],Kn=$(Je(An,Ft),je,j,0),Bn=$(Je(An+Ne,Ft),je,j,0),ta(Ti(Kn,Bn),xn(Bn-Kn))):ta(0,j),_i&&wn?(Ge==1?(An=ye,Ne=Kt):(An=fe,Ne=Wt),je=S[yt],Kn=N(Je(An,ie),je,lt,0),Bn=N(Je(An+Ne,ie),je,lt,0),ea(Ti(Kn,Bn),xn(Bn-Kn))):ea(0,lt)}else yl()}else{let mt=xn(pu-du),yt=xn(mu-fu);if(L.ori==1){let ie=mt;mt=yt,yt=ie}En=Cn.x&&mt>=Cn.dist,wn=Cn.y&&yt>=Cn.dist;let Nt=Cn.uni;Nt!=null?En&&wn&&(En=mt>=Nt,wn=yt>=Nt,!En&&!wn&&(yt>mt?wn=!0:En=!0)):Cn.x&&Cn.y&&(En||wn)&&(En=wn=!0);let It,Ft;En&&(L.ori==0?(It=or,Ft=ke):(It=lr,Ft=We),ta(Ti(It,Ft),xn(Ft-It)),wn||ea(0,lt)),wn&&(L.ori==1?(It=or,Ft=ke):(It=lr,Ft=We),ea(Ti(It,Ft),xn(Ft-It)),En||ta(0,j)),!En&&!wn&&(ta(0,0),ea(0,0))}if(Cn._x=En,Cn._y=wn,v==null){if(P){if(Ru!=null){let[mt,yt]=hn.scales;hn.values[0]=mt!=null?Di(L.ori==0?ke:We,mt):null,hn.values[1]=yt!=null?Di(L.ori==1?ke:We,yt):null}ia(fc,n,ke,We,F,Ct,D)}if(Jt){let mt=P&&hn.setSeries,yt=Ot.prox;Us==null?ts<=yt&&Li(ms,hr,!0,mt):ts>yt?Li(null,hr,!0,mt):ms!=Us&&Li(ms,hr,!0,mt)}}_t&&(pt.idx=D,xl()),E!==!1&&Tn("setCursor")}let gs=null;Object.defineProperty(n,"rect",{get(){return gs==null&&na(!1),gs}});function na(v=!1){v?gs=null:(gs=_.getBoundingClientRect(),Tn("syncRect",gs))}function vu(v,E,P,D,X,j,lt){ft._lock||fs&&v!=null&&v.movementX==0&&v.movementY==0||(Sl(v,E,P,D,X,j,lt,!1,v!=null),v!=null?Fs(null,!0,!0):Fs(E,!0,!1))}function Sl(v,E,P,D,X,j,lt,mt,yt){if(gs==null&&na(!1),Zt(v),v!=null)P=v.clientX-gs.left,D=v.clientY-gs.top;else{if(P<0||D<0){ke=-10,We=-10;return}let[Nt,It]=hn.scales,Ft=E.cursor.sync,[ie,Ee]=Ft.values,[ye,fe]=Ft.scales,[Kt,Wt]=hn.match,Ge=E.axes[0].side%2==1,Je=L.ori==0?F:Ct,An=L.ori==1?F:Ct,Ne=Ge?j:X,je=Ge?X:j,Kn=Ge?D:P,Bn=Ge?P:D;if(ye!=null?P=Kt(Nt,ye)?o(ie,S[Nt],Je,0):-10:P=Je*(Kn/Ne),fe!=null?D=Wt(It,fe)?o(Ee,S[It],An,0):-10:D=An*(Bn/je),L.ori==1){let si=P;P=D,D=si}}yt&&(E==null||E.cursor.event.type==fc)&&((P<=1||P>=F-1)&&(P=Vs(P,F)),(D<=1||D>=Ct-1)&&(D=Vs(D,Ct))),mt?(du=P,fu=D,[or,lr]=ft.move(n,P,D)):(ke=P,We=D)}const Ml={width:0,height:0,left:0,top:0};function yl(){$a(Ml,!1)}let xu,Su,Mu,yu;function bu(v,E,P,D,X,j,lt){fs=!0,En=wn=Cn._x=Cn._y=!1,Sl(v,E,P,D,X,j,lt,!0,!1),v!=null&&(de(pc,gh,Eu,!1),ia(tf,n,or,lr,F,Ct,null));let{left:mt,top:yt,width:Nt,height:It}=He;xu=mt,Su=yt,Mu=Nt,yu=It}function Eu(v,E,P,D,X,j,lt){fs=Cn._x=Cn._y=!1,Sl(v,E,P,D,X,j,lt,!1,!0);let{left:mt,top:yt,width:Nt,height:It}=He,Ft=Nt>0||It>0,ie=xu!=mt||Su!=yt||Mu!=Nt||yu!=It;if(Ft&&ie&&$a(He),Cn.setScale&&Ft&&ie){let Ee=mt,ye=Nt,fe=yt,Kt=It;if(L.ori==1&&(Ee=yt,ye=It,fe=mt,Kt=Nt),En&&ps(b,Di(Ee,b),Di(Ee+ye,b)),wn)for(let Wt in S){let Ge=S[Wt];Wt!=b&&Ge.from==null&&Ge.min!=Fe&&ps(Wt,Di(fe+Kt,Wt),Di(fe,Wt))}yl()}else ft.lock&&(ft._lock=!ft._lock,Fs(E,!0,v!=null));v!=null&&(pn(pc,gh),ia(pc,n,ke,We,F,Ct,null))}function ng(v,E,P,D,X,j,lt){if(ft._lock)return;Zt(v);let mt=fs;if(fs){let yt=!0,Nt=!0,It=10,Ft,ie;L.ori==0?(Ft=En,ie=wn):(Ft=wn,ie=En),Ft&&ie&&(yt=ke<=It||ke>=F-It,Nt=We<=It||We>=Ct-It),Ft&&yt&&(ke=ke<or?0:F),ie&&Nt&&(We=We<lr?0:Ct),Fs(null,!0,!0),fs=!1}ke=-10,We=-10,st.fill(null),Fs(null,!0,!0),mt&&(fs=mt)}function wu(v,E,P,D,X,j,lt){ft._lock||(Zt(v),Qr(),yl(),v!=null&&ia(sf,n,ke,We,F,Ct,null))}function Tu(){A.forEach(yw),U(n.width,n.height,!0)}Ys(Jo,Or,Tu);const ur={};ur.mousedown=bu,ur.mousemove=vu,ur.mouseup=Eu,ur.dblclick=wu,ur.setSeries=(v,E,P,D)=>{let X=hn.match[2];P=X(n,E,P),P!=-1&&Li(P,D,!0,!1)},et&&(de(tf,_,bu),de(fc,_,vu),de(ef,_,v=>{Zt(v),na(!1)}),de(nf,_,ng),de(sf,_,wu),Eh.add(n),n.syncRect=na);const Ya=n.hooks=i.hooks||{};function Tn(v,E,P){On?Pe.push([v,E,P]):v in Ya&&Ya[v].forEach(D=>{D.call(null,n,E,P)})}(i.plugins||[]).forEach(v=>{for(let E in v.hooks)Ya[E]=(Ya[E]||[]).concat(v.hooks[E])});const Au=(v,E,P)=>P,hn=dn({key:null,setSeries:!1,filters:{pub:mf,sub:mf},scales:[b,x[1]?x[1].scale:null],match:[gf,gf,Au],values:[null,null]},ft.sync);hn.match.length==2&&hn.match.push(Au),ft.sync=hn;const Ru=hn.key,bl=Im(Ru);function ia(v,E,P,D,X,j,lt){hn.filters.pub(v,E,P,D,X,j,lt)&&bl.pub(v,E,P,D,X,j,lt)}bl.sub(n);function ig(v,E,P,D,X,j,lt){hn.filters.sub(v,E,P,D,X,j,lt)&&ur[v](null,E,P,D,X,j,lt)}n.pub=ig;function sg(){bl.unsub(n),Eh.delete(n),rn.clear(),xh(Jo,Or,Tu),c.remove(),gt?.remove(),Tn("destroy")}n.destroy=sg;function El(){Tn("init",i,t),jr(t||i.data,!1),W[b]?gl(b,W[b]):Qr(),rt=He.show&&(He.width>0||He.height>0),nt=_t=!0,U(i.width,i.height)}return x.forEach(er),A.forEach(Zi),e?e instanceof HTMLElement?(e.appendChild(c),El()):e(n,El):El(),n}Un.assign=dn;Un.fmtNum=tu;Un.rangeNum=jo;Un.rangeLog=ol;Un.rangeAsinh=jh;Un.orient=tr;Un.pxRatio=we;Un.join=fE;Un.fmtDate=nu,Un.tzDate=EE;Un.sync=Im;{Un.addGap=aw,Un.clipGaps=hl;let i=Un.paths={points:km};i.linear=Gm,i.stepped=cw,i.bars=hw,i.spline=dw}class pl{shown=new Map;observer;constructor(){this.observer=typeof IntersectionObserver>"u"?null:new IntersectionObserver(t=>{for(const e of t)this.shown.set(e.target,e.isIntersecting)})}watch(t){this.shown.set(t,!0),this.observer?.observe(t)}visible(t){return this.shown.get(t)??!0}}const bw=1e-6,Ew=1e-12,cu=2**-52;function Th(i,t,e=.05){if(i===null||t===null||!Number.isFinite(i)||!Number.isFinite(t))return[-1,1];i>t&&([i,t]=[t,i]);const n=Math.max(bw*Math.max(Math.abs(i),Math.abs(t)),Ew),s=t-i;if(s<n){const r=i/2+t/2;return[r-n/2,r+n/2]}return[i-e*s,t+e*s]}function ww(i,t){return!Number.isFinite(i)||!(t>0)?null:Math.max(Math.abs(i)/t,cu/10)}function Tw(i,t){const e=cu/10,n=i!==null&&Number.isFinite(i)&&i>0?Math.min(i,e):e,s=t!==null&&Number.isFinite(t)&&t>0?Math.max(t,1e-12):1e-12;return[10**Math.floor(Math.log10(n)),10**Math.ceil(Math.log10(s)+1e-9)]}function Aw(i,t,e,n,s){const r=Math.max(Math.abs(n),1);return{energy:Math.max(Math.abs(i),e*r*s),j3:Math.max(Math.abs(t),e*s*Math.sqrt(r*s))}}const xc=[{title:"plot.dE",axis:"|ΔE|/E_s",key:"dE",color:"#ffb347",drift:"energy"},{title:"plot.dJ3",axis:"|ΔJ₃|/J_s",key:"dJ3",color:"#7dff8a",drift:"j3"},{title:"plot.z",axis:"z [m]",key:"z",color:"#59c3ff",events:!0},{title:"plot.tension",axis:"T [N]",key:"tension",color:"#ff5d73",events:!0}];function Rw(i){if(i===null||!Number.isFinite(i))return"";if(i===0)return"0";const t=Math.abs(i);return t>=.001&&t<1e4?String(+i.toPrecision(4)):i.toExponential(0)}class Cw{constructor(t,e=()=>{}){this.container=t;let n=0;const s={stroke:"#aab",grid:{stroke:"#2a2f3a"},ticks:{stroke:"#2a2f3a"},labelSize:16};for(const r of xc){const a=document.createElement("div");a.className="plot",a.dataset.plot=r.key,t.appendChild(a),this.els.push(a),this.visibility.watch(a),this.shown.push({h:null,n:-1,t:NaN,ev:null});const o=[()=>e(performance.now()-n)];r.events&&o.push(c=>this.markEvents(c)),r.drift&&o.push(c=>this.markFloor(c));const l={title:O(r.title),width:this.width(),height:160,scales:{x:{time:!1,range:(c,h,u)=>Th(h,u,0)},y:r.drift?{distr:3,log:10,range:(c,h,u)=>Tw(h,u)}:{range:(c,h,u)=>Th(h,u)}},legend:{show:!0,live:!1},hooks:{drawClear:[()=>{n=performance.now()}],draw:o},cursor:{show:!0,drag:{x:!1,y:!1}},series:[{label:"t [s]"},{label:r.axis,stroke:r.color,width:1.5}],axes:[{...s,label:O("plot.time")},{...s,label:r.axis,size:64,values:(c,h)=>h.map(Rw)}]};this.charts.push(new Un(l,[[],[]],a))}new ResizeObserver(()=>this.resize()).observe(t)}container;charts=[];els=[];visibility=new pl;shown=[];events=[];width(){return Math.max(200,this.container.clientWidth-8)}resize(){for(const t of this.charts)t.setSize({width:this.width(),height:160})}markFloor(t){const{ctx:e,bbox:n}=t,s=Math.round(t.valToPos(cu,"y",!0))+.5;s>=n.top&&s<=n.top+n.height&&(e.save(),e.strokeStyle="#8a93a6",e.setLineDash([5,4]),e.beginPath(),e.moveTo(n.left,s),e.lineTo(n.left+n.width,s),e.stroke(),e.fillStyle="#8a93a6",e.font=`${Math.round(11*devicePixelRatio)}px system-ui, sans-serif`,e.textAlign="left",e.textBaseline="bottom",e.fillText(O("plot.floor"),n.left+4,s-3),e.restore())}markEvents(t){const[e,n]=[t.scales.x?.min,t.scales.x?.max];if(e===void 0||n===void 0||e===null||n===null)return;const{ctx:s,bbox:r}=t;s.save(),s.lineWidth=1,s.strokeStyle="#e0e0e0";for(const a of this.events){if(a.t<e||a.t>n)continue;const o=Math.round(t.valToPos(a.t,"x",!0))+.5;s.setLineDash(a.kind==="slack"?[4,3]:[]),s.beginPath(),s.moveTo(o,r.top),s.lineTo(o,r.top+r.height),s.stroke()}s.restore()}scales(){return xc.map((t,e)=>{const n=this.charts[e]?.scales.y;return{key:t.key,distr:n?.distr??1,min:n?.min??null,max:n?.max??null}})}update(t,e=[],n={energy:1,j3:1}){this.events=e;const s=t.t.length,r=t.t[s-1]??NaN;xc.forEach((a,o)=>{const l=this.charts[o],c=this.els[o],h=this.shown[o];if(l===void 0||c===void 0||h===void 0||!this.visibility.visible(c)||h.h===t&&h.n===s&&Object.is(h.t,r)&&h.ev===e)return;Object.assign(h,{h:t,n:s,t:r,ev:e});const u=t[a.key],d=a.drift;l.setData([t.t,d?u.map(m=>ww(m,n[d])):u])})}}function qs(i,t=.1){let e=1/0,n=-1/0;for(const a of i)Number.isFinite(a)&&(a<e&&(e=a),a>n&&(n=a));if(e>n)return{lo:-1,hi:1};if(e===n)return{lo:e-Math.max(.5,Math.abs(e)*.1),hi:n+Math.max(.5,Math.abs(e)*.1)};const[s,r]=Th(e,n,t);return{lo:s,hi:r}}function Pw(i,t,e){const n=Math.max(t===null?0:t-i,.2*e);return{lo:i-.15*n,hi:i+2.2*n}}function Co(i,t=Math.abs(i)){if(i===0)return"0";const e=Math.abs(i),n=Math.min(12,Math.max(3,Math.ceil(Math.log10(e/Math.max(t,1e-300)))+2));return e>=.01&&e<1e4?String(+i.toPrecision(n)):i.toExponential(Math.max(1,n-2))}class Ta{constructor(t,e,n,s,r=150){this.xLabel=n,this.yLabel=s,this.height=r;const a=document.createElement("div");a.className="plot curve";const o=document.createElement("div");o.className="curve-title",o.textContent=e,a.appendChild(o),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("aria-label",e),a.appendChild(this.canvas),t.appendChild(a),this.ctx=this.canvas.getContext("2d")}xLabel;yLabel;height;canvas;ctx;draw(t,e,n,s,r={}){const a=this.ctx;if(a===null)return;const o=Math.min(window.devicePixelRatio||1,2),l=Math.max(100,t),c=this.height;this.canvas.width!==Math.round(l*o)&&(this.canvas.width=Math.round(l*o),this.canvas.height=Math.round(c*o),this.canvas.style.width=`${l}px`,this.canvas.style.height=`${c}px`),a.setTransform(o,0,0,o,0,0),a.clearRect(0,0,l,c);const h=56,u=c-20,d=6,m=l-8,_=x=>h+(x-n.lo)/(n.hi-n.lo)*(m-h),M=x=>u-(x-s.lo)/(s.hi-s.lo)*(u-d);a.strokeStyle="#2a2f3a",a.strokeRect(h,d,m-h,u-d),a.fillStyle="#aab",a.font="11px system-ui, sans-serif",a.fillText(Co(s.hi,s.hi-s.lo),4,d+10),a.fillText(Co(s.lo,s.hi-s.lo),4,u),a.fillText(this.yLabel,4,(d+u)/2),a.fillText(Co(n.lo,n.hi-n.lo),h,c-4);const p=Co(n.hi,n.hi-n.lo);a.fillText(p,m-a.measureText(p).width,c-4),a.fillText(this.xLabel,(h+m)/2-10,c-4),a.save(),a.beginPath(),a.rect(h,d,m-h,u-d),a.clip(),r.hLine!==void 0&&r.hLine!==null&&this.line(a,h,M(r.hLine),m,M(r.hLine),"#ffb347"),r.vLine!==void 0&&r.vLine!==null&&this.line(a,_(r.vLine),d,_(r.vLine),u,"#888");for(const x of e){a.strokeStyle=x.color,a.lineWidth=1.5,a.beginPath();let A=!1;for(let S=0;S<x.x.length;S++){const R=x.x[S],b=x.y[S];if(!Number.isFinite(R)||!Number.isFinite(b)){A=!1;continue}const g=Math.max(-1e4,Math.min(1e4,M(b)));A?a.lineTo(_(R),g):a.moveTo(_(R),g),A=!0}a.stroke()}r.dot&&(a.fillStyle="#ff8c42",a.beginPath(),a.arc(_(r.dot[0]),M(r.dot[1]),3.5,0,2*Math.PI),a.fill()),a.restore();let f=d+12;a.textAlign="right";for(const x of e)x.label&&(a.fillStyle=x.color,a.fillText(`— ${x.label}`,m-4,f),f+=13);a.textAlign="left"}line(t,e,n,s,r,a){t.strokeStyle=a,t.lineWidth=1,t.setLineDash([4,3]),t.beginPath(),t.moveTo(e,n),t.lineTo(s,r),t.stroke(),t.setLineDash([])}}function Lw(i){return Math.atan2(Math.hypot(i[0],i[1]),-i[2])}class Dw{constructor(t){this.container=t,this.phase=new Ta(t,O("portrait.phase"),"z [m]","ż [m/s]"),this.potential=new Ta(t,O("portrait.veff"),"θ [rad]","E [J]"),this.em=new Ta(t,O("portrait.em"),"J₃ [kg m²/s]","E [J]");for(const e of[this.phase,this.potential,this.em])this.visibility.watch(e.canvas);this.note=document.createElement("p"),this.note.className="note",this.note.dataset.note="portraits",t.appendChild(this.note)}container;phase;potential;em;note;visibility=new pl;setModel(t){const e=Dh(t)??"";this.note.textContent!==e&&(this.note.textContent=e)}updateEM(t,e){if(!this.visibility.visible(this.em.canvas))return;const n=Math.max(200,this.container.clientWidth-8);if(t===null){this.em.draw(n,[],{lo:-1,hi:1},{lo:-1,hi:1});return}const s=t.top.energy,r=qs([...t.boundary.j3.filter((o,l)=>(t.boundary.energy[l]??1/0)<2.6*s),e?.j3??0],.05),a={lo:t.bottom.energy-.15*s,hi:Math.max(2.6*s,(e?.energy??0)+.2*s)};this.em.draw(n,[{x:t.boundary.j3,y:t.boundary.energy,color:"#c9a0ff",label:O("portrait.emBoundary")}],r,a,{vLine:0,hLine:t.top.energy,dot:e?[e.j3,e.energy]:null})}update(t,e,n,s,r,a){const o=Math.max(200,this.container.clientWidth-8);if(this.visibility.visible(this.phase.canvas)){const c=e?[e.x[2],e.v[2]]:null,h=qs(e?[...t.z,e.x[2]]:t.z),u=qs(e?[...t.zdot,e.v[2]]:t.zdot);this.phase.draw(o,[{x:t.z,y:t.zdot,color:"#59c3ff",label:O("portrait.orbit")}],h,u,{dot:c})}if(!this.visibility.visible(this.potential.canvas))return;if(n===null||n.theta.length===0){this.potential.draw(o,[],{lo:0,hi:Math.PI},{lo:-1,hi:1});return}const l=Pw(n.minimum.v_eff,e?.energy??null,s*Math.max(Math.abs(r),1)*a);this.potential.draw(o,[{x:n.theta,y:n.v_eff,color:"#7dff8a",label:"V_eff(θ)"}],{lo:0,hi:Math.PI},l,{hLine:e?.energy??null,vLine:e?Lw(e.x):null})}}async function Ah(i,t){const e=await fetch(i,t),n=await e.json();if(!e.ok){const s=n.detail;throw new Error(typeof s=="string"?s:`${i}: HTTP ${e.status}`)}return n}function Po(i,t){return Ah(i,{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(t)})}const Lo=i=>i instanceof Error?i.message:String(i);class Nw{constructor(t,e,n){this.store=t,this.reduced=e,this.explain=n}store;reduced;explain;veff=null;em=null;veffKey="";veffAt=-1/0;veffJ3=null;emKey="";exactEpoch=-1;reducedEpoch=-1;onFrames(){const t=this.store.status,e=this.store.trajectory[0],n=this.store.latest();if(!(t===null||e===void 0||n===null)){if(this.exactEpoch!==t.epoch&&this.fetchExact(t,e),this.reducedEpoch!==t.epoch&&this.fetchReduced(t,e),!Sg(t.model)){[this.veff,this.em,this.veffKey,this.emKey]=[null,null,"",""];return}this.fetchEM(t,e),this.fetchPotential(t,n)}}fetchPotential(t,e){const n=t.params,s=`${t.epoch}:${n.length}:${n.mass}:${n.g}`,r=performance.now(),a=Math.abs(e.j3-(this.veffJ3??NaN))>.001*Math.max(Math.abs(e.j3),1e-9);s===this.veffKey&&!(a&&r-this.veffAt>1e3)||(s!==this.veffKey&&(this.veff=null),[this.veffKey,this.veffAt,this.veffJ3]=[s,r,e.j3],Po("api/effective_potential",{length:n.length,mass:n.mass,g:n.g,j3:e.j3}).then(o=>{this.veffKey===s&&(this.veff=o)},o=>this.explain(`V_eff: ${Lo(o)}`)))}fetchEM(t,e){const n=t.params,s=`${n.length}:${n.mass}:${n.g}`;s!==this.emKey&&(this.emKey=s,this.em=null,n.g!==0&&Po("api/em_map",{length:n.length,mass:n.mass,g:n.g,x:e.x,v:e.v}).then(r=>{this.emKey===s&&(this.em=r)},r=>this.explain(`energy–momentum map: ${Lo(r)}`)))}fetchReduced(t,e){if(this.reducedEpoch=t.epoch,t.model!=="ideal"){this.reduced.setNote(Dh(t.model)??O("note.reducedIdeal",{model:t.model}));return}this.reduced.setNote(null);const n=t.params;Po("api/reduced",{length:n.length,mass:n.mass,g:n.g,x:e.x,v:e.v}).then(s=>{this.store.status?.epoch===t.epoch&&this.reduced.set(s)},s=>this.reduced.setNote(`reduced view: ${Lo(s)}`))}fetchExact(t,e){if(this.exactEpoch=t.epoch,t.model!=="ideal")return;const n=t.params;Po("api/exact",{length:n.length,mass:n.mass,g:n.g,x:e.x,v:e.v}).then(s=>{this.store.status?.epoch===t.epoch&&this.store.setExact(s)},s=>{this.store.status?.epoch===t.epoch&&this.store.setExact(null,Lo(s))})}}function Iw(i,t){const e=t*t;return[i.x[2]/t,i.v[2]/t,(i.v[0]**2+i.v[1]**2+i.v[2]**2)/e]}function Uw(i){const t=Math.max(...i.surface.sigma2.map(Math.abs),1e-9),e=Math.max(...i.orbit.sigma3,i.point[2],1e-9);return{s2:t,s3top:1.6*e+1e-9}}class hu{constructor(t,e){this.container=t;const n=document.createElement("div");n.className="curve-title",n.textContent=O("data.reduced"),t.appendChild(n),this.renderer=new Qp({antialias:e.antialias,preserveDrawingBuffer:!0}),this.renderer.localClippingEnabled=!0,this.renderer.setPixelRatio(e.pixelRatio),this.renderer.domElement.className="reduced-canvas",t.appendChild(this.renderer.domElement),this.note=document.createElement("p"),this.note.className="note",t.appendChild(this.note),this.scene.background=new ce(1448482),this.camera.up.set(0,0,1),this.camera.position.set(3.2,-3.6,2.2),this.controls=new em(this.camera,this.renderer.domElement),this.point=new fn(new Rs(.05,16,12),new As({color:16747586,depthTest:!1,transparent:!0})),this.point.renderOrder=3,this.point.visible=!1,this.scene.add(this.group,this.point,new Hp(1.2)),this.resize(),new ResizeObserver(()=>this.resize()).observe(t),new IntersectionObserver(s=>{this.visible=s.some(r=>r.isIntersecting)}).observe(this.renderer.domElement),this.controls.addEventListener("change",()=>{this.dirty=!0})}container;renderer;camera=new Xn(35,1,.01,100);controls;scene=new wp;group=new Vi;point;scales=null;note;visible=!1;lastDrawn=-1/0;dirty=!0;resize(){const t=Math.max(200,this.container.clientWidth-8),e=220;this.renderer.setSize(t,e,!1),this.renderer.domElement.style.width=`${t}px`,this.renderer.domElement.style.height=`${e}px`,this.camera.aspect=t/e,this.camera.updateProjectionMatrix()}setNote(t){this.note.textContent=t??"",t!==null&&this.set(null)}set(t){for(const b of[...this.group.children]){this.group.remove(b);const g=b;g.geometry?.dispose(),g.material?.dispose()}if(this.scales=t===null?null:Uw(t),this.dirty=!0,t===null||this.scales===null)return;const{s2:e,s3top:n}=this.scales,s=(b,g,w)=>new k(b,g/e,2*w/n-1),r=[new wi(new k(0,0,-1),1)],{sigma1:a,sigma2:o,sigma3:l}=t.surface,c=[];a.forEach((b,g)=>o.forEach((w,z)=>c.push(...s(b,w,l[g]?.[z]??NaN).toArray())));const h=[],u=o.length;for(let b=0;b+1<a.length;b++)for(let g=0;g+1<u;g++){const w=b*u+g;h.push(w,w+u,w+1,w+1,w+u,w+u+1)}const d=new Be;d.setAttribute("position",new sn(c,3)),d.setIndex(h);const m={color:9417727,transparent:!0,opacity:.25,side:di,clippingPlanes:r};this.group.add(new fn(d,new As({...m,depthWrite:!1}))),this.group.add(new fn(d.clone(),new As({...m,wireframe:!0,opacity:.25})));const{h:_,gamma:M}=t.plane,p=(b,g)=>s(b,g,2*(_-M*b)),f=new Be().setFromPoints([p(-1,-e),p(1,-e),p(1,e),p(-1,e)]);f.setIndex([0,1,2,0,2,3]);const x=new As({color:16757575,transparent:!0,opacity:.22,side:di,depthWrite:!1,clippingPlanes:[...r,new wi(new k(0,0,1),1)]});this.group.add(new fn(f,x));const A=t.orbit,S=new Be().setFromPoints(A.sigma1.map((b,g)=>s(b,A.sigma2[g]??NaN,A.sigma3[g]??NaN))),R=new Ki(S,new mi({color:5882879,depthTest:!1,transparent:!0}));R.renderOrder=2,this.group.add(R),this.point.visible=!0}update(t,e){if(this.scales!==null&&t!==null){const[s,r,a]=Iw(t,e);this.point.position.set(s,r/this.scales.s2,2*a/this.scales.s3top-1)}this.point.visible=this.scales!==null&&t!==null;const n=performance.now();!this.visible||!this.dirty&&n-this.lastDrawn<hu.MIN_INTERVAL||(this.lastDrawn=n,this.dirty=!1,this.controls.update(),this.renderer.render(this.scene,this.camera))}static MIN_INTERVAL=250}class Fw{constructor(t){this.intervalMs=t}intervalMs;last=-1/0;due(t){return t-this.last<this.intervalMs?!1:(this.last=t,!0)}reset(){this.last=-1/0}}class Ow{last=null;changed(t){const e=this.last;return e!==null&&e.length===t.length&&t.every((n,s)=>Object.is(n,e[s]))?!1:(this.last=[...t],!0)}}class Bw{sums=new Map;add(t,e){const n=this.sums.get(t);n===void 0?this.sums.set(t,{ms:e,count:1}):(n.ms+=e,n.count++)}take(){const t={};for(const[e,n]of this.sums)t[e]={ms:n.ms/n.count,count:n.count};return this.sums.clear(),t}}function zw(i){const t={model:i.model,length:i.params.length,mass:i.params.mass,g:i.params.g,params:{...i.model_params},x:i.start.x,v:i.start.v,method:i.method,dt:i.dt,t0:i.t0,t_end:Math.max(i.t0+100,Math.ceil(i.t))},e=i.title??i.scenario;return e&&(t.title=`${e} (from the lab)`),t}function ys(i){return Object.is(i,-0)?"-0":String(i)}function kw(i){const t=new URLSearchParams;return i.scenario!==void 0&&t.set("s",i.scenario),i.model!==void 0&&t.set("model",i.model),i.modelParams!==void 0&&Object.keys(i.modelParams).length>0&&t.set("mp",Object.entries(i.modelParams).map(([e,n])=>`${e}:${ys(n)}`).join(",")),i.length!==void 0&&t.set("l",ys(i.length)),i.mass!==void 0&&t.set("m",ys(i.mass)),i.g!==void 0&&t.set("g",ys(i.g)),i.method!==void 0&&t.set("method",i.method),i.dt!==void 0&&t.set("dt",ys(i.dt)),i.timeScale!==void 0&&t.set("ts",ys(i.timeScale)),i.x!==void 0&&t.set("x",i.x.map(ys).join(",")),i.v!==void 0&&t.set("v",i.v.map(ys).join(",")),i.paused===!0&&t.set("paused","1"),t.toString()}const Hw=/^[A-Za-z0-9_.-]{1,100}$/;function Sc(i){if(!/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(i.trim()))return null;const t=Number(i);return Number.isFinite(t)?t:null}function Gw(i){const t=new URLSearchParams(i.startsWith("?")?i.slice(1):i),e={},n=[],s=new Set(["s","model","mp","l","m","g","method","dt","ts","x","v","paused","lang"]);for(const S of t.keys())s.has(S)||n.push(`unknown URL key ${S}`);const r=S=>{const R=t.get(S);if(R!==null){if(!Hw.test(R)){n.push(`${S} = ${JSON.stringify(R)} is not a name`);return}return R}},a=S=>{const R=t.get(S);if(R===null)return;const b=Sc(R);return b===null&&n.push(`${S} = ${JSON.stringify(R)} is not a finite number`),b??void 0},o=S=>{const R=t.get(S);if(R===null)return;const b=R.split(",").map(Sc);if(b.length!==3||b.some(g=>g===null)){n.push(`${S} = ${JSON.stringify(R)} is not three finite numbers`);return}return b},l=r("s");l!==void 0&&(e.scenario=l);const c=r("model");c!==void 0&&(e.model=c);const h=t.get("mp");if(h!==null){const S={};for(const R of h.split(",")){const[b,g,...w]=R.split(":"),z=g===void 0?null:Sc(g);if(b===void 0||!/^[A-Za-z_][A-Za-z0-9_]{0,40}$/.test(b)||z===null||w.length>0){n.push(`mp: ${JSON.stringify(R)} is not name:number`);continue}S[b]=z}Object.keys(S).length>0&&(e.modelParams=S)}const u=a("l");u!==void 0&&(e.length=u);const d=a("m");d!==void 0&&(e.mass=d);const m=a("g");m!==void 0&&(e.g=m);const _=r("method");_!==void 0&&(e.method=_);const M=a("dt");M!==void 0&&(e.dt=M);const p=a("ts");p!==void 0&&(e.timeScale=p);const f=o("x"),x=o("v");f===void 0!=(x===void 0)&&n.length===0?n.push("the start needs both x and v"):f!==void 0&&x!==void 0&&(e.x=f,e.v=x);const A=t.get("paused");return A!==null&&(e.paused=A==="1"||A==="true"),{value:e,problems:n}}function Bf(i){const t={model:i.model,length:i.params.length,mass:i.params.mass,g:i.params.g,method:i.method,dt:i.dt,timeScale:i.time_scale,x:i.start.x,v:i.start.v};return i.scenario!==null&&(t.scenario=i.scenario),Object.keys(i.model_params).length>0&&(t.modelParams={...i.model_params}),i.paused&&(t.paused=!0),t}function Rh(i){const t=[];i.scenario!==void 0&&t.push({type:"load_scenario",name:i.scenario}),i.model!==void 0&&t.push({type:"set_model",model:i.model,params:{...i.modelParams}});const e={type:"set_params"};i.length!==void 0&&(e.length=i.length),i.mass!==void 0&&(e.mass=i.mass),i.g!==void 0&&(e.g=i.g),Object.keys(e).length>1&&t.push(e);const n={type:"set_method"};return i.method!==void 0&&(n.method=i.method),i.dt!==void 0&&(n.dt=i.dt),Object.keys(n).length>1&&t.push(n),i.timeScale!==void 0&&t.push({type:"set_time_scale",time_scale:i.timeScale}),i.x!==void 0&&i.v!==void 0&&t.push({type:"set_state",x:i.x,v:i.v}),t.length>0&&t.push({type:"reset"}),i.paused===!0&&t.push({type:"pause"}),t}const zf="(max-width: 700px), (max-aspect-ratio: 3/4)";function Cr(i,t,e,n=!1){const s=document.createElement("button");return s.type="button",s.dataset.action=i,s.textContent=t,s.title=e,s.setAttribute("aria-label",e),n&&s.classList.add("when-open"),s}class Vw{constructor(t,e,n){this.panel=e,t.setAttribute("aria-label",O("toolbar.label")),this.toggle=Cr("panel","",O("toolbar.collapse")),this.toggle.setAttribute("aria-controls","panel-body"),this.toggle.addEventListener("click",()=>{this.setCollapsed(!e.classList.contains("collapsed")),n.collapsed(e.classList.contains("collapsed"))}),this.runButton=Cr("run",O("toolbar.pauseShort"),O("toolbar.pause")),this.runButton.addEventListener("click",()=>n.run());const s=Cr("reset",O("toolbar.resetShort"),O("toolbar.reset"));s.addEventListener("click",()=>n.reset());const r=Cr("step",O("toolbar.stepShort"),O("toolbar.step"));r.addEventListener("click",()=>n.step()),this.recordButton=Cr("record",O("toolbar.recordShort"),O("toolbar.record")),this.recordButton.setAttribute("aria-pressed","false"),this.recordButton.addEventListener("click",()=>n.record());const a=Cr("help","?",O("toolbar.help"));a.addEventListener("click",()=>n.help());const o=document.createElement("select");o.dataset.input="language",o.classList.add("when-open"),o.setAttribute("aria-label",O("toolbar.language"));for(const[l,c]of Object.entries(Oa)){const h=document.createElement("option");h.value=l,h.textContent=c.name,o.appendChild(h)}o.value=_g(),o.addEventListener("change",()=>n.language(o.value)),t.append(this.toggle,this.runButton,s,r,this.recordButton,a,o),this.setCollapsed(!1),window.matchMedia(zf).addEventListener("change",()=>this.setCollapsed(e.classList.contains("collapsed")))}panel;runButton;recordButton;toggle;setCollapsed(t){this.panel.classList.toggle("collapsed",t),this.toggle.setAttribute("aria-expanded",String(!t));const e=window.matchMedia(zf).matches;this.toggle.textContent=e?t?"▴":"▾":t?"◂":"▸",this.toggle.title=O(t?"toolbar.expand":"toolbar.collapse"),this.toggle.setAttribute("aria-label",this.toggle.title)}showRunning(t){const e=O(t?"toolbar.startShort":"toolbar.pauseShort");this.runButton.textContent!==e&&(this.runButton.textContent=e,this.runButton.title=O(t?"toolbar.start":"toolbar.pause"),this.runButton.setAttribute("aria-label",this.runButton.title))}showRecording(t){this.recordButton.setAttribute("aria-pressed",String(t)),this.recordButton.textContent=O(t?"toolbar.recordStopShort":"toolbar.recordShort"),this.recordButton.title=O(t?"toolbar.recordStop":"toolbar.record")}}const kf=[["gravity.earth",9.81],["gravity.moon",1.62],["gravity.mars",3.71],["gravity.jupiter",24.79],["gravity.zero",0],["gravity.negative",-9.81]];function Ww(i,t){return i===null?null:"damping"in(i.model_params??{})?{type:"set_params",params:{damping:t}}:i.model==="ideal"&&t>0?{type:"set_model",model:"damped",params:{damping:t}}:null}function Xw(i,t,e){for(const[n,s]of[["θ₀",i],["φ₀",t],["φ̇₀",e]])if(!Number.isFinite(s))return O("start.notNumber",{name:n});return i<0||i>180?O("start.thetaRange",{value:i}):{type:"set_state",theta:i/$i,phi:t/$i,theta_dot:0,phi_dot:e/$i}}function Qe(i,t={},e=""){const n=document.createElement(i);for(const[s,r]of Object.entries(t))n.setAttribute(s,r);return e&&(n.textContent=e),n}function Pr(i,t,e){const n=Qe("section",{class:"tools","data-tool":e});return n.appendChild(Qe("h3",{},t)),i.appendChild(n),n}function Mc(i,t,e,n){const s=Qe("label");s.append(`${i} `);const r=Qe("input",{type:"number",step:n,name:t,"data-input":t});return r.value=String(e),r.style.width="5.5em",s.appendChild(r),[s,r]}class $w{constructor(t,e,n){this.store=e;const s=()=>this.now=e.playT??this.now,r=Pr(t,O("tools.start"),"start"),[a,o]=Mc("θ₀ [°]","theta0",30,"1"),[l,c]=Mc("φ₀ [°]","phi0",0,"1"),[h,u]=Mc("φ̇₀ [°/s]","phidot0",0,"10");o.title=O("tools.thetaHelp"),c.title=O("tools.phiHelp"),u.title=O("tools.phiDotHelp");const d=Qe("button",{type:"button","data-action":"set-start"},O("tools.setStart")),m=()=>{const g=Xw(Number(o.value),Number(c.value),Number(u.value));typeof g=="string"?n.explain(g):n.send(g)};d.addEventListener("click",m);for(const g of[o,c,u])g.addEventListener("keydown",w=>w.key==="Enter"&&m());r.append(a,l,h,d);const _=Pr(t,O("tools.world"),"world"),M=Qe("label");M.append(`${O("tools.gravity")} `),this.gravity=Qe("select",{"data-input":"gravity-preset"}),this.gravity.appendChild(Qe("option",{value:""},O("gravity.custom")));for(const[g,w]of kf)this.gravity.appendChild(Qe("option",{value:String(w)},`${O(g)} (${w} m/s²)`));this.gravity.addEventListener("change",()=>{this.gravity.value!==""&&n.send({type:"set_params",g:Number(this.gravity.value)})}),M.appendChild(this.gravity);const p=Qe("label");p.append(`${O("tools.friction")} `),this.friction=Qe("input",{type:"range",min:"0",max:"2",step:"0.01","data-input":"friction"}),this.friction.value="0",this.friction.title=O("tools.frictionHelp"),this.frictionValue=Qe("output"),this.friction.addEventListener("input",()=>{this.frictionValue.textContent=`${Number(this.friction.value).toFixed(2)} 1/s`}),this.friction.addEventListener("change",()=>{const g=Ww(e.status,Number(this.friction.value));g!==null?n.send(g):Number(this.friction.value)>0&&n.explain(O("tools.noFriction",{model:e.status?.model??"?"}))}),p.append(this.friction," ",this.frictionValue),_.append(M,p);const f=Pr(t,O("tools.now"),"angles");this.angleText=Qe("div",{class:"big","data-readout":"angles","aria-live":"off"}),f.appendChild(this.angleText);const x=Pr(t,O("tools.stopwatch"),"stopwatch");this.watchText=Qe("div",{class:"big","data-readout":"stopwatch"},"0.000 s"),this.watchButton=Qe("button",{type:"button","data-action":"stopwatch"},O("tools.swStart"));const A=Qe("button",{type:"button","data-action":"lap"},O("tools.swLap")),S=Qe("button",{type:"button","data-action":"stopwatch-reset"},O("tools.swReset"));this.lapList=Qe("ol",{class:"laps"}),this.watchButton.addEventListener("click",()=>{this.stopwatch.running?this.stopwatch.stop(s()):this.stopwatch.start(s()),this.watchButton.textContent=this.stopwatch.running?O("tools.swStop"):O("tools.swStart")}),A.addEventListener("click",()=>this.stopwatch.lap(s())),S.addEventListener("click",()=>{this.stopwatch.reset(),this.watchButton.textContent=O("tools.swStart")}),x.append(this.watchText,this.watchButton," ",A," ",S,this.lapList);const R=Pr(t,O("tools.period"),"period");R.title=O("tools.periodHelp"),this.periodTable=Qe("table",{"data-readout":"period"}),R.appendChild(this.periodTable);const b=Pr(t,O("tools.overlays"),"overlays");for(const g of["ruler","protractor"]){const w=Qe("label"),z=Qe("input",{type:"checkbox","data-input":g});z.addEventListener("change",()=>n.overlay(g,z.checked)),w.append(z,` ${O(g==="ruler"?"tools.ruler":"tools.protractor")}`),b.appendChild(w)}}store;stopwatch=new Dy;angleText;watchText;lapList;watchButton;periodTable;friction;frictionValue;gravity;now=0;sync(t){const e=kf.find(([,s])=>s===t.params.g);document.activeElement!==this.gravity&&(this.gravity.value=e?String(e[1]):"");const n=t.model_params?.damping;document.activeElement!==this.friction&&(this.friction.value=String(n??0),this.friction.disabled=n===void 0&&t.model!=="ideal",this.frictionValue.textContent=`${(n??0).toFixed(2)} 1/s`)}update(t,e){e!==null&&(this.now=e);const n=t===null?null:ph(t),s=n===null?"—":`θ = ${(n.theta*$i).toFixed(1)}°   φ = ${(n.phi*$i).toFixed(1)}°`;this.angleText.textContent!==s&&(this.angleText.textContent=s);const r=`${this.stopwatch.reading(this.now).toFixed(3)} s`;this.watchText.textContent!==r&&(this.watchText.textContent=r);const a=this.stopwatch.laps.map(o=>`${o.toFixed(3)} s`).join("|");this.lapList.dataset.shown!==a&&(this.lapList.dataset.shown=a,this.lapList.replaceChildren(...this.stopwatch.laps.map(o=>Qe("li",{},`${o.toFixed(3)} s`)))),this.fillPeriod()}fillPeriod(){const t=this.store.periodTimer.reading(),e=Fy(t,this.store.exact),n=([l,c])=>l===null||c===null||c===0?"":`${((l-c)/c*100).toFixed(2)} %`,s=l=>l===null?"—":(l*$i).toFixed(2),r=[["",O("tools.measured"),O("tools.exact"),O("tools.difference")],[e.swing?O("tools.swingPeriod"):"T_z [s]",ve(e.period[0],5),ve(e.period[1],5),n(e.period)],["Δφ [°]",s(e.advance[0]),s(e.advance[1]),n(e.advance)]],a=this.periodTable;r.forEach((l,c)=>{const h=a.rows[c]??a.insertRow();for(;h.cells.length<4;)h.insertCell();l.forEach((u,d)=>{const m=h.cells[d];m&&m.textContent!==u&&(m.textContent=u)})});const o=O("tools.periodCount",{n:t.intervals});a.caption?.textContent!==o&&(a.createCaption().textContent=o),a.dataset.period=t.period===null?"":String(t.period)}}const Yw={kinetic:"#7dff8a",potential:"#59c3ff",lost:"#ff5d73",total:"#e8e8e8"};class qw{canvas;ctx;scale=1;shown=null;constructor(t){const e=document.createElement("h3");e.textContent=O("energy.title"),t.appendChild(e),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("role","img"),this.canvas.setAttribute("aria-label",O("energy.title")),t.appendChild(this.canvas),this.ctx=this.canvas.getContext("2d")}rescale(){this.scale=1}draw(t,e){this.shown=t;const n=this.ctx;if(n===null)return;const s=Math.min(window.devicePixelRatio||1,2),r=Math.max(200,(this.canvas.parentElement?.clientWidth??300)-4),a=130;if(this.canvas.width!==Math.round(r*s)&&(this.canvas.width=Math.round(r*s),this.canvas.height=Math.round(a*s),this.canvas.style.width=`${r}px`,this.canvas.style.height=`${a}px`),n.setTransform(s,0,0,s,0,0),n.clearRect(0,0,r,a),t===null)return;const o=[["kinetic",O("energy.kinetic"),t.kinetic],["potential",O("energy.potential"),t.potential]];e&&o.push(["lost",O("energy.lost"),t.lost]),o.push(["total",O("energy.total"),t.total]);const l=Math.max(...o.map(([,,m])=>Math.abs(m)),1e-12);this.scale=l>this.scale?l:Math.max(l,.995*this.scale);const c=14,h=a-30,u=h,d=r/o.length;n.font="11px system-ui, sans-serif",n.textAlign="center",o.forEach(([m,_,M],p)=>{const f=d*p+d*.2,x=d*.6,A=Math.abs(M)/this.scale*(h-c);n.fillStyle=Yw[m],M>=0?n.fillRect(f,u-A,x,A):(n.globalAlpha=.5,n.fillRect(f,u-A,x,A),n.globalAlpha=1),n.fillStyle="#dde3ee",n.fillText(_,f+x/2,a-16),n.fillText(`${M.toPrecision(4)} J`,f+x/2,a-3)}),n.strokeStyle="#555",n.beginPath(),n.moveTo(0,u+.5),n.lineTo(r,u+.5),n.stroke()}}const Hf=(i,t)=>.5*t.mass*(i.v[0]**2+i.v[1]**2+i.v[2]**2),Ch=[{name:"t",label:"var.t",unit:"s",get:i=>i.t},{name:"theta",label:"var.theta",unit:"°",get:i=>ph(i.x).theta*$i},{name:"phi",label:"var.phi",unit:"°",get:i=>ph(i.x).phi*$i},{name:"x",label:"var.x",unit:"m",get:i=>i.x[0]},{name:"y",label:"var.y",unit:"m",get:i=>i.x[1]},{name:"z",label:"var.z",unit:"m",get:i=>i.x[2]},{name:"zdot",label:"var.zdot",unit:"m/s",get:i=>i.v[2]},{name:"speed",label:"var.speed",unit:"m/s",get:i=>Math.hypot(...i.v)},{name:"energy",label:"var.energy",unit:"J",get:i=>i.energy},{name:"kinetic",label:"var.kinetic",unit:"J",get:Hf},{name:"potential",label:"var.potential",unit:"J",get:(i,t)=>i.energy-Hf(i,t)},{name:"j3",label:"var.j3",unit:"kg m²/s",get:i=>i.j3},{name:"tension",label:"var.tension",unit:"N",get:i=>i.tension},{name:"power",label:"var.power",unit:"W",get:i=>i.power},{name:"radius",label:"var.radius",unit:"m",get:i=>Math.hypot(...i.x)}];function Aa(i){return Ch.find(t=>t.name===i)??Ch[0]}function Gf(i,t,e,n){const[s,r]=[Aa(t),Aa(e)];return{x:i.map(a=>s.get(a,n)),y:i.map(a=>r.get(a,n))}}class Kw{constructor(t){this.container=t;const e=document.createElement("div");e.className="tools chosen",e.dataset.tool="chosen";const n=document.createElement("h3");n.textContent=O("chosen.title"),e.appendChild(n);for(const s of["y","x"]){const r=document.createElement("label");r.append(`${O(s==="x"?"chosen.xAxis":"chosen.yAxis")} `);const a=document.createElement("select");a.dataset.input=`chosen-${s}`;for(const o of Ch){const l=document.createElement("option");l.value=o.name,l.textContent=`${O(o.label)} [${o.unit}]`,a.appendChild(l)}a.value=this.choice[s],a.addEventListener("change",()=>{this.choice[s]=a.value,this.labels()}),r.appendChild(a),e.append(r," ")}t.appendChild(e),this.plot=new Ta(t,"","","",170),this.plot.canvas.dataset.plot="chosen",this.visibility.watch(this.plot.canvas),this.labels()}container;plot;visibility=new pl;choice={x:"t",y:"theta"};labels(){const[t,e]=[Aa(this.choice.x),Aa(this.choice.y)];this.plot.xLabel=`${O(t.label)} [${t.unit}]`,this.plot.yLabel=`${O(e.label)} [${e.unit}]`}update(t,e,n=null){if(!this.visibility.visible(this.plot.canvas))return;const r=[{...Gf(t,this.choice.x,this.choice.y,e),color:"#59c3ff",label:O(n?"twin.first":Aa(this.choice.y).label)}];n!==null&&r.push({...Gf(n,this.choice.x,this.choice.y,e),color:"#c8f560",label:O("twin.second")});const a=r.flatMap(l=>l.x),o=r.flatMap(l=>l.y);this.plot.draw(this.container.clientWidth-8,r,qs(a,.02),qs(o))}}function Zw(i,t){const e=Math.hypot(...i),n=Math.atan2(Math.hypot(i[0],i[1]),-i[2])+t,s=Math.atan2(i[1],i[0]);return[e*Math.sin(n)*Math.cos(s),e*Math.sin(n)*Math.sin(s),-e*Math.cos(n)]}function Jw(i,t){const e=[];i.scenario&&e.push({type:"load_scenario",name:i.scenario});const n=t.mode==="damped",s=n&&i.model==="ideal"?"damped":i.model,r={...i.model_params};n&&(r.damping=t.damping),e.push({type:"set_model",model:s,params:r}),e.push({type:"set_params",length:i.params.length,mass:i.params.mass,g:i.params.g}),e.push({type:"set_method",method:t.mode==="method"?t.method:i.method,dt:i.dt});const a=t.mode==="epsilon"?Zw(i.start.x,t.epsilon):i.start.x;return e.push({type:"set_state",x:a,v:i.start.v,project:!0}),e.push({type:"set_time_scale",time_scale:i.time_scale}),e.push({type:"reset"}),e.push({type:i.paused?"pause":"resume"}),e}function jw(i,t){const e=i.length;if(e===0)return null;const n=i[0],s=i[e-1];if(t<n.t||t>s.t)return null;let r=0,a=e-1;for(;a-r>1;){const p=r+a>>1;i[p].t<=t?r=p:a=p}const o=i[r],l=i[a],c=l.t-o.t;if(!(c>0))return[o.x[0]+o.pivot[0],o.x[1]+o.pivot[1],o.x[2]+o.pivot[2]];const h=(t-o.t)/c,[u,d,m,_]=[2*h**3-3*h**2+1,h**3-2*h**2+h,-2*h**3+3*h**2,h**3-h**2],M=p=>u*o.x[p]+d*c*o.v[p]+m*l.x[p]+_*c*l.v[p]+(1-h)*o.pivot[p]+h*l.pivot[p];return[M(0),M(1),M(2)]}function Vf(i,t){const e=[],n=[];for(const s of i){const r=jw(t,s.t);r!==null&&(e.push(s.t),n.push(Math.hypot(s.x[0]+s.pivot[0]-r[0],s.x[1]+s.pivot[1]-r[1],s.x[2]+s.pivot[2]-r[2])))}return{t:e,d:n}}class Qw{constructor(t,e,n,s,r){this.first=e,this.socket=s,this.actions=r;const a=document.createElement("section");a.className="tools",a.dataset.tool="twin";const o=document.createElement("h3");o.textContent=O("twin.title"),a.appendChild(o);const l=document.createElement("label");l.append(`${O("twin.mode")} `);const c=document.createElement("select");c.dataset.input="twin-mode";const h=[["off",O("twin.off")],["epsilon",O("twin.epsilon")],["method",O("twin.method")],["damped",O("twin.damped")]];for(const[A,S]of h){const R=document.createElement("option");R.value=A,R.textContent=S,c.appendChild(R)}l.appendChild(c);const u=document.createElement("label");u.append("ε [°] ");const d=document.createElement("input");d.type="number",d.step="0.01",d.value="0.01",d.dataset.input="twin-epsilon",d.style.width="5em",u.appendChild(d);const m=document.createElement("label");m.append(`${O("twin.methodPick")} `);const _=document.createElement("select");_.dataset.input="twin-method";for(const A of n){const S=document.createElement("option");S.value=A.name,S.textContent=A.name,_.appendChild(S)}_.value=n.some(A=>A.name==="rk4")?"rk4":n[0]?.name??"",m.appendChild(_);const M=document.createElement("label");M.append(`${O("twin.damping")} `);const p=document.createElement("input");p.type="number",p.step="0.1",p.min="0",p.value="0.5",p.dataset.input="twin-damping",p.style.width="5em",M.appendChild(p);const f=document.createElement("button");f.type="button",f.dataset.action="twin-start",f.textContent=O("twin.start");const x=()=>{u.hidden=c.value!=="epsilon",m.hidden=c.value!=="method",M.hidden=c.value!=="damped",f.hidden=c.value==="off"};c.addEventListener("change",()=>{x(),c.value==="off"&&this.stop()}),f.addEventListener("click",()=>{if(this.options.mode=c.value,this.options.epsilon=Number(d.value)/$i,this.options.method=_.value,this.options.damping=Number(p.value),!Number.isFinite(this.options.epsilon)||!(this.options.damping>=0)){r.explain(O("twin.bad"));return}this.start()}),x(),a.append(l," ",u,m,M," ",f),t.appendChild(a),this.plot=new Ta(t,O("twin.separation"),"t [s]","|r₁ − r₂| [m]",140),this.plot.canvas.dataset.plot="separation",this.plot.canvas.parentElement?.setAttribute("hidden",""),this.visibility.watch(this.plot.canvas)}first;socket;actions;store=new nm;options={mode:"off",epsilon:.01/$i,method:"rk4",damping:.5};conn=null;pending=[];plot;visibility=new pl;get on(){return this.conn!==null}start(){const t=this.first.status;if(t===null)return this.actions.explain(O("msg.notConnected"));this.pending=Jw(t,this.options),this.conn===null?this.conn=new Xf(this.socket,{onOpen:()=>this.flush(),onClose:()=>this.store.setConnected(!1),onFrames:e=>this.store.onFrames(e),onNotice:e=>{e.type==="status"?this.store.onStatus(e):e.type==="event"?this.store.onEvent(e):this.actions.explain(`${O("twin.second")}: ${e.message}`)},onProtocolError:e=>this.actions.explain(`${O("twin.second")}: ${e}`)}):this.flush(),this.actions.send({type:"reset"}),this.plot.canvas.parentElement?.removeAttribute("hidden")}flush(){if(!(this.conn===null||!this.conn.isOpen)){for(const t of this.pending)this.conn.send(t);this.pending=[]}}stop(){this.conn?.close(),this.conn=null,this.store.clear(),this.store.status=null,this.plot.canvas.parentElement?.setAttribute("hidden","")}mirror(t){this.conn!==null&&(t.type==="pause"||t.type==="resume"||t.type==="reset"||t.type==="step")&&this.conn.send(t)}drawn(t,e){if(this.conn===null||t===null||this.store.frames.length===0)return null;const n=this.store.frames;this.store.playT=Math.min(Math.max(t,n[0].t),n[n.length-1].t);const{start:s,end:r}=this.store.trailRange(e);return{frame:this.store.displayed(),trail:{frames:this.store.trail,start:s,end:r}}}update(t){if(this.conn===null||!this.visibility.visible(this.plot.canvas))return;const e=Vf(this.first.history.frames,this.store.trajectory);this.plot.draw(t,[{x:e.t,y:e.d,color:"#c8f560",label:O("twin.separation")}],qs(e.t,.02),qs([0,...e.d]))}separationNow(){return Vf(this.first.history.frames,this.store.trajectory)}}const tT=i=>`#${i.toString(16).padStart(6,"0")}`,eT={velocity:"vec.velocity",momentum:"vec.momentum",gravity:"vec.gravity",tension:"vec.tension",net:"vec.net",angularMomentum:"vec.angularMomentum",torque:"vec.torque"};class nT{constructor(t){this.el=t,t.setAttribute("aria-label",O("help.title"));const e=document.createElement("div");e.className="help-box";const n=document.createElement("h2");n.textContent=O("help.title");const s=document.createElement("table"),r=[["Space","help.space"],["R","help.r"],["S","help.s"],["← → ↑ ↓","help.arrows"],["Page ↑ / Page ↓","help.page"],["Tab","help.tab"],["?","help.help"],["Esc","help.esc"]];for(const[h,u]of r){const d=s.insertRow(),m=d.insertCell(),_=document.createElement("kbd");_.textContent=h,m.appendChild(_),d.insertCell().textContent=O(u)}const a=document.createElement("h3");a.textContent=O("help.colours");const o=document.createElement("ul");o.className="colour-key";const l=[["#ff8c42",O("help.bob")],["#59c3ff",O("help.trail")],["#c8f560",O("help.twin")],...Object.entries(eT).map(([h,u])=>[tT(qh[h]),O(u)]),["#e6d3a3",O("help.ruler")]];for(const[h,u]of l){const d=document.createElement("li"),m=document.createElement("span");m.className="swatch",m.style.background=h,d.append(m,` ${u}`),o.appendChild(d)}const c=document.createElement("button");c.type="button",c.dataset.action="help-close",c.textContent=O("help.close"),c.addEventListener("click",()=>this.toggle(!1)),e.append(n,s,a,o,c),t.appendChild(e),t.addEventListener("click",h=>h.target===t&&this.toggle(!1))}el;returnFocus=null;get open(){return!this.el.hidden}toggle(t=!this.open){t!==this.open&&(t?(this.returnFocus=document.activeElement instanceof HTMLElement?document.activeElement:null,this.el.hidden=!1,this.el.querySelector("button")?.focus()):(this.el.hidden=!0,this.returnFocus?.focus()))}}const iT=300,sT=25e5;function rT(i){for(const t of["video/webm;codecs=vp9","video/webm;codecs=vp8","video/webm"])if(i(t))return t;return null}class aT{constructor(t,e){this.canvas=t,this.done=e}canvas;done;recorder=null;chunks=[];timer=null;get recording(){return this.recorder!==null}start(){if(this.recorder!==null)return null;if(typeof MediaRecorder>"u"||typeof this.canvas.captureStream!="function")return"no MediaRecorder";const t=rT(s=>MediaRecorder.isTypeSupported(s));if(t===null)return"no WebM";const e=this.canvas.captureStream(30),n=new MediaRecorder(e,{mimeType:t,videoBitsPerSecond:sT});return this.chunks=[],n.ondataavailable=s=>{s.data.size>0&&this.chunks.push(s.data)},n.onstop=()=>{for(const s of e.getTracks())s.stop();this.done(new Blob(this.chunks,{type:"video/webm"})),this.chunks=[]},n.start(1e3),this.recorder=n,this.timer=setTimeout(()=>this.stop(),iT*1e3),null}stop(){this.timer!==null&&clearTimeout(this.timer),this.timer=null;const t=this.recorder;this.recorder=null,t!==null&&t.state!=="inactive"&&t.stop()}}function oT(i,t){if(t)return null;switch(i){case" ":case"Spacebar":return"run";case"r":case"R":return"reset";case"s":case"S":return"step";case"?":return"help";case"Escape":return"close";default:return null}}function lT(i){switch(i){case"ArrowUp":case"ArrowRight":return 1;case"ArrowDown":case"ArrowLeft":return-1;case"PageUp":return 10;case"PageDown":return-10;case"Home":return-1/0;case"End":return 1/0;default:return null}}function cT(i,t=""){return typeof HTMLElement>"u"||!(i instanceof HTMLElement)?!1:t===" "&&(i instanceof HTMLButtonElement||i instanceof HTMLInputElement&&["checkbox","radio","button"].includes(i.type))||i.isContentEditable||i instanceof HTMLSelectElement||i instanceof HTMLTextAreaElement?!0:i instanceof HTMLInputElement?!["checkbox","radio","button"].includes(i.type):i.getAttribute("role")==="slider"}function Wf(i){for(const t of i.controllersRecursive()){const e=t.$slider;e!==void 0&&(e.setAttribute("aria-valuenow",String(t.getValue())),e.dataset.keys!=="1"&&(e.dataset.keys="1",e.tabIndex=0,e.setAttribute("role","slider"),e.setAttribute("aria-label",t.$name.textContent??""),t._min!==void 0&&e.setAttribute("aria-valuemin",String(t._min)),t._max!==void 0&&e.setAttribute("aria-valuemax",String(t._max)),e.addEventListener("keydown",n=>{const s=lT(n.key);if(s===null)return;n.preventDefault(),n.stopPropagation();const[r,a,o]=[t._min??-1/0,t._max??1/0,t._step??.01],l=Number(t.getValue()),c=s===1/0?a:s===-1/0?r:Math.min(a,Math.max(r,l+s*o));Number.isFinite(c)&&t.setValue(+c.toPrecision(12)),e.setAttribute("aria-valuenow",String(t.getValue()))})))}}const Ph=2*2**20,hT=["damped","ideal","rotating","slewing","vibrating"];function uT(i,t,e,n,s){if(e>Ph)return`${i}: ${(e/2**20).toFixed(1)} MiB; the lab fits files of at most ${Ph/2**20} MiB (use pendulab fit for larger ones)`;if(t.trim()==="")return`${i}: the file is empty`;const r={csv:t,name:i,model:n},a=s.split(/[\s,]+/).filter(o=>o!=="");return a.length>0&&(r.fit=a),r}const $m=i=>typeof i=="number"&&Number.isFinite(i),dT=i=>Array.isArray(i)&&i.length===3&&i.every($m);function fT(i){if(typeof i!="object"||i===null)return"the fit answer is not an object";const t=i;if(typeof t.report!="string"||typeof t.scenario_toml!="string")return"the fit answer has no report";const e=t.measured;if(e!=null){const n=e,s=n.t,r=n.x;if(!Array.isArray(s)||!Array.isArray(r)||s.length!==r.length||!s.every($m)||!r.every(dT))return"the fit answer has a malformed measured path"}return{report:t.report,warnings:Array.isArray(t.warnings)?t.warnings.filter(n=>typeof n=="string"):[],params:t.params??{},converged:t.converged===!0,scenario_toml:t.scenario_toml,lab:t.lab??null,measured:e??null}}function pT(i){const t={model:i.model,modelParams:{...i.model_params},length:i.params.length,mass:i.params.mass,g:i.params.g,method:i.method,dt:i.dt,x:i.start.x,v:i.start.v};return Rh(t)}function mT(i){return Object.entries(i).map(([t,e])=>{const n=e.determined&&e.stderr!==null?` ± ${e.stderr.toPrecision(2)}`:" (not determined by these data)",s=e.unit&&e.unit!=="1"?` ${e.unit}`:"";return`${t} = ${e.value.toPrecision(6)}${n}${s}`})}function oi(i,t={},e=""){const n=document.createElement(i);for(const[s,r]of Object.entries(t))n.setAttribute(s,r);return e&&(n.textContent=e),n}class gT{constructor(t,e){this.actions=e;const n=oi("section",{class:"tools","data-tool":"fit"});n.appendChild(oi("h3",{},O("fit.title")));const s=oi("label");s.append(`${O("fit.load")} `),this.input=oi("input",{type:"file",accept:".csv,.txt,.tsv,text/csv,text/plain","data-input":"fit-file"}),s.appendChild(this.input),s.title=O("fit.help");const r=oi("label");r.append(`${O("fit.model")} `),this.model=oi("select",{"data-input":"fit-model"});for(const o of hT)this.model.appendChild(oi("option",{value:o},o));r.appendChild(this.model);const a=oi("label");a.append(`${O("fit.params")} `),this.names=oi("input",{type:"text","data-input":"fit-params",placeholder:O("fit.paramsDefault")}),this.names.style.width="12em",a.appendChild(this.names),a.title=O("fit.paramsHelp"),this.clear=oi("button",{type:"button","data-action":"fit-clear"},O("fit.clear")),this.clear.disabled=!0,this.clear.addEventListener("click",()=>this.reset()),this.report=oi("pre",{class:"fit-report","data-output":"fit-report","aria-live":"polite"}),this.report.hidden=!0;for(const o of[s,r,a,this.clear]){const l=oi("p");l.appendChild(o),n.appendChild(l)}n.appendChild(this.report),t.appendChild(n),this.input.addEventListener("change",()=>{const o=this.input.files?.[0];o!==void 0&&this.send(o)})}actions;input;model;names;clear;report;busy=!1;reset(){this.report.hidden=!0,this.report.textContent="",this.clear.disabled=!0,this.input.value="",this.actions.cleared()}async send(t){if(this.busy)return;const e=t.size>Ph?"":await t.text(),n=uT(t.name,e,t.size,this.model.value,this.names.value);if(typeof n=="string")return this.actions.explain(n);this.busy=!0,this.input.disabled=!0,this.report.hidden=!1,this.report.textContent=O("fit.running",{name:t.name});try{const s=await fetch("api/fit",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(n)}),r=await s.json().catch(()=>({detail:`HTTP ${s.status}`}));if(!s.ok){const l=r.detail;throw new Error(typeof l=="string"?l:`HTTP ${s.status}`)}const a=fT(r);if(typeof a=="string")throw new Error(a);const o=[a.report,"",...mT(a.params),...a.warnings.map(l=>`warning: ${l}`)];a.measured===null&&o.push(O("fit.noPath")),this.report.textContent=o.join(`
`),this.clear.disabled=!1,this.actions.loaded(a,t.name)}catch(s){const r=s instanceof Error?s.message:String(s);this.report.textContent=`${t.name}: ${r}`,this.actions.explain(O("fit.failed",{why:r}))}finally{this.busy=!1,this.input.disabled=!1}}}function Ye(i){const t=document.getElementById(i);if(t===null)throw new Error(`#${i} missing from index.html`);return t}function Do(i,t){const e=document.createElement("a");e.href=t,e.download=i,document.body.appendChild(e),e.click(),e.remove()}async function _T(){const i=mg(new URLSearchParams(window.location.search).get("lang"),window.localStorage?.getItem("pendulab.lang")??null,navigator.languages??[navigator.language]);gg(i),document.documentElement.lang=i,document.title=O("page.title"),Ye("units").textContent=O("page.units"),Ye("scene").setAttribute("aria-label",O("page.scene")),Ye("panel").setAttribute("aria-label",O("page.panel"));const t=new nm,e=Ye("message");let n=null;const s=(B,et=!1)=>{e.textContent=B,e.classList.toggle("info",et),e.classList.add("shown"),n!==null&&clearTimeout(n),n=setTimeout(()=>e.classList.remove("shown"),6e3)},[r,a]=await Promise.all([Ah("api/schema"),Ah("api/scenarios")]);t.tickHz=r.tick_hz;const o=Qy(tb(),window.devicePixelRatio);o.software&&(Ye("render").textContent=` · ${O("page.software")}`,Ye("render").title=O("page.softwareHelp",{renderer:o.renderer??""}));const l=new Eb(Ye("scene"),o);l.renderer.domElement.setAttribute("role","img"),l.renderer.domElement.setAttribute("aria-label",O("page.scene"));const c={...mb},h=new Bw,u=new Kw(Ye("plots")),d=new Cw(Ye("plots"),B=>h.add("plots drawn (uPlot)",B)),m=new Dw(Ye("portraits")),_=new hu(Ye("reduced"),o),M=new Cg(Ye("data")),p=Gw(window.location.search);p.problems.length>0&&s(`link: ${p.problems.join("; ")}`);let f=Rh(p.value),x=null,A=null;const S=B=>{x===null||!x.send(B)?s(O("msg.notConnected")):A?.mirror(B)},R=()=>S({type:t.status?.paused===!1?"pause":"resume"}),b=()=>S({type:"reset"}),g=()=>S({type:"step",n:1});let w=null;const z=new aT(l.renderer.domElement,B=>{B.slice(0,4).arrayBuffer().then(ht=>{w={size:B.size,head:[...new Uint8Array(ht)].map(gt=>gt.toString(16).padStart(2,"0")).join("")}});const et=URL.createObjectURL(B);Do(`pendulab-${t.status?.scenario??"lab"}.webm`,et),setTimeout(()=>URL.revokeObjectURL(et),1e4),s(O("msg.recorded",{mb:(B.size/1e6).toFixed(1)}),!0)}),I=new nT(Ye("help")),L=new Vw(Ye("toolbar"),Ye("panel"),{run:R,reset:b,step:g,record:()=>{if(z.recording)z.stop();else{const B=z.start();B!==null?s(O("msg.noRecording",{why:B})):s(O("msg.recording"),!0)}L.showRecording(z.recording)},help:()=>I.toggle(),language:B=>{window.localStorage?.setItem("pendulab.lang",B),ug(()=>t.status?.commands,()=>x?.sent??0,2e3).then(()=>{const et=new URLSearchParams(window.location.search);et.set("lang",B),window.location.search=et.toString()})},collapsed:()=>{}});document.addEventListener("keydown",B=>{const et=oT(B.key,B.ctrlKey||B.metaKey||B.altKey);if(et!==null){if(et==="close"){I.open&&I.toggle(!1);return}cT(B.target,B.key)||I.open&&et!=="help"||(B.preventDefault(),et==="run"?R():et==="reset"?b():et==="step"?g():I.toggle())}});const V=new $w(Ye("tools"),t,{send:S,explain:s,overlay:(B,et)=>{c[B]=et}}),$=new qw(Ye("energy"));new gT(Ye("tools"),{loaded:(B,et)=>{if(l.setMeasured(B.measured?.x??null),B.lab!==null)for(const ht of pT(B.lab))S(ht);s(O("fit.loaded",{name:et}),!0)},cleared:()=>l.setMeasured(null),explain:s});const N=new Ab(Ye("gui"),r,a,c,{send:S,explain:s,downloadCSV:()=>{const B=new Blob([t.toCSV()],{type:"text/csv"}),et=URL.createObjectURL(B);Do(`pendulab-${t.status?.scenario??"lab"}.csv`,et),setTimeout(()=>URL.revokeObjectURL(et),1e4)},downloadTOML:()=>{const B=t.status;if(B===null)return s(O("msg.notConnected"));fetch("api/scenario.toml",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(zw(B))}).then(async et=>{if(!et.ok)throw new Error((await et.json()).detail??`HTTP ${et.status}`);const ht=URL.createObjectURL(await et.blob());Do(`pendulab-${B.scenario??"lab"}.toml`,ht),setTimeout(()=>URL.revokeObjectURL(ht),1e4)}).catch(et=>s(`scenario download: ${et instanceof Error?et.message:String(et)}`))},screenshot:()=>Do(`pendulab-${t.status?.scenario??"lab"}.png`,l.screenshot()),copyLink:()=>{const B=window.location.href;navigator.clipboard?.writeText(B).then(()=>s(O("msg.linkCopied"),!0),()=>s(B))??s(B)},viewChanged:(B,et)=>{l.setTopView(et),l.setStereo(B.stereo)}}),W=new Nw(t,_,s);A=new Qw(Ye("tools"),t,r.methods,Lu(window.location),{send:S,explain:s}),Wf(N.gui);const J=B=>{const et=t.status;t.onStatus(B),et!==null&&(et.scenario!==B.scenario||et.model!==B.model)&&e.classList.contains("info")&&e.classList.remove("shown"),(et===null||et.epoch!==B.epoch)&&$.rescale(),N.sync(B),Wf(N.gui),V.sync(B),L.showRunning(B.paused),l.setLength(B.params.length),l.setModel(B.model),m.setModel(B.model),f.length===0&&window.history.replaceState(null,"",`?${kw(Bf(B))}`)};x=new Xf(Lu(window.location),{onOpen:()=>{t.setConnected(!0),Ye("conn").textContent=O("conn.connected")},onClose:()=>{t.setConnected(!1),Ye("conn").textContent=O("conn.retrying"),t.status!==null&&(f=Rh(Bf(t.status)))},onFrames:B=>{const et=performance.now();t.onFrames(B),W.onFrames(),h.add("frames received",performance.now()-et)},onNotice:B=>{if(B.type==="error"){t.onError(B),s(B.command?`${B.command}: ${B.message}`:B.message);return}if(B.type==="event"){t.onEvent(B),s(yg(B),!0);return}if(J(B),f.length>0){const et=f;f=[];for(const ht of et)S(ht)}},onProtocolError:B=>s(`protocol: ${B}`)});let H=0;const ct=Ih((B,et)=>{S({type:"set_state",x:B,v:et,project:!0})},50),Z=()=>{t.status?.paused===!1&&S({type:"pause"})};l.enableDrag((B,et)=>{et==="start"&&Z(),ct(B,[0,0,0]),et==="end"&&s(O("msg.dragged"),!0)},(B,et,ht)=>{if(ht==="start"){Z(),s(O("msg.pull"),!0);return}if(et===null)return;ct(B,et.v);const gt=et.capped?O("msg.capped"):"";s(ht==="end"?O("msg.velocitySet",{v:et.speed.toFixed(2),cap:gt}):O("msg.velocity",{v:et.speed.toFixed(2),cap:gt}),!0)}),window.pendulab={store:t,drawn:()=>H,send:S,screenshot:()=>l.screenshot(),bobOnScreen:()=>l.bobOnScreen(),handleOnScreen:()=>l.handleOnScreen(),quality:()=>o,frameCosts:()=>h.take(),twin:A.store,twinOnScreen:()=>l.twinOnScreen(),sphereOnScreen:()=>l.sphereOnScreen(),separation:()=>A?.separationNow()??{t:[],d:[]},energy:()=>$.shown,lastVideo:()=>w,plotScales:()=>d.scales(),measuredPoints:()=>l.measuredPoints()};let tt=performance.now();const st=new Fw(100),pt=new Ow,ft=B=>{const et=(B-tt)/1e3;tt=B;let ht=performance.now();t.advancePlayhead(et);const gt=t.displayed(),vt=t.status?.params,Gt=Wy(t.status?.model_params),{start:Qt,end:kt}=t.trailRange(c.trailSeconds),ne=vt?.mass??1,ee=vt?.g??9.81,qt=A?.drawn(t.playT,c.trailSeconds)??null,Ie=pt.changed([gt,t.trail,Qt,kt,ne,ee,...Gt,...Object.values(c),qt?.frame??null,qt?.trail.end??0]);Ie&&(l.update(gt,{frames:t.trail,start:Qt,end:kt},c,ne,ee,Gt),l.updateTwin(qt?.frame??null,qt?.trail??{frames:[],start:0,end:0}));let me=performance.now();if(h.add("scene update",me-ht),l.draw(Ie)?(H++,ht=performance.now(),h.add("scene render (submit)",ht-me)):ht=me,st.due(B)){const Xe=t.reference,Me=vt?.length??1;d.update(t.history,t.events,Aw(Xe?.energy??0,Xe?.j3??0,ne,ee,Me));const rn={mass:ne,g:ee,length:Me};u.update(t.history.frames,rn,A?.on?A.store.history.frames:null),A?.update(Ye("plots").clientWidth-8),V.update(gt?.x??null,gt?.t??null);const de=t.latest();$.draw(de?Iy(de,ne,ee,Me,t.work):null,t.status?.model!=="ideal"),me=performance.now(),h.add("plots setData",me-ht),m.update(t.history,gt,W.veff,vt?.mass??1,vt?.g??9.81,vt?.length??1),m.updateEM(W.em,gt),ht=performance.now(),h.add("portraits",ht-me),_.update(gt,vt?.length??1),me=performance.now(),h.add("reduced view",me-ht),M.update(gt,t),h.add("data panel",performance.now()-me)}requestAnimationFrame(ft)};requestAnimationFrame(ft)}_T().catch(i=>{const t=document.getElementById("message");t&&(t.textContent=`the lab could not start: ${i instanceof Error?i.message:String(i)}`,t.classList.add("shown")),console.error(i)});
