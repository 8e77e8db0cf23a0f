# El tanque en palabras, para quien no puede verlo (src/a11y/describe.rs).

describe-aligned-tight = muy alineados
describe-aligned-loose = algo alineados
describe-aligned-none = nadando cada uno por su lado
describe-the-fish = Los peces
describe-fish-count = { $count ->
        [one] { $count } pez
       *[other] { $count } peces
    }
describe-empty = El tanque está vacío.
describe-one-school = en un solo banco
describe-alone = solo
describe-scattered = dispersos ({ $groups } grupos separados)
describe-in-groups = en { $groups } grupos
describe-school = { $fish } { $arrangement }, { $alignment } (polarización { $polarization }), a unos { $spacing } largos de cuerpo entre sí, nadando a { $speed } metros por segundo
describe-milling = dando vueltas alrededor de su centro (remolino { $milling })
describe-caught-so-far = Los tiburones han atrapado { $count ->
        [one] { $count } pez
       *[other] { $count } peces
    } hasta ahora.
describe-reef = El arrecife: { $predators ->
        [one] { $predators } depredador
       *[other] { $predators } depredadores
    }, { $prey ->
        [one] { $prey } pez presa
       *[other] { $prey } peces presa
    }, { $pacifists ->
        [one] { $pacifists } pacifista
       *[other] { $pacifists } pacifistas
    } y { $food ->
        [one] { $food } trocito
       *[other] { $food } trocitos
    } de plancton.
describe-drill = Ejercicio de entrenamiento { $drill } de { $drills }: { $percent } % hecho, mejor puntuación { $best }.
describe-lab = El laboratorio de aprendizaje: { $learned } de { $drills } ejercicios aprendidos; el pez nada con { $source ->
        [shipped] los controladores que trae Shoal
        [trained] sus controladores recién entrenados
       *[loaded] controladores cargados
    }.
describe-race = Hay una carrera de { $count ->
        [one] { $count } pez
       *[other] { $count } peces
    } en marcha.
describe-sharks-hunting = { $count ->
        [one] { $count } tiburón está cazando
       *[other] { $count } tiburones están cazando
    }.
describe-physics-fish = El pez { $number } nada a { $speed } metros por segundo.
describe-physics-fish-turning = El pez { $number } nada a { $speed } metros por segundo, girando.
describe-left-tank = Tanque izquierdo: { $words }
describe-right-tank = Tanque derecho: { $words }
describe-sees = El pez seleccionado ve { $count ->
        [one] { $count } vecino
       *[other] { $count } vecinos
    }.
describe-paused = En pausa.
describe-selected = Seleccionado: { $what }
describe-selected-body = Seleccionado: pez { $number }, de especie { $species }, de { $length } metros de largo, nadando a { $speed } metros por segundo.
describe-selected-body-turning = Seleccionado: pez { $number }, de especie { $species }, de { $length } metros de largo, nadando a { $speed } metros por segundo y girando.
describe-selected-sees = Seleccionado: pez { $number }. Ve { $count ->
        [one] { $count } vecino
       *[other] { $count } vecinos
    }.
describe-selected-sees-far = Seleccionado: pez { $number }. Ve { $count ->
        [one] { $count } vecino
       *[other] { $count } vecinos
    } y un banco más lejos.
describe-fleeing = Está huyendo de un tiburón.
describe-eaten = { $name } fue devorado.
describe-mind = { $name } { $doing ->
        [avoid] esquiva un obstáculo
        [escape] huye de un depredador
        [school] nada en banco con otros
        [eat] tiene hambre y va por comida
        [mate] está cortejando
        [leave] se aleja de los demás
       *[other] anda sin rumbo
    } (hambre { $hunger }, miedo { $fear }, libido { $libido }).
describe-trend = { $now }, { $direction ->
        [steady] estable
        [rising] subiendo
       *[falling] bajando
    } (hace diez segundos era { $then })
describe-plots = Gráficas: polarización { $polarization }; vecino más cercano a { $neighbour } largos de cuerpo; grupos { $groups }; remolino { $milling }; rapidez media { $speed } metros por segundo.
describe-latest = Lo último: { $events }.
describe-time = Tiempo { $seconds } segundos, velocidad { $speed }×, semilla { $seed }.
describe-split = El banco se dividió en { $groups } grupos.
describe-together = Los peces se juntaron en un solo banco.
describe-in-line = Ahora los peces nadan alineados (polarización { $polarization }).
describe-out-of-line = Los peces ya no nadan alineados (polarización { $polarization }).
describe-caught = { $count ->
        [one] Un tiburón atrapó un pez
       *[other] Los tiburones atraparon { $count } peces
    } ({ $total } hasta ahora).
