package io.github.jdem846.io;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.raster.DemFormatException;
import io.github.jdem846.raster.GridGeometry;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * ESRI ASCII grid ({@code .asc}): a header of {@code key value} lines ({@code ncols}, {@code nrows},
 * {@code xllcorner|xllcenter}, {@code yllcorner|yllcenter}, {@code cellsize} or {@code dx}/{@code dy},
 * optional {@code NODATA_value}) followed by {@code nrows × ncols} decimal numbers, north row first, separated by
 * any white space. Text can only be read in order: rows are parsed forward, and a read of an earlier row starts
 * over from the top of the file.
 */
final class EsriAsciiSource implements RasterSource {

    private final Path file;
    private final DemInfo info;
    private Tokens tokens;
    private long nextRow; // row the tokenizer stands at

    private EsriAsciiSource(Path file, DemInfo info) {
        this.file = file;
        this.info = info;
    }

    static RasterSource open(Path asc) throws IOException {
        List<String> headerLines = new ArrayList<>();
        try (Tokens t = new Tokens(asc)) {
            t.readHeader(headerLines);
        }
        EsriHeader h = EsriHeader.parse(asc, headerLines);
        List<String> notices = new ArrayList<>();
        EsriGridLayout layout = EsriGridLayout.of(h, false, notices);
        Double noData = h.firstNumber("nodata_value", "nodata").orElse(null);
        CrsInfo crs = SidecarCrs.resolve(asc, layout, notices);
        GridGeometry g = new GridGeometry(layout.cols(), layout.rows(), layout.originX(), layout.originY(),
                layout.cellWidth(), layout.cellHeight(), crs, layout.anchor());
        return new EsriAsciiSource(asc, new DemInfo(asc.toString(), DemFormat.ESRI_ASCII, SampleType.TEXT, 1, g,
                noData, notices));
    }

    @Override
    public DemInfo info() {
        return info;
    }

    @Override
    public void readRows(int col, int row, int width, int rows, float[] dst) throws IOException {
        int cols = info.width();
        if (tokens == null || row < nextRow) {
            if (tokens != null) {
                tokens.close();
            }
            tokens = new Tokens(file);
            tokens.readHeader(new ArrayList<>());
            nextRow = 0;
        }
        for (; nextRow < row; nextRow++) {
            for (int c = 0; c < cols; c++) {
                tokens.nextValue(nextRow, c);
            }
        }
        for (int r = 0; r < rows; r++, nextRow++) {
            for (int c = 0; c < cols; c++) {
                float v = tokens.nextValue(nextRow, c);
                if (c >= col && c < col + width) {
                    dst[r * width + c - col] = v;
                }
            }
        }
    }

    @Override
    public void close() throws IOException {
        if (tokens != null) {
            tokens.close();
        }
    }

    /** White-space separated words of the file. */
    private static final class Tokens implements AutoCloseable {
        private final Path file;
        private final Reader in;
        private final StringBuilder word = new StringBuilder(24);
        private String pushedBack;
        private long valuesRead;

        Tokens(Path file) throws IOException {
            this.file = file;
            this.in = new BufferedReader(Files.newBufferedReader(file, StandardCharsets.ISO_8859_1), 1 << 16);
        }

        /** Reads the {@code key value} pairs before the first number into {@code lines}. */
        void readHeader(List<String> lines) throws IOException {
            String w;
            while ((w = next()) != null) {
                if (isNumber(w)) {
                    pushedBack = w;
                    return;
                }
                String value = next();
                if (value == null) {
                    break;
                }
                lines.add(w + " " + value);
            }
            if (lines.isEmpty()) {
                throw new DemFormatException(file, "is not an ESRI ASCII grid: it does not start with 'ncols'");
            }
        }

        float nextValue(long row, int col) throws IOException {
            String w = next();
            if (w == null) {
                throw new DemFormatException(file, "ends after " + valuesRead + " values, at row " + row
                        + ", column " + col + "; the header promises ncols × nrows values (truncated?)");
            }
            valuesRead++;
            try {
                return w.equalsIgnoreCase("nan") || w.equalsIgnoreCase("-nan") ? Float.NaN : Float.parseFloat(w);
            } catch (NumberFormatException e) {
                throw new DemFormatException(file, "value '" + w + "' at row " + row + ", column " + col
                        + " is not a number");
            }
        }

        private String next() throws IOException {
            if (pushedBack != null) {
                String w = pushedBack;
                pushedBack = null;
                return w;
            }
            word.setLength(0);
            int c;
            while ((c = in.read()) >= 0 && Character.isWhitespace(c)) {
                // skip separators
            }
            if (c < 0) {
                return null;
            }
            do {
                word.append((char) c);
            } while ((c = in.read()) >= 0 && !Character.isWhitespace(c));
            return word.toString();
        }

        private static boolean isNumber(String w) {
            String s = w.toLowerCase(Locale.ROOT);
            if (s.equals("nan") || s.equals("-nan")) {
                return true;
            }
            try {
                Double.parseDouble(s);
                return true;
            } catch (NumberFormatException e) {
                return false;
            }
        }

        @Override
        public void close() throws IOException {
            in.close();
        }
    }
}
