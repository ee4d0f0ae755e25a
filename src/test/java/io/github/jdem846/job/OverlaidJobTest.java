package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.overlay.Overlay;
import io.github.jdem846.overlay.OverlayFiles;
import io.github.jdem846.overlay.OverlayStyle;
import io.github.jdem846.render.RenderSettings;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@link OverlaidJob}: no overlay writes the same bytes as the plain job; a picture rendered in tiles gets the same
 * overlay pixels as one rendered in memory; the overlay changes the picture only near its shapes.
 */
class OverlaidJobTest {

    static final Path JACKSBORO = Path.of("testdata/dem/jacksboro_srtm3s_wgs84.flt");
    static final Path SHAPES = Path.of("testdata/overlay/jacksboro_test_shapes.geojson");
    static final WriteOptions NO_SIDECARS = WriteOptions.defaults()
            .withSidecars(WriteOptions.Sidecars.NONE);
    static final RenderSettings TWO_THREADS = new RenderSettings(2, 64);

    @TempDir
    Path tmp;

    @Test
    void noOverlayWritesTheSameBytesAsThePlainJob() throws Exception {
        ReliefJob job = ReliefJob.of(JACKSBORO).withExecution(TWO_THREADS);
        Path plain = tmp.resolve("plain.png");
        Path overlaid = tmp.resolve("overlaid.png");
        job.runAndWrite(plain, NO_SIDECARS, JobListener.NONE);
        new OverlaidJob(job, List.of()).runAndWrite(overlaid, NO_SIDECARS, JobListener.NONE);
        assertArrayEquals(Files.readAllBytes(plain), Files.readAllBytes(overlaid));
    }

    @Test
    void tilesGetTheSamePixelsAsTheWholePicture() throws Exception {
        Overlay shapes = OverlayFiles.read(SHAPES, OverlayStyle.parse(
                "color=#ffff00,width=2.5,fill=#0050ff60,radius=5"));
        ReliefJob job = ReliefJob.of(JACKSBORO).withExecution(TWO_THREADS);
        Path plain = tmp.resolve("plain.png");
        Path whole = tmp.resolve("whole.png");
        Path tiled = tmp.resolve("tiled.png");
        job.runAndWrite(plain, NO_SIDECARS, JobListener.NONE);
        new OverlaidJob(job, List.of(shapes)).runAndWrite(whole, NO_SIDECARS, JobListener.NONE);
        List<String> notices = new ArrayList<>();
        new OverlaidJob(job.withMemory(300_000), List.of(shapes)).runAndWrite(tiled, NO_SIDECARS,
                new JobListener() {
                    @Override
                    public void notice(String message) {
                        notices.add(message);
                    }
                });
        assertTrue(notices.stream().anyMatch(n -> n.contains("tiles")), "rendered in tiles: " + notices);
        int[] p = pixels(plain);
        int[] w = pixels(whole);
        int[] t = pixels(tiled);
        assertArrayEquals(w, t, "tiled and whole pictures with the overlay");
        int width = ImageIO.read(plain.toFile()).getWidth();
        int changed = 0;
        for (int i = 0; i < p.length; i++) {
            if (p[i] != w[i]) {
                changed++;
                int col = i % width;
                int row = i / width;
                boolean nearLine = Math.abs(row - 100) <= 3 && col >= 46 && col <= 354;
                boolean nearPolygon = row >= 176 && row <= 263 && col >= 56 && col <= 163;
                boolean nearPoint = Math.abs(row - 250) <= 7 && Math.abs(col - 300) <= 7;
                assertTrue(nearLine || nearPolygon || nearPoint, "pixel " + col + "," + row + " changed");
            }
        }
        assertTrue(changed > 6000, changed + " pixels changed");
        assertFalse(p[100 * width + 200] == w[100 * width + 200], "the line's pixel changed");
    }

    static int[] pixels(Path png) throws Exception {
        BufferedImage img = ImageIO.read(png.toFile());
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }
}
