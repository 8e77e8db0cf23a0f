# Las palabras del dibujo del tanque (src/render/).

render-tier-native = GPU nativa
