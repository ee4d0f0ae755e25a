package io.github.jdem846.drape;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.render.ColorLayer;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Compositing and sampling of draped images, against values worked by hand. */
class DrapeTest {

    @TempDir
    Path dir;

    @Test
    void sourceOverIsPorterDuffRoundedToTheNearestLevel() {
        // α = 128 over opaque: (128·255 + 127·0) / 255 = 128 red, (128·0 + 127·255) / 255 = 127 blue
        assertEquals(0xFF80007F, ColorLayer.over(0x80FF0000, 0xFF0000FF));
        // over nothing: itself; nothing over: what is below; opaque: itself
        assertEquals(0x40102030, ColorLayer.over(0x40102030, 0));
        assertEquals(0xFF123456, ColorLayer.over(0, 0xFF123456));
        assertEquals(0xFF654321, ColorLayer.over(0xFF654321, 0xFF123456));
        // both half: αo = 128 + 128·127/255 = 191.75 → 192; red 255·128·255 / (128·255 + 128·127) = 170.2 → 170,
        // blue 255·128·127 / 48896 = 84.8 → 85
        assertEquals(0xC0AA0055, ColorLayer.over(0x80FF0000, 0x800000FF));
    }

    @Test
    void bilinearInterpolationIsOnPremultipliedColours() {
        // a quarter of the way from black to white: 63.75 → 64
        assertEquals(0xFF404040, Drape.bilinear(0xFF000000, 0xFFFFFFFF, 0xFF000000, 0xFFFFFFFF, 0.25, 0));
        // halfway to a transparent pixel: half the alpha, and the transparent pixel's (blue) colour lends nothing
        assertEquals(0x80FF0000, Drape.bilinear(0xFFFF0000, 0x000000FF, 0xFFFF0000, 0x000000FF, 0.5, 0.5));
        // on a pixel centre: the pixel itself
        assertEquals(0x7F123456, Drape.bilinear(0x7F123456, 0xFFFFFFFF, 0xFFFFFFFF, 0xFFFFFFFF, 0, 0));
        assertEquals(0, Drape.bilinear(0, 0, 0, 0, 0.3, 0.7));
    }

    /** A PNG of {@code argb} pixels (one row) with a world file: pixels {@code size} wide, west edge at x0. */
    private Path image(String name, int[] argb, double x0, double size, double north) throws IOException {
        BufferedImage img = new BufferedImage(argb.length, 1, BufferedImage.TYPE_INT_ARGB);
        for (int i = 0; i < argb.length; i++) {
            img.setRGB(i, 0, argb[i]);
        }
        Path png = dir.resolve(name + ".png");
        ImageIO.write(img, "png", png.toFile());
        Files.writeString(dir.resolve(name + ".pgw"), size + "\n0\n0\n" + -size + "\n" + (x0 + size / 2) + "\n"
                + (north - size / 2) + "\n");
        return png;
    }

    @Test
    void eachCellTakesTheImageAtItsCentreTheTintOutsideAndNoDataStaysTransparent() throws Exception {
        // 6 × 2 cells of 10 m from x = 0; the image: 2 pixels of 20 m from x = 10, centres at x = 20 and 40
        Path png = image("two", new int[] {0xFF000000, 0xFFC8C8C8}, 10, 20, 20);
        GridGeometry grid = GridGeometry.metric(6, 2, 10);
        float nan = Float.NaN;
        Dem dem = new Dem(new float[] {1, 2, 3, 4, 5, 6, 1, 2, nan, 4, 5, 6}, grid);
        Scene scene = Scene.defaults().withTint(null).withHillshade(null)
                .withDrape(new Drape(List.of(DrapeImage.open(png))));
        int[] argb = new Renderer(new RenderSettings(1, 16)).render(dem, scene).argb();
        int gray = 0xFF808080;  // the plain tint
        // centres 5 (outside: tint), 15 (edge pixel), 25 (¾·0 + ¼·200 = 50), 35 (150), 45 (edge pixel), 55 (tint)
        int[] row = {gray, 0xFF000000, 0xFF323232, 0xFF969696, 0xFFC8C8C8, gray};
        assertArrayEquals(row, java.util.Arrays.copyOf(argb, 6));
        assertEquals(0, argb[8], "no-data stays transparent");
        assertEquals(0xFF969696, argb[9]);
    }

