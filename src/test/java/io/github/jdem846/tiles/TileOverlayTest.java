package io.github.jdem846.tiles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.overlay.Overlay;
import io.github.jdem846.overlay.OverlayFiles;
import io.github.jdem846.overlay.OverlayPainter;
import io.github.jdem846.overlay.OverlayStyle;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Overlays on map tiles: the tiles of one zoom drawn with the Jacksboro test shapes, put side by side, are the tiles
 * drawn without them with the shapes painted once over the whole mosaic (its own grid, one window of the zoom's
 * world), so shapes run on across tile seams; line widths are in tile pixels.
 */
class TileOverlayTest {

    static final Path JACKSBORO = Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif");
    static final Path SHAPES = Path.of("testdata/overlay/jacksboro_test_shapes.geojson");
    static final int Z = 12;
    static final int S = WebMercatorTile.SIZE;

    @TempDir
    Path dir;

    /** The tiles of zoom {@link #Z} in {@code tiles} as one picture from tile (x0, y0); 0 where there is none. */
    static int[] mosaic(Path tiles, int x0, int y0, int nx, int ny) throws IOException {
        int[] argb = new int[nx * S * ny * S];
        for (int ty = 0; ty < ny; ty++) {
            for (int tx = 0; tx < nx; tx++) {
                Path f = tiles.resolve(Z + "/" + (x0 + tx) + "/" + (y0 + ty) + ".png");
                if (!Files.exists(f)) {
                    continue;
                }
                BufferedImage img = ImageIO.read(f.toFile());
                for (int r = 0; r < S; r++) {
                    for (int c = 0; c < S; c++) {
                        argb[(ty * S + r) * nx * S + tx * S + c] = img.getRGB(c, r);
                    }
                }
            }
        }
        return argb;
    }

    static List<String> tileNames(Path tiles) throws IOException {
        try (Stream<Path> s = Files.walk(tiles)) {
            return s.filter(p -> p.toString().endsWith(".png")).map(p -> tiles.relativize(p).toString()).sorted()
                    .toList();
        }
    }

    @Test
    void tilesSideBySideAreTheMosaicDrawnAtOnce() throws Exception {
        Overlay shapes = OverlayFiles.read(SHAPES, OverlayStyle.parse("color=#ffff00,width=3,fill=#0050ff50,"
                + "radius=4"));
        TileJob plain = TileJob.of(JACKSBORO, new ZoomRange(Z, Z));
        Path without = dir.resolve("without");
        Path with = dir.resolve("with");
        plain.run(without, JobListener.NONE);
        plain.withOverlays(List.of(shapes)).run(with, JobListener.NONE);
        List<String> names = tileNames(with);
        assertEquals(tileNames(without), names, "the same tiles");

        int x0 = Integer.MAX_VALUE;
        int y0 = Integer.MAX_VALUE;
        int x1 = 0;
        int y1 = 0;
        for (String n : names) {
            String[] p = n.replace(".png", "").split("[/\\\\]");
            x0 = Math.min(x0, Integer.parseInt(p[1]));
            x1 = Math.max(x1, Integer.parseInt(p[1]));
            y0 = Math.min(y0, Integer.parseInt(p[2]));
            y1 = Math.max(y1, Integer.parseInt(p[2]));
        }
        int nx = x1 - x0 + 1;
        int ny = y1 - y0 + 1;
        assertTrue(nx >= 2 && ny >= 2, nx + " × " + ny + " tiles");
        int[] drawn = mosaic(with, x0, y0, nx, ny);
        int[] expected = mosaic(without, x0, y0, nx, ny);
        double cell = WebMercatorTile.pixelSize(Z);
        GridGeometry mosaic = new GridGeometry(nx * S, ny * S, -WebMercator.HALF_WORLD + x0 * S * cell,
                WebMercator.HALF_WORLD - y0 * S * cell, cell, cell, WebMercator.CRS, PixelAnchor.CORNER);
        int[] blank = expected.clone();
        OverlayPainter.onMap(List.of(shapes), mosaic, 0, WebMercator.MAX_LATITUDE).paintRows(expected, 0, ny * S);
        int changed = 0;
        int differ = 0;
        int maxDiff = 0;
        int nearSeams = 0;
        for (int i = 0; i < drawn.length; i++) {
            if (blank[i] == 0) {
                continue; // no tile here
            }
            if (expected[i] != blank[i]) {
                changed++;
                int c = i % (nx * S);
                int r = i / (nx * S);
                if (c % S <= 1 || c % S >= S - 2 || r % S <= 1 || r % S >= S - 2) {
                    nearSeams++;
                }
            }
            for (int shift = 0; shift <= 24; shift += 8) {
                maxDiff = Math.max(maxDiff, Math.abs(((drawn[i] >>> shift) & 0xff) - ((expected[i] >>> shift) & 0xff)));
            }
            differ += drawn[i] != expected[i] ? 1 : 0;
        }
        assertTrue(changed > 10_000, changed + " pixels changed by the shapes");
        assertTrue(nearSeams > 100, nearSeams + " of them next to a tile seam");
        assertEquals(0, maxDiff, differ + " pixels differ, by at most " + maxDiff);

        // the line is 3 tile pixels wide: it is horizontal (one latitude), so each column it crosses holds 3 × 255
        int[] line = new int[nx * S * ny * S];
        Overlay lineOnly = new Overlay("line", shapes.geometries().stream()
                .filter(g -> g instanceof org.locationtech.jts.geom.LineString).toList(), shapes.crs(),
                OverlayStyle.parse("color=white,width=3"));
        OverlayPainter.onMap(List.of(lineOnly), mosaic, 0, WebMercator.MAX_LATITUDE).paintRows(line, 0, ny * S);
        int columns = 0;
        for (int c = 0; c < nx * S; c++) {
            double sum = 0;
            for (int r = 0; r < ny * S; r++) {
                sum += line[r * nx * S + c] >>> 24;
            }
            if (sum > 3 * 255 * 0.9) {
                columns++;
                assertEquals(3 * 255, sum, 3 * 255 * 0.05, "column " + c);
            }
        }
        assertTrue(columns > 100, columns + " columns crossed by the line");
    }
}
