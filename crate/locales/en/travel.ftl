## Time travel: the timeline under the plots and the "what if" branches.

timeline-label = Timeline
timeline-hint = Drag, click or use ←/→ (a step), Shift+←/→ (a second), Home/End to look back at any moment of the run. The views show that moment; the plots mark it.
timeline-at = t = { $t } s
timeline-live = Live
timeline-live-hint = Back to now: the run goes on as it was (playing or paused).
timeline-now = now, t = { $t } s
timeline-seeking = Going back to t = { $t } s…
timeline-what-if = What if…
timeline-what-if-hint = Move sliders now, then start a second run from this moment with them: the same noise from here on, so what differs is your change alone.
timeline-changes = At this moment: { $changes }
timeline-no-changes = Move a slider to ask "what if"; with no change the second run is this one, bit for bit.
branch-chip = What if { $n }: { $changes } (from t = { $t } s)
branch-no-change = no change
branch-drop = Remove
branch-drop-hint = Remove this second run.
branch-promote = Make main
branch-promote-hint = Make this second run the main run (it is re-run from t = 0).
branch-catching-up = catching up: t = { $t } s
branch-summary = { $estimator }: attitude error over the next { $over } s: { $before }° → { $after }°
branch-summary-none = { $estimator }: no attitude error to compare (no truth or no estimate)
branch-legend = { $name } (what if { $n })
msg-branch-full = at most { $most } second runs: remove one first
msg-branch-promoted = the second run is now the main run
msg-travel-failed = cannot go back there: { $why }
job-promote = Re-running the second run from t = 0 to make it the main run
error-travel-no-history = this run keeps no snapshots
error-travel-before = t = { $t } s is before the run's first snapshot at { $first } s
error-travel-needs-reset = { $name } takes effect only at a reset, so a second run cannot change it
