/**
 * The picture of a grid: a {@link io.github.jdem846.render.Scene} says which stages (tint, hillshade, cast shadows)
 * and which light, the {@link io.github.jdem846.render.Renderer} computes it in tiles on its own thread pool into a
 * {@link io.github.jdem846.render.RenderedRelief}; {@link io.github.jdem846.render.OutputSize} and
 * {@link io.github.jdem846.render.RenderSettings} set the size and the execution.
 */
package io.github.jdem846.render;
