package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code jdem846 view}: a picture of the size asked for; misuse is exit 2 and leaves no file. */
class ViewCommandTest {

    private static final String DEM = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";

    @TempDir
    Path tmp;

    @Test
    void writesAPerspectiveViewOfTheSizeAskedFor() throws Exception {
        Path out = tmp.resolve("view.png");
        CliRun run = CliRun.of("view", DEM, "-o", out.toString(), "-q", "--width", "180", "--height", "120",
                "--camera-azimuth", "150", "--camera-elevation", "40", "--exaggeration", "2", "--shadows", "sweep");
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage image = ImageIO.read(out.toFile());
        assertEquals(180, image.getWidth());
        assertEquals(120, image.getHeight());
        assertTrue(image.getRGB(90, 60) != image.getRGB(0, 0), "terrain in the middle, background in the corner");
    }

    @Test
    void badCameraOptionsAreBadUsage() {
        Path out = tmp.resolve("x.png");
        CliRun low = CliRun.of("view", DEM, "-o", out.toString(), "--camera-elevation", "0");
        assertEquals(2, low.exitCode(), low.err());
        assertTrue(low.err().contains("--camera-elevation"), low.err());
        CliRun fov = CliRun.of("view", DEM, "-o", out.toString(), "--fov", "180");
        assertEquals(2, fov.exitCode(), fov.err());
        assertTrue(fov.err().contains("--fov"), fov.err());
        CliRun scale = CliRun.of("view", DEM, "-o", out.toString(), "--scale", "0.5");
        assertEquals(2, scale.exitCode(), scale.err());
        CliRun worldFile = CliRun.of("view", DEM, "-o", out.toString(), "--world-file");
        assertEquals(2, worldFile.exitCode(), worldFile.err());
        assertFalse(Files.exists(out));
    }

    @Test
    void aMissingFileIsExitOne() {
        Path out = tmp.resolve("x.png");
        CliRun run = CliRun.of("view", tmp.resolve("missing.tif").toString(), "-o", out.toString());
        assertEquals(1, run.exitCode(), run.err());
        assertEquals(1, run.err().strip().lines().count(), run.err());
        assertFalse(Files.exists(out));
    }
}
