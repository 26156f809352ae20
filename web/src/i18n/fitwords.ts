// The fit report's words in every language the page speaks (issue 28; docs/web.md, "Languages"): the server
// sends the report and the fit's warnings as message keys with values beside their English text
// (python/pendulab/server/fit_words.py, fit_words.json: `notes`, `items`, a parameter's `reason`); this
// table words each key for a student, and names the fit's parameters (no `theta_dot0`), data kinds and
// models in plain words. A key the table does not have is shown as the server's English text. Values are
// the server's strings (numbers as its English text has them, SI units); `kind`, `kinds`, `param`, `model`,
// `others` and `label` hold code names and are worded here. No DOM; unit-tested (tests/unit/fitwords.test.ts).
import { language, modelWords, paramWords } from './index';
import type { Lang } from './index';
import type { FittedParam, KeyedLine } from '../fitdata';
import { readKeyed } from '../fitdata';

type Table = Record<string, string>;

const EN: Table = {
  explainsLittle: "{kind}: the fitted motion explains only {percent} % of how much the data vary: the data may not show a pendulum's swing above their noise, or the model or the starting values are far off",
  correlatedNoise: '{kind}: the misses follow each other (lag-1 autocorrelation {lag1}) like the noise of video tracking or a filter, not like a wrong model: the error bars were widened for it',
  systematicDrift: "{kind}: the fit misses the data systematically, with a slow drift: the misses (rms {rms}) are {ratio} times the data's own noise ({floor}). The model lacks something (another kind of friction, a moving pivot, a wrong scale), or the noise itself is correlated",
  systematic: "{kind}: the fit misses the data systematically: the misses (rms {rms}) are {ratio} times the data's own noise ({floor}). The model lacks something (another kind of friction, a sensor offset, a moving pivot, a wrong scale), or the noise itself is correlated",
  correlatedSmall: "{kind}: the misses follow each other (lag-1 autocorrelation {lag1}) though they are no larger than the data's noise: correlated noise, or a small effect the model lacks; the error bars were widened for it",
  aboveFloor: '{kind}: the misses (rms {rms}) are {ratio} times the noise read off the data ({floor}): the model does not fit, or the noise is not random',
  outliers: '{kind}: {n} values lie far from the fit (more than {sigmas} standard deviations): outliers?',
  chi2Large: 'the fitted motion misses the data by {factor} times their given noise (chi2 = {chi2}): improbable for a right model. The model lacks something (friction, a moving pivot), the noise given is too small, or the fit is stuck (try other starting values)',
  chi2Small: 'chi2/dof = {reduced} is improbably small for {dof} degrees of freedom: the noise given is too large, and so are the error bars',
  blocksDisagree: "the record's {n} parts, each fitted on its own, disagree: {param} = {values} (the parts in time order), {scale} times their error bars apart. The model misses something that changes along the record (friction that depends on the amplitude, a drifting sensor, a hinge that is not ideal): the error bars were widened for it",
  blocksTimeLimit: "the lab's fits stop after {seconds} s, before the check that compares fits to the record's parts was made: the model misses the data, and the error bars were not widened for it, so they may be too narrow. Fit the data file on your computer with pendulab fit FILE --time-limit none (or pl.fit(..., time_limit=None)), or start the lab with a longer pendulab serve --fit-time-limit",
  blocksCtrlC: "Ctrl-C stopped the fit before the check that compares fits to the record's parts was made: the model misses the data, and the error bars were not widened for it, so they may be too narrow. Fit again and let it finish",
  blocksCtrlCIn: "Ctrl-C stopped the check that compares fits to the record's {n} parts before it was done: the error bars were not widened for the parts' disagreement, so if the model misses the data they may be too narrow. Fit again and let it finish",
  blocksSearchTimeLimit: "the lab's fits stop after {seconds} s, which cut the search short before it converged: the misfit may be the unfinished search's, not the model's. The check that compares fits to the record's parts was not made and the error bars were not widened for it. Fit the data file on your computer with pendulab fit FILE --time-limit none (or pl.fit(..., time_limit=None)), or start the lab with a longer pendulab serve --fit-time-limit",
  blocksSearchCtrlC: "Ctrl-C cut the search short before it converged: the misfit may be the unfinished search's, not the model's. The check that compares fits to the record's parts was not made and the error bars were not widened for it. Fit again and let it finish",
  bandPower: '; near {hz} Hz the misses have {ratio} times the power of the rest of their spectrum (p = {p}): a pattern at a few frequencies, not random noise',
  dampingDry: '; the damping fitted to each part grows as the swing dies down (the swing shrinks more linearly than exponentially), as dry friction makes: fit {param} as well',
  dampingDrag: '; the damping fitted to each part falls as the swing dies down (the large swings lose more), as air drag makes: fit {param} as well',
  stopTimeLimit: "; the lab's fits stop after {seconds} s, before the profile likelihood that checks these error bars was computed: fit the data file on your computer with pendulab fit FILE --time-limit none (or pl.fit(..., time_limit=None))",
  stopCtrlC: '; Ctrl-C stopped the fit before the profile likelihood that checks these error bars was computed',
  stopRobust: '; the profile likelihood that checks these error bars is not computed with a robust loss ({loss}): fit again with the linear loss once the outliers are removed',
  gFar: "the fitted g = {g} m/s² is far from any planet's (Earth: 9.81 m/s²): are the data in SI units (metres, not mm or pixels; seconds; radians)?",
  pivotFitted: 'the positions do not hang from the origin: where the pivot is was fitted too',
  timeLimit: 'the fit stopped at its time limit of {seconds} s: the values are the best reached',
  notConverged: 'the fit did not converge: the values are the best reached',
  dropped: '{n} of {total} rows had a missing or infinite value and were left out',
  sorted: 'the times were not in increasing order: the rows were sorted',
  lengthHint: "the positions lie {radius} m from the pivot, but the pendulum is {length} m long: are the positions in metres and is the pivot right? The fit starts from the data's distance",
  shortUndetermined: "{others} are not determined: the record spans only {periods} of a swing (a small-swing period is {period} s), too short to tell the length from g, and the error bars from the fit's curvature would be far too narrow. Record at least one full swing",
  shortWidened: "the record spans only {periods} of a swing (a small-swing period is {period} s): the error bars of {others} were taken from their 95 % profile-likelihood intervals, which the fit's curvature understates. Record at least one full swing to narrow them",
  mirrorPlanar: 'the data are consistent with a swing in one plane: held in the plane (no sideways start angle or speed) the misfit rises by only {rise} (the 95 % level for the two is {level}). Seen from the side, the sideways motion shows only weakly near the plane, so its error bars were taken from the profile of the misfit. Fit the swing as planar if it swings in a plane',
  mirrorWidened: "seen from the side near its plane, the sideways motion shows only weakly: the error bars of {others} were taken from their 95 % profile-likelihood intervals, which the fit's curvature understates",
  mirrorUndetermined: "seen from the side, the sideways motion is not determined ({others}): near its plane it shows only weakly, and the error bars from the fit's curvature would be too narrow. Fit the swing as planar if it swings in a plane",
  mirrorSignUndetermined: 'seen from the side, the direction of the sideways motion is not determined: only a term the mirror y → −y changes (a turning frame, a pivot moving sideways) tells the motion from its mirror image, and the mirror image fits as well (its misfit is higher by only {rise}; the 95 % level is {level}). Record y too, or fit the swing as planar if it swings in a plane',
  notFinite: "the model's response to it is not finite at the fit",
  flat: 'the data do not change with it (a symmetry of the data, or a rate of 0 seen from the side)',
  combination: 'the data determine only a combination of it with {others}',
  shortRecord: 'a record of {periods} of a swing does not determine it',
  mirrorUnchecked: "the fit stopped before the error bars of the sideways motion were checked (seen from the side near its plane, the curvature's bars would be too narrow)",
  mirrorOpen: 'seen from the side near its plane, the data do not bound the sideways motion (its profile likelihood does not close)',
  mirrorSign: 'seen from the side, only a term the mirror y → −y changes (a turning frame, a pivot moving sideways) tells the motion from its mirror image, and the mirror image fits as well (its misfit is higher by only {rise}; the 95 % level is {level})',
  mirrorSignUnchecked: "the fit stopped before the motion's mirror image was refitted (seen from the side, only a turning frame or a pivot moving sideways tells the two apart)",
  lateBars: "the fit's time limit ran out before the error bars were computed",
  header: 'fit of the {model} to {samples} measurements ({kinds}), starting at t = {t0} s',
  droppedRows: '({n} rows with missing values were left out)',
  combinationValue: 'determined instead: {label} = {value} ± {err}',
  mirror: 'the data cannot tell this motion from its mirror image (y → −y): the direction of the sideways motion is a choice',
  mirrorSignTold: 'seen from the side, the data tell the direction of the sideways motion: only a term the mirror y → −y changes (a turning frame, a pivot moving sideways) tells the motion from its mirror image, and the mirror image fits worse (its misfit is higher by {rise}; the threshold is {threshold}, the 95 % level {level})',
  mirrorSignNotTold: 'seen from the side, the data do not tell the direction of the sideways motion: the mirror image y → −y fits as well (its misfit is higher by only {rise}; the 95 % level is {level})',
  mirrorSignNotChecked: 'seen from the side, the direction of the sideways motion was not checked: the fit stopped before the motion\'s mirror image y → −y was refitted',
  planar: 'the swing was fitted in one plane (a hinge): no sideways start angle or speed',
  residual: "{kind}: the fit misses the data by {rms} {unit} (rms); the data's own noise is about {floor} {unit}; lag-1 autocorrelation of the misses {lag1} (near 0: random misses, near 1: misses that follow a pattern)",
  chi2: 'chi2/dof = {reduced} (chi2 = {chi2} for {dof} degrees of freedom): the misses measured in units of the noise given; about 1 means the fit is as close as the noise allows, much more means the model misses something',
  chi2Estimated: 'chi2/dof = {reduced} (chi2 = {chi2} for {dof} degrees of freedom): the noise was estimated from the misses themselves, so chi2/dof is 1 by construction and says nothing here; see the lines above',
  noise: 'noise of the {kind}: {sigma} {unit}',
  fixed: 'held fixed: {param} = {value} {unit}',
  converged: 'the fit converged ({runs} model runs, {seconds} s)',
  notConvergedItem: 'the fit did NOT converge ({runs} model runs, {seconds} s): the values are the best reached',
  aicBic: 'information criteria: AIC = {aic}, BIC = {bic}; only for comparing fits of the same data (another model, other parameters): the lower one fits better for the parameters it uses',
  compound: 'compound pendulum (a body, not a point mass): equivalent length l_eq = I_O/(M h) = {inertia} kg m² / ({mass} kg × {centre} m) = {leq} m',
  compoundLengthHeld: "the length was held at the body's equivalent length l_eq; fit the length to test the body's measurements",
  compoundLength: "the fitted length {value} ± {err} m is {off} standard errors from the body's equivalent length l_eq",
  compoundTorque: '{param} = {value} ± {err} {unit} (the fitted value times the moment of inertia I_O)',
  'p.damping_torque': 'damping torque at the pivot',
  'p.friction_torque': 'dry friction torque at the pivot',
  'p.length': 'length l',
  'p.g': 'gravity g',
  'p.mass': 'mass m',
  'p.damping': 'friction (damping)',
  'p.drag': 'air drag',
  'p.theta0': 'start angle from the vertical',
  'p.phi0': 'start direction around the vertical',
  'p.theta_dot0': 'start speed of the swing (angle per second)',
  'p.phi_dot0': 'start speed around the vertical (angle per second)',
  'p.pivot_x': 'pivot position x',
  'p.pivot_y': 'pivot position y',
  'p.pivot_z': 'pivot position z',
  'p.t_offset': 'time offset of the data',
  'p.scale': 'scale of the positions',
  'p.angle_offset': 'zero of the angle sensor',
  'p.force_bias': 'offset of the accelerometer',
  'p.rate_bias': 'offset of the gyroscope',
  'p.perspective': 'camera perspective (1/distance)',
  'k.positions': 'positions',
  'k.horizontal': 'horizontal positions',
  'k.angles': 'angles',
  'k.planar_angle': 'swing angle',
  'k.specific_force': 'accelerometer readings',
  'k.angular_speed': 'gyroscope readings',
  'm.ideal': 'ideal pendulum',
  'm.damped': 'pendulum with friction',
  'm.rotating': 'pendulum on the turning Earth',
  'm.slewing': 'pendulum on a slewing crane',
  'm.vibrating': 'pendulum on a shaken pivot',
  'm.spring': 'swinging spring',
  notDetermined: 'not determined: {reason}',
};

