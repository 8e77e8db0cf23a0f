# The renderer's words (src/render/).

render-tier-native = native GPU
