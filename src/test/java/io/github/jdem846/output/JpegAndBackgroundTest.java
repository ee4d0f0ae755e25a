package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.RenderedRelief;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * JPEG output (the original wrote PNG and JPEG) and the background colour that no-data pixels take, on Luxembourg,
 * a real DEM with no-data outside the country's border.
 */
class JpegAndBackgroundTest {

    private static final Path LUX = Path.of("testdata/dem/luxembourg_srtm30s_wgs84.tif");

    @TempDir
    Path dir;

    private static RenderedRelief relief() throws Exception {
        Dem dem = DemReader.read(LUX);
        return new Renderer().render(dem, Scene.defaults());
    }

    @Test
    void overIsPorterDuffWorkedByHand() {
        assertEquals(0xFF102030, Background.over(0xFF102030, 0xFFFFFFFF), "opaque stays");
        assertEquals(0xFFFFFFFF, Background.over(0x00000000, 0xFFFFFFFF), "transparent takes the background");
        // half-transparent red over opaque blue: (255·128 + 0·127)/255 = 128, blue (0·128 + 255·127)/255 = 127
        assertEquals(0xFF80007F, Background.over(0x80FF0000, 0xFF0000FF));
        // over a half-transparent background: alpha 128 + 128·127/255 = 191.75 → 192
        assertEquals(192, Background.over(0x80FF0000, 0x800000FF) >>> 24);
        assertEquals(0, Background.over(0, 0), "nothing over nothing");
        assertEquals(128, JpegWriter.over(255, 0, 128), "JPEG's opaque blend");
    }

    @Test
    void aJpegIsThePictureOnWhiteWithinJpegsLoss() throws Exception {
        RenderedRelief r = relief();
        Path jpg = dir.resolve("lux.jpg");
        WriteResult result = ImageOutput.writeRgba(jpg, r.argb(), r.width(), r.height(), GeoReference.of(r.geometry()),
                WriteOptions.defaults().withJpegQuality(95).withSidecars(WriteOptions.Sidecars.WHEN_NOT_EMBEDDED));
        BufferedImage back = ImageIO.read(jpg.toFile());
        assertEquals(r.width(), back.getWidth());
        assertEquals(r.height(), back.getHeight());
        double sum = 0;
        int noData = 0;
        for (int y = 0; y < r.height(); y++) {
            for (int x = 0; x < r.width(); x++) {
                int expected = Background.over(r.argb()[y * r.width() + x], 0xFFFFFFFF);
                int got = back.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) {
                    sum += Math.abs((expected >> shift & 0xff) - (got >> shift & 0xff));
                }
                noData += r.argb()[y * r.width() + x] == 0 ? 1 : 0;
            }
        }
        double mean = sum / (3.0 * r.width() * r.height());
        assertTrue(noData > 1000, "Luxembourg has no-data outside its border: " + noData);
        assertTrue(mean < 3, "mean |ΔDN| at quality 95: " + mean);
        // Far from the country the pixels are white, not black (JPEG has no alpha).
        assertTrue((back.getRGB(0, 0) & 0xff) > 240, Integer.toHexString(back.getRGB(0, 0)));
        assertTrue(result.sidecars().contains(dir.resolve("lux.jgw")), "a JPEG world file is .jgw: " + result.sidecars());
    }

    @Test
    void qualityTradesSizeAndGrayPicturesStayGray() throws Exception {
        RenderedRelief r = relief();
        List<Long> sizes = new ArrayList<>();
        for (int q : new int[] {20, 60, 95}) {
            Path jpg = dir.resolve("q" + q + ".jpg");
            ImageOutput.writeRgba(jpg, r.argb(), r.width(), r.height(), null, WriteOptions.defaults().withJpegQuality(q));
            sizes.add(Files.size(jpg));
        }
        assertTrue(sizes.get(0) < sizes.get(1) && sizes.get(1) < sizes.get(2), sizes.toString());
        byte[] gray = new byte[r.width() * r.height()];
        for (int i = 0; i < gray.length; i++) {
            gray[i] = (byte) (i % r.width() * 255 / r.width());
        }
        Path g = dir.resolve("gray.jpg");
        ImageOutput.writeGray(g, gray, r.width(), r.height(), null, WriteOptions.defaults());
        BufferedImage back = ImageIO.read(g.toFile());
        assertEquals(1, back.getRaster().getNumBands());
        assertEquals(128, back.getRaster().getSample(r.width() / 2, 5, 0), 3);
    }

    @Test
    void aBackgroundFillsNoDataInPngAndLeavesDataAlone() throws Exception {
        RenderedRelief r = relief();
        Path png = dir.resolve("bg.png");
        ImageOutput.writeRgba(png, r.argb(), r.width(), r.height(), null,
                WriteOptions.defaults().withBackground(0xFF203040));
        BufferedImage back = ImageIO.read(png.toFile());
        for (int y = 0; y < r.height(); y++) {
            for (int x = 0; x < r.width(); x++) {
                int p = r.argb()[y * r.width() + x];
                assertEquals(p == 0 ? 0xFF203040 : p, back.getRGB(x, y), x + "," + y);
            }
        }
    }

    @Test
    void aJpegTooLargeIsRefusedBeforeAnythingIsWritten() {
        Path jpg = dir.resolve("huge.jpg");
        IllegalArgumentException side = assertThrows(IllegalArgumentException.class,
                () -> ImageOutput.openRgba(jpg, 70_000, 10, null, WriteOptions.defaults()));
        assertTrue(side.getMessage().contains("65535") && side.getMessage().contains("huge.jpg"), side.getMessage());
        IllegalArgumentException memory = assertThrows(IllegalArgumentException.class,
                () -> ImageOutput.openRgba(jpg, 60_000, 60_000, null, WriteOptions.defaults()));
        assertTrue(memory.getMessage().contains("in memory"), memory.getMessage());
        assertFalse(Files.exists(jpg));
        assertEquals(0, dir.toFile().list().length, "nothing left behind");
    }

    @Test
    void jpegQualityOutsideItsRangeIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> WriteOptions.defaults().withJpegQuality(0));
        assertThrows(IllegalArgumentException.class, () -> WriteOptions.defaults().withJpegQuality(101));
    }
}