const DE: Table = {
  explainsLittle: '{kind}: die angepasste Bewegung erklärt nur {percent} % der Schwankung der Daten: die Daten zeigen vielleicht kein Pendelschwingen über ihrem Rauschen, oder Modell oder Startwerte liegen weit daneben',
  correlatedNoise: '{kind}: die Abweichungen folgen aufeinander (Autokorrelation bei Abstand 1: {lag1}) wie das Rauschen einer Videoverfolgung oder eines Filters, nicht wie ein falsches Modell: die Fehlerbalken wurden dafür verbreitert',
  systematicDrift: '{kind}: die Anpassung verfehlt die Daten systematisch, mit einer langsamen Drift: die Abweichungen (rms {rms}) sind {ratio}-mal so groß wie das eigene Rauschen der Daten ({floor}). Dem Modell fehlt etwas (eine andere Art Reibung, ein bewegter Aufhängepunkt, ein falscher Maßstab), oder das Rauschen selbst ist korreliert',
  systematic: '{kind}: die Anpassung verfehlt die Daten systematisch: die Abweichungen (rms {rms}) sind {ratio}-mal so groß wie das eigene Rauschen der Daten ({floor}). Dem Modell fehlt etwas (eine andere Art Reibung, ein Sensor-Versatz, ein bewegter Aufhängepunkt, ein falscher Maßstab), oder das Rauschen selbst ist korreliert',
  correlatedSmall: '{kind}: die Abweichungen folgen aufeinander (Autokorrelation bei Abstand 1: {lag1}), sind aber nicht größer als das Rauschen der Daten: korreliertes Rauschen oder ein kleiner Effekt, der dem Modell fehlt; die Fehlerbalken wurden dafür verbreitert',
  aboveFloor: '{kind}: die Abweichungen (rms {rms}) sind {ratio}-mal so groß wie das aus den Daten abgelesene Rauschen ({floor}): das Modell passt nicht, oder das Rauschen ist nicht zufällig',
  outliers: '{kind}: {n} Werte liegen weit neben der Anpassung (mehr als {sigmas} Standardabweichungen): Ausreißer?',
  chi2Large: 'die angepasste Bewegung verfehlt die Daten um das {factor}-Fache ihres angegebenen Rauschens (chi2 = {chi2}): für ein richtiges Modell unwahrscheinlich. Dem Modell fehlt etwas (Reibung, ein bewegter Aufhängepunkt), das angegebene Rauschen ist zu klein, oder die Anpassung hängt fest (andere Startwerte versuchen)',
  chi2Small: 'chi2/dof = {reduced} ist für {dof} Freiheitsgrade unwahrscheinlich klein: das angegebene Rauschen ist zu groß, und damit auch die Fehlerbalken',
  blocksDisagree: 'die {n} Abschnitte der Aufnahme, jeder für sich angepasst, widersprechen sich: {param} = {values} (die Abschnitte zeitlich geordnet), um das {scale}-Fache ihrer Fehlerbalken auseinander. Dem Modell fehlt etwas, das sich entlang der Aufnahme ändert (Reibung, die von der Amplitude abhängt, ein driftender Sensor, ein nicht ideales Scharnier): die Fehlerbalken wurden dafür verbreitert',
  blocksTimeLimit: 'die Anpassungen des Labors enden nach {seconds} s, bevor die Prüfung gemacht war, die Anpassungen an Abschnitte der Aufnahme vergleicht: das Modell verfehlt die Daten, und die Fehlerbalken wurden dafür nicht verbreitert, sie sind also vielleicht zu schmal. Die Datendatei auf dem eigenen Rechner anpassen mit pendulab fit DATEI --time-limit none (oder pl.fit(..., time_limit=None)), oder das Labor mit einem längeren pendulab serve --fit-time-limit starten',
  blocksCtrlC: 'Strg+C hat die Anpassung angehalten, bevor die Prüfung gemacht war, die Anpassungen an Abschnitte der Aufnahme vergleicht: das Modell verfehlt die Daten, und die Fehlerbalken wurden dafür nicht verbreitert, sie sind also vielleicht zu schmal. Noch einmal anpassen und zu Ende laufen lassen',
  blocksCtrlCIn: 'Strg+C hat die Prüfung angehalten, die Anpassungen an {n} Abschnitte der Aufnahme vergleicht, bevor sie fertig war: die Fehlerbalken wurden nicht für die Abweichungen der Abschnitte verbreitert, sie sind also vielleicht zu schmal, falls das Modell die Daten verfehlt. Noch einmal anpassen und zu Ende laufen lassen',
  blocksSearchTimeLimit: 'die Anpassungen des Labors enden nach {seconds} s, was die Suche abgebrochen hat, bevor sie konvergiert war: die Abweichung kann von der unfertigen Suche kommen, nicht vom Modell. Die Prüfung, die Anpassungen an Abschnitte der Aufnahme vergleicht, wurde nicht gemacht, und die Fehlerbalken wurden dafür nicht verbreitert. Die Datendatei auf dem eigenen Rechner anpassen mit pendulab fit DATEI --time-limit none (oder pl.fit(..., time_limit=None)), oder das Labor mit einem längeren pendulab serve --fit-time-limit starten',
  blocksSearchCtrlC: 'Strg+C hat die Suche abgebrochen, bevor sie konvergiert war: die Abweichung kann von der unfertigen Suche kommen, nicht vom Modell. Die Prüfung, die Anpassungen an Abschnitte der Aufnahme vergleicht, wurde nicht gemacht, und die Fehlerbalken wurden dafür nicht verbreitert. Noch einmal anpassen und zu Ende laufen lassen',
  bandPower: '; bei {hz} Hz haben die Abweichungen das {ratio}-Fache der Leistung ihres übrigen Spektrums (p = {p}): ein Muster bei wenigen Frequenzen, kein zufälliges Rauschen',
  dampingDry: '; die an jeden Abschnitt angepasste Dämpfung wächst, während die Schwingung abklingt (sie nimmt eher linear als exponentiell ab), wie es trockene Reibung bewirkt: {param} zusätzlich anpassen',
  dampingDrag: '; die an jeden Abschnitt angepasste Dämpfung sinkt, während die Schwingung abklingt (die großen Schwingungen verlieren mehr), wie es Luftwiderstand bewirkt: {param} zusätzlich anpassen',
  stopTimeLimit: '; die Anpassungen des Labors enden nach {seconds} s, bevor die Profil-Likelihood berechnet war, die diese Fehlerbalken prüft: die Datendatei auf dem eigenen Rechner anpassen mit pendulab fit DATEI --time-limit none (oder pl.fit(..., time_limit=None))',
  stopCtrlC: '; Strg+C hat die Anpassung angehalten, bevor die Profil-Likelihood berechnet war, die diese Fehlerbalken prüft',
  stopRobust: '; die Profil-Likelihood, die diese Fehlerbalken prüft, wird mit einer robusten Verlustfunktion ({loss}) nicht berechnet: nach dem Entfernen der Ausreißer mit der linearen Verlustfunktion erneut anpassen',
  gFar: 'das angepasste g = {g} m/s² passt zu keinem Planeten (Erde: 9,81 m/s²): sind die Daten in SI-Einheiten (Meter, nicht mm oder Pixel; Sekunden; Radiant)?',
  pivotFitted: 'die Positionen hängen nicht am Ursprung: der Ort des Aufhängepunkts wurde mit angepasst',
  timeLimit: 'die Anpassung hielt an ihrer Zeitgrenze von {seconds} s an: die Werte sind die besten erreichten',
  notConverged: 'die Anpassung ist nicht konvergiert: die Werte sind die besten erreichten',
  dropped: '{n} von {total} Zeilen hatten einen fehlenden oder unendlichen Wert und wurden weggelassen',
  sorted: 'die Zeiten waren nicht aufsteigend: die Zeilen wurden sortiert',
  lengthHint: 'die Positionen liegen {radius} m vom Aufhängepunkt, das Pendel ist aber {length} m lang: sind die Positionen in Metern und stimmt der Aufhängepunkt? Die Anpassung startet mit dem Abstand aus den Daten',
  shortUndetermined: '{others} sind nicht bestimmt: die Aufnahme umfasst nur {periods} einer Schwingung (eine Periode kleiner Schwingungen dauert {period} s), zu kurz, um die Länge von g zu trennen, und die Fehlerbalken aus der Krümmung der Anpassung wären viel zu schmal. Mindestens eine ganze Schwingung aufnehmen',
  shortWidened: 'die Aufnahme umfasst nur {periods} einer Schwingung (eine Periode kleiner Schwingungen dauert {period} s): die Fehlerbalken von {others} wurden aus ihren 95-%-Profil-Likelihood-Intervallen genommen, die die Krümmung der Anpassung unterschätzt. Mindestens eine ganze Schwingung aufnehmen, um sie zu verkleinern',
  mirrorPlanar: 'die Daten passen zu einer Schwingung in einer Ebene: in der Ebene festgehalten (kein seitlicher Startwinkel und keine seitliche Startgeschwindigkeit) steigt die Abweichung nur um {rise} (die 95-%-Schwelle für beide ist {level}). Von der Seite gesehen zeigt sich die seitliche Bewegung nahe der Ebene nur schwach, deshalb wurden ihre Fehlerbalken aus dem Profil der Abweichung genommen. Eine Schwingung in einer Ebene als eben anpassen',
  mirrorWidened: 'von der Seite gesehen zeigt sich die seitliche Bewegung nahe ihrer Ebene nur schwach: die Fehlerbalken von {others} wurden aus ihren 95-%-Profil-Likelihood-Intervallen genommen, die die Krümmung der Anpassung unterschätzt',
  mirrorUndetermined: 'von der Seite gesehen ist die seitliche Bewegung nicht bestimmt ({others}): nahe ihrer Ebene zeigt sie sich nur schwach, und die Fehlerbalken aus der Krümmung der Anpassung wären zu schmal. Eine Schwingung in einer Ebene als eben anpassen',
  mirrorSignUndetermined: 'von der Seite gesehen ist die Richtung der seitlichen Bewegung nicht bestimmt: nur ein Term, den die Spiegelung y → −y ändert (ein sich drehendes Bezugssystem, ein seitlich bewegter Aufhängepunkt), unterscheidet die Bewegung von ihrem Spiegelbild, und das Spiegelbild passt ebenso gut (seine Abweichung ist nur um {rise} größer; die 95-%-Schwelle ist {level}). Auch y aufzeichnen oder eine Schwingung in einer Ebene als eben anpassen',
  notFinite: 'die Antwort des Modells darauf ist bei der Anpassung nicht endlich',
  flat: 'die Daten ändern sich damit nicht (eine Symmetrie der Daten, oder eine Rate 0 von der Seite gesehen)',
  combination: 'die Daten bestimmen nur eine Kombination mit {others}',
  shortRecord: 'eine Aufnahme von {periods} einer Schwingung bestimmt ihn nicht',
  mirrorUnchecked: 'die Anpassung endete, bevor die Fehlerbalken der seitlichen Bewegung geprüft wurden (von der Seite gesehen wären die Balken aus der Krümmung nahe der Ebene zu schmal)',
  mirrorOpen: 'von der Seite gesehen begrenzen die Daten die seitliche Bewegung nahe ihrer Ebene nicht (ihre Profil-Likelihood schließt sich nicht)',
  mirrorSign: 'von der Seite gesehen unterscheidet nur ein Term, den die Spiegelung y → −y ändert (ein sich drehendes Bezugssystem, ein seitlich bewegter Aufhängepunkt), die Bewegung von ihrem Spiegelbild, und das Spiegelbild passt ebenso gut (seine Abweichung ist nur um {rise} größer; die 95-%-Schwelle ist {level})',
  mirrorSignUnchecked: 'die Anpassung endete, bevor das Spiegelbild der Bewegung neu angepasst wurde (von der Seite gesehen unterscheidet nur ein sich drehendes Bezugssystem oder ein seitlich bewegter Aufhängepunkt die beiden)',
  lateBars: 'das Zeitlimit der Anpassung lief ab, bevor die Fehlerbalken berechnet waren',
  header: 'Anpassung des Modells „{model}“ an {samples} Messwerte ({kinds}), Beginn bei t = {t0} s',
  droppedRows: '({n} Zeilen mit fehlenden Werten wurden weggelassen)',
  combinationValue: 'stattdessen bestimmt: {label} = {value} ± {err}',
  mirror: 'die Daten können diese Bewegung nicht von ihrem Spiegelbild (y → −y) unterscheiden: die Richtung der Seitwärtsbewegung ist eine Wahl',
  mirrorSignTold: 'von der Seite gesehen bestimmen die Daten die Richtung der seitlichen Bewegung: nur ein Term, den die Spiegelung y → −y ändert (ein sich drehendes Bezugssystem, ein seitlich bewegter Aufhängepunkt), unterscheidet die Bewegung von ihrem Spiegelbild, und das Spiegelbild passt schlechter (seine Abweichung ist um {rise} größer; die Schwelle ist {threshold}, die 95-%-Schwelle {level})',
  mirrorSignNotTold: 'von der Seite gesehen bestimmen die Daten die Richtung der seitlichen Bewegung nicht: das Spiegelbild y → −y passt ebenso gut (seine Abweichung ist nur um {rise} größer; die 95-%-Schwelle ist {level})',
  mirrorSignNotChecked: 'von der Seite gesehen wurde die Richtung der seitlichen Bewegung nicht geprüft: die Anpassung endete, bevor das Spiegelbild y → −y der Bewegung neu angepasst wurde',
  planar: 'die Schwingung wurde in einer Ebene angepasst (ein Scharnier): kein seitlicher Startwinkel und keine seitliche Startgeschwindigkeit',
  residual: '{kind}: die Anpassung verfehlt die Daten um {rms} {unit} (rms); das eigene Rauschen der Daten ist etwa {floor} {unit}; Autokorrelation der Abweichungen bei Abstand 1: {lag1} (nahe 0: zufällige Abweichungen, nahe 1: Abweichungen mit Muster)',
  chi2: 'chi2/dof = {reduced} (chi2 = {chi2} bei {dof} Freiheitsgraden): die Abweichungen in Einheiten des angegebenen Rauschens; etwa 1 heißt, die Anpassung ist so nah, wie das Rauschen erlaubt, viel mehr heißt, dem Modell fehlt etwas',
  chi2Estimated: 'chi2/dof = {reduced} (chi2 = {chi2} bei {dof} Freiheitsgraden): das Rauschen wurde aus den Abweichungen selbst geschätzt, daher ist chi2/dof per Konstruktion 1 und sagt hier nichts; siehe die Zeilen darüber',
  noise: 'Rauschen der {kind}: {sigma} {unit}',
  fixed: 'festgehalten: {param} = {value} {unit}',
  converged: 'die Anpassung ist konvergiert ({runs} Modellläufe, {seconds} s)',
  notConvergedItem: 'die Anpassung ist NICHT konvergiert ({runs} Modellläufe, {seconds} s): die Werte sind die besten erreichten',
  aicBic: 'Informationskriterien: AIC = {aic}, BIC = {bic}; nur zum Vergleich von Anpassungen an dieselben Daten (ein anderes Modell, andere Parameter): die kleinere passt besser für die Zahl ihrer Parameter',
  compound: 'physikalisches Pendel (ein Körper, kein Massenpunkt): reduzierte Pendellänge l_eq = I_O/(M h) = {inertia} kg m² / ({mass} kg × {centre} m) = {leq} m',
  compoundLengthHeld: 'die Länge wurde auf der reduzierten Pendellänge l_eq des Körpers festgehalten; die Länge anpassen, um die Maße des Körpers zu prüfen',
  compoundLength: 'die angepasste Länge {value} ± {err} m liegt {off} Standardfehler von der reduzierten Pendellänge l_eq des Körpers entfernt',
  compoundTorque: '{param} = {value} ± {err} {unit} (der angepasste Wert mal dem Trägheitsmoment I_O)',
  'p.damping_torque': 'Dämpfungsmoment am Aufhängepunkt',
  'p.friction_torque': 'Reibungsmoment (trocken) am Aufhängepunkt',
  'p.length': 'Länge l',
  'p.g': 'Schwerebeschleunigung g',
  'p.mass': 'Masse m',
  'p.damping': 'Reibung (Dämpfung)',
  'p.drag': 'Luftwiderstand',
  'p.theta0': 'Startwinkel zur Senkrechten',
  'p.phi0': 'Startrichtung um die Senkrechte',
  'p.theta_dot0': 'Startgeschwindigkeit der Schwingung (Winkel pro Sekunde)',
  'p.phi_dot0': 'Startgeschwindigkeit um die Senkrechte (Winkel pro Sekunde)',
  'p.pivot_x': 'Aufhängepunkt x',
  'p.pivot_y': 'Aufhängepunkt y',
  'p.pivot_z': 'Aufhängepunkt z',
  'p.t_offset': 'Zeitversatz der Daten',
  'p.scale': 'Maßstab der Positionen',
  'p.angle_offset': 'Nullpunkt des Winkelsensors',
  'p.force_bias': 'Versatz des Beschleunigungssensors',
  'p.rate_bias': 'Versatz des Drehratensensors',
  'p.perspective': 'Kameraperspektive (1/Abstand)',
  'k.positions': 'Positionen',
  'k.horizontal': 'waagrechten Positionen',
  'k.angles': 'Winkel',
  'k.planar_angle': 'Schwingwinkel',
  'k.specific_force': 'Beschleunigungsmesswerte',
  'k.angular_speed': 'Drehratenmesswerte',
  'm.ideal': 'ideales Pendel',
  'm.damped': 'Pendel mit Reibung',
  'm.rotating': 'Pendel auf der drehenden Erde',
  'm.slewing': 'Pendel am Drehkran',
  'm.vibrating': 'Pendel an gerütteltem Aufhängepunkt',
  'm.spring': 'Schwingfeder',
  notDetermined: 'nicht bestimmt: {reason}',
};

