package lt.spindulys.frontend;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.OptionalLong;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledOnOs;
import org.junit.jupiter.api.condition.OS;

class PeakResidentTest {
    @Test
    void readsTheHighWaterMarkInKibibytes() {
        String status = "Name:\tjava\nVmPeak:\t 5000000 kB\nVmHWM:\t  412345 kB\nVmRSS:\t  400000 kB\n";
        assertEquals(OptionalLong.of(412345L * 1024), PeakResident.parse(status));
    }

    @Test
    void noLineOrABadOneIsUnknown() {
        assertEquals(OptionalLong.empty(), PeakResident.parse("Name:\tjava\nVmRSS:\t 1 kB\n"));
        assertEquals(OptionalLong.empty(), PeakResident.parse("VmHWM:\t lots kB\n"));
        assertEquals(OptionalLong.empty(), PeakResident.parse("VmHWM:\n"));
    }

    @Test
    @EnabledOnOs(OS.LINUX)
    void thisProcessHasOneOnLinux() {
        if (!Files.isReadable(Path.of("/proc/self/status"))) return; // a Linux without /proc mounted
        long bytes = PeakResident.bytes().orElseThrow();
        // At least the heap already used, and a JVM never runs in under a megabyte.
        assertTrue(bytes > 1 << 20, Long.toString(bytes));
    }
}
