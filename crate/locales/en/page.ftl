# The page's own words (panels, buttons, hints, status). The labs' words (titles, parameters,
# series) come from the labs themselves. Every message here has its Russian twin in
# ../ru/page.ftl; a test fails when one is missing on either side.

app-title = Attitude Lab
language = Language
lab = Lab

## Run controls
play = ▶ Play
pause = Pause
step = Step
reset = ⟲ Reset
reset-hint = Restart at t = 0 with the seed below
presenter = Presenter
presenter-hint = For a projector: large type, thick lines, the presets only (also `presenter=1` in the link)
light = Light
light-hint = Light panels in dark type, for a projector (the default in presenter mode; also `theme=light` or `theme=dark` in the link)
seed = Seed
new-seed = New seed
new-seed-hint = A random seed, then Reset
speed = speed ×

## Parameters
presets = Presets:
preset-hint = { $help } — parameters marked "applies at Reset" need Reset
all-parameters = All parameters
parameters = Parameters
defaults = defaults
applies-at-reset = { $help } (applies at Reset)
waiting-for-reset = Waiting for Reset: { $names }.
reset-now = Reset now
reset-now-hint = Restart from t = 0 with these values

## Outputs
ghost = 3D ghost
export-csv = Export CSV
export-csv-hint = Every series at every step since t = 0 (the run is re-simulated exactly; empty cells are missing samples)
copy-link = Copy link
copy-link-hint = A link that restores lab, seed, speed and parameters
copy-python = Copy as Python
copy-python-hint = A pandas + matplotlib snippet that loads the exported CSV and draws the plot tab on screen
png-plots = PNG of the plots
png-plots-hint = Every plot tab at this instant, one below the other, in one PNG (key p). A view shows its own PNG button when the pointer is over it.
export-output = Export the paper's output file
export-output-hint = The paper's own rows (t, angle₁, angle₂, angle₃), re-run from t = 0 with the current parameters, ending at the first row within tolerance
png = PNG
png-view-hint = Save this view as a PNG (key p while it is shown alone)

## Help
what-am-i-looking-at = What am I looking at?
keys-help = Keys: space pause/resume · r reset · s single step · ←/→ plot tab · in a lesson PageDown/PageUp or →/← next/previous step, Shift+←/→ plot tab · f one view at full size (repeat for the next view, then the plots alone, then all) · p PNG of the view shown alone, else of every plot tab · ? or F1 every key (Tab moves between the controls)
frames-help = Frames: reference ζ up; body ξ′ right, η′ forward, ζ′ up. The sphere shows the vertical k = (a′, b′, c′) in body axes; the ray from the pole S through k meets the body plane at w = u + jv = (a′ + jb′)/(1 + c′). |w| = 1 is pitch ±90°; w → ∞ is upside down, where the (u, v, z) integrator switches to s = 1/w.

## A narrow screen
controls = Controls
controls-hint = The parameters, presets and exports, in a sheet below
view = View:
close = Close