const FR: Table = {
  explainsLittle: '{kind} : le mouvement ajusté n’explique que {percent} % de la variation des données : les données ne montrent peut-être pas d’oscillation au-dessus de leur bruit, ou le modèle ou les valeurs de départ sont très loin',
  correlatedNoise: '{kind} : les écarts se suivent (autocorrélation au pas 1 : {lag1}) comme le bruit d’un suivi vidéo ou d’un filtre, pas comme un mauvais modèle : les barres d’erreur ont été élargies en conséquence',
  systematicDrift: '{kind} : l’ajustement manque les données systématiquement, avec une lente dérive : les écarts (rms {rms}) valent {ratio} fois le bruit propre des données ({floor}). Il manque quelque chose au modèle (un autre frottement, un pivot qui bouge, une mauvaise échelle), ou le bruit lui-même est corrélé',
  systematic: '{kind} : l’ajustement manque les données systématiquement : les écarts (rms {rms}) valent {ratio} fois le bruit propre des données ({floor}). Il manque quelque chose au modèle (un autre frottement, un décalage du capteur, un pivot qui bouge, une mauvaise échelle), ou le bruit lui-même est corrélé',
  correlatedSmall: '{kind} : les écarts se suivent (autocorrélation au pas 1 : {lag1}) sans dépasser le bruit des données : bruit corrélé, ou petit effet absent du modèle ; les barres d’erreur ont été élargies en conséquence',
  aboveFloor: '{kind} : les écarts (rms {rms}) valent {ratio} fois le bruit lu dans les données ({floor}) : le modèle ne convient pas, ou le bruit n’est pas aléatoire',
  outliers: '{kind} : {n} valeurs sont loin de l’ajustement (plus de {sigmas} écarts-types) : des valeurs aberrantes ?',
  chi2Large: 'le mouvement ajusté manque les données de {factor} fois leur bruit donné (chi2 = {chi2}) : improbable pour un bon modèle. Il manque quelque chose au modèle (frottement, pivot qui bouge), le bruit donné est trop petit, ou l’ajustement est bloqué (essayer d’autres valeurs de départ)',
  chi2Small: 'chi2/dof = {reduced} est improbablement petit pour {dof} degrés de liberté : le bruit donné est trop grand, et les barres d’erreur aussi',
  blocksDisagree: 'les {n} parties de l’enregistrement, ajustées chacune seule, sont en désaccord : {param} = {values} (les parties dans l’ordre du temps), écartées de {scale} fois leurs barres d’erreur. Il manque au modèle quelque chose qui change le long de l’enregistrement (un frottement qui dépend de l’amplitude, un capteur qui dérive, une charnière imparfaite) : les barres d’erreur ont été élargies en conséquence',
  blocksTimeLimit: 'les ajustements du labo s’arrêtent après {seconds} s, avant la vérification qui compare les ajustements des parties de l’enregistrement : le modèle manque les données, et les barres d’erreur n’ont pas été élargies en conséquence, elles sont donc peut-être trop étroites. Ajuster le fichier de données sur votre ordinateur avec pendulab fit FICHIER --time-limit none (ou pl.fit(..., time_limit=None)), ou lancer le labo avec un pendulab serve --fit-time-limit plus long',
  blocksCtrlC: 'Ctrl-C a arrêté l’ajustement avant la vérification qui compare les ajustements des parties de l’enregistrement : le modèle manque les données, et les barres d’erreur n’ont pas été élargies en conséquence, elles sont donc peut-être trop étroites. Ajuster à nouveau et le laisser finir',
  blocksCtrlCIn: 'Ctrl-C a arrêté la vérification qui compare les ajustements des {n} parties de l’enregistrement avant sa fin : les barres d’erreur n’ont pas été élargies pour le désaccord des parties, elles sont donc peut-être trop étroites si le modèle manque les données. Ajuster à nouveau et le laisser finir',
  blocksSearchTimeLimit: 'les ajustements du labo s’arrêtent après {seconds} s, ce qui a interrompu la recherche avant sa convergence : l’écart peut venir de la recherche inachevée, pas du modèle. La vérification qui compare les ajustements des parties de l’enregistrement n’a pas été faite et les barres d’erreur n’ont pas été élargies en conséquence. Ajuster le fichier de données sur votre ordinateur avec pendulab fit FICHIER --time-limit none (ou pl.fit(..., time_limit=None)), ou lancer le labo avec un pendulab serve --fit-time-limit plus long',
  blocksSearchCtrlC: 'Ctrl-C a interrompu la recherche avant sa convergence : l’écart peut venir de la recherche inachevée, pas du modèle. La vérification qui compare les ajustements des parties de l’enregistrement n’a pas été faite et les barres d’erreur n’ont pas été élargies en conséquence. Ajuster à nouveau et le laisser finir',
  bandPower: ' ; vers {hz} Hz, les écarts ont {ratio} fois la puissance du reste de leur spectre (p = {p}) : un motif à quelques fréquences, pas un bruit aléatoire',
  dampingDry: ' ; l’amortissement ajusté à chaque partie croît à mesure que l’oscillation s’éteint (elle décroît plus linéairement qu’exponentiellement), comme le fait un frottement sec : ajuster aussi {param}',
  dampingDrag: ' ; l’amortissement ajusté à chaque partie diminue à mesure que l’oscillation s’éteint (les grandes oscillations perdent plus), comme le fait la résistance de l’air : ajuster aussi {param}',
  stopTimeLimit: ' ; les ajustements du labo s’arrêtent après {seconds} s, avant le calcul de la vraisemblance profilée qui vérifie ces barres d’erreur : ajuster le fichier de données sur votre ordinateur avec pendulab fit FICHIER --time-limit none (ou pl.fit(..., time_limit=None))',
  stopCtrlC: ' ; Ctrl-C a arrêté l’ajustement avant le calcul de la vraisemblance profilée qui vérifie ces barres d’erreur',
  stopRobust: ' ; la vraisemblance profilée qui vérifie ces barres d’erreur n’est pas calculée avec une perte robuste ({loss}) : ajuster de nouveau avec la perte linéaire une fois les valeurs aberrantes retirées',
  gFar: 'le g ajusté = {g} m/s² ne correspond à aucune planète (Terre : 9,81 m/s²) : les données sont-elles en unités SI (mètres, pas mm ni pixels ; secondes ; radians) ?',
  pivotFitted: 'les positions ne pendent pas de l’origine : la position du pivot a aussi été ajustée',
  timeLimit: 'l’ajustement s’est arrêté à sa limite de {seconds} s : les valeurs sont les meilleures atteintes',
  notConverged: 'l’ajustement n’a pas convergé : les valeurs sont les meilleures atteintes',
  dropped: '{n} lignes sur {total} avaient une valeur manquante ou infinie et ont été écartées',
  sorted: 'les temps n’étaient pas croissants : les lignes ont été triées',
  lengthHint: 'les positions sont à {radius} m du pivot, mais le pendule mesure {length} m : les positions sont-elles en mètres et le pivot est-il juste ? L’ajustement part de la distance des données',
  shortUndetermined: '{others} ne sont pas déterminés : l’enregistrement ne couvre que {periods} d’une oscillation (une période des petites oscillations dure {period} s), trop peu pour séparer la longueur de g, et les barres d’erreur tirées de la courbure de l’ajustement seraient bien trop étroites. Enregistrer au moins une oscillation complète',
  shortWidened: 'l’enregistrement ne couvre que {periods} d’une oscillation (une période des petites oscillations dure {period} s) : les barres d’erreur de {others} ont été prises de leurs intervalles de vraisemblance profilée à 95 %, que la courbure de l’ajustement sous-estime. Enregistrer au moins une oscillation complète pour les réduire',
  mirrorPlanar: 'les données sont compatibles avec une oscillation dans un plan : maintenue dans le plan (sans angle ni vitesse latérale au départ), l’écart n’augmente que de {rise} (le seuil à 95 % pour les deux est {level}). Vu de côté, le mouvement latéral ne se voit que faiblement près du plan, et ses barres d’erreur ont été prises du profil de l’écart. Ajuster l’oscillation comme plane si elle oscille dans un plan',
  mirrorWidened: 'vu de côté près de son plan, le mouvement latéral ne se voit que faiblement : les barres d’erreur de {others} ont été prises de leurs intervalles de vraisemblance profilée à 95 %, que la courbure de l’ajustement sous-estime',
  mirrorUndetermined: 'vu de côté, le mouvement latéral n’est pas déterminé ({others}) : près de son plan, il ne se voit que faiblement, et les barres d’erreur tirées de la courbure de l’ajustement seraient trop étroites. Ajuster l’oscillation comme plane si elle oscille dans un plan',
  mirrorSignUndetermined: 'vu de côté, le sens du mouvement latéral n’est pas déterminé : seul un terme que la symétrie y → −y change (un référentiel en rotation, un point de suspension qui se déplace latéralement) distingue le mouvement de son image miroir, et l’image miroir s’ajuste aussi bien (son écart n’est plus grand que de {rise} ; le seuil à 95 % est {level}). Enregistrer aussi y, ou ajuster l’oscillation comme plane si elle oscille dans un plan',
  notFinite: 'la réponse du modèle n’est pas finie à l’ajustement',
  flat: 'les données ne changent pas avec lui (une symétrie des données, ou une vitesse nulle vue de côté)',
  combination: 'les données ne déterminent qu’une combinaison avec {others}',
  shortRecord: 'un enregistrement de {periods} d’une oscillation ne le détermine pas',
  mirrorUnchecked: 'l’ajustement s’est arrêté avant que les barres d’erreur du mouvement latéral soient vérifiées (vu de côté près du plan, les barres tirées de la courbure seraient trop étroites)',
  mirrorOpen: 'vu de côté près de son plan, les données ne bornent pas le mouvement latéral (sa vraisemblance profilée ne se referme pas)',
  mirrorSign: 'vu de côté, seul un terme que la symétrie y → −y change (un référentiel en rotation, un point de suspension qui se déplace latéralement) distingue le mouvement de son image miroir, et l’image miroir s’ajuste aussi bien (son écart n’est plus grand que de {rise} ; le seuil à 95 % est {level})',
  mirrorSignUnchecked: 'l’ajustement s’est arrêté avant que l’image miroir du mouvement soit réajustée (vu de côté, seul un référentiel en rotation ou un point de suspension qui se déplace latéralement distingue les deux)',
  lateBars: 'la limite de temps de l’ajustement a expiré avant le calcul des barres d’erreur',
  header: 'ajustement du modèle « {model} » à {samples} mesures ({kinds}), début à t = {t0} s',
  droppedRows: '({n} lignes avec des valeurs manquantes ont été écartées)',
  combinationValue: 'déterminé à la place : {label} = {value} ± {err}',
  mirror: 'les données ne distinguent pas ce mouvement de son image miroir (y → −y) : le sens du mouvement latéral est un choix',
  mirrorSignTold: 'vu de côté, les données déterminent le sens du mouvement latéral : seul un terme que la symétrie y → −y change (un référentiel en rotation, un point de suspension qui se déplace latéralement) distingue le mouvement de son image miroir, et l’image miroir s’ajuste moins bien (son écart est plus grand de {rise} ; le seuil est {threshold}, le seuil à 95 % {level})',
  mirrorSignNotTold: 'vu de côté, les données ne déterminent pas le sens du mouvement latéral : l’image miroir y → −y s’ajuste aussi bien (son écart n’est plus grand que de {rise} ; le seuil à 95 % est {level})',
  mirrorSignNotChecked: 'vu de côté, le sens du mouvement latéral n’a pas été vérifié : l’ajustement s’est arrêté avant que l’image miroir y → −y du mouvement soit réajustée',
  planar: 'l’oscillation a été ajustée dans un plan (une charnière) : ni angle ni vitesse latérale au départ',
  residual: '{kind} : l’ajustement manque les données de {rms} {unit} (rms) ; le bruit propre des données est d’environ {floor} {unit} ; autocorrélation des écarts au pas 1 : {lag1} (près de 0 : écarts aléatoires, près de 1 : écarts qui suivent un motif)',
  chi2: 'chi2/dof = {reduced} (chi2 = {chi2} pour {dof} degrés de liberté) : les écarts mesurés en unités du bruit donné ; environ 1 signifie que l’ajustement est aussi proche que le bruit le permet, beaucoup plus qu’il manque quelque chose au modèle',
  chi2Estimated: 'chi2/dof = {reduced} (chi2 = {chi2} pour {dof} degrés de liberté) : le bruit a été estimé à partir des écarts eux-mêmes, donc chi2/dof vaut 1 par construction et ne dit rien ici ; voir les lignes au-dessus',
  noise: 'bruit des {kind} : {sigma} {unit}',
  fixed: 'fixé : {param} = {value} {unit}',
  converged: 'l’ajustement a convergé ({runs} calculs du modèle, {seconds} s)',
  notConvergedItem: 'l’ajustement n’a PAS convergé ({runs} calculs du modèle, {seconds} s) : les valeurs sont les meilleures atteintes',
  aicBic: 'critères d’information : AIC = {aic}, BIC = {bic} ; seulement pour comparer des ajustements des mêmes données (un autre modèle, d’autres paramètres) : le plus petit s’ajuste mieux pour le nombre de ses paramètres',
  compound: 'pendule pesant (un corps, pas un point matériel) : longueur équivalente l_eq = I_O/(M h) = {inertia} kg m² / ({mass} kg × {centre} m) = {leq} m',
  compoundLengthHeld: 'la longueur a été fixée à la longueur équivalente l_eq du corps ; ajuster la longueur pour vérifier les mesures du corps',
  compoundLength: 'la longueur ajustée {value} ± {err} m est à {off} erreurs types de la longueur équivalente l_eq du corps',
  compoundTorque: '{param} = {value} ± {err} {unit} (la valeur ajustée fois le moment d’inertie I_O)',
  'p.damping_torque': 'couple d’amortissement au point de suspension',
  'p.friction_torque': 'couple de frottement sec au point de suspension',
  'p.length': 'longueur l',
  'p.g': 'pesanteur g',
  'p.mass': 'masse m',
  'p.damping': 'frottement (amortissement)',
  'p.drag': 'résistance de l’air',
  'p.theta0': 'angle de départ par rapport à la verticale',
  'p.phi0': 'direction de départ autour de la verticale',
  'p.theta_dot0': 'vitesse de départ de l’oscillation (angle par seconde)',
  'p.phi_dot0': 'vitesse de départ autour de la verticale (angle par seconde)',
  'p.pivot_x': 'position du pivot x',
  'p.pivot_y': 'position du pivot y',
  'p.pivot_z': 'position du pivot z',
  'p.t_offset': 'décalage temporel des données',
  'p.scale': 'échelle des positions',
  'p.angle_offset': 'zéro du capteur d’angle',
  'p.force_bias': 'décalage de l’accéléromètre',
  'p.rate_bias': 'décalage du gyroscope',
  'p.perspective': 'perspective de la caméra (1/distance)',
  'k.positions': 'positions',
  'k.horizontal': 'positions horizontales',
  'k.angles': 'angles',
  'k.planar_angle': 'angle d’oscillation',
  'k.specific_force': 'mesures de l’accéléromètre',
  'k.angular_speed': 'mesures du gyroscope',
  'm.ideal': 'pendule idéal',
  'm.damped': 'pendule avec frottement',
  'm.rotating': 'pendule sur la Terre qui tourne',
  'm.slewing': 'pendule sur une grue pivotante',
  'm.vibrating': 'pendule à pivot secoué',
  'm.spring': 'ressort oscillant',
  notDetermined: 'non déterminé : {reason}',
};

