package io.github.jdem846;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.RenderedRelief;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.tint.ColorRamp;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicLong;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The stage-level use README names (Renderer → RenderedRelief → ImageOutput), on a real DEM. */
class ReadmeExampleTest {

    @Test
    void readmeLibraryExampleWorks(@TempDir Path dir) throws Exception {
        AtomicLong reports = new AtomicLong();
        Dem dem = DemReader.read(Path.of("testdata/dem/vancouver-island_topobathy_2min_mercator.tif"));
        Scene scene = Scene.defaults()
                .withTint(ColorRamp.named("etopo1"))
                .withShadows(ShadowAlgorithm.SWEEP)
                .withLight(new LightDirection(300, 12));
        RenderedRelief image = new Renderer().render(dem, scene, (stage, done, total) -> reports.incrementAndGet());
        BufferedImage picture = image.toBufferedImage();
        ImageOutput.writeRgba(dir.resolve("relief.png"), image.argb(), image.width(), image.height(),
                GeoReference.of(image.geometry()), WriteOptions.defaults());

        assertEquals(dem.width(), picture.getWidth());
        assertTrue(reports.get() > 0);
        BufferedImage back = ImageIO.read(dir.resolve("relief.png").toFile());
        assertEquals(picture.getRGB(10, 10), back.getRGB(10, 10));
        assertFalse(Files.exists(dir.resolve("relief.pgw")), "no sidecars by default, as the CLI");
        // etopo1 colours the sea blue and the land green/brown: the deepest cell is bluer than it is red
        int deep = picture.getRGB(indexOfMin(dem) % dem.width(), indexOfMin(dem) / dem.width());
        assertTrue((deep & 0xff) > ((deep >> 16) & 0xff), Integer.toHexString(deep));
    }

    private static int indexOfMin(Dem dem) {
        float[] v = dem.backingArray();
        int best = 0;
        for (int i = 1; i < v.length; i++) {
            if (v[i] < v[best]) {
                best = i;
            }
        }
        return best;
    }
}