## The plots
estimators = Estimators:
estimators-menu = Estimators
more-estimators = +{ $n } more…
chip-hide-hint = { $name } — click to hide it everywhere
chip-show-hint = { $name } — click to show it everywhere
more = More…
more-with = More: { $title }
log10 = log10
bands = ±3σ bands
outages = shade outages
replay-gaps = no logged sample (a gap or a restart of the log's clock)
outages-hint = Shade the intervals where a sensor gives nothing (every plot)
axis-time = t [s]
axis-mixed-units = mixed units (see the legend)
axis-value = value
axis-of-deg = angle
axis-of-deg-s = angular rate
axis-of-rad = angle
axis-of-rad-s = angular rate
axis-of-nT = field
axis-of-s = time
axis-of-rad-s2 = angular acceleration
axis-of-deg-s2 = angular acceleration
axis-of-N-m-s = angular momentum
axis-of-1-s2 = disturbance
axis-of-N = force
axis-of-J = energy
axis-attitude = angle
axis-rate = angular rate
axis-error = error
axis-covariance = covariance
axis-innovation = innovation
bands-legend = ±3σ of the filter's own covariance
legend-no-data = no values recorded
legend-no-positive = no values above 0 to draw on a log scale

## The views
view-body3d = 3D body
view-sphere = Riemann sphere
view-wplane = w plane
view-dial = Dial
view-phase = Phase portrait
truth = truth
body-truth = truth (solid)
body-ghost = estimate (ghost): { $label }
body-no-truth = no truth: a log holds only readings
body-estimate = estimate (solid): { $label }
body-hint = drag: orbit · wheel or pinch: zoom · double-click: reset · x red, y green, z blue
body-hint-touch = drag: turn · pinch: zoom · x red, y green, z blue
sphere-title = Riemann sphere: vertical k in body axes
chart-all-w = every filter in chart w (from S)
chart-w-rest = { $n ->
    [one] { $n } other in chart w (from S)
   *[other] { $n } others in chart w (from S)
}
chart-s = chart s = 1/w (upside down): { $ids }
dial-title = Angle on a dial (0° up)

## The status line
job-reselect = Re-running the simulation for this plot
job-export-csv = Exporting every sample as CSV
job-progress = { $what } · { $percent } %
job-holds = the simulation holds meanwhile
stop = Stop
status-short = t = { $t } s · ×{ $realtime } real time (×{ $asked } asked)
status-long = t = { $t } s · step { $step } ms · { $rate } steps/s · { $realtime } real time (×{ $asked } asked) · frame { $frame } ms · sim { $sim } ms/frame · recorder { $mib } MiB ({ $series } series, whole run)
behind = · behind real time: lower the speed
diverged = · { $id } diverged: { $why } (press Reset)
unobservable = · { $id } unobservable: { $why }
diverged-many = · { $n } filters diverged: which and why… (press Reset)
unobservable-many = · { $n } filters unobservable: which and why…

## Why a filter is in trouble (after "diverged:" or "unobservable:")
trouble-not-finite = the state or the covariance is not finite (NaN or ∞)
trouble-sensitivity-not-finite = Λ, U or p is not finite
trouble-innovation-not-positive = update refused: H P Hᵀ + R is not positive definite (a degenerate geometry?)
trouble-measurement-not-finite = update refused: the measurement or the result is not finite
trouble-lost-definiteness = the covariance lost positive definiteness: R is too small beside P for double precision
trouble-attitude-lost = attitude 2σ { $sigma }° (over { $limit }°): the filter has lost the attitude
trouble-angle-ran-away = the angle ran { $deg }° away from the integrated gyro angle (the adaptation is unstable here)
trouble-singular-sensitivity = UᵀQU is singular: raise ε (method 10)
trouble-sun-along-field = sun and field within { $deg }° of parallel: the rotation about them is not observed

## The plot tabs of series groups
group-time = Time
group-attitude = Attitude
group-rate = Rates
group-error = Errors
group-covariance = Covariance
group-innovation = Innovation
group-sphere = (u, v) and vertical
group-lab = Lab

## The keyboard dialog (key ? or F1)
keys-button = Keys (?)
keys-button-hint = Every key of the page: moving between controls, sliders, the run (also ? or F1)
keys-title = Keyboard
keys-intro = Every control is reached with Tab. A yellow or blue ring shows which one has the keyboard.
keys-tab = Tab, Shift+Tab
keys-tab-does = the next, the previous control
keys-activate = Enter, Space
keys-activate-does = press the button, tick the box, open the list
keys-slider-arrows = ← → (↓ ↑) on a slider
keys-slider-arrows-does = a twentieth of its range; with Shift a hundredth
keys-slider-pages = PageUp, PageDown
keys-slider-pages-does = a tenth of the slider's range
keys-slider-ends = Home, End
keys-slider-ends-does = the slider's least, greatest value
keys-escape = Esc
keys-escape-does = leave the control (the keys below work again); close this dialog
keys-space = Space
keys-space-does = pause, resume (when no control has the keyboard)
keys-reset = r
keys-reset-does = reset: t = 0 with the same seed
keys-step = s
keys-step-does = one step, paused
keys-tabs = ← → (in a lesson Shift+← →)
keys-tabs-does = the previous, the next plot tab (when no control has the keyboard)
keys-lesson = PageDown or →, PageUp or ← in a lesson
keys-lesson-does = the next, the previous step of the lesson (the keys a presenter's clicker sends)
keys-full = f
keys-full-does = one view at full size (again: the next view, the plots alone, everything)
keys-png = p
keys-png-does = a PNG of the view shown alone, else of every plot tab

## The live description a screen reader reads (every 10 s while running, at once on a pause)
live-run = { $lab } — t = { $t } s, { $state }.
live-running = running at ×{ $speed }
live-paused = paused
live-within = { $name }: attitude error { $error }°, within its 3σ band of { $band }°.
live-outside = { $name }: attitude error { $error }°, outside its 3σ band of { $band }°.
live-error = { $name }: attitude error { $error }°.
live-no-truth = { $name }: no true attitude to compare with (a replayed log).

## The live accuracy table (paper 2)
accuracy-help = σ: largest per-axis RMS error against the truth over the last { $covered } s of { $window } s (mean included); √P: the filter's own √max diag P now (the paper's metric). Click a row to show that filter as the ghost.
accuracy-filter = filter
accuracy-att = σ att °
accuracy-att-p = √P att °
accuracy-paper-att = paper °
accuracy-rate = σ rate °/s
accuracy-rate-p = √P rate °/s
accuracy-paper-rate = paper °/s
accuracy-tab-all = all filters
accuracy-tab-table = Table { $n }

## The laboratory mode
replay-example = Replay the example log
replaying = replaying { $name } ({ $n } samples)
back-to-simulation = Back to simulation

## The sweeps
sweep-title = Sweep: { $title }
cancel = Cancel
sweep-run = Run sweep
sweep-run-hint = One run per value and seed with the current parameters; the page stays live
sweep-run-log = Run sweep on the log
sweep-run-log-hint = One run per value over the replayed log (no truth: the log's own scores)
sweep-size = { $cells } values × { $seeds ->
    [one] { $seeds } seed
   *[other] { $seeds } seeds
}
sweep-size-grid = { $cells } cells × { $seeds ->
    [one] { $seeds } seed
   *[other] { $seeds } seeds
}
sweep-each = { $s } s each
sweep-workers = { $n ->
    [one] in 1 background worker
   *[other] in { $n } background workers
}
sweep-on-log = on the replayed log
sweep-diverged = { $at }: a filter diverged (missing samples)
sweep-unscored = { $at }: not scored: { $why }
sweep-skipped = skipped: { $why }
sweep-best = best for { $series }: { $param } = { $value } ({ $rms } rms)
sweep-max-axis = log10 max |value|
sweep-objective-axis = objective
sweep-argmin = argmin of { $name } over this sweep's { $n } values: { $at }
sweep-argmin-marker = argmin { $name }
sweep-cell-range = { $value }: the median of { $n } runs, which range from { $lo } to { $hi }
sweep-heat-needs = A heat map needs at least two positive values on each axis.
sweep-heat-colour = colour: log10 { $name }, from { $lo } (dark) to { $hi } (bright). Optimum: { $at } ({ $name } = { $best }).
sweep-heat-filling = colour: log10 { $name }; cells fill in as the sweep runs.
sweep-optimum = optimum

## Messages about what the page did
msg-no-example-log = this lab ships no example log
msg-python-copied = copied: a Python snippet that loads the exported CSV and draws this plot
msg-no-logs = this lab replays no logs
msg-no-logs-named = { $name }: this lab replays no logs
msg-log-skipped = { $name }: skipped { $why }
msg-log-more-bad = { $name }: … and { $n } more bad lines
msg-log-replaying = { $name }: replaying { $n } samples of { $lines } lines ({ $reordered } put back in order, { $merged } merged, { $rejected } rejected; clock gaps: { $gaps })
msg-log-failed = { $name }: { $why }
msg-picker-refused = the browser opened no file window: it opens one only right after a click or a key press. Press the load button again.
msg-file-unreadable = cannot read { $name }: { $why }
msg-workers-failed = sweep workers stopped ({ $why }); the sweep goes on in slices on the page's thread

## A log line that could not be used (in "skipped …"), and why; the same facts the CLI prints
log-line = line { $line }: { $reason }: `{ $text }`
log-fault-columns = expected { $expected } columns ({ $names }), found { $found }
log-fault-columns-merged = expected { $expected } columns ({ $names }), found { $found } (two lines merged?)
log-fault-before-data = before the data (a sketch's banner?)
log-fault-not-a-number = not a number: `{ $text }`
log-fault-not-utf8 = not UTF-8 text: byte { $byte } at column { $column }
log-fault-not-a-word = `{ $raw }` is not a { $bits }-bit word (0 … { $max })
log-fault-time-glitch = time glitch: { $t } s between { $last } s and the lines after it
log-fault-duplicate = same time as line { $line }: a duplicate of it
log-fault-averaged = same time as line { $line }: averaged with it
log-fault-out-of-order = out of order: put before line { $line }

## Why a whole log cannot be replayed; the same facts the CLI prints
log-refused-not-replayed = lab { $lab } does not replay logs; these do: { $labs }
log-refused-width = { $lines } lines have { $width } numbers and { $own } have { $columns }: lab { $lab } reads { $format }, { $columns } numbers a line.
log-refused-width-like = { $lines } lines have { $width } numbers and { $own } have { $columns }: lab { $lab } reads { $format }, { $columns } numbers a line. It looks like { $other } (read by { $count ->
        [one] lab
       *[other] labs
    } { $labs }).
log-refused-few = the log needs at least two samples with increasing times ({ $kept } samples kept of { $lines } lines ({ $reordered } reordered), { $merged } merged, { $rejected } rejected)
log-refused-few-first = the log needs at least two samples with increasing times ({ $kept } samples kept of { $lines } lines ({ $reordered } reordered), { $merged } merged, { $rejected } rejected; first bad line: { $first })
log-refused-accel = the accelerometer reads a median of { $g } g where about 1 g is expected: its unit does not fit (the unit `{ $unit }` gives { $gives } g)

## Live sensors (a phone's gyro and accelerometer, an Arduino over Web Serial)
live-title = Live sensors
live-help = The filters run on this phone's gyro and accelerometer, or on an Arduino's MPU-6050 over USB, as the samples arrive. Phone: hold it flat, screen up, top edge forward; roll it about its long axis — that is the lab's x axis and roll φ. Arduino: the sketch prints lines `time, ax, ay, az, gx, gy, gz` in the units chosen above. Needs https:// or localhost.
live-phone = Use this phone's sensors
live-serial = Arduino over USB (Web Serial)
live-baud = baud
live-phone-source = phone
live-serial-source = serial port at { $baud } baud
live-rate = { $rate } samples/s
live-ended = stream ended
live-status = { $source } · { $api } · { $state } · { $n } lines recorded, { $rejected } rejected
live-zero = Zero: the pose held now is level
live-stop = Stop
live-save = Save record (CSV)
live-no-detail = no detail given
live-why-permission-denied = the motion sensors' permission was denied
live-why-sensor-error = the motion sensors failed: { $detail }
live-why-no-motion = this browser has no motion sensors
live-why-no-serial = this browser has no Web Serial (Chrome, Edge and Opera on a computer; Firefox from 151)
live-why-no-port = no port chosen ({ $detail })
live-why-cannot-open = cannot open the port: { $detail }
live-why-unplugged = the device was unplugged
live-why-closed = the device closed the stream
live-why-stopped = the source stopped
live-why-script = the page's sensor script failed: { $detail }
live-why-desktop-phone = live sensors run in the web page (a phone's browser)
live-why-desktop-serial = Web Serial runs in the web page (Chrome or Edge on a computer)
live-why-tap-again = tap the page once more to allow the motion sensors
live-why-read-error = serial read error, reading on: { $detail }
msg-live-failed = live sensors: { $why }
msg-live-waiting = live sensors: waiting for the first samples…
msg-live-zeroed = live sensors: the pose held now is level (later samples are turned by it)
msg-live-stalled = live sensors: no samples for { $s } s (the run waits; nothing is lost)
msg-live-dropped = live sensors: { $n } samples dropped while the page was not drawing
msg-live-ended = live sensors: the stream ended ({ $why }); { $n } good lines are kept in the record
msg-live-none = no live session to save
msg-live-record-saved = { $n } good lines; attlab replay reads it to the same estimates
msg-export-failed = export failed: { $why }
msg-export-busy = an export is under way: one at a time
msg-no-output-file = this lab has no output file of its paper
msg-output-rows = { $n } rows
msg-output-rows-stopped = { $n } rows, to the first row within tolerance
msg-csv-rows = { $n } rows, every sample, re-run from t = 0
msg-plot-failed = cannot show this plot: { $why }
msg-plots-lost = the plots lost their history: { $why }
msg-rerun-took = re-ran { $t } s of simulation for this plot in { $ms } ms
msg-preset-applied = preset { $name } applied
msg-preset-waits = preset { $name }: some values apply at Reset
msg-locked-kept = locked by the teacher's link, kept as it was: { $names }
locked-hint = Locked by the teacher's link: presets, “defaults” and the lesson's steps leave it as it is.
a11y-dot = dot
a11y-double-dot = double dot
a11y-resize-panel = Resize panel
msg-png-lab-changed = PNG export stopped: the lab changed
msg-png-busy = a PNG is being made already: one at a time
msg-png-failed = PNG export failed: { $why }
png-why-no-picture = no picture from the renderer after { $n ->
    [one] { $n } frame
   *[other] { $n } frames
} (this renderer cannot take screenshots)
png-why-off-screen = the part to capture is not on screen
png-why-empty = nothing to save: the picture is { $w }×{ $h } pixels
png-why-too-large = the picture is too large: { $w }×{ $h } pixels
png-why-encoder = the PNG encoder: { $detail }
saved-downloaded = { $name } downloaded
saved-written = saved { $path }
saved-cancelled = save cancelled
save-refused = the browser refused the download: { $detail }
save-cannot-write = cannot write { $path }: { $error }
msg-png-saved = { $saved } ({ $w }×{ $h } pixels)

## A link's bad items, shown at the top of the page
link-problems = This link had items the page could not use; the rest of it is applied:
link-dismiss = Dismiss
link-bad = Link item { $item }: { $why } — ignored.
link-unknown = Link item { $item }: this lab has no such setting — ignored.
link-unknown-near = Link item { $item }: this lab has no such setting; did you mean “{ $label }”? — ignored.
link-not-a-number = Link item { $item }: “{ $label }” needs a number — kept at { $kept }.
link-out-of-range = Link item { $item }: “{ $label }” goes from { $range } — kept at { $kept }.
link-not-whole = Link item { $item }: “{ $label }” takes a whole number — kept at { $kept }.
link-no-option = Link item { $item }: “{ $label }” is one of: { $range } — kept at { $kept }.
link-malformed = Link item { $item }: not of the form name=value — ignored.
link-fault-no-such-lab = no such lab (labs: { $ids })
link-fault-no-such-lesson = no such lesson (lessons: { $ids })
link-fault-step-without-lesson = step needs a lesson (lesson=<lab>)
link-fault-no-such-step = step must be a whole number 1–{ $steps }
link-fault-not-key-value = expected key=value
link-fault-seed = seed must be a whole number ≥ 0
link-fault-speed = speed must be between { $lo } and { $hi }
link-fault-presenter = presenter must be 1 or 0
link-fault-theme = theme must be light or dark
link-fault-lang = lang must be en or ru
link-fault-embed = embed must be 1 or 0
link-fault-origin = `{ $text }` is not a web origin (like https://example.org or http://127.0.0.1:8000, or *)
link-fault-at = at must be a time in seconds ≥ 0
link-fault-what-if = `{ $text }` is not a what-if: a time in seconds, then the changes (like 1390:q_scale=0.1,x=2)
link-fault-too-many-what-ifs = at most { $most } what-ifs
link-fault-answers-without-lesson = answers need a lesson (lesson=<lab>)
link-fault-no-lesson = this lab has no lesson
link-fault-not-an-answer = `{ $part }` is not a step number and an answer letter (like 2b)
link-fault-no-such-answer = step { $step } has no answer { $letter }
link-fault-not-a-parameter = `{ $key }` is not a parameter of { $lab } (or `all`)

## A value a slider or a log's unit choice refused (the run goes on unchanged)
param-out-of-range = “{ $label }” goes from { $range }; { $given } is outside it — unchanged.
param-not-a-number = “{ $label }” needs a number; “{ $given }” is not one — unchanged.
param-not-finite = “{ $label }” needs a finite number — unchanged.
param-not-whole = “{ $label }” takes a whole number; { $given } is not one — unchanged.
param-no-option = “{ $label }” is one of: { $range }; “{ $given }” names none of them — unchanged.
param-unknown = This lab has no setting “{ $key }”.
param-malformed = “{ $text }” is not of the form name=value.

## The command line's `attlab labs --lang`
cli-paper = paper
cli-default = default

## Words drawn in the views
sphere-pole = S (pole of w)
phase-title = Phase portrait: rate against angle (the recent trail)
phase-angle = angle [°]
phase-rate = rate [°/s]
body-unobservable = unobservable axis
body-orbit = orbit
body-shadow = shadow
body-no-gpu = 3D view needs the wgpu renderer

## Zoom and its way back
plot-reset-hint = Show the whole run again (the wheel zooms about the pointer; drag to move; a double click does this too)
plot-steady-note = scaled to the steady part: the first { $s } s run off it (the wheel or a pinch zooms out)
view-reset-hint = Back to the first view (a double click does this too)

## The lesson card (web/src/panels/lesson.rs)
lesson-start = ▶ Start the lesson
lesson-step = step { $n } of { $count }
lesson-predict = Choose what you expect; then the run shows it.
lesson-shows = The run shows: { $answer }
lesson-running = Running to t = { $t } s…
lesson-back = ◀ Back
lesson-next = Next ▶
lesson-again = ⟲ Again
lesson-end = End the lesson
msg-lesson-bad-step = This lesson step cannot be opened: { $why }
share = Share…
cycle-open = The filter's cycle
share-hint = A link for the class: this state or this lesson step, with controls hidden or locked, and its QR code.
share-title = Share with the class
share-scan = Scan with a phone's camera.
share-copy = Copy the link
share-embed = Embed in a slide or a course page
share-embed-hint = An <iframe> of this state without the page's panels (embed=1), 960×540 like a slide. The host page can drive it by postMessage: see docs/embed.md.
share-copy-embed = Copy the embed code
share-from-step = This lesson step, from its start
share-as-is = The page as it is now
share-answers = With the answers chosen
share-presenter = Open in presenter mode
share-controls = Hide or lock controls
share-control = Control
share-hide = Hide
share-lock = Lock
share-all = Every control
cycle-title = The filter's cycle
cycle-at = t = { $t } s, step { $k }
cycle-step = Step one sample (s)
cycle-pause = Pause
cycle-states = States: { $names }
cycle-no-update = No measurement this step: x̂⁺ = x̂⁻, P⁺ = P⁻.
cycle-note-window = The adaptation window ended: P was replaced by the window's estimate (§2.6, Table 2.3).
tile-none = —
lesson-bar = Lesson · step { $n } of { $count }
note-string-holds = This string holds { $mass } kg with a safety factor of { $factor } (§3.1 asks for { $required }: d ≥ { $dmin } mm).
note-string-too-thin = Too thin for { $mass } kg: a safety factor of { $factor }, below the { $required } §3.1 asks for (d ≥ { $dmin } mm).
note-string-period = The string and the body give T = { $period } s.
note-p2-tuned-q-table3 = It runs with q_Λ = { $att }, q_ω = { $rate }, q_bias = { $bias } (with the Q scale); Table 3 gives this set { $paper_att }, { $paper_rate }, { $paper_bias }.
note-p2-tuned-q-uncertain = It runs with q_Λ = { $att }, q_ω = { $rate }, q_bias = { $bias } (with the Q scale); this set's row at ×1: { $paper_att }, { $paper_rate }, { $paper_bias }, Table 3 as the OCR reads it, unsure of some digits.
note-p2-tuned-q-ours = It runs with q_Λ = { $att }, q_ω = { $rate }, q_bias = { $bias } (with the Q scale); this set's row at ×1: { $paper_att }, { $paper_rate }, { $paper_bias }, this project's choice (the OCR lost Table 3's).
note-p0-limited = P₀ would be singular or indefinite (b₀² ≥ a₀c₀): the filters use b₀ = ±{ $limit } deg²/s, a correlation of 0.99.
note-u0-range = Eq. 4: u₀ lies in [{ $lo }, { $hi }] rad/s²; this rig needs { $needed } rad/s².

## Before the app starts: index.html holds a copy of these (a test checks they agree)
boot-loading = Loading Attitude Lab…
boot-failed = Attitude Lab could not start
boot-failed-why = Either the page's files did not load, or this browser lacks WebAssembly or WebGL2. Try reloading, or use a recent Chrome, Firefox or Safari.
boot-no-script = Attitude Lab needs JavaScript: please enable it and reload the page.

## The words of units (i18n::unit): each word of a unit the code writes (`N·m`, `deg/s`) is
## shown as its message here; the signs between (·, /, ², √) stay.
unit-deg = °
unit-s = s
unit-ms = ms
unit-min = min
unit-h = h
unit-Hz = Hz
unit-rad = rad
unit-kg = kg
unit-m = m
unit-mm = mm
unit-km = km
unit-N = N
unit-nT = nT
unit-ug = µg
unit-bit = bit
unit-J = J
unit-mJ = mJ

## Errors: why a run, a re-run, an export, a score or a sweep's point failed (the { $why }
## of the messages above). Each error type's every kind has words here (i18n::errors).
error-stats-empty = there were no values to take it of
error-stats-nan = value { $index } is not a number
error-score-columns = the scoring expected { $expected } series and got { $got }
error-score-empty-run = the run has no samples
error-score-diverged = the tuned filter's error is not a number (it diverged)
error-score-no-step = the set-point step is 0°, so there is no transient to time
error-score-ends-too-soon = the run ends at { $end } s, too soon after the step at { $step } s
error-score-few-samples = only { $n } samples have both θ̂ and the accelerometer angle
error-score-stat = { $of ->
        [mse] the MSE
        [t-tr] the transient time t_tr
        [offset-before] the offset before the step
        [offset-after] the offset after the step
        [noise] the noise
        [rms] the RMS
       *[jitter] the jitter
    } could not be computed: { $why }
error-score-count = the scoring gave { $got } numbers for { $expected } scores
error-score-seed = seed { $seed }: { $why }
error-sim-series = the lab records no series “{ $name }”
error-sim-few-samples = the log needs at least two samples with increasing times
error-sim-refused = the change { $change } at step { $step } was refused on re-run: { $why }
error-sim-csv = the CSV could not be written: { $detail }
error-sweep-wrong-lab = a worker was handed a job of lab { $job } on lab { $lab }
error-sweep-no-sweep = lab { $lab } has no sweep number { $sweep }
error-sweep-no-point = sweep number { $sweep } has no point { $point }
error-lesson-no-preset = the step names a preset “{ $preset }” that lab { $lab } does not have
error-lesson-preset = the step's preset “{ $preset }” sets a value the lab refuses: { $why }
error-worker-bad-job = a worker could not read its job ({ $detail })
error-worker-no-lab = a worker's build has no lab { $detail }
error-worker-unreadable = a worker's answer could not be read ({ $detail })
error-worker-threw = a worker failed: { $detail }
error-worker-could-not-start = a worker could not start or load the page's code { $detail }
error-qr-too-long = the link is too long for a QR code ({ $bytes } bytes): leave some items out
error-qr-other = no QR code for this link: { $detail }

## The page embedded in another (embed=1) and the host page's messages (docs/embed.md).
embed-time = t = { $t } s
embed-open = Open in Attitude Lab ↗
embed-open-hint = { $lab }: this state in the whole page, in a new tab.
host-must-value = a number or a choice's name
host-error-not-json = The message is not JSON (it stops parsing at line { $line }, column { $column }; 0 if it is a value JSON cannot hold).
host-error-not-attlab = The message is not for Attitude Lab: it needs "api": 1 and a "type".
host-error-api-version = This page speaks version { $api } of the API; the message asked for { $version }.
host-error-unknown-type = No message type “{ $type }” (docs/embed.md lists them).
host-error-bad-argument = “{ $name }” must be { $must }.
host-error-bad-parameter = { $why }
host-error-locked = The link locks the control “{ $label }”: it keeps its value.
host-error-no-preset = This lab has no preset “{ $id }”.
host-error-no-lab = No lab “{ $id }”.
host-error-no-lesson = This lab has no lesson.
host-error-no-step = The lesson has no step “{ $id }”.
host-error-no-question = The step shown asks no question.
host-error-no-answer = The question has no answer { $answer }.
host-error-origin-not-allowed = The page at { $origin } may not drive this one: its link must allow it with origin={ $origin }.
host-must-string = a string
host-must-params = an object of parameter keys and values
host-must-positive = a positive number
host-must-step = a step number from 1, or the step's id
host-must-answer = an answer number from 1

## About and citing (the end of the controls).
about-title = About and citing
about-build = Attitude Lab { $version }, commit { $commit }, built { $date }.
about-cite = Cite the software
about-cite-software = The Attitude Lab contributors (2026). Attitude Lab, version { $version } (commit { $commit }) [software]. MIT OR Apache-2.0. CITATION.cff in the repository gives it and the papers.
about-papers = The papers the labs reproduce
about-teacher-notes = Teacher notes for this lesson (printable)
about-licence = Free software under the MIT or Apache-2.0 licence.