/** Every language's table (the keys of EN in each: tests/unit/fitwords.test.ts). */
export const FIT_WORDS: Record<Lang, Table> = { en: EN, de: DE, fr: FR };

type FitLine = KeyedLine;

function look(key: string): string | undefined {
  const own = FIT_WORDS[language()][key];
  return own ?? EN[key];
}

/** A fitted parameter's name for a student: this table's, else the model registry's label, else the name. */
export function fitParamName(name: string): string {
  return look(`p.${name}`) ?? paramWords(name, name, '')[0];
}

/** A data kind (positions, angles, …) in words. */
export function fitKindName(kind: string): string {
  return look(`k.${kind}`) ?? kind;
}

/** A model in words. */
export function fitModelName(model: string): string {
  return look(`m.${model}`) ?? modelWords(model, model);
}

/** A value of a line in words: code names of kinds, parameters, models and combinations translated. */
function worded(name: string, value: string): string {
  const params = (s: string) => s.replace(/[A-Za-z_][A-Za-z_0-9]*/g, (n) => (look(`p.${n}`) !== undefined ? fitParamName(n) : n));
  if (name === 'kind') return fitKindName(value);
  if (name === 'kinds') return value.split(',').map(fitKindName).join(', ');
  if (name === 'param') return fitParamName(value);
  if (name === 'model') return fitModelName(value);
  if (name === 'others') return value.split(/,\s*/).map(fitParamName).join(', ');
  if (name === 'label') return params(value);
  return value;
}

