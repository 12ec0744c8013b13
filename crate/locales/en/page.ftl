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
keys-help = Keys: space pause/resume · r reset · s single step · ←/→ plot tab · f one view at full size (repeat for the next view, then the plots alone, then all) · p PNG of the view shown alone, else of every plot tab · ? or F1 every key (Tab moves between the controls)
frames-help = Frames: reference ζ up; body ξ′ right, η′ forward, ζ′ up. The sphere shows the vertical k = (a′, b′, c′) in body axes; the ray from the pole S through k meets the body plane at w = u + jv = (a′ + jb′)/(1 + c′). |w| = 1 is pitch ±90°; w → ∞ is upside down, where the (u, v, z) integrator switches to s = 1/w.

## A narrow screen
controls = Controls
controls-hint = The parameters, presets and exports, in a sheet below
view = View:
close = Close

## The plots
estimators = Estimators:
more-estimators = +{ $n } more…
chip-hide-hint = { $name } — click to hide it everywhere
chip-show-hint = { $name } — click to show it everywhere
more = More…
more-with = More: { $title }
log10 = log10
bands = ±3σ bands
outages = shade outages
outages-hint = Shade the intervals where a sensor gives nothing (every plot)
axis-time = t [s]
axis-mixed-units = mixed units (see the legend)
bands-legend = ±3σ of the filter's own covariance

## The views
view-body3d = 3D body
view-sphere = Riemann sphere
view-wplane = w plane
view-dial = Dial
view-phase = Phase portrait
truth = truth
body-truth = truth (solid)
body-ghost = estimate (ghost): { $label }
body-hint = drag: orbit · wheel or pinch: zoom · double-click: reset · x red, y green, z blue
sphere-title = Riemann sphere: vertical k in body axes
chart-w = chart w (from S): { $ids }
chart-s = chart s = 1/w (upside down): { $ids }
dial-title = Angle on a dial (0° up)

## The status line
job-holds = the simulation holds meanwhile
stop = Stop
status-short = t = { $t } s · ×{ $realtime } real time (×{ $asked } asked)
status-long = t = { $t } s · step { $step } ms · { $rate } steps/s · ×{ $realtime } real time (×{ $asked } asked) · frame every { $frame } ms · sim { $sim } ms/frame · recorder { $mib } MiB ({ $series } series, whole run)
behind = · behind real time: lower the speed
diverged = · { $id } diverged: { $why } (press Reset)
unobservable = · { $id } unobservable: { $why }

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
keys-tabs = ← →
keys-tabs-does = the previous, the next plot tab (when no control has the keyboard)
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
