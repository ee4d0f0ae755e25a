package io.github.jdem846.job;

import io.github.jdem846.internal.Clamp;
import io.github.jdem846.internal.Rounding;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import java.util.Objects;

/**
 * Draws a job's product over an area of a grid in memory, under the light of the whole picture: the same pixels
 * whether the grid holds the whole picture (with its halo) or one tile of it (with the tile's halo).
 */
final class AreaRenderer {

    /** The pixels of an area: RGBA for a relief or a tint, 8-bit gray for a hillshade or a shadow mask. */
    record Pixels(int[] argb, byte[] gray) {
    }

    private final Product product;
    private final Scene scene;
    private final Sun.Lighting lighting;
    private final Renderer renderer;

    /**
     * @param product   what to draw
     * @param scene     the product's scene, its tint range and terrain minimum those of the whole file
     * @param lighting  the light over the picture (null for a tint, which is not lit)
     * @param execution threads and tile size
     */
    AreaRenderer(Product product, Scene scene, Sun.Lighting lighting, RenderSettings execution) {
        this.product = Objects.requireNonNull(product, "product");
        this.scene = Objects.requireNonNull(scene, "scene");
        if (lighting == null && product != Product.TINT) {
            throw new IllegalArgumentException("a " + product + " needs a light");
        }
        this.lighting = lighting;
        this.renderer = new Renderer(execution);
    }

    /** @return true for RGBA pixels, false for gray */
    boolean rgba() {
        return product == Product.RELIEF || product == Product.TINT;
    }

    /**
     * The product over {@code area} of {@code dem}.
     *
     * @param pictureCol the column of {@code dem} where the picture's first column lies (negative when the grid
     *                   starts inside the picture)
     * @param pictureRow the row of {@code dem} where the picture's first row lies
     */
    Pixels render(Dem dem, CellWindow area, int pictureCol, int pictureRow, RenderProgress progress)
            throws InterruptedException {
        if (product == Product.TINT) {
            return new Pixels(renderer.render(dem, scene, area, progress).argb(), null);
        }
        Sun.Lighting l = lighting.inGrid(pictureCol, pictureRow);
        return switch (product) {
            case RELIEF -> new Pixels(renderer.render(dem, scene.withLight(l.field()).withFade(l.fade()), area,
                    progress).argb(), null);
            case HILLSHADE -> new Pixels(null, renderer.hillshadeGray(dem, scene.hillshade(),
                    scene.hillshadeOptions(), l.field(), area, progress));
            case SHADOWS -> new Pixels(null, renderer.shadowBytes(dem, scene.withLight(l.field()), area, progress));
            case SKY_VIEW -> new Pixels(null, skyViewBytes(renderer.skyView(dem, scene, area, progress)));
            case TINT -> throw new AssertionError();
        };
    }

    /** The sky-view factor 0..1 as 1..255, no-data (NaN) as 0. */
    static byte[] skyViewBytes(float[] factor) {
        byte[] bytes = new byte[factor.length];
        for (int i = 0; i < factor.length; i++) {
            float f = factor[i];
            bytes[i] = f == f ? (byte) (1 + Rounding.halfUp(Clamp.between(f, 0f, 1f) * 254f)) : 0;
        }
        return bytes;
    }
}
