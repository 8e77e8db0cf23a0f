# Each scene's facts (src/scenes/*.rs): its name on the scene picker, with
# .description (the sentence under the picker).

scene-schooling = Laboratorio de cardúmenes
    .description = Cada pez sigue cinco impulsos: quedarse en el tanque, nadar como los demás, mantenerse cerca, guardar su espacio y esquivar rocas. Cámbialos y mira cómo se forma un banco de peces.
scene-aquarium = Acuario
    .description = Los peces pasean por el tanque y nadan alrededor de rocas y pilares.
scene-physics = Peces físicos
    .description = Cada pez es un cuerpo de 23 masas y 91 resortes. Doce resortes son músculos: tiran de la cola de un lado a otro, el agua empuja de vuelta y el pez nada.
scene-reef = Arrecife
    .description = Peces que ven, tienen hambre, se asustan y se enamoran. Cada uno decide qué hacer según lo que ve y cómo se siente. Haz clic en un pez para mirar dentro de su cabeza.
scene-learning = Laboratorio de aprendizaje
    .description = Cómo aprende a nadar un pez: empieza con movimientos musculares al azar, se queda con lo que funciona y poco a poco aprende a nadar y girar, como quien practica un deporte nuevo. El nadador entre las boyas usa controladores aprendidos antes hasta que entrenes los tuyos.