/** A keyed line in the page's language, followed by its keyed clauses (each table's clause words begin
 *  with their own separator); a line without a known key as the server's English text (with its clauses). */
export function fitLine(line: FitLine): string {
  const words = line.key === null ? undefined : look(line.key);
  if (words === undefined) return line.text ?? line.key ?? '';
  const own = words.replace(/\{(\w+)\}/g, (m, name: string) => {
    const v = line.values[name];
    return v === undefined ? m : worded(name, v);
  });
  return own + (line.clauses ?? []).map((c) => (c.key !== null && look(c.key) !== undefined ? fitLine(c) : '')).join('');
}

/** A fitted parameter as a line: `name = value ± error unit`, or why the data do not determine it. */
export function fitParamLine(name: string, p: FittedParam): string {
  const unit = p.unit && p.unit !== '1' ? ` ${p.unit}` : '';
  const value = `${fitParamName(name)} = ${p.value.toPrecision(6)}`;
  if (p.determined && p.stderr !== null) return `${value} ± ${p.stderr.toPrecision(2)}${unit}`;
  const reason = readKeyed(p.reason);
  const why = reason === null ? '' : fitLine(reason);
  return `${value}${unit} (${fitLine({ key: 'notDetermined', values: { reason: why } })})`.replace(/\s*:\s*\)$/, ")");
}

/** The report in the page's language: its header, the fitted parameters, then its other lines. */
export function fitReportLines(items: readonly KeyedLine[], params: Readonly<Record<string, FittedParam>>): string[] {
  const [head, ...rest] = items;
  const lines = head === undefined ? [] : [fitLine(head)];
  lines.push(...Object.entries(params).map(([name, p]) => `  ${fitParamLine(name, p)}`));
  lines.push(...rest.map((l) => `  ${fitLine(l)}`));
  return lines;
}
