# Each scene's facts (src/scenes/*.rs): its name on the scene picker, with
# .description (the sentence under the picker).

scene-schooling = Schooling lab
    .description = Each fish follows five urges: stay in the tank, swim like the others, stay close, keep space and dodge rocks. Change them and watch a school form.
scene-aquarium = Aquarium
    .description = Fish wander through the tank and swim around rocks and pillars.
scene-physics = Physics fish
    .description = Each fish is a body of 23 masses and 91 springs. Twelve springs are muscles: they pull the tail from side to side, the water pushes back, and the fish swims.
scene-reef = Reef
    .description = Fish that see, get hungry, get scared and fall in love. Each one decides what to do next from what it sees and how it feels. Click a fish to look inside its head.
scene-learning = Learning lab
    .description = How a fish learns to swim: starting from random muscle moves, it keeps what works and slowly learns to swim and turn, like practising a new sport. The swimmer between the buoys uses controllers learned before until you train your own.