    @Test
    void aWindowOfTheGridGetsTheSameColours() throws IOException {
        Path png = image("ramp", new int[] {0xFF000000, 0xFF402010, 0x80FFFFFF, 0xFF00FF00}, 3, 7, 50);
        Drape drape = new Drape(List.of(DrapeImage.open(png)));
        GridGeometry grid = GridGeometry.metric(9, 5, 3.3);
        int[] whole = drape.argb(grid, CellWindow.whole(9, 5));
        int[] part = drape.argb(grid.window(2, 1, 6, 3), CellWindow.whole(6, 3));
        int[] area = drape.argb(grid, new CellWindow(2, 1, 6, 3));
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 6; c++) {
                assertEquals(whole[(r + 1) * 9 + c + 2], part[r * 6 + c], "window cell " + c + "," + r);
                assertEquals(whole[(r + 1) * 9 + c + 2], area[r * 6 + c], "area cell " + c + "," + r);
            }
        }
    }

    @Test
    void anImageMuchFinerThanTheGridIsReadEveryKthPixelNearestEachCentre() throws IOException {
        // 5 × 3 cells of 8 m; the image 20 × 12 pixels of 2 m: each cell a block of 4 × 4 pixels of its own colour,
        // but for one stray pixel per block at the block's north-west corner (never the one read)
        BufferedImage img = new BufferedImage(20, 12, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 12; y++) {
            for (int x = 0; x < 20; x++) {
                boolean stray = x % 4 == 0 && y % 4 == 0;
                img.setRGB(x, y, stray ? 0xFFFFFF : blockColour(x / 4, y / 4));
            }
        }
        Path png = dir.resolve("fine.png");
        ImageIO.write(img, "png", png.toFile());
        Files.writeString(dir.resolve("fine.pgw"), "2\n0\n0\n-2\n1\n23\n");
        DrapeImage image = DrapeImage.open(png);
        Drape drape = new Drape(List.of(image));
        GridGeometry grid = GridGeometry.metric(5, 3, 8);
        assertArrayEquals(new int[] {4, 4}, Drape.steps(image, null, grid));
        int[] argb = drape.argb(grid, CellWindow.whole(5, 3));
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 5; c++) {
                assertEquals(0xFF000000 | blockColour(c, r), argb[r * 5 + c], "cell " + c + "," + r);
            }
        }
        // a window reads with the same steps and gets the same colours
        assertArrayEquals(new int[] {4, 4}, Drape.steps(image, null, grid.window(3, 1, 2, 2)));
        int[] part = drape.argb(grid.window(3, 1, 2, 2), CellWindow.whole(2, 2));
        assertArrayEquals(new int[] {argb[8], argb[9], argb[13], argb[14]}, part);
    }

    private static int blockColour(int c, int r) {
        return (40 + c * 40) << 16 | (60 + r * 80) << 8 | 7;
    }

    @Test
    void grayPixelsKeepTheirLevels() throws IOException {
        BufferedImage img = new BufferedImage(3, 1, BufferedImage.TYPE_BYTE_GRAY);
        img.getRaster().setPixels(0, 0, 3, 1, new int[] {0, 100, 255});
        Path png = dir.resolve("gray.png");
        ImageIO.write(img, "png", png.toFile());
        Files.writeString(dir.resolve("gray.wld"), "1\n0\n0\n-1\n0.5\n0.5\n");
        DrapeImage image = DrapeImage.open(png);
        assertArrayEquals(new int[] {0xFF000000, 0xFF646464, 0xFFFFFFFF}, image.readArgb(0, 0, 3, 1));
        assertEquals(0, image.grid().originX());
        assertEquals(1, image.grid().originY());
    }

    @Test
    void anImageInACrsOnADemWithoutOneCannotBePlaced() throws IOException {
        Path png = image("utm", new int[] {0xFF000000}, 0, 10, 10);
        Files.writeString(dir.resolve("utm.prj"), Files.readString(Path.of(
                "testdata/dem/bigtujunga_srtm30m_utm11n.prj")));
        DrapeImage image = DrapeImage.open(png);
        assertTrue(image.crsGiven());
        assertEquals(32611, image.grid().crs().epsg());
        GridGeometry unknown = new GridGeometry(1, 1, 0, 10, 10, 10, CrsInfo.UNKNOWN, PixelAnchor.CORNER);
        Drape drape = new Drape(List.of(image));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> drape.requireCovers(unknown));
        assertTrue(e.getMessage().contains("the DEM's CRS is unknown"), e.getMessage());
        // on a grid in the same CRS it is placed without a transformation
        GridGeometry utm = new GridGeometry(1, 1, 0, 10, 10, 10, CrsResolver.fromEpsg(32611).orElseThrow(),
                PixelAnchor.CORNER);
        drape.requireCovers(utm);
        assertEquals(0xFF000000, drape.argb(utm, CellWindow.whole(1, 1))[0]);
    }
}
