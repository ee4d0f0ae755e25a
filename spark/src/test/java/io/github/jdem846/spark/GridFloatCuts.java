package io.github.jdem846.spark;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/** Cuts a real GridFloat DEM into four tiles (a mosaic that reads back as the DEM), with its header and .prj. */
final class GridFloatCuts {

    private GridFloatCuts() {
    }

    /**
     * @param stem the DEM without extension ({@code .flt}, {@code .hdr}, {@code .prj} beside)
     * @param cx   the first column of the eastern tiles
     * @param ry   the first row of the southern tiles
     * @return the four {@code .flt} files: north-west, north-east, south-west, south-east
     */
    static List<Path> quarters(Path stem, int cx, int ry, Path dir) throws IOException {
        Map<String, String> hdr = new LinkedHashMap<>();
        for (String line : Files.readAllLines(Path.of(stem + ".hdr"))) {
            String[] kv = line.strip().split("\\s+");
            hdr.put(kv[0].toLowerCase(Locale.ROOT), kv[1]);
        }
        int w = Integer.parseInt(hdr.get("ncols"));
        int h = Integer.parseInt(hdr.get("nrows"));
        double cell = Double.parseDouble(hdr.get("cellsize"));
        double west = Double.parseDouble(hdr.get("xllcorner"));
        double north = Double.parseDouble(hdr.get("yllcorner")) + h * cell;
        byte[] cells = Files.readAllBytes(Path.of(stem + ".flt"));
        Files.createDirectories(dir);
        List<Path> out = new ArrayList<>();
        int[][] cuts = {{0, 0, cx, ry}, {cx, 0, w - cx, ry}, {0, ry, cx, h - ry}, {cx, ry, w - cx, h - ry}};
        for (int i = 0; i < cuts.length; i++) {
            int c0 = cuts[i][0];
            int r0 = cuts[i][1];
            int cw = cuts[i][2];
            int ch = cuts[i][3];
            byte[] part = new byte[cw * ch * 4];
            for (int r = 0; r < ch; r++) {
                System.arraycopy(cells, ((r0 + r) * w + c0) * 4, part, r * cw * 4, cw * 4);
            }
            String name = Path.of(stem.getFileName() + "_" + i).toString();
            Path flt = dir.resolve(name + ".flt");
            Files.write(flt, part);
            Files.writeString(dir.resolve(name + ".hdr"), String.format(Locale.ROOT,
                    "ncols %d%nnrows %d%nxllcorner %s%nyllcorner %s%ncellsize %s%nNODATA_value %s%nbyteorder %s%n",
                    cw, ch, Double.toString(west + c0 * cell), Double.toString(north - (r0 + ch) * cell),
                    hdr.get("cellsize"), hdr.get("nodata_value"), hdr.get("byteorder")));
            Files.copy(Path.of(stem + ".prj"), dir.resolve(name + ".prj"));
            out.add(flt);
        }
        return out;
    }
}
