# The app's own words: the Keyboard window and what the keys say
# (src/app/keys.rs), notices and views (src/app/mod.rs, views.rs, facade.rs).

keys-title = Keyboard
keys-play = Space or P
    .does = Play or pause (Space presses a button instead while one has the focus)
keys-step = S
    .does = One step forward
keys-reset = R
    .does = Reset the run
keys-scenes = 1 to 5
    .does = Aquarium, Schooling lab, Physics fish, Reef, Learning lab
keys-speed = { $slower } and { $faster }
    .does = Slower and faster (half and twice the speed)
keys-arrows = Arrow keys
    .does = Turn the camera round the tank (when no control has the focus)
keys-zoom = + and −
    .does = Zoom the camera in and out
keys-view = V
    .does = Put the camera back
keys-next = N and B
    .does = Select the next or the previous fish, and hear what it does
keys-follow = F
    .does = The camera follows the selected fish, or stops (Physics fish, Reef)
keys-describe = D
    .does = Describe the tank: what the fish do and what the plots show
keys-tab = Tab and Shift+Tab
    .does = Move between the controls; Enter or Space presses one
keys-help = ?
    .does = Show or hide this list
keys-screen-reader = With a screen reader, every control is in the page; the tank is described in a live region, and D reads it all.
keys-close = Close
keys-cannot-pick = In the { $scene } you cannot pick a fish.
keys-following = The camera follows the selected fish.
keys-select-first = Select a fish first (N or B), then F follows it.
keys-not-following = The camera no longer follows the fish.
keys-cannot-follow = In the { $scene } the camera does not follow a fish.
keys-left-tank = Left tank
keys-right-tank = Right tank

app-no-gpu = Shoal needs a GPU renderer (WebGPU or WebGL2), and none could be started.
app-bench-title = Benchmark
app-bench-done = Done. Figures for this computer and browser:
app-bench-measuring = Measuring… (about a minute)
app-bench-scene = scene
app-bench-fish = fish
app-bench-steps = steps/s
app-bench-fish-steps = fish-steps/s
app-bench-frame = frame ms
app-bench-cpu = CPU ms
app-bench-annealing = Learning lab: { $rate } annealing evaluations/s
app-bench-experiment = Experiment { $name }: { $rate } runs/s ({ $runs } runs of { $steps } steps, one thread)
app-status = Status
app-controls = Controls
    .help = Show the control panel
app-reset-view = Reset view (V)
    .help = Put the camera back on what this scene is about
notice-link-copied = Link copied. Paste it in a message or a web page: it opens Shoal with exactly these settings.
notice-csv-next = open it with a spreadsheet
notice-ok = OK
    .help = Hide this message
notice-experiment-link-copied = Link copied: it opens Shoal on this experiment and runs it again, with the same numbers.
notice-investigation-link-error = This link could not open its investigation: { $error }. The rest of the link was opened.
notice-experiment-link-error = This link could not open its experiment: { $error }. The rest of the link was opened.
notice-experiment-reopened = This link reopened the experiment '{ $name }': its runs start now, the same runs and numbers as when the link was made.

# The graphics device was lost (the computer slept, or changed screens) and
# Shoal started drawing again on a new one.
app-gpu-recovered = The graphics were lost for a moment (the computer slept or changed screens). Shoal drew the tank again; the fish, the clock and your settings carried on.
app-gpu-lost-title = Shoal lost its graphics and could not get them back
app-gpu-lost-why = The computer slept, changed screens or reset its graphics. Reloading the page starts Shoal again with the same settings (they are in the page's address).
