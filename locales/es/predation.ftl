# Los interruptores del efecto de confusión y la huida conjunta (laboratorio de cardúmenes y arrecife).
predation-heading = Lo que agregamos a los artículos
    .help = Dos formas en que un cardumen protege a sus peces que ningún artículo (Reynolds 1987, Tu y Terzopoulos 1994) tiene. Nosotros las agregamos; apágalas para ver qué hacen los peces de los artículos sin ellas.
predation-confusion = Efecto de confusión
    .help = Un depredador se confunde con los muchos peces que rodean al que persigue. Laboratorio de cardúmenes: un tiburón pierde de vista a su presa, más seguido cuantos más peces nadan cerca de ella. Arrecife: un ataque falla más seguido cuantas más presas nadan cerca de su objetivo. Apagado: cada ataque sigue como si la presa estuviera sola.
predation-joint-flight = Huida conjunta
    .help = Un cardumen asustado huye junto. Laboratorio de cardúmenes: un pez que ve huir a un vecino también se asusta, y la alarma recorre el cardumen. Arrecife: un pez de cardumen huye con los compañeros que ve. Apagado: cada pez huye solo, y solo de un depredador que él mismo nota.
predation-paper-only = Solo los artículos: ambos apagados
    .help = Apaga el efecto de confusión y la huida conjunta, y nada más.
