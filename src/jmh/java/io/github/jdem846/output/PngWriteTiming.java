package io.github.jdem846.output;

import com.sun.management.OperatingSystemMXBean;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * The write phase of a command, alone and repeated: re-encodes the pixels of a PNG with {@link PngWriter} as the
 * commands write it (level 1, segments compressed on all processors), {@code rounds} times in one JVM, and prints
 * the wall time and the process CPU time of each round (docs/performance.md, "Writing PNG and GeoTIFF"). CPU time
 * tells more than wall time on a shared machine. Not a test; run by hand.
 *
 * <p>Arguments: {@code PNG ROUNDS OUT}.
 */
public final class PngWriteTiming {

    private PngWriteTiming() {
    }

    public static void main(String[] args) throws IOException {
        BufferedImage image = ImageIO.read(new File(args[0]));
        int rounds = Integer.parseInt(args[1]);
        Path out = Path.of(args[2]);
        OperatingSystemMXBean os = (OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        StringBuilder times = new StringBuilder();
        for (int i = 0; i < rounds; i++) {
            long cpu = os.getProcessCpuTime();
            long t0 = System.nanoTime();
            PngWriter.write(image, out, 1, true);
            times.append(' ').append((System.nanoTime() - t0) / 1_000_000).append('/')
                    .append((os.getProcessCpuTime() - cpu) / 1_000_000);
        }
        System.out.println("wall/CPU ms per round:" + times + "; " + Files.size(out) + " bytes");
    }
}
