# The learning lab's words (src/ui/learning_panel.rs, src/sim/learning/*.rs)
# and the lab's refusals (src/lab.rs).

## The controls.
learning-heading = Learning to swim
learning-learner = Learner
    .help = Who learns. A shark is the same body, twice as long
learning-fish = Fish
learning-shark = Shark
learning-train-start = Start training
    .help = The fish practises a little every frame: it changes its muscle timing at random, keeps changes that take it farther, and sometimes keeps a worse one to explore
learning-train-pause = Pause training
learning-reset = Reset training
    .help = Forget everything: the fish is brain-dead again
learning-swimmer-uses = The swimmer between the buoys uses
    .help = Which controllers swim the fish between the two orange buoys: the hand-tuned ones its designers wrote, or the ones it learned by itself
learning-learned = Learned
learning-hand-tuned = Hand-tuned
learning-race = Run the race
    .help = Copies of the fish, saved after more and more tries of the first drill, race from the same start line (the paper's Fig. 7). Practice helps a lot at first and then hardly at all: the last two copies finish almost together
learning-save = Save controllers
    .help = Download what the fish learned as a file
learning-load = Load controllers
    .help = Open a file saved before; the swimmer then uses it

## The drills.
learning-drill-swim-far = swim as far as it can
learning-drill-hold-speed = swim straight at { $speed } body lengths/s
learning-drill-turn-left = turn left at { $rate }°/s
learning-drill-turn-right = turn right at { $rate }°/s

## The progress under the tank.
learning-drill-title = Drill { $number } of { $count }: { $drill }
learning-all-drills = All { $count } drills learned
learning-tries = { $tries } of { $total } tries · best E { $best } · temperature { $temperature }
    .help = E is what the fish tries to make small: how far it ended from its goal, plus a little for jerky muscles. The temperature is how willing it still is to try worse moves; it cools down as training goes on
learning-in-use = Learned controllers in use: { $source }
learning-source-shipped = the shipped set (trained before)
learning-source-here = trained here
learning-source-loaded = loaded from a file
learning-swimmer-on-its-way = Swimmer: on its way to the first buoy
learning-swimmer-first-buoy = Swimmer: first buoy at { $first } s
learning-swimmer-buoys = Swimmer: buoys at { $first } s and { $second } s
learning-race-after = Race after { $seconds } s (the paper's Fig. 7):
learning-race-racer = racer
learning-race-practice = practice (tries)
learning-race-distance = distance
learning-race-metres = { $distance } m
learning-race-what = After a few thousand tries the copies swim about equally fast. The race shows that the first minutes of practice matter most and then the gains level off, so the copy that practised longest does not always win.

## The plots.
learning-objective-caption = How well it swims (E, lower is better)
    .help = How far the practice swim missed its goal (the target, speed or turn of the drill), plus a little for jerky muscles, as a score E: lower is better. High at the start: the fish flails; falling: it is learning; flat and low: it has learned the stroke (the best line never goes up).
learning-axis-tries = tries
learning-line-now = now
learning-line-best = best
learning-muscle-middle = middle
learning-muscle-tail = tail
learning-fig8-raw = What it learned (left muscles)
    .help = How hard each muscle pulls over the practice swim, as learned. Tall, regular waves: a strong, steady stroke; flat lines: muscles the fish hardly uses.
learning-fig8-modes = Main rhythms (Fourier modes)
    .help = The main rhythm alone: the strongest wave in the learned pattern, around each muscle's average pull. Big, even swings: one rhythm carries most of the stroke; if it looks much like the first plot, little else is needed.
learning-fig8-abstract = Simplified controller
    .help = The learned pattern rebuilt from those few waves: this is what the fish keeps. The closer it looks to the first plot, the less the fish lost by keeping only a few waves.
learning-axis-time = time (s)

## Notices.
learning-open-first = Open the learning lab first.
learning-open-first-reason = open the learning lab first
learning-no-race = No race yet: { $reason }.
learning-loaded = Controllers loaded: the swimmer now uses them.
learning-load-refused = That file cannot be used, nothing was changed: { $reason }
learning-save-failed = the controllers could not be written: { $reason }
learning-race-not-ready = the race needs the first drill to finish ({ $done } of { $needed } annealing steps done)

## Why a controllers file cannot be used.
learning-map-no-straight = no straight-swimming controller that moves the fish forward was learned
learning-map-invalid = a learned controller contains a non-finite number or too many modes
learning-set-too-large = the file is larger than { $max } bytes
learning-set-not-a-set = the file is not a learned controller set: { $reason }
learning-set-wrong-version = the file has format version { $found }; this Shoal reads version { $expected }
learning-set-bad-controls = drill { $drill }: the learned controls are damaged (wrong size, or a value outside [0, 1] or not a number)
learning-set-bad-controller = drill { $drill }: the abstracted controller is damaged (a value that is not a number, or more than { $max } modes)
learning-set-non-finite = drill { $drill }: a measured speed, rate or objective is not a number
learning-set-map = the set cannot drive a fish: { $reason }

## The lab's refusals (src/lab.rs): commands of the shoal.* API and the panels.
lab-error-learning-lab-only = { $command }() works in the learning lab only
lab-error-physics-scene-only = turn() works in the physics fish scene only
lab-error-no-fish-selected = turn(): select a fish first (physics.selected)
lab-error-turn-out-of-range = turn(): { $angle } is out of range: choose from -{ $max } to { $max } degrees
lab-error-no-moment = skip(): this scene has no moment to skip to (the reef's demos have)
