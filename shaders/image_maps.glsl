// image_maps.glsl: the scene's image maps (render/image_maps.h), one texture array for
// every kind that reads maps (Textured, GltfPbr): declared once here.
precision highp sampler2DArray;
uniform highp sampler2DArray u_maps;
